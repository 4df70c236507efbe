//! ga-benchmark's inverse kinematics on our types (`benches/examples/peer_ops/ik.rs`): the
//! Taylor-series port reproduces ga-benchmark's sanity values, and agrees with the closed-form
//! exponential where the series is accurate (and not where it is not).

#[path = "../examples/peer_ops/ik.rs"]
#[allow(dead_code)]
mod ik;

use ik::{solve, Closed, Solve, Taylor};

/// The angles of ga-benchmark's sanity test, in degrees.
const SANITY_DEG: [f64; 5] = [14.0, -25.0, 32.6, 66.9, -42.0];

fn rad(deg: [f64; 5]) -> [f64; 5] {
    deg.map(f64::to_radians)
}

/// The seven outputs' coefficients, each as its own slice.
fn parts(s: &Solve) -> Vec<Vec<f64>> {
    let a = s.to_array();
    let mut at = 0;
    [4, 8, 8, 4, 8, 8, 5]
        .iter()
        .map(|&n| {
            at += n;
            a[at - n..at].to_vec()
        })
        .collect()
}

/// The largest difference of two solves, each output relative to `max(1, its largest |value|)`.
fn rel_diff(a: &Solve, b: &Solve) -> f64 {
    parts(a)
        .iter()
        .zip(parts(b))
        .map(|(x, y)| {
            let scale = x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            x.iter()
                .zip(&y)
                .map(|(p, q)| (p - q).abs() / scale)
                .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

#[test]
fn taylor_port_reproduces_ga_benchmark_sanity_values() {
    let s = solve::<Taylor>(rad(SANITY_DEG));
    // AlgorithmInverseKinematics.cpp's comment, printed to 6 digits, in our blade order
    // (Rotor s e12 e13 e23; Motor s e12 e13 e23 e1i e2i e3i e123i; Translator s e1i e2i e3i).
    // Its Rg and Jg_f are left out: they carry GATL's integral evaluation of d5 = 1142 / 10
    // (`benches/peers/gatl_ik.hpp`), and ours differ in the 5th digit.
    let expect: [&[f64]; 5] = [
        &[0.992546, 0.121869, 0.0, 0.0],
        &[
            0.976296, 0.0, 0.210006, -0.0523604, 142.804, -35.6051, -43.2871, 0.0,
        ],
        &[
            0.959806, 0.0, -0.272314, 0.0678954, -404.827, 100.935, 161.69, 0.0,
        ],
        &[1.0, -182.475, 45.4961, 41.6926],
        &[
            0.834423, 0.296658, 0.112228, 0.450123, 145.475, 583.469, 0.0, 0.0,
        ],
    ];
    for (k, (got, want)) in parts(&s).iter().zip(expect).enumerate() {
        for (g, w) in got.iter().zip(want) {
            // Six significant digits; a printed 0 means below the printed precision.
            let tol = if *w == 0.0 { 1e-6 } else { 6e-6 * w.abs() };
            assert!((g - w).abs() <= tol, "output {k}: {got:?} against {want:?}");
        }
    }
}

#[test]
fn taylor_and_closed_form_agree_for_small_angles() {
    // |a| <= 0.2 rad: half-angles h <= 0.1, where the series' first dropped term h^5/5! is
    // 8e-8; the lines' moments (~1e3 mm) and the chained products amplify it, so the stated
    // tolerance is 1e-6 relative to each output's largest coefficient.
    let mut x = 0x1234_5678_u64;
    let mut worst = 0.0f64;
    for _ in 0..200 {
        let a: [f64; 5] = std::array::from_fn(|_| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0) * 0.2
        });
        let d = rel_diff(&solve::<Taylor>(a), &solve::<Closed>(a));
        worst = worst.max(d);
        assert!(
            d <= 1e-6,
            "angles {a:?}: series and closed form differ by {d:e}"
        );
    }
    assert!(
        worst > 0.0,
        "the two exponentials should not be the same code"
    );
}

#[test]
fn taylor_and_closed_form_differ_for_large_angles() {
    // At ga-benchmark's sanity angles (half-angles up to 0.58 rad) the series is off by about
    // h^5/5! ~ 6e-4: the comparison above can fail.
    let a = rad(SANITY_DEG);
    let d = rel_diff(&solve::<Taylor>(a), &solve::<Closed>(a));
    assert!(
        d > 1e-5,
        "series and closed form agree to {d:e} at large angles"
    );
}

#[test]
fn closed_form_versors_are_unit_and_keep_the_gripper_a_point() {
    // The closed form gives unit motors, so the moved gripper stays a normalised conformal
    // point: eo stays 1 and the point is null.
    let s = solve::<Closed>(rad(SANITY_DEG));
    for m in [s.r2, s.r3, s.r4, s.rg] {
        let n = (m * m.rev()).to_array();
        assert!(
            (n[0] - 1.0).abs() < 1e-12 && n[1..].iter().all(|v| v.abs() < 1e-9),
            "{n:?}"
        );
    }
    let p = s.jg;
    assert!((p.eo - 1.0).abs() < 1e-12, "{p:?}");
    let null = p.e1 * p.e1 + p.e2 * p.e2 + p.e3 * p.e3 - 2.0 * p.eo * p.ei;
    assert!(null.abs() < 1e-9 * p.ei.abs(), "not null: {null}");
}
