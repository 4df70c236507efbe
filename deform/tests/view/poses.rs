//! What the server poses is what the library poses: handles (painted over the socket), a live
//! blend switch, ARAP with the session's warm start, a rig with a joint edit, and a cut with
//! undo and redo.

use crate::client::{worst, Frame, Server};
use cga::ScaledMotor;
use deform::deformers::arap::{Arap, ArapOptions, Stop, Targets};
use deform::deformers::handles::HandleOptions;
use deform::input::{parse_key_list, parse_selection_json};
use deform::mesh::shapes::{icosphere, tube, tube_ring};
use deform::skinning::{procedural_arm, JointEdit, Skinning};
use deform::surgery::{CutOptions, Frame as SurgeryFrame, Surgery};
use deform::{BlendMethod, Deformer, MotorHandles};
use glam::{DQuat, DVec3};
use serde_json::{json, Value};

fn exported(c: &mut crate::client::Client, what: &str) -> String {
    c.send(json!({"op": "export", "what": what}));
    c.until(false, |f| match f {
        Frame::Text(v) if v["type"] == "file" => Some(v["text"].as_str().unwrap().to_string()),
        _ => None,
    })
}

/// The name and bytes of the `.glb` the server exports (sent as base64).
fn exported_glb(c: &mut crate::client::Client) -> (String, Vec<u8>) {
    use base64::Engine;
    c.send(json!({"op": "export", "what": "glb"}));
    let (name, text) = c.until(false, |f| match f {
        Frame::Text(v) if v["type"] == "file" => {
            assert_eq!(v["base64"], true);
            Some((
                v["name"].as_str().unwrap().to_string(),
                v["text"].as_str().unwrap().to_string(),
            ))
        }
        _ => None,
    });
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(text)
        .unwrap();
    (name, bytes)
}

#[test]
fn painted_handles_pose_as_the_library_poses_them_and_the_blend_switches_live() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    let s = c.state();
    assert_eq!(s["scene"], "sphere");
    assert_eq!(s["groups"].as_array().unwrap().len(), 3);
    // Paint a fourth group where a ray from +z meets the sphere, then bind.
    c.send(
        json!({"op": "paint", "origin": [0.0, 0.0, 5.0], "direction": [0.0, 0.0, -1.0],
        "radius": 0.3, "group": 3}),
    );
    let painted = c.until(false, |f| match f {
        Frame::Groups(g) => Some(g.clone()),
        _ => None,
    });
    let s = c.state();
    assert_eq!(s["groups"].as_array().unwrap().len(), 4);
    assert_eq!(s["stale"], true);
    c.send(json!({"op": "bind"}));
    assert_eq!(c.state()["stale"], false);
    let mesh = icosphere(1.0, 4);
    let selection = exported(&mut c, "selection");
    let sel = parse_selection_json(&selection, mesh.vertex_count(), "export").unwrap();
    assert_eq!(sel.groups.len(), 4);
    for &v in &sel.groups[3] {
        let p = mesh.positions[v as usize];
        assert!((p - DVec3::Z).length() < 0.31, "painted vertex {v} at {p}");
    }
    assert!(sel.groups[3].len() > 10);
    for (g, vs) in sel.groups.iter().enumerate() {
        assert!(vs.iter().all(|&v| painted[v as usize] as usize == g + 1));
    }
    let grouped: usize = sel.groups.iter().map(Vec::len).sum();
    assert_eq!(painted.iter().filter(|&&g| g > 0).count(), grouped);

    let specs = json!([{}, {"translate": [0, 0.8, 0], "scale": 1.4, "center": [0, 1, 0]},
        {"rotate": {"axis": [1, 0, 0], "degrees": 90, "center": [1, 0, 0]}},
        {"translate": [0, 0, 0.5], "rotate": {"axis": [0, 1, 0], "degrees": 30, "center": [0, 0, 1]}}]);
    let keys = parse_key_list(&specs.to_string(), "specs").unwrap();
    c.send(json!({"op": "motors", "seq": 7, "motors": specs}));
    let got = c.positions(7);
    let rest = [ScaledMotor::IDENTITY; 4];
    for method in [BlendMethod::MotorLog, BlendMethod::DualQuaternion] {
        if method != BlendMethod::MotorLog {
            c.send(json!({"op": "method", "method": "handles", "blend": method.name()}));
            assert_eq!(c.state()["blend"], method.name());
        }
        let got = if method == BlendMethod::MotorLog {
            got.clone()
        } else {
            c.positions(0)
        };
        let options = HandleOptions {
            method,
            ..HandleOptions::default()
        };
        let handles = MotorHandles::bind_with(&mesh, &sel.sets(), &rest, options).unwrap();
        let mut want = mesh.positions.clone();
        handles.pose(&keys, &mut want).unwrap();
        let e = worst(&got, &want);
        assert!(e <= 1e-12, "{}: {e}", method.name());
        assert!(worst(&got, &mesh.positions) > 0.4, "it moved");
    }
    // Colour by group 3's harmonic coordinate: 1 on its handle, in [0, 1] everywhere.
    // (Requests are answered in order: the last field before the export's file is ours.)
    c.send(json!({"op": "field", "name": "harmonic", "group": 3}));
    c.send(json!({"op": "export", "what": "motors"}));
    let mut field = Vec::new();
    c.until(false, |f| match f {
        Frame::Field(v) => {
            field = v.clone();
            None
        }
        Frame::Text(v) if v["type"] == "file" => Some(()),
        _ => None,
    });
    assert_eq!(field.len(), mesh.vertex_count());
    assert!(field.iter().all(|x| (-1e-6..=1.0 + 1e-6).contains(x)));
    assert!(sel.groups[3]
        .iter()
        .all(|&v| (field[v as usize] - 1.0).abs() < 1e-6));
    // The posed surface as .glb: the library's bytes for the positions the server sent
    // (validated by .ci/run with the other glTF files the tests write).
    c.send(json!({"op": "method", "method": "handles", "blend": "motor-log"}));
    let posed = c.positions(0);
    let (name, glb) = exported_glb(&mut c);
    let want =
        deform::mesh::io::glb_bytes(&deform::Mesh::new(posed, mesh.triangles.clone())).unwrap();
    assert_eq!(name, "sphere-posed.glb");
    assert!(glb == want, "the exported .glb is not the library's");
    let out = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gltf-out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join(format!("view-{name}")), &glb).unwrap();
    // The exported motors replay the same pose.
    let motors: Value = serde_json::from_str(&exported(&mut c, "motors")).unwrap();
    let replay = deform::input::parse_group_motors(&motors.to_string(), "m", 4).unwrap();
    for (a, b) in replay.iter().zip(&keys) {
        let p = DVec3::new(0.3, -0.2, 0.9);
        assert!((a.transform_point(p) - b.transform_point(p)).length() < 1e-12);
    }
}

#[test]
fn arap_frames_warm_start_from_the_last_one_as_a_pose_loop_with_one_scratch_does() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    c.send(json!({"op": "scene", "name": "beam"}));
    let s = c.state();
    assert_eq!(s["method"], "arap");
    let first = c.positions(0);
    let end = json!({"translate": [-3.0, 4.0, 0.0],
        "rotate": {"axis": [0, 0, 1], "degrees": 60, "center": [10, 0, 0]}});
    c.send(json!({"op": "motors", "seq": 1, "motors": [{}, end]}));
    let second = c.positions(1);

    let beam = tube(1.0, 10.0, 6, 41);
    let (g0, g1) = (tube_ring(6, 0), tube_ring(6, 40));
    let arap = Arap::bind(&beam, &[], &[&g0, &g1], ArapOptions::default()).unwrap();
    let mut scratch = arap.scratch().unwrap();
    let mut out = beam.positions.clone();
    let identity = [ScaledMotor::IDENTITY; 2];
    let stop = Stop::Iterations(2);
    arap.pose_using(
        &Targets::Motors(&identity),
        stop,
        &mut scratch,
        &mut out,
        |_, _| {},
    )
    .unwrap();
    assert!(worst(&first, &out) <= 1e-12, "{}", worst(&first, &out));
    let keys = parse_key_list(&json!([{}, end]).to_string(), "k").unwrap();
    arap.pose_using(
        &Targets::Motors(&keys),
        stop,
        &mut scratch,
        &mut out,
        |_, _| {},
    )
    .unwrap();
    assert!(worst(&second, &out) <= 1e-12, "{}", worst(&second, &out));
    let tip = keys[1].transform_point(beam.positions[g1[0] as usize]);
    assert!(
        (second[g1[0] as usize] - tip).length() < 1e-9,
        "the handle follows its motor"
    );
}

#[test]
fn the_rig_poses_as_the_library_poses_it_and_a_cut_undoes_and_redoes() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    c.send(json!({"op": "scene", "name": "arm"}));
    let s = c.state();
    assert_eq!(s["kind"], "rig");
    let rig = procedural_arm(24, 81);
    assert_eq!(s["vertices"], rig.mesh.vertex_count());
    c.send(
        json!({"op": "rig", "seq": 3, "animation": 0, "time": 1.0, "backend": "motor-log",
        "edits": [{"joint": 1, "motor": {"scale": 1.3}}]}),
    );
    let got = c.positions(3);
    let edit = JointEdit {
        joint: 1,
        motor: ScaledMotor::from_scale_rotation_translation(1.3, DQuat::IDENTITY, DVec3::ZERO),
    };
    let pose = rig.pose(Some(0), 1.0, &[edit]).unwrap();
    let skin = Skinning::bind(&rig, BlendMethod::MotorLog).unwrap();
    let mut want = rig.mesh.positions.clone();
    skin.pose(pose.skin_motors().unwrap(), &mut want).unwrap();
    assert!(worst(&got, &want) <= 1e-12, "{}", worst(&got, &want));

    // Cut in the posed frame; both pieces stay on the skeleton.
    let (point, normal) = (DVec3::new(3.7, 0.0, 0.0), DVec3::new(1.0, 0.3, 0.0));
    c.send(json!({"op": "cut", "point": point.to_array(), "normal": normal.to_array()}));
    let (cut_mesh, triangles) = c.until(false, |f| match f {
        Frame::Mesh { rest, triangles } => Some((rest.len(), triangles.len())),
        _ => None,
    });
    let s = c.state();
    assert_eq!(s["rig"]["undo"], 1);
    let n = normal.normalize();
    let plane = cga::Plane::from_normal_distance(n, n.dot(point));
    // The page drew the frame by motor log blending: its keys map the new vertices back.
    let prepared =
        deform::blend::PreparedKeys::new(pose.skin_motors().unwrap(), BlendMethod::MotorLog)
            .unwrap();
    let frame = SurgeryFrame::Blended {
        positions: &want,
        keys: &prepared,
    };
    let cut = Surgery::new(&rig.mesh, &rig.influences)
        .unwrap()
        .cut(
            &plane,
            frame,
            &CutOptions {
                cap: true,
                ..CutOptions::default()
            },
        )
        .unwrap();
    let pieces: usize = cut.pieces.iter().map(|p| p.mesh.mesh.vertex_count()).sum();
    assert_eq!(cut_mesh, pieces);
    let faces: usize = cut
        .pieces
        .iter()
        .map(|p| p.mesh.mesh.triangle_count())
        .sum();
    assert_eq!(triangles, faces);
    assert!(cut_mesh > rig.mesh.vertex_count());
    // The cut rig animates.
    c.send(
        json!({"op": "rig", "seq": 4, "animation": 0, "time": 2.0, "backend": "dual-quaternion"}),
    );
    assert_eq!(c.positions(4).len(), cut_mesh);
    // The cut rig with its edit baked, as .glb (validated by .ci/run with the others).
    c.send(
        json!({"op": "rig", "seq": 6, "animation": 0, "time": 1.0, "backend": "motor-log",
        "edits": [{"joint": 1, "motor": {"scale": 1.3}}]}),
    );
    // Posed again as it was cut (motor log blending), the new vertices lie on the plane.
    let again = c.positions(6);
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    let mut first = 0;
    for piece in &cut.pieces {
        for (v, o) in piece.origin.iter().enumerate() {
            if let deform::surgery::VertexOrigin::Edge { .. } = o {
                let d = plane.signed_distance(again[first + v]).abs();
                assert!(
                    d < 1e-9 * diag,
                    "new vertex {} is {d} off the plane",
                    first + v
                );
            }
        }
        first += piece.mesh.mesh.vertex_count();
    }
    let (name, bytes) = exported_glb(&mut c);
    let back =
        deform::skinning::parse_gltf(&bytes, &name, None).expect("the exported .glb reads back");
    assert_eq!(back.mesh.vertex_count(), cut_mesh);
    let out = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gltf-out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join(format!("view-{name}")), &bytes).unwrap();
    c.send(json!({"op": "undo"}));
    let s = c.state();
    // The replay line names the file the export wrote.
    assert!(
        s["replay"].as_str().unwrap().contains(&name),
        "{}",
        s["replay"]
    );
    assert_eq!(
        (s["vertices"].as_u64(), s["rig"]["redo"].as_u64()),
        (Some(rig.mesh.vertex_count() as u64), Some(1))
    );
    c.send(json!({"op": "redo"}));
    assert_eq!(c.state()["vertices"], cut_mesh);
    c.send(json!({"op": "redo"}));
    assert!(c.error().contains("nothing to redo"));
}

#[test]
fn tears_and_drills_from_rays_make_what_the_library_makes_and_undo() {
    use deform::surgery::{Drill, DrillOptions, FaceBvh, Scalpel, TearOptions};
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    c.send(json!({"op": "scene", "name": "arm"}));
    let s = c.state();
    let rig = procedural_arm(24, 81);
    let n = rig.mesh.vertex_count();
    assert_eq!(s["vertices"], n);
    // The library's own reading of the same rays (rest pose: nothing posed yet).
    let b = rig.mesh.bounding_box().unwrap();
    let size = (b.max - b.min).length();
    let bvh = FaceBvh::new(&rig.mesh);
    let down = -DVec3::Z;
    let hit = |x: f64| {
        bvh.ray_hit(&rig.mesh, DVec3::new(x, 0.05, 5.0), down)
            .unwrap()
            .point
    };
    let surgery = Surgery::new(&rig.mesh, &rig.influences).unwrap();

    let rays: Vec<Value> = [4.6, 5.4, 6.3]
        .iter()
        .map(|x| json!([[x, 0.05, 5.0], [0, 0, -1]]))
        .collect();
    c.send(json!({"op": "tear", "rays": rays, "open": 0.2}));
    let torn = c.state();
    let blades: Vec<Scalpel> = [4.6, 5.4, 6.3]
        .iter()
        .map(|&x| Scalpel {
            a: hit(x) - 0.02 * size * down,
            b: hit(x) + 0.08 * size * down,
        })
        .collect();
    let options = TearOptions {
        open: 0.2,
        ..TearOptions::default()
    };
    let tear = surgery.tear(&blades, SurgeryFrame::Rest, &options).unwrap();
    assert_eq!(torn["vertices"], tear.mesh.mesh.vertex_count());
    assert!(tear.mesh.mesh.vertex_count() > n);
    c.send(json!({"op": "undo"}));
    assert_eq!(c.state()["vertices"], n);

    c.send(json!({"op": "drill", "origin": [5.0, 0.05, 5.0], "direction": [0, 0, -1], "radius": 0.01, "depth": 0.15}));
    let drilled = c.state();
    let drill = Drill {
        tip: hit(5.0) - 0.25 * 0.15 * size * down,
        end: hit(5.0) + 0.15 * size * down,
        radius: 0.01 * size,
    };
    let hole = surgery
        .drill(&drill, SurgeryFrame::Rest, &DrillOptions::default())
        .unwrap();
    assert_eq!(drilled["vertices"], hole.mesh.mesh.vertex_count());
    assert_ne!(hole.mesh.mesh.vertex_count(), n);
    assert_eq!(
        drilled["rig"]["undo"], 1,
        "the tear was undone, so the drill is the only step"
    );
    // Rays that miss, and silly sizes, are refused with the rig unchanged.
    c.send(json!({"op": "drill", "origin": [5.0, 50.0, 5.0], "direction": [0, 0, -1], "radius": 0.01, "depth": 0.15}));
    assert!(c.error().contains("aim at the surface"));
    c.send(json!({"op": "drill", "origin": [5.0, 0.05, 5.0], "direction": [0, 0, -1], "radius": -1, "depth": 0.15}));
    assert!(c.error().contains("positive"));
    c.send(json!({"op": "tear", "rays": [[[5.0, 50.0, 5.0], [0, 0, -1]]]}));
    assert!(c.error().contains("met the surface 0"));
    c.send(json!({"op": "undo"}));
    assert_eq!(c.state()["vertices"], n);
}

#[test]
fn arap_energy_and_local_step_are_the_library_options() {
    use deform::deformers::arap::{ArapEnergy, LocalStep};
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    c.send(json!({"op": "scene", "name": "beam"}));
    c.state();
    let end = json!({"translate": [0.0, 3.0, 1.0]});
    c.send(json!({"op": "motors", "seq": 1, "motors": [{}, end]}));
    c.positions(1);
    c.send(
        json!({"op": "method", "method": "arap", "blend": "motor-log", "options":
        {"iterations": 3, "energy": "spokes", "local-step": "svd"}}),
    );
    let s = c.state();
    assert_eq!(
        (
            s["options"]["energy"].as_str(),
            s["options"]["local-step"].as_str()
        ),
        (Some("spokes"), Some("svd"))
    );
    // The rebind poses the current motors from the rest pose.
    let got = c.positions(0);
    let beam = tube(1.0, 10.0, 6, 41);
    let (g0, g1) = (tube_ring(6, 0), tube_ring(6, 40));
    let options = ArapOptions {
        energy: ArapEnergy::Spokes,
        local_step: LocalStep::Svd,
        ..ArapOptions::default()
    };
    let arap = Arap::bind(&beam, &[], &[&g0, &g1], options).unwrap();
    let keys = parse_key_list(&json!([{}, end]).to_string(), "k").unwrap();
    let mut out = beam.positions.clone();
    let mut scratch = arap.scratch().unwrap();
    arap.pose_using(
        &Targets::Motors(&keys),
        Stop::Iterations(3),
        &mut scratch,
        &mut out,
        |_, _| {},
    )
    .unwrap();
    assert!(worst(&got, &out) <= 1e-12, "{}", worst(&got, &out));
    c.send(json!({"op": "method", "method": "arap", "blend": "motor-log", "options": {"energy": "elastic"}}));
    assert!(c.error().contains("no ARAP energy"));
}

/// A slow request is announced (`binding`, what it is), answered, then closed by `idle`, also
/// when it is refused; a quick one (a pose) has neither. The announcement carries the time the
/// same request took last time (`expect_ms`, for the page's progress bar) once there was one.
#[test]
fn slow_requests_are_announced_and_closed() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    let groups = c.state()["groups"].as_array().unwrap().len();
    // The text replies until `idle`, in order, without the `posed` replies of poses sent
    // before (the opening pose's may still be on its way), and the `binding` reply's estimate.
    let texts = |c: &mut crate::client::Client| {
        let mut seen = Vec::new();
        let mut expect = None;
        c.until(true, |f| {
            if let Frame::Text(v) = f {
                let t = v["type"].as_str().unwrap().to_string();
                if t == "binding" {
                    expect = v.get("expect_ms").map(|e| e.as_f64().expect("a number"));
                }
                let done = t == "idle";
                seen.push(t);
                return done.then_some(());
            }
            None
        });
        seen.retain(|t| t != "posed");
        (seen, expect)
    };
    c.send(json!({"op": "method", "method": "arap", "blend": "motor-log"}));
    assert_eq!(
        texts(&mut c),
        (vec!["binding".into(), "state".into(), "idle".into()], None)
    );
    c.send(json!({"op": "method", "method": "nonsense", "blend": "motor-log"}));
    let (seen, expect) = texts(&mut c);
    assert_eq!(
        (seen, expect),
        (vec!["binding".into(), "error".into(), "idle".into()], None)
    );
    // A pose is not slow: its reply and positions, no `binding`.
    c.send(json!({"op": "motors", "seq": 9, "motors": vec![json!({}); groups]}));
    c.positions(9);
    // Binding ARAP again: expected to take as long as the first time.
    c.send(json!({"op": "bind"}));
    let (seen, expect) = texts(&mut c);
    assert_eq!(seen, ["binding", "state", "idle"]);
    assert!(expect.is_some_and(|ms| ms > 0.0), "{expect:?}");
    // Another method on the same scene has no estimate yet.
    c.send(json!({"op": "method", "method": "handles", "blend": "motor-log"}));
    assert_eq!(texts(&mut c).1, None);
}

/// The page's positions come in f32 once it asks (half the bytes): each the f64 frame's value
/// rounded; f64 again when asked; an unknown precision is a malformed message.
#[test]
fn positions_come_in_f32_when_asked_and_round_the_f64_ones() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    assert_eq!(c.state()["groups"].as_array().unwrap().len(), 3);
    let specs = json!([{"translate": [0, 0.3, 0]}, {"scale": 1.2, "center": [0, 1, 0]},
        {"rotate": {"axis": [1, 0, 0], "degrees": 40, "center": [1, 0, 0]}}]);
    c.send(json!({"op": "motors", "seq": 5, "motors": specs}));
    let exact = c.positions(5);
    c.send(json!({"op": "precision", "positions": "f32"}));
    c.send(json!({"op": "motors", "seq": 6, "motors": specs}));
    let rounded = c.until(false, |f| match f {
        Frame::PositionsF32 { seq: 6, posed } => Some(posed.clone()),
        Frame::Positions { seq: 6, .. } => panic!("f64 positions after asking for f32"),
        _ => None,
    });
    assert_eq!(rounded.len(), exact.len());
    for (r, e) in rounded.iter().zip(&exact) {
        assert_eq!(*r, [e.x as f32, e.y as f32, e.z as f32]);
    }
    c.send(json!({"op": "precision", "positions": "f64"}));
    c.send(json!({"op": "motors", "seq": 7, "motors": specs}));
    assert_eq!(c.positions(7), exact);
    c.send(json!({"op": "precision", "positions": "f16"}));
    assert!(matches!(
        c.until(true, |f| matches!(f, Frame::Closed)
            .then_some(Frame::Closed)),
        Frame::Closed
    ));
}
