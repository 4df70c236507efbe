//! Agreement with libigl 2.6.3 (`../shared/reference/libigl_*.json`) to 1e-10.

use crate::common;

use deform::mesh::validate::validate;
use deform::operators::harmonic::{harmonic_field, HarmonicOptions};
use deform::operators::laplacian::cotangent_laplacian;

const CASES: &[&str] = &["libigl_knight.json", "libigl_tube_41x24.json"];

#[test]
fn cotangent_matrix_matches_libigl() {
    for name in CASES {
        let Some(r) = common::reference(name) else {
            return;
        };
        let mesh = common::reference_mesh(&r);
        assert!(validate(&mesh).is_clean(), "{name}");
        let l = cotangent_laplacian(&mesh, Default::default()).expect("cotmatrix");
        let (i, j, x) = (
            common::u32s(&r["cotmatrix"]["I"]),
            common::u32s(&r["cotmatrix"]["J"]),
            common::f64s(&r["cotmatrix"]["X"]),
        );
        // Sum libigl's triplets into a dense-by-key map, then compare both ways.
        let mut reference = std::collections::BTreeMap::new();
        for k in 0..x.len() {
            *reference
                .entry((i[k] as usize, j[k] as usize))
                .or_insert(0.0) += x[k];
        }
        let mut worst = 0.0f64;
        for (&(a, b), &v) in &reference {
            let ours = l.get(a, b).copied().unwrap_or(0.0);
            worst = worst.max((ours - v).abs());
        }
        for (&v, (a, b)) in l.iter() {
            let theirs = reference.get(&(a, b)).copied().unwrap_or(0.0);
            worst = worst.max((v - theirs).abs());
        }
        assert!(worst < 1e-10, "{name}: max |L - L_igl| = {worst:e}");
        assert_eq!(l.nnz(), reference.len(), "{name}: same sparsity pattern");
    }
}

#[test]
fn harmonic_field_matches_libigl() {
    for name in CASES {
        let Some(r) = common::reference(name) else {
            return;
        };
        let mesh = common::reference_mesh(&r);
        let fixed = common::u32s(&r["spec"]["fixed"]);
        let handles = common::u32s(&r["spec"]["handles"]);
        let expect = common::f64s(&r["harmonic"]);
        let x =
            harmonic_field(&mesh, &fixed, &handles, HarmonicOptions::default()).expect("harmonic");
        let worst = x
            .iter()
            .zip(&expect)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-10, "{name}: max |x - x_igl| = {worst:e}");
        // Non-trivial: the field takes intermediate values.
        assert!(expect.iter().any(|&v| v > 0.1 && v < 0.9), "{name}");
    }
}
