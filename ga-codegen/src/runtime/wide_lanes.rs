//! Lane types for the generated wide (structure-of-arrays) twins.
//!
//! A wide twin of a generated type (`wide::Motor<W>`, emitted with
//! [`crate::EmitOptions::wide`]) stores each field as a [`Lane`] value `W`: lane `i` of every
//! field belongs to operand `i`, so one call of a generated product or sandwich computes
//! [`Lane::LANES`] of them. `W = f64` (one lane) is the scalar form the tests compare with;
//! [`F64x4`] and [`F32x8`] are four and eight lanes.
//!
//! The lane types are plain arrays whose operations are lane-wise loops marked
//! `#[inline(always)]`: compiled inside a function with
//! `#[target_feature(enable = "avx2")]` they become 256-bit instructions, elsewhere SSE2
//! (part of the x86-64 baseline) or whatever the target has. Callers choose at run time
//! (`is_x86_feature_detected!`) which copy of their loop to call, so a binary stays portable.
//! No lane operation fuses a multiply and an add, so every copy gives the same bits as the
//! scalar expressions with the same grouping, on every CPU; the one exception is
//! [`Lane::mul_add`], which callers use only in a copy compiled with the `fma` target feature
//! (elsewhere it is a call into the C library's software `fma`, correct but slow).

use core::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// A value of several lanes of one scalar type, with lane-wise arithmetic.
pub trait Lane:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
{
    /// The scalar of one lane.
    type Scalar: Copy;
    /// Number of lanes.
    const LANES: usize;
    /// Every lane `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// Every lane the constant `c` (rounded to the lane's scalar): how generated code writes
    /// its coefficients.
    fn constant(c: f64) -> Self;
    /// Lane `i` is `f(i)`.
    fn from_fn(f: impl FnMut(usize) -> Self::Scalar) -> Self;
    /// Lane `i` (`i < LANES`; panics past the last lane).
    fn lane(self, i: usize) -> Self::Scalar;
    /// Lane-wise square root.
    fn sqrt(self) -> Self;
    /// Lane-wise `if self < 0 { -x } else { x }`: a sign flip without a branch.
    fn flip_sign_if_negative(self, x: Self) -> Self;
    /// Lane-wise `if self > t { yes } else { no }` (a compare and a blend; NaN picks `no`).
    fn gt_select(self, t: Self, yes: Self, no: Self) -> Self;
    /// Lane-wise `self * a + b` with one rounding (a fused multiply-add instruction where the
    /// function calling it is compiled with the `fma` target feature).
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// `self * a + b`: [`Lane::mul_add`] when `FUSED`, else a multiply and an add (the form
    /// a kernel written once for both copies of its loop uses).
    #[inline(always)]
    fn mul_add_if<const FUSED: bool>(self, a: Self, b: Self) -> Self {
        if FUSED {
            self.mul_add(a, b)
        } else {
            self * a + b
        }
    }
}

impl Lane for f64 {
    type Scalar = f64;
    const LANES: usize = 1;
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn constant(c: f64) -> f64 {
        c
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> f64 {
        f(0)
    }
    #[inline(always)]
    fn lane(self, i: usize) -> f64 {
        assert!(i == 0, "lane {i} of one");
        self
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn flip_sign_if_negative(self, x: f64) -> f64 {
        if self < 0.0 {
            -x
        } else {
            x
        }
    }
    #[inline(always)]
    fn gt_select(self, t: f64, yes: f64, no: f64) -> f64 {
        if self > t {
            yes
        } else {
            no
        }
    }
    #[inline(always)]
    fn mul_add(self, a: f64, b: f64) -> f64 {
        f64::mul_add(self, a, b)
    }
}

impl Lane for f32 {
    type Scalar = f32;
    const LANES: usize = 1;
    #[inline(always)]
    fn splat(x: f32) -> f32 {
        x
    }
    #[inline(always)]
    fn constant(c: f64) -> f32 {
        c as f32
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f32) -> f32 {
        f(0)
    }
    #[inline(always)]
    fn lane(self, i: usize) -> f32 {
        assert!(i == 0, "lane {i} of one");
        self
    }
    #[inline(always)]
    fn sqrt(self) -> f32 {
        f32::sqrt(self)
    }
    #[inline(always)]
    fn flip_sign_if_negative(self, x: f32) -> f32 {
        if self < 0.0 {
            -x
        } else {
            x
        }
    }
    #[inline(always)]
    fn gt_select(self, t: f32, yes: f32, no: f32) -> f32 {
        if self > t {
            yes
        } else {
            no
        }
    }
    #[inline(always)]
    fn mul_add(self, a: f32, b: f32) -> f32 {
        f32::mul_add(self, a, b)
    }
}

macro_rules! lanes {
    ($(#[$doc:meta])* $name:ident, $s:ty, $n:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Default)]
        #[repr(C, align(32))]
        pub struct $name(pub [$s; $n]);

        impl $name {
            /// Lane-wise `f(a, b)`.
            #[inline(always)]
            fn zip(self, o: $name, f: impl Fn($s, $s) -> $s) -> $name {
                let mut r = [0.0; $n];
                for i in 0..$n {
                    r[i] = f(self.0[i], o.0[i]);
                }
                $name(r)
            }
        }

        impl Lane for $name {
            type Scalar = $s;
            const LANES: usize = $n;
            #[inline(always)]
            fn splat(x: $s) -> $name {
                $name([x; $n])
            }
            #[inline(always)]
            fn constant(c: f64) -> $name {
                $name([c as $s; $n])
            }
            #[inline(always)]
            fn from_fn(mut f: impl FnMut(usize) -> $s) -> $name {
                // A loop, not `core::array::from_fn`: that one is not always inlined, and a
                // call out of an AVX2 loop into baseline code costs more than the work.
                let mut r = [0.0; $n];
                for (i, x) in r.iter_mut().enumerate() {
                    *x = f(i);
                }
                $name(r)
            }
            #[inline(always)]
            fn lane(self, i: usize) -> $s {
                self.0[i]
            }
            #[inline(always)]
            fn sqrt(self) -> $name {
                let mut r = self.0;
                for x in &mut r {
                    *x = x.sqrt();
                }
                $name(r)
            }
            #[inline(always)]
            fn flip_sign_if_negative(self, x: $name) -> $name {
                // A select per lane (a compare and a blend, no branch, once vectorised).
                self.zip(x, |s, x| if s < 0.0 { -x } else { x })
            }
            #[inline(always)]
            fn gt_select(self, t: $name, yes: $name, no: $name) -> $name {
                let mut r = no.0;
                for i in 0..$n {
                    if self.0[i] > t.0[i] {
                        r[i] = yes.0[i];
                    }
                }
                $name(r)
            }
            #[inline(always)]
            fn mul_add(self, a: $name, b: $name) -> $name {
                let mut r = self.0;
                for i in 0..$n {
                    r[i] = r[i].mul_add(a.0[i], b.0[i]);
                }
                $name(r)
            }
        }

        impl Add for $name {
            type Output = $name;
            #[inline(always)]
            fn add(self, o: $name) -> $name {
                self.zip(o, |a, b| a + b)
            }
        }
        impl AddAssign for $name {
            #[inline(always)]
            fn add_assign(&mut self, o: $name) {
                *self = *self + o;
            }
        }
        impl Sub for $name {
            type Output = $name;
            #[inline(always)]
            fn sub(self, o: $name) -> $name {
                self.zip(o, |a, b| a - b)
            }
        }
        impl Mul for $name {
            type Output = $name;
            #[inline(always)]
            fn mul(self, o: $name) -> $name {
                self.zip(o, |a, b| a * b)
            }
        }
        impl Div for $name {
            type Output = $name;
            #[inline(always)]
            fn div(self, o: $name) -> $name {
                self.zip(o, |a, b| a / b)
            }
        }
        impl Neg for $name {
            type Output = $name;
            #[inline(always)]
            fn neg(self) -> $name {
                let mut r = self.0;
                for x in &mut r {
                    *x = -*x;
                }
                $name(r)
            }
        }
    };
}

lanes!(
    /// Four `f64` lanes (one AVX register, two SSE2 registers).
    F64x4, f64, 4
);
lanes!(
    /// Eight `f32` lanes (one AVX register, two SSE registers).
    F32x8, f32, 8
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_compute_lane_by_lane() {
        let a = F64x4([1.0, -2.0, 3.5, 0.0]);
        let b = F64x4::from_fn(|i| i as f64 + 0.5);
        let r = (a * b - a) / b + -a;
        for i in 0..4 {
            let (x, y) = (a.lane(i), b.lane(i));
            assert_eq!(r.lane(i), (x * y - x) / y + -x);
        }
        assert_eq!(F32x8::splat(2.0).sqrt().lane(7), 2f32.sqrt());
    }

    #[test]
    fn sign_flip_follows_the_sign_of_the_selector() {
        let s = F64x4([-1.0, 2.0, -0.0, 0.0]);
        let x = F64x4::splat(3.0);
        assert_eq!(s.flip_sign_if_negative(x).0, [-3.0, 3.0, 3.0, 3.0]);
        assert_eq!((-1.0f64).flip_sign_if_negative(3.0), -3.0);
        assert_eq!((-0.0f64).flip_sign_if_negative(3.0), 3.0);
        assert_eq!((-0.5f32).flip_sign_if_negative(-2.0), 2.0);
        let s8 = F32x8::from_fn(|i| i as f32 - 3.5);
        let r = s8.flip_sign_if_negative(F32x8::splat(1.0));
        assert_eq!(r.0, [-1.0, -1.0, -1.0, -1.0, 1.0, 1.0, 1.0, 1.0]);
    }
}
