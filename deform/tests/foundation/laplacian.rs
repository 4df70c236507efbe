//! Laplacians and mass matrices against closed-form cases.

use crate::common;
use deform::mesh::MeshError;

use common::{grid, mul};
use deform::operators::laplacian::{
    cotangent_laplacian, mean_value_laplacian, mean_value_weights, uniform_laplacian,
    CotangentOptions, DegeneratePolicy,
};
use deform::operators::mass::{mass_diagonal, MassKind};
use deform::Mesh;
use glam::DVec3;
use proptest::prelude::*;
use sprs::CsMat;

fn interior(nx: u32, ny: u32) -> impl Iterator<Item = usize> {
    (1..ny - 1).flat_map(move |j| (1..nx - 1).map(move |i| (j * nx + i) as usize))
}

fn max_row_sum(l: &CsMat<f64>) -> f64 {
    mul(l, &vec![1.0; l.rows()])
        .iter()
        .fold(0.0, |m, s| m.max(s.abs()))
}

fn max_asymmetry(l: &CsMat<f64>) -> f64 {
    l.iter()
        .map(|(&v, (i, j))| (v - l.get(j, i).copied().unwrap_or(0.0)).abs())
        .fold(0.0, f64::max)
}

#[test]
fn cotangent_on_a_regular_grid_is_the_five_point_stencil() {
    // Right isosceles triangles: axis edges get 1 (two 45° angles: 2 * cot 45° / 2), the
    // diagonals 0 (two right angles), interior diagonal entries -4.
    let (nx, ny) = (5, 4);
    let l = cotangent_laplacian(&grid(nx, ny, false), Default::default()).expect("L");
    for i in interior(nx, ny) {
        assert!((l.get(i, i).unwrap() + 4.0).abs() < 1e-14);
        for (j, &v) in l.outer_view(i).unwrap().iter() {
            if j == i {
                continue;
            }
            let axis = j == i + 1 || j + 1 == i || j == i + nx as usize || j + nx as usize == i;
            let expect = if axis { 1.0 } else { 0.0 };
            assert!((v - expect).abs() < 1e-14, "L[{i},{j}] = {v}");
        }
    }
}

#[test]
fn equilateral_weights() {
    // Two equilateral triangles sharing edge 0-1: interior edge (cot 60° + cot 60°)/2.
    let h = 3f64.sqrt() / 2.0;
    let m = Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(0.5, h, 0.0),
            DVec3::new(0.5, -h, 0.0),
        ],
        vec![[0, 1, 2], [1, 0, 3]],
    );
    let l = cotangent_laplacian(&m, Default::default()).expect("L");
    let c = 1.0 / 3f64.sqrt();
    assert!((l.get(0, 1).unwrap() - c).abs() < 1e-15);
    assert!((l.get(0, 2).unwrap() - c / 2.0).abs() < 1e-15);
    assert!((l.get(0, 0).unwrap() + 2.0 * c).abs() < 1e-15);
    // Equilateral: Voronoi and barycentric shares coincide.
    let v = mass_diagonal(&m, MassKind::Voronoi).expect("mass");
    let b = mass_diagonal(&m, MassKind::Barycentric).expect("mass");
    for (x, y) in v.iter().zip(&b) {
        assert!((x - y).abs() < 1e-15);
    }
    assert!((b[0] - 2.0 * h / 2.0 / 3.0).abs() < 1e-15);
}

#[test]
fn cotangent_reproduces_linear_functions_on_a_flat_irregular_grid() {
    let (nx, ny) = (9, 7);
    let m = grid(nx, ny, true);
    assert!(deform::mesh::validate::validate(&m).is_clean());
    let l = cotangent_laplacian(&m, Default::default()).expect("L");
    let f: Vec<f64> = m
        .positions
        .iter()
        .map(|p| 2.0 * p.x - 3.5 * p.y + 0.25)
        .collect();
    let lf = mul(&l, &f);
    for i in interior(nx, ny) {
        assert!(lf[i].abs() < 1e-12, "(L f)[{i}] = {}", lf[i]);
    }
    // ... but not at the boundary (so the test can tell).
    assert!(lf.iter().any(|v| v.abs() > 1e-3));
    assert!(max_row_sum(&l) < 1e-13);
    assert!(max_asymmetry(&l) < 1e-14);
}

#[test]
fn mean_value_directed_weights_reproduce_linear_functions() {
    let (nx, ny) = (9, 7);
    let m = grid(nx, ny, true);
    let w = mean_value_weights(&m).expect("mean-value W");
    let f: Vec<f64> = m
        .positions
        .iter()
        .map(|p| -1.5 * p.x + 0.75 * p.y + 4.0)
        .collect();
    let wf = mul(&w, &f);
    for i in interior(nx, ny) {
        assert!(wf[i].abs() < 1e-12, "(W f)[{i}] = {}", wf[i]);
    }
    assert!(max_row_sum(&w) < 1e-13);
    assert!(
        max_asymmetry(&w) > 1e-3,
        "directed weights are not symmetric"
    );
    // The symmetrised matrix: symmetric, zero row sums, positive off-diagonal weights.
    let s = mean_value_laplacian(&m).expect("mean-value L");
    assert!(max_asymmetry(&s) == 0.0);
    assert!(max_row_sum(&s) < 1e-13);
    for (&v, (i, j)) in s.iter() {
        if i != j {
            assert!(v > 0.0, "S[{i},{j}] = {v}");
        }
    }
    // It is the symmetric part of the directed matrix.
    for (&v, (i, j)) in s.iter() {
        let expect = 0.5 * (w.get(i, j).unwrap() + w.get(j, i).unwrap());
        assert!(i == j || (v - expect).abs() < 1e-14);
    }
}

/// Every Laplacian and mass matrix refuses out-of-range indices (they panicked) and
/// non-finite or huge coordinates (they skipped the NaN triangles and returned `Ok`).
#[test]
fn laplacians_and_masses_refuse_bad_elements() {
    use deform::operators::laplacian::laplacian;
    use deform::operators::laplacian::{mean_value_weights, LaplacianKind};
    use deform::operators::mass::{mass_diagonal, mass_matrix, MassKind};
    let good = || Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
    let mut out_of_range = good();
    out_of_range.triangles[0] = [0, 1, 7];
    let mut nan = good();
    nan.positions[2].y = f64::NAN;
    let mut huge = good();
    huge.positions[1].x = 1e301;
    for (m, what) in [
        (out_of_range, "triangles [0] refer to vertices outside 0..3"),
        (nan, "vertices [2] have non-finite coordinates"),
        (huge, "vertices [1] have coordinates beyond"),
    ] {
        let results = [
            cotangent_laplacian(&m, Default::default()).map(|_| ()),
            mean_value_laplacian(&m).map(|_| ()),
            mean_value_weights(&m).map(|_| ()),
            uniform_laplacian(&m).map(|_| ()),
            laplacian(&m, LaplacianKind::Uniform).map(|_| ()),
            mass_diagonal(&m, MassKind::Voronoi).map(|_| ()),
            mass_matrix(&m, MassKind::Barycentric).map(|_| ()),
        ];
        for (k, r) in results.into_iter().enumerate() {
            let e = r.expect_err(what).to_string();
            assert!(e.contains(what), "function {k}: {e}");
        }
    }
}

#[test]
fn uniform_is_the_graph_laplacian() {
    let (nx, ny) = (4, 4);
    let m = grid(nx, ny, true);
    let l = uniform_laplacian(&m).unwrap();
    let rings = m.one_rings();
    for i in 0..m.vertex_count() {
        assert_eq!(l.get(i, i).copied(), Some(-(rings.row(i).len() as f64)));
        for &j in rings.row(i) {
            assert_eq!(l.get(i, j as usize).copied(), Some(1.0));
        }
    }
    assert_eq!(max_row_sum(&l), 0.0);
}

#[test]
fn obtuse_weights_kept_or_clamped() {
    // A flat kite with a very obtuse angle opposite the shared edge 0-1 on both sides.
    let m = Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::new(4.0, 0.0, 0.0),
            DVec3::new(2.0, 0.3, 0.0),
            DVec3::new(2.0, -0.3, 0.0),
        ],
        vec![[0, 1, 2], [1, 0, 3]],
    );
    let raw = cotangent_laplacian(&m, Default::default()).expect("L");
    let w = raw.get(0, 1).copied().unwrap();
    // cot of the angle at 2: dot / |cross| with e = (-2, -0.3), (2, -0.3).
    let cot = (-4.0 + 0.09) / (2.0 * 2.0 * 0.3);
    assert!((w - cot).abs() < 1e-14, "{w} vs {cot}");
    assert!(w < 0.0);
    let clamped = cotangent_laplacian(
        &m,
        CotangentOptions {
            clamp_negative: true,
            ..Default::default()
        },
    )
    .expect("L");
    assert_eq!(clamped.get(0, 1).copied(), Some(0.0));
    assert!(max_row_sum(&clamped) < 1e-14);
    for (&v, (i, j)) in clamped.iter() {
        assert!(i == j || v >= 0.0);
    }
}

#[test]
fn degenerate_triangles_skipped_or_reported() {
    let mut m = grid(3, 3, false);
    // Collapse triangle 0 by moving its corner onto a line: make a zero-area sliver.
    m.positions.push(DVec3::new(0.5, 0.0, 0.0));
    let sliver = [0u32, 9, 1];
    m.triangles.push(sliver);
    let l = cotangent_laplacian(&m, Default::default()).expect("skipped");
    assert!(l.data().iter().all(|v| v.is_finite()));
    assert_eq!(l.get(9, 9).copied(), Some(0.0));
    let err = cotangent_laplacian(
        &m,
        CotangentOptions {
            degenerate: DegeneratePolicy::Error,
            ..Default::default()
        },
    );
    match err {
        Err(deform::operators::SolveError::Mesh(MeshError::DegenerateTriangles { faces })) => {
            assert_eq!(faces.0, vec![8])
        }
        other => panic!("{other:?}"),
    }
    assert!(mean_value_laplacian(&m)
        .expect("mean-value L")
        .data()
        .iter()
        .all(|v| v.is_finite()));
    assert_eq!(mass_diagonal(&m, MassKind::Voronoi).expect("mass")[9], 0.0);
}

#[test]
fn mass_matrices_sum_to_the_area() {
    let m = grid(6, 5, true);
    let area = m.area();
    for kind in [MassKind::Barycentric, MassKind::Voronoi] {
        let d = mass_diagonal(&m, kind).expect("mass");
        let total: f64 = d.iter().sum();
        assert!((total - area).abs() < 1e-12 * area, "{kind:?}");
        assert!(d.iter().all(|&x| x > 0.0));
    }
    // A right triangle: obtuse rule not triggered, Voronoi areas 1/4, 1/8, 1/8.
    let t = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
    assert_eq!(
        mass_diagonal(&t, MassKind::Voronoi).expect("mass"),
        vec![0.25, 0.125, 0.125]
    );
    // An obtuse triangle: half to the obtuse corner.
    let o = Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::new(4.0, 0.0, 0.0),
            DVec3::new(2.0, 0.5, 0.0),
        ],
        vec![[0, 1, 2]],
    );
    assert_eq!(
        mass_diagonal(&o, MassKind::Voronoi).expect("mass"),
        vec![0.25, 0.25, 0.5]
    );
    let mm = deform::operators::mass::mass_matrix(&o, MassKind::Barycentric).expect("M");
    assert_eq!(mm.nnz(), 3);
    assert!((mm.get(2, 2).unwrap() - 1.0 / 3.0).abs() < 1e-15);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// On any bumpy grid: symmetric, zero row sums, and `-L` positive semi-definite.
    #[test]
    fn laplacians_are_symmetric_psd_with_zero_row_sums(
        heights in prop::collection::vec(-1.0f64..1.0, 25),
        x in prop::collection::vec(-1.0f64..1.0, 25),
    ) {
        let mut m = grid(5, 5, true);
        for (p, h) in m.positions.iter_mut().zip(&heights) {
            p.z = *h;
        }
        for l in [
            cotangent_laplacian(&m, Default::default()).unwrap(),
            mean_value_laplacian(&m).expect("mean-value L"),
            uniform_laplacian(&m).unwrap(),
        ] {
            prop_assert!(max_asymmetry(&l) < 1e-13);
            prop_assert!(max_row_sum(&l) < 1e-12);
            let lx = mul(&l, &x);
            let energy: f64 = -x.iter().zip(&lx).map(|(a, b)| a * b).sum::<f64>();
            prop_assert!(energy > -1e-12, "x^T (-L) x = {}", energy);
        }
    }
}
