//! Quick report of bind time on armadillo-50k, phase by phase: the system matrix (cotangent
//! Laplacian), the symbolic analysis and numeric Cholesky factorisation of the free block,
//! the solves for 4 handle coordinates, the rest points, and a whole 4-handle bind (what a
//! new selection in `deform view` costs). Medians of repeated runs with their range.
//!
//! `cargo run --release -p deform --example bind_report`

#[path = "../benches/support/scenes.rs"]
mod scenes;

use deform::{
    harmonic_system, BlendMethod, BoundBlend, DirichletSolver, HarmonicOptions, KeyWeights,
    SolverOptions,
};
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
    for (label, s, target) in [
        ("system matrix (cotangent Laplacian)", system, None),
        ("analyse + factorise the free block", factor, None),
        ("  of which the numeric factorisation", numeric, None),
        ("solve 4 coordinate columns", solve, None),
        ("rest points (blend bind)", bind_rest, None),
        (
            "whole 4-handle bind (new selection)",
            whole,
            Some(Target::AtMost(60.0)),
        ),
    ] {
        println!("{}", tally.row(&format!("  {label}"), s, "ms", target));
    }
    println!("{}", tally.summary());
}
