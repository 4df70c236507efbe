//! The logarithm of any finite multiple `k V` of a (scaled) motor `V`, from `k = 1e300` down to
//! the subnormals, in `f64` and `f32`: either it is the logarithm of `V` (the scalar factor has
//! no bivector part) and `exp` of it gives back `V`'s motion, as precisely as `k V` holds `V`
//! (to the smallest subnormal over `k`), or the call refuses with `CgaError::Overflow` (or
//! `NonFinite` where `k V` itself overflowed the scalar type). Never
//! a wrong `Ok`: at `k = 1e-45` in `f32` the coefficients of `k V` are a few subnormal steps
//! and no longer hold the motion of `V`.

use proptest::prelude::*;

/// `10^e` with a sign, `e` spread over the whole finite range, subnormals included.
fn factor(max_exp: f64, min_exp: f64) -> impl Strategy<Value = f64> {
    (min_exp..max_exp, any::<bool>()).prop_map(|(e, neg)| {
        let k = 10f64.powf(e);
        if neg {
            -k
        } else {
            k
        }
    })
}

/// The largest difference of two coefficient arrays.
fn max_diff<T: Copy + Into<f64>>(a: &[T], b: &[T]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0, |m, (&p, &q)| m.max((p.into() - q.into()).abs()))
}

macro_rules! multiples {
    ($name:ident, $m:path, $S:ty, $V3:ty, $Q:ty, $exps:expr, $tol:expr) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(3000))]
            #[test]
            fn $name(
                angle in -3.1..3.1f64,
                axis in (-1.0..1.0f64, -1.0..1.0f64, 0.1..1.0f64),
                t in (-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64),
                d in 0.2..5.0f64,
                k in factor($exps.0, $exps.1),
            ) {
                use $m as c;
                let axis = <$V3>::new(axis.0 as $S, axis.1 as $S, axis.2 as $S).normalize();
                let q = <$Q>::from_axis_angle(axis, angle as $S);
                let t = <$V3>::new(t.0 as $S, t.1 as $S, t.2 as $S);
                let k = k as $S;
                // What `k V` can hold of `V`: the smallest subnormal relative to `k`.
                let tol = $tol + 20.0 * (<$S>::from_bits(1) / k.abs()) as f64;
                let m = c::Motor::from_rotation_translation(q, t);
                let km = m * k;
                // `k V` itself overflowed the scalar type: that input is not finite.
                let finite_m = km.to_array().iter().all(|x| x.is_finite());
                match km.try_log() {
                    Ok(b) => {
                        let diff = max_diff(&b.to_array(), &m.log().to_array());
                        prop_assert!(diff < tol, "k {k:e}: log(kM) off log(M) by {diff:e}");
                        let e = b.exp_motor();
                        let diff = max_diff(&e.to_mat4().to_cols_array(), &m.to_mat4().to_cols_array());
                        prop_assert!(diff < tol, "k {k:e}: exp(log(kM)) off M by {diff:e}");
                    }
                    Err(e) => prop_assert!(
                        (matches!(e, cga::CgaError::NonFinite { .. }) && !finite_m) ||
                        matches!(e, cga::CgaError::Overflow { .. }) && k.abs() <= 1e-30 as $S,
                        "k {k:e}: {e}"
                    ),
                }
                let s = c::ScaledMotor::from_scale_rotation_translation(d as $S, q, t);
                let ks = s * k;
                // `k V` itself overflowed the scalar type: that input is not finite.
                let finite_s = ks.to_array().iter().all(|x| x.is_finite());
                match ks.try_log() {
                    Ok(b) => {
                        let diff = max_diff(&b.to_array(), &s.log().to_array());
                        prop_assert!(diff < tol, "k {k:e}: log(kS) off log(S) by {diff:e}");
                        let (d2, q2, t2) = b.exp_scaled().to_scale_rotation_translation();
                        let diff = ((d2 / d as $S - 1.0) as f64).abs()
                            .max(((q2.dot(q).abs() - 1.0) as f64).abs())
                            .max((t2 - t).length() as f64);
                        prop_assert!(diff < tol, "k {k:e}: exp(log(kS)) off S by {diff:e}");
                    }
                    Err(e) => prop_assert!(
                        (matches!(e, cga::CgaError::NonFinite { .. }) && !finite_s) ||
                        matches!(e, cga::CgaError::Overflow { .. }) && k.abs() <= 1e-30 as $S,
                        "k {k:e}: {e}"
                    ),
                }
            }
        }
    };
}

multiples!(
    f64_multiples,
    cga,
    f64,
    glam::DVec3,
    glam::DQuat,
    (300.0, -323.5),
    1e-9
);
multiples!(
    f32_multiples,
    cga::f32,
    f32,
    glam::Vec3,
    glam::Quat,
    (38.0, -45.0),
    2e-3
);

#[test]
fn the_smallest_multiples_are_refused_not_misread() {
    use glam::{Quat, Vec3};
    let m = cga::f32::Motor::from_rotation_translation(Quat::from_rotation_y(0.8), Vec3::X);
    let tiny = m * 1e-45;
    assert!(matches!(
        tiny.try_log(),
        Err(cga::CgaError::Overflow { .. })
    ));
    assert!(matches!(
        tiny.try_normalize_rigid(),
        Err(cga::CgaError::Overflow { .. })
    ));
    let s = cga::f32::ScaledMotor::from_scale_rotation_translation(
        2.0,
        Quat::from_rotation_y(0.8),
        Vec3::X,
    );
    assert!(matches!(
        (s * 1e-45).try_log(),
        Err(cga::CgaError::Overflow { .. })
    ));
    let m64 =
        cga::Motor::from_rotation_translation(glam::DQuat::from_rotation_y(0.8), glam::DVec3::X);
    assert!(matches!(
        (m64 * 5e-324).try_log(),
        Err(cga::CgaError::Overflow { .. })
    ));
    // A few hundred subnormal steps are too few too; far above them the motion is kept.
    assert!((m64 * 1e-321).try_log().is_err());
    let b = (m64 * 1e-310).try_log().unwrap();
    assert!(max_diff(&b.to_array(), &m64.log().to_array()) < 1e-9);
}
