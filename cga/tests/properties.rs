//! Property tests: versor identities, composition against glam matrices, exp/log round trips,
//! blends, dilations, objects, and the error paths.

use cga::{
    Bivector, CgaError, Dilator, DualQuat, Motor, Point, Rotor, Sandwich, ScaledMotor, Translator,
};
use glam::{DAffine3, DMat4, DQuat, DVec3};
use proptest::prelude::*;
use std::f64::consts::PI;

fn v3() -> impl Strategy<Value = DVec3> {
    (-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn unit_axis() -> impl Strategy<Value = DVec3> {
    v3().prop_filter("non-zero", |v| v.length() > 1e-3)
        .prop_map(|v| v.normalize())
}

fn quat() -> impl Strategy<Value = DQuat> {
    (unit_axis(), -PI..PI).prop_map(|(a, t)| DQuat::from_axis_angle(a, t))
}

fn motor() -> impl Strategy<Value = (DQuat, DVec3, Motor)> {
    (quat(), v3()).prop_map(|(q, t)| (q, t, Motor::from_rotation_translation(q, t)))
}

/// `M ~M - 1` over all eight coefficients.
fn unit_defect(m: Motor) -> f64 {
    let p = m * m.rev();
    let mut c = p.to_array();
    c[0] -= 1.0;
    c.iter().fold(0.0, |a: f64, x| a.max(x.abs()))
}

/// Largest difference between motors up to sign.
fn motor_diff(a: Motor, b: Motor) -> f64 {
    let d = |x: Motor, y: Motor| {
        x.to_array()
            .iter()
            .zip(y.to_array())
            .fold(0.0, |m: f64, (p, q)| m.max((p - q).abs()))
    };
    d(a, b).min(d(a, -b))
}

fn bivector_diff(a: Bivector, b: Bivector) -> f64 {
    a.to_array()
        .iter()
        .zip(b.to_array())
        .fold(0.0, |m: f64, (p, q)| m.max((p - q).abs()))
}

fn mat_diff(a: DMat4, b: DMat4) -> f64 {
    (a - b)
        .abs()
        .to_cols_array()
        .iter()
        .fold(0.0, |m: f64, x| m.max(*x))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn motors_are_unit((_q, _t, m) in motor(), (_q2, _t2, m2) in motor()) {
        prop_assert!(unit_defect(m) < 1e-14);
        prop_assert!(unit_defect(m * m2) < 1e-13);
        prop_assert!(m.versor_defect().abs() < 1e-14);
    }

    #[test]
    fn composition_matches_matrices((q, t, m) in motor(), (q2, t2, m2) in motor(), x in v3()) {
        let a = DMat4::from_rotation_translation(q, t);
        let b = DMat4::from_rotation_translation(q2, t2);
        prop_assert!(mat_diff((m2 * m).to_mat4(), b * a) < 1e-12);
        prop_assert!(((m2 * m).transform_point(x) - (b * a).transform_point3(x)).length() < 1e-12);
        prop_assert!((m.then(m2).transform_point(x) - m2.transform_point(m.transform_point(x))).length() < 1e-12);
    }

    #[test]
    fn glam_agreement((q, t, m) in motor(), xs in prop::collection::vec(v3(), 1..20)) {
        let mat = DMat4::from_rotation_translation(q, t);
        let aff = DAffine3::from_rotation_translation(q, t);
        let dq = DualQuat::from(m);
        let mut out = vec![DVec3::ZERO; xs.len()];
        m.transform_points(&xs, &mut out);
        for (x, y) in xs.iter().zip(&out) {
            let e = mat.transform_point3(*x);
            prop_assert!((m.transform_point(*x) - e).length() < 1e-12);
            prop_assert!((*y - e).length() < 1e-12);
            prop_assert!((aff.transform_point3(*x) - e).length() < 1e-12);
            prop_assert!((dq.transform_point(*x) - e).length() < 1e-12);
            prop_assert!((m.transform_vector(*x) - q * *x).length() < 1e-12);
        }
        // Round trips through glam types.
        prop_assert!(motor_diff(Motor::try_from(mat).unwrap(), m) < 1e-12);
        prop_assert!(motor_diff(Motor::try_from(aff).unwrap(), m) < 1e-12);
        prop_assert!(motor_diff(Motor::from(dq), m) == 0.0);
        let (q2, t2) = m.to_rotation_translation();
        prop_assert!(q2.abs_diff_eq(q, 1e-14) && (t2 - t).length() < 1e-12);
        prop_assert!(mat_diff(m.to_mat4(), mat) < 1e-12);
        // Dual quaternion product = motor product.
        let (_, _, m2) = (q, t, Motor::from_rotation_translation(q.inverse(), -t));
        prop_assert!(motor_diff(Motor::from(DualQuat::from(m2) * dq), m2 * m) < 1e-13);
    }

    #[test]
    fn exp_log_round_trip(axis in unit_axis(), angle in 0.0..(PI - 1e-6), v in v3()) {
        let b = Bivector::rotation_generator(axis, angle) + Bivector::translation_generator(v);
        let m = b.exp_motor();
        prop_assert!(unit_defect(m) < 1e-13);
        prop_assert!(bivector_diff(m.log(), b) < 1e-12);
        prop_assert!(motor_diff(m.log().exp_motor(), m) < 1e-13);
    }

    #[test]
    fn exp_matches_generic_series(axis in unit_axis(), angle in -3.0..3.0f64, v in v3(), l in -1.0..1.0f64) {
        let b = Bivector::rotation_generator(axis, angle) + Bivector::translation_generator(v);
        let reference = b.to_multivector().exp();
        prop_assert!(b.exp_motor().to_multivector().max_diff(&reference) < 1e-11 * reference.max_abs().max(1.0));
        let mut bs = b;
        bs.eoi = l;
        let reference = bs.to_multivector().exp();
        prop_assert!(bs.exp_scaled().to_multivector().max_diff(&reference) < 1e-11 * reference.max_abs().max(1.0));
    }

    #[test]
    fn log_of_any_motor((_q, _t, m) in motor()) {
        // Both signs of M are the same motion and must give the same principal log.
        let l = m.try_log().unwrap();
        prop_assert!(motor_diff(l.exp_motor(), m) < 1e-12);
        prop_assert!(bivector_diff((-m).log(), l) < 1e-12);
    }

    #[test]
    fn scaled_round_trip(q in quat(), t in v3(), s in 0.05..20.0f64, x in v3(), y in v3()) {
        let sm = ScaledMotor::try_from_scale_rotation_translation(s, q, t).unwrap();
        let expect = |p: DVec3| s * (q * p) + t;
        prop_assert!((sm.transform_point(x) - expect(x)).length() < 1e-11 * s.max(1.0));
        // Distances scale by the factor.
        let d0 = x.distance(y);
        let d1 = sm.transform_point(x).distance(sm.transform_point(y));
        prop_assert!((d1 - s * d0).abs() < 1e-11 * s.max(1.0) * d0.max(1.0));
        let (s2, q2, t2) = sm.to_scale_rotation_translation();
        prop_assert!((s2 - s).abs() < 1e-12 * s && (q2.dot(q).abs() - 1.0).abs() < 1e-12 && (t2 - t).length() < 1e-11);
        let l = sm.try_log().unwrap();
        let back = l.exp_scaled();
        prop_assert!((back.transform_point(x) - expect(x)).length() < 1e-10 * s.max(1.0));
        prop_assert!((l.eoi - 0.5 * s.ln()).abs() < 1e-12);
        let mut out = [DVec3::ZERO; 1];
        sm.transform_points(&[x], &mut out);
        prop_assert!((out[0] - expect(x)).length() < 1e-11 * s.max(1.0));
    }

    #[test]
    fn dilation_scales_distances(s in 0.01..100.0f64, x in v3(), y in v3()) {
        let d = Dilator::try_from_scale(s).unwrap();
        let px = d.transform_point(x);
        prop_assert!((px - s * x).length() < 1e-12 * s.max(1.0) * x.length().max(1.0));
        let (dx, dy) = (d.sandwich(Point::from_vec3(x)).try_to_point().unwrap(), d.sandwich(Point::from_vec3(y)).try_to_point().unwrap());
        prop_assert!((dx.distance(dy) - s * x.distance(y)).abs() < 1e-10 * s.max(1.0) * x.distance(y).max(1.0));
    }

    #[test]
    fn blends_partition_of_unity((_q, _t, m) in motor(), (_q2, _t2, m2) in motor(), w in prop::collection::vec(0.0..1.0f64, 1..6)) {
        let sum: f64 = w.iter().sum();
        prop_assume!(sum > 1e-3);
        let w: Vec<f64> = w.iter().map(|x| x / sum).collect();
        // Equal motors (with random signs) and weights summing to 1 give that motor.
        let ms: Vec<Motor> = (0..w.len()).map(|i| if i % 2 == 0 { m } else { -m }).collect();
        prop_assert!(motor_diff(Motor::try_blend_linear(&ms, &w).unwrap(), m) < 1e-13);
        prop_assert!(motor_diff(Motor::try_blend_log(&ms, &w).unwrap(), m) < 1e-12);
        // Exact at the keys.
        let keys = [m, m2];
        prop_assert!(motor_diff(Motor::blend_linear(&keys, &[1.0, 0.0]), m) < 1e-14);
        prop_assert!(motor_diff(Motor::blend_log(&keys, &[0.0, 1.0]), m2) < 1e-12);
        prop_assert!(motor_diff(Motor::interpolate(m, m2, 0.0), m) < 1e-12);
        prop_assert!(motor_diff(Motor::interpolate(m, m2, 1.0), m2) < 1e-12);
        // Blends stay unit motors.
        prop_assert!(unit_defect(Motor::blend_linear(&keys, &[0.3, 0.7])) < 1e-13);
        prop_assert!(unit_defect(Motor::interpolate(m, m2, 0.37)) < 1e-13);
    }

    #[test]
    fn interpolation_is_smooth((_q, _t, m) in motor(), (_q2, _t2, m2) in motor(), x in v3()) {
        // Constant-speed screw: equal parameter steps move a point continuously, and the
        // midpoint of a to b equals the midpoint of b to a.
        let mid = Motor::interpolate(m, m2, 0.5);
        let mid2 = Motor::interpolate(m2, m, 0.5);
        prop_assert!((mid.transform_point(x) - mid2.transform_point(x)).length() < 1e-9);
        let mut prev = m.transform_point(x);
        for i in 1..=50 {
            let p = Motor::interpolate(m, m2, i as f64 / 50.0).transform_point(x);
            prop_assert!((p - prev).length() < 0.2 * (1.0 + x.length() + 10.0));
            prev = p;
        }
    }

    #[test]
    fn objects_predicates(a in v3(), b in v3(), c in v3(), d in v3(), s in -3.0..3.0f64, t in -3.0..3.0f64) {
        if let Ok(plane) = cga::Plane::through_points(a, b, c) {
            // Points on the plane (and their affine combinations) are at distance zero.
            for p in [a, b, c, a + s * (b - a) + t * (c - a)] {
                prop_assert!(plane.signed_distance(p).abs() < 1e-10 * (1.0 + p.length()));
            }
            let n = plane.normal();
            prop_assert!((n.length() - 1.0).abs() < 1e-12);
            prop_assert!((plane.signed_distance(a + s * n) - s).abs() < 1e-10);
            prop_assert!(n.dot((b - a).cross(c - a)) > 0.0);
        }
        if let Ok(sphere) = cga::Sphere::through_points(a, b, c, d) {
            let r = sphere.radius();
            prop_assume!(r < 1e4);
            for p in [a, b, c, d] {
                prop_assert!(sphere.power(p).abs() < 1e-8 * (1.0 + r * r));
                prop_assert!(sphere.signed_distance(p).abs() < 1e-8 * (1.0 + r));
            }
            prop_assert!(sphere.contains(sphere.center()));
            prop_assert!(!sphere.contains(sphere.center() + DVec3::X * (r * 1.01 + 1e-9)));
        }
        // Distance via the inner product.
        let (pa, pb) = (Point::from_vec3(a), Point::from_vec3(b));
        prop_assert!((pa.distance(pb) - a.distance(b)).abs() < 1e-12 * (1.0 + a.length_squared() + b.length_squared()));
    }

    #[test]
    fn meets(a in v3(), b in v3(), c in v3(), p in v3(), u in unit_axis()) {
        let Ok(plane) = cga::Plane::through_points(a, b, c) else { return Ok(()) };
        let line = cga::Line::from_point_direction(p, u).unwrap();
        prop_assert!(line.distance_to_point(p) < 1e-12 * (1.0 + p.length()));
        prop_assert!(line.distance_to_point(p + 2.5 * u) < 1e-11 * (1.0 + p.length()));
        if plane.normal().dot(u).abs() > 1e-3 {
            let x = plane.meet_line(&line).unwrap().point();
            prop_assert!(plane.signed_distance(x).abs() < 1e-9 * (1.0 + x.length()));
            prop_assert!(line.distance_to_point(x) < 1e-9 * (1.0 + x.length()));
        }
        let (q, r) = (p, p + 3.0 * u);
        if let Some((s, x)) = plane.meet_segment(q, r) {
            prop_assert!((0.0..=1.0).contains(&s));
            prop_assert!(plane.signed_distance(x).abs() < 1e-10 * (1.0 + x.length()));
        } else {
            prop_assert!(plane.signed_distance(q) * plane.signed_distance(r) >= 0.0);
        }
        let other = cga::Plane::from_point_normal(p, u);
        if let Some(l) = plane.meet_plane(&other) {
            let x = l.closest_to_origin();
            prop_assert!(plane.signed_distance(x).abs() < 1e-8 * (1.0 + x.length()));
            prop_assert!(other.signed_distance(x).abs() < 1e-8 * (1.0 + x.length()));
            prop_assert!(l.direction().dot(u).abs() < 1e-9 * l.direction().length());
        }
    }
}

#[test]
fn special_exp_log_cases() {
    let axis = DVec3::new(1.0, -2.0, 0.5).normalize();
    let t = DVec3::new(0.3, 2.0, -1.0);
    // Pure translation: log(T) = -0.5 t ei.
    let m = Motor::from_translation(t);
    let l = m.try_log().unwrap();
    assert!(bivector_diff(l, Bivector::translation_generator(t)) < 1e-15);
    assert_eq!(Bivector::translation_generator(t).exp_motor(), m);
    // Zero.
    assert_eq!(Motor::IDENTITY.log(), Bivector::default());
    assert_eq!(Bivector::default().exp_motor(), Motor::IDENTITY);
    // Angles near and at pi, screws, tiny angles.
    for angle in [PI - 1e-9, PI, PI + 1e-9, 1e-9, 1e-300, 0.0, 2.0 * PI - 1e-7] {
        for pitch in [0.0, 1.5] {
            let m = Motor::from_rotation_translation(
                DQuat::from_axis_angle(axis, angle),
                t + pitch * axis,
            );
            let l = m.try_log().unwrap();
            assert!(
                motor_diff(l.exp_motor(), m) < 1e-12,
                "angle {angle} pitch {pitch}"
            );
            let x = DVec3::new(0.2, 0.1, -0.7);
            assert!((l.exp_motor().transform_point(x) - m.transform_point(x)).length() < 1e-12);
            let rot_angle = 2.0 * (l.e12 * l.e12 + l.e13 * l.e13 + l.e23 * l.e23).sqrt();
            assert!(rot_angle <= PI + 1e-12);
        }
    }
    // Scaled motors: pure dilation, d -> 1, rotation by pi with scale.
    for s in [1.0, 1.0 + 1e-12, 2.0, 0.25] {
        for angle in [0.0, 1e-10, 1.0, PI] {
            let q = DQuat::from_axis_angle(axis, angle);
            let sm = ScaledMotor::from_scale_rotation_translation(s, q, t);
            let l = sm.try_log().unwrap();
            let back = l.exp_scaled();
            let x = DVec3::new(0.2, 0.1, -0.7);
            let err = (back.transform_point(x) - sm.transform_point(x)).length();
            assert!(err < 1e-12, "s {s} angle {angle}: {err:e}");
        }
    }
    let d = ScaledMotor::from(Dilator::from_scale(3.0));
    let l = d.try_log().unwrap();
    assert!((l.eoi - 0.5 * 3f64.ln()).abs() < 1e-15 && l.e1i == 0.0 && l.e12 == 0.0);
}

#[test]
fn interpolate_screw_example() {
    // Half of a screw about z through (1, 0, 0): half the angle about the same axis.
    let axis_point = DVec3::X;
    let screw = |a: f64, h: f64| {
        Motor::from_translation(axis_point + DVec3::Z * h)
            * Motor::from_axis_angle(DVec3::Z, a)
            * Motor::from_translation(-axis_point)
    };
    let m = Motor::interpolate(Motor::IDENTITY, screw(2.0, 4.0), 0.25);
    assert!(motor_diff(m, screw(0.5, 1.0)) < 1e-14);
    let b = Motor::blend_log(&[Motor::IDENTITY, screw(2.0, 4.0)], &[0.75, 0.25]);
    assert!(motor_diff(b, screw(0.5, 1.0)) < 1e-14);
}

#[test]
fn linear_blend_takes_short_way() {
    let a = Motor::from_axis_angle(DVec3::Z, 3.0);
    let b = -Motor::from_axis_angle(DVec3::Z, -3.0); // same motion as rotating by 2pi - 3
    let mid = Motor::blend_linear(&[a, b], &[0.5, 0.5]);
    // Short way round from 3 rad to 2pi - 3 rad passes through pi.
    let y = mid.transform_point(DVec3::X);
    assert!((y - DVec3::new(-1.0, 0.0, 0.0)).length() < 1e-12, "{y}");
}

#[test]
fn objects_examples() {
    let s = cga::Sphere::try_new(DVec3::new(1.0, 2.0, 3.0), 2.0).unwrap();
    assert!((s.radius() - 2.0).abs() < 1e-15);
    assert!(s.contains(DVec3::new(1.0, 2.0, 4.9)) && !s.contains(DVec3::new(1.0, 2.0, 5.1)));
    let s4 = cga::Sphere::through_points(
        DVec3::new(3.0, 2.0, 3.0),
        DVec3::new(1.0, 4.0, 3.0),
        DVec3::new(1.0, 2.0, 5.0),
        DVec3::new(-1.0, 2.0, 3.0),
    )
    .unwrap();
    assert!((s4.center() - DVec3::new(1.0, 2.0, 3.0)).length() < 1e-14);
    assert!((s4.radius() - 2.0).abs() < 1e-14);
    // Line through the sphere's centre pierces it in two points at distance r.
    let line =
        cga::Line::through_points(DVec3::new(1.0, 2.0, 3.0), DVec3::new(2.0, 2.0, 3.0)).unwrap();
    let (p, q) = s.meet_line(&line).unwrap().points().unwrap();
    let mut xs = [p.x, q.x];
    xs.sort_by(f64::total_cmp);
    assert!(
        (xs[0] + 1.0).abs() < 1e-12 && (xs[1] - 3.0).abs() < 1e-12,
        "{p} {q}"
    );
    let far =
        cga::Line::through_points(DVec3::new(10.0, 2.0, 3.0), DVec3::new(10.0, 3.0, 3.0)).unwrap();
    assert!(s.meet_line(&far).is_none());
    // Circle through three points; its plane, centre and radius.
    let c = cga::Circle::through_points(
        DVec3::new(1.0, 0.0, 2.0),
        DVec3::new(0.0, 1.0, 2.0),
        DVec3::new(-1.0, 0.0, 2.0),
    )
    .unwrap();
    assert!((c.center() - DVec3::new(0.0, 0.0, 2.0)).length() < 1e-14);
    assert!((c.radius() - 1.0).abs() < 1e-14);
    assert!((c.plane().signed_distance(DVec3::new(5.0, 5.0, 2.0))).abs() < 1e-14);
    assert!(c.contains(DVec3::new(0.0, -1.0, 2.0)) && !c.contains(DVec3::new(0.0, -1.1, 2.0)));
    // Point pair and flat point.
    let pp = cga::PointPair::from_points(DVec3::X, DVec3::Y).unwrap();
    let (a, b) = pp.points().unwrap();
    assert!(
        ((a - DVec3::X).length() < 1e-14 && (b - DVec3::Y).length() < 1e-14)
            || ((a - DVec3::Y).length() < 1e-14 && (b - DVec3::X).length() < 1e-14)
    );
    assert!(
        (cga::FlatPoint::new(DVec3::new(1.0, -2.0, 3.0)).point() - DVec3::new(1.0, -2.0, 3.0))
            .length()
            < 1e-15
    );
    // Parallel and degenerate cases.
    let z0 = cga::Plane::from_normal_distance(DVec3::Z, 0.0);
    let z1 = cga::Plane::from_normal_distance(DVec3::Z, 1.0);
    assert!(z0.meet_plane(&z1).is_none());
    let flat = cga::Line::through_points(DVec3::ZERO, DVec3::X).unwrap();
    assert!(z1.meet_line(&flat).is_none());
    assert!(z0.meet_segment(DVec3::ZERO, DVec3::X).is_none());
    assert_eq!(
        z0.meet_segment(DVec3::ZERO, DVec3::Z),
        Some((0.0, DVec3::ZERO))
    );
    assert!(matches!(
        cga::Plane::through_points(DVec3::ZERO, DVec3::X, 2.0 * DVec3::X),
        Err(CgaError::Degenerate { .. })
    ));
    assert!(matches!(
        cga::Sphere::through_points(DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE.with_z(0.0)),
        Err(CgaError::Degenerate { .. })
    ));
    // Transforming objects.
    let m =
        Motor::from_rotation_translation(DQuat::from_rotation_x(0.7), DVec3::new(1.0, 2.0, 3.0));
    let moved = s.transformed(m);
    assert!((moved.center() - m.transform_point(s.center())).length() < 1e-14);
    let pl = z1.transformed(m);
    assert!(
        pl.signed_distance(m.transform_point(DVec3::new(4.0, -1.0, 1.0)))
            .abs()
            < 1e-14
    );
    let l2 = line.transformed(m);
    assert!(l2.distance_to_point(m.transform_point(DVec3::new(7.0, 2.0, 3.0))) < 1e-13);
}

#[test]
fn errors() {
    let nan = f64::NAN;
    assert!(matches!(
        Rotor::try_from_axis_angle(DVec3::ZERO, 1.0),
        Err(CgaError::ZeroAxis { .. })
    ));
    assert!(matches!(
        Rotor::try_from_axis_angle(DVec3::X, nan),
        Err(CgaError::NonFinite { .. })
    ));
    assert!(matches!(
        Rotor::try_from_axis_angle(DVec3::new(nan, 0.0, 1.0), 1.0),
        Err(CgaError::NonFinite { .. })
    ));
    assert_eq!(Rotor::from_axis_angle(DVec3::ZERO, 1.0), Rotor::IDENTITY);
    assert!(matches!(
        Translator::try_from_translation(DVec3::INFINITY),
        Err(CgaError::NonFinite { .. })
    ));
    for s in [0.0, -1.0, nan, f64::INFINITY] {
        assert!(
            matches!(Dilator::try_from_scale(s), Err(CgaError::NonPositiveScale)),
            "{s}"
        );
    }
    assert!(matches!(
        Motor::default().try_log(),
        Err(CgaError::NotAMotor { .. })
    ));
    let mut bad = Motor::from_translation(DVec3::X);
    bad.e123i = 0.5;
    assert!(matches!(bad.try_log(), Err(CgaError::NotAMotor { .. })));
    assert!(matches!(
        bad.try_normalize_rigid(),
        Err(CgaError::NotAMotor { .. })
    ));
    assert!(matches!(
        Motor::new(nan, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0).try_log(),
        Err(CgaError::NonFinite { .. })
    ));
    assert!(matches!(
        ScaledMotor::default().try_log(),
        Err(CgaError::NotAMotor { .. })
    ));
    let mut bad_s = ScaledMotor::from(Dilator::from_scale(2.0));
    bad_s.eo12i = 0.3;
    assert!(matches!(bad_s.try_log(), Err(CgaError::NotAMotor { .. })));
    let mut b = Bivector::translation_generator(DVec3::X);
    b.eo1 = 1.0;
    assert!(matches!(
        b.try_exp_motor(),
        Err(CgaError::NotAGenerator { .. })
    ));
    assert!(matches!(
        Motor::try_blend_log(&[], &[]),
        Err(CgaError::BadBlend { .. })
    ));
    assert!(matches!(
        Motor::try_blend_linear(&[Motor::IDENTITY], &[1.0, 2.0]),
        Err(CgaError::BadBlend { .. })
    ));
    assert!(matches!(
        Motor::try_blend_linear(&[Motor::IDENTITY, -Motor::IDENTITY], &[1.0, -1.0]),
        Err(CgaError::NotAMotor { .. })
    ));
    // Non-rigid matrices.
    let scale = DMat4::from_scale(DVec3::new(1.0, 2.0, 1.0));
    assert!(matches!(
        Motor::try_from(scale),
        Err(CgaError::NotRigid { .. })
    ));
    let mirror = DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0));
    assert!(matches!(
        Motor::try_from(mirror),
        Err(CgaError::NotRigid { .. })
    ));
    let mut proj = DMat4::IDENTITY;
    proj.x_axis.w = 0.1;
    assert!(matches!(
        Motor::try_from(proj),
        Err(CgaError::NotRigid { .. })
    ));
    let shear =
        DAffine3::from_cols_array(&[1.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    assert!(matches!(
        Motor::try_from(shear),
        Err(CgaError::NotRigid { .. })
    ));
    let us = DMat4::from_scale_rotation_translation(
        DVec3::splat(2.5),
        DQuat::from_rotation_y(1.0),
        DVec3::X,
    );
    let sm = ScaledMotor::try_from(us).unwrap();
    assert!(mat_diff(sm.to_mat4(), us) < 1e-12);
    assert!(matches!(
        ScaledMotor::try_from(scale),
        Err(CgaError::NotRigid { .. })
    ));
    assert!(matches!(
        Point::try_from_vec3(DVec3::NAN),
        Err(CgaError::NonFinite { .. })
    ));
    assert!(cga::Vector::new(0.0, 1.0, 0.0, 0.0, 0.0)
        .try_to_point()
        .is_err());
    let mut out = [DVec3::ZERO; 2];
    assert!(Motor::IDENTITY
        .try_transform_points(&[DVec3::X], &mut out)
        .is_err());
}

#[test]
fn normalize_rigid_repairs_drift() {
    let m =
        Motor::from_rotation_translation(DQuat::from_rotation_y(0.4), DVec3::new(1.0, -2.0, 0.5));
    let mut drifted = m * 1.3;
    drifted.e2i += 1e-7;
    let n = drifted.try_normalize_rigid().unwrap();
    assert!(unit_defect(n) < 1e-15);
    assert!(motor_diff(n, m) < 1e-6);
}

#[test]
fn f32_twins() {
    use glam::{Mat4, Quat, Vec3};
    let q = Quat::from_rotation_z(0.5);
    let t = Vec3::new(1.0, 2.0, 3.0);
    let m = cga::f32::Motor::from_rotation_translation(q, t);
    let x = Vec3::new(0.3, -0.2, 1.0);
    let e = Mat4::from_rotation_translation(q, t).transform_point3(x);
    assert!((m.transform_point(x) - e).length() < 1e-5);
    let l = m.try_log().unwrap();
    assert!((l.exp_motor().transform_point(x) - e).length() < 1e-5);
    let back = cga::f32::Motor::try_from(Mat4::from(m)).unwrap();
    assert!((back.transform_point(x) - e).length() < 1e-5);
    let aff = glam::Affine3A::from_rotation_translation(q, t);
    assert!((cga::f32::Motor::try_from(aff).unwrap().transform_point(x) - e).length() < 1e-5);
    let dq = cga::f32::DualQuat::from(m);
    assert!((dq.transform_point(x) - e).length() < 1e-5);
    let s = cga::f32::ScaledMotor::from_scale_rotation_translation(2.0, q, t);
    assert!((s.transform_point(x) - (2.0 * (q * x) + t)).length() < 1e-5);
    let p = cga::f32::Plane::through_points(Vec3::ZERO, Vec3::X, Vec3::Y).unwrap();
    assert!((p.signed_distance(Vec3::Z) - 1.0).abs() < 1e-6);
}

proptest! {
    /// The quaternion form of `exp(B)` moves points as the scaled motor's sandwich does, and
    /// `ScaledMotor::to_similarity` inverts the composition.
    #[test]
    fn exp_similarity_is_the_action_of_exp_scaled(axis in unit_axis(), angle in -3.0..3.0f64, v in v3(), l in -1.5..1.5f64, x in v3()) {
        let mut b = Bivector::rotation_generator(axis, angle) + Bivector::translation_generator(v);
        b.eoi = l;
        let s = b.exp_scaled();
        let sim = b.exp_similarity();
        prop_assert!((sim.transform_point(x) - s.transform_point(x)).length() < 1e-12 * (1.0 + x.length()) * (1.0 + v.length()));
        prop_assert!((sim.scale - (2.0 * l).exp()).abs() < 1e-13 * sim.scale);
        let back = s.to_similarity();
        prop_assert!((back.transform_point(x) - sim.transform_point(x)).length() < 1e-11 * (1.0 + x.length()) * (1.0 + v.length()));
        b.eoi = 0.0;
        let m = b.exp_motor();
        prop_assert!((b.exp_similarity().transform_point(x) - m.transform_point(x)).length() < 1e-12 * (1.0 + x.length()) * (1.0 + v.length()));
    }
}

proptest! {
    /// Dividing a blended motor by its rotor norm only moves points exactly as the full
    /// renormalisation does, although the sum keeps its `e123i` defect.
    #[test]
    fn normalize_for_points_acts_like_normalize_rigid(
        (_q, _t, a) in motor(), (_q2, _t2, b) in motor(), (_q3, _t3, c) in motor(),
        w in (0.05..1.0f64, 0.05..1.0f64, 0.05..1.0f64), x in v3(),
    ) {
        let sum = a * w.0 + b * w.1 + c * w.2;
        prop_assume!(sum.norm_squared() > 1e-3);
        let exact = sum.normalize_rigid();
        let cheap = sum.normalize_for_points();
        // The rotor part is the same; only the defect differs.
        prop_assert!(unit_defect(exact) < 1e-12);
        prop_assert!((cheap.norm_squared() - 1.0).abs() < 1e-12);
        let scale = 1.0 + x.length() + 15.0;
        prop_assert!((cheap.transform_point(x) - exact.transform_point(x)).length() < 1e-12 * scale);
    }
}

/// The test above is not vacuous: a blend of motors with different rotations has a defect,
/// which `normalize_for_points` keeps and `normalize_rigid` removes.
#[test]
fn blended_motors_have_a_defect() {
    let a =
        Motor::from_rotation_translation(DQuat::from_rotation_y(0.2), DVec3::new(1.0, 0.0, 0.0));
    let b =
        Motor::from_rotation_translation(DQuat::from_rotation_x(1.1), DVec3::new(0.0, 3.0, -1.0));
    let sum = a * 0.5 + b * 0.5;
    let cheap = sum.normalize_for_points();
    assert!(
        cheap.versor_defect().abs() > 1e-3,
        "{}",
        cheap.versor_defect()
    );
    assert!(sum.normalize_rigid().versor_defect().abs() < 1e-15);
    let x = DVec3::new(0.3, -2.0, 1.5);
    let d = cheap.transform_point(x) - sum.normalize_rigid().transform_point(x);
    assert!(d.length() < 1e-14, "{d}");
}

proptest! {
    /// `ScaledMotor::origin_weight` is the `eo` entry of the point matrix of a unit scaled
    /// motor (`1/d` for a scale `d`), and `k^2` times that for `k` times it.
    #[test]
    fn origin_weight_is_the_point_matrix_eo_entry(
        (q, t, _) in motor(),
        log_scale in -3.0..3.0f64,
        k in 0.2..5.0f64,
    ) {
        let d = log_scale.exp();
        let m = ScaledMotor::from_scale_rotation_translation(d, q, t);
        prop_assert!((m.origin_weight() * d - 1.0).abs() < 1e-13);
        let expanded = m.point_matrix().rows()[0][4];
        prop_assert!((m.origin_weight() - expanded).abs() < 1e-12 * expanded.abs());
        let multiple = (m * k).origin_weight();
        prop_assert!((multiple - k * k * m.origin_weight()).abs() < 1e-13 * multiple);
    }
}
