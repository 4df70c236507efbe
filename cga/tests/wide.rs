//! The generated wide twins (`cga::wide`, `cga::f32::wide`) against the scalar types and the
//! generic multivector: every lane of a wide product or sandwich is the scalar result, bit for
//! bit (the same expressions), and the scalar result is the multivector's `V X ~V`.

use cga::wide::{F64x4, Lane};
use cga::{Bivector, Motor, Point, Rotor, Sandwich, ScaledMotor, Translator, Vector};
use glam::{DQuat, DVec3};
use proptest::prelude::*;

fn v3() -> impl Strategy<Value = DVec3> {
    (-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn quat() -> impl Strategy<Value = DQuat> {
    (v3(), -3.2..3.2f64).prop_map(|(a, t)| {
        let a = if a.length() < 1e-3 {
            DVec3::X
        } else {
            a.normalize()
        };
        DQuat::from_axis_angle(a, t)
    })
}

fn motor() -> impl Strategy<Value = Motor> {
    (quat(), v3()).prop_map(|(q, t)| Motor::from_rotation_translation(q, t))
}

fn scaled() -> impl Strategy<Value = ScaledMotor> {
    (quat(), v3(), -1.5..1.5f64)
        .prop_map(|(q, t, g)| ScaledMotor::from_scale_rotation_translation(g.exp(), q, t))
}

fn points() -> impl Strategy<Value = [Point; 4]> {
    [v3(), v3(), v3(), v3()].prop_map(|p| p.map(Point::from_vec3))
}

/// Largest coefficient of `a - b` relative to the larger of the two.
fn rel(a: &ga_codegen::Multivector, b: &ga_codegen::Multivector) -> f64 {
    (a - b).max_abs() / a.max_abs().max(b.max_abs()).max(1.0)
}

/// Largest coefficient difference.
fn off(a: Motor, b: Motor) -> f64 {
    a.to_array()
        .iter()
        .zip(b.to_array())
        .fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn sandwiches_lane_by_lane(
        ms in [motor(), motor(), motor(), motor()],
        ss in [scaled(), scaled(), scaled(), scaled()],
        ps in points(),
    ) {
        let wp = cga::wide::Point::<F64x4>::gather(&ps);
        let wm = cga::wide::Motor::<F64x4>::gather(&ms);
        let ws = cga::wide::ScaledMotor::<F64x4>::gather(&ss);
        let rs: Vec<Rotor> = ms.iter().map(|m| m.rotor()).collect();
        let wr = cga::wide::Rotor::<F64x4>::gather(&rs);
        let (om, os, or) = (wm.sandwich(wp), ws.sandwich(wp), wr.sandwich(wp));
        for i in 0..4 {
            prop_assert_eq!(om.lane(i), ms[i].sandwich(ps[i]));
            prop_assert_eq!(os.lane(i), ss[i].sandwich(ps[i]));
            prop_assert_eq!(or.lane(i), rs[i].sandwich(ps[i]));
            // One lane (`W = f64`) is the scalar type's result too.
            let one = cga::wide::Motor::<f64>::gather(&ms[i..]).sandwich(cga::wide::Point::<f64>::gather(&ps[i..]));
            prop_assert_eq!(one.lane(0), ms[i].sandwich(ps[i]));
            // And the generic algebra agrees: V X ~V.
            let (v, x) = (ss[i].to_multivector(), ps[i].to_multivector());
            let want = &(&v * &x) * &v.rev();
            prop_assert!(rel(&os.lane(i).to_multivector(), &want) < 1e-12);
            let v = ms[i].to_multivector();
            let want = &(&v * &x) * &v.rev();
            prop_assert!(rel(&om.lane(i).to_multivector(), &want) < 1e-12);
        }
    }

    #[test]
    fn products_sums_and_reverses_lane_by_lane(
        a in [motor(), motor(), motor(), motor()],
        b in [motor(), motor(), motor(), motor()],
        w in [-2.0..2.0f64, -2.0..2.0, -2.0..2.0, -2.0..2.0],
        t in v3(),
    ) {
        let (wa, wb) = (cga::wide::Motor::<F64x4>::gather(&a), cga::wide::Motor::<F64x4>::gather(&b));
        let ww = F64x4(w);
        let wt = cga::wide::Translator::<F64x4>::splat(Translator::from_translation(t));
        let (p, s, d, r, k, mt) = (wa * wb, wa + wb, wa - wb, wa.rev(), wa.scale(ww), wt * wa);
        for i in 0..4 {
            // The scalar product is written in paired-lane form (`F64x2`), grouped differently.
            prop_assert!(off(p.lane(i), a[i] * b[i]) < 1e-14);
            prop_assert_eq!(s.lane(i), a[i] + b[i]);
            prop_assert_eq!(d.lane(i), a[i] - b[i]);
            prop_assert_eq!(r.lane(i), a[i].rev());
            prop_assert_eq!(k.lane(i), a[i] * w[i]);
            prop_assert!(off(mt.lane(i), Translator::from_translation(t) * a[i]) < 1e-14);
            let want = &a[i].to_multivector() * &b[i].to_multivector();
            prop_assert!(rel(&p.lane(i).to_multivector(), &want) < 1e-12);
        }
    }

    #[test]
    fn single_precision_twins_over_eight_lanes(ms in prop::array::uniform8(motor()), ps in prop::array::uniform8(v3())) {
        use cga::f32::wide::{F32x8, Motor as WMotor, Point as WPoint};
        use cga::f32::Sandwich as _;
        let ms32: Vec<cga::f32::Motor> = ms.iter().map(|m| cga::f32::Motor::from_array(m.to_array().map(|c| c as f32))).collect();
        let ps32: Vec<cga::f32::Point> = ps.iter().map(|p| cga::f32::Point::from_vec3(p.as_vec3())).collect();
        let out = WMotor::<F32x8>::gather(&ms32).sandwich(WPoint::<F32x8>::gather(&ps32));
        for i in 0..8 {
            let want = ms32[i].sandwich(ps32[i]);
            prop_assert_eq!(out.lane(i), want);
        }
    }
}

#[test]
fn the_wide_module_has_every_versor_and_what_it_acts_on() {
    // Compiles only if the twins exist with these products.
    let m = cga::wide::Motor::<F64x4>::splat(Motor::IDENTITY);
    let v: cga::wide::Vector<F64x4> = m.sandwich(cga::wide::Vector::splat(Vector::default()));
    let b: cga::wide::Bivector<F64x4> = m.sandwich(cga::wide::Bivector::splat(Bivector::default()));
    assert_eq!(v.lane(3), Vector::default());
    assert_eq!(b.lane(0), Bivector::default());
    assert_eq!(F64x4::LANES, 4);
}
