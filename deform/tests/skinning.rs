//! Skinning: glTF rigs against three.js, libigl LBS/DQS, backends against each other, the
//! paper's Fig. 2 experiment, glb round trips.

mod common;

use cga::ScaledMotor;
use common::{data_dir, reference, reference_mesh};
use deform::skinning::{
    glb_bytes, libigl_rig, parse_gltf, procedural_arm, read_gltf, read_libigl_animation,
    GlbOptions, Influences, JointEdit, Rig, Skinning,
};
use deform::{BlendMethod, Deformer};
use glam::{DQuat, DVec3};

/// Where tests write glTF files; `.ci/run` checks each with the Khronos validator.
fn gltf_out() -> std::path::PathBuf {
    let d = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gltf-out");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn gltf(name: &str) -> Option<Rig> {
    let path = data_dir()?.join("gltf").join(name);
    Some(read_gltf(&path).unwrap_or_else(|e| panic!("{name}: {e}")))
}

fn vec3s(v: &serde_json::Value) -> Vec<DVec3> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|p| {
            let c: Vec<f64> = p
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            DVec3::new(c[0], c[1], c[2])
        })
        .collect()
}

fn max_dist(a: &[DVec3], b: &[DVec3]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| x.distance(*y))
        .fold(0.0, f64::max)
}

/// Skin `rig` at `(animation, t)` with `method`.
fn skin(
    rig: &Rig,
    method: BlendMethod,
    animation: Option<usize>,
    t: f64,
    edits: &[JointEdit],
) -> Vec<DVec3> {
    let bound = Skinning::bind(rig, method).unwrap();
    let pose = rig.pose(animation, t, edits).unwrap();
    let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    bound.pose(pose.skin_motors().unwrap(), &mut out).unwrap();
    out
}

/// Every model in the data set loads and animates, against three.js positions.
#[test]
fn gltf_models_match_three_js() {
    let Some(r) = reference("three_skinning_visible.json") else {
        return;
    };
    let mut checked = 0;
    for e in r["entries"].as_array().unwrap() {
        let model = e["model"].as_str().unwrap();
        let Some(rig) = gltf(model) else { return };
        let anim = rig
            .animation_index(e["animation_name"].as_str().unwrap())
            .unwrap_or_else(|_| e["animation_index"].as_u64().unwrap() as usize);
        let t = e["time"].as_f64().unwrap();
        let diag = e["bbox_diag"].as_f64().unwrap();
        // three.js feeds SimpleSkin's non-unit rotation keys to its matrices as they are; this
        // crate normalises keys (glTF requires unit quaternions): compare with the reference's
        // unit-key positions there (the README of the reference folder explains).
        let want = if e["positions_spec_unit_quat_keys"].is_array() {
            vec3s(&e["positions_spec_unit_quat_keys"])
        } else {
            vec3s(&e["positions"])
        };
        for method in [
            BlendMethod::Matrix,
            BlendMethod::Conformal,
            BlendMethod::ConformalProjected,
        ] {
            let got = skin(&rig, method, Some(anim), t, &[]);
            let err = max_dist(&got, &want) / diag;
            assert!(
                err < 1e-5,
                "{model} t={t} {}: {err:e} of the diagonal",
                method.name()
            );
        }
        if !e["positions_spec_unit_quat_keys"].is_array() {
            let got = skin(&rig, BlendMethod::Matrix, Some(anim), t, &[]);
            let three = vec3s(&e["positions"]);
            assert!(max_dist(&got, &three) / diag < 1e-5);
        }
        checked += 1;
    }
    assert_eq!(checked, 15);
    // CesiumMan loads and animates too (no three.js entries for it).
    let man = gltf("CesiumMan.glb").unwrap();
    assert_eq!(man.joints.len(), 19);
    assert_eq!(man.mesh.vertex_count(), 3273);
    let (t0, t1) = man.animations[0].range();
    for method in BlendMethod::ALL {
        let p = skin(&man, method, Some(0), 0.5 * (t0 + t1), &[]);
        assert!(p.iter().all(|x| x.is_finite()), "{}", method.name());
    }
}

fn bones_of(r: &serde_json::Value) -> Vec<ScaledMotor> {
    r["bones"]["bones"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| {
            let q: Vec<f64> = b["quat_wxyz"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            let t: Vec<f64> = b["translation"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            ScaledMotor::from_scale_rotation_translation(
                1.0,
                DQuat::from_xyzw(q[1], q[2], q[3], q[0]),
                DVec3::new(t[0], t[1], t[2]),
            )
        })
        .collect()
}

/// libigl's LBS and DQS, to 1e-12; equation (17) and motor blending agree with them.
#[test]
fn libigl_lbs_and_dqs() {
    for case in ["libigl_knight.json", "libigl_tube_41x24.json"] {
        let Some(r) = reference(case) else { return };
        let mesh = reference_mesh(&r);
        let keys = bones_of(&r);
        let w: Vec<Vec<f64>> = r["weights"]
            .as_array()
            .unwrap()
            .iter()
            .map(|row| {
                row.as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap())
                    .collect()
            })
            .collect();
        let m = keys.len();
        let influences = Influences {
            width: m,
            joints: (0..w.len()).flat_map(|_| 0..m as u32).collect(),
            weights: w.iter().flatten().copied().collect(),
        };
        let scale = mesh.bounding_box().unwrap().diagonal();
        let run = |method| {
            let b = Skinning::bind_influences(&mesh.positions, &influences, m, method).unwrap();
            let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
            b.pose(&keys, &mut out).unwrap();
            out
        };
        let lbs = vec3s(&r["lbs"]);
        let dqs = vec3s(&r["dqs"]);
        for (method, want, tol) in [
            (BlendMethod::Matrix, &lbs, 1e-12),
            (BlendMethod::Conformal, &lbs, 1e-12),
            (BlendMethod::ConformalProjected, &lbs, 1e-12),
            (BlendMethod::DualQuaternion, &dqs, 1e-12),
            (BlendMethod::MotorLinear, &dqs, 1e-12),
            (BlendMethod::MatrixF32, &lbs, 1e-6),
        ] {
            let err = max_dist(&run(method), want) / scale;
            assert!(err < tol, "{case} {}: {err:e}", method.name());
        }
    }
}

/// The bind pose (identity skin motors) reproduces the rest mesh in every backend; the rig's
/// own rest pose gives the rest mesh placed by the skinned mesh node's world transform (the
/// bind-time placement: CesiumMan's mesh sits under a Z-up node), to the precision of its
/// single-precision matrices.
#[test]
fn bind_pose_reproduces_rest_mesh() {
    let mut rigs = vec![procedural_arm(16, 30)];
    for name in ["SimpleSkin.gltf", "Fox.glb", "CesiumMan.glb"] {
        if let Some(r) = gltf(name) {
            rigs.push(r);
        }
    }
    for rig in &rigs {
        let diag = rig.mesh.bounding_box().unwrap().diagonal();
        let identity = vec![ScaledMotor::IDENTITY; rig.joints.len()];
        let rest_pose = rig.rest_pose().unwrap();
        for method in BlendMethod::ALL {
            let b = Skinning::bind(rig, method).unwrap();
            let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
            b.pose(&identity, &mut out).unwrap();
            let tol = if method == BlendMethod::MatrixF32 {
                1e-6
            } else {
                1e-12
            };
            assert!(
                max_dist(&out, &rig.mesh.positions) / diag < tol,
                "{}",
                method.name()
            );
            b.pose(rest_pose.skin_motors().unwrap(), &mut out).unwrap();
            let place = rest_pose.globals[rig.primitives[0].node];
            let want: Vec<DVec3> = rig
                .mesh
                .positions
                .iter()
                .map(|&p| place.transform_point3(p))
                .collect();
            let err = max_dist(&out, &want) / diag;
            assert!(
                err < 1e-5,
                "{}: rest pose {}: {err:e}",
                rig.nodes[0].name,
                method.name()
            );
        }
    }
}

/// One rigid motion on every joint moves the mesh rigidly in every backend.
#[test]
fn rigid_motion_agrees_across_backends() {
    let rig = procedural_arm(16, 30);
    let m = ScaledMotor::from_scale_rotation_translation(
        1.0,
        DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 2.5),
        DVec3::new(3.0, -1.0, 0.25),
    );
    let keys = vec![m; 3];
    let want: Vec<DVec3> = rig
        .mesh
        .positions
        .iter()
        .map(|&p| m.transform_point(p))
        .collect();
    for method in BlendMethod::ALL {
        let b = Skinning::bind(&rig, method).unwrap();
        let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
        b.pose(&keys, &mut out).unwrap();
        let tol = if method == BlendMethod::MatrixF32 {
            1e-5
        } else {
            1e-9
        };
        assert!(max_dist(&out, &want) < tol, "{}", method.name());
    }
}

/// The candy wrapper: a (nearly) half-turn twist of each bone of `arm.obj` about its axis.
/// LBS loses volume; dual quaternions and motor blending do not (they may bulge a little).
#[test]
fn candy_wrapper_volume() {
    let Some(rig) = common::libigl_rig("arm") else {
        return;
    };
    let skeleton = deform::io::read_tgf(data_dir().unwrap().join("meshes/libigl/arm.tgf")).unwrap();
    let v0 = rig.mesh.volume();
    // Twist the last bone about its own axis by 180 degrees (in place).
    for bone in 0..skeleton.bones.len() {
        let [a, b] = skeleton.bones[bone].map(|j| skeleton.joints[j as usize]);
        let twist = ScaledMotor::from_scale_rotation_translation(
            1.0,
            DQuat::from_axis_angle((b - a).normalize(), std::f64::consts::PI * 0.999),
            DVec3::ZERO,
        );
        let about = ScaledMotor::from_scale_rotation_translation(1.0, DQuat::IDENTITY, a)
            * twist
            * ScaledMotor::from_scale_rotation_translation(1.0, DQuat::IDENTITY, -a);
        let mut keys = vec![ScaledMotor::IDENTITY; skeleton.bones.len()];
        keys[bone] = about;
        let ratio = |method| {
            let bnd = Skinning::bind(&rig, method).unwrap();
            let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
            bnd.pose(&keys, &mut out).unwrap();
            deform::Mesh::new(out, rig.mesh.triangles.clone()).volume() / v0
        };
        let lbs = ratio(BlendMethod::Matrix);
        let dqs = ratio(BlendMethod::DualQuaternion);
        let motor = ratio(BlendMethod::MotorLinear);
        let eq17 = ratio(BlendMethod::Conformal);
        eprintln!("bone {bone} twisted: volume ratio lbs {lbs:.4} dqs {dqs:.4} motor {motor:.4} eq17 {eq17:.4}");
        assert!(lbs < dqs.min(motor) - 0.01, "bone {bone}: LBS keeps {lbs}");
        assert!(
            dqs > 0.99 && motor > 0.99,
            "bone {bone}: dqs {dqs} motor {motor}"
        );
        assert!(
            (dqs - motor).abs() < 1e-9,
            "motor blending is dual-quaternion blending for rigid keys"
        );
        assert!(
            (eq17 - lbs).abs() < 1e-9,
            "equation (17) is LBS for rigid keys"
        );
    }
}

/// The elephant's libigl animation: LBS by the DMAT's matrices, computed here directly; the
/// matrix and equation (17) backends reproduce it, the motor backends stay close (its weights
/// are smooth, so they differ where bones bend).
#[test]
fn elephant_animation() {
    let Some(dir) = data_dir() else { return };
    let lib = dir.join("meshes/libigl");
    let mesh = deform::io::read_obj(lib.join("elephant.obj")).unwrap();
    let skeleton = deform::io::read_tgf(lib.join("elephant.tgf")).unwrap();
    let weights = deform::io::read_dmat(lib.join("elephant-weights.dmat")).unwrap();
    let anim = deform::io::read_dmat(lib.join("elephant-anim.dmat")).unwrap();
    let rig = libigl_rig(mesh, &skeleton, &weights).unwrap();
    let anim = read_libigl_animation(&anim, skeleton.bones.len()).unwrap();
    assert_eq!(anim.frames.len(), 457);
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    for f in [0, 100, 456] {
        let keys = anim.skin_motors(f).unwrap();
        let want: Vec<DVec3> = (0..rig.mesh.vertex_count())
            .map(|i| {
                rig.influences
                    .row(i)
                    .map(|(j, w)| {
                        w * anim.frames[f][j as usize].transform_point3(rig.mesh.positions[i])
                    })
                    .sum()
            })
            .collect();
        for method in BlendMethod::ALL {
            let b = Skinning::bind(&rig, method).unwrap();
            let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
            b.pose(&keys, &mut out).unwrap();
            let tol = match method {
                BlendMethod::MatrixF32 => 1e-6,
                BlendMethod::Matrix | BlendMethod::Conformal | BlendMethod::ConformalProjected => {
                    1e-9
                }
                _ => 0.05,
            };
            let err = max_dist(&out, &want) / diag;
            assert!(err < tol, "frame {f} {}: {err:e}", method.name());
        }
    }
}

/// A written `.glb` read back gives the same positions at the same times.
#[test]
fn glb_round_trip() {
    let mut rigs = vec![("arm".to_string(), procedural_arm(12, 20))];
    for name in ["SimpleSkin.gltf", "Fox.glb", "CesiumMan.glb"] {
        if let Some(r) = gltf(name) {
            rigs.push((name.to_string(), r));
        }
    }
    for (name, rig) in &rigs {
        let bytes = glb_bytes(rig, &GlbOptions::default()).unwrap();
        std::fs::write(gltf_out().join(format!("{name}.glb")), &bytes).unwrap();
        let back = parse_gltf(&bytes, name, None).unwrap();
        check_written_normals(&bytes, rig, name);
        assert_eq!(back.animations.len(), rig.animations.len());
        assert_eq!(back.mesh.triangles, rig.mesh.triangles);
        let diag = rig.mesh.bounding_box().unwrap().diagonal();
        for (a, anim) in rig.animations.iter().enumerate() {
            let (t0, t1) = anim.range();
            for k in 0..5 {
                let t = t0 + (t1 - t0) * k as f64 / 4.0;
                let p = skin(rig, BlendMethod::Matrix, Some(a), t, &[]);
                let q = skin(&back, BlendMethod::Matrix, Some(a), t, &[]);
                let err = max_dist(&p, &q) / diag;
                assert!(err < 2e-6, "{name} animation {a} t={t}: {err:e}");
            }
        }
    }
}

/// Every written primitive has unit normals that are the rig's smooth vertex normals.
fn check_written_normals(bytes: &[u8], rig: &deform::skinning::Rig, name: &str) {
    let g = gltf::Gltf::from_slice(bytes).unwrap();
    let blob = g.blob.as_deref();
    let want = rig.mesh.vertex_normals();
    let mut seen = 0;
    for prim in g.meshes().flat_map(|m| m.primitives().collect::<Vec<_>>()) {
        let reader = prim.reader(|b| if b.index() == 0 { blob } else { None });
        let normals: Vec<[f32; 3]> = reader.read_normals().expect("a NORMAL attribute").collect();
        let count = reader.read_positions().unwrap().count();
        assert_eq!(normals.len(), count, "{name}");
        for n in normals {
            let n = glam::Vec3::from(n);
            assert!(
                (n.length() - 1.0).abs() < 1e-6,
                "{name}: |n| = {}",
                n.length()
            );
            let w = want[seen];
            if w != glam::DVec3::ZERO {
                assert!((n.as_dvec3() - w).length() < 1e-6, "{name} vertex {seen}");
            }
            seen += 1;
        }
    }
    assert_eq!(seen, rig.mesh.vertex_count(), "{name}");
}

/// The paper's Fig. 2: a slight rotation, dilation and translation at CesiumMan's neck;
/// equation (17) against dual-quaternion skinning, the l-infinity norm of the difference over
/// all vertices as a percentage of the bounding-box diagonal (the paper: 0.3 %, 0.00035 %,
/// 1 % on its model; `deform skin --backend cga --compare dqs` prints the same figure).
#[test]
fn fig2_neck_edits() {
    let Some(rig) = gltf("CesiumMan.glb") else {
        return;
    };
    let neck = rig
        .joint_index("Skeleton_neck_joint_1")
        .expect("CesiumMan has a neck joint");
    let edits = [
        (
            "rotation",
            ScaledMotor::from_scale_rotation_translation(
                1.0,
                DQuat::from_rotation_x(10f64.to_radians()),
                DVec3::ZERO,
            ),
        ),
        (
            "dilation",
            ScaledMotor::from_scale_rotation_translation(1.1, DQuat::IDENTITY, DVec3::ZERO),
        ),
        (
            "translation",
            ScaledMotor::from_scale_rotation_translation(
                1.0,
                DQuat::IDENTITY,
                DVec3::new(0.0, 0.02, 0.0),
            ),
        ),
    ];
    let linf = |a: &[DVec3], b: &[DVec3]| {
        a.iter()
            .zip(b)
            .map(|(p, q)| (*p - *q).abs().max_element())
            .fold(0.0, f64::max)
    };
    let mut percent = Vec::new();
    for (what, motor) in edits {
        let e = [JointEdit { joint: neck, motor }];
        let eq17 = skin(&rig, BlendMethod::Conformal, None, 0.0, &e);
        let dqs = skin(&rig, BlendMethod::DualQuaternion, None, 0.0, &e);
        let rest = skin(&rig, BlendMethod::Conformal, None, 0.0, &[]);
        let diag = deform::Mesh::new(eq17.clone(), vec![])
            .bounding_box()
            .unwrap()
            .diagonal();
        let moved = 100.0 * linf(&eq17, &rest) / diag;
        let diff = 100.0 * linf(&eq17, &dqs) / diag;
        eprintln!("Fig. 2 {what}: the edit moves vertices by up to {moved:.3} %, equation (17) vs DQS {diff:.5} % of the diagonal");
        assert!(moved > 0.1, "{what} must move the head");
        percent.push(diff);
    }
    // Rotation and dilation: the two blends differ only where the neck's weight is partial.
    assert!(
        percent[0] > 1e-4 && percent[0] < 1.0,
        "rotation {}",
        percent[0]
    );
    assert!(
        percent[1] > 1e-4 && percent[1] < 1.0,
        "dilation {}",
        percent[1]
    );
    // A translation of the neck moves its vertices rigidly in both: they agree.
    assert!(percent[2] < 1e-6, "translation {}", percent[2]);
}

/// SimpleSkin's JSON, edited by `f`, parsed again.
fn simple_skin_edited(
    f: impl FnOnce(&mut serde_json::Value),
) -> Option<Result<Rig, deform::skinning::SkinError>> {
    let path = data_dir()?.join("gltf/SimpleSkin.gltf");
    let mut doc: serde_json::Value = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    f(&mut doc);
    Some(parse_gltf(
        &serde_json::to_vec(&doc).unwrap(),
        "edited",
        None,
    ))
}

/// Bad input: typed errors or documented handling, never a panic.
#[test]
fn bad_gltf_input() {
    use deform::skinning::SkinError;
    let Some(dir) = data_dir() else { return };
    // Truncated and corrupt files, at many lengths.
    for name in ["Fox.glb", "SimpleSkin.gltf"] {
        let bytes = std::fs::read(dir.join("gltf").join(name)).unwrap();
        for cut in (0..bytes.len()).step_by(bytes.len() / 97 + 1) {
            assert!(
                parse_gltf(&bytes[..cut], name, None).is_err(),
                "{name} cut at {cut}"
            );
        }
        let mut flipped = bytes.clone();
        for k in (0..flipped.len()).step_by(131) {
            flipped[k] ^= 0x5a;
            let _ = parse_gltf(&flipped, name, None); // any result, no panic
        }
    }
    // Missing inverse bind matrices: identity, as the specification says.
    let r = simple_skin_edited(|d| {
        d["skins"][0]
            .as_object_mut()
            .unwrap()
            .remove("inverseBindMatrices");
    })
    .unwrap()
    .unwrap();
    assert!(r.inverse_bind.iter().all(|m| *m == glam::DMat4::IDENTITY));
    // An animation targeting a missing node: the glTF checks refuse it.
    let e = simple_skin_edited(|d| d["animations"][0]["channels"][0]["target"]["node"] = 99.into())
        .unwrap();
    assert!(matches!(e, Err(SkinError::Gltf { .. })), "{e:?}");
    // A skin joint that is not a node.
    let e = simple_skin_edited(|d| d["skins"][0]["joints"][1] = 42.into()).unwrap();
    assert!(matches!(e, Err(SkinError::Gltf { .. })), "{e:?}");
    // A buffer shorter than declared.
    let e = simple_skin_edited(|d| {
        let uri = d["buffers"][0]["uri"].as_str().unwrap().to_string();
        d["buffers"][0]["uri"] = uri[..uri.len() - 40].into();
    })
    .unwrap();
    assert!(matches!(e, Err(SkinError::Data { .. })), "{e:?}");
    // An accessor reaching past its view.
    let e = simple_skin_edited(|d| {
        let c = d["accessors"][0]["count"].as_u64().unwrap();
        d["accessors"][0]["count"] = (c + 1000).into();
    })
    .unwrap();
    assert!(e.is_err(), "{e:?}");
}

/// Joint indices out of range, bad weights, weights that do not sum to 1, non-finite keys,
/// non-similarity transforms asked for as motors.
#[test]
fn bad_rig_input() {
    use deform::skinning::{Animation, Channel, Interpolation, Property, SkinError};
    let rig = procedural_arm(6, 4);
    let rebuild = |f: &dyn Fn(&mut deform::skinning::Influences)| {
        let mut inf = rig.influences.clone();
        f(&mut inf);
        Rig::new(
            rig.nodes.clone(),
            rig.joints.clone(),
            rig.inverse_bind.clone(),
            rig.mesh.clone(),
            inf,
            rig.primitives.clone(),
            rig.animations.clone(),
            Default::default(),
        )
    };
    let e = rebuild(&|i| i.joints[5] = 7).unwrap_err();
    assert!(
        matches!(
            e,
            SkinError::JointOutOfRange {
                vertex: 1,
                joint: 7,
                ..
            }
        ),
        "{e:?}"
    );
    let e = rebuild(&|i| i.weights[2] = f64::NAN).unwrap_err();
    assert!(matches!(e, SkinError::BadWeight { vertex: 0, .. }), "{e:?}");
    let e = rebuild(&|i| i.weights[2] = -0.5).unwrap_err();
    assert!(matches!(e, SkinError::BadWeight { .. }), "{e:?}");
    // Weights scaled by 2 on 3 vertices: normalised and counted.
    let r = rebuild(&|i| (0..12).for_each(|k| i.weights[k] *= 2.0)).unwrap();
    assert_eq!(r.report.renormalised_vertices, 3);
    for v in 0..r.mesh.vertex_count() {
        let s: f64 = r.influences.row(v).map(|(_, w)| w).sum();
        assert!((s - 1.0).abs() < 1e-12);
    }
    // Keyframes: non-finite values and times that do not increase.
    let bad = Channel::new(
        0,
        Property::Translation,
        Interpolation::Linear,
        vec![0.0, 1.0],
        vec![glam::DVec4::ZERO, glam::DVec4::splat(f64::INFINITY)],
        "c",
    );
    assert!(matches!(bad, Err(SkinError::BadTransform { .. })));
    let bad = Channel::new(
        0,
        Property::Translation,
        Interpolation::Linear,
        vec![1.0, 1.0],
        vec![glam::DVec4::ZERO; 2],
        "c",
    );
    assert!(matches!(bad, Err(SkinError::BadTransform { .. })));
    let bad = Channel::new(
        0,
        Property::Rotation,
        Interpolation::Step,
        vec![0.0],
        vec![glam::DVec4::ZERO],
        "c",
    );
    assert!(
        matches!(bad, Err(SkinError::BadTransform { .. })),
        "a zero quaternion key"
    );
    // A non-uniform scale on a joint: matrices skin it, motors say why they cannot.
    let mut squash = rig.clone();
    squash.animations = vec![Animation {
        name: "squash".into(),
        channels: vec![Channel::new(
            1,
            Property::Scale,
            Interpolation::Step,
            vec![0.0],
            vec![glam::DVec4::new(1.0, 0.5, 1.0, 0.0)],
            "s",
        )
        .unwrap()],
    }];
    let pose = squash.pose(Some(0), 0.0, &[]).unwrap();
    assert!(matches!(
        pose.skin_motors(),
        Err(SkinError::NotSimilarity { .. })
    ));
    assert!(squash.pose(Some(3), 0.0, &[]).is_err());
    assert!(squash.joint_index("no such joint").is_err());
    assert_eq!(squash.joint_index("elbow").unwrap(), 1);
}

/// STEP holds, CUBICSPLINE follows the Hermite form with tangents scaled by the interval,
/// LINEAR rotations take the shortest path; times clamp to the keys.
#[test]
fn samplers_closed_forms() {
    use deform::skinning::{Channel, Interpolation, Property};
    use glam::DVec4;
    let step = Channel::new(
        0,
        Property::Translation,
        Interpolation::Step,
        vec![1.0, 2.0],
        vec![DVec4::X, DVec4::Y],
        "s",
    )
    .unwrap();
    assert_eq!(step.sample(0.0), DVec4::X);
    assert_eq!(step.sample(1.99), DVec4::X);
    assert_eq!(step.sample(2.0), DVec4::Y);
    assert_eq!(step.sample(9.0), DVec4::Y);
    // p(s) = 2s^3 - 3s^2 + 1 for value 1 -> 0 with out-tangent 0 and in-tangent 0, plus the
    // tangent terms: out-tangent m0 = 1 per second over an interval of 2 s.
    let cubic = Channel::new(
        0,
        Property::Translation,
        Interpolation::CubicSpline,
        vec![0.0, 2.0],
        vec![
            DVec4::ZERO,
            DVec4::X,
            DVec4::X,
            DVec4::ZERO,
            DVec4::ZERO,
            DVec4::ZERO,
        ],
        "c",
    )
    .unwrap();
    for s in [0.0, 0.25, 0.5, 0.9] {
        let want = (2.0 * s * s * s - 3.0 * s * s + 1.0) + 2.0 * (s * s * s - 2.0 * s * s + s);
        assert!((cubic.sample(2.0 * s).x - want).abs() < 1e-14, "s = {s}");
    }
    // Shortest path: keys q and -q' (nearly the same rotation) interpolate without a flip.
    let a = DQuat::from_rotation_z(0.1);
    let b = -DQuat::from_rotation_z(0.3);
    let lin = Channel::new(
        0,
        Property::Rotation,
        Interpolation::Linear,
        vec![0.0, 1.0],
        vec![DVec4::from(a), DVec4::from(b)],
        "r",
    )
    .unwrap();
    let mid = DQuat::from_vec4(lin.sample(0.5));
    assert!(mid.angle_between(DQuat::from_rotation_z(0.2)) < 1e-12);
}

/// The CLI: glTF and libigl rigs, OBJ and .glb out (validated in CI), exit code 2 on bad input.
#[test]
fn skin_cli() {
    use std::process::Command;
    let Some(dir) = data_dir() else { return };
    let out = gltf_out();
    let exe = env!("CARGO_BIN_EXE_deform");
    let edit = out.join("neck.json");
    std::fs::write(
        &edit,
        r#"{"rotate": {"axis": [1, 0, 0], "degrees": 20}, "scale": 1.1}"#,
    )
    .unwrap();
    let run = |args: &[&str]| Command::new(exe).args(args).output().unwrap();
    let man = dir.join("gltf/CesiumMan.glb");
    let glb = out.join("cesium-edited.glb");
    let o = run(&[
        "skin",
        man.to_str().unwrap(),
        "--edit",
        &format!("Skeleton_neck_joint_1={}", edit.display()),
        "-o",
        glb.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let back = read_gltf(&glb).unwrap();
    assert_eq!(back.animations.len(), 1);
    let obj = out.join("fox.obj");
    let o = run(&[
        "skin",
        dir.join("gltf/Fox.glb").to_str().unwrap(),
        "--animation",
        "Walk",
        "--time",
        "0.35",
        "--backend",
        "dqs",
        "-o",
        obj.to_str().unwrap(),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let m = deform::io::read_obj(&obj).unwrap();
    assert_eq!(m.vertex_count(), 1728);
    // A libigl rig with its DMAT animation: frame 100.
    let lib = dir.join("meshes/libigl");
    let ele = out.join("elephant-100.obj");
    let o = run(&[
        "skin",
        lib.join("elephant.obj").to_str().unwrap(),
        "--skeleton",
        lib.join("elephant.tgf").to_str().unwrap(),
        "--weights",
        lib.join("elephant-weights.dmat").to_str().unwrap(),
        "--dmat-animation",
        lib.join("elephant-anim.dmat").to_str().unwrap(),
        "--time",
        "100",
        "--backend",
        "lbs",
        "-o",
        ele.to_str().unwrap(),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(deform::io::read_obj(&ele).unwrap().vertex_count(), 6034);
    // Bad input: exit code 2 with a message.
    let trunc = out.join("truncated.bin");
    std::fs::write(&trunc, &std::fs::read(&man).unwrap()[..500]).unwrap();
    let trunc_glb = out.join("truncated-input.glb.bin");
    std::fs::rename(&trunc, &trunc_glb).unwrap();
    for args in [
        vec!["skin", trunc_glb.to_str().unwrap(), "-o", "/tmp/never.obj"],
        vec![
            "skin",
            man.to_str().unwrap(),
            "--animation",
            "nope",
            "-o",
            "/tmp/never.obj",
        ],
        vec![
            "skin",
            man.to_str().unwrap(),
            "--edit",
            "nobody=x.json",
            "-o",
            "/tmp/never.obj",
        ],
        vec!["skin", man.to_str().unwrap(), "-o", man.to_str().unwrap()],
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!o.stderr.is_empty());
    }
}

/// Logarithmic keyframe blending: at the keys it is the keys; between keys of a rotation
/// about a fixed pivot it is the slerp (a motor geodesic of rotations is a rotation); with a
/// simultaneous translation it is a screw motion, not glTF's separate lerp and slerp.
#[test]
fn motor_log_keyframes() {
    use deform::skinning::{Animation, Channel, Interpolation, KeyframeBlend, Property, RigPose};
    use glam::DVec4;
    let mut rig = procedural_arm(8, 10);
    let rot = |deg: f64| DVec4::from(DQuat::from_rotation_z(deg.to_radians()));
    let spin = Channel::new(
        1,
        Property::Rotation,
        Interpolation::Linear,
        vec![0.0, 1.0],
        vec![rot(0.0), rot(90.0)],
        "spin",
    )
    .unwrap();
    let slide = Channel::new(
        1,
        Property::Translation,
        Interpolation::Linear,
        vec![0.0, 1.0],
        vec![
            DVec4::new(4.0, 0.0, 0.0, 0.0),
            DVec4::new(4.0, 2.0, 0.0, 0.0),
        ],
        "slide",
    )
    .unwrap();
    rig.animations = vec![
        Animation {
            name: "spin".into(),
            channels: vec![spin.clone()],
        },
        Animation {
            name: "screw".into(),
            channels: vec![spin, slide],
        },
    ];
    let (mut a, mut b) = (RigPose::default(), RigPose::default());
    for t in [0.0, 0.3, 0.5, 1.0] {
        rig.pose_into(Some(0), t, KeyframeBlend::Gltf, &[], &mut a)
            .unwrap();
        rig.pose_into(Some(0), t, KeyframeBlend::MotorLog, &[], &mut b)
            .unwrap();
        let d = (a.globals[2] - b.globals[2])
            .abs()
            .to_cols_array()
            .into_iter()
            .fold(0.0, f64::max);
        assert!(d < 1e-12, "rotation only, t = {t}: {d}");
        rig.pose_into(Some(1), t, KeyframeBlend::Gltf, &[], &mut a)
            .unwrap();
        rig.pose_into(Some(1), t, KeyframeBlend::MotorLog, &[], &mut b)
            .unwrap();
        let d = (a.globals[2] - b.globals[2])
            .abs()
            .to_cols_array()
            .into_iter()
            .fold(0.0, f64::max);
        if t == 0.0 || t == 1.0 {
            assert!(d < 1e-12, "screw at a key, t = {t}: {d}");
        } else {
            assert!(
                d > 1e-3,
                "a screw motion differs from lerp + slerp between keys, t = {t}"
            );
        }
        // The screw: the elbow's local motor at t is exp(t log(M0^-1 M1)) from M0.
        let m0 = ScaledMotor::from_scale_rotation_translation(
            1.0,
            DQuat::IDENTITY,
            DVec3::new(4.0, 0.0, 0.0),
        );
        let m1 = ScaledMotor::from_scale_rotation_translation(
            1.0,
            DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2),
            DVec3::new(4.0, 2.0, 0.0),
        );
        let want = ScaledMotor::interpolate(m0, m1, t);
        let got = b.locals[1];
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert!((want.transform_point(p) - got.matrix().transform_point3(p)).length() < 1e-12);
    }
}

/// More than 4 influences: the writer keeps the 8 largest as two joint sets, the reader reads
/// both; vertices with at most 8 influences skin exactly as before.
#[test]
fn second_joint_set_round_trip() {
    let Some(rig) = common::libigl_rig("elephant") else {
        return;
    };
    let bytes = glb_bytes(&rig, &GlbOptions::default()).unwrap();
    std::fs::write(gltf_out().join("elephant-8-influences.glb"), &bytes).unwrap();
    let back = parse_gltf(&bytes, "elephant", None).unwrap();
    assert_eq!(back.influences.width, 8);
    let keys: Vec<ScaledMotor> = (0..rig.joints.len())
        .map(|j| {
            ScaledMotor::from_scale_rotation_translation(
                1.0,
                DQuat::from_rotation_y(0.1 * j as f64),
                DVec3::ZERO,
            )
        })
        .collect();
    let pose = |r: &Rig| {
        let b = Skinning::bind(r, BlendMethod::Matrix).unwrap();
        let mut out = vec![DVec3::ZERO; r.mesh.vertex_count()];
        b.pose(&keys, &mut out).unwrap();
        out
    };
    let (p, q) = (pose(&rig), pose(&back));
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    let mut exact = 0;
    for v in 0..rig.mesh.vertex_count() {
        if rig.influences.row(v).filter(|&(_, w)| w > 0.0).count() <= 8 {
            exact += 1;
            assert!(p[v].distance(q[v]) / diag < 1e-6, "vertex {v}");
        }
    }
    assert!(exact > 0);
}

/// Morph targets are read past and reported (unsupported), not an error.
#[test]
fn morph_targets_are_reported() {
    let Some(r) = simple_skin_edited(|d| {
        d["meshes"][0]["primitives"][0]["targets"] = serde_json::json!([{"POSITION": 1}]);
    }) else {
        return;
    };
    let rig = r.unwrap();
    assert!(
        rig.report.notes.iter().any(|n| n.contains("morph targets")),
        "{:?}",
        rig.report.notes
    );
}

/// A coordinate beyond the f32 range (issue 20: a vertex or joint at 1e300) is an error when
/// writing `.glb`, not an accessor of infinities.
#[test]
fn glb_refuses_coordinates_beyond_single_precision() {
    let mut rig = procedural_arm(6, 5);
    assert!(glb_bytes(&rig, &GlbOptions::default()).is_ok());
    rig.mesh.positions[3].x = 1e300;
    let err = glb_bytes(&rig, &GlbOptions::default()).unwrap_err();
    assert!(err.to_string().contains("POSITION: element 3"), "{err}");
}

/// External buffers (issue 20): a URI that leaves the model's folder is refused unless
/// allowed, and only the declared `byteLength` is read from a longer file.
#[test]
fn external_buffers_stay_in_the_model_folder_and_within_their_length() {
    use deform::skinning::{parse_gltf_with, GltfReadOptions};
    let glb = glb_bytes(&procedural_arm(6, 5), &GlbOptions::default()).unwrap();
    let u32_at = |i: usize| u32::from_le_bytes(glb[i..i + 4].try_into().unwrap()) as usize;
    let json_len = u32_at(12);
    let json: &[u8] = &glb[20..20 + json_len];
    let bin_len = u32_at(20 + json_len);
    let bin = &glb[28 + json_len..28 + json_len + bin_len];
    let root = std::env::temp_dir().join(format!("deform-external-{}", std::process::id()));
    let model = root.join("model");
    std::fs::create_dir_all(&model).unwrap();
    let mut longer = bin.to_vec();
    longer.extend_from_slice(&[0xAB; 4096]);
    std::fs::write(root.join("outside.bin"), bin).unwrap();
    std::fs::write(model.join("inside.bin"), &longer).unwrap();
    let with_uri = |uri: &str| {
        let mut doc: serde_json::Value = serde_json::from_slice(json).unwrap();
        doc["buffers"][0]["uri"] = uri.into();
        doc.to_string().into_bytes()
    };
    let strict = GltfReadOptions::default();
    let inside = parse_gltf_with(&with_uri("inside.bin"), "inside", Some(&model), &strict);
    assert_eq!(
        inside.unwrap().mesh.vertex_count(),
        procedural_arm(6, 5).mesh.vertex_count()
    );
    let outside = with_uri("../outside.bin");
    let err = parse_gltf_with(&outside, "outside", Some(&model), &strict).unwrap_err();
    assert!(
        err.to_string().contains("leaves the model's folder"),
        "{err}"
    );
    let open = GltfReadOptions {
        allow_external: true,
        ..strict
    };
    assert!(parse_gltf_with(&outside, "outside", Some(&model), &open).is_ok());
    let small = GltfReadOptions {
        max_buffer_bytes: 16,
        ..strict
    };
    let err = parse_gltf_with(&with_uri("inside.bin"), "small", Some(&model), &small).unwrap_err();
    assert!(err.to_string().contains("over the limit"), "{err}");
    let _ = std::fs::remove_dir_all(&root);
}
