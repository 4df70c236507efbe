//! Throughput and scaling of the Laplacian and harmonic-field pipeline:
//! cactus-5k (5,261 vertices) -> armadillo-50k (49,999) -> armadillo-50k after one midpoint
//! subdivision (199,990). Prints median times and vertices per second.
//!
//! `CARGO_TARGET_DIR=/work/target-deform cargo run --release -p deform --example scaling`

use deform::{
    cotangent_laplacian, harmonic_system, validate, DirichletSolver, HarmonicOptions, Mesh,
    SolverOptions,
};
use std::path::PathBuf;
use std::time::Instant;

/// Median wall time in milliseconds of `runs` calls.
fn time_ms<T>(runs: usize, mut f: impl FnMut() -> T) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            std::hint::black_box(f());
            s.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[runs / 2]
}

fn main() -> Result<(), deform::Error> {
    let dir = std::env::var_os("CGA_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data"))
        .join("meshes");
    if !dir.is_dir() {
        eprintln!("skipped: {} not found (set CGA_DATA_DIR)", dir.display());
        return Ok(());
    }
    let cactus = deform::io::read_mesh(dir.join("large/cactus-5k.off"))?;
    let arma = deform::io::read_mesh(dir.join("large/armadillo-50k.obj"))?;
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
            deform::harmonic_field(mesh, &fixed, &moved, opts).map(|x| x.len())
        });
        let s = DirichletSolver::new(&q, &constrained, SolverOptions::default())?;
        let bc: Vec<f64> = (0..constrained.len()).map(|i| (i % 3) as f64).collect();
        let t_res = time_ms(runs, || s.solve(&bc, 1));
        println!(
            "{:<16} {:>7} {:>6} | {:>8.2} {:>8.2} {:>8.2} {:>8.2} {:>8.2} {:>8.2} | {:>9.2} {:>9.2}",
            name,
            n,
            constrained.len(),
            t_val,
            t_cot,
            t_sys,
            t_fac,
            t_harm,
            t_res,
            n as f64 / t_cot / 1e3,
            n as f64 / t_harm / 1e3,
        );
    }
    println!("times in ms (median); b = constrained vertices (5% slabs by y);");
    println!(
        "system = check_solvable + cotan + negate; factor = DirichletSolver::new (AMD + Cholesky);"
    );
    println!("harmonic = harmonic_field end to end; resolve = one solve with new boundary values");
    Ok(())
}
