//! `DirichletSolver::with_analysis`: one symbolic analysis of the whole matrix, reused for
//! every constrained set, solves as `DirichletSolver::new` does (to rounding), keeps working
//! after `update_values`, and reports the same typed errors.

use deform::mesh::shapes::icosphere;
use deform::mesh::MeshError;
use deform::operators::laplacian::cotangent_laplacian;
use deform::operators::solve::{DirichletSolver, SolverOptions, SystemAnalysis};
use deform::operators::SolveError;

fn worst(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

#[test]
fn a_shared_analysis_solves_every_constrained_set_as_a_fresh_factorisation() {
    let mesh = icosphere(1.0, 3);
    let n = mesh.vertex_count() as u32;
    let q = cotangent_laplacian(&mesh, Default::default())
        .unwrap()
        .map(|x| -x);
    let analysis = SystemAnalysis::new(&q).unwrap();
    assert_eq!(analysis.len(), n as usize);
    // Three selections of different sizes and places, two boundary columns each.
    let sets: [Vec<u32>; 3] = [
        vec![0, 5, 17, 40],
        (0..n).filter(|v| v % 7 == 3).collect(),
        (n / 2..n / 2 + 30).chain([1, 2]).collect(),
    ];
    for set in &sets {
        let nc = set.len();
        let boundary: Vec<f64> = (0..2 * nc).map(|i| ((i * 37) % 11) as f64 - 5.0).collect();
        let fresh = DirichletSolver::new(&q, set, SolverOptions::default()).unwrap();
        let mut shared =
            DirichletSolver::with_analysis(&analysis, set, SolverOptions::default()).unwrap();
        assert_eq!(shared.free(), fresh.free());
        assert_eq!(shared.constrained(), fresh.constrained());
        let want = fresh.solve(&boundary, 2).unwrap();
        let got = shared.solve(&boundary, 2).unwrap();
        assert!(worst(&want, &got) < 1e-10, "{}", worst(&want, &got));
        // Constrained vertices get their values exactly.
        for (k, &v) in set.iter().enumerate() {
            assert_eq!(got[v as usize], boundary[k]);
        }
        // New values of the same pattern: still the fresh solver's answer.
        let q2 = q.map(|x| 2.0 * x);
        shared.update_values(&q2).unwrap();
        let again = shared.solve(&boundary, 2).unwrap();
        assert!(worst(&want, &again) < 1e-10);
    }
}

#[test]
fn a_shared_analysis_reports_bad_constraints() {
    let mesh = icosphere(1.0, 1);
    let q = cotangent_laplacian(&mesh, Default::default())
        .unwrap()
        .map(|x| -x);
    let analysis = SystemAnalysis::new(&q).unwrap();
    let opts = SolverOptions::default();
    let err = |set: &[u32]| {
        DirichletSolver::with_analysis(&analysis, set, opts)
            .map(|_| ())
            .unwrap_err()
    };
    assert!(matches!(
        err(&[0, 999]),
        SolveError::Mesh(MeshError::ConstraintOutOfRange { .. })
    ));
    assert!(matches!(
        err(&[3, 3]),
        SolveError::Mesh(MeshError::OverlappingConstraints { .. })
    ));
    // Nothing constrained: the Laplacian's constants are free.
    assert!(matches!(err(&[]), SolveError::Unconstrained { .. }));
    let rect = sprs::CsMat::<f64>::zero((3, 4));
    assert!(SystemAnalysis::new(&rect).is_err());
}
