//! criterion benches of the motor deformers on armadillo-50k (49,999 vertices) and its
//! 200k-vertex subdivision (scenes in `support/scenes.rs`): bind (harmonic fields and rest points),
//! pose per frame (both cores), and the four blend methods on the same weights (per-vertex
//! cost = time / vertices). Targets (issue 10): pose <= 2 ms per frame, bind <= 150 ms on
//! armadillo-50k. `cargo run --release -p deform --example deformer_report` prints the same
//! figures quickly.
//!
//! `cargo bench -p deform --bench deformers`

mod support;

use support::scenes;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use deform::{BlendMethod, Deformer};
use glam::DVec3;
use std::hint::black_box;
use std::time::Duration;

fn benches(c: &mut Criterion) {
    let Some(arma) = scenes::armadillo() else {
        return;
    };
    let big = arma.subdivide_midpoint();
    for (name, mesh) in [("armadillo-50k", &arma), ("armadillo-200k", &big)] {
        let n = mesh.vertex_count();
        let mut g = c.benchmark_group(name);
        g.sample_size(10).measurement_time(Duration::from_secs(5));
        if n < 100_000 {
            g.bench_function("bind_spline", |b| {
                b.iter(|| scenes::bind_spline(black_box(mesh)))
            });
            g.bench_function("bind_4_handles", |b| {
                b.iter(|| scenes::bind_handles(black_box(mesh)))
            });
        }
        g.sample_size(50).measurement_time(Duration::from_secs(3));
        g.throughput(Throughput::Elements(n as u64));
        let spline = scenes::bind_spline(mesh);
        let handles = scenes::bind_handles(mesh);
        let keys = scenes::keys(mesh, 4);
        let rigid = scenes::rigid_keys(mesh, 4);
        let mut out = vec![DVec3::ZERO; n];
        let (mut spline_poser, mut handles_poser) = (spline.poser(), handles.poser());
        g.bench_function("pose_spline_4_bspline_keys", |b| {
            b.iter(|| spline_poser.pose(black_box(&keys), &mut out).expect("pose"))
        });
        g.bench_function("pose_4_handles", |b| {
            b.iter(|| {
                handles_poser
                    .pose(black_box(&keys), &mut out)
                    .expect("pose")
            })
        });
        for method in BlendMethod::ALL {
            let d = scenes::rebind_spline(mesh, &spline, method);
            let mut poser = d.poser();
            g.bench_function(format!("blend_{}_rigid", method.name()), |b| {
                b.iter(|| poser.pose(black_box(&rigid), &mut out).expect("pose"))
            });
        }
        g.finish();
    }
}

criterion_group!(deformer_benches, benches);
criterion_main!(deformer_benches);
