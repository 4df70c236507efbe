//! The closed forms the generator emits for G(4,1) (`Exp`, `Log`, `EvenVersor`, issue 26), in
//! f64 and f32: rigid motors against the generic multivector's series exponential
//! (`Bivector::exp_motor` and `Motor::log` are the generated forms since issue 47), scaled motors
//! against the hand-written closed forms of this crate (`ScaledMotor::exp`, `ScaledMotor::log`),
//! and f32 against f64.

use proptest::prelude::*;

/// `|a - b| <= tol (1 + |b|)` coefficientwise.
fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    let m = b.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).abs() <= tol * (1.0 + m))
}

macro_rules! agree {
    ($name:ident, $m:ident, $s:ty, $tol:expr) => {
        mod $name {
            use super::*;
            use cga::$m::{Bivector, EvenVersor, Exp, Log, Motor, ScaledMotor};

            fn f64s<const N: usize>(a: [$s; N]) -> Vec<f64> {
                a.iter().map(|&x| f64::from(x)).collect()
            }

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(256))]

                #[test]
                fn rigid_motors_agree_with_the_series(c in prop::array::uniform6(-2.0f64..2.0)) {
                    let mut b = Bivector::default();
                    (b.e12, b.e13, b.e23) = (c[0] as $s, c[1] as $s, c[2] as $s);
                    (b.e1i, b.e2i, b.e3i) = (c[3] as $s, c[4] as $s, c[5] as $s);
                    // `exp_motor` and `Motor::log` are the generated closed forms: the truth
                    // here is the generic multivector's series exponential.
                    let m = b.exp_motor();
                    let generated: Motor = Exp::exp(b);
                    prop_assert_eq!(m, generated);
                    let series = b.to_multivector().exp();
                    prop_assert!(close(m.to_multivector().coeffs(), series.coeffs(), $tol), "exp {m:?} vs the series {series:?}");
                    // exp(log M) = +-M (the series again), and the log is the generator when
                    // the rotation is under a half turn (|B_E| < pi/2).
                    let l = m.log();
                    let back = l.to_multivector().exp();
                    let sign = if back.coeffs()[0] * f64::from(m.s) < 0.0 { -1.0 } else { 1.0 };
                    prop_assert!(close(back.scale(sign).coeffs(), m.to_multivector().coeffs(), $tol), "exp(log) {back:?} vs {m:?}");
                    let angle = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
                    if angle < 1.5 {
                        prop_assert!(close(&f64s(l.to_array()), &f64s(b.to_array()), $tol), "log {l:?} vs {b:?}");
                    }
                    // A drifted motor's log is that of its normalisation, by either closed form.
                    let mut drift = m;
                    drift.e123i += 0.01;
                    drift.s *= 1.5;
                    let (nh, ng) = (drift.log(), Log::log(EvenVersor::normalize(drift)));
                    prop_assert!(close(&f64s(ng.to_array()), &f64s(nh.to_array()), $tol * 10.0), "log of normalised {ng:?} vs {nh:?}");
                }

                #[test]
                fn scaled_motors_agree(c in prop::array::uniform7(-1.5f64..1.5)) {
                    let mut b = Bivector::default();
                    (b.e12, b.e13, b.e23) = (c[0] as $s, c[1] as $s, c[2] as $s);
                    (b.e1i, b.e2i, b.e3i) = (c[3] as $s, c[4] as $s, c[5] as $s);
                    b.eoi = c[6] as $s;
                    let hand = ScaledMotor::exp(b);
                    let generated: ScaledMotor = Exp::exp(b);
                    prop_assert!(close(&f64s(generated.to_array()), &f64s(hand.to_array()), $tol), "exp {generated:?} vs {hand:?}");
                    let (lh, lg) = (hand.log(), Log::log(hand));
                    prop_assert!(close(&f64s(lg.to_array()), &f64s(lh.to_array()), $tol), "log {lg:?} vs {lh:?}");
                }
            }
        }
    };
}

agree!(f64_closed_forms, f64, f64, 1e-12);
agree!(f32_closed_forms, f32, f32, 1e-4);

/// The f32 closed forms evaluate their sine, cosine, arctangent and the series of a simple
/// exponential inline (`ga_codegen::runtime::trig`): on the same f32-exact generators they
/// agree with the f64 closed forms to a few f32 roundings (worst seen 3.1e-7 of `1 + |B|`
/// for exp, 1.9e-7 for log, over 2,000 cases each), on both sides of the series' range
/// (`|l| <= pi^2/4`, a rotation angle `2 sqrt(-l)` up to a half turn) and beyond the first
/// full turns, where the reduction by `pi/2` takes over.
mod f32_against_f64 {
    use c32::Exp as _;
    use c64::Exp as _;
    use cga::f32 as c32;
    use cga::f64 as c64;
    use cga::f64::Log;
    use proptest::prelude::*;

    /// The largest coefficient difference over `1 + |b|` (b the generator's largest).
    fn err(a: &[f32], b: &[f64], scale: f64) -> f64 {
        a.iter()
            .zip(b)
            .map(|(&x, &y)| (f64::from(x) - y).abs())
            .fold(0.0, f64::max)
            / (1.0 + scale)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]

        #[test]
        fn exp_and_log_agree_with_f64(
            axis in prop::array::uniform3(-1.0f64..1.0),
            angle in prop_oneof![0.0f64..1.6, 1.5f64..1.65, 0.0f64..40.0],
            t in prop::array::uniform3(-3.0f64..3.0),
        ) {
            let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
            prop_assume!(n > 1e-3);
            // Generator coefficients exact in f32, the same on both sides.
            let r: Vec<f32> = axis.iter().map(|a| (a / n * angle) as f32).collect();
            let tr: Vec<f32> = t.iter().map(|&x| x as f32).collect();
            let mut b32 = c32::Bivector::default();
            (b32.e12, b32.e13, b32.e23, b32.e1i, b32.e2i, b32.e3i) = (r[0], r[1], r[2], tr[0], tr[1], tr[2]);
            let mut b64 = c64::Bivector::default();
            (b64.e12, b64.e13, b64.e23) = (f64::from(r[0]), f64::from(r[1]), f64::from(r[2]));
            (b64.e1i, b64.e2i, b64.e3i) = (f64::from(tr[0]), f64::from(tr[1]), f64::from(tr[2]));
            let scale = b64.to_array().iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let (m32, m64): (c32::Motor, c64::Motor) = (b32.exp(), b64.exp());
            let e = err(&m32.to_array(), &m64.to_array(), scale);
            prop_assert!(e < 1e-6, "exp: {e:e} for angle {angle} ({m32:?} vs {m64:?})");
            // The log of the f32 motor, against the f64 log of the same f32 coefficients, away
            // from a half turn (|<M>_0| small), where the principal log's axis is ill-posed.
            prop_assume!(m32.s.abs() > 0.05);
            let mut w64 = c64::Motor::default();
            let a32 = m32.to_array();
            (w64.s, w64.e12, w64.e13, w64.e23) = (f64::from(a32[0]), f64::from(a32[1]), f64::from(a32[2]), f64::from(a32[3]));
            (w64.e1i, w64.e2i, w64.e3i, w64.e123i) = (f64::from(a32[4]), f64::from(a32[5]), f64::from(a32[6]), f64::from(a32[7]));
            let (l32, l64): (c32::Bivector, c64::Bivector) = (c32::Log::log(m32), Log::log(w64.normalize_rigid()));
            let e = err(&l32.to_array(), &l64.to_array(), scale);
            prop_assert!(e < 1e-6, "log: {e:e} for angle {angle} ({l32:?} vs {l64:?})");
        }
    }
}
