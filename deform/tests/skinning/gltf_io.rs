//! glTF and glb input and output: round trips, normals, a second joint set, morph targets,
//! external buffers, coordinates beyond single precision, and bad glTF or rig input.

use crate::common::{self, data_dir};
use crate::{gltf, gltf_out, max_dist, skin};
use cga::ScaledMotor;
use deform::skinning::{glb_bytes, parse_gltf, procedural_arm, GlbOptions, Rig, Skinning};
use deform::{BlendMethod, Deformer};
use glam::{DQuat, DVec3};

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

/// Every written primitive has unit normals: the model's own where it has them, none for a
/// flat-shaded glTF model, else the rig's smooth vertex normals (summed over the copies of a
/// vertex along UV seams).
fn check_written_normals(bytes: &[u8], rig: &deform::skinning::Rig, name: &str) {
    let g = gltf::Gltf::from_slice(bytes).unwrap();
    let blob = g.blob.as_deref();
    if rig.look.flat {
        // A model without normals stays flat shaded: none written.
        for prim in g.meshes().flat_map(|m| m.primitives().collect::<Vec<_>>()) {
            assert!(prim.get(&gltf::Semantic::Normals).is_none(), "{name}");
        }
        return;
    }
    let want: Vec<glam::DVec3> = match rig.look.attribute("NORMAL") {
        Some(own) => own
            .values
            .chunks_exact(3)
            .map(|c| glam::Vec3::from_slice(c).as_dvec3())
            .collect(),
        None => rig.mesh.seamless_vertex_normals(),
    };
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

/// `glb` with its header's length field set to `stated`.
fn with_stated_length(glb: &[u8], stated: u32) -> Vec<u8> {
    let mut out = glb.to_vec();
    out[8..12].copy_from_slice(&stated.to_le_bytes());
    out
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
    // A binary header whose stated length is below its own size (the `gltf` crate's
    // subtraction overflowed: a panic in a debug build), or not the file's.
    let fox = std::fs::read(dir.join("gltf/Fox.glb")).unwrap();
    let mut trailing = fox.clone();
    trailing.extend_from_slice(&[0; 8]);
    for (bytes, words) in [
        (with_stated_length(&fox, 0), "as 0 bytes"),
        (with_stated_length(&fox, 11), "as 11 bytes"),
        (
            with_stated_length(&fox, fox.len() as u32 - 4),
            "follow its stated end",
        ),
        (trailing, "follow its stated end"),
    ] {
        match parse_gltf(&bytes, "Fox.glb", None) {
            Err(SkinError::Gltf { message, .. }) => assert!(message.contains(words), "{message}"),
            other => panic!("{words}: {other:?}"),
        }
    }
    // An accessor offset that overflows with its view's (the view of POSITION starts at 48):
    // it panicked in a debug build and wrapped to the buffer's start in a release build.
    for offset in [u64::MAX - 47, u64::MAX] {
        match simple_skin_edited(|d| d["accessors"][1]["byteOffset"] = offset.into()).unwrap() {
            Err(SkinError::Data { message, .. }) => {
                assert!(message.contains("accessor 1: size overflows"), "{message}")
            }
            other => panic!("offset {offset}: {:?}", other.map(|_| ())),
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
    // A non-uniform scale on a joint: matrices skin it exactly, motors take the nearest
    // similarity and name the joints (and their deviation) they approximate.
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
    assert!(pose.skin_motors().is_ok());
    let far: Vec<(usize, f64)> = pose.approximated_joints().collect();
    assert!(!far.is_empty(), "the squashed joint is approximated");
    // Singular values 1, 0.5, 1: the nearest similarity has scale 0.75, deviation 1/3.
    assert!(
        far.iter().all(|&(_, d)| (d - 1.0 / 3.0).abs() < 1e-9),
        "{far:?}"
    );
    assert!(squash.similarity_shift(&pose) > 0.0);
    assert!(squash.pose(Some(3), 0.0, &[]).is_err());
    assert!(squash.joint_index("no such joint").is_err());
    assert_eq!(squash.joint_index("elbow").unwrap(), 1);
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

/// Morph targets are kept (issue 45): each target is a look attribute `TARGET{k}_POSITION`, the
/// default weights are kept and applied to the rest shape. SimpleSkin's target here is its own
/// position accessor, so weight `w` scales every rest vertex by `1 + w`.
#[test]
fn morph_targets_are_kept() {
    let load = |weights: Option<f64>| {
        simple_skin_edited(|d| {
            d["meshes"][0]["primitives"][0]["targets"] = serde_json::json!([{"POSITION": 1}]);
            if let Some(w) = weights {
                d["meshes"][0]["weights"] = serde_json::json!([w]);
            }
        })
        .map(|r| r.unwrap())
    };
    let (Some(plain), Some(weighted)) = (load(None), load(Some(0.5))) else {
        return;
    };
    assert_eq!(plain.look.morph_weights, vec![0.0]);
    assert_eq!(weighted.look.morph_weights, vec![0.5]);
    let target = plain
        .look
        .attribute("TARGET0_POSITION")
        .expect("target kept");
    assert_eq!(target.vertex_count(), plain.mesh.vertex_count());
    for (v, (a, b)) in plain
        .mesh
        .positions
        .iter()
        .zip(&weighted.mesh.positions)
        .enumerate()
    {
        let offset = target.row(v);
        assert!(
            (a.x - offset[0] as f64).abs() < 1e-6,
            "vertex {v}: target is the positions"
        );
        assert!(b.distance(*a * 1.5) < 1e-6, "vertex {v}: {a} -> {b}");
    }
    assert!(
        !plain.report.notes.iter().any(|n| n.contains("morph")),
        "{:?}",
        plain.report.notes
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
    // Percent-encoded names are decoded (as image URIs were); remote URIs are named as such,
    // not looked for as a folder `http:` beside the model, even where external files are allowed.
    std::fs::rename(model.join("inside.bin"), model.join("in side.bin")).unwrap();
    let encoded = parse_gltf_with(&with_uri("in%20side.bin"), "encoded", Some(&model), &strict);
    assert!(encoded.is_ok(), "{:?}", encoded.err());
    let remote = with_uri("http://example.com/inside.bin");
    let err = parse_gltf_with(&remote, "remote", Some(&model), &open).unwrap_err();
    assert!(err.to_string().contains("nothing is fetched"), "{err}");
    let _ = std::fs::remove_dir_all(&root);
}

/// Accessors stored as glTF does not allow for their use are typed errors: positions read as
/// integers (`v 3204448256 0 0`), indices as floats, times as integers or two-vectors and
/// non-normalized integer weights were all read as garbage with exit code 0. The layouts glTF
/// allows still read: normalized 16-bit weights.
#[test]
fn accessors_stored_as_gltf_forbids_are_refused() {
    let accessor_of = |doc: &serde_json::Value, what: &str| -> usize {
        let prim = &doc["meshes"][0]["primitives"][0];
        let a = match what {
            "indices" => &prim["indices"],
            "times" => &doc["animations"][0]["samplers"][0]["input"],
            a => &prim["attributes"][a],
        };
        a.as_u64().expect("an accessor index") as usize
    };
    let cases: [(&str, &str, serde_json::Value, &str); 6] = [
        ("POSITION", "componentType", 5125.into(), "POSITION"),
        ("POSITION", "componentType", 5123.into(), "POSITION"),
        ("indices", "componentType", 5126.into(), "indices"),
        ("times", "componentType", 5125.into(), "keyframe times"),
        ("times", "type", "VEC2".into(), "keyframe times"),
        ("WEIGHTS_0", "componentType", 5125.into(), "WEIGHTS"),
    ];
    for (what, key, value, named) in cases {
        let Some(r) = simple_skin_edited(|doc| {
            let a = accessor_of(doc, what);
            doc["accessors"][a][key] = value.clone();
        }) else {
            return;
        };
        let e = r.expect_err(&format!("{what} {key} = {value}"));
        let message = e.to_string();
        assert!(
            message.contains(named) && message.contains("glTF does not allow"),
            "{what} {key} = {value}: {message}"
        );
    }
    // Allowed: normalized unsigned shorts for the weights (read as they say).
    let Some(r) = simple_skin_edited(|doc| {
        let a = accessor_of(doc, "WEIGHTS_0");
        // The same bytes reinterpreted: only the layout check is under test here.
        doc["accessors"][a]["componentType"] = 5123.into();
        doc["accessors"][a]["normalized"] = true.into();
    }) else {
        return;
    };
    if let Err(e) = r {
        assert!(!e.to_string().contains("glTF does not allow"), "{e}");
    }
}
