//! Phase 5: the exact products of the metric fit in 128-bit rationals, with room for what
//! generation does with them.
//!
//! The products of basis blades are computed exactly, with checked arithmetic: the whole table
//! (what [`crate::Algebra`] computes in the generated code) for algebras of up to
//! `FULL_TABLE_DIMENSION` basis vectors, and above that the blade pairs generation multiplies
//! (those of the declared types, of each sandwich's versor by its intermediate product, and
//! of the pseudoscalar), one pair at a time ([`BladeProducts`]). Generation
//! then multiplies table coefficients with each other and with type constants: a sandwich
//! term is two table coefficients and up to three constants, a dual term one coefficient and
//! `1 / (I ~I)`. For a set of values let `h = bits(ceil(max |v|)) + bits(D)`, `D` the common
//! denominator: a product of `k` values, summed over `4^n` blade pairs, then has at most
//! `k h + 2n` bits. With `h_t` for the table (and metric entries), `h_i` for `1 / (I ~I)` and
//! `h_c` for the constants, the check asks, with one table factor to spare,
//!
//! - products: `3 h_t + 3 h_c + 2n <= 127`;
//! - duals: `2 h_t + h_i + 3 h_c + 2n <= 127`.
//!
//! Metric entries such as `0.1`, `0.3`, `0.7` or `0.001` pass with room to spare; `1e13` on
//! three vectors (a pseudoscalar square of `1e39`) fails while building the table, and entries
//! with many digits (`0.3333333333333333`) or very small ones (`1e-9`) fail the headroom.

use super::error::{SpecError, SpecErrorKind, SpecLocation};
use super::metric::error as metric_error;
use super::{RawType, SandwichDef, TypeDef};
use crate::runtime::algebra::{exact_products, Exact};
use crate::runtime::blade::reverse_sign;
use crate::runtime::blade::Bitmap;
use crate::runtime::metric::{Metric, MetricError};
use crate::runtime::rational::Rational;
use crate::runtime::sparse::blades::BladeProducts;
use std::collections::HashSet;

/// Bits of a positive integer (1 for 0 and 1).
fn bits(x: u128) -> u32 {
    (128 - x.leading_zeros()).max(1)
}

/// `h` of a set of values: bits of the largest magnitude (rounded up) plus bits of the common
/// denominator; `None` when the denominator does not fit in 128 bits.
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
    let mag = values
        .map(|v| v.numer().unsigned_abs().div_ceil(v.denom() as u128))
        .max()
        .unwrap_or(1);
    Some(bits(mag) + bits(den))
}

/// Check the metric and the type constants; `types` are the validated types, `raw` the
/// types as written (for locations).
pub(super) fn check(
    metric: &Metric,
    basis: &[String],
    types: &[TypeDef],
    sandwiches: &[SandwichDef],
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
    let (table, ii) = products(metric, types, sandwiches).ok_or_else(overflow)?;
    let full = (1u32 << n) - 1;
    let ii = ii
        .get(&0)
        .map(|c| if reverse_sign(full) < 0 { -*c } else { *c });
    let table_values = table
        .iter()
        .flat_map(|m| m.values().copied())
        .chain((0..n).flat_map(|i| (0..n).map(move |j| metric.get(i, j))));
    let h_table = height(table_values).ok_or_else(overflow)?;
    let h_dual = match ii.and_then(Rational::recip) {
        Some(r) => height(std::iter::once(r)).ok_or_else(overflow)?,
        None => 0,
    };
    let constants = types
        .iter()
        .flat_map(|t| t.constants.iter().map(|c| c.1))
        .chain([Rational::ONE]);
    let h_const = height(constants).map_or(u32::MAX / 8, |h| 3 * h);
    let room = 127u32.saturating_sub(2 * n as u32);
    let fits =
        |h_const: u32| 3 * h_table + h_const <= room && 2 * h_table + h_dual + h_const <= room;
    if fits(h_const) {
        return Ok(());
    }
    if fits(3 * 2) {
        // The metric passes with constants of 1: the constants are too large.
        return Err(constant_error(types, raw, source));
    }
    Err(overflow())
}

/// Largest number of basis vectors whose whole product table is checked (4,096 blade pairs).
const FULL_TABLE_DIMENSION: usize = 6;

/// The exact blade products generation may multiply, and the pseudoscalar's square `I I`;
/// `None` on overflow.
fn products(
    metric: &Metric,
    types: &[TypeDef],
    sandwiches: &[SandwichDef],
) -> Option<(Vec<Exact>, Exact)> {
    let full: Bitmap = (1 << metric.dim()) - 1;
    if metric.dim() <= FULL_TABLE_DIMENSION {
        let (table, _) = exact_products(metric)?;
        let ii = table[full as usize * (full as usize + 2)].clone();
        return Some((table, ii));
    }
    let c = BladeProducts::new(metric)?;
    let mut declared: Vec<Bitmap> = types.iter().flat_map(TypeDef::blades).collect();
    declared.extend([0, full]);
    declared.sort_unstable();
    declared.dedup();
    // Each blade pair once: a sandwich's middle blades are often declared ones, and two
    // sandwiches of one versor share most of theirs.
    let mut pairs: HashSet<(Bitmap, Bitmap)> = HashSet::new();
    let mut table = Vec::new();
    for &a in &declared {
        for &b in &declared {
            pairs.insert((a, b));
            table.push(c.product(a, b)?);
        }
    }
    for s in sandwiches {
        let versor: Vec<Bitmap> = types[s.versor].blades().collect();
        let mut middle: Vec<Bitmap> = Vec::new();
        for &a in &versor {
            for b in types[s.operand].blades() {
                middle.extend(c.product(a, b)?.keys());
            }
        }
        middle.sort_unstable();
        middle.dedup();
        for &k in &middle {
            for &v in &versor {
                if pairs.insert((k, v)) {
                    table.push(c.product(k, v)?);
                }
            }
        }
    }
    let ii = c.product(full, full)?;
    Some((table, ii))
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
