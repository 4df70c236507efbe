//! Issue 21: previews that show the result (a title and a colour legend on every PNG, the
//! tools drawn over the meshes, a zoomed view of a small surgery), outputs by extension
//! (`.ply`; any other extension refused before any work), one vocabulary for skinning
//! backends, and one `--time`/`--animation` convention for `skin` and the surgery tools.

use super::{run, stderr, Scene};
use deform::render::{viridis, TEXT_COLOR};
use std::path::Path;

/// Overlay colours of the program's previews (`preview.rs`).
const REST_INK: [u8; 3] = [40, 70, 160];
const POSED_INK: [u8; 3] = [220, 40, 40];
const TOOL_INK: [u8; 3] = [230, 0, 200];
const FOCUS_INK: [u8; 3] = [255, 140, 0];

/// A decoded RGB8 PNG.
struct Png {
    width: u32,
    height: u32,
    rgb: Vec<u8>,
}

impl Png {
    fn read(path: &str) -> Png {
        let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{path}: {e}"));
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut rgb).unwrap();
        assert_eq!(info.color_type, png::ColorType::Rgb);
        rgb.truncate(info.buffer_size());
        Png {
            width: info.width,
            height: info.height,
            rgb,
        }
    }

    /// How many pixels of rows `rows` have colour `c`.
    fn count(&self, rows: std::ops::Range<u32>, c: [u8; 3]) -> usize {
        let w = self.width as usize;
        rows.flat_map(|y| (0..w).map(move |x| 3 * (y as usize * w + x)))
            .filter(|&i| self.rgb[i..i + 3] == c)
            .count()
    }
}

fn colormap(t: f64) -> [u8; 3] {
    viridis(t).map(|c| c.round() as u8)
}

/// A title of dark text in the top band, the colour bar from the colormap's start to its
/// end and its labels in the bottom band, and each of `inks` drawn somewhere.
fn assert_annotated(path: &str, inks: &[[u8; 3]]) {
    let png = Png::read(path);
    let (w, h) = (png.width, png.height);
    let title = png.count(0..30, TEXT_COLOR);
    assert!(title > 150, "{path}: {title} title pixels");
    let bottom = h - 50..h;
    assert!(
        png.count(bottom.clone(), colormap(0.0)) >= 8,
        "{path}: no bar start"
    );
    assert!(
        png.count(bottom.clone(), colormap(1.0)) >= 8,
        "{path}: no bar end"
    );
    let labels = png.count(bottom, TEXT_COLOR);
    assert!(labels > 100, "{path}: {labels} legend text pixels");
    for ink in inks {
        let n = png.count(30..h - 50, *ink);
        assert!(n >= 10, "{path} ({w}x{h}): {n} pixels of {ink:?}");
    }
}

/// A closed box cage around the bar (x 0..10, radius 1), outward triangles.
fn write_cage(path: &str) {
    let (lo, hi) = ([-1.0, -2.0, -2.0], [11.0, 2.0, 2.0]);
    let mut obj = String::new();
    for k in 0..8 {
        let c = |a: usize| if k >> a & 1 == 0 { lo[a] } else { hi[a] };
        obj.push_str(&format!("v {} {} {}\n", c(0), c(1), c(2)));
    }
    for f in [
        [1, 3, 4, 2], // x = lo
        [5, 6, 8, 7], // x = hi
        [1, 2, 6, 5], // y = lo
        [3, 7, 8, 4], // y = hi
        [1, 5, 7, 3], // z = lo
        [2, 4, 8, 6], // z = hi
    ] {
        obj.push_str(&format!(
            "f {} {} {}\nf {} {} {}\n",
            f[0], f[1], f[2], f[0], f[2], f[3]
        ));
    }
    std::fs::write(path, obj).unwrap();
}

/// The deformer subcommands on the small bar, each with `-o OUT --png PNG` to append.
fn deformer_runs(s: &Scene) -> Vec<(&'static str, Vec<String>)> {
    std::fs::write(s.p("arap.json"), r#"{"1": {"translate": [0, 3, 0]}}"#).unwrap();
    std::fs::write(
        s.p("lift.json"),
        r#"{"0": {}, "*": {"translate": [0, 2, 0]}}"#,
    )
    .unwrap();
    write_cage(&s.p("box-cage.obj"));
    let (bar, sel, keys, motors) = (
        s.p("bar.obj"),
        s.p("sel.json"),
        s.p("keys.json"),
        s.p("motors.json"),
    );
    let v = |a: &[&str]| a.iter().map(|x| x.to_string()).collect::<Vec<_>>();
    vec![
        (
            "spline",
            v(&["spline", &bar, "--select", &sel, "--keys", &keys]),
        ),
        (
            "handles",
            v(&["handles", &bar, "--select", &sel, "--motors", &motors]),
        ),
        (
            "fabrik",
            v(&["fabrik", &bar, "--select", &sel, "--target", "6,5,1"]),
        ),
        (
            "arap",
            v(&[
                "arap",
                &bar,
                "--select",
                &sel,
                "--motors",
                &s.p("arap.json"),
            ]),
        ),
        (
            "ffd",
            v(&[
                "ffd",
                &bar,
                "--lattice",
                "2x2x2",
                "--motors",
                &s.p("lift.json"),
            ]),
        ),
        (
            "cage",
            v(&[
                "cage",
                &bar,
                "--cage",
                &s.p("box-cage.obj"),
                "--motors",
                &s.p("lift.json"),
            ]),
        ),
    ]
}

#[test]
fn every_deformer_preview_has_a_title_a_legend_and_its_tools() {
    let s = Scene::new("annotated");
    for (name, mut args) in deformer_runs(&s) {
        let (out, png) = (s.p(&format!("{name}.obj")), s.p(&format!("{name}.png")));
        args.extend(["-o".into(), out, "--png".into(), png.clone()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = run(&args);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        // Every tool at rest (blue) and moved (red); FABRIK's target and the handles'
        // motions in magenta.
        let inks: &[[u8; 3]] = match name {
            "handles" => &[REST_INK, POSED_INK, TOOL_INK],
            "fabrik" => &[REST_INK, POSED_INK, TOOL_INK],
            _ => &[REST_INK, POSED_INK],
        };
        assert_annotated(&png, inks);
    }
}

/// The procedural arm as a `.glb` in the scene's folder.
fn write_arm(s: &Scene) -> String {
    use deform::skinning::{glb_bytes, procedural_arm, GlbOptions};
    let glb = glb_bytes(&procedural_arm(24, 81), &GlbOptions::default()).unwrap();
    std::fs::write(s.p("arm.glb"), glb).unwrap();
    s.p("arm.glb")
}

#[test]
fn a_small_surgery_gets_a_zoomed_third_view_and_the_tool_is_drawn() {
    let s = Scene::new("zoom");
    let arm = write_arm(&s);
    let (out, png) = (s.p("drilled.obj"), s.p("drilled.png"));
    let args = [
        "drill",
        &arm,
        "--tip",
        "1.5,0.1,-2",
        "--end",
        "1.5,0.1,2",
        "--radius",
        "0.3",
        "-o",
        &out,
        "--png",
        &png,
    ];
    let o = run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_annotated(&png, &[TOOL_INK, FOCUS_INK]);
    let cut = (s.p("cut.obj"), s.p("cut.png"));
    let args = [
        "cut",
        &arm,
        "--plane",
        "1,0.3,0,2.6",
        "-o",
        &cut.0,
        "--png",
        &cut.1,
    ];
    let o = run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_annotated(&cut.1, &[TOOL_INK]);
    // Three views beside each other for the drill, two for the cut (which has no zoom).
    let (d, c) = (Png::read(&png), Png::read(&cut.1));
    assert!(d.width > c.width * 5 / 4, "{} vs {}", d.width, c.width);
    assert_eq!(c.count(0..c.height, FOCUS_INK), 0);
}

#[test]
fn the_demo_tiles_are_titled() {
    let s = Scene::new("demo-tiles");
    let out = s.p("demo");
    let o = run(&["demo", "--out", &out, "--quiet"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let sheet = Png::read(&format!("{out}/contact-sheet.png"));
    // The first row of tiles: a title over each of the four columns.
    let quarter = sheet.width / 4;
    for col in 0..4 {
        let x0 = (col * quarter) as usize;
        let text = (0..12u32)
            .flat_map(|y| (x0..x0 + quarter as usize).map(move |x| (x, y)))
            .filter(|&(x, y)| {
                let i = 3 * (y as usize * sheet.width as usize + x);
                sheet.rgb[i..i + 3] == TEXT_COLOR
            })
            .count();
        assert!(text > 40, "tile {col}: {text} title pixels");
    }
    assert_annotated(&format!("{out}/tear-arm.png"), &[FOCUS_INK]);
}

/// The header of a binary PLY file and the byte count it promises.
fn ply_counts(path: &str) -> (usize, usize) {
    let bytes = std::fs::read(path).unwrap();
    let end = b"end_header\n";
    let at = bytes
        .windows(end.len())
        .position(|w| w == end)
        .expect("a header")
        + end.len();
    let header = std::str::from_utf8(&bytes[..at]).unwrap();
    assert!(
        header.starts_with("ply\nformat binary_little_endian 1.0\n"),
        "{header}"
    );
    let count = |element: &str| -> usize {
        let line = header
            .lines()
            .find(|l| l.starts_with(&format!("element {element} ")))
            .unwrap_or_else(|| panic!("no {element} element: {header}"));
        line.rsplit(' ').next().unwrap().parse().unwrap()
    };
    let (v, f) = (count("vertex"), count("face"));
    assert_eq!(bytes.len() - at, 24 * v + 13 * f, "{path}: body size");
    (v, f)
}

#[test]
fn ply_outputs_have_the_header_and_the_counts() {
    let s = Scene::new("ply");
    let bar = super::read_obj(&s.p("bar.obj"));
    for (name, mut args) in deformer_runs(&s) {
        let out = s.p(&format!("{name}.ply"));
        args.extend(["-o".into(), out.clone()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = run(&args);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert_eq!(
            ply_counts(&out),
            (bar.vertex_count(), bar.triangle_count()),
            "{name}"
        );
    }
    let arm = write_arm(&s);
    let rig = deform::skinning::procedural_arm(24, 81);
    let out = s.p("arm.ply");
    let o = run(&["skin", &arm, "--time", "1", "-o", &out]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        ply_counts(&out),
        (rig.mesh.vertex_count(), rig.mesh.triangle_count())
    );
    let o = run(&["skin", &arm, "--range", "0:1:2", "-o", &out]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(Path::new(&s.p("arm_0001.ply")).exists());
    // The same drill as OBJ and as PLY: the same counts.
    let drill = |out: &str| {
        let args = [
            "drill",
            &arm,
            "--tip",
            "1.5,0.1,-2",
            "--end",
            "1.5,0.1,2",
            "--radius",
            "0.3",
            "-o",
            out,
        ];
        let o = run(&args);
        assert!(o.status.success(), "{}", stderr(&o));
    };
    let (ply, obj) = (s.p("drilled.ply"), s.p("drilled.obj"));
    drill(&ply);
    drill(&obj);
    let m = super::read_obj(&obj);
    assert!(m.vertex_count() > rig.mesh.vertex_count());
    assert_eq!(ply_counts(&ply), (m.vertex_count(), m.triangle_count()));
}

#[test]
fn unknown_output_extensions_exit_2_before_any_work() {
    let s = Scene::new("unknown-ext");
    // Missing inputs: refusing the name must come before reading anything.
    let (gone, sel, json) = (
        s.p("missing.obj"),
        s.p("missing.json"),
        s.p("missing2.json"),
    );
    let rig = s.p("missing.glb");
    let commands: Vec<Vec<&str>> = vec![
        vec!["spline", &gone, "--select", &sel, "--keys", &json],
        vec!["handles", &gone, "--select", &sel, "--motors", &json],
        vec!["fabrik", &gone, "--select", &sel, "--target", "1,2,3"],
        vec!["arap", &gone, "--select", &sel, "--motors", &json],
        vec!["ffd", &gone, "--lattice", "2x2x2", "--motors", &json],
        vec!["cage", &gone, "--cage", &sel, "--motors", &json],
        vec!["skin", &rig],
        vec!["cut", &rig, "--plane", "1,0,0,1"],
        vec![
            "tear",
            &rig,
            "--scalpel",
            "0,0,1:0,0,0",
            "--scalpel",
            "1,0,1:1,0,0",
        ],
        vec![
            "drill", &rig, "--tip", "0,0,1", "--end", "0,0,-1", "--radius", "0.1",
        ],
    ];
    for ext in ["stl", "png", "OBJX", ""] {
        let out = s.p(&format!("x.{ext}"));
        let png = s.p("x-preview.png");
        for c in &commands {
            let mut args = c.clone();
            args.extend(["-o", &out, "--png", &png]);
            let o = run(&args);
            let err = stderr(&o);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
            assert!(
                err.contains("this command writes .obj or .glb or .ply"),
                "{args:?}: {err}"
            );
            assert!(
                !Path::new(&out).exists() && !Path::new(&png).exists(),
                "{args:?}"
            );
        }
    }
}

#[test]
fn skin_reports_backends_by_the_names_of_its_flags() {
    let s = Scene::new("backends");
    let arm = write_arm(&s);
    let out = s.p("o.obj");
    for (backend, other) in [
        ("cga", "dqs"),
        ("lbs", "motor-log"),
        ("lbs-f32", "cga-projected"),
    ] {
        let args = [
            "skin",
            &arm,
            "--time",
            "1",
            "--backend",
            backend,
            "--compare",
            other,
            "-o",
            &out,
            "--json",
        ];
        let o = run(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(
            (v["backend"].as_str(), v["compared_with"].as_str()),
            (Some(backend), Some(other))
        );
    }
}

#[test]
fn animation_alone_means_its_time_0_in_skin_and_in_the_surgery_tools() {
    let s = Scene::new("time-defaults");
    let arm = write_arm(&s);
    let plane = ["--plane", "1,0.3,0,2.6"];
    for (tool, extra) in [("skin", &[][..]), ("cut", &plane[..])] {
        let (a, b) = (s.p(&format!("{tool}-a.obj")), s.p(&format!("{tool}-b.obj")));
        let mut first = vec![tool, &arm, "--animation", "0", "-o", &a];
        first.extend_from_slice(extra);
        let mut second = vec![tool, &arm, "--time", "0", "-o", &b];
        second.extend_from_slice(extra);
        for args in [&first, &second] {
            let o = run(args);
            assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        }
        assert_eq!(
            std::fs::read(&a).unwrap(),
            std::fs::read(&b).unwrap(),
            "{tool}"
        );
    }
}
