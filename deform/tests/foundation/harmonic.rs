//! Harmonic fields and coordinates on real data, and bad input.

use crate::common;
use deform::mesh::MeshError;
use deform::operators::SolveError;

use common::{grid, mul};
use deform::mesh::io::{read_dmat, read_mesh};
use deform::operators::harmonic::{
    harmonic_coordinates, harmonic_field, Harmonic, HarmonicOptions,
};
use deform::operators::laplacian::{cotangent_laplacian, LaplacianKind};
use deform::operators::solve::{DirichletSolver, Parallelism, SolverOptions};
use deform::Mesh;
use glam::DVec3;

/// Mesh and selection groups (`-1` free, then groups 0, 1, 2).
fn selection(mesh: &str, sel: &str) -> Option<(Mesh, Vec<Vec<u32>>)> {
    let dir = common::data_dir()?.join("meshes/libigl");
    let m = read_mesh(dir.join(mesh)).expect("mesh");
    let s = read_dmat(dir.join(sel)).expect("selection");
    Some((
        m,
        (0..3)
            .map(|g| s.rows_equal_to(g).expect("selection"))
            .collect(),
    ))
}

#[test]
fn knight_field_is_bounded_exact_and_harmonic() {
    let Some((m, groups)) = selection("decimated-knight.off", "decimated-knight-selection.dmat")
    else {
        return;
    };
    let fixed = &groups[0];
    let handles: Vec<u32> = groups[1].iter().chain(&groups[2]).copied().collect();
    let x = harmonic_field(&m, fixed, &handles, HarmonicOptions::default()).expect("field");
    assert!(
        x.iter().all(|v| (0.0..=1.0).contains(v)),
        "field leaves [0, 1]"
    );
    assert!(fixed.iter().all(|&v| x[v as usize] == 0.0));
    assert!(handles.iter().all(|&v| x[v as usize] == 1.0));
    let l = cotangent_laplacian(&m, Default::default()).expect("L");
    let lx = mul(&l, &x);
    let mut constrained = vec![false; m.vertex_count()];
    fixed
        .iter()
        .chain(&handles)
        .for_each(|&v| constrained[v as usize] = true);
    let worst = (0..m.vertex_count())
        .filter(|&i| !constrained[i])
        .map(|i| lx[i].abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-9, "Laplace residual {worst:e}");
    // Not trivially constant: intermediate values exist.
    assert!(x.iter().filter(|v| **v > 0.05 && **v < 0.95).count() > 100);
}

#[test]
fn max_coordinates_are_a_partition_of_unity() {
    let Some((m, groups)) = selection("decimated-max.obj", "decimated-max-selection.dmat") else {
        return;
    };
    let sets: Vec<&[u32]> = groups.iter().map(|g| g.as_slice()).collect();
    let w = harmonic_coordinates(&m, &sets, HarmonicOptions::default()).expect("coordinates");
    assert_eq!(w.len(), 3);
    let worst = (0..m.vertex_count())
        .map(|i| (w.iter().map(|c| c[i]).sum::<f64>() - 1.0).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-10, "partition of unity off by {worst:e}");
    for (j, c) in w.iter().enumerate() {
        for (k, g) in groups.iter().enumerate() {
            let want = if j == k { 1.0 } else { 0.0 };
            assert!(g.iter().all(|&v| c[v as usize] == want));
        }
    }
    // Every coordinate is used somewhere away from its set.
    for c in &w {
        assert!(c.iter().filter(|v| **v > 0.01 && **v < 0.99).count() > 50);
    }
}

#[test]
fn biharmonic_and_other_laplacians_keep_partition_of_unity() {
    let m = grid(8, 6, true);
    let sets: [&[u32]; 3] = [&[0, 8, 16], &[7, 15], &[43, 44, 45]];
    for (laplacian, order) in [
        (LaplacianKind::Default, 2),
        (LaplacianKind::MeanValue, 1),
        (LaplacianKind::Uniform, 1),
        (LaplacianKind::MeanValue, 2),
    ] {
        let opts = HarmonicOptions {
            laplacian,
            order,
            ..Default::default()
        };
        let w = harmonic_coordinates(&m, &sets, opts).expect("coordinates");
        for i in 0..m.vertex_count() {
            let s: f64 = w.iter().map(|c| c[i]).sum();
            assert!((s - 1.0).abs() < 1e-12, "{laplacian:?} k={order}: {s}");
        }
        if order == 1 {
            // Positive weights: maximum principle.
            assert!(w
                .iter()
                .flatten()
                .all(|v| (-1e-14..=1.0 + 1e-14).contains(v)));
        }
    }
}

#[test]
fn biharmonic_reproduces_linear_functions_on_a_flat_grid() {
    // Bilaplacian with two rings of Dirichlet data: a linear function is exact.
    let (nx, ny) = (9, 8);
    let m = grid(nx, ny, true);
    let ring = |i: u32, j: u32| i < 2 || j < 2 || i + 2 >= nx || j + 2 >= ny;
    let boundary: Vec<u32> = (0..nx * ny).filter(|&v| ring(v % nx, v / nx)).collect();
    let f = |p: DVec3| 0.5 * p.x - 2.0 * p.y + 1.0;
    let opts = HarmonicOptions {
        order: 2,
        ..Default::default()
    };
    let q = deform::operators::harmonic::harmonic_system(&m, &opts).expect("Q");
    let s = DirichletSolver::new(&q, &boundary, SolverOptions::default()).expect("solver");
    let bc: Vec<f64> = boundary
        .iter()
        .map(|&v| f(m.positions[v as usize]))
        .collect();
    let x = s.solve(&bc, 1).expect("solve");
    for (v, p) in m.positions.iter().enumerate() {
        assert!((x[v] - f(*p)).abs() < 1e-10, "vertex {v}");
    }
}

#[test]
fn solver_reuse_multi_column_and_parallel() {
    let m = grid(10, 10, true);
    let q = cotangent_laplacian(&m, Default::default())
        .expect("L")
        .map(|v| -v);
    let bnd: Vec<u32> = (0..100).filter(|v| v % 10 == 0 || v % 10 == 9).collect();
    let mut s = DirichletSolver::new(&q, &bnd, SolverOptions::default()).expect("solver");
    // Two columns at once equal two single solves.
    let nc = bnd.len();
    let bc: Vec<f64> = (0..2 * nc).map(|k| (k as f64 * 0.37).sin()).collect();
    let both = s.solve(&bc, 2).expect("2 columns");
    let a = s.solve(&bc[..nc], 1).expect("col 0");
    let b = s.solve(&bc[nc..], 1).expect("col 1");
    assert_eq!(&both[..100], a.as_slice());
    assert_eq!(&both[100..], b.as_slice());
    // Parallel factorisation gives the same field.
    let par = DirichletSolver::new(
        &q,
        &bnd,
        SolverOptions {
            parallelism: Parallelism::Rayon(2),
            ..Default::default()
        },
    )
    .expect("parallel");
    let p = par.solve(&bc, 2).expect("parallel solve");
    assert!(p.iter().zip(&both).all(|(x, y)| (x - y).abs() < 1e-12));
    // New values, same pattern: symbolic reuse; scaling Q leaves the field unchanged.
    let q2 = q.map(|v| 3.0 * v);
    s.update_values(&q2).expect("same pattern");
    let c = s.solve(&bc, 2).expect("after update");
    assert!(c.iter().zip(&both).all(|(x, y)| (x - y).abs() < 1e-12));
    // A right-hand side: Q x = b with b = Q f reproduces f.
    let f: Vec<f64> = (0..100).map(|k| (k as f64).cos()).collect();
    let b = mul(&q2, &f);
    let fb: Vec<f64> = bnd.iter().map(|&v| f[v as usize]).collect();
    let mut out = vec![0.0; 100];
    let mut scratch = s.scratch(1).expect("scratch");
    s.solve_into(Some(&b), &fb, 1, &mut out, &mut scratch)
        .expect("rhs");
    assert!(out.iter().zip(&f).all(|(x, y)| (x - y).abs() < 1e-10));
    // A different pattern is refused; a new constrained set refactors.
    let other = cotangent_laplacian(&grid(10, 10, false), Default::default())
        .expect("L")
        .map(|v| -v);
    let mut pattern_changed = q.clone();
    pattern_changed.insert(0, 99, 0.0);
    assert!(matches!(
        s.update_values(&pattern_changed),
        Err(SolveError::PatternChanged)
    ));
    s.set_constrained(&other, &[0, 99]).expect("new set");
    assert_eq!(s.constrained(), &[0, 99]);
    let x = s.solve(&[0.0, 1.0], 1).expect("solve");
    assert!(x.iter().all(|v| (0.0..=1.0).contains(v)));
}

fn two_triangles_apart() -> Mesh {
    Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::X,
            DVec3::Y,
            DVec3::new(5.0, 0.0, 0.0),
            DVec3::new(6.0, 0.0, 0.0),
            DVec3::new(5.0, 1.0, 0.0),
        ],
        vec![[0, 1, 2], [3, 4, 5]],
    )
}

/// A component or a vertex without constraints, or no constraint at all: `Unconstrained`,
/// naming the vertices, in the message too.
#[test]
fn unconstrained_components_and_vertices_are_named() {
    let o = HarmonicOptions::default();
    // A component without constraints.
    match harmonic_field(&two_triangles_apart(), &[0], &[1], o) {
        Err(SolveError::Unconstrained {
            components,
            isolated,
            vertices,
        }) => {
            assert_eq!(components, 1);
            assert_eq!(isolated, 0, "a triangle is no single vertex");
            assert_eq!(vertices.0, vec![3, 4, 5]);
        }
        other => panic!("{other:?}"),
    }
    // An unreferenced vertex.
    let mut m = grid(3, 3, false);
    m.positions.push(DVec3::ONE);
    match harmonic_field(&m, &[0], &[8], o) {
        Err(SolveError::Unconstrained { vertices, .. }) => assert_eq!(vertices.0, vec![9]),
        other => panic!("{other:?}"),
    }
    // No constraint at all.
    let m = grid(3, 3, false);
    assert!(matches!(
        harmonic_field(&m, &[], &[], o),
        Err(SolveError::Unconstrained { .. })
    ));
    // Messages name the vertices.
    let e = harmonic_field(&two_triangles_apart(), &[0], &[1], o).unwrap_err();
    assert!(e.to_string().contains("[3, 4, 5]"), "{e}");
}

/// Constraints out of range or on one vertex twice name the vertices; an empty mesh is
/// `EmptyMesh`.
#[test]
fn bad_constraints_and_an_empty_mesh_give_typed_errors() {
    let o = HarmonicOptions::default();
    let m = grid(3, 3, false);
    match harmonic_field(&m, &[0, 12], &[8, 40], o) {
        Err(SolveError::Mesh(MeshError::ConstraintOutOfRange { vertices, .. })) => {
            assert_eq!(vertices.0, vec![12, 40])
        }
        other => panic!("{other:?}"),
    }
    match harmonic_field(&m, &[0, 4], &[8, 4], o) {
        Err(SolveError::Mesh(MeshError::OverlappingConstraints { vertices })) => {
            assert_eq!(vertices.0, vec![4])
        }
        other => panic!("{other:?}"),
    }
    match harmonic_field(&m, &[0, 0], &[8], o) {
        Err(SolveError::Mesh(MeshError::OverlappingConstraints { vertices })) => {
            assert_eq!(vertices.0, vec![0])
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        harmonic_field(&Mesh::default(), &[], &[], o),
        Err(SolveError::Mesh(MeshError::EmptyMesh { .. }))
    ));
}

/// Non-finite coordinates, non-manifold edges and vertices, and bad triangle indices name
/// the vertices, the edge or the faces.
#[test]
fn bad_geometry_names_the_vertices_edges_and_faces() {
    let o = HarmonicOptions::default();
    // Non-finite coordinates.
    let mut nan = grid(3, 3, false);
    nan.positions[4].y = f64::NAN;
    match harmonic_field(&nan, &[0], &[8], o) {
        Err(SolveError::Mesh(MeshError::NonFinite { vertices })) => assert_eq!(vertices.0, vec![4]),
        other => panic!("{other:?}"),
    }
    // Three triangles on one edge (0-1).
    let fin = Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z, DVec3::NEG_Y],
        vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]],
    );
    match harmonic_field(&fin, &[2], &[3], o) {
        Err(SolveError::Mesh(MeshError::NonManifold { edge_vertices, .. })) => {
            assert_eq!(edge_vertices.0, vec![0, 1])
        }
        other => panic!("{other:?}"),
    }
    // A bow-tie vertex (0) joining two fans.
    let bow = Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::NEG_X, DVec3::NEG_Y],
        vec![[0, 1, 2], [0, 3, 4]],
    );
    match harmonic_field(&bow, &[1], &[3], o) {
        Err(SolveError::Mesh(MeshError::NonManifold { vertices, .. })) => {
            assert_eq!(vertices.0, vec![0])
        }
        other => panic!("{other:?}"),
    }
    // Bad triangle indices.
    let bad = Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    match harmonic_field(&bad, &[0], &[1], o) {
        Err(SolveError::Mesh(MeshError::FaceIndexOutOfRange { faces, .. })) => {
            assert_eq!(faces.0, vec![1])
        }
        other => panic!("{other:?}"),
    }
}

/// Unsupported order, wrong value counts, non-finite boundary values.
#[test]
fn bad_boundary_values_and_orders_give_typed_errors() {
    let o = HarmonicOptions::default();
    let m = grid(3, 3, false);
    let h = Harmonic::new(&m, &[&[0], &[8]], o).expect("ok");
    assert!(matches!(
        h.field(&[0.0]),
        Err(SolveError::Mesh(MeshError::DimensionMismatch { .. }))
    ));
    assert!(matches!(
        h.field(&[0.0, f64::NAN]),
        Err(SolveError::Mesh(MeshError::NonFinite { .. }))
    ));
    let o3 = HarmonicOptions { order: 3, ..o };
    assert!(matches!(
        Harmonic::new(&m, &[&[0], &[8]], o3),
        Err(SolveError::Mesh(MeshError::InvalidArgument(_)))
    ));
}

/// Without the component check, a singular system fails in the factorisation, not as NaN,
/// naming a vertex of the unconstrained component.
#[test]
fn an_unchecked_singular_system_fails_in_the_factorisation() {
    let q = cotangent_laplacian(&two_triangles_apart(), Default::default())
        .expect("L")
        .map(|v| -v);
    let unchecked = SolverOptions {
        check_components: false,
        ..Default::default()
    };
    match DirichletSolver::new(&q, &[0], unchecked) {
        Err(SolveError::NotPositiveDefinite(msg)) => {
            let v: u32 = msg
                .rsplit(' ')
                .next()
                .and_then(|t| t.parse().ok())
                .expect("a vertex");
            assert!([3, 4, 5].contains(&v), "{msg}");
        }
        other => panic!("{other:?}"),
    }
}

/// `Harmonic::new` orders the Laplacian's pattern while the weights are computed (two
/// threads when the pool has them); it must give the bits of the sequential path (the
/// system matrix, then a fresh `DirichletSolver`), on any pool, for every Laplacian.
#[test]
fn overlapped_bind_gives_the_sequential_bits() {
    let Some((m, groups)) = selection("decimated-knight.off", "decimated-knight-selection.dmat")
    else {
        return;
    };
    let sets: Vec<&[u32]> = groups.iter().map(Vec::as_slice).collect();
    let constrained: Vec<u32> = groups.iter().flatten().copied().collect();
    for laplacian in [
        LaplacianKind::Default,
        LaplacianKind::MeanValue,
        LaplacianKind::Uniform,
    ] {
        let options = HarmonicOptions {
            laplacian,
            ..Default::default()
        };
        let q = deform::operators::harmonic::harmonic_system(&m, &options).expect("system");
        let s = DirichletSolver::new(&q, &constrained, options.solver).expect("solver");
        let mut boundary = vec![0.0; constrained.len() * 3];
        let mut at = 0;
        for (j, g) in groups.iter().enumerate() {
            boundary[j * constrained.len() + at..j * constrained.len() + at + g.len()].fill(1.0);
            at += g.len();
        }
        let expect = s.solve(&boundary, 3).expect("solve");
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("pool");
            let h = pool.install(|| Harmonic::new(&m, &sets, options).expect("harmonic"));
            let got: Vec<f64> = h.coordinates().expect("coordinates").concat();
            assert_eq!(got, expect, "{laplacian:?}, {threads} threads");
        }
    }
}

/// The three factor layouts solve the same system: the knight's coordinates agree to 1e-12.
#[test]
fn factor_layouts_agree() {
    use deform::operators::solve::Factorization;
    let Some((m, groups)) = selection("decimated-knight.off", "decimated-knight-selection.dmat")
    else {
        return;
    };
    let sets: Vec<&[u32]> = groups.iter().map(Vec::as_slice).collect();
    let solve = |factorization| {
        let options = HarmonicOptions {
            solver: SolverOptions {
                factorization,
                ..SolverOptions::default()
            },
            ..Default::default()
        };
        harmonic_coordinates(&m, &sets, options)
            .expect("coordinates")
            .concat()
    };
    let auto = solve(Factorization::Auto);
    for f in [Factorization::Supernodal, Factorization::Simplicial] {
        let other = solve(f);
        let worst = auto
            .iter()
            .zip(&other)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-12, "{f:?}: {worst:e}");
    }
}
