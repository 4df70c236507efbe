//! `deform pose METHOD`: every method of the library's catalogue (`Method::ALL`, so a method
//! added to the library is tested here too) poses a bar from the command line exactly as the
//! library's `BoundMethod` does with the same settings; option values are the library's
//! names, and any other is refused with them listed.

use deform::mesh::shapes::tube_ring;
use deform::methods::bound::BoundMethod;
use deform::methods::budget::WorkBudget;
use deform::methods::harmonic_cache::HarmonicCache;
use deform::methods::named::Named;
use deform::methods::scenes::{bar, bar_cage};
use deform::methods::{Method, MethodSettings};
use std::path::PathBuf;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_deform"))
        .args(args)
        .output()
        .expect("run deform")
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("deform-pose-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn every_method_poses_from_the_command_line_as_the_library_does() {
    let dir = scratch("all");
    let mesh = bar();
    let groups = vec![tube_ring(16, 0), tube_ring(16, 20), tube_ring(16, 40)];
    let s = |p: &PathBuf| p.to_str().unwrap().to_string();
    let (mesh_obj, cage_obj) = (dir.join("bar.obj"), dir.join("cage.obj"));
    let (sel, motors) = (dir.join("sel.json"), dir.join("motors.json"));
    deform::mesh::io::write_obj(&mesh, &mesh_obj).unwrap();
    deform::mesh::io::write_obj(&bar_cage(), &cage_obj).unwrap();
    std::fs::write(&sel, r#"{"0": [0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15], "1": [320,321,322,323,324,325,326,327,328,329,330,331,332,333,334,335], "2": [640,641,642,643,644,645,646,647,648,649,650,651,652,653,654,655]}"#).unwrap();
    assert_eq!(
        groups[1][0], 320,
        "the selection file names the rings above"
    );
    let text = r#"{"0": {}, "*": {"rotate": {"axis": [0, 0, 1], "degrees": 30, "center": [10, 0, 0]}, "translate": [0, 1, 0]}}"#;
    std::fs::write(&motors, text).unwrap();
    for &method in Method::ALL {
        for flags in [&[][..], &["--blend", "dual-quaternion"][..]] {
            if method == Method::Arap && !flags.is_empty() {
                continue;
            }
            let out = dir.join(format!("posed-{}.obj", method.name()));
            let (m, sj, mj, cj, oj) = (s(&mesh_obj), s(&sel), s(&motors), s(&cage_obj), s(&out));
            let mut args = vec![
                "pose",
                method.name(),
                &m,
                "--motors",
                &mj,
                "-o",
                &oj,
                "--quiet",
            ];
            if !method.controls() {
                args.extend(["--select", &sj]);
            }
            if method == Method::Cage {
                args.extend(["--cage", &cj]);
            }
            args.extend(flags);
            let o = run(&args);
            assert!(
                o.status.success(),
                "{args:?}: {}",
                String::from_utf8_lossy(&o.stderr)
            );
            let got = deform::mesh::io::read_mesh(&out).unwrap();
            // The library, in process, with the same settings.
            let mut settings = MethodSettings::default();
            settings.set_method(method);
            if let [name, value] = flags {
                settings.set(&name[2..], value).unwrap();
            }
            let groups = if method.controls() {
                Vec::new()
            } else {
                groups.clone()
            };
            let cage = bar_cage();
            let mut bound = BoundMethod::bind(
                &mesh,
                &groups,
                Some(&cage),
                &settings,
                &WorkBudget::default(),
                &mut HarmonicCache::default(),
            )
            .unwrap();
            let keys = deform::input::parse_group_motors(text, "m", bound.key_count()).unwrap();
            let mut want = mesh.positions.clone();
            bound.pose(&keys, &mesh.positions, &mut want).unwrap();
            let moved = want
                .iter()
                .zip(&mesh.positions)
                .map(|(a, b)| a.distance(*b))
                .fold(0.0, f64::max);
            assert!(
                moved > 0.1,
                "{}: the pose moves the bar ({moved})",
                method.name()
            );
            let worst = got
                .positions
                .iter()
                .zip(&want)
                .map(|(a, b)| a.distance(*b))
                .fold(0.0, f64::max);
            assert!(worst < 1e-12, "{} {flags:?}: {worst}", method.name());
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn option_values_are_the_library_names() {
    let dir = scratch("names");
    let (mesh_obj, cage_obj) = (dir.join("bar.obj"), dir.join("cage.obj"));
    deform::mesh::io::write_obj(&bar(), &mesh_obj).unwrap();
    deform::mesh::io::write_obj(&bar_cage(), &cage_obj).unwrap();
    std::fs::write(dir.join("m.json"), r#"{"*": {}}"#).unwrap();
    let (m, c, mj, o) = (
        mesh_obj.to_str().unwrap(),
        cage_obj.to_str().unwrap(),
        dir.join("m.json"),
        dir.join("o.obj"),
    );
    let (mj, o) = (mj.to_str().unwrap(), o.to_str().unwrap());
    let out = run(&[
        "pose",
        "cage",
        m,
        "--cage",
        c,
        "--motors",
        mj,
        "--coordinates",
        "mvc",
        "-o",
        o,
    ]);
    assert_eq!(out.status.code(), Some(2));
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(e.contains("mean-value") && e.contains("harmonic"), "{e}");
    assert!(!std::path::Path::new(o).exists());
    // A value the library refuses (out of its range) names the flag.
    let out = run(&[
        "pose",
        "cage",
        m,
        "--cage",
        c,
        "--motors",
        mj,
        "--coordinates",
        "harmonic",
        "--grid",
        "4",
        "-o",
        o,
    ]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("--grid"));
    assert!(!std::path::Path::new(o).exists());
    // An option of another method is refused, naming the methods it is for.
    let out = run(&[
        "pose", "ffd", m, "--motors", mj, "--energy", "spokes", "-o", o,
    ]);
    assert_eq!(out.status.code(), Some(2));
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(e.contains("--energy is for arap, not ffd"), "{e}");
    assert!(!std::path::Path::new(o).exists());
    // A method's inputs left out are named.
    for (method, flag) in [
        ("cage", "--cage"),
        ("spline", "--select"),
        ("arap", "--select"),
    ] {
        let out = run(&["pose", method, m, "--motors", mj, "-o", o]);
        assert_eq!(out.status.code(), Some(2));
        let e = String::from_utf8_lossy(&out.stderr);
        assert!(e.contains(flag), "{method}: {e}");
    }
    assert!(!std::path::Path::new(o).exists());
    std::fs::remove_dir_all(&dir).ok();
}
