//! Seeded mutation test of every subcommand through the real `deform` binary (issue 20): valid
//! base invocations on procedural inputs (a sphere in a cage, a bar with handle groups, a rigged
//! arm as `.glb`), then one mutation per case: a numeric flag replaced by a hostile value, an
//! input file's bytes flipped or truncated, a number in a JSON or OBJ input replaced by NaN, an
//! infinity, 1e308, -1 or a huge count. Every run must exit 0 or 2 without a panic; an exit 0
//! must leave a readable output with finite positions; no input may change.
//!
//! `DEFORM_FUZZ_CASES` (default 3000) and `DEFORM_FUZZ_SEED` (default 20) set the run.

use crate::common;

use common::Lcg;
use deform::mesh::shapes::{icosphere, tube, tube_ring};
use deform::skinning::{glb_bytes, procedural_arm, GlbOptions};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Values a careless or hostile user gives to numeric flags.
const HOSTILE: &[&str] = &[
    "nan",
    "NaN",
    "inf",
    "-inf",
    "-1",
    "0",
    "1e308",
    "-1e308",
    "1e-320",
    "18446744073709551615",
    "4294967297",
    "100000000",
    "",
    "abc",
    "1,2",
    "1,nan,3",
    "1e300,0,0",
    "0:1:nan",
    "2x2x0",
    "65536x65536x65536",
];

/// Numbers that replace a number inside an input file.
const HOSTILE_NUMBERS: &[&str] = &["nan", "inf", "-inf", "1e308", "-1", "1e300", "99999999"];

struct Inputs {
    dir: PathBuf,
}

impl Inputs {
    fn new() -> Inputs {
        let dir = std::env::temp_dir().join(format!("deform-fuzz-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let (sides, rings) = (6, 7);
        deform::mesh::io::write_obj(&tube(1.0, 10.0, sides, rings), dir.join("bar.obj")).unwrap();
        let sel = format!(
            "{{\"0\": {:?}, \"1\": {:?}}}",
            tube_ring(sides, 0),
            tube_ring(sides, rings - 1)
        );
        std::fs::write(dir.join("sel.json"), sel).unwrap();
        std::fs::write(
            dir.join("keys.json"),
            r#"[{}, {"rotate": {"axis": [1, 0, 0], "degrees": 90, "center": [10, 0, 0]}, "scale": 1.5}]"#,
        )
        .unwrap();
        std::fs::write(
            dir.join("motors.json"),
            r#"{"0": {}, "*": {"rotate": {"axis": [0, 0, 1], "degrees": 30, "center": [5, 0, 0]}, "translate": [0, 2, 0]}}"#,
        )
        .unwrap();
        // The bar as a libigl rig: a skeleton of two bones along it and linear weights.
        let bar = tube(1.0, 10.0, sides, rings);
        let tgf = "1 0 0 0\n2 5 0 0\n3 10 0 0\n#\n1 2\n2 3\n#\n";
        std::fs::write(dir.join("bar.tgf"), tgf).unwrap();
        let mut dmat = format!("2 {}\n", bar.vertex_count());
        for bone in 0..2 {
            for p in &bar.positions {
                let t = (p.x / 10.0).clamp(0.0, 1.0);
                dmat += &format!("{}\n", if bone == 0 { 1.0 - t } else { t });
            }
        }
        std::fs::write(dir.join("bar.dmat"), dmat).unwrap();
        deform::mesh::io::write_obj(&icosphere(1.0, 1), dir.join("ball.obj")).unwrap();
        deform::mesh::io::write_obj(&icosphere(1.6, 1), dir.join("cage.obj")).unwrap();
        let arm = glb_bytes(&procedural_arm(8, 9), &GlbOptions::default()).unwrap();
        std::fs::write(dir.join("arm.glb"), arm).unwrap();
        std::fs::write(
            dir.join("edit.json"),
            r#"{"rotate": {"axis": [0, 0, 1], "degrees": 20}}"#,
        )
        .unwrap();
        Inputs { dir }
    }

    fn p(&self, name: &str) -> String {
        self.dir.join(name).to_string_lossy().into_owned()
    }

    /// The base invocations: (arguments, the input files among them, the output).
    fn bases(&self) -> Vec<Vec<String>> {
        let p = |n: &str| self.p(n);
        let v = |a: &[&str]| a.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let (bar, sel, keys, motors) = (
            p("bar.obj"),
            p("sel.json"),
            p("keys.json"),
            p("motors.json"),
        );
        let (ball, cage, arm) = (p("ball.obj"), p("cage.obj"), p("arm.glb"));
        let (tgf, dmat) = (p("bar.tgf"), p("bar.dmat"));
        let edit = format!("1={}", p("edit.json"));
        vec![
            v(&["spline", &bar, "--select", &sel, "--keys", &keys]),
            v(&["handles", &bar, "--select", &sel, "--motors", &motors]),
            v(&[
                "fabrik", &bar, "--select", &sel, "--target", "2,6,0", "--joints", "5",
            ]),
            v(&[
                "arap",
                &bar,
                "--select",
                &sel,
                "--motors",
                &motors,
                "--iterations",
                "3",
            ]),
            v(&["ffd", &bar, "--lattice", "2x2x2", "--motors", &motors]),
            v(&["cage", &ball, "--cage", &cage, "--motors", &motors]),
            v(&[
                "skin",
                &arm,
                "--animation",
                "0",
                "--time",
                "0.5",
                "--edit",
                &edit,
            ]),
            v(&["cut", &arm, "--plane", "1,0,0,4"]),
            v(&[
                "drill", &arm, "--tip", "3,0,-2", "--end", "3,0,2", "--radius", "0.3",
            ]),
            v(&[
                "tear",
                &arm,
                "--scalpel",
                "2,0,2:2,0,0",
                "--scalpel",
                "3,0,2:3,0,0",
            ]),
            v(&[
                "cut",
                &bar,
                "--skeleton",
                &tgf,
                "--weights",
                &dmat,
                "--plane",
                "1,0,0,5",
            ]),
            v(&[
                "drill",
                &bar,
                "--skeleton",
                &tgf,
                "--weights",
                &dmat,
                "--tip",
                "5,0,-2",
                "--end",
                "5,0,2",
                "--radius",
                "0.3",
            ]),
        ]
    }
}

impl Drop for Inputs {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// One mutation of `args` (files it names are copied before they are changed).
fn mutate(rng: &mut Lcg, args: &mut [String], scratch: &Path) {
    let files: Vec<usize> = (1..args.len())
        .filter(|&i| Path::new(&args[i]).is_file() && !args[i].ends_with("edit.json"))
        .collect();
    let values: Vec<usize> = (2..args.len())
        .filter(|&i| args[i - 1].starts_with("--") && !Path::new(&args[i]).is_file())
        .collect();
    match rng.below(3) {
        0 if !values.is_empty() => {
            let i = values[rng.below(values.len())];
            args[i] = HOSTILE[rng.below(HOSTILE.len())].to_string();
        }
        1 if !files.is_empty() => {
            let i = files[rng.below(files.len())];
            let mut bytes = std::fs::read(&args[i]).unwrap();
            let glb = args[i].ends_with(".glb");
            let text = std::str::from_utf8(&bytes).is_ok() && !glb;
            let spans: Vec<(usize, usize)> = if text {
                number_spans(&bytes)
            } else {
                Vec::new()
            };
            if glb && rng.below(3) > 0 {
                bytes = mutate_glb_json(rng, &bytes);
            } else if !spans.is_empty() && rng.below(2) == 0 {
                let (a, b) = spans[rng.below(spans.len())];
                let with = HOSTILE_NUMBERS[rng.below(HOSTILE_NUMBERS.len())].as_bytes();
                bytes.splice(a..b, with.iter().copied());
            } else if rng.below(3) == 0 {
                let keep = rng.below(bytes.len());
                bytes.truncate(keep);
            } else {
                for _ in 0..1 + rng.below(8) {
                    let k = rng.below(bytes.len());
                    bytes[k] ^= 1 << rng.below(8);
                }
            }
            let name = Path::new(&args[i]).file_name().unwrap().to_owned();
            let copy = scratch.join(name);
            std::fs::write(&copy, bytes).unwrap();
            args[i] = copy.to_string_lossy().into_owned();
        }
        _ => {} // the base invocation as it is
    }
}

/// A `.glb` whose JSON chunk has one number replaced by a hostile one (an index, a count, an
/// offset, a coordinate), the binary chunk kept: the paths a reader follows by index.
fn mutate_glb_json(rng: &mut Lcg, glb: &[u8]) -> Vec<u8> {
    let at = |i: usize| u32::from_le_bytes(glb[i..i + 4].try_into().unwrap()) as usize;
    let json_len = at(12);
    let mut json = glb[20..20 + json_len].to_vec();
    let rest = &glb[20 + json_len..];
    let spans = number_spans(&json);
    if spans.is_empty() {
        return glb.to_vec();
    }
    let (a, b) = spans[rng.below(spans.len())];
    let with: &[&str] = &["99999", "4294967296", "-1", "0", "1e308", "3", "65535"];
    json.splice(a..b, with[rng.below(with.len())].bytes());
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let mut out = Vec::with_capacity(glb.len() + 16);
    out.extend_from_slice(&glb[..8]);
    out.extend_from_slice(&((20 + json.len() + rest.len()) as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    out.extend_from_slice(rest);
    out
}

/// Byte ranges of the decimal numbers in `text`.
fn number_spans(text: &[u8]) -> Vec<(usize, usize)> {
    let mut spans = Vec::new();
    let mut i = 0;
    while i < text.len() {
        if text[i].is_ascii_digit() {
            let a = i;
            while i < text.len() && (text[i].is_ascii_digit() || text[i] == b'.') {
                i += 1;
            }
            spans.push((a, i));
        } else {
            i += 1;
        }
    }
    spans
}

/// The bytes of every file in the inputs folder.
fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut v: Vec<(PathBuf, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .map(|p| {
            let b = std::fs::read(&p).unwrap();
            (p, b)
        })
        .collect();
    v.sort();
    v
}

/// Whether an output the run reported as written holds finite positions.
fn output_is_finite(path: &Path) -> Result<(), String> {
    if path.extension().is_some_and(|e| e == "glb") {
        let rig = deform::skinning::read_gltf(path).map_err(|e| e.to_string())?;
        if rig.mesh.positions.iter().all(|p| p.is_finite()) {
            return Ok(());
        }
        return Err("non-finite position in the .glb".into());
    }
    let mesh = deform::mesh::io::read_obj(path).map_err(|e| e.to_string())?;
    match mesh.positions.iter().position(|p| !p.is_finite()) {
        None => Ok(()),
        Some(i) => Err(format!("vertex {i} is not finite")),
    }
}

#[test]
fn every_subcommand_survives_mutated_arguments_and_files() {
    let env = |k: &str, d: u64| {
        std::env::var(k)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(d)
    };
    let cases = env("DEFORM_FUZZ_CASES", 3000) as usize;
    let mut rng = Lcg(env("DEFORM_FUZZ_SEED", 20));
    let inputs = Inputs::new();
    let before = snapshot(&inputs.dir);
    let bases = inputs.bases();
    let scratch = inputs.dir.join("scratch");
    std::fs::create_dir_all(&scratch).unwrap();
    for base in &bases {
        // Each unmutated invocation works: the mutants start from valid runs.
        let out = scratch.join("base.obj").to_string_lossy().into_owned();
        let o = Command::new(env!("CARGO_BIN_EXE_deform"))
            .args(base)
            .args(["-o", &out, "--quiet"])
            .output()
            .expect("run deform");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "deform {}: {err}", base.join(" "));
        output_is_finite(Path::new(&out)).unwrap();
    }
    std::fs::remove_dir_all(&scratch).unwrap();
    let mut exits = [0usize; 2];
    let mut failures = Vec::new();
    for case in 0..cases {
        std::fs::create_dir_all(&scratch).unwrap();
        let mut args = bases[case % bases.len()].clone();
        mutate(&mut rng, &mut args, &scratch);
        let surgery = ["cut", "tear", "drill"].contains(&args[0].as_str());
        let ext = if surgery {
            if rng.below(2) == 0 {
                "glb"
            } else {
                "obj"
            }
        } else {
            "obj"
        };
        let out = scratch.join(format!("out.{ext}"));
        args.extend([
            "-o".to_string(),
            out.to_string_lossy().into_owned(),
            "--quiet".into(),
        ]);
        let o = Command::new(env!("CARGO_BIN_EXE_deform"))
            .args(&args)
            .env("RAYON_NUM_THREADS", "1")
            .stdin(std::process::Stdio::piped())
            .output()
            .expect("run deform");
        let err = String::from_utf8_lossy(&o.stderr);
        let verdict = match o.status.code() {
            Some(0) => output_is_finite(&out).map(|()| exits[0] += 1),
            Some(2) if !err.contains("panicked") && !err.trim().is_empty() => {
                exits[1] += 1;
                Ok(())
            }
            code => Err(format!("exit {code:?}: {err}")),
        };
        if let Err(why) = verdict {
            // Keep the case's files (mutated inputs, output) to reproduce it.
            let keep = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-fuzz/case-{case}"));
            let _ = std::fs::create_dir_all(&keep);
            for e in std::fs::read_dir(&scratch).unwrap().flatten() {
                let _ = std::fs::copy(e.path(), keep.join(e.file_name()));
            }
            failures.push(format!(
                "case {case}: deform {}\n  {why}\n  files kept in {}",
                args.join(" "),
                keep.display()
            ));
        }
        std::fs::remove_dir_all(&scratch).unwrap();
    }
    assert_eq!(before, snapshot(&inputs.dir), "an input file changed");
    println!("{cases} cases: {} exit 0, {} exit 2", exits[0], exits[1]);
    assert!(
        exits[0] > cases / 20,
        "too few mutants ran to completion: {exits:?}"
    );
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
