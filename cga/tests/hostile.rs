//! Hostile input: every fallible function of `cga` fed huge, tiny, subnormal, NaN and infinite
//! values. The promise under test: a `try_` function never panics, and returns `Ok` only with a
//! finite, valid result (checked on the output, not only the input). The first tests pin the
//! cases a hostile user found; the property tests sweep the classes.

use cga::{
    Bivector, CgaError, Circle, Dilator, Line, Motor, Plane, Point, PointPair, Rotor, ScaledMotor,
    Sphere, Translator, Vector,
};
use glam::{DAffine3, DMat4, DQuat, DVec3};
use proptest::prelude::*;
use std::f64::consts::PI;

fn finite(c: &[f64]) -> bool {
    c.iter().all(|x| x.is_finite())
}

/// `M ~M = 1` for a unit motor: rotor norm 1 and the versor defect zero, both to `tol`.
fn assert_unit_motor(m: Motor, tol: f64) {
    assert!(finite(&m.to_array()), "non-finite motor {m:?}");
    assert!((m.norm_squared() - 1.0).abs() <= tol, "not unit: {m:?}");
    let dual = m.to_array()[4..].iter().fold(1.0f64, |a, x| a.max(x.abs()));
    assert!(m.versor_defect().abs() <= tol * dual, "not a versor: {m:?}");
}

fn is_overflow<T: std::fmt::Debug>(r: Result<T, CgaError>) -> bool {
    matches!(r, Err(CgaError::Overflow { .. }))
}

fn rotation_by_pi() -> Motor {
    Motor::from_rotation_translation(DQuat::from_rotation_x(PI), DVec3::new(1.0, 2.0, 3.0))
}

#[test]
fn huge_finite_input_that_overflows_is_an_overflow_error() {
    let far = DVec3::new(1e300, 0.0, 0.0);
    assert!(is_overflow(Point::try_from_vec3(far)));
    assert!(is_overflow(Sphere::try_new(DVec3::ZERO, 1e300)));
    assert!(is_overflow(
        ScaledMotor::try_from_scale_rotation_translation(1e300, DQuat::IDENTITY, DVec3::ZERO)
    ));
    assert!(is_overflow(
        ScaledMotor::try_from_scale_rotation_translation(1e-300, DQuat::IDENTITY, DVec3::ZERO)
    ));
    assert!(is_overflow(Line::through_points(far, -far)));
    assert!(is_overflow(Line::through_points(
        DVec3::new(0.0, 1e300, 0.0),
        far
    )));
    assert!(is_overflow(PointPair::from_points(far, DVec3::ZERO)));
    assert!(is_overflow(Circle::through_points(far, DVec3::Y, DVec3::Z)));
    assert!(is_overflow(Sphere::through_points(
        far,
        DVec3::X,
        DVec3::Y,
        DVec3::Z
    )));
    let mut b = Bivector::rotation_generator(DVec3::X, 0.3);
    b.e12 = 1e300;
    assert!(is_overflow(b.try_exp_motor()));
    let mut b = Bivector::translation_generator(DVec3::X);
    b.e12 = 1e300;
    assert!(is_overflow(b.try_exp_motor()));
    let a = Motor::IDENTITY;
    let m = Motor::from_rotation_translation(DQuat::from_rotation_z(1.0), DVec3::X);
    assert!(is_overflow(Motor::try_interpolate(a, m, f64::MAX)));
    assert!(is_overflow(Motor::try_blend_log(&[m, a], &[1e300, 1.0])));
    assert!(is_overflow(Motor::try_blend_log(&[m, m], &[1e300, 1e300])));
    let s = ScaledMotor::from_scale_rotation_translation(2.0, DQuat::IDENTITY, DVec3::X);
    assert!(is_overflow(ScaledMotor::try_blend_log(&[s], &[1e300])));
    let shift = Motor::from_translation(DVec3::new(f64::MAX, 0.0, 0.0));
    let mut out = [DVec3::ZERO; 2];
    let src = [DVec3::ZERO, DVec3::new(f64::MAX, 0.0, 0.0)];
    assert!(is_overflow(shift.try_transform_points(&src, &mut out)));
    assert!(shift.try_transform_points(&src[..1], &mut out[..1]).is_ok());
    assert_eq!(out[0], DVec3::new(f64::MAX, 0.0, 0.0));
}

#[test]
fn huge_and_tiny_multiples_of_a_motor_are_the_same_motion() {
    let m = rotation_by_pi();
    let reference = m.log();
    // 5e-320 M is a handful of subnormal steps: refused (see tests/log_of_multiples.rs).
    assert!(matches!(
        (m * 5e-320).try_log(),
        Err(CgaError::Overflow { .. })
    ));
    for k in [1e300, 1e-300, 1e-310, -1e300, 1e150] {
        let scaled = m * k;
        let log = scaled.try_log().unwrap_or_else(|e| panic!("{k}: {e}"));
        let diff = log
            .to_array()
            .iter()
            .zip(reference.to_array())
            .fold(0.0f64, |a, (p, q)| a.max((p - q).abs()));
        assert!(diff < 1e-12, "{k}: log {log:?} vs {reference:?}");
        let n = scaled.try_normalize_rigid().unwrap();
        assert_unit_motor(n, 1e-14);
        assert!(
            n.to_mat4().abs_diff_eq(m.to_mat4(), 1e-12),
            "{k}: {:?}",
            n.to_mat4()
        );
        let blend = Motor::try_blend_linear(&[scaled, m], &[0.5, 0.5]).unwrap();
        assert!(blend.to_mat4().abs_diff_eq(m.to_mat4(), 1e-12), "{k}");
    }
}

#[test]
fn non_finite_motors_are_rejected() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for k in 0..8 {
            let mut c = Motor::IDENTITY.to_array();
            c[k] = bad;
            let m = Motor::from_array(c);
            assert!(matches!(m.try_log(), Err(CgaError::NonFinite { .. })));
            assert!(matches!(
                m.try_normalize_rigid(),
                Err(CgaError::NonFinite { .. })
            ));
            assert!(matches!(
                Motor::try_blend_linear(&[Motor::IDENTITY, m], &[0.5, 0.5]),
                Err(CgaError::NonFinite { .. })
            ));
        }
    }
}

#[test]
fn subnormal_weight_is_an_error_or_a_finite_point() {
    let v = Vector::new(5.6e-309, 1.0, 2.0, 3.0, 4.0);
    assert!(is_overflow(v.try_to_point()));
    // A subnormal weight with coordinates of the same tiny scale is a fine point.
    let v = Vector::new(5.6e-309, 5.6e-309, 2.0 * 5.6e-309, 0.0, 5.6e-309);
    let p = v.try_to_point().unwrap();
    assert!((p.to_vec3() - DVec3::new(1.0, 2.0, 0.0)).length() < 1e-9);
}

#[test]
fn huge_or_tiny_axes_are_axes() {
    for k in [1e300, 1e-310, f64::MAX, 5e-324] {
        let r = Rotor::try_from_axis_angle(DVec3::new(0.0, 0.0, k), PI / 2.0).unwrap();
        assert!(
            (r.transform_point(DVec3::X) - DVec3::Y).length() < 1e-15,
            "{k}"
        );
        assert_eq!(Rotor::from_axis_angle(DVec3::new(0.0, 0.0, k), PI / 2.0), r);
        let q = Rotor::try_from_quat(DQuat::from_xyzw(0.0, 0.0, k, k)).unwrap();
        assert!(
            (q.transform_point(DVec3::X) - DVec3::Y).length() < 1e-15,
            "{k}"
        );
        let p = Plane::try_from_normal_distance(DVec3::new(k, 0.0, 0.0), 2.0).unwrap();
        assert!((p.signed_distance(DVec3::new(5.0, 1.0, 1.0)) - 3.0).abs() < 1e-15);
        let l = Line::from_point_direction(DVec3::ZERO, DVec3::new(k, 0.0, 0.0));
        let l = l.unwrap();
        assert!((l.distance_to_point(DVec3::new(3.0, 4.0, 0.0)) - 4.0).abs() < 1e-12);
        assert!((l.direction() - DVec3::X).length() < 1e-15);
    }
    assert!(matches!(
        Rotor::try_from_axis_angle(DVec3::ZERO, 1.0),
        Err(CgaError::ZeroAxis { .. })
    ));
}

#[test]
fn dilators_outside_the_representable_range_are_refused() {
    for d in [
        1e12,
        1e-12,
        1e300,
        1e-300,
        f64::MAX,
        f64::MIN_POSITIVE,
        5e-324,
    ] {
        assert!(is_overflow(Dilator::try_from_scale(d)), "{d}");
    }
    for d in [1e-8, 0.5, 1.0, 3.0, 1e8] {
        let x = Dilator::try_from_scale(d).unwrap();
        assert!((x.scale() / d - 1.0).abs() < 1e-6, "{d}");
    }
}

#[test]
fn matrices_that_overflow_are_not_rigid() {
    let huge = DMat4::from_cols_array(&[1e200; 16]);
    assert!(Motor::try_from_mat4(huge).is_err());
    let mut m = DMat4::IDENTITY;
    m.x_axis.x = 1e200;
    m.y_axis.x = -1e200;
    assert!(Motor::try_from_mat4(m).is_err());
    assert!(ScaledMotor::try_from_mat4(m).is_err());
    let big = DMat4::from_scale(DVec3::splat(1e200));
    assert!(ScaledMotor::try_from_mat4(big).is_err());
}

#[test]
fn f32_twins_check_their_results() {
    use cga::f32::{Motor as M32, Point as P32, Sphere as S32};
    use glam::{Quat, Vec3};
    assert!(matches!(
        P32::try_from_vec3(Vec3::new(1e30, 0.0, 0.0)),
        Err(CgaError::Overflow { .. })
    ));
    assert!(matches!(
        S32::try_new(Vec3::ZERO, 1e30),
        Err(CgaError::Overflow { .. })
    ));
    let m = M32::from_rotation_translation(Quat::from_rotation_x(std::f32::consts::PI), Vec3::X);
    let log = (m * 1e30).try_log().unwrap();
    assert!(log.to_array().iter().all(|x| x.is_finite()));
    assert!(
        (log.to_array()[4..7]
            .iter()
            .map(|x| x * x)
            .sum::<f32>()
            .sqrt()
            - 1.5707964)
            .abs()
            < 1e-5
    );
}

/// Plain, huge, tiny, subnormal, zero, NaN and infinite values.
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        2 => (-308.0..308.0f64, any::<bool>())
            .prop_map(|(e, neg)| if neg { -(10f64.powf(e)) } else { 10f64.powf(e) }),
        1 => prop::sample::select(vec![
            0.0,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            -f64::MAX,
            f64::MIN_POSITIVE,
            5.6e-309,
            -5e-324,
            1e300,
            -1e300,
            1e-300,
        ]),
    ]
}

fn hv3() -> impl Strategy<Value = DVec3> {
    (hostile(), hostile(), hostile()).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn hquat() -> impl Strategy<Value = DQuat> {
    (hostile(), hostile(), hostile(), hostile())
        .prop_map(|(x, y, z, w)| DQuat::from_xyzw(x, y, z, w))
}

/// A real motor times a hostile factor, or a motor with one hostile coefficient.
fn hmotor() -> impl Strategy<Value = Motor> {
    (-PI..PI, -5.0..5.0f64, hostile(), 0..9usize, hostile()).prop_map(|(angle, t, k, slot, v)| {
        let m = Motor::from_rotation_translation(
            DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), angle),
            DVec3::new(t, -2.0 * t, 0.5),
        );
        if slot == 8 {
            m * k
        } else {
            let mut c = m.to_array();
            c[slot] = v;
            Motor::from_array(c)
        }
    })
}

fn hbivector() -> impl Strategy<Value = Bivector> {
    prop::collection::vec(hostile(), 10).prop_map(|c| {
        let mut a = [0.0; 10];
        a.copy_from_slice(&c);
        Bivector::from_array(a)
    })
}

/// Zero the `eo` parts (the generators of similarities and rigid motions), for some cases.
fn rigid(mut b: Bivector, keep_dilation: bool) -> Bivector {
    b.eo1 = 0.0;
    b.eo2 = 0.0;
    b.eo3 = 0.0;
    if !keep_dilation {
        b.eoi = 0.0;
    }
    b
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn points_and_vectors(x in hv3(), c in prop::collection::vec(hostile(), 5)) {
        if let Ok(p) = Point::try_from_vec3(x) {
            prop_assert!(finite(&p.to_array()));
            prop_assert_eq!(p.to_vec3(), x);
            prop_assert!((p.ei - 0.5 * x.length_squared()).abs() <= 1e-15 * p.ei);
        }
        let v = Vector::new(c[0], c[1], c[2], c[3], c[4]);
        if let Ok(p) = v.try_to_point() {
            prop_assert!(finite(&p.to_array()));
        }
    }

    #[test]
    fn rotors_translators_dilators(axis in hv3(), angle in hostile(), q in hquat(), t in hv3(), d in hostile()) {
        if let Ok(r) = Rotor::try_from_axis_angle(axis, angle) {
            prop_assert!(finite(&r.to_array()));
            prop_assert!((r.norm_squared() - 1.0).abs() < 1e-12);
        }
        if let Ok(r) = Rotor::try_from_quat(q) {
            prop_assert!(finite(&r.to_array()));
            prop_assert!((r.norm_squared() - 1.0).abs() < 1e-12);
        }
        if let Ok(tr) = Translator::try_from_translation(t) {
            prop_assert!(finite(&tr.to_array()));
            prop_assert!((tr.translation() - t).length() <= 1e-15 * t.length());
        }
        if let Ok(x) = Dilator::try_from_scale(d) {
            prop_assert!(finite(&x.to_array()) && d > 0.0);
            prop_assert!((x.scale() / d - 1.0).abs() <= 1e-6);
        }
    }

    #[test]
    fn motors_from_parts(q in hquat(), t in hv3(), s in hostile()) {
        if let Ok(m) = Motor::try_from_rotation_translation(q, t) {
            assert_unit_motor(m, 1e-12);
            prop_assert!((m.translation() - t).length() <= 1e-12 * (1.0 + t.length()));
        }
        if let Ok(m) = ScaledMotor::try_from_scale_rotation_translation(s, q, t) {
            prop_assert!(finite(&m.to_array()));
            let log = m.try_log();
            prop_assert!(log.is_ok() || is_overflow(log));
        }
    }

    #[test]
    fn motor_checks_log_and_normalise(m in hmotor()) {
        if let Ok(n) = m.try_normalize_rigid() {
            assert_unit_motor(n, 1e-12);
        }
        if let Ok(b) = m.try_log() {
            prop_assert!(finite(&b.to_array()));
            if let Ok(e) = b.try_exp_motor() {
                assert_unit_motor(e, 1e-12);
                let n = m.try_normalize_rigid().unwrap();
                let scale = 1.0 + n.translation().length();
                prop_assert!(e.to_mat4().abs_diff_eq(n.to_mat4(), 1e-9 * scale));
            }
        }
    }

    #[test]
    fn exponentials(b in hbivector(), keep in any::<bool>()) {
        let b = rigid(b, keep);
        if let Ok(m) = b.try_exp_motor() {
            assert_unit_motor(m, 1e-9);
        }
        if let Ok(s) = b.try_exp_scaled() {
            prop_assert!(finite(&s.to_array()));
            let (d, q, t) = s.to_scale_rotation_translation();
            prop_assert!(d.is_finite() && d > 0.0 && q.is_finite() && t.is_finite());
        }
        if let Ok(s) = ScaledMotor::try_from_scale_rotation_translation(1.5, DQuat::IDENTITY, DVec3::X) {
            prop_assert!(s.try_log().is_ok());
        }
    }

    #[test]
    fn blends_and_interpolation(a in hmotor(), b in hmotor(), w0 in hostile(), w1 in hostile(), t in hostile()) {
        if let Ok(m) = Motor::try_blend_linear(&[a, b], &[w0, w1]) {
            assert_unit_motor(m, 1e-12);
        }
        if let Ok(m) = Motor::try_blend_log(&[a, b], &[w0, w1]) {
            assert_unit_motor(m, 1e-9);
        }
        if let Ok(m) = Motor::try_interpolate(a, b, t) {
            assert_unit_motor(m, 1e-9);
        }
        let s = [ScaledMotor::from(a), ScaledMotor::from_scale_rotation_translation(2.0, DQuat::IDENTITY, DVec3::Y)];
        if let Ok(m) = ScaledMotor::try_blend_log(&s, &[w0, w1]) {
            prop_assert!(finite(&m.to_array()));
            prop_assert!(m.scale().is_finite() && m.scale() > 0.0);
        }
    }

    #[test]
    fn objects(a in hv3(), b in hv3(), c in hv3(), d in hv3(), r in hostile(), k in hostile()) {
        if let Ok(s) = Sphere::try_new(a, r) {
            prop_assert!(finite(&s.dual_vector.to_array()) && s.dual_vector.eo == 1.0);
        }
        if let Ok(s) = Sphere::through_points(a, b, c, d) {
            prop_assert!(finite(&s.dual_vector.to_array()) && s.dual_vector.eo == 1.0);
        }
        if let Ok(p) = Plane::try_from_normal_distance(a, k) {
            prop_assert!(finite(&p.dual_vector.to_array()));
            prop_assert!((p.normal().length() - 1.0).abs() < 1e-12);
        }
        if let Ok(p) = Plane::through_points(a, b, c) {
            prop_assert!(finite(&p.dual_vector.to_array()));
            prop_assert!((p.normal().length() - 1.0).abs() < 1e-12);
        }
        if let Ok(l) = Line::through_points(a, b) {
            prop_assert!(finite(&l.direct.to_array()));
        }
        if let Ok(l) = Line::from_point_direction(a, b) {
            prop_assert!(finite(&l.direct.to_array()));
        }
        if let Ok(ci) = Circle::through_points(a, b, c) {
            prop_assert!(finite(&ci.direct.to_array()));
        }
        if let Ok(pp) = PointPair::from_points(a, b) {
            prop_assert!(finite(&pp.direct.to_array()));
        }
    }

    #[test]
    fn matrices(c in prop::collection::vec(hostile(), 12), pick in 0..3usize) {
        let mut a = [0.0; 12];
        a.copy_from_slice(&c);
        // Mix hostile entries into a real rotation so that some inputs are near-valid.
        let base = DAffine3::from_rotation_translation(DQuat::from_rotation_y(0.7), DVec3::new(1.0, 2.0, 3.0));
        let mut m = base.to_cols_array();
        match pick {
            0 => m = a,
            1 => m[9 + (c[0].to_bits() % 3) as usize] = c[1],
            _ => m[(c[0].to_bits() % 9) as usize] = c[1],
        }
        let affine = DAffine3::from_cols_array(&m);
        if let Ok(x) = Motor::try_from_affine(affine) {
            assert_unit_motor(x, 1e-12);
        }
        let mat = DMat4::from(affine);
        if let Ok(x) = Motor::try_from_mat4(mat) {
            assert_unit_motor(x, 1e-12);
        }
        if let Ok(x) = ScaledMotor::try_from_mat4(mat) {
            prop_assert!(finite(&x.to_array()));
            prop_assert!(x.scale().is_finite() && x.scale() > 0.0);
        }
    }
}

/// The generated predicates, as glam's: `is_finite` (no infinity, no NaN), `is_nan` (any
/// NaN), `abs_diff_eq` (every stored coefficient within the bound; false with a NaN), in f64
/// and f32, agreeing with the coefficient arrays.
#[test]
fn generated_predicates_match_the_coefficients() {
    let m =
        Motor::from_rotation_translation(DQuat::from_rotation_y(0.4), DVec3::new(1.0, -2.0, 0.5));
    assert!(m.is_finite() && !m.is_nan());
    assert!(m.abs_diff_eq(m, 0.0));
    for i in 0..Motor::LEN {
        for (bad, nan) in [
            (f64::NAN, true),
            (f64::INFINITY, false),
            (-f64::INFINITY, false),
        ] {
            let mut c = m.to_array();
            c[i] = bad;
            let x = Motor::from_array(c);
            assert_eq!(x.is_finite(), finite(&c));
            assert_eq!(x.is_nan(), nan, "{x:?}");
            assert!(!x.is_finite());
            assert!(!x.abs_diff_eq(m, 1e300) && !m.abs_diff_eq(x, 1e300));
        }
        let mut c = m.to_array();
        c[i] += 1e-3;
        let near = Motor::from_array(c);
        assert!(near.abs_diff_eq(m, 1.001e-3) && m.abs_diff_eq(near, 1.001e-3));
        assert!(!near.abs_diff_eq(m, 0.999e-3));
    }
    // A point's constant `eo` is not stored, so only stored coefficients count.
    let p = Point::from_vec3(DVec3::new(3.0, 4.0, 0.0));
    assert!(p.is_finite() && p.abs_diff_eq(Point::from_vec3(DVec3::new(3.0, 4.0, 1e-9)), 1e-8));
    let p32 = cga::f32::Point::from_vec3(glam::Vec3::new(1e20, 0.0, 0.0));
    assert!(
        !p32.is_finite() && !p32.is_nan(),
        "0.5 |x|^2 overflows f32: {p32:?}"
    );
    let r32 = cga::f32::Rotor::from_array([f32::NAN, 0.0, 0.0, 0.0]);
    assert!(r32.is_nan() && !r32.is_finite() && !r32.abs_diff_eq(r32, f32::MAX));
}
