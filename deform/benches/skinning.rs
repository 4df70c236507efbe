//! criterion benches of skinning (issue 12): every backend on the same rig and frame
//! (`support/skin_scenes.rs`: libigl's armadillo with 5 weights, arm, CesiumMan), both cores; per
//! vertex = time / vertices. Targets: on armadillo, CGA motor blending (`motor-linear`) at most
//! 1.0 ms and no slower than dual-quaternion skinning; equation (17) (`conformal`) within
//! 1.2x of matrix LBS (`matrix`); each backend also `/vertex_by_vertex`, the per-vertex loop
//! the batch loop replaced (issue 23: speed-ups measured in the same run; one thread with
//! `RAYON_NUM_THREADS=1`). Also: sampling CesiumMan's animation and building its global and
//! skin motors, per frame.
//!
//! `cargo bench -p deform --bench skinning`; quick: `cargo run --release -p deform --example
//! skinning_report`.

mod support;

use support::skin_scenes;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use deform::skinning::{KeyframeBlend, RigPose, Skinning};
use deform::Deformer;
use glam::DVec3;
use std::hint::black_box;
use std::time::Duration;

fn benches(c: &mut Criterion) {
    for s in skin_scenes::all() {
        let n = s.positions.len();
        let mut g = c.benchmark_group(format!("skin_{}", s.name));
        g.sample_size(50).measurement_time(Duration::from_secs(3));
        g.throughput(Throughput::Elements(n as u64));
        let mut out = vec![DVec3::ZERO; n];
        for method in skin_scenes::BACKENDS {
            let d = Skinning::bind_influences(&s.positions, &s.influences, s.joints, method)
                .expect("bind");
            let mut poser = d.poser();
            g.bench_function(method.name(), |b| {
                b.iter(|| poser.pose(black_box(&s.keys), &mut out).expect("pose"))
            });
            // The vertex-by-vertex loop the batch loop replaced (issue 23's baseline).
            let mut prepared = d.blend().scratch();
            g.bench_function(format!("{}/vertex_by_vertex", method.name()), |b| {
                b.iter(|| {
                    d.blend()
                        .pose_vertex_by_vertex(black_box(&s.keys), &mut prepared, &mut out)
                        .expect("pose")
                })
            });
        }
        g.finish();
    }
    if let Some(rig) = skin_scenes::cesium_rig() {
        let mut g = c.benchmark_group("cesium_animation");
        let (t0, t1) = rig.animations[0].range();
        let mut pose = RigPose::default();
        let mut t = t0;
        for (name, blend) in [
            ("sample_gltf", KeyframeBlend::Gltf),
            ("sample_motor_log", KeyframeBlend::MotorLog),
        ] {
            g.bench_function(name, |b| {
                b.iter(|| {
                    t = if t > t1 { t0 } else { t + 0.013 };
                    rig.pose_into(Some(0), black_box(t), blend, &[], &mut pose)
                        .expect("pose");
                    black_box(pose.skin_motors().expect("motors").len())
                })
            });
        }
        g.finish();
    }
}

criterion_group!(skinning_benches, benches);
criterion_main!(skinning_benches);
