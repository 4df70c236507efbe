//! exp and log on exact inputs where other libraries break: the zero bivector, pure
//! translations, half turns at and near pi, tiny angles, nearly null four-vectors, huge and tiny
//! scales, far motors, negative-scalar versors, and the sign conventions of each algebra.

use super::*;
use std::f64::consts::FRAC_PI_2;
use tests::{cga, g3, pga3d, sta};

#[test]
fn zero_bivector_is_the_identity_both_ways() {
    use g3::{Exp as _, Log as _};
    let r: g3::Rotor = g3::Bivector::default().exp();
    assert_eq!(r, g3::Rotor::new(1.0, 0.0, 0.0, 0.0));
    assert_eq!(r.log(), g3::Bivector::default());
    use pga3d::{Exp as _, Log as _};
    let m: pga3d::Motor = pga3d::Line::default().exp();
    assert_eq!(m.s, 1.0);
    assert_eq!(m.to_array()[1..], [0.0; 7]);
    assert_eq!(m.log(), pga3d::Line::default());
    use sta::{Exp as _, Log as _};
    let l: sta::Rotor = sta::Bivector::default().exp();
    assert_eq!(l.s, 1.0);
    assert_eq!(l.log(), sta::Bivector::default());
    use cga::{Exp as _, Log as _};
    let e: cga::Even = cga::Bivector::default().exp();
    assert_eq!(e.s, 1.0);
    assert_eq!(e.log(), cga::Bivector::default());
}

#[test]
fn pure_translations_are_one_plus_the_bivector() {
    use pga3d::{Exp as _, Log as _};
    let b = pga3d::Line::new(1.5, -2.0, 3.0, 0.0, 0.0, 0.0);
    let m: pga3d::Motor = b.exp();
    assert_eq!(
        m,
        pga3d::Motor::new(1.0, 0.0, 0.0, 0.0, 1.5, -2.0, 3.0, 0.0)
    );
    assert_eq!(m.log(), b);
    let t: pga3d::Translator = b.exp();
    assert_eq!(t.log(), b);
    use cga::{Exp as _, Log as _};
    let mut c = cga::Bivector::default();
    (c.e1i, c.e2i, c.e3i) = (0.25, -4.0, 1e-3);
    let m: cga::Motor = c.exp();
    assert_eq!(
        (m.s, m.e1i, m.e2i, m.e3i, m.e12, m.e123i),
        (1.0, 0.25, -4.0, 1e-3, 0.0, 0.0)
    );
    assert_eq!(m.log(), c);
    let e: cga::Even = c.exp();
    near(
        "cga even translation",
        &e.log().to_multivector(),
        &c.to_multivector(),
        1e-15,
    );
}

#[test]
fn half_turns_at_and_near_pi() {
    use g3::{Exp as _, Log as _};
    // Exactly e12: a half-turn (rotation by pi), scalar part exactly zero.
    let r = g3::Rotor::new(0.0, 0.0, 0.0, 1.0);
    let want = g3::Bivector::new(0.0, 0.0, FRAC_PI_2);
    near(
        "log e12",
        &r.log().to_multivector(),
        &want.to_multivector(),
        1e-15,
    );
    // The rotation angle pi - 2e-9, and pi - 1e-15.
    for eps in [1e-9, 5e-16] {
        let b = g3::Bivector::new(0.6 * (FRAC_PI_2 - eps), 0.0, 0.8 * (FRAC_PI_2 - eps));
        let r: g3::Rotor = b.exp();
        near(
            "log near pi",
            &r.log().to_multivector(),
            &b.to_multivector(),
            1e-15,
        );
    }
    // Past the half turn: the log takes the short way round (the other sign).
    let b = g3::Bivector::new(0.0, 0.0, FRAC_PI_2 + 0.25);
    let r: g3::Rotor = b.exp();
    let short = g3::Bivector::new(0.0, 0.0, FRAC_PI_2 + 0.25 - std::f64::consts::PI);
    near(
        "short way",
        &r.log().to_multivector(),
        &short.to_multivector(),
        1e-15,
    );
    // A PGA screw motion with a half turn: rotation by pi about the z axis plus a
    // translation along it, and the same motor with a scalar part of exactly zero.
    use pga3d::{Exp as _, Log as _};
    let b = pga3d::Line::new(0.0, 0.0, 0.7, 0.0, 0.0, FRAC_PI_2);
    let m: pga3d::Motor = b.exp();
    near(
        "pga screw half turn",
        &m.log().to_multivector(),
        &b.to_multivector(),
        1e-15,
    );
    let mut exact = m;
    exact.s = 0.0;
    near(
        "pga exact half turn",
        &exact.log().to_multivector(),
        &b.to_multivector(),
        1e-15,
    );
    // An off-axis half turn: rotation by pi about a line through (1, 0, 0).
    let b = pga3d::Line::new(0.0, -FRAC_PI_2, 0.0, 0.0, 0.0, FRAC_PI_2);
    let m: pga3d::Motor = b.exp();
    near(
        "pga off-axis half turn",
        &m.log().to_multivector(),
        &b.to_multivector(),
        1e-15,
    );
}

#[test]
fn tiny_angles() {
    use g3::{Exp as _, Log as _};
    let b = g3::Bivector::new(1e-300, -2e-300, 3e-300);
    let r: g3::Rotor = b.exp();
    assert_eq!(r, g3::Rotor::new(1.0, 1e-300, -2e-300, 3e-300));
    let back = r.log();
    for (x, y) in back.to_array().iter().zip(b.to_array()) {
        assert!((x - y).abs() <= 1e-15 * y.abs(), "{back:?}");
    }
    // A tiny rotation with a unit translation (PGA), and the same in CGA.
    use pga3d::{Exp as _, Log as _};
    let b = pga3d::Line::new(1.0, 0.5, -0.25, 1e-160, 0.0, 2e-160);
    let m: pga3d::Motor = b.exp();
    near(
        "pga tiny",
        &m.log().to_multivector(),
        &b.to_multivector(),
        1e-15,
    );
    let b = pga3d::Line::new(1.0, 0.5, -0.25, 1e-9, 0.0, 2e-9);
    let m: pga3d::Motor = b.exp();
    near(
        "pga small",
        &m.to_multivector(),
        &b.to_multivector().exp(),
        1e-15,
    );
    near(
        "pga small log",
        &m.log().to_multivector(),
        &b.to_multivector(),
        1e-15,
    );
    use cga::{Exp as _, Log as _};
    let mut c = cga::Bivector::default();
    (c.e12, c.e1i, c.e3i) = (1e-200, 1.0, -2.0);
    let m: cga::Motor = c.exp();
    near(
        "cga tiny",
        &m.log().to_multivector(),
        &c.to_multivector(),
        1e-15,
    );
}

/// A CGA `Even` whose grade-4 part is nearly null (a screw motion, perturbed: `<v>_4^2 =
/// 3.7e-5` from terms of about 1.5): read as two rotations, its logarithm divided by
/// `sqrt(3.7e-5)` and came back 2e-10 off in f64 (0.1 in f32); the split by the squares of
/// the bivector part, which differ by far more, is exact to the precision. Found by
/// `exp_inverts_log_up_to_sign`.
#[test]
fn nearly_null_four_vector_is_not_a_double_rotation() {
    use cga::{Exp as _, Log as _};
    let c = [
        0.0,
        0.5484113127473594,
        -0.6998074726588602,
        -0.10538637554802817,
        -0.3189749429318847,
        -0.8870899831501191,
        -0.4728025201250004,
        -0.7512948226609527,
        0.20229413691089634,
        0.3966802151832649,
        0.719364939533516,
    ];
    let alg = cga::algebra();
    let b = cga::Bivector::from_multivector(&on_blades(
        &alg,
        &cga::Even::BLADES,
        &[2],
        &c,
        1.3835437951184608,
    ));
    let v: cga::Even = b.exp();
    let r4 = [v.eo123, v.eo12i, v.eo13i, v.eo23i, v.e123i];
    let r4sq = 2.0 * r4[0] * r4[4] - r4[1] * r4[1] - r4[2] * r4[2] - r4[3] * r4[3];
    assert!(r4sq > 0.0 && r4sq < 1e-4, "the case under test: {r4sq}");
    let back: cga::Even = v.log().exp();
    if let Err(e) = close_up_to_sign(
        "nearly null grade 4",
        &back.to_multivector(),
        &v.to_multivector(),
        1e-14,
    ) {
        panic!("{e}");
    }
    use tests::cga_f32::{self, Exp as _};
    let vf = cga_f32::Even::from_array(v.to_array().map(|x| x as f32));
    let backf: cga_f32::Even = cga_f32::Log::log(vf).exp();
    if let Err(e) = close_up_to_sign(
        "nearly null grade 4, f32",
        &backf.to_multivector(),
        &vf.to_multivector(),
        1e-5,
    ) {
        panic!("{e}");
    }
}

#[test]
fn huge_and_tiny_scales_normalise() {
    use pga3d::{EvenVersor as _, Exp as _};
    let b = pga3d::Line::new(0.3, -1.0, 2.0, 0.4, -0.2, 0.9);
    let m: pga3d::Motor = b.exp();
    for k in [1e200, 1e-200, 1e300, 1e-300] {
        let mk = pga3d::Motor::from_array(m.to_array().map(|x| x * k));
        near(
            "normalize scaled",
            &mk.normalize().to_multivector(),
            &m.to_multivector(),
            1e-15,
        );
    }
    // A huge translation stays finite and inverts.
    use pga3d::Log as _;
    let t = pga3d::Line::new(1e200, -3e199, 0.0, 0.0, 0.0, 0.0);
    let m: pga3d::Motor = t.exp();
    assert_eq!(m.log(), t);
    use cga::{EvenVersor as _, Exp as _};
    let mut c = cga::Bivector::default();
    (c.e12, c.e13, c.e1i, c.eoi) = (0.4, -0.3, 2.0, 0.2);
    let s: cga::ScaledMotor = c.exp();
    let sk = cga::ScaledMotor::from_array(s.to_array().map(|x| x * 1e250));
    near(
        "cga scaled normalize",
        &sk.normalize().to_multivector(),
        &s.to_multivector(),
        1e-14,
    );
}

/// Motors whose rotation part is tiny next to their translation (a turn of 0.28 rad with a
/// shift of `1e6` to `1e11` units in f32, `1e60` and `1e100` in f64): `normalize` took
/// `1 / sqrt(2 a N^2)` with `a ~ N ~ n0` (the squared rotation part over the largest
/// coefficient squared), which underflowed to zero, so `inf` or `NaN`, once that ratio
/// fell under about `3e-8` in f32 and `1e-54` in f64; `sqrt` of a motor within `1e-9` of
/// a full turn went through it too. Below `1e-19` (f32) and `1e-154` (f64) `n0` itself
/// underflows.
#[test]
fn motors_far_from_the_origin_normalise_finitely() {
    use tests::cga_f32;
    let unit = |w: Multivector, what: &str, tol: f64| {
        let one = Multivector::scalar(w.algebra(), 1.0);
        near(what, &w.gp(&w.rev()), &one, tol);
    };
    for (far, f32_too) in [
        (1e6, true),
        (1e7, true),
        (1e11, true),
        (1e60, false),
        (1e100, false),
    ] {
        let mut c = cga::Bivector::default();
        (c.e12, c.e13, c.e1i, c.e2i) = (0.1, -0.1, far, -0.5 * far);
        let m: cga::Motor = cga::Exp::exp(c);
        let drift = cga::Motor::from_array(m.to_array().map(|x| x * 1.001));
        let n = cga::EvenVersor::normalize(drift).to_multivector();
        near(
            &format!("f64 normalize, {far:e}"),
            &n,
            &m.to_multivector(),
            1e-13 * far,
        );
        unit(n, &format!("f64 normalize unit, {far:e}"), 1e-13 * far);
        if f32_too {
            let m32 = cga_f32::Motor::from_array(m.to_array().map(|x| x as f32));
            let drift = cga_f32::Motor::from_array(m32.to_array().map(|x| x * 1.001));
            let n = cga_f32::EvenVersor::normalize(drift);
            assert!(
                n.to_array().iter().all(|x| x.is_finite()),
                "f32 normalize, {far:e}: {:?}",
                n.to_array()
            );
            near(
                &format!("f32 normalize, {far:e}"),
                &n.to_multivector(),
                &m32.to_multivector(),
                1e-6 * far,
            );
        }
    }
}

#[test]
fn negative_scalar_versors_log_to_the_same_motion() {
    use sta::{Exp as _, Log as _};
    let b = sta::Bivector::new(0.3, -0.2, 0.5, 1.1, 0.4, -0.7);
    let r: sta::Rotor = b.exp();
    near(
        "log -R",
        &(-r).log().to_multivector(),
        &b.to_multivector(),
        1e-14,
    );
    near(
        "log R",
        &r.log().to_multivector(),
        &b.to_multivector(),
        1e-14,
    );
    use pga3d::{Exp as _, Log as _};
    let b = pga3d::Line::new(0.3, -1.0, 2.0, 0.4, -0.2, 0.9);
    let m: pga3d::Motor = b.exp();
    assert_eq!((-m).log(), m.log());
}

#[test]
fn sign_conventions_of_each_algebra() {
    // G3: exp(-(t/2) e12) turns e1 towards e2 by t; the field e31 stores -e13.
    use g3::{Exp as _, Sandwich as _};
    let t = 0.7f64;
    let r: g3::Rotor = g3::Bivector::new(0.0, 0.0, -t / 2.0).exp();
    let v = r.sandwich(g3::Vector::new(1.0, 0.0, 0.0));
    near(
        "g3 rotation",
        &v.to_multivector(),
        &g3::Vector::new(t.cos(), t.sin(), 0.0).to_multivector(),
        1e-15,
    );
    let r31: g3::Rotor = g3::Bivector::new(0.0, -t / 2.0, 0.0).exp();
    let v = r31.sandwich(g3::Vector::new(0.0, 0.0, 1.0));
    near(
        "g3 e31",
        &v.to_multivector(),
        &g3::Vector::new(t.sin(), 0.0, t.cos()).to_multivector(),
        1e-15,
    );
    // STA: exp((p/2) e01) is a boost with rapidity p: e0 -> cosh(p) e0 - sinh(p) e1.
    use sta::{Exp as _, Sandwich as _};
    let p = 0.9f64;
    let r: sta::Rotor = sta::Bivector::new(p / 2.0, 0.0, 0.0, 0.0, 0.0, 0.0).exp();
    let v = r.sandwich(sta::Vector::new(1.0, 0.0, 0.0, 0.0));
    near(
        "sta boost",
        &v.to_multivector(),
        &sta::Vector::new(p.cosh(), -p.sinh(), 0.0, 0.0).to_multivector(),
        1e-15,
    );
}
