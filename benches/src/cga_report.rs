//! Quick speed report for the `cga` crate: GA motors against glam matrices and quaternions in
//! one run (ratios measured side by side), plus the closed-form `log`/`exp` and blends.
//!
//! In-process timing loops with `std::time::Instant` and `black_box`; the whole report takes a
//! few seconds. Ratios below 1 mean the GA path is faster.

use crate::grade::{Spread, Tally, Target};
use crate::timing::Lcg;
use cga::Sandwich;
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Duration;

/// Elements per batch in each timing loop.
const N: usize = 1024;
/// Time budget per measurement.
const BUDGET: Duration = Duration::from_millis(250);

/// Nanoseconds per element of `f`, which processes `N` elements per call; best of 5 rounds.
fn time_ns(f: impl FnMut()) -> Spread {
    crate::timing::time_ns(N, BUDGET, f)
}

struct Row {
    what: &'static str,
    ga: Spread,
    /// The baseline measured in the same run; the target then bounds the ratio `ga / reference`.
    reference: Option<(&'static str, Spread)>,
    /// A ratio bound with a reference, a nanosecond bound without; `None`: reported only.
    target: Option<Target>,
}

/// Runs every measurement and returns a printable table.
pub fn report() -> String {
    let mut rng = Lcg(0x5eed);
    let qs: Vec<glam::DQuat> = (0..N).map(|_| rng.quat()).collect();
    let ts: Vec<glam::DVec3> = (0..N).map(|_| rng.vec3()).collect();
    let pts: Vec<glam::DVec3> = (0..N).map(|_| rng.vec3()).collect();
    let motors: Vec<cga::Motor> = qs
        .iter()
        .zip(&ts)
        .map(|(q, t)| cga::Motor::from_rotation_translation(*q, *t))
        .collect();
    let mats: Vec<glam::DMat4> = motors.iter().map(|m| m.to_mat4()).collect();
    let logs: Vec<cga::Bivector> = motors.iter().map(|m| m.log()).collect();
    let motors32: Vec<cga::f32::Motor> = motors
        .iter()
        .map(|m| cga::f32::Motor::from_array(m.to_array().map(|x| x as f32)))
        .collect();
    let mats32: Vec<glam::Mat4> = mats.iter().map(|m| m.as_mat4()).collect();
    let pts32: Vec<glam::Vec3> = pts.iter().map(|p| p.as_vec3()).collect();
    let qs32: Vec<glam::Quat> = qs.iter().map(|q| q.as_quat()).collect();
    let ts32: Vec<glam::Vec3> = ts.iter().map(|t| t.as_vec3()).collect();
    let logs32: Vec<cga::f32::Bivector> = motors32.iter().map(|m| m.log()).collect();

    let mut rows = Vec::new();
    let mut out_m = vec![cga::Motor::IDENTITY; N];
    let mut out_mat = vec![glam::DMat4::IDENTITY; N];
    let mut out_p = vec![glam::DVec3::ZERO; N];
    let mut out_m32 = vec![cga::f32::Motor::IDENTITY; N];
    let mut out_mat32 = vec![glam::Mat4::IDENTITY; N];
    let mut out_p32 = vec![glam::Vec3::ZERO; N];

    // Composition.
    let ga = time_ns(|| {
        let (a, o) = (black_box(&motors), &mut out_m);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (a, o) = (black_box(&mats), &mut out_mat);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    rows.push(Row {
        what: "f64 motor * motor",
        ga,
        reference: Some(("DMat4 * DMat4", gl)),
        target: Some(Target::AtMost(1.0)),
    });
    let ga = time_ns(|| {
        let (a, o) = (black_box(&motors32), &mut out_m32);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (a, o) = (black_box(&mats32), &mut out_mat32);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    rows.push(Row {
        what: "f32 motor * motor",
        ga,
        reference: Some(("Mat4 * Mat4 (SIMD)", gl)),
        target: Some(Target::AtMost(1.0)),
    });

    // One motor per point (sandwich) against quaternion + translation.
    let ga = time_ns(|| {
        let (m, p, o) = (black_box(&motors), black_box(&pts), &mut out_p);
        for i in 0..N {
            o[i] = m[i].transform_point(p[i]);
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (q, t, p, o) = (black_box(&qs), black_box(&ts), black_box(&pts), &mut out_p);
        for i in 0..N {
            o[i] = q[i] * p[i] + t[i];
        }
        black_box(o);
    });
    rows.push(Row {
        what: "f64 motor on point (sandwich)",
        ga,
        reference: Some(("DQuat * p + t", gl)),
        target: Some(Target::AtMost(1.3)),
    });
    let ga = time_ns(|| {
        let (m, p, o) = (black_box(&motors32), black_box(&pts32), &mut out_p32);
        for i in 0..N {
            o[i] = m[i].transform_point(p[i]);
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (q, t, p, o) = (
            black_box(&qs32),
            black_box(&ts32),
            black_box(&pts32),
            &mut out_p32,
        );
        for i in 0..N {
            o[i] = q[i] * p[i] + t[i];
        }
        black_box(o);
    });
    rows.push(Row {
        what: "f32 motor on point (sandwich)",
        ga,
        reference: Some(("Quat * p + t", gl)),
        target: Some(Target::AtMost(1.3)),
    });

    // Batch: one motor, many points.
    let m0 = motors[7];
    let mat0 = mats[7];
    let ga = time_ns(|| {
        black_box(m0).transform_points(black_box(&pts), &mut out_p);
        black_box(&out_p);
    });
    let gl = time_ns(|| {
        let m = black_box(mat0);
        for (o, p) in out_p.iter_mut().zip(black_box(&pts)) {
            *o = m.transform_point3(*p);
        }
        black_box(&out_p);
    });
    rows.push(Row {
        what: "f64 batch transform_points",
        ga,
        reference: Some(("DMat4::transform_point3", gl)),
        target: Some(Target::AtMost(1.1)),
    });
    let m032 = motors32[7];
    let mat032 = mats32[7];
    let ga = time_ns(|| {
        black_box(m032).transform_points(black_box(&pts32), &mut out_p32);
        black_box(&out_p32);
    });
    let gl = time_ns(|| {
        let m = black_box(mat032);
        for (o, p) in out_p32.iter_mut().zip(black_box(&pts32)) {
            *o = m.transform_point3(*p);
        }
        black_box(&out_p32);
    });
    rows.push(Row {
        what: "f32 batch transform_points",
        ga,
        reference: Some(("Mat4::transform_point3", gl)),
        target: Some(Target::AtMost(1.1)),
    });
    // The fused sandwich on many points, for comparison.
    let ga = time_ns(|| {
        let m = black_box(m0);
        for (o, p) in out_p.iter_mut().zip(black_box(&pts)) {
            *o = m.sandwich(cga::Point::from_vec3(*p)).to_vec3();
        }
        black_box(&out_p);
    });
    rows.push(Row {
        what: "f64 sandwich loop (one motor)",
        ga,
        reference: Some((
            "DMat4::transform_point3",
            gl_f64_batch(&mat0, &pts, &mut out_p),
        )),
        target: None,
    });

    // Closed-form log / exp and blends.
    let mut out_b = vec![cga::Bivector::default(); N];
    let ga = time_ns(|| {
        for (o, m) in out_b.iter_mut().zip(black_box(&motors)) {
            *o = m.log();
        }
        black_box(&out_b);
    });
    rows.push(Row {
        what: "f64 rigid log",
        ga,
        reference: None,
        target: Some(Target::Below(100.0)),
    });
    let ga = time_ns(|| {
        for (o, b) in out_m.iter_mut().zip(black_box(&logs)) {
            *o = b.exp_motor();
        }
        black_box(&out_m);
    });
    rows.push(Row {
        what: "f64 rigid exp",
        ga,
        reference: None,
        target: Some(Target::Below(100.0)),
    });
    let w = [0.1, 0.2, 0.3, 0.4];
    let ga = time_ns(|| {
        let ms = black_box(&motors);
        for i in 0..N {
            let k = [ms[i], ms[(i + 1) % N], ms[(i + 2) % N], ms[(i + 3) % N]];
            out_m[i] = cga::Motor::blend_log(&k, black_box(&w));
        }
        black_box(&out_m);
    });
    rows.push(Row {
        what: "f64 log blend of 4 motors",
        ga,
        reference: None,
        target: Some(Target::Below(400.0)),
    });
    let ga = time_ns(|| {
        let ms = black_box(&motors);
        for i in 0..N {
            let k = [ms[i], ms[(i + 1) % N], ms[(i + 2) % N], ms[(i + 3) % N]];
            out_m[i] = cga::Motor::blend_linear(&k, black_box(&w));
        }
        black_box(&out_m);
    });
    rows.push(Row {
        what: "f64 linear blend of 4 motors",
        ga,
        reference: None,
        target: None,
    });
    let ga = time_ns(|| {
        let ms = black_box(&motors);
        for i in 0..N {
            out_m[i] = cga::Motor::interpolate(ms[i], ms[(i + 1) % N], 0.3);
        }
        black_box(&out_m);
    });
    rows.push(Row {
        what: "f64 interpolate(a, b, t)",
        ga,
        reference: None,
        target: None,
    });
    let mut out_b32 = vec![cga::f32::Bivector::default(); N];
    let ga = time_ns(|| {
        for (o, m) in out_b32.iter_mut().zip(black_box(&motors32)) {
            *o = m.log();
        }
        black_box(&out_b32);
    });
    rows.push(Row {
        what: "f32 rigid log",
        ga,
        reference: None,
        target: None,
    });
    let ga = time_ns(|| {
        for (o, b) in out_m32.iter_mut().zip(black_box(&logs32)) {
            *o = b.exp_motor();
        }
        black_box(&out_m32);
    });
    rows.push(Row {
        what: "f32 rigid exp",
        ga,
        reference: None,
        target: None,
    });
    let w32 = [0.1f32, 0.2, 0.3, 0.4];
    let ga = time_ns(|| {
        let ms = black_box(&motors32);
        for i in 0..N {
            let k = [ms[i], ms[(i + 1) % N], ms[(i + 2) % N], ms[(i + 3) % N]];
            out_m32[i] = cga::f32::Motor::blend_log(&k, black_box(&w32));
        }
        black_box(&out_m32);
    });
    rows.push(Row {
        what: "f32 log blend of 4 motors",
        ga,
        reference: None,
        target: None,
    });

    let mut s = String::new();
    let _ = writeln!(
        s,
        "cga speed report (ns per element, best of 5 rounds [range of the rounds], N = {N})"
    );
    let mut tally = Tally::default();
    for r in rows {
        match r.reference {
            Some((name, ns)) => {
                let _ = writeln!(s, "{}", tally.row(r.what, r.ga, "ns", None));
                let _ = writeln!(s, "{}", tally.row(&format!("  {name}"), ns, "ns", None));
                let label = format!("{} / reference", r.what);
                let _ = writeln!(s, "{}", tally.row(&label, r.ga.ratio(ns), "x", r.target));
            }
            None => {
                let _ = writeln!(s, "{}", tally.row(r.what, r.ga, "ns", r.target));
            }
        }
    }
    let _ = writeln!(s, "{}", tally.summary());
    s
}

fn gl_f64_batch(m: &glam::DMat4, pts: &[glam::DVec3], out: &mut [glam::DVec3]) -> Spread {
    time_ns(|| {
        let m = black_box(*m);
        for (o, p) in out.iter_mut().zip(black_box(pts)) {
            *o = m.transform_point3(*p);
        }
        black_box(&*out);
    })
}
