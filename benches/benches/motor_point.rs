//! criterion: one unit motor on one point (the per-vertex step of every deformer) against
//! glam's quaternion rotation plus translation, f64 and f32, in the same run.
//!
//! Two shapes: `single` is one call per iteration (latency, inputs behind `black_box`);
//! `stream` applies 1024 different motors to 1024 points (throughput, what skinning does).
//! The ratio to read is GA / glam within one group.
//!
//! `cargo bench -p benches --bench motor_point`

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;

const N: usize = 1024;

struct Inputs {
    qs: Vec<glam::DQuat>,
    ts: Vec<glam::DVec3>,
    pts: Vec<glam::DVec3>,
    ms: Vec<cga::Motor>,
}

fn inputs() -> Inputs {
    let mut rng = benches::timing::Lcg(0x9e37);
    let qs: Vec<glam::DQuat> = (0..N).map(|_| rng.quat()).collect();
    let ts: Vec<glam::DVec3> = (0..N).map(|_| rng.vec3()).collect();
    let pts: Vec<glam::DVec3> = (0..N).map(|_| rng.vec3()).collect();
    let ms = qs
        .iter()
        .zip(&ts)
        .map(|(q, t)| cga::Motor::from_rotation_translation(*q, *t))
        .collect();
    Inputs { qs, ts, pts, ms }
}

fn single(c: &mut Criterion) {
    let inp = inputs();
    let (q, t, p, m) = (inp.qs[5], inp.ts[5], inp.pts[5], inp.ms[5]);
    let m32 = cga::f32::Motor::from_array(m.to_array().map(|x| x as f32));
    let (q32, t32, p32) = (q.as_quat(), t.as_vec3(), p.as_vec3());
    let mut g = c.benchmark_group("motor_point_single");
    g.bench_function("f64 motor.transform_point", |b| {
        b.iter(|| black_box(m).transform_point(black_box(p)))
    });
    g.bench_function("f64 DQuat*p+t", |b| {
        b.iter(|| black_box(q) * black_box(p) + black_box(t))
    });
    g.bench_function("f32 motor.transform_point", |b| {
        b.iter(|| black_box(m32).transform_point(black_box(p32)))
    });
    g.bench_function("f32 Quat*p+t", |b| {
        b.iter(|| black_box(q32) * black_box(p32) + black_box(t32))
    });
    g.finish();
}

fn stream(c: &mut Criterion) {
    let inp = inputs();
    let ms32: Vec<cga::f32::Motor> = inp
        .ms
        .iter()
        .map(|m| cga::f32::Motor::from_array(m.to_array().map(|x| x as f32)))
        .collect();
    let qs32: Vec<glam::Quat> = inp.qs.iter().map(|q| q.as_quat()).collect();
    let ts32: Vec<glam::Vec3> = inp.ts.iter().map(|t| t.as_vec3()).collect();
    let pts32: Vec<glam::Vec3> = inp.pts.iter().map(|p| p.as_vec3()).collect();
    let mut out = vec![glam::DVec3::ZERO; N];
    let mut out32 = vec![glam::Vec3::ZERO; N];
    let mut g = c.benchmark_group("motor_point_stream");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("f64 motor.transform_point", |b| {
        b.iter(|| {
            let (m, p) = (black_box(&inp.ms), black_box(&inp.pts));
            for i in 0..N {
                out[i] = m[i].transform_point(p[i]);
            }
            black_box(&out);
        })
    });
    g.bench_function("f64 DQuat*p+t", |b| {
        b.iter(|| {
            let (q, t, p) = (black_box(&inp.qs), black_box(&inp.ts), black_box(&inp.pts));
            for i in 0..N {
                out[i] = q[i] * p[i] + t[i];
            }
            black_box(&out);
        })
    });
    g.bench_function("f32 motor.transform_point", |b| {
        b.iter(|| {
            let (m, p) = (black_box(&ms32), black_box(&pts32));
            for i in 0..N {
                out32[i] = m[i].transform_point(p[i]);
            }
            black_box(&out32);
        })
    });
    g.bench_function("f32 Quat*p+t", |b| {
        b.iter(|| {
            let (q, t, p) = (black_box(&qs32), black_box(&ts32), black_box(&pts32));
            for i in 0..N {
                out32[i] = q[i] * p[i] + t[i];
            }
            black_box(&out32);
        })
    });
    g.finish();
}

criterion_group!(benches, single, stream);
criterion_main!(benches);
