//! Mutation test: small shipped files and in-memory examples of every format, mutated
//! deterministically (byte flips, truncation, deleted/duplicated/swapped lines, numbers
//! replaced by NaN, infinities, 1e308, -1 or huge indices), then parsed, validated and, when
//! valid and small, turned into a Laplacian and a harmonic field. No mutant may panic, and
//! every `Ok` must hold finite values. Runs in a few seconds.

use crate::common;

use common::Lcg;
use deform::mesh::io::{parse_dmat, parse_medit, parse_obj, parse_off, parse_tgf};
use deform::mesh::validate::validate;
use deform::operators::harmonic::{harmonic_field, HarmonicOptions};
use deform::operators::laplacian::cotangent_laplacian;
use deform::Mesh;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Formats the test knows how to read.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Format {
    Obj,
    Off,
    Medit,
    Dmat,
    Tgf,
}

impl Format {
    fn of(name: &str) -> Option<Format> {
        let ext = name.rsplit('.').next()?.to_ascii_lowercase();
        Some(match ext.as_str() {
            "obj" => Format::Obj,
            "off" => Format::Off,
            "mesh" => Format::Medit,
            "dmat" => Format::Dmat,
            "tgf" => Format::Tgf,
            _ => return None,
        })
    }
}

const REPLACEMENTS: [&str; 12] = [
    "NaN",
    "nan",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "1e-320",
    "-1",
    "0",
    "4294967296",
    "99999999999999999999",
    "1e400",
];

/// Applies mutation `kind` (0..6) and returns a description of it.
fn mutate(bytes: &[u8], kind: usize, rng: &mut Lcg) -> (Vec<u8>, String) {
    let mut b = bytes.to_vec();
    let lines =
        |b: &[u8]| -> Vec<Vec<u8>> { b.split(|&c| c == b'\n').map(<[u8]>::to_vec).collect() };
    match kind {
        0 => {
            let at = rng.below(b.len());
            let bit = 1u8 << rng.below(8);
            if let Some(x) = b.get_mut(at) {
                *x ^= bit;
            }
            (b, format!("flip bit {bit:#x} of byte {at}"))
        }
        1 => {
            let at = rng.below(b.len());
            b.truncate(at);
            (b, format!("truncate at {at}"))
        }
        2..=4 => {
            let mut ls = lines(&b);
            let i = rng.below(ls.len());
            let what = match kind {
                2 => {
                    ls.remove(i);
                    format!("delete line {i}")
                }
                3 => {
                    let l = ls[i].clone();
                    ls.insert(i, l);
                    format!("duplicate line {i}")
                }
                _ => {
                    let j = rng.below(ls.len());
                    ls.swap(i, j);
                    format!("swap lines {i} and {j}")
                }
            };
            (ls.join(&b'\n'), what)
        }
        _ => {
            // Replace the k-th whitespace-separated token that looks like a number.
            let text = String::from_utf8_lossy(&b).into_owned();
            let spans: Vec<(usize, usize)> = token_spans(&text)
                .into_iter()
                .filter(|&(s, e)| text[s..e].parse::<f64>().is_ok())
                .collect();
            if spans.is_empty() {
                return (b, "no number to replace".into());
            }
            let (s, e) = spans[rng.below(spans.len())];
            let r = REPLACEMENTS[rng.below(REPLACEMENTS.len())];
            let out = format!("{}{}{}", &text[..s], r, &text[e..]);
            (
                out.into_bytes(),
                format!("replace {:?} at {s} by {r}", &text[s..e]),
            )
        }
    }
}

fn token_spans(text: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.char_indices() {
        match (c.is_ascii_whitespace(), start) {
            (false, None) => start = Some(i),
            (true, Some(s)) => {
                out.push((s, i));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, text.len()));
    }
    out
}

/// Parses, validates and (when valid and small) solves; panics on a non-finite `Ok`.
fn process(format: Format, bytes: &[u8]) {
    let text = String::from_utf8_lossy(bytes);
    let mesh = match format {
        Format::Obj => parse_obj(&text, "m").ok(),
        Format::Off => parse_off(&text, "m").ok(),
        Format::Medit => parse_medit(&text, "m").ok().map(|m| {
            let n = m.positions.len();
            assert!(m.tetrahedra.iter().flatten().all(|&v| (v as usize) < n));
            m.surface()
        }),
        Format::Dmat => {
            if let Ok(d) = parse_dmat(bytes, "m") {
                assert!(
                    d.data.iter().all(|x| x.is_finite()),
                    "non-finite DMAT value"
                );
                assert_eq!(d.data.len(), d.rows * d.cols);
                let _ = d.rows_equal_to(0);
            }
            None
        }
        Format::Tgf => {
            if let Ok(s) = parse_tgf(&text, "m") {
                assert!(s.joints.iter().all(|p| p.is_finite()), "non-finite joint");
                let n = s.joints.len() as u32;
                assert!(
                    s.bones.iter().flatten().all(|&j| j < n),
                    "bone out of range"
                );
            }
            None
        }
    };
    if let Some(m) = mesh {
        assert!(
            m.positions.iter().all(|p| p.is_finite()),
            "non-finite vertex"
        );
        solve(&m);
    }
}

fn solve(m: &Mesh) {
    let report = validate(m);
    if report.check_solvable().is_err() || m.vertex_count() > 2000 {
        return;
    }
    if let Ok(l) = cotangent_laplacian(m, Default::default()) {
        assert!(
            l.data().iter().all(|x| x.is_finite()),
            "non-finite Laplacian"
        );
    }
    let last = m.vertex_count() as u32 - 1;
    if let Ok(x) = harmonic_field(m, &[0], &[last], HarmonicOptions::default()) {
        assert!(x.iter().all(|v| v.is_finite()), "non-finite field");
    }
}

/// In-memory examples of every format (binary DMAT included).
fn examples() -> Vec<(String, Vec<u8>)> {
    let tet_off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    let obj = "# cube corner\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n\
               f 1 2 3 4\nf 1 2 5\nf 2/1 3/2 5/3\nf 3//1 4//1 5//1\nf -2 -5 -1\n";
    let medit = "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n\
                 0 0 1 0\nTriangles\n4\n1 3 2 0\n1 2 4 0\n1 4 3 0\n2 3 4 0\nTetrahedra\n1\n\
                 1 2 3 4 0\nEnd\n";
    let dmat = "1 5\n-1\n0\n1\n-1\n2\n";
    let tgf = "1 0 0 0\n2 0 1 0\n3 0 2 0\n#\n1 2\n2 3\n#\n";
    let mut bin = b"0 0\n2 3\n".to_vec();
    for k in 0..6 {
        bin.extend((k as f64 * 0.5 - 1.0).to_le_bytes());
    }
    vec![
        ("tet.off".into(), tet_off.into()),
        ("example.obj".into(), obj.into()),
        ("tet.mesh".into(), medit.into()),
        ("selection.dmat".into(), dmat.into()),
        ("binary.dmat".into(), bin),
        ("chain.tgf".into(), tgf.into()),
    ]
}

/// Small shipped files (skipped, with a message, when the data directory is absent).
fn shipped() -> Vec<(String, Vec<u8>)> {
    let Some(dir) = common::data_dir() else {
        return Vec::new();
    };
    [
        "libigl/xcylinder.obj",
        "libigl/decimated-knight.off",
        "libigl/decimated-knight-selection.dmat",
        "libigl/hand-pose.dmat",
        "libigl/arm.tgf",
        "libigl/hand.tgf",
        "cages/bar_cage.OBJ",
    ]
    .iter()
    .map(|rel| {
        let path = dir.join("meshes").join(rel);
        let bytes =
            std::fs::read(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        (rel.to_string(), bytes)
    })
    .collect()
}

#[test]
fn mutated_files_never_panic_and_ok_is_finite() {
    const MUTANTS: usize = 200;
    let inputs: Vec<(String, Vec<u8>)> = examples().into_iter().chain(shipped()).collect();
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let mut failures = Vec::new();
    let mut runs = 0;
    for (name, bytes) in &inputs {
        let format = Format::of(name).expect("known extension");
        // The unmutated input must process cleanly too.
        if catch_unwind(|| process(format, bytes)).is_err() {
            failures.push(format!("{name}: unmutated input"));
        }
        let mut rng = Lcg(0x9e37_79b9_7f4a_7c15 ^ bytes.len() as u64);
        for k in 0..MUTANTS {
            // One or two stacked mutations.
            let mut b = bytes.clone();
            let mut what = Vec::new();
            for _ in 0..1 + rng.below(2) {
                let kind = rng.below(6);
                let (nb, w) = mutate(&b, kind, &mut rng);
                b = nb;
                what.push(w);
            }
            runs += 1;
            if let Err(e) = catch_unwind(AssertUnwindSafe(|| process(format, &b))) {
                let msg = e
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                failures.push(format!("{name} mutant {k} ({}): {msg}", what.join(", ")));
            }
        }
    }
    std::panic::set_hook(previous);
    assert!(
        failures.is_empty(),
        "{} of {runs} mutants failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(runs >= examples().len() * MUTANTS);
}
