//! The closed forms the generator emits for G(4,1) (`Exp`, `Log`, `EvenVersor`, issue 26)
//! against the hand-written ones of this crate (`Bivector::exp_motor`, `Motor::log`,
//! `ScaledMotor::exp`, `ScaledMotor::log`), in f64 and f32, on random rigid and scaled
//! generators.

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
                fn rigid_motors_agree(c in prop::array::uniform6(-2.0f64..2.0)) {
                    let mut b = Bivector::default();
                    (b.e12, b.e13, b.e23) = (c[0] as $s, c[1] as $s, c[2] as $s);
                    (b.e1i, b.e2i, b.e3i) = (c[3] as $s, c[4] as $s, c[5] as $s);
                    let hand = b.exp_motor();
                    let generated: Motor = Exp::exp(b);
                    prop_assert!(close(&f64s(generated.to_array()), &f64s(hand.to_array()), $tol), "exp {generated:?} vs {hand:?}");
                    let (lh, lg) = (hand.log(), Log::log(hand));
                    prop_assert!(close(&f64s(lg.to_array()), &f64s(lh.to_array()), $tol), "log {lg:?} vs {lh:?}");
                    // The generated normalisation agrees with the hand-written one on a drifted motor.
                    let mut drift = hand;
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
