//! The sparse reference against the dense one: on small algebras (G(4,1) in its null basis,
//! PGA, STA, a dense non-orthogonal metric) every product of random multivectors agrees, and
//! the exact blade products agree with the dense table.

use ga_codegen::runtime::derived::DerivedProducts as _;
use ga_codegen::runtime::sparse::multivector::{SparseAlgebra, SparseMultivector};
use ga_codegen::{Algebra, Multivector};
use proptest::prelude::*;
use std::sync::Arc;

/// The metrics compared: names and rows.
fn metrics() -> Vec<(Vec<&'static str>, Vec<Vec<f64>>)> {
    let diag = |d: &[f64]| -> Vec<Vec<f64>> {
        (0..d.len())
            .map(|i| {
                (0..d.len())
                    .map(|j| if i == j { d[i] } else { 0.0 })
                    .collect()
            })
            .collect()
    };
    let mut cga = diag(&[0.0, 1.0, 1.0, 1.0, 0.0]);
    cga[0][4] = -1.0;
    cga[4][0] = -1.0;
    let dense: Vec<Vec<f64>> = (0..4)
        .map(|i| (0..4).map(|j| if i == j { 2.0 } else { 0.5 }).collect())
        .collect();
    vec![
        (vec!["eo", "e1", "e2", "e3", "ei"], cga),
        (vec!["e0", "e1", "e2", "e3"], diag(&[0.0, 1.0, 1.0, 1.0])),
        (vec!["e0", "e1", "e2", "e3"], diag(&[1.0, -1.0, -1.0, -1.0])),
        (vec!["ea", "eb", "ec", "ed"], dense),
    ]
}

/// The same random coefficients as a dense and a sparse multivector (about half the blades).
fn pair(
    dense: &Arc<Algebra>,
    sparse: &Arc<SparseAlgebra>,
    coeffs: &[Option<f64>],
) -> (Multivector, SparseMultivector) {
    let mut d = Multivector::zero(dense);
    let mut s = SparseMultivector::zero(sparse);
    for (b, c) in coeffs.iter().enumerate().take(dense.size()) {
        if let Some(x) = c {
            d.set(b as u32, *x);
            s.set(b as u32, *x);
        }
    }
    (d, s)
}

/// Largest difference between a dense and a sparse multivector.
fn diff(d: &Multivector, s: &SparseMultivector) -> f64 {
    (0..d.algebra().size() as u32)
        .map(|b| (d.get(b) - s.get(b)).abs())
        .fold(0.0, f64::max)
}

#[test]
fn blade_products_match_the_dense_table() {
    for (names, g) in metrics() {
        let dense = Algebra::from_metric(&names, &g).unwrap();
        let sparse = SparseAlgebra::from_metric(&names, &g).unwrap();
        for a in 0..dense.size() as u32 {
            for b in 0..dense.size() as u32 {
                assert_eq!(&*sparse.gp_blades(a, b), dense.gp_blades(a, b), "{names:?}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn sparse_products_equal_dense_products(
        which in 0usize..4,
        x in proptest::collection::vec(proptest::option::of(-2.0f64..2.0), 32),
        y in proptest::collection::vec(proptest::option::of(-2.0f64..2.0), 32),
    ) {
        let (names, g) = &metrics()[which];
        let dense = Algebra::from_metric(names, g).unwrap();
        let sparse = SparseAlgebra::from_metric(names, g).unwrap();
        let (dx, sx) = pair(&dense, &sparse, &x);
        let (dy, sy) = pair(&dense, &sparse, &y);
        prop_assert_eq!(diff(&dx.gp(&dy), &sx.gp(&sy)), 0.0);
        prop_assert_eq!(diff(&dx.outer(&dy), &sx.outer(&sy)), 0.0);
        prop_assert_eq!(diff(&dx.left_contraction(&dy), &sx.left_contraction(&sy)), 0.0);
        prop_assert_eq!(dx.scalar_product(&dy), sx.scalar_product(&sy));
        prop_assert_eq!(diff(&dx.rev(), &sx.rev()), 0.0);
        prop_assert_eq!(diff(&dx.involute(), &sx.involute()), 0.0);
        prop_assert_eq!(diff(&dx.conjugate(), &sx.conjugate()), 0.0);
        prop_assert_eq!(diff(&dx.grade(2), &sx.grade(2)), 0.0);
        prop_assert_eq!(dx.norm(), sx.norm());
        prop_assert_eq!(diff(&(&dx + &dy), &sx.add_scaled(&sy, 1.0)), 0.0);
        // The exponential of a bivector: the same series, term by term.
        let (db, sb) = (dx.grade(2).scale(0.5), sx.grade(2).scale(0.5));
        prop_assert_eq!(diff(&db.exp(), &sb.exp()), 0.0);
        // What the check harness of a large algebra uses: the dual (pseudoscalar or right
        // complement), the operators and the inverse of a versor (the dense one solves the
        // whole system, the sparse one divides the reverse by `R ~R`).
        prop_assert!(diff(&dx.dual(), &sx.dual()) < 1e-12);
        prop_assert_eq!(diff(&(&dx - &dy), &(&sx - &sy)), 0.0);
        prop_assert_eq!(diff(&(-&dx), &(-&sx)), 0.0);
        prop_assert_eq!(diff(&(&dx + &dy), &(&sx + &sy)), 0.0);
        prop_assert_eq!(sx.coeffs().len(), sx.terms().count());
        let (dr, sr) = (db.exp(), sb.exp());
        if let (Some(di), Some(si)) = (dr.inverse(), sr.inverse()) {
            prop_assert!(diff(&di, &si) < 1e-9 * (1.0 + di.max_abs()));
        }
        // ga-benchmark's products, which the named products of a large algebra are checked
        // against: the same definitions over the sparse operations.
        let tol = 1e-12 * (1.0 + dx.max_abs() * dy.max_abs());
        prop_assert_eq!(diff(&dx.right_contraction(&dy), &sx.right_contraction(&sy)), 0.0);
        prop_assert!(diff(&dx.dot_product(&dy), &sx.dot_product(&sy)) < tol);
        prop_assert!(diff(&dx.hestenes_inner_product(&dy), &sx.hestenes_inner_product(&sy)) < tol);
        prop_assert!(diff(&dx.commutator_product(&dy), &sx.commutator_product(&sy)) < tol);
        prop_assert!(diff(&dx.undual(), &sx.undual()) < 1e-12 * (1.0 + dx.max_abs()));
        prop_assert!(diff(&dx.regressive_product(&dy), &sx.regressive_product(&sy)) < tol);
        if dr.norm_squared().abs() > 1e-3 {
            prop_assert!(diff(&dx.reverse_quotient(&dr), &sx.reverse_quotient(&sr)) < 1e-9 * (1.0 + dx.max_abs()));
            if let (Some(d), Some(s)) = (dx.inverse_geometric_product(&dr), sx.inverse_geometric_product(&sr)) {
                prop_assert!(diff(&d, &s) < 1e-9 * (1.0 + d.max_abs()));
            }
        }
    }
}

#[test]
fn large_algebras_cost_only_the_blades_used() {
    // G(9,6): 32,768 blades, never enumerated. e_i squares to 1, the others pair up as null
    // vectors with eo.ei = -1.
    let n = 15;
    let names: Vec<String> = (0..n)
        .map(|i| format!("e{}", (b'a' + i as u8) as char))
        .collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let mut g = vec![vec![0.0; n]; n];
    for (i, row) in g.iter_mut().enumerate().take(3) {
        row[i] = 1.0;
    }
    for k in 0..6 {
        g[3 + k][9 + k] = -1.0;
        g[9 + k][3 + k] = -1.0;
    }
    let alg = SparseAlgebra::from_metric(&names, &g).unwrap();
    let start = std::time::Instant::now();
    let eo = SparseMultivector::blade(&alg, 1 << 3, 1.0);
    let ei = SparseMultivector::blade(&alg, 1 << 9, 1.0);
    assert_eq!(eo.gp(&ei).get(0), -1.0);
    assert_eq!(eo.gp(&ei).get((1 << 3) | (1 << 9)), 1.0);
    // The pseudoscalar squares to +-1 (here I ~I = 1 up to the sign of the null pairs).
    let full = (1u32 << n) - 1;
    let i = SparseMultivector::blade(&alg, full, 1.0);
    assert_eq!(i.gp(&i.rev()).get(0).abs(), 1.0);
    assert!(start.elapsed().as_secs_f64() < 10.0);
}
