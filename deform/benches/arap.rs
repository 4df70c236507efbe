//! criterion benches of ARAP (issue 11) on libigl's armadillo (43,243 vertices),
//! armadillo-50k (49,999) and its midpoint subdivision (199,990), with the bottom 5% of the
//! box in y fixed and the top 5% a handle moved by a motor: precomputation (weights, cells,
//! constrained system, faer Cholesky), one and five iterations of a pose warm-started from a
//! deformed pose (spokes and rims, rotor local step; a pose of `k` iterations does `k` local
//! steps, right-hand sides and solves and `k + 1` covariance passes, the last one for the
//! reported energy), and the rotor and SVD rotation fits per cell on covariances of that
//! pose. Targets: one iteration <= 20 ms on armadillo.obj and <= 25 ms on armadillo-50k,
//! precomputation <= 300 ms, the rotor fit no slower than the SVD fit.
//!
//! `cargo bench -p deform --bench arap`

use cga::ScaledMotor;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use deform::deformers::arap::{fit_rotor, fit_svd, Arap, ArapOptions, Stop, Targets};
use deform::Mesh;
use glam::{DQuat, DVec3};
use std::hint::black_box;
use std::time::Duration;

mod support;

use support::scenes;

/// Fixed bottom, handle top.
fn sets(mesh: &Mesh) -> (Vec<u32>, Vec<u32>) {
    (
        mesh.vertices_in_slab(1, 0.0, 0.05),
        mesh.vertices_in_slab(1, 0.95, 1.0),
    )
}

/// The handle's motor: a turn of 0.6 rad about an oblique axis through the top, and a shift.
fn key(mesh: &Mesh) -> ScaledMotor {
    let b = mesh.bounding_box().expect("box");
    let c = DVec3::new(b.center().x, b.max.y, b.center().z);
    let q = DQuat::from_axis_angle(DVec3::new(1.0, 0.2, 0.4).normalize(), 0.6);
    let t = 0.15 * b.diagonal() * DVec3::X;
    ScaledMotor::from_scale_rotation_translation(1.0, q, c - q * c + t)
}

/// Triangle covariances `sum_k e_k e'_k^T` of the pose `p` (a cell's worth of edges each).
fn covariances(mesh: &Mesh, p: &[DVec3]) -> Vec<([f64; 9], f64)> {
    mesh.triangles
        .iter()
        .map(|t| {
            let mut s = [0.0; 9];
            let mut bound = 0.0;
            for k in 0..3 {
                let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
                let (e, e1) = (mesh.positions[b] - mesh.positions[a], p[b] - p[a]);
                for r in 0..3 {
                    for c in 0..3 {
                        s[3 * r + c] += e[r] * e1[c];
                    }
                }
                bound += 0.5 * (e.length_squared() + e1.length_squared());
            }
            (s, bound)
        })
        .collect()
}

fn benches(c: &mut Criterion) {
    for (name, rel, subdivide) in [
        ("armadillo-43k", "libigl/armadillo.obj", false),
        ("armadillo-50k", "large/armadillo-50k.obj", false),
        ("armadillo-200k", "large/armadillo-50k.obj", true),
    ] {
        let Some(mesh) = scenes::mesh(rel) else {
            continue;
        };
        let mesh = if subdivide {
            mesh.subdivide_midpoint()
        } else {
            mesh
        };
        let n = mesh.vertex_count();
        let (fixed, handle) = sets(&mesh);
        let keys = [key(&mesh)];
        let mut g = c.benchmark_group(name);
        g.sample_size(10).measurement_time(Duration::from_secs(6));
        g.bench_function("precompute", |b| {
            b.iter(|| {
                Arap::bind(black_box(&mesh), &fixed, &[&handle], ArapOptions::default())
                    .expect("bind")
            })
        });
        let arap = Arap::bind(&mesh, &fixed, &[&handle], ArapOptions::default()).expect("bind");
        let mut warm = mesh.positions.clone();
        arap.pose(&Targets::Motors(&keys), Stop::Iterations(3), &mut warm)
            .expect("pose");
        let mut p = warm.clone();
        let mut scratch = arap.scratch().expect("scratch");
        g.sample_size(20).measurement_time(Duration::from_secs(5));
        for k in [1, 5] {
            g.bench_function(format!("pose_{k}_iterations"), |b| {
                b.iter(|| {
                    p.copy_from_slice(&warm);
                    let targets = Targets::Motors(&keys);
                    arap.pose_using(
                        &targets,
                        Stop::Iterations(k),
                        &mut scratch,
                        &mut p,
                        |_, _| {},
                    )
                    .expect("pose")
                })
            });
        }
        let cov = covariances(&mesh, &warm);
        let cells = cov.len().min(n);
        g.throughput(Throughput::Elements(cells as u64));
        g.bench_function("fit_rotor_per_cell", |b| {
            b.iter(|| {
                let mut q = DQuat::IDENTITY;
                for (s, bound) in &cov[..cells] {
                    q = fit_rotor(black_box(s), *bound, q);
                }
                q
            })
        });
        g.bench_function("fit_svd_per_cell", |b| {
            b.iter(|| {
                let mut acc = 0.0;
                for (s, _) in &cov[..cells] {
                    acc += fit_svd(black_box(s)).x_axis.x;
                }
                acc
            })
        });
        g.finish();
    }
}

criterion_group!(arap_benches, benches);
criterion_main!(arap_benches);
