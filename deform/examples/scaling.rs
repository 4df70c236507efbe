//! Throughput and scaling of the Laplacian and harmonic-field pipeline:
//! cactus-5k (5,261 vertices) -> armadillo-50k (49,999) -> armadillo-50k after one midpoint
//! subdivision (199,990). Prints median times and vertices per second, then grades the
//! armadillo-50k targets of `deform/BENCH.md` (cotangent Laplacian < 20 ms, harmonic field
//! < 120 ms, re-solve < 15 ms) with the range of the runs.
//!
//! `cargo run --release -p deform --example scaling`

use devkit::grade::{Spread, Tally, Target};
use devkit::measure::spread_ms;
use devkit::shared::data_file;

use deform::mesh::validate::validate;
use deform::operators::harmonic::{harmonic_system, HarmonicOptions};
use deform::operators::laplacian::cotangent_laplacian;
use deform::operators::solve::{DirichletSolver, SolverOptions};
use deform::Mesh;

/// Median (with range) wall time in milliseconds of `runs` calls.
fn time_ms<T>(runs: usize, mut f: impl FnMut() -> T) -> Spread {
    spread_ms(runs, || {
        std::hint::black_box(f());
    })
}

fn main() -> Result<(), deform::Error> {
    let (Some(cactus), Some(arma)) = (
        data_file("meshes/large/cactus-5k.off"),
        data_file("meshes/large/armadillo-50k.obj"),
    ) else {
        return Ok(());
    };
    let cactus = deform::mesh::io::read_mesh(cactus)?;
    let arma = deform::mesh::io::read_mesh(arma)?;
    let arma4 = arma.subdivide_midpoint();
    let cases: [(&str, &Mesh); 3] = [
        ("cactus-5k", &cactus),
        ("armadillo-50k", &arma),
        ("armadillo-50k/4", &arma4),
    ];
    println!(
        "{:<16} {:>7} {:>6} | {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} | {:>9} {:>9}",
        "mesh",
        "V",
        "b",
        "validate",
        "cotan",
        "system",
        "factor",
        "harmonic",
        "resolve",
        "cot Mv/s",
        "harm Mv/s"
    );
    let opts = HarmonicOptions::default();
    let mut graded = Vec::new();
    for (name, mesh) in cases {
        let n = mesh.vertex_count();
        let fixed = mesh.vertices_in_slab(1, 0.0, 0.05);
        let moved = mesh.vertices_in_slab(1, 0.95, 1.0);
        let constrained: Vec<u32> = fixed.iter().chain(&moved).copied().collect();
        let runs = if n > 100_000 { 5 } else { 11 };
        let t_val = time_ms(runs, || validate(mesh));
        let t_cot = time_ms(runs, || cotangent_laplacian(mesh, Default::default()));
        let t_sys = time_ms(runs, || harmonic_system(mesh, &opts));
        let q = harmonic_system(mesh, &opts)?;
        let t_fac = time_ms(runs, || {
            DirichletSolver::new(&q, &constrained, SolverOptions::default())
        });
        let t_harm = time_ms(runs, || {
            deform::operators::harmonic::harmonic_field(mesh, &fixed, &moved, opts).map(|x| x.len())
        });
        let s = DirichletSolver::new(&q, &constrained, SolverOptions::default())?;
        let bc: Vec<f64> = (0..constrained.len()).map(|i| (i % 3) as f64).collect();
        let t_res = time_ms(runs, || s.solve(&bc, 1));
        if name == "armadillo-50k" {
            graded = vec![
                ("armadillo-50k cotangent Laplacian", t_cot, 20.0),
                ("armadillo-50k harmonic field (k = 1)", t_harm, 120.0),
                ("armadillo-50k re-solve, 1 column", t_res, 15.0),
            ];
        }
        println!(
            "{:<16} {:>7} {:>6} | {:>8.2} {:>8.2} {:>8.2} {:>8.2} {:>8.2} {:>8.2} | {:>9.2} {:>9.2}",
            name,
            n,
            constrained.len(),
            t_val.value,
            t_cot.value,
            t_sys.value,
            t_fac.value,
            t_harm.value,
            t_res.value,
            n as f64 / t_cot.value / 1e3,
            n as f64 / t_harm.value / 1e3,
        );
    }
    println!("times in ms (median); b = constrained vertices (5% slabs by y);");
    println!(
        "system = check_solvable + cotan + negate; factor = DirichletSolver::new (AMD + Cholesky);"
    );
    println!("harmonic = harmonic_field end to end; resolve = one solve with new boundary values");
    let mut tally = Tally::default();
    for (label, t, ms) in graded {
        println!("{}", tally.row(label, t, "ms", Some(Target::Below(ms))));
    }
    println!("{}", tally.summary());
    Ok(())
}
