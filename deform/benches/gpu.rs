//! criterion benches of posing on the GPU (issue 25): every backend on the procedural rig of
//! 1M vertices and 64 bones and on libigl's armadillo (`support/skin_scenes.rs`), per pose:
//! `pass` (the compute pass alone, between timestamps the device writes; only where the device
//! has timestamp queries), `pose` (keys uploaded, the pass, submit and wait) and `pose+read`
//! (with the positions read back). Without an adapter it says so and measures nothing. On
//! Mesa's lavapipe the figures are a CPU's; `benches/gpu/run.sh` runs the quick report
//! (`examples/gpu_report.rs`, graded against the bandwidth limit) on a lent GPU.
//!
//! `cargo bench -p deform --features gpu --bench gpu`

mod support;

use support::skin_scenes;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use deform::gpu::{GpuBlend, GpuContext};
use deform::skinning::Skinning;
use glam::DVec3;
use std::hint::black_box;
use std::time::Duration;

fn benches(c: &mut Criterion) {
    let ctx = match GpuContext::new() {
        Ok(ctx) => ctx,
        Err(e) => {
            eprintln!("gpu bench: {e}; nothing measured");
            return;
        }
    };
    eprintln!("gpu bench on {}", ctx.adapter());
    let mut scenes = vec![skin_scenes::procedural(1_000_000, 64)];
    scenes.extend(skin_scenes::armadillo());
    for s in &scenes {
        let n = s.positions.len();
        let mut g = c.benchmark_group(format!("gpu_{}", s.name.replace([' ', '/'], "_")));
        g.sample_size(10).measurement_time(Duration::from_secs(2));
        g.throughput(Throughput::Elements(n as u64));
        let mut out = vec![DVec3::ZERO; n];
        for method in skin_scenes::BACKENDS {
            let cpu = Skinning::bind_influences(&s.positions, &s.influences, s.joints, method)
                .expect("bind");
            let mut gpu = GpuBlend::bind(&ctx, cpu.blend()).expect("gpu bind");
            if ctx.has_timestamps() {
                g.bench_function(format!("{}/pass", method.name()), |b| {
                    b.iter_custom(|iters| {
                        let ms: f64 = (0..iters)
                            .map(|_| {
                                let t = gpu.run_timed(&ctx, black_box(&s.keys)).expect("run");
                                t.expect("the device has timestamps")
                            })
                            .sum();
                        Duration::from_secs_f64(ms * 1e-3)
                    })
                });
            }
            g.bench_function(format!("{}/pose", method.name()), |b| {
                b.iter(|| gpu.run(&ctx, black_box(&s.keys)).expect("run"))
            });
            g.bench_function(format!("{}/pose+read", method.name()), |b| {
                b.iter(|| {
                    gpu.run(&ctx, black_box(&s.keys)).expect("run");
                    gpu.read_back(&ctx, &mut out).expect("read back")
                })
            });
        }
        g.finish();
    }
}

criterion_group!(gpu_benches, benches);
criterion_main!(gpu_benches);
