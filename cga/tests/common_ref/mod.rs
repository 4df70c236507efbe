//! Shared helpers: locating `../shared/reference` and converting clifford's orthonormal basis.

#![allow(dead_code)]

use ga_codegen::Multivector;
use std::path::PathBuf;

/// The reference directory: `$CGA_REFERENCE_DIR`, else `<workspace>/../shared/reference`.
/// `None` (with a message) when absent; under `CI=true` absence is a failure.
pub fn reference_dir() -> Option<PathBuf> {
    let dir = devkit::shared::shared_dir(devkit::shared::REFERENCE_VAR, "reference");
    if dir.join("cga_oracle_seed2.json").is_file() {
        return Some(dir);
    }
    devkit::shared::missing(
        format_args!("reference data missing at {} (CI=true)", dir.display()),
        format_args!("reference data not found at {}", dir.display()),
    )
}

pub fn load_oracle() -> Option<serde_json::Value> {
    let dir = reference_dir()?;
    let text = std::fs::read_to_string(dir.join("cga_oracle_seed2.json")).expect("read oracle");
    Some(serde_json::from_str(&text).expect("parse oracle"))
}

pub fn f64s(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

pub fn vec3(v: &serde_json::Value) -> glam::DVec3 {
    let a = f64s(v);
    glam::DVec3::new(a[0], a[1], a[2])
}

/// Convert a clifford g3c coefficient list (shortlex blades over orthonormal e1..e5 with
/// e4 = e+, e5 = e-) to the project's null basis: e4 = 0.5 ei - eo, e5 = 0.5 ei + eo.
pub fn from_clifford(oracle: &serde_json::Value, coeffs: &serde_json::Value) -> Multivector {
    let alg = cga::f64::algebra();
    let bitmaps: Vec<u64> = oracle["convention"]["blade_bitmaps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b.as_u64().unwrap())
        .collect();
    let c = f64s(coeffs);
    // Null-basis bitmaps: eo = 1, e1 = 2, e2 = 4, e3 = 8, ei = 16.
    let basis = |i: usize| -> Multivector {
        match i {
            0 => Multivector::blade(&alg, 2, 1.0),
            1 => Multivector::blade(&alg, 4, 1.0),
            2 => Multivector::blade(&alg, 8, 1.0),
            3 => &Multivector::blade(&alg, 16, 0.5) + &Multivector::blade(&alg, 1, -1.0),
            4 => &Multivector::blade(&alg, 16, 0.5) + &Multivector::blade(&alg, 1, 1.0),
            _ => unreachable!(),
        }
    };
    let mut out = Multivector::zero(&alg);
    for (k, &bm) in bitmaps.iter().enumerate() {
        if c[k] == 0.0 {
            continue;
        }
        let mut blade = Multivector::scalar(&alg, c[k]);
        for i in 0..5 {
            if bm & (1 << i) != 0 {
                blade = blade.gp(&basis(i));
            }
        }
        out = &out + &blade;
    }
    out
}
