//! `deform surgery` end to end.

use deform::skinning::{procedural_arm, Skinning};
use deform::{BlendMethod, Deformer};
use glam::DVec3;

/// The CLI: cut, tear and drill a rig into `.glb` files that keep the skin and animations
/// (checked by the Khronos validator in CI, read back and animated here); exit code 2 on bad
/// input.
#[test]
fn surgery_cli() {
    use std::process::Command;
    let out = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gltf-out");
    std::fs::create_dir_all(&out).unwrap();
    let exe = env!("CARGO_BIN_EXE_deform");
    let run = |args: &[&str]| Command::new(exe).args(args).output().unwrap();
    let rig_path = out.join("arm-rig.glb");
    let rig = procedural_arm(24, 81);
    deform::skinning::write_glb(&rig, &Default::default(), &rig_path).unwrap();
    let model = rig_path.to_str().unwrap();
    let cases: [(&str, Vec<&str>); 4] = [
        (
            "arm-cut.glb",
            vec!["cut", model, "--plane", "1,0.2,0,3.1", "--cap"],
        ),
        (
            "arm-tear.glb",
            vec![
                "tear",
                model,
                "--scalpel",
                "2,0.05,1.2:2,0.05,0.2",
                "--scalpel",
                "3,0.1,1.2:3,0.1,0.2",
                "--open",
                "0.2",
            ],
        ),
        (
            "arm-drill.glb",
            vec![
                "drill",
                model,
                "--tip=1.5,0.1,-2",
                "--end",
                "1.5,0.1,2",
                "--radius",
                "0.3",
            ],
        ),
        (
            "arm-cut-posed.glb",
            vec!["cut", model, "--plane", "0,1,0,2", "--time", "2"],
        ),
    ];
    for (file, mut args) in cases {
        let o = out.join(file);
        let path = o.to_str().unwrap().to_string();
        args.extend(["-o", &path, "--json"]);
        let r = run(&args);
        assert!(
            r.status.success(),
            "{file}: {}",
            String::from_utf8_lossy(&r.stderr)
        );
        let back = deform::skinning::read_gltf(&o).unwrap();
        assert_eq!(back.animations.len(), 1, "{file}: the animation is kept");
        assert_eq!(back.joints.len(), 3);
        let pose = back.pose(Some(0), 1.0, &[]).unwrap();
        let b = Skinning::bind(&back, BlendMethod::Conformal).unwrap();
        let mut p = vec![DVec3::ZERO; back.mesh.vertex_count()];
        b.pose(pose.skin_motors().unwrap(), &mut p).unwrap();
        assert!(p.iter().all(|x| x.is_finite()), "{file} re-animates");
    }
    for args in [
        vec!["cut", model, "--plane", "1,0,0,100", "-o", "/tmp/never.glb"],
        vec!["cut", model, "--plane", "0,0,0,1", "-o", "/tmp/never.glb"],
        vec![
            "drill",
            model,
            "--tip=0,9,0",
            "--end",
            "1,9,0",
            "--radius",
            "0.1",
            "-o",
            "/tmp/never.glb",
        ],
        vec![
            "tear",
            model,
            "--scalpel",
            "2,0,1.2:2,0,0.2",
            "-o",
            "/tmp/never.glb",
        ],
        vec!["cut", model, "--plane", "1,0,0,3", "-o", model],
    ] {
        let r = run(&args);
        assert_eq!(r.status.code(), Some(2), "{args:?}");
        assert!(!r.stderr.is_empty());
    }
}
