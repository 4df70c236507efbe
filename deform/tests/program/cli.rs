//! The `deform` program end to end on small meshes: outputs exist and parse back with the
//! input's counts, previews decode, bad arguments and bad input exit with code 2 and a message
//! naming what and where, and nothing is half-written or overwritten.

use deform::mesh::shapes::{tube, tube_ring};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod previews;
mod refusals;
mod rigs;

const SIDES: usize = 8;
const RINGS: usize = 11;

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_deform"))
        .args(args)
        .output()
        .expect("run deform")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A scratch folder with a small bar, its selection and keys.
struct Scene {
    dir: PathBuf,
}

impl Scene {
    fn new(name: &str) -> Scene {
        let dir = std::env::temp_dir().join(format!("deform-cli-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let bar = tube(1.0, 10.0, SIDES, RINGS);
        deform::mesh::io::write_obj(&bar, dir.join("bar.obj")).unwrap();
        let sel = format!(
            "{{\"0\": {:?}, \"1\": {:?}}}",
            tube_ring(SIDES, 0),
            tube_ring(SIDES, RINGS - 1)
        );
        std::fs::write(dir.join("sel.json"), sel).unwrap();
        let mut dmat = format!("1 {}\n", bar.vertex_count());
        for v in 0..bar.vertex_count() {
            let g = if v < SIDES {
                0
            } else if v / SIDES == RINGS - 1 && v < SIDES * RINGS {
                1
            } else {
                -1
            };
            dmat.push_str(&format!("{g}\n"));
        }
        std::fs::write(dir.join("sel.dmat"), dmat).unwrap();
        std::fs::write(
            dir.join("keys.json"),
            r#"[{}, {"translate": [0, 1, 0]}, {"rotate": {"axis": [1, 0, 0], "degrees": 90, "center": [10, 0, 0]}, "scale": 1.5}, {}]"#,
        )
        .unwrap();
        std::fs::write(
            dir.join("motors.json"),
            r#"{"0": {}, "*": {"rotate": {"axis": [0, 0, 1], "degrees": 30, "center": [10, 0, 0]}, "translate": [0, 2, 0]}}"#,
        )
        .unwrap();
        Scene { dir }
    }
    fn p(&self, name: &str) -> String {
        self.dir.join(name).to_string_lossy().into_owned()
    }
}

impl Drop for Scene {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

fn read_obj(path: &str) -> deform::Mesh {
    deform::mesh::io::read_obj(Path::new(path)).expect("output parses back")
}

#[test]
fn demo_writes_meshes_previews_and_a_table() {
    let s = Scene::new("demo");
    let out = s.p("demo");
    let o = run(&["demo", "--out", &out]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = String::from_utf8_lossy(&o.stdout);
    assert!(
        table.contains("bind ms") && table.contains("twist-matrix"),
        "{table}"
    );
    for name in [
        "bend-linear",
        "twist-motor",
        "twist-matrix",
        "fabrik-chain",
        "handles-sphere",
        "arap-beam",
    ] {
        let m = read_obj(&format!("{out}/{name}.obj"));
        assert!(m.vertex_count() > 100);
        let png = std::fs::read(format!("{out}/{name}.png")).unwrap();
        assert_eq!(&png[1..4], b"PNG");
    }
    assert!(Path::new(&format!("{out}/contact-sheet.png")).exists());
    let o = run(&["demo", "--out", &out, "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    // One row per scene, one OBJ per scene.
    let objs = std::fs::read_dir(&out)
        .unwrap()
        .filter(|e| e.as_ref().unwrap().path().extension() == Some("obj".as_ref()))
        .count();
    assert_eq!(v["scenes"].as_array().unwrap().len(), objs);
    assert!(objs >= 12, "{objs} scenes");
}

#[test]
fn spline_handles_and_fabrik_write_meshes_with_the_input_counts() {
    let s = Scene::new("ok");
    let bar = read_obj(&s.p("bar.obj"));
    let (mesh, keys, sel_json, sel_dmat) = (
        s.p("bar.obj"),
        s.p("keys.json"),
        s.p("sel.json"),
        s.p("sel.dmat"),
    );
    let (out, png) = (s.p("out.obj"), s.p("out.png"));
    let o = run(&[
        "spline", &mesh, "--select", &sel_json, "--keys", &keys, "-o", &out, "--png", &png,
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["vertices"], bar.vertex_count());
    assert_eq!(v["scheme"], "bspline");
    let posed = read_obj(&out);
    assert_eq!(
        (posed.vertex_count(), posed.triangles),
        (bar.vertex_count(), bar.triangles.clone())
    );
    // The last ring follows the last key (identity): it stays.
    for v in tube_ring(SIDES, RINGS - 1) {
        assert!(posed.positions[v as usize].distance(bar.positions[v as usize]) < 1e-9);
    }
    assert!(Path::new(&png).exists());

    let o = run(&[
        "handles",
        &mesh,
        "--select",
        &sel_dmat,
        "--motors",
        &s.p("motors.json"),
        "-o",
        &out,
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    let posed = read_obj(&out);
    let ring0 = tube_ring(SIDES, 0);
    assert!(ring0
        .iter()
        .all(|&v| posed.positions[v as usize] == bar.positions[v as usize]));

    let o = run(&[
        "fabrik", &mesh, "--select", &sel_json, "--target", "6,5,0", "-o", &out, "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["status"], "reached");
    assert_eq!(read_obj(&out).vertex_count(), bar.vertex_count());
    let o = run(&[
        "fabrik", &mesh, "--select", &sel_json, "--target", "0,40,0", "-o", &out, "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["status"], "unreachable");
}

/// Exit code 2 with `needle` in the message, and the scene's `never.obj` not written.
fn expect_2(s: &Scene, args: &[&str], needle: &str) {
    let out = s.p("never.obj");
    let o = run(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    assert!(
        stderr(&o).contains(needle),
        "{args:?}: {:?} lacks {needle:?}",
        stderr(&o)
    );
    assert!(!Path::new(&out).exists(), "{args:?} left an output");
}

#[test]
fn bad_arguments_exit_2_naming_the_argument_and_leave_no_file() {
    let s = Scene::new("bad-args");
    let (mesh, keys, sel) = (s.p("bar.obj"), s.p("keys.json"), s.p("sel.json"));
    let out = s.p("never.obj");
    expect_2(
        &s,
        &["spline", &mesh, "--select", &sel, "-o", &out],
        "--keys",
    );
    // `--gpu auto` with a space: clap takes `auto` for the model; the hint says `--gpu=auto`.
    expect_2(
        &s,
        &["skin", "--gpu", "auto", &mesh, "-o", &out],
        "write --gpu=auto",
    );
    expect_2(
        &s,
        &[
            "spline", &mesh, "--select", &sel, "--keys", &keys, "-o", &out, "--scheme", "cubic",
        ],
        "cubic",
    );
    expect_2(
        &s,
        &[
            "spline",
            &mesh,
            "--select",
            &sel,
            "--keys",
            &keys,
            "-o",
            &out,
            "--scheme",
            "quadratic",
        ],
        "quadratic takes exactly 3 keys",
    );
    expect_2(&s, &["frobnicate"], "frobnicate");
}

#[test]
fn an_output_naming_an_input_exits_2_and_leaves_the_input_unchanged() {
    let s = Scene::new("bad-overwrite");
    let (mesh, keys, sel) = (s.p("bar.obj"), s.p("keys.json"), s.p("sel.json"));
    let before = std::fs::read(&mesh).unwrap();
    let o = run(&[
        "spline", &mesh, "--select", &sel, "--keys", &keys, "-o", &mesh,
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("refusing to overwrite an input"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read(&mesh).unwrap(), before);
}

#[test]
fn bad_keys_and_selections_exit_2_naming_the_key_or_vertex() {
    let s = Scene::new("bad-keys");
    let (mesh, keys, sel) = (s.p("bar.obj"), s.p("keys.json"), s.p("sel.json"));
    let out = s.p("never.obj");
    std::fs::write(
        s.p("bad-keys.json"),
        r#"[{}, {"rotate": {"axis": [0, 0, 0], "degrees": 10}}]"#,
    )
    .unwrap();
    let bad_keys = s.p("bad-keys.json");
    let args = [
        "spline", &mesh, "--select", &sel, "--keys", &bad_keys, "-o", &out,
    ];
    expect_2(&s, &args, "key 1");
    std::fs::write(s.p("shape.json"), r#"{"rotate": 3}"#).unwrap();
    let shape = s.p("shape.json");
    let args = [
        "spline", &mesh, "--select", &sel, "--keys", &shape, "-o", &out,
    ];
    expect_2(&s, &args, "expected an array");
    std::fs::write(s.p("far.json"), r#"{"0": [0, 1], "1": [99999]}"#).unwrap();
    let far = s.p("far.json");
    let args = [
        "spline", &mesh, "--select", &far, "--keys", &keys, "-o", &out,
    ];
    expect_2(&s, &args, "vertex 99999 does not exist");
    std::fs::write(s.p("one.json"), r#"{"0": [0, 1]}"#).unwrap();
    let one = s.p("one.json");
    let args = [
        "spline", &mesh, "--select", &one, "--keys", &keys, "-o", &out,
    ];
    expect_2(&s, &args, "at least two groups");
}

#[test]
fn bad_motors_targets_and_meshes_exit_2_naming_the_input() {
    let s = Scene::new("bad-inputs");
    let (mesh, keys, sel) = (s.p("bar.obj"), s.p("keys.json"), s.p("sel.json"));
    let out = s.p("never.obj");
    std::fs::write(s.p("m.json"), r#"{"7": {}}"#).unwrap();
    let motors = s.p("m.json");
    let args = [
        "handles", &mesh, "--select", &sel, "--motors", &motors, "-o", &out,
    ];
    expect_2(&s, &args, "group \"7\"");
    expect_2(
        &s,
        &[
            "fabrik", &mesh, "--select", &sel, "--target", "1,2", "-o", &out,
        ],
        "three finite numbers",
    );
    let missing = s.p("missing.obj");
    let args = [
        "spline", &missing, "--select", &sel, "--keys", &keys, "-o", &out,
    ];
    expect_2(&s, &args, "missing.obj");
    std::fs::write(s.p("broken.obj"), "v 0 0 0\nv 1 0 nan\nf 1 2 3\n").unwrap();
    let broken = s.p("broken.obj");
    let args = [
        "spline", &broken, "--select", &sel, "--keys", &keys, "-o", &out,
    ];
    expect_2(&s, &args, "broken.obj");
}

/// Ctrl-C during a long frame sequence (issue 20): exit code 130, and neither frames nor
/// temporary files are left behind.
#[test]
fn ctrl_c_stops_a_sequence_and_leaves_no_partial_output() {
    use deform::skinning::{glb_bytes, procedural_arm, GlbOptions};
    let s = Scene::new("interrupt");
    let glb = glb_bytes(&procedural_arm(32, 80), &GlbOptions::default()).unwrap();
    std::fs::write(s.p("arm.glb"), glb).unwrap();
    let names = |dir: &Path| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    };
    let before = names(&s.dir);
    let mut child = Command::new(env!("CARGO_BIN_EXE_deform"))
        .args([
            "skin",
            &s.p("arm.glb"),
            "--animation",
            "0",
            "--range",
            "0:2:2000",
        ])
        .args(["-o", &s.p("seq.obj"), "--quiet"])
        .stdin(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until the sequence is being written, then interrupt.
    let first = s.dir.join("seq_0000.obj");
    let start = std::time::Instant::now();
    while !first.exists() && start.elapsed().as_secs() < 60 {
        assert!(
            child.try_wait().unwrap().is_none(),
            "finished before it could be interrupted"
        );
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    assert!(first.exists(), "no frame was written within 60 s");
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{err}");
    assert!(err.contains("interrupted"), "{err}");
    let left: Vec<String> = names(&s.dir)
        .into_iter()
        .filter(|n| !before.contains(n))
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
}

/// `deform ffd MESH --lattice 2x2x2 --motors MOTORS -o OUT`.
fn ffd_2x2x2(mesh: &str, motors: &str, out: &str) -> Output {
    run(&[
        "ffd",
        mesh,
        "--lattice",
        "2x2x2",
        "--motors",
        motors,
        "-o",
        out,
    ])
}

/// A mesh input that is not text is refused by name, with exit code 2 and no output (the
/// program reads an OBJ once, for its mesh and its texture coordinates together).
#[test]
fn obj_input_that_is_not_text_is_refused() {
    let s = Scene::new("binary-obj");
    std::fs::write(
        s.p("bad.obj"),
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\xff\xfe\n",
    )
    .unwrap();
    std::fs::write(s.p("id.json"), r#"{"*": {}}"#).unwrap();
    let out = s.p("out.obj");
    let o = ffd_2x2x2(&s.p("bad.obj"), &s.p("id.json"), &out);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("bad.obj") && err.contains("not UTF-8"),
        "{err}"
    );
    assert!(!std::path::Path::new(&out).exists(), "nothing written");
}

/// A deformed OBJ keeps the input's texture coordinates, corner by corner, and gets normals
/// where the input had them (issue 21).
#[test]
fn deformed_obj_keeps_texture_coordinates() {
    let s = Scene::new("textured");
    let bar = tube(1.0, 10.0, SIDES, RINGS);
    let mut text = String::new();
    for p in &bar.positions {
        text.push_str(&format!("v {} {} {}\n", p.x, p.y, p.z));
    }
    // One vt per corner, so the output must follow the corners, not the vertices.
    for (f, _) in bar.triangles.iter().enumerate() {
        for k in 0..3 {
            text.push_str(&format!("vt {} {}\n", f as f64 / 1000.0, k as f64 / 4.0));
        }
    }
    text.push_str("vn 0 0 1\n");
    for (f, t) in bar.triangles.iter().enumerate() {
        let c = |k: usize| format!("{}/{}/1", t[k] + 1, 3 * f + k + 1);
        text.push_str(&format!("f {} {} {}\n", c(0), c(1), c(2)));
    }
    std::fs::write(s.p("textured.obj"), &text).unwrap();
    std::fs::write(
        s.p("twist.json"),
        r#"{"0": {"rotate": {"axis": [1, 0, 0], "degrees": 40}}}"#,
    )
    .unwrap();
    let out = s.p("out.obj");
    let o = ffd_2x2x2(&s.p("textured.obj"), &s.p("twist.json"), &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let written = std::fs::read_to_string(&out).unwrap();
    let (mesh, texture) = deform::mesh::io::parse_obj_textured(&written, "out").unwrap();
    let (input, input_texture) = deform::mesh::io::parse_obj_textured(&text, "in").unwrap();
    assert_eq!(mesh.triangles, input.triangles);
    assert_eq!(texture, input_texture, "the same vt, corner by corner");
    assert!(
        mesh.positions != input.positions,
        "the lattice moved the bar"
    );
    let vn = written.lines().filter(|l| l.starts_with("vn ")).count();
    assert_eq!(
        vn,
        mesh.vertex_count(),
        "normals of the deformed mesh, per vertex"
    );
}
