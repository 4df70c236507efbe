//! Quick report of bind time on armadillo-50k, phase by phase: the system matrix (cotangent
//! Laplacian), the symbolic analysis and numeric Cholesky factorisation of the free block,
//! the solves for 4 handle coordinates, the rest points, a whole 4-handle bind, and what a new
//! selection costs when the mesh's system is analysed once (`SystemAnalysis`, what `deform
//! view` keeps): target <= 60 ms on both cores. Medians of repeated runs with their range.
//!
//! `cargo run --release -p deform --example bind_report`

#[path = "../benches/support/scenes.rs"]
mod scenes;

use deform::blend::{BoundBlend, KeyWeights};
use deform::deformers::handles::HandleOptions;
use deform::operators::harmonic::{harmonic_system, HarmonicOptions};
use deform::operators::solve::{DirichletSolver, SolverOptions, SystemAnalysis};
use deform::{BlendMethod, MotorHandles};
use devkit::grade::{Tally, Target};
use devkit::measure::spread_ms;

fn main() {
    let Some(mesh) = scenes::armadillo() else {
        return;
    };
    let n = mesh.vertex_count();
    println!(
        "armadillo-50k ({n} vertices, {} threads)",
        rayon::current_num_threads()
    );
    let mut tally = Tally::default();
    let sets = scenes::handle_sets(&mesh);
    let constrained: Vec<u32> = sets.iter().flatten().copied().collect();
    let options = HarmonicOptions::default();
    let system = spread_ms(5, || {
        std::hint::black_box(harmonic_system(&mesh, &options).expect("system"));
    });
    let checks = spread_ms(5, || {
        deform::mesh::validate::check_solvable(&mesh).expect("valid");
    });
    let cot = spread_ms(5, || {
        std::hint::black_box(
            deform::operators::laplacian::cotangent_laplacian(&mesh, Default::default())
                .expect("laplacian"),
        );
    });
    let q = harmonic_system(&mesh, &options).expect("system");
    let factor = spread_ms(5, || {
        std::hint::black_box(
            DirichletSolver::new(&q, &constrained, SolverOptions::default()).expect("factor"),
        );
    });
    let mut solver =
        DirichletSolver::new(&q, &constrained, SolverOptions::default()).expect("solver");
    let numeric = spread_ms(5, || solver.update_values(&q).expect("refactor"));
    let m = sets.len();
    let mut boundary = vec![0.0; constrained.len() * m];
    let mut start = 0;
    for (j, s) in sets.iter().enumerate() {
        boundary[j * constrained.len() + start..j * constrained.len() + start + s.len()].fill(1.0);
        start += s.len();
    }
    let solve = spread_ms(5, || {
        std::hint::black_box(solver.solve(&boundary, m).expect("solve"));
    });
    let x = solver.solve(&boundary, m).expect("solve");
    let columns: Vec<Vec<f64>> = (0..m).map(|j| x[j * n..(j + 1) * n].to_vec()).collect();
    let weights = KeyWeights::from_columns(&columns).expect("weights");
    let rest = vec![cga::ScaledMotor::IDENTITY; m];
    let bind_rest = spread_ms(5, || {
        std::hint::black_box(
            BoundBlend::bind(
                &mesh.positions,
                weights.clone(),
                &rest,
                BlendMethod::MotorLog,
            )
            .expect("bind"),
        );
    });
    let whole = spread_ms(5, || {
        std::hint::black_box(scenes::bind_handles(&mesh));
    });
    // Interactive rebinding: the mesh's system analysed once, then a new selection (another
    // four groups, as a user paints) bound with it.
    let analysis_ms = spread_ms(3, || {
        std::hint::black_box(SystemAnalysis::new(&q).expect("analysis"));
    });
    let analysis = SystemAnalysis::new(&q).expect("analysis");
    let moved: Vec<Vec<u32>> = [(0.02, 0.07), (0.9, 0.97), (0.45, 0.5), (0.6, 0.63)]
        .iter()
        .map(|&(a, b)| mesh.vertices_in_slab(1, a, b))
        .collect();
    let moved_refs: Vec<&[u32]> = moved.iter().map(Vec::as_slice).collect();
    let rebind = spread_ms(7, || {
        std::hint::black_box(
            MotorHandles::bind_with_analysis(
                &mesh,
                &analysis,
                &moved_refs,
                &rest,
                HandleOptions::default(),
            )
            .expect("rebind"),
        );
    });
    for (label, s, target) in [
        ("system matrix (cotangent Laplacian)", system, None),
        ("  of which the mesh checks", checks, None),
        ("  of which the Laplacian", cot, None),
        ("analyse + factorise the free block", factor, None),
        ("  of which the numeric factorisation", numeric, None),
        ("solve 4 coordinate columns", solve, None),
        ("rest points (blend bind)", bind_rest, None),
        ("whole 4-handle bind from the mesh", whole, None),
        (
            "analysis of the system matrix (once per mesh)",
            analysis_ms,
            None,
        ),
        (
            "rebind 4 new handles with the analysis",
            rebind,
            Some(Target::AtMost(60.0)),
        ),
    ] {
        println!("{}", tally.row(&format!("  {label}"), s, "ms", target));
    }
    println!("{}", tally.summary());
}
