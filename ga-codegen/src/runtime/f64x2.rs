//! Two `f64` lanes, for generated products written in paired-lane form.
//!
//! Generated geometric products between versor types (motor times motor, rotor times
//! translator, ...) pair the output fields two by two and compute both lanes at once:
//! `o = splat(a.s) * (b.s, b.e12) + splat(a.e12) * (b.e12, b.s) * (-1, 1) + ...`. On x86-64 a
//! lane pair is an SSE2 register (part of the baseline target, so always available); elsewhere
//! it is a plain array and the compiler vectorises it as it can. Every operation is exact lane
//! by lane: the results are bit for bit those of the scalar expressions with the same grouping.

#[cfg(target_arch = "x86_64")]
use core::arch::x86_64::{
    __m128d, _mm_add_pd, _mm_cvtsd_f64, _mm_mul_pd, _mm_set1_pd, _mm_set_pd, _mm_shuffle_pd,
    _mm_sub_pd, _mm_unpackhi_pd,
};

/// Two `f64` lanes, `lo` and `hi`.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct F64x2(
    #[cfg(target_arch = "x86_64")] __m128d,
    #[cfg(not(target_arch = "x86_64"))] [f64; 2],
);

#[cfg(target_arch = "x86_64")]
impl F64x2 {
    /// `(lo, hi)`.
    #[inline(always)]
    #[must_use]
    pub fn new(lo: f64, hi: f64) -> F64x2 {
        // SAFETY (all intrinsics here): SSE2 is part of the x86-64 baseline target.
        F64x2(unsafe { _mm_set_pd(hi, lo) })
    }

    /// `(x, x)`.
    #[inline(always)]
    #[must_use]
    pub fn splat(x: f64) -> F64x2 {
        F64x2(unsafe { _mm_set1_pd(x) })
    }

    /// `(hi, lo)`.
    #[inline(always)]
    #[must_use]
    pub fn swap(self) -> F64x2 {
        F64x2(unsafe { _mm_shuffle_pd::<1>(self.0, self.0) })
    }

    /// The low lane.
    #[inline(always)]
    #[must_use]
    pub fn lo(self) -> f64 {
        unsafe { _mm_cvtsd_f64(self.0) }
    }

    /// The high lane.
    #[inline(always)]
    #[must_use]
    pub fn hi(self) -> f64 {
        unsafe { _mm_cvtsd_f64(_mm_unpackhi_pd(self.0, self.0)) }
    }
}

#[cfg(not(target_arch = "x86_64"))]
impl F64x2 {
    /// `(lo, hi)`.
    #[inline(always)]
    #[must_use]
    pub fn new(lo: f64, hi: f64) -> F64x2 {
        F64x2([lo, hi])
    }

    /// `(x, x)`.
    #[inline(always)]
    #[must_use]
    pub fn splat(x: f64) -> F64x2 {
        F64x2([x, x])
    }

    /// `(hi, lo)`.
    #[inline(always)]
    #[must_use]
    pub fn swap(self) -> F64x2 {
        F64x2([self.0[1], self.0[0]])
    }

    /// The low lane.
    #[inline(always)]
    #[must_use]
    pub fn lo(self) -> f64 {
        self.0[0]
    }

    /// The high lane.
    #[inline(always)]
    #[must_use]
    pub fn hi(self) -> f64 {
        self.0[1]
    }
}

macro_rules! lane_op {
    ($tr:ident, $method:ident, $intr:ident, $op:tt) => {
        impl core::ops::$tr for F64x2 {
            type Output = F64x2;
            #[inline(always)]
            fn $method(self, o: F64x2) -> F64x2 {
                #[cfg(target_arch = "x86_64")]
                {
                    F64x2(unsafe { $intr(self.0, o.0) })
                }
                #[cfg(not(target_arch = "x86_64"))]
                {
                    F64x2([self.0[0] $op o.0[0], self.0[1] $op o.0[1]])
                }
            }
        }
    };
}

lane_op!(Add, add, _mm_add_pd, +);
lane_op!(Sub, sub, _mm_sub_pd, -);
lane_op!(Mul, mul, _mm_mul_pd, *);

#[cfg(test)]
mod tests {
    use super::F64x2;

    #[test]
    fn lanes() {
        let a = F64x2::new(1.5, -2.0);
        let b = F64x2::new(4.0, 0.25);
        assert_eq!(((a + b).lo(), (a + b).hi()), (5.5, -1.75));
        assert_eq!(((a - b).lo(), (a - b).hi()), (-2.5, -2.25));
        assert_eq!(((a * b).lo(), (a * b).hi()), (6.0, -0.5));
        assert_eq!((a.swap().lo(), a.swap().hi()), (-2.0, 1.5));
        assert_eq!((F64x2::splat(3.0).lo(), F64x2::splat(3.0).hi()), (3.0, 3.0));
    }
}
