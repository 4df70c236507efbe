//! Phase 5: the exact products of the metric fit in 128-bit rationals, with room for what
//! generation does with them.
//!
//! The product table of the basis blades is computed exactly, with checked arithmetic (it is
//! what [`crate::Algebra`] computes at generation time and in the generated code). Generation
//! then multiplies table coefficients with each other and with type constants: a sandwich
//! term is two table coefficients and up to three constants, a dual term a coefficient and
//! `1 / (I ~I)`. The check asks that any product of [`TABLE_FACTORS`] table values (one more
//! than a sandwich needs) and [`CONSTANT_FACTORS`] constants, summed over all `4^n` blade
//! pairs, fits in 127 bits: with `N` the largest numerator and `D` the common denominator of
//! each set, `TABLE_FACTORS * bits(N D) + CONSTANT_FACTORS * bits(N_c D_c) + 2n <= 127`.
//! Metric entries such as `0.1`, `0.3`, `0.7` pass with room to spare; `1e13` on three vectors
//! (a pseudoscalar square of `1e39`) fails while building the table, and entries with many
//! digits (`0.3333333333333333`) or very small ones (`1e-9`) fail the headroom.

use super::error::{SpecError, SpecErrorKind, SpecLocation};
use super::metric::error as metric_error;
use super::{RawType, TypeDef};
use crate::algebra::exact_products;
use crate::blade::reverse_sign;
use crate::metric::{Metric, MetricError};
use crate::rational::Rational;

/// Table values per product of the bound.
pub const TABLE_FACTORS: u32 = 3;
/// Constants per product of the bound.
pub const CONSTANT_FACTORS: u32 = 3;

/// Bits of a positive integer (1 for 0 and 1).
fn bits(x: u128) -> u32 {
    (128 - x.leading_zeros()).max(1)
}

/// `bits(N * D)` of a set of values: the bits of the largest numerator over the common
/// denominator; `None` when that does not fit in 128 bits.
fn height(values: impl Iterator<Item = Rational> + Clone) -> Option<u32> {
    let mut den: u128 = 1;
    for v in values.clone() {
        let d = v.denom() as u128;
        let (mut a, mut b) = (den, d);
        while b != 0 {
            (a, b) = (b, a % b);
        }
        den = (den / a).checked_mul(d)?;
    }
    let num = values.map(|v| v.numer().unsigned_abs()).max().unwrap_or(1);
    Some(bits(num) + bits(den))
}

/// Check the metric and the type constants; `types` are the validated types, `raw` the
/// types as written (for locations).
pub(super) fn check(
    metric: &Metric,
    basis: &[String],
    types: &[TypeDef],
    raw: &[RawType],
    source: &str,
) -> Result<(), SpecError> {
    let overflow = || metric_error(source, basis, metric.overflow_error());
    // The generated module writes the metric as `f64` literals and reads them back.
    let n = metric.dim();
    for i in 0..n {
        for j in 0..n {
            let g = metric.get(i, j);
            if Rational::from_f64(g.to_f64()) != Some(g) {
                return Err(metric_error(source, basis, MetricError::NotExact { i, j }));
            }
        }
    }
    let (table, _) = exact_products(metric).ok_or_else(overflow)?;
    let full = (1usize << n) - 1;
    let ii = table[full * (full + 1) + full].get(&0).map(|c| {
        if reverse_sign(full as u32) < 0 {
            -*c
        } else {
            *c
        }
    });
    let table_values = table
        .iter()
        .flat_map(|m| m.values().copied())
        .chain((0..n).flat_map(|i| (0..n).map(move |j| metric.get(i, j))))
        .chain(ii.and_then(Rational::recip));
    let h_table = height(table_values).ok_or_else(overflow)?;
    let constants = types
        .iter()
        .flat_map(|t| t.constants.iter().map(|c| c.1))
        .chain([Rational::ONE]);
    let h_const = height(constants).unwrap_or(u32::MAX / 8);
    let room = 127u32.saturating_sub(2 * n as u32);
    if TABLE_FACTORS * h_table + CONSTANT_FACTORS.saturating_mul(h_const) <= room {
        return Ok(());
    }
    if TABLE_FACTORS * h_table + CONSTANT_FACTORS * 2 <= room {
        // The metric alone passes: the constants are too large.
        return Err(constant_error(types, raw, source));
    }
    Err(overflow())
}

/// The error for the constant with the largest numerator or denominator.
fn constant_error(types: &[TypeDef], raw: &[RawType], source: &str) -> SpecError {
    let mut worst: Option<(u32, usize, &str)> = None;
    for (ti, rt) in raw.iter().enumerate() {
        for (key, &value) in &rt.constants {
            let h = Rational::from_f64(value).map_or(u32::MAX, Rational::height);
            if worst.is_none_or(|w| h > w.0) {
                worst = Some((h, ti, key));
            }
        }
    }
    let (ti, key) = worst.map_or((0, ""), |w| (w.1, w.2));
    let name = types.get(ti).map_or("", |t| t.name.as_str());
    SpecError::new(
        source,
        SpecLocation::ConstantValue {
            ty: ti,
            key: key.to_string(),
        },
        SpecErrorKind::BadConstant,
    )
    .in_type(name)
    .at_blade(key)
}
