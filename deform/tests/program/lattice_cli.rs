//! The `ffd` and `cage` subcommands end to end: outputs parse back with the input's counts,
//! identity motors reproduce the input, a cage that does not enclose the mesh and a motor for
//! a control point that does not exist exit with code 2.

use crate::common;

use deform::mesh::shapes::{icosphere, tube};
use std::path::PathBuf;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_deform"))
        .args(args)
        .output()
        .expect("run deform")
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("deform-lattice-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &std::path::Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn ffd_twists_a_bar_and_writes_obj_png_and_json() {
    let dir = scratch("ffd");
    let bar = tube(1.0, 10.0, 8, 11);
    deform::mesh::io::write_obj(&bar, dir.join("bar.obj")).unwrap();
    // Layer u = 1 of a 2x2x2 lattice (odd indices) turns 90 degrees about the bar's axis.
    let motors = r#"{"1": {"rotate": {"axis": [1, 0, 0], "degrees": 90}},
        "3": {"rotate": {"axis": [1, 0, 0], "degrees": 90}},
        "5": {"rotate": {"axis": [1, 0, 0], "degrees": 90}},
        "7": {"rotate": {"axis": [1, 0, 0], "degrees": 90}}}"#;
    std::fs::write(dir.join("m.json"), motors).unwrap();
    let (bar_obj, m_json) = (dir.join("bar.obj"), dir.join("m.json"));
    let (out_obj, out_png) = (dir.join("out.obj"), dir.join("out.png"));
    for extra in [
        &[][..],
        &["--positional"][..],
        &["--basis", "bspline-1"][..],
    ] {
        let mut args = vec![
            "ffd",
            s(&bar_obj),
            "--lattice",
            "2x2x2",
            "--box",
            "-0.5,-1,-1,10.5,1,1",
            "--motors",
            s(&m_json),
            "-o",
            s(&out_obj),
            "--png",
            s(&out_png),
            "--json",
        ];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(json["command"], "ffd");
        let out = deform::mesh::io::read_mesh(dir.join("out.obj")).unwrap();
        assert_eq!(out.vertex_count(), bar.vertex_count());
        assert!(dir.join("out.png").is_file());
    }
    // A motor for control point 8 of a 2x2x2 lattice, a flat box: exit code 2.
    std::fs::write(dir.join("bad.json"), r#"{"8": {}}"#).unwrap();
    for (motors, bounds) in [
        ("bad.json", "-0.5,-1,-1,10.5,1,1"),
        ("m.json", "0,0,0,1,0,1"),
    ] {
        let o = run(&[
            "ffd",
            s(&dir.join("bar.obj")),
            "--lattice",
            "2x2x2",
            "--box",
            bounds,
            "--motors",
            s(&dir.join(motors)),
            "-o",
            s(&dir.join("bad.obj")),
        ]);
        assert_eq!(o.status.code(), Some(2));
        assert!(!dir.join("bad.obj").exists());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn cage_identity_reproduces_the_mesh_and_a_small_cage_exits_2() {
    let dir = scratch("cage");
    let model = icosphere(1.0, 2);
    deform::mesh::io::write_obj(&model, dir.join("model.obj")).unwrap();
    deform::mesh::io::write_obj(&icosphere(1.6, 1), dir.join("cage.obj")).unwrap();
    deform::mesh::io::write_obj(&icosphere(0.5, 1), dir.join("small.obj")).unwrap();
    std::fs::write(dir.join("id.json"), r#"{"*": {}}"#).unwrap();
    for coords in ["mean-value", "harmonic"] {
        let o = run(&[
            "cage",
            s(&dir.join("model.obj")),
            "--cage",
            s(&dir.join("cage.obj")),
            "--coordinates",
            coords,
            "--grid",
            "24",
            "--motors",
            s(&dir.join("id.json")),
            "-o",
            s(&dir.join("out.obj")),
            "--quiet",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let out = deform::mesh::io::read_mesh(dir.join("out.obj")).unwrap();
        assert_eq!(out.vertex_count(), model.vertex_count());
        assert!(out
            .positions
            .iter()
            .zip(&model.positions)
            .all(|(a, b)| a.distance(*b) < 1e-9));
    }
    let o = run(&[
        "cage",
        s(&dir.join("model.obj")),
        "--cage",
        s(&dir.join("small.obj")),
        "--motors",
        s(&dir.join("id.json")),
        "-o",
        s(&dir.join("bad.obj")),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("does not enclose"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_partial_bar_cage_exits_2() {
    let Some(cages) = common::mesh_path("cages") else {
        return;
    };
    let dir = scratch("partial");
    std::fs::write(dir.join("id.json"), r#"{"*": {}}"#).unwrap();
    let o = run(&[
        "cage",
        s(&cages.join("bar.OBJ")),
        "--cage",
        s(&cages.join("bar_cage_partial.OBJ")),
        "--motors",
        s(&dir.join("id.json")),
        "-o",
        s(&dir.join("out.obj")),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("bar_cage_partial.OBJ") && err.contains("does not enclose"),
        "{err}"
    );
    assert!(!dir.join("out.obj").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// `ffd --gpu` and `cage --gpu` pose on the GPU what the CPU poses (f32: to 1e-5 of the
/// bounding-box diagonal), in both forms; a program without the `gpu` feature or a machine
/// without an adapter says so with exit code 2 and writes nothing. `--gpu=auto` poses on the
/// GPU where `--gpu` can, else on the CPU (the CPU's bits) with a note.
#[test]
fn ffd_and_cage_on_the_gpu_pose_as_the_cpu() {
    let dir = scratch("gpu");
    let bar = tube(1.0, 10.0, 8, 21);
    deform::mesh::io::write_obj(&bar, dir.join("bar.obj")).unwrap();
    let mut cage = tube(1.6, 12.0, 4, 6);
    cage.positions.iter_mut().for_each(|p| p.x -= 1.0);
    deform::mesh::io::write_obj(&cage, dir.join("cage.obj")).unwrap();
    std::fs::write(
        dir.join("m.json"),
        r#"{"1": {"rotate": {"axis": [1, 0, 0], "degrees": 60}, "translate": [0, 0.5, 0]},
            "5": {"scale": 1.2}, "*": {"translate": [0, 0, 0.1]}}"#,
    )
    .unwrap();
    let diag = bar.bounding_box().unwrap().diagonal();
    let (bar_obj, cage_obj, m) = (
        dir.join("bar.obj"),
        dir.join("cage.obj"),
        dir.join("m.json"),
    );
    let ffd = ["ffd", s(&bar_obj), "--lattice", "4x3x3"];
    let cage_args = ["cage", s(&bar_obj), "--cage", s(&cage_obj)];
    for (what, head) in [("ffd", &ffd[..]), ("cage", &cage_args[..])] {
        for form in [
            &[][..],
            &["--positional"][..],
            &["--blend", "dual-quaternion"][..],
        ] {
            let pose = |gpu: Option<&str>, out: &str| {
                let mut args: Vec<&str> = head.to_vec();
                args.extend_from_slice(&["--motors", s(&m), "-o", out, "--quiet"]);
                args.extend_from_slice(form);
                args.extend(gpu);
                run(&args)
            };
            let (cpu_obj, gpu_obj) = (dir.join("cpu.obj"), dir.join("gpu.obj"));
            let auto_obj = dir.join("auto.obj");
            let o = pose(None, s(&cpu_obj));
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            let _ = std::fs::remove_file(&gpu_obj);
            let auto = pose(Some("--gpu=auto"), s(&auto_obj));
            assert!(
                auto.status.success(),
                "{}",
                String::from_utf8_lossy(&auto.stderr)
            );
            let o = pose(Some("--gpu"), s(&gpu_obj));
            if o.status.code() == Some(2) {
                let err = String::from_utf8_lossy(&o.stderr);
                assert!(err.contains("--gpu"), "{what} {form:?}: {err}");
                assert!(!gpu_obj.exists());
                // auto fell back to the CPU: its bits, and a note (not printed: --quiet).
                assert_eq!(
                    std::fs::read(&auto_obj).unwrap(),
                    std::fs::read(&cpu_obj).unwrap(),
                    "{what} {form:?}"
                );
                let mut args: Vec<&str> = head.to_vec();
                args.extend_from_slice(&["--motors", s(&m), "-o", s(&auto_obj), "--json"]);
                args.extend_from_slice(form);
                args.push("--gpu=auto");
                let o = run(&args);
                let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
                assert_eq!(report["device"], "cpu", "{what} {form:?}");
                let err = String::from_utf8_lossy(&o.stderr);
                assert!(err.contains("posing on the CPU (--gpu=auto)"), "{err}");
                continue;
            }
            let b = deform::mesh::io::read_mesh(&auto_obj).unwrap();
            let g = deform::mesh::io::read_mesh(&gpu_obj).unwrap();
            assert_eq!(
                b.positions, g.positions,
                "{what} {form:?}: auto is the GPU's pose"
            );
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            let a = deform::mesh::io::read_mesh(&cpu_obj).unwrap();
            let b = deform::mesh::io::read_mesh(&gpu_obj).unwrap();
            let worst = a
                .positions
                .iter()
                .zip(&b.positions)
                .map(|(p, q)| p.distance(*q))
                .fold(0.0, f64::max);
            assert!(worst <= 1e-5 * diag, "{what} {form:?}: {worst:e}");
            let moved = a
                .positions
                .iter()
                .zip(&bar.positions)
                .map(|(p, q)| p.distance(*q))
                .fold(0.0, f64::max);
            assert!(moved > 0.1, "{what} {form:?}: it moved");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
