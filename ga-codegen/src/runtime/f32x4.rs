//! Four `f32` lanes, for generated f32 products written in 4-lane form.
//!
//! Generated f32 geometric products between versor types (motor times motor, ...) take the
//! output fields four by four and compute the four lanes at once, as sums of terms such as
//! `splat(a.e12) * (b.e12, b.s, b.e23, b.e13)` grouped by their signs. On x86-64 a quad is an
//! SSE register (part of the baseline target, so always available); elsewhere it is a plain
//! array. Every operation is exact lane by lane: the results are bit for bit those of the
//! scalar expressions with the same grouping.

#[cfg(target_arch = "x86_64")]
use core::arch::x86_64::{
    __m128, _mm_add_ps, _mm_loadu_ps, _mm_mul_ps, _mm_set1_ps, _mm_setr_ps, _mm_shuffle_ps,
    _mm_storeu_ps, _mm_sub_ps, _mm_unpackhi_ps, _mm_unpacklo_ps, _mm_xor_ps,
};

/// Four `f32` lanes.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct F32x4(
    #[cfg(target_arch = "x86_64")] __m128,
    #[cfg(not(target_arch = "x86_64"))] [f32; 4],
);

#[cfg(target_arch = "x86_64")]
impl F32x4 {
    /// `(x0, x1, x2, x3)`.
    #[inline(always)]
    #[must_use]
    pub fn new(x0: f32, x1: f32, x2: f32, x3: f32) -> F32x4 {
        // SAFETY (all intrinsics here): SSE is part of the x86-64 baseline target.
        F32x4(unsafe { _mm_setr_ps(x0, x1, x2, x3) })
    }

    /// The four lanes from an array.
    #[inline(always)]
    #[must_use]
    pub fn from_array(x: [f32; 4]) -> F32x4 {
        // SAFETY: reads four f32 from a live array (unaligned load).
        F32x4(unsafe { _mm_loadu_ps(x.as_ptr()) })
    }

    /// `(x, x, x, x)`.
    #[inline(always)]
    #[must_use]
    pub fn splat(x: f32) -> F32x4 {
        F32x4(unsafe { _mm_set1_ps(x) })
    }

    /// The lanes picked by `IMM` as `_mm_shuffle_ps` does: lane `i` of the result is lane
    /// `(IMM >> 2 i) & 3` of `self`. The generator computes `IMM` with `shuffle_imm`.
    #[inline(always)]
    #[must_use]
    pub fn shuffle<const IMM: i32>(self) -> F32x4 {
        F32x4(unsafe { _mm_shuffle_ps::<IMM>(self.0, self.0) })
    }

    /// Two lanes of `self` then two of `b`, as `_mm_shuffle_ps(self, b)`: lanes 0 and 1 are
    /// lanes `IMM & 3` and `(IMM >> 2) & 3` of `self`, lanes 2 and 3 lanes `(IMM >> 4) & 3`
    /// and `(IMM >> 6) & 3` of `b`.
    #[inline(always)]
    #[must_use]
    pub fn shuffle2<const IMM: i32>(self, b: F32x4) -> F32x4 {
        F32x4(unsafe { _mm_shuffle_ps::<IMM>(self.0, b.0) })
    }

    /// `(self0, b0, self1, b1)`.
    #[inline(always)]
    #[must_use]
    pub fn unpack_lo(self, b: F32x4) -> F32x4 {
        F32x4(unsafe { _mm_unpacklo_ps(self.0, b.0) })
    }

    /// `(self2, b2, self3, b3)`.
    #[inline(always)]
    #[must_use]
    pub fn unpack_hi(self, b: F32x4) -> F32x4 {
        F32x4(unsafe { _mm_unpackhi_ps(self.0, b.0) })
    }

    /// Negate the lanes whose bit is set in `MASK` (bit `i` for lane `i`): an exact sign flip.
    #[inline(always)]
    #[must_use]
    pub fn flip<const MASK: i32>(self) -> F32x4 {
        let s = |i: i32| if MASK & (1 << i) != 0 { -0.0 } else { 0.0 };
        F32x4(unsafe { _mm_xor_ps(self.0, _mm_setr_ps(s(0), s(1), s(2), s(3))) })
    }

    /// The four lanes as an array.
    #[inline(always)]
    #[must_use]
    pub fn to_array(self) -> [f32; 4] {
        let mut out = [0.0f32; 4];
        // SAFETY: writes four f32 into a live array (unaligned store).
        unsafe { _mm_storeu_ps(out.as_mut_ptr(), self.0) };
        out
    }
}

#[cfg(not(target_arch = "x86_64"))]
impl F32x4 {
    /// `(x0, x1, x2, x3)`.
    #[inline(always)]
    #[must_use]
    pub fn new(x0: f32, x1: f32, x2: f32, x3: f32) -> F32x4 {
        F32x4([x0, x1, x2, x3])
    }

    /// The four lanes from an array.
    #[inline(always)]
    #[must_use]
    pub fn from_array(x: [f32; 4]) -> F32x4 {
        F32x4(x)
    }

    /// `(x, x, x, x)`.
    #[inline(always)]
    #[must_use]
    pub fn splat(x: f32) -> F32x4 {
        F32x4([x; 4])
    }

    /// The lanes picked by `IMM` as `_mm_shuffle_ps` does: lane `i` of the result is lane
    /// `(IMM >> 2 i) & 3` of `self`. The generator computes `IMM` with `shuffle_imm`.
    #[inline(always)]
    #[must_use]
    pub fn shuffle<const IMM: i32>(self) -> F32x4 {
        let l = |i: i32| self.0[((IMM >> (2 * i)) & 3) as usize];
        F32x4([l(0), l(1), l(2), l(3)])
    }

    /// Two lanes of `self` then two of `b`, as `_mm_shuffle_ps(self, b)`: lanes 0 and 1 are
    /// lanes `IMM & 3` and `(IMM >> 2) & 3` of `self`, lanes 2 and 3 lanes `(IMM >> 4) & 3`
    /// and `(IMM >> 6) & 3` of `b`.
    #[inline(always)]
    #[must_use]
    pub fn shuffle2<const IMM: i32>(self, b: F32x4) -> F32x4 {
        let l = |x: &[f32; 4], i: i32| x[((IMM >> (2 * i)) & 3) as usize];
        F32x4([l(&self.0, 0), l(&self.0, 1), l(&b.0, 2), l(&b.0, 3)])
    }

    /// `(self0, b0, self1, b1)`.
    #[inline(always)]
    #[must_use]
    pub fn unpack_lo(self, b: F32x4) -> F32x4 {
        F32x4([self.0[0], b.0[0], self.0[1], b.0[1]])
    }

    /// `(self2, b2, self3, b3)`.
    #[inline(always)]
    #[must_use]
    pub fn unpack_hi(self, b: F32x4) -> F32x4 {
        F32x4([self.0[2], b.0[2], self.0[3], b.0[3]])
    }

    /// Negate the lanes whose bit is set in `MASK` (bit `i` for lane `i`): an exact sign flip.
    #[inline(always)]
    #[must_use]
    pub fn flip<const MASK: i32>(self) -> F32x4 {
        let f = |i: usize| {
            if MASK & (1 << i) != 0 {
                -self.0[i]
            } else {
                self.0[i]
            }
        };
        F32x4([f(0), f(1), f(2), f(3)])
    }

    /// The four lanes as an array.
    #[inline(always)]
    #[must_use]
    pub fn to_array(self) -> [f32; 4] {
        self.0
    }
}

/// The `IMM` of [`F32x4::shuffle`] that puts lane `lanes[i]` of the source in lane `i`.
#[must_use]
#[cfg(any(feature = "codegen", test))]
pub(crate) const fn shuffle_imm(lanes: [u8; 4]) -> i32 {
    (lanes[0] as i32) | (lanes[1] as i32) << 2 | (lanes[2] as i32) << 4 | (lanes[3] as i32) << 6
}

macro_rules! lane_op {
    ($tr:ident, $method:ident, $intr:ident, $op:tt) => {
        impl core::ops::$tr for F32x4 {
            type Output = F32x4;
            #[inline(always)]
            fn $method(self, o: F32x4) -> F32x4 {
                #[cfg(target_arch = "x86_64")]
                {
                    F32x4(unsafe { $intr(self.0, o.0) })
                }
                #[cfg(not(target_arch = "x86_64"))]
                {
                    F32x4(core::array::from_fn(|i| self.0[i] $op o.0[i]))
                }
            }
        }
    };
}

lane_op!(Add, add, _mm_add_ps, +);
lane_op!(Sub, sub, _mm_sub_ps, -);
lane_op!(Mul, mul, _mm_mul_ps, *);

#[cfg(test)]
mod tests {
    use super::{shuffle_imm, F32x4};

    #[test]
    fn lanes() {
        let a = F32x4::new(1.5, -2.0, 3.0, 0.5);
        let b = F32x4::new(4.0, 0.25, -1.0, 2.0);
        assert_eq!((a + b).to_array(), [5.5, -1.75, 2.0, 2.5]);
        assert_eq!((a - b).to_array(), [-2.5, -2.25, 4.0, -1.5]);
        assert_eq!((a * b).to_array(), [6.0, -0.5, -3.0, 1.0]);
        assert_eq!(F32x4::splat(3.0).to_array(), [3.0; 4]);
        const IMM: i32 = shuffle_imm([3, 2, 1, 0]);
        assert_eq!(a.shuffle::<IMM>().to_array(), [0.5, 3.0, -2.0, 1.5]);
        assert_eq!(a.flip::<0b0101>().to_array(), [-1.5, -2.0, -3.0, 0.5]);
        assert_eq!(a.unpack_lo(b).to_array(), [1.5, 4.0, -2.0, 0.25]);
        assert_eq!(a.unpack_hi(b).to_array(), [3.0, -1.0, 0.5, 2.0]);
        const IMM2: i32 = shuffle_imm([3, 0, 1, 2]);
        assert_eq!(a.shuffle2::<IMM2>(b).to_array(), [0.5, 1.5, 0.25, -1.0]);
        assert_eq!(
            F32x4::from_array([1.0, 2.0, 3.0, 4.0]).to_array(),
            [1.0, 2.0, 3.0, 4.0]
        );
    }
}
