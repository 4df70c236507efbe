//! criterion benches on `meshes/large/armadillo-50k.obj` (49,999 vertices), compared with the
//! libigl timings in the data README (same kind of 2-core machine, single-threaded):
//! cotmatrix 37 ms, harmonic k=1 176 ms, k=2 1025 ms.
//!
//! Handles follow the README: the lowest 5% of the bounding box by y fixed, the top 5% moved.
//!
//! `CARGO_TARGET_DIR=/work/target-deform cargo bench -p deform --bench deform`

use criterion::{criterion_group, criterion_main, Criterion};
use deform::operators::harmonic::{harmonic_field, Harmonic, HarmonicOptions};
use deform::operators::laplacian::cotangent_laplacian;
use std::hint::black_box;
use std::time::Duration;

mod support;

use support::scenes;

use scenes::armadillo;

fn benches(c: &mut Criterion) {
    let Some(mesh) = armadillo() else {
        return;
    };
    let fixed = mesh.vertices_in_slab(1, 0.0, 0.05);
    let moved = mesh.vertices_in_slab(1, 0.95, 1.0);
    assert_eq!(fixed.len() + moved.len(), 5924, "README handle count");
    let mut g = c.benchmark_group("armadillo-50k");
    g.sample_size(20).measurement_time(Duration::from_secs(4));
    g.bench_function("cotangent_laplacian", |b| {
        b.iter(|| cotangent_laplacian(black_box(&mesh), Default::default()).expect("L"))
    });
    g.bench_function("harmonic_k1_prefactor_and_solve", |b| {
        b.iter(|| {
            harmonic_field(black_box(&mesh), &fixed, &moved, HarmonicOptions::default())
                .expect("field")
        })
    });
    let h = Harmonic::new(&mesh, &[&fixed, &moved], HarmonicOptions::default()).expect("h");
    let nc = fixed.len() + moved.len();
    let mut k = 0u32;
    g.bench_function("harmonic_k1_resolve_new_boundary_values", |b| {
        b.iter(|| {
            // Per-vertex boundary values that change every iteration.
            k += 1;
            let bc: Vec<f64> = (0..nc).map(|i| ((i as u32 + k) % 7) as f64 / 7.0).collect();
            h.solver().solve(&bc, 1).expect("solve")
        })
    });
    g.bench_function("harmonic_k1_resolve_3_columns", |b| {
        let bc: Vec<f64> = (0..3 * nc).map(|i| (i % 5) as f64).collect();
        b.iter(|| h.solver().solve(black_box(&bc), 3).expect("solve"))
    });
    g.sample_size(10).measurement_time(Duration::from_secs(10));
    g.bench_function("harmonic_k2_prefactor_and_solve", |b| {
        let o = HarmonicOptions {
            order: 2,
            ..Default::default()
        };
        b.iter(|| harmonic_field(black_box(&mesh), &fixed, &moved, o).expect("field"))
    });
    g.finish();
}

criterion_group!(deform_benches, benches);
criterion_main!(deform_benches);
