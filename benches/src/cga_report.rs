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

impl Row {
    /// A GA timing against the baseline `name` timed in the same run; `target` bounds the ratio.
    fn versus(
        what: &'static str,
        ga: Spread,
        name: &'static str,
        reference: Spread,
        target: Option<Target>,
    ) -> Row {
        Row {
            what,
            ga,
            reference: Some((name, reference)),
            target,
        }
    }

    /// A GA timing with no baseline; `target` bounds the nanoseconds.
    fn alone(what: &'static str, ga: Spread, target: Option<Target>) -> Row {
        Row {
            what,
            ga,
            reference: None,
            target,
        }
    }
}

/// The inputs every measurement reads: `N` random rigid motions as quaternion + translation,
/// motor, matrix and motor log, and `N` points, each in f64 and in f32.
struct Inputs {
    qs: Vec<glam::DQuat>,
    ts: Vec<glam::DVec3>,
    pts: Vec<glam::DVec3>,
    motors: Vec<cga::Motor>,
    mats: Vec<glam::DMat4>,
    logs: Vec<cga::Bivector>,
    motors32: Vec<cga::f32::Motor>,
    mats32: Vec<glam::Mat4>,
    pts32: Vec<glam::Vec3>,
    qs32: Vec<glam::Quat>,
    ts32: Vec<glam::Vec3>,
    logs32: Vec<cga::f32::Bivector>,
}

impl Inputs {
    /// Draws the inputs from the report's fixed seed and derives the other forms from them.
    fn new() -> Inputs {
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
        Inputs {
            qs,
            ts,
            pts,
            motors,
            mats,
            logs,
            motors32,
            mats32,
            pts32,
            qs32,
            ts32,
            logs32,
        }
    }
}

/// The output buffers the timing loops write into, `N` each, allocated once for the report.
struct Outputs {
    m: Vec<cga::Motor>,
    mat: Vec<glam::DMat4>,
    p: Vec<glam::DVec3>,
    m32: Vec<cga::f32::Motor>,
    mat32: Vec<glam::Mat4>,
    p32: Vec<glam::Vec3>,
}

impl Outputs {
    /// Buffers filled with identities and zeros.
    fn new() -> Outputs {
        Outputs {
            m: vec![cga::Motor::IDENTITY; N],
            mat: vec![glam::DMat4::IDENTITY; N],
            p: vec![glam::DVec3::ZERO; N],
            m32: vec![cga::f32::Motor::IDENTITY; N],
            mat32: vec![glam::Mat4::IDENTITY; N],
            p32: vec![glam::Vec3::ZERO; N],
        }
    }
}

/// Runs every measurement and returns a printable table.
pub fn report() -> String {
    let inp = Inputs::new();
    let mut out = Outputs::new();
    let mut rows = composition(&inp, &mut out);
    rows.extend(motor_per_point(&inp, &mut out));
    rows.extend(one_motor_many_points(&inp, &mut out));
    rows.extend(log_exp_blends_f64(&inp, &mut out));
    rows.extend(log_exp_blends_f32(&inp, &mut out));
    render(rows)
}

/// Composition: motor * motor against matrix * matrix, f64 then f32.
fn composition(inp: &Inputs, out: &mut Outputs) -> Vec<Row> {
    let ga = time_ns(|| {
        let (a, o) = (black_box(&inp.motors), &mut out.m);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (a, o) = (black_box(&inp.mats), &mut out.mat);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    let f64_row = Row::versus(
        "f64 motor * motor",
        ga,
        "DMat4 * DMat4",
        gl,
        Some(Target::AtMost(1.0)),
    );
    let ga = time_ns(|| {
        let (a, o) = (black_box(&inp.motors32), &mut out.m32);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (a, o) = (black_box(&inp.mats32), &mut out.mat32);
        for i in 0..N {
            o[i] = a[i] * a[(i + 1) % N];
        }
        black_box(o);
    });
    let f32_row = Row::versus(
        "f32 motor * motor",
        ga,
        "Mat4 * Mat4 (SIMD)",
        gl,
        Some(Target::AtMost(1.0)),
    );
    vec![f64_row, f32_row]
}

/// One motor per point (sandwich) against quaternion + translation, f64 then f32.
fn motor_per_point(inp: &Inputs, out: &mut Outputs) -> Vec<Row> {
    let ga = time_ns(|| {
        let (m, p, o) = (black_box(&inp.motors), black_box(&inp.pts), &mut out.p);
        for i in 0..N {
            o[i] = m[i].transform_point(p[i]);
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (q, t, p, o) = (
            black_box(&inp.qs),
            black_box(&inp.ts),
            black_box(&inp.pts),
            &mut out.p,
        );
        for i in 0..N {
            o[i] = q[i] * p[i] + t[i];
        }
        black_box(o);
    });
    let f64_row = Row::versus(
        "f64 motor on point (sandwich)",
        ga,
        "DQuat * p + t",
        gl,
        Some(Target::AtMost(1.3)),
    );
    let ga = time_ns(|| {
        let (m, p, o) = (
            black_box(&inp.motors32),
            black_box(&inp.pts32),
            &mut out.p32,
        );
        for i in 0..N {
            o[i] = m[i].transform_point(p[i]);
        }
        black_box(o);
    });
    let gl = time_ns(|| {
        let (q, t, p, o) = (
            black_box(&inp.qs32),
            black_box(&inp.ts32),
            black_box(&inp.pts32),
            &mut out.p32,
        );
        for i in 0..N {
            o[i] = q[i] * p[i] + t[i];
        }
        black_box(o);
    });
    let f32_row = Row::versus(
        "f32 motor on point (sandwich)",
        ga,
        "Quat * p + t",
        gl,
        Some(Target::AtMost(1.3)),
    );
    vec![f64_row, f32_row]
}

/// Batch: one motor on many points against the matrix, f64 then f32, then the fused sandwich
/// loop on many points for comparison.
fn one_motor_many_points(inp: &Inputs, out: &mut Outputs) -> Vec<Row> {
    let m0 = inp.motors[7];
    let mat0 = inp.mats[7];
    let ga = time_ns(|| {
        black_box(m0).transform_points(black_box(&inp.pts), &mut out.p);
        black_box(&out.p);
    });
    let gl = time_ns(|| {
        let m = black_box(mat0);
        for (o, p) in out.p.iter_mut().zip(black_box(&inp.pts)) {
            *o = m.transform_point3(*p);
        }
        black_box(&out.p);
    });
    let f64_row = Row::versus(
        "f64 batch transform_points",
        ga,
        "DMat4::transform_point3",
        gl,
        Some(Target::AtMost(1.1)),
    );
    let m032 = inp.motors32[7];
    let mat032 = inp.mats32[7];
    let ga = time_ns(|| {
        black_box(m032).transform_points(black_box(&inp.pts32), &mut out.p32);
        black_box(&out.p32);
    });
    let gl = time_ns(|| {
        let m = black_box(mat032);
        for (o, p) in out.p32.iter_mut().zip(black_box(&inp.pts32)) {
            *o = m.transform_point3(*p);
        }
        black_box(&out.p32);
    });
    let f32_row = Row::versus(
        "f32 batch transform_points",
        ga,
        "Mat4::transform_point3",
        gl,
        Some(Target::AtMost(1.1)),
    );
    // The fused sandwich on many points, for comparison.
    let ga = time_ns(|| {
        let m = black_box(m0);
        for (o, p) in out.p.iter_mut().zip(black_box(&inp.pts)) {
            *o = m.sandwich(cga::Point::from_vec3(*p)).to_vec3();
        }
        black_box(&out.p);
    });
    let sandwich_row = Row::versus(
        "f64 sandwich loop (one motor)",
        ga,
        "DMat4::transform_point3",
        gl_f64_batch(&mat0, &inp.pts, &mut out.p),
        None,
    );
    vec![f64_row, f32_row, sandwich_row]
}

/// Closed-form f64 log and exp, the log and linear blends of 4 motors, and interpolation.
fn log_exp_blends_f64(inp: &Inputs, out: &mut Outputs) -> Vec<Row> {
    let mut rows = Vec::new();
    let mut out_b = vec![cga::Bivector::default(); N];
    let ga = time_ns(|| {
        for (o, m) in out_b.iter_mut().zip(black_box(&inp.motors)) {
            *o = m.log();
        }
        black_box(&out_b);
    });
    rows.push(Row::alone("f64 rigid log", ga, Some(Target::Below(100.0))));
    let ga = time_ns(|| {
        for (o, b) in out.m.iter_mut().zip(black_box(&inp.logs)) {
            *o = b.exp_motor();
        }
        black_box(&out.m);
    });
    rows.push(Row::alone("f64 rigid exp", ga, Some(Target::Below(100.0))));
    let w = [0.1, 0.2, 0.3, 0.4];
    let ga = time_ns(|| {
        let ms = black_box(&inp.motors);
        for i in 0..N {
            let k = [ms[i], ms[(i + 1) % N], ms[(i + 2) % N], ms[(i + 3) % N]];
            out.m[i] = cga::Motor::blend_log(&k, black_box(&w));
        }
        black_box(&out.m);
    });
    rows.push(Row::alone(
        "f64 log blend of 4 motors",
        ga,
        Some(Target::Below(400.0)),
    ));
    let ga = time_ns(|| {
        let ms = black_box(&inp.motors);
        for i in 0..N {
            let k = [ms[i], ms[(i + 1) % N], ms[(i + 2) % N], ms[(i + 3) % N]];
            out.m[i] = cga::Motor::blend_linear(&k, black_box(&w));
        }
        black_box(&out.m);
    });
    rows.push(Row::alone("f64 linear blend of 4 motors", ga, None));
    let ga = time_ns(|| {
        let ms = black_box(&inp.motors);
        for i in 0..N {
            out.m[i] = cga::Motor::interpolate(ms[i], ms[(i + 1) % N], 0.3);
        }
        black_box(&out.m);
    });
    rows.push(Row::alone("f64 interpolate(a, b, t)", ga, None));
    rows
}

/// Closed-form f32 log and exp and the log blend of 4 motors (reported only).
fn log_exp_blends_f32(inp: &Inputs, out: &mut Outputs) -> Vec<Row> {
    let mut rows = Vec::new();
    let mut out_b32 = vec![cga::f32::Bivector::default(); N];
    let ga = time_ns(|| {
        for (o, m) in out_b32.iter_mut().zip(black_box(&inp.motors32)) {
            *o = m.log();
        }
        black_box(&out_b32);
    });
    rows.push(Row::alone("f32 rigid log", ga, None));
    let ga = time_ns(|| {
        for (o, b) in out.m32.iter_mut().zip(black_box(&inp.logs32)) {
            *o = b.exp_motor();
        }
        black_box(&out.m32);
    });
    rows.push(Row::alone("f32 rigid exp", ga, None));
    let w32 = [0.1f32, 0.2, 0.3, 0.4];
    let ga = time_ns(|| {
        let ms = black_box(&inp.motors32);
        for i in 0..N {
            let k = [ms[i], ms[(i + 1) % N], ms[(i + 2) % N], ms[(i + 3) % N]];
            out.m32[i] = cga::f32::Motor::blend_log(&k, black_box(&w32));
        }
        black_box(&out.m32);
    });
    rows.push(Row::alone("f32 log blend of 4 motors", ga, None));
    rows
}

/// The printable table: a heading, per row the GA time (and with a reference, the reference
/// time and the graded ratio), then the tally's summary.
fn render(rows: Vec<Row>) -> String {
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
