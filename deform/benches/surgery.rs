//! criterion benches of cut, tear and drill (issue 14) with the face index built (scenes in
//! `support/surgery_scenes.rs`: libigl's arm, 16.6k faces, and CesiumMan), plus the index build
//! on its own. Targets on the arm and CesiumMan: cut under 1 ms, one tear step under 0.5 ms, drill
//! under 0.5 ms. `cargo run --release -p deform --example surgery_report` prints the same
//! figures and the ratios to the paper's Python timings.
//!
//! `cargo bench -p deform --bench surgery`

mod support;

use support::surgery_scenes;

use criterion::{criterion_group, criterion_main, Criterion};
use deform::surgery::{CutOptions, DrillOptions, Frame, Surgery, TearOptions};
use std::hint::black_box;
use std::time::Duration;

fn benches(c: &mut Criterion) {
    for s in surgery_scenes::all() {
        let mut g = c.benchmark_group(format!("surgery_{}", s.name));
        g.sample_size(50).measurement_time(Duration::from_secs(3));
        let rig = &s.rig;
        g.bench_function("index", |b| {
            b.iter(|| Surgery::new(black_box(&rig.mesh), &rig.influences).expect("index"))
        });
        let surgery = Surgery::new(&rig.mesh, &rig.influences).expect("index");
        g.bench_function("cut", |b| {
            b.iter(|| {
                surgery
                    .cut(black_box(&s.plane), Frame::Rest, &CutOptions::default())
                    .expect("cut")
            })
        });
        g.bench_function("tear_step", |b| {
            b.iter(|| {
                surgery
                    .tear(black_box(&s.scalpel), Frame::Rest, &TearOptions::default())
                    .expect("tear")
            })
        });
        g.bench_function("drill", |b| {
            b.iter(|| {
                surgery
                    .drill(black_box(&s.drill), Frame::Rest, &DrillOptions::default())
                    .expect("drill")
            })
        });
        g.finish();
    }
}

criterion_group!(surgery_benches, benches);
criterion_main!(surgery_benches);
