use cga::{Motor, ScaledMotor};
use glam::{DQuat, DVec3};
use std::hint::black_box;
use std::time::Instant;
fn main() {
    let ms: Vec<Motor> = (0..5)
        .map(|j| {
            Motor::from_rotation_translation(
                DQuat::from_axis_angle(
                    DVec3::new(0.3, 1.0, 0.1 * j as f64).normalize(),
                    0.3 * j as f64,
                ),
                DVec3::new(j as f64, 1.0, 2.0),
            )
        })
        .collect();
    let w = [0.1, 0.2, 0.3, 0.25, 0.15];
    let n = 5_000_000;
    let p = DVec3::new(0.3, 0.4, 0.5);
    let t = Instant::now();
    let mut acc = DVec3::ZERO;
    for i in 0..n {
        let m = Motor::blend_linear(black_box(&ms), black_box(&w));
        acc += m.transform_point(p + DVec3::X * (i as f64 * 1e-9));
    }
    println!(
        "blend+normalize+sandwich {:.2} ns {acc}",
        t.elapsed().as_secs_f64() * 1e9 / n as f64
    );
    let m = Motor::blend_linear(&ms, &w);
    let t = Instant::now();
    for i in 0..n {
        acc += black_box(m).transform_point(p + DVec3::X * (i as f64 * 1e-9));
    }
    println!(
        "sandwich {:.2} ns",
        t.elapsed().as_secs_f64() * 1e9 / n as f64
    );
    let t = Instant::now();
    for _ in 0..n {
        let m = Motor::blend_linear(black_box(&ms), black_box(&w));
        acc.x += m.s;
    }
    println!(
        "blend+normalize {:.2} ns",
        t.elapsed().as_secs_f64() * 1e9 / n as f64
    );
    let (q, tr) = m.to_rotation_translation();
    let t = Instant::now();
    for i in 0..n {
        acc += black_box(q) * (p + DVec3::X * (i as f64 * 1e-9)) + tr;
    }
    println!(
        "quat {:.2} ns {acc}",
        t.elapsed().as_secs_f64() * 1e9 / n as f64
    );
    let _ = ScaledMotor::IDENTITY;
}
