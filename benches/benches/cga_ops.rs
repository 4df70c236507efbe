//! criterion benchmarks of the `cga` crate against glam: composition, point transforms (single
//! and batch), closed-form log/exp and blends, f64 and f32.
//!
//! `CGA_REPORT=1 cargo bench -p benches --bench cga_ops` also prints the quick ratio table of
//! `benches::cga_report` first (`CGA_REPORT=only` prints just the table).

use criterion::{criterion_group, Criterion};
use std::hint::black_box;

fn motors() -> Vec<(glam::DQuat, glam::DVec3)> {
    (0..64)
        .map(|i| {
            let a = i as f64 * 0.37;
            let axis = glam::DVec3::new(a.sin(), a.cos(), 0.3 + 0.1 * a).normalize();
            (
                glam::DQuat::from_axis_angle(axis, 0.1 + 0.045 * i as f64),
                glam::DVec3::new(a.cos(), 2.0 * a.sin(), 0.5 - a * 0.1),
            )
        })
        .collect()
}

fn composition(c: &mut Criterion) {
    let ms: Vec<cga::Motor> = motors()
        .iter()
        .map(|(q, t)| cga::Motor::from_rotation_translation(*q, *t))
        .collect();
    let mats: Vec<glam::DMat4> = ms.iter().map(|m| m.to_mat4()).collect();
    let ms32: Vec<cga::f32::Motor> = ms
        .iter()
        .map(|m| cga::f32::Motor::from_array(m.to_array().map(|x| x as f32)))
        .collect();
    let mats32: Vec<glam::Mat4> = mats.iter().map(|m| m.as_mat4()).collect();
    let mut g = c.benchmark_group("compose");
    g.bench_function("f64 motor*motor", |b| {
        b.iter(|| black_box(ms[3]) * black_box(ms[9]))
    });
    g.bench_function("f64 DMat4*DMat4", |b| {
        b.iter(|| black_box(mats[3]) * black_box(mats[9]))
    });
    g.bench_function("f32 motor*motor", |b| {
        b.iter(|| black_box(ms32[3]) * black_box(ms32[9]))
    });
    g.bench_function("f32 Mat4*Mat4", |b| {
        b.iter(|| black_box(mats32[3]) * black_box(mats32[9]))
    });
    g.finish();
}

fn points(c: &mut Criterion) {
    let (q, t) = motors()[5];
    let m = cga::Motor::from_rotation_translation(q, t);
    let mat = m.to_mat4();
    let m32 = cga::f32::Motor::from_array(m.to_array().map(|x| x as f32));
    let mat32 = mat.as_mat4();
    let pts: Vec<glam::DVec3> = (0..4096)
        .map(|i| glam::DVec3::new(i as f64, (i * 7 % 13) as f64, 0.5))
        .collect();
    let pts32: Vec<glam::Vec3> = pts.iter().map(|p| p.as_vec3()).collect();
    let mut out = vec![glam::DVec3::ZERO; pts.len()];
    let mut out32 = vec![glam::Vec3::ZERO; pts.len()];
    let mut g = c.benchmark_group("points");
    g.bench_function("f64 motor.transform_point", |b| {
        b.iter(|| black_box(m).transform_point(black_box(pts[3])))
    });
    g.bench_function("f64 DQuat*p+t", |b| {
        b.iter(|| black_box(q) * black_box(pts[3]) + black_box(t))
    });
    g.bench_function("f64 batch motor 4096", |b| {
        b.iter(|| black_box(m).transform_points(black_box(&pts), &mut out))
    });
    g.bench_function("f64 batch DMat4 4096", |b| {
        b.iter(|| {
            let mm = black_box(mat);
            for (o, p) in out.iter_mut().zip(black_box(&pts)) {
                *o = mm.transform_point3(*p);
            }
        })
    });
    g.bench_function("f32 batch motor 4096", |b| {
        b.iter(|| black_box(m32).transform_points(black_box(&pts32), &mut out32))
    });
    g.bench_function("f32 batch Mat4 4096", |b| {
        b.iter(|| {
            let mm = black_box(mat32);
            for (o, p) in out32.iter_mut().zip(black_box(&pts32)) {
                *o = mm.transform_point3(*p);
            }
        })
    });
    g.finish();
}

fn exp_log(c: &mut Criterion) {
    let ms: Vec<cga::Motor> = motors()
        .iter()
        .map(|(q, t)| cga::Motor::from_rotation_translation(*q, *t))
        .collect();
    let b0 = ms[11].log();
    let ms32: Vec<cga::f32::Motor> = ms
        .iter()
        .map(|m| cga::f32::Motor::from_array(m.to_array().map(|x| x as f32)))
        .collect();
    let w = [0.1, 0.2, 0.3, 0.4];
    let w32 = [0.1f32, 0.2, 0.3, 0.4];
    let mut g = c.benchmark_group("exp_log");
    g.bench_function("f64 log", |b| b.iter(|| black_box(ms[11]).log()));
    g.bench_function("f64 exp", |b| b.iter(|| black_box(b0).exp_motor()));
    g.bench_function("f64 blend_log 4", |b| {
        b.iter(|| cga::Motor::blend_log(black_box(&ms[..4]), black_box(&w)))
    });
    g.bench_function("f64 blend_linear 4", |b| {
        b.iter(|| cga::Motor::blend_linear(black_box(&ms[..4]), black_box(&w)))
    });
    g.bench_function("f64 interpolate", |b| {
        b.iter(|| cga::Motor::interpolate(black_box(ms[1]), black_box(ms[2]), 0.3))
    });
    g.bench_function("f32 log", |b| b.iter(|| black_box(ms32[11]).log()));
    g.bench_function("f32 blend_log 4", |b| {
        b.iter(|| cga::f32::Motor::blend_log(black_box(&ms32[..4]), black_box(&w32)))
    });
    g.finish();
}

criterion_group!(benches, composition, points, exp_log);

fn main() {
    match std::env::var("CGA_REPORT").as_deref() {
        Ok("only") => {
            print!("{}", benches::cga_report::report());
            return;
        }
        Ok(_) => print!("{}", benches::cga_report::report()),
        Err(_) => {}
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
