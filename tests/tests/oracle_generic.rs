//! The generic `Multivector` for G(4,1) and the generated CGA general multivector (`cga::Mv`)
//! against the independent values of the Python `clifford` package in
//! `../shared/reference/cga_oracle_seed2.json` (60 random pairs of general multivectors:
//! geometric, outer and left-contraction products, reverse, grade involution, Clifford
//! conjugate and dual) to 1e-12.

use ga_codegen::Multivector;
use serde_json::Value;
use std::path::PathBuf;

const TOL: f64 = 1e-12;

fn load_oracle() -> Option<Value> {
    let dir = match std::env::var_os("CGA_REFERENCE_DIR") {
        Some(d) => PathBuf::from(d),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/reference"),
    };
    let path = dir.join("cga_oracle_seed2.json");
    if !path.is_file() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "reference data missing at {} (CI=true)",
            path.display()
        );
        eprintln!("skipped: reference data not found at {}", path.display());
        return None;
    }
    let text = std::fs::read_to_string(&path).expect("read oracle");
    Some(serde_json::from_str(&text).expect("parse oracle"))
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// Converts clifford's coefficients (shortlex blades over orthonormal e1..e5, e4 = e+, e5 = e-)
/// to the null basis `eo, e1, e2, e3, ei`: e4 = ei/2 - eo, e5 = ei/2 + eo. Each orthonormal blade
/// is the outer product of its (mutually orthogonal) vectors.
fn from_clifford(oracle: &Value, coeffs: &Value) -> Multivector {
    let alg = cga::f64::algebra();
    let bitmaps: Vec<u64> = oracle["convention"]["blade_bitmaps"]
        .as_array()
        .expect("blade_bitmaps")
        .iter()
        .map(|b| b.as_u64().expect("bitmap"))
        .collect();
    // Null-basis bitmaps: eo = 1, e1 = 2, e2 = 4, e3 = 8, ei = 16.
    let vector = |i: usize| -> Multivector {
        let mut v = Multivector::zero(&alg);
        match i {
            0 => v.set(2, 1.0),
            1 => v.set(4, 1.0),
            2 => v.set(8, 1.0),
            3 => {
                v.set(16, 0.5);
                v.set(1, -1.0);
            }
            _ => {
                v.set(16, 0.5);
                v.set(1, 1.0);
            }
        }
        v
    };
    let c = numbers(coeffs);
    assert_eq!(c.len(), 32);
    let mut out = Multivector::zero(&alg);
    for (k, &bm) in bitmaps.iter().enumerate() {
        if c[k] == 0.0 {
            continue;
        }
        let mut blade = Multivector::scalar(&alg, c[k]);
        for i in 0..5 {
            if bm & (1 << i) != 0 {
                blade = blade.outer(&vector(i));
            }
        }
        out = &out + &blade;
    }
    out
}

#[test]
fn oracle_conversion_is_an_algebra_map() {
    let Some(o) = load_oracle() else { return };
    // eo and einf as clifford defines them are our eo and ei; clifford's I5 = e12345 is our
    // pseudoscalar eo123i.
    let alg = cga::f64::algebra();
    let eo = from_clifford(&o, &o["convention"]["eo"]["coeffs"]);
    let ei = from_clifford(&o, &o["convention"]["einf"]["coeffs"]);
    assert!(eo.max_diff(&Multivector::blade(&alg, 1, 1.0)) < TOL);
    assert!(ei.max_diff(&Multivector::blade(&alg, 16, 1.0)) < TOL);
    let mut i5 = vec![0.0; 32];
    i5[31] = 1.0;
    let i5 = from_clifford(&o, &serde_json::json!(i5));
    assert!(i5.max_diff(&Multivector::pseudoscalar(&alg)) < TOL);
}

#[test]
fn generic_multivector_matches_clifford() {
    let Some(o) = load_oracle() else { return };
    let cases = o["general"].as_array().expect("general cases");
    assert_eq!(cases.len(), 60);
    let mut worst = 0.0f64;
    for (k, c) in cases.iter().enumerate() {
        let a = from_clifford(&o, &c["a"]);
        let b = from_clifford(&o, &c["b"]);
        let checks: [(&str, Multivector, &str); 7] = [
            ("gp", a.gp(&b), "gp"),
            ("outer", a.outer(&b), "op"),
            ("left contraction", a.left_contraction(&b), "lc"),
            ("reverse", a.rev(), "reverse_a"),
            ("grade involution", a.involute(), "grade_involution_a"),
            ("conjugate", a.conjugate(), "clifford_conjugate_a"),
            ("dual", a.dual(), "dual_a"),
        ];
        for (what, ours, key) in checks {
            let want = from_clifford(&o, &c[key]);
            let d = ours.max_diff(&want);
            worst = worst.max(d);
            assert!(d < TOL, "case {k}: generic {what} differs by {d:e}");
        }
    }
    println!("generic multivector vs clifford: worst difference {worst:e}");
}

#[test]
fn generated_cga_multivector_matches_clifford() {
    let Some(o) = load_oracle() else { return };
    let cases = o["general"].as_array().expect("general cases");
    let mut worst = 0.0f64;
    for (k, c) in cases.iter().enumerate() {
        let a = cga::Mv::from_multivector(&from_clifford(&o, &c["a"]));
        let b = cga::Mv::from_multivector(&from_clifford(&o, &c["b"]));
        let checks: [(&str, cga::Mv, &str); 7] = [
            ("*", a * b, "gp"),
            ("^", a ^ b, "op"),
            ("|", a | b, "lc"),
            ("rev", a.rev(), "reverse_a"),
            ("involute", a.involute(), "grade_involution_a"),
            ("conjugate", a.conjugate(), "clifford_conjugate_a"),
            ("dual", a.dual(), "dual_a"),
        ];
        for (what, ours, key) in checks {
            let want = from_clifford(&o, &c[key]);
            let d = ours.to_multivector().max_diff(&want);
            worst = worst.max(d);
            assert!(d < TOL, "case {k}: generated Mv {what} differs by {d:e}");
        }
    }
    println!("generated cga::Mv vs clifford: worst difference {worst:e}");
}
