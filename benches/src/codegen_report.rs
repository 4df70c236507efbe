//! Quick speed report for the generator (`ga-codegen`): generated CGA products against the generic
//! [`ga_codegen::Multivector`] on the same inputs, one unit motor applied to 1M points (matrix
//! path and fused sandwich) against glam's `DMat4::transform_point3`, and the time and size of
//! generating the CGA module. Ratios are measured side by side in one run.

use crate::grade::{Spread, Tally, Target};
use crate::timing::{time_ns, Lcg};
use cga::Sandwich;
use ga_codegen::generator::emit::Generated;
use ga_codegen::Multivector;
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Inputs per timing loop for the generated-vs-generic table.
const N: usize = 256;
/// Points in the batch comparison.
const POINTS: usize = 1_000_000;

/// Times a generated binary operation and the generic multivector's version on the same inputs.
fn pair<A: Copy, B: Copy, R>(
    a: &[A],
    b: &[B],
    to_mv_a: impl Fn(A) -> Multivector,
    to_mv_b: impl Fn(B) -> Multivector,
    generated: impl Fn(A, B) -> R,
    generic: impl Fn(&Multivector, &Multivector) -> Multivector,
) -> (Spread, Spread) {
    let budget = Duration::from_millis(150);
    let ga = time_ns(a.len(), budget, || {
        for (x, y) in black_box(a).iter().zip(black_box(b)) {
            black_box(generated(*x, *y));
        }
    });
    let ma: Vec<Multivector> = a.iter().map(|x| to_mv_a(*x)).collect();
    let mb: Vec<Multivector> = b.iter().map(|x| to_mv_b(*x)).collect();
    let gen = time_ns(a.len(), budget, || {
        for (x, y) in black_box(&ma).iter().zip(black_box(&mb)) {
            black_box(generic(x, y));
        }
    });
    (ga, gen)
}

/// Runs every measurement and returns a printable table.
pub fn report() -> String {
    let mut rng = Lcg(0xC6A);
    let mut s = String::new();
    let mut tally = Tally::default();

    // Generated vs generic.
    let inputs = ProductInputs::new(&mut rng);
    let rows = time_products(&inputs);
    write_products(&rows, &mut s, &mut tally);

    // One unit motor on 1M points.
    let points = time_points(&mut rng);
    write_points(&points, &mut s, &mut tally);

    // Generating the CGA module.
    generation(&mut s, &mut tally);
    let _ = writeln!(s, "{}", tally.summary());
    s
}

/// `N` random operands of each kind for the generated-vs-generic table; two sets where a
/// product takes two of a kind.
struct ProductInputs {
    motors: Vec<cga::Motor>,
    motors2: Vec<cga::Motor>,
    points: Vec<cga::Point>,
    vectors: Vec<cga::Vector>,
    vectors2: Vec<cga::Vector>,
    bivectors: Vec<cga::Bivector>,
    evens: Vec<cga::Even>,
    evens2: Vec<cga::Even>,
    mvs: Vec<cga::Mv>,
    mvs2: Vec<cga::Mv>,
}

impl ProductInputs {
    /// Draws the operands from `rng`, in the order of the fields.
    fn new(rng: &mut Lcg) -> ProductInputs {
        let motors: Vec<cga::Motor> = (0..N).map(|_| rng.motor()).collect();
        let motors2: Vec<cga::Motor> = (0..N).map(|_| rng.motor()).collect();
        let points: Vec<cga::Point> = (0..N).map(|_| cga::Point::from_vec3(rng.vec3())).collect();
        let vectors: Vec<cga::Vector> = (0..N)
            .map(|_| cga::Vector::from_array(rng.array()))
            .collect();
        let vectors2: Vec<cga::Vector> = (0..N)
            .map(|_| cga::Vector::from_array(rng.array()))
            .collect();
        let bivectors: Vec<cga::Bivector> = (0..N)
            .map(|_| cga::Bivector::from_array(rng.array()))
            .collect();
        let evens: Vec<cga::Even> = (0..N).map(|_| cga::Even::from_array(rng.array())).collect();
        let evens2: Vec<cga::Even> = (0..N).map(|_| cga::Even::from_array(rng.array())).collect();
        let mvs: Vec<cga::Mv> = (0..N).map(|_| cga::Mv::from_array(rng.array())).collect();
        let mvs2: Vec<cga::Mv> = (0..N).map(|_| cga::Mv::from_array(rng.array())).collect();
        ProductInputs {
            motors,
            motors2,
            points,
            vectors,
            vectors2,
            bivectors,
            evens,
            evens2,
            mvs,
            mvs2,
        }
    }
}

/// Times each generated product and its generic version: (label, (generated, generic)) in ns.
fn time_products(inputs: &ProductInputs) -> Vec<(&'static str, (Spread, Spread))> {
    let ProductInputs {
        motors,
        motors2,
        points,
        vectors,
        vectors2,
        bivectors,
        evens,
        evens2,
        mvs,
        mvs2,
    } = inputs;
    vec![
        (
            "Motor * Motor",
            pair(
                motors,
                motors2,
                |x| x.to_multivector(),
                |x| x.to_multivector(),
                |x, y| x * y,
                |x, y| x.gp(y),
            ),
        ),
        (
            "Motor.sandwich(Point)",
            pair(
                motors,
                points,
                |x| x.to_multivector(),
                |x| x.to_multivector(),
                |x, y| x.sandwich(y),
                |x, y| x.gp(y).gp(&x.rev()),
            ),
        ),
        (
            "Vector ^ Vector",
            pair(
                vectors,
                vectors2,
                |x| x.to_multivector(),
                |x| x.to_multivector(),
                |x, y| x ^ y,
                |x, y| x.outer(y),
            ),
        ),
        (
            "Vector | Bivector",
            pair(
                vectors,
                bivectors,
                |x| x.to_multivector(),
                |x| x.to_multivector(),
                |x, y| x | y,
                |x, y| x.left_contraction(y),
            ),
        ),
        (
            "Even * Even",
            pair(
                evens,
                evens2,
                |x| x.to_multivector(),
                |x| x.to_multivector(),
                |x, y| x * y,
                |x, y| x.gp(y),
            ),
        ),
        (
            "Mv * Mv (32 x 32)",
            pair(
                mvs,
                mvs2,
                |x| x.to_multivector(),
                |x| x.to_multivector(),
                |x, y| x * y,
                |x, y| x.gp(y),
            ),
        ),
    ]
}

/// Writes the generated-vs-generic table: the heading, then per product both times and the
/// graded speed-up.
fn write_products(rows: &[(&str, (Spread, Spread))], s: &mut String, tally: &mut Tally) {
    let _ = writeln!(
        s,
        "generated CGA products vs the generic multivector (f64, ns per call, best of 5 rounds [range])"
    );
    for (what, (ga, gen)) in rows {
        let _ = writeln!(s, "{what}: generated {ga} ns, generic {gen} ns");
        let label = format!("{what}, speedup over generic");
        let speedup = ga.speedup_over(*gen);
        let _ = writeln!(
            s,
            "{}",
            tally.row(&label, speedup, "x", Some(Target::AtLeast(50.0)))
        );
    }
}

/// Per-point times (ns) of one unit motor on `POINTS` points, measured in this order.
struct PointTimes {
    /// glam's `DMat4::transform_point3`, the reference.
    glam: Spread,
    /// `Motor::transform_points` (the point matrix).
    matrix: Spread,
    /// The fused sandwich, point by point.
    sandwich: Spread,
}

/// Draws `POINTS` points and one unit motor from `rng` and times the three ways to move them.
fn time_points(rng: &mut Lcg) -> PointTimes {
    let pts: Vec<glam::DVec3> = (0..POINTS).map(|_| rng.vec3()).collect();
    let mut out = vec![glam::DVec3::ZERO; POINTS];
    let m = rng.motor();
    let mat = m.to_mat4();
    let budget = Duration::from_millis(600);
    let glam_ns = time_ns(POINTS, budget, || {
        let mat = black_box(mat);
        for (o, p) in out.iter_mut().zip(black_box(&pts)) {
            *o = mat.transform_point3(*p);
        }
        black_box(&out);
    });
    let matrix_ns = time_ns(POINTS, budget, || {
        black_box(m).transform_points(black_box(&pts), &mut out);
        black_box(&out);
    });
    let sandwich_ns = time_ns(POINTS, budget, || {
        let m = black_box(m);
        for (o, p) in out.iter_mut().zip(black_box(&pts)) {
            *o = m.sandwich(cga::Point::from_vec3(*p)).to_vec3();
        }
        black_box(&out);
    });
    PointTimes {
        glam: glam_ns,
        matrix: matrix_ns,
        sandwich: sandwich_ns,
    }
}

/// Writes the one-motor-on-many-points table: the heading, each time, and the graded ratio
/// to glam of the two GA paths.
fn write_points(times: &PointTimes, s: &mut String, tally: &mut Tally) {
    let glam_ns = times.glam;
    let _ = writeln!(
        s,
        "\none unit motor on {POINTS} points (f64, ns per point, ratio to glam in the same run)"
    );
    let rows = [
        ("glam DMat4::transform_point3", glam_ns, None),
        (
            "Motor::transform_points (point_matrix)",
            times.matrix,
            Some(Target::AtMost(1.1)),
        ),
        (
            "Motor.sandwich(Point) per point (fused)",
            times.sandwich,
            Some(Target::AtMost(2.0)),
        ),
    ];
    for (label, ns, target) in rows {
        let _ = writeln!(s, "{}", tally.row(label, ns, "ns/point", None));
        if target.is_some() {
            let ratio = ns.ratio(glam_ns);
            let label = format!("{label} / glam");
            let _ = writeln!(s, "{}", tally.row(&label, ratio, "x", target));
        }
    }
}

/// Times generating the CGA module from `algebras/cga.toml` once and writes the heading, the
/// graded time and the module's size (or why it could not be read or generated).
fn generation(s: &mut String, tally: &mut Tally) {
    let spec_path = concat!(env!("CARGO_MANIFEST_DIR"), "/../algebras/cga.toml");
    let _ = writeln!(
        s,
        "\ngenerating algebras/cga.toml (spec parse + symbolic products + emit + format; target < 2 s)"
    );
    match std::fs::read_to_string(spec_path) {
        Ok(text) => {
            let (secs, result) = time_generation(&text);
            write_generation(secs, result, s, tally);
        }
        Err(e) => {
            let _ = writeln!(s, "cannot read {spec_path}: {e}");
        }
    }
}

/// Parses, generates and formats the spec `text` once: seconds taken, and the generated module
/// or the first error.
fn time_generation(text: &str) -> (f64, Result<Generated, String>) {
    let start = Instant::now();
    let result = ga_codegen::Spec::from_toml(text, "algebras/cga.toml")
        .map_err(|e| e.to_string())
        .and_then(|spec| {
            let g = ga_codegen::generate(&spec, &ga_codegen::EmitOptions::default())
                .map_err(|e| e.to_string())?;
            // Format too (prettyplease), as the CLI and the build script do.
            g.code().map_err(|e| e.to_string())?;
            Ok(g)
        });
    let secs = start.elapsed().as_secs_f64();
    (secs, result)
}

/// Writes the graded generation time and the module's size, or the failure and its reason.
fn write_generation(
    secs: f64,
    result: Result<Generated, String>,
    s: &mut String,
    tally: &mut Tally,
) {
    match result {
        Ok(g) => {
            let label = "generation (one run)";
            let time = Spread::exact(secs);
            let _ = writeln!(
                s,
                "{}",
                tally.row(label, time, "s", Some(Target::Below(2.0)))
            );
            let _ = writeln!(
                s,
                "{} lines, {} types, {} operations ({} identically zero, not emitted)",
                g.lines(),
                g.types.len(),
                g.ops.len(),
                g.zero_ops
            );
        }
        Err(e) => {
            let failed = Spread::exact(f64::NAN);
            let label = "generation (failed)";
            let _ = writeln!(
                s,
                "{}",
                tally.row(label, failed, "s", Some(Target::Below(2.0)))
            );
            let _ = writeln!(s, "generation failed: {e}");
        }
    }
}
