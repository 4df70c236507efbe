//! `deform skin` end to end.

use crate::common::data_dir;
use crate::gltf_out;
use deform::skinning::read_gltf;

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
