//! Checks shared by every fallible function: inputs are finite, and so are the results.
//!
//! A `try_` function returns `Ok` only when its result is finite and valid. Input that is NaN or
//! infinite is [`CgaError::NonFinite`]; finite input whose result overflows (or loses every
//! significant digit) is [`CgaError::Overflow`]. Every comparison is written so that NaN fails.

use super::*;

/// Whether every coefficient is finite.
#[inline]
#[must_use]
pub(crate) fn all_finite(c: &[S]) -> bool {
    c.iter().all(|x| x.is_finite())
}

/// The largest absolute coefficient (NaN when one is NaN).
#[inline]
#[must_use]
pub(crate) fn max_abs(c: &[S]) -> S {
    let mut m: S = 0.0;
    for x in c {
        if x.is_nan() {
            return S::NAN;
        }
        m = m.max(x.abs());
    }
    m
}

/// `Err(Overflow)` when the largest coefficient `k` of a versor is so small that its
/// coefficients, subnormal, keep fewer than half their significant digits (the smallest
/// subnormal over `k` above `sqrt(eps)`): `k M` at `k = 1e-45` in `f32` (`1e-320` in `f64`)
/// no longer holds the motion of `M`, and a logarithm or normalisation of it would be a wrong
/// `Ok`. Above the limit the result is as precise as the input: off by about the smallest
/// subnormal over `k`.
#[inline]
pub(crate) fn precise_scale(k: S, what: &'static str) -> Result<()> {
    // `smallest / sqrt(eps)` is exact enough (a few thousand subnormal steps); the product
    // `sqrt(eps) * k` is not: near the limit it underflows and rounds up to `smallest`.
    let limit = S::from_bits(1) / S::EPSILON.sqrt();
    if limit <= k {
        Ok(())
    } else {
        Err(CgaError::Overflow { what })
    }
}

/// `Err(NonFinite)` unless every input coefficient is finite.
#[inline]
pub(crate) fn finite_input(c: &[S], what: &'static str) -> Result<()> {
    if all_finite(c) {
        Ok(())
    } else {
        Err(CgaError::NonFinite { what })
    }
}

/// `Err(NonFinite)` unless `v` is finite.
#[inline]
pub(crate) fn finite3(v: V3, what: &'static str) -> Result<()> {
    finite_input(&[v.x, v.y, v.z], what)
}

/// `Ok(value)` when every coefficient of the result is finite, else `Err(Overflow)`.
#[inline]
pub(crate) fn finite_result<T>(value: T, coeffs: &[S], what: &'static str) -> Result<T> {
    if all_finite(coeffs) {
        Ok(value)
    } else {
        Err(CgaError::Overflow { what })
    }
}

/// The unit vector along a finite `v`, computed without overflow or underflow (the vector is
/// first divided by its largest component, so `1e300` and `1e-310` axes work). `None` for the
/// zero vector or non-finite input.
#[inline]
#[must_use]
pub(crate) fn unit_direction(v: V3) -> Option<V3> {
    let m = v.abs().max_element();
    if !(m > 0.0) || !m.is_finite() {
        return None;
    }
    let u = v / m;
    Some(u / u.length())
}

/// [`unit_direction`] with the errors of the `try_` functions.
#[inline]
pub(crate) fn try_unit_direction(v: V3, what: &'static str) -> Result<V3> {
    finite3(v, what)?;
    unit_direction(v).ok_or(CgaError::ZeroAxis { what })
}
