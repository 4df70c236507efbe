//! `deform view MODEL`: a mesh of the user's with its selection (handles and the spline posed
//! as the library poses them), a glTF rig from the shared data, and models the program must
//! refuse before it serves anything.

use crate::client::{worst, Server};
use cga::ScaledMotor;
use deform::deformers::handles::HandleOptions;
use deform::deformers::spline::SplineOptions;
use deform::input::parse_key_list;
use deform::mesh::shapes::{tube, tube_ring};
use deform::skinning::{read_gltf, Skinning};
use deform::{BlendMethod, Deformer, MotorHandles, SplineDeformer};
use glam::DVec3;
use serde_json::json;
use std::path::PathBuf;
use std::process::Command;

use crate::common;

/// A fresh folder for this test's files.
fn folder(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("deform-view-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn a_mesh_with_its_selection_poses_by_handles_and_by_the_spline_as_the_library_does() {
    let dir = folder("mesh");
    let bar = tube(1.0, 10.0, 12, 31);
    let (first, middle, last) = (tube_ring(12, 0), tube_ring(12, 15), tube_ring(12, 30));
    let obj = dir.join("bar.obj");
    deform::mesh::io::write_obj(&bar, &obj).unwrap();
    let sel = dir.join("bar-groups.json");
    std::fs::write(
        &sel,
        json!({"0": first, "1": middle, "2": last}).to_string(),
    )
    .unwrap();
    let server = Server::start(&[obj.to_str().unwrap(), "--select", sel.to_str().unwrap()]);
    let mut c = server.connect(None).expect("connects");
    let s = c.state();
    assert_eq!(
        (s["scene"].as_str(), s["method"].as_str()),
        (Some("bar.obj"), Some("handles"))
    );
    assert_eq!(s["groups"].as_array().unwrap().len(), 3);
    assert!(
        s["scenes"].as_array().unwrap().contains(&json!("sphere")),
        "the demo scenes too"
    );
    c.positions(0);

    let specs = json!([{}, {"translate": [0, 2, 0]},
        {"rotate": {"axis": [1, 0, 0], "degrees": 90, "center": [10, 0, 0]}, "translate": [0, 3, 1]}]);
    let keys = parse_key_list(&specs.to_string(), "specs").unwrap();
    let sets: [&[u32]; 3] = [&first, &middle, &last];
    c.send(json!({"op": "motors", "seq": 1, "motors": specs}));
    let got = c.positions(1);
    let rest = [ScaledMotor::IDENTITY; 3];
    let handles = MotorHandles::bind_with(&bar, &sets, &rest, HandleOptions::default()).unwrap();
    let mut want = bar.positions.clone();
    handles.pose(&keys, &mut want).unwrap();
    assert!(
        worst(&got, &want) <= 1e-12,
        "handles: {}",
        worst(&got, &want)
    );

    // The spline: each group's centre is a key at rest; a key posed is its group's motor after it.
    c.send(json!({"op": "method", "method": "spline", "blend": "motor-log"}));
    assert_eq!(c.state()["method"], "spline");
    c.positions(0);
    c.send(json!({"op": "motors", "seq": 2, "motors": specs}));
    let got = c.positions(2);
    let centre =
        |g: &[u32]| g.iter().map(|&v| bar.positions[v as usize]).sum::<DVec3>() / g.len() as f64;
    let rest: Vec<ScaledMotor> = sets
        .iter()
        .map(|g| ScaledMotor::from_motor(cga::Motor::from_translation(centre(g))))
        .collect();
    let spline =
        SplineDeformer::bind(&bar, &first, &last, &rest, SplineOptions::default()).unwrap();
    let posed: Vec<ScaledMotor> = rest.iter().zip(&keys).map(|(r, k)| r.then(*k)).collect();
    let mut want = bar.positions.clone();
    spline.pose(&posed, &mut want).unwrap();
    assert!(
        worst(&got, &want) <= 1e-12,
        "spline: {}",
        worst(&got, &want)
    );
    assert!(worst(&got, &bar.positions) > 1.0, "it moved");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_gltf_rig_from_the_shared_data_animates_as_the_library_skins_it() {
    let Some(data) = common::data_dir() else {
        return;
    };
    let path = data.join("gltf/CesiumMan.glb");
    let server = Server::start(&[path.to_str().unwrap()]);
    let mut c = server.connect(None).expect("connects");
    let s = c.state();
    assert_eq!(
        (s["scene"].as_str(), s["kind"].as_str()),
        (Some("CesiumMan.glb"), Some("rig"))
    );
    let rig = read_gltf(&path).unwrap();
    assert_eq!(
        s["rig"]["joints"].as_array().unwrap().len(),
        rig.joints.len()
    );
    c.send(
        json!({"op": "rig", "seq": 5, "animation": 0, "time": 0.5, "backend": "dual-quaternion"}),
    );
    let got = c.positions(5);
    let pose = rig.pose(Some(0), 0.5, &[]).unwrap();
    let skin = Skinning::bind(&rig, BlendMethod::DualQuaternion).unwrap();
    let mut want = rig.mesh.positions.clone();
    skin.pose(pose.skin_motors().unwrap(), &mut want).unwrap();
    assert!(worst(&got, &want) <= 1e-12, "{}", worst(&got, &want));
}

/// A libigl rig (mesh, TGF skeleton, DMAT weights) is a rig in the editor: a joint edit poses
/// as the library skins it, and a cut in that frame re-rigs it.
#[test]
fn a_libigl_rig_from_the_shared_data_poses_as_the_library_skins_it() {
    let Some(data) = common::data_dir() else {
        return;
    };
    let lib = data.join("meshes/libigl");
    let arg = |f: &str| lib.join(f).display().to_string();
    let (mesh, tgf, dmat) = (arg("arm.obj"), arg("arm.tgf"), arg("arm-weights.dmat"));
    let server = Server::start(&[&mesh, "--skeleton", &tgf, "--weights", &dmat]);
    let mut c = server.connect(None).expect("connects");
    let s = c.state();
    assert_eq!(
        (s["scene"].as_str(), s["kind"].as_str()),
        (Some("arm.obj"), Some("rig"))
    );
    let rig = common::libigl_rig("arm").unwrap();
    assert_eq!(
        s["rig"]["joints"].as_array().unwrap().len(),
        rig.joints.len()
    );
    let edit = json!({"rotate": {"axis": [0, 0, 1], "degrees": 30}, "scale": 1.1});
    c.send(
        json!({"op": "rig", "seq": 7, "animation": null, "time": 0.0,
        "backend": "motor-log", "edits": [{"joint": 1, "motor": edit}]}),
    );
    let got = c.positions(7);
    let motor = deform::input::parse_motor(&edit.to_string(), "edit").unwrap();
    let pose = rig
        .pose(
            None,
            0.0,
            &[deform::skinning::JointEdit { joint: 1, motor }],
        )
        .unwrap();
    let skin = Skinning::bind(&rig, BlendMethod::MotorLog).unwrap();
    let mut want = rig.mesh.positions.clone();
    skin.pose(pose.skin_motors().unwrap(), &mut want).unwrap();
    assert!(worst(&got, &want) <= 1e-12, "{}", worst(&got, &want));
    assert!(worst(&got, &rig.mesh.positions) > 1e-3, "the edit moved it");
    // Cut across the arm's middle in the posed frame: more vertices, one undo step.
    let b = rig.mesh.bounding_box().unwrap();
    c.send(json!({"op": "cut", "point": b.center().to_array(), "normal": [1, 0.1, 0]}));
    let s = c.state();
    assert!(s["vertices"].as_u64().unwrap() > rig.mesh.vertex_count() as u64);
    assert_eq!(s["rig"]["undo"], 1);
}

#[test]
fn models_it_cannot_serve_are_refused_before_it_listens() {
    let dir = folder("refused");
    let obj = dir.join("bar.obj");
    deform::mesh::io::write_obj(&tube(1.0, 4.0, 6, 5), &obj).unwrap();
    let sel = dir.join("sel.json");
    std::fs::write(&sel, r#"{"0": [999]}"#).unwrap();
    let cases: Vec<(Vec<String>, &str)> = vec![
        (
            vec![dir.join("missing.obj").display().to_string()],
            "missing.obj",
        ),
        (
            vec!["--select".into(), sel.display().to_string()],
            "--select needs a MODEL",
        ),
        (
            vec![
                obj.display().to_string(),
                "--select".into(),
                sel.display().to_string(),
            ],
            "999",
        ),
        (
            vec![
                dir.join("x.glb").display().to_string(),
                "--select".into(),
                sel.display().to_string(),
            ],
            "--select is for a mesh",
        ),
        (
            vec![
                dir.join("x.glb").display().to_string(),
                "--skeleton".into(),
                sel.display().to_string(),
                "--weights".into(),
                sel.display().to_string(),
            ],
            "a glTF model has its own",
        ),
        (
            vec![
                obj.display().to_string(),
                "--skeleton".into(),
                sel.display().to_string(),
            ],
            "--weights",
        ),
    ];
    for (args, says) in cases {
        let out = Command::new(env!("CARGO_BIN_EXE_deform"))
            .arg("view")
            .args(&args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}: no address printed");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
