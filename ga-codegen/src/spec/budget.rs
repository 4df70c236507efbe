//! Phase 4: refuse, before any product is expanded, a spec too large to generate.
//!
//! The estimate counts the work the generator does, in units of about one term inserted in a
//! symbolic polynomial (a few microseconds and about a kilobyte at the peak, on a laptop core),
//! and is proportional to the code emitted:
//!
//! - the exact product table of the basis blades: `2 * 4^n`;
//! - each type of `w` blades (stored and constant): `2 w^2 + 8 w` for its unary methods
//!   (reverse, dual, norm, scalar products) plus [`ITEMS_PER_TYPE`] emitted items;
//! - each ordered pair of types: `3 w_a w_b` for the geometric and outer products and the
//!   left contraction, plus [`ITEMS_PER_PAIR`] emitted items (`*`, `^`, `|`, `+`, `-`, `From`);
//! - each sandwich of a versor of `v` blades on an operand of `x`: `v x + 2 v^2 x` (the
//!   product `V X` and then `(V X) ~V`), plus its matrix form;
//! - each emitted item costs [`ITEM`] units (formatting, parsing, printing).
//!
//! Measured: `algebras/cga.toml` is about 0.2 million units (0.5 s), `--signature 7,0,0`
//! about 1.45 million (3.4 s, 830 MB), 80 two-blade types 1.6 million (2.8 s, 870 MB),
//! `--signature 8,0,0` about 9 million (50 s, 4.7 GB). The budget is [`BUDGET`].

use super::error::{SpecError, SpecErrorKind, SpecLocation, TooLarge};
use super::{SandwichDef, TypeDef};

/// Largest number of basis vectors the generator takes: the general multivector of an
/// 8-dimensional algebra has 256 blades and its products alone are 65,536 terms each.
pub const MAX_DIMENSION: usize = 8;

/// Largest estimate accepted, in units of work (about 5 s and 1.2 GB).
pub const BUDGET: u64 = 2_000_000;

/// Units of work per emitted item (an impl or a method).
pub const ITEM: u64 = 40;

/// Emitted items per type (struct, constructors, unary methods, conversions).
pub const ITEMS_PER_TYPE: u64 = 12;

/// Emitted items per ordered pair of types.
pub const ITEMS_PER_PAIR: u64 = 6;

/// The estimate of one spec, by part.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Estimate {
    /// The product table of the basis blades.
    pub table: u64,
    /// The unary methods of every type.
    pub types: u64,
    /// The binary operators of every ordered pair of types.
    pub pairs: u64,
    /// Every sandwich, with its index and units.
    pub sandwiches: Vec<(usize, u64)>,
}

impl Estimate {
    /// The estimate of a spec: its dimension, types and sandwiches.
    pub fn of(dim: usize, types: &[TypeDef], sandwiches: &[SandwichDef]) -> Estimate {
        let width = |t: &TypeDef| (t.fields.len() + t.constants.len()) as u64;
        let widths: Vec<u64> = types.iter().map(width).collect();
        let sum: u64 = widths.iter().sum();
        let count = types.len() as u64;
        Estimate {
            table: 2u64.saturating_mul(1u64 << (2 * dim.min(31))),
            types: widths
                .iter()
                .map(|w| 2 * w * w + 8 * w + ITEMS_PER_TYPE * ITEM)
                .sum(),
            pairs: 3 * sum * sum + count * count * ITEMS_PER_PAIR * ITEM,
            sandwiches: sandwiches
                .iter()
                .enumerate()
                .map(|(i, s)| {
                    let (v, x) = (widths[s.versor], widths[s.operand]);
                    (i, v * x + 2 * v * v * x + 3 * ITEM)
                })
                .collect(),
        }
    }

    /// The total.
    pub fn total(&self) -> u64 {
        self.table + self.types + self.pairs + self.sandwiches.iter().map(|s| s.1).sum::<u64>()
    }
}

/// Refuse a spec over [`MAX_DIMENSION`] or over [`BUDGET`], saying why.
pub(super) fn check(
    dim: usize,
    types: &[TypeDef],
    sandwiches: &[SandwichDef],
    source: &str,
) -> Result<(), SpecError> {
    if dim > MAX_DIMENSION {
        return Err(SpecError::new(
            source,
            SpecLocation::BasisList,
            SpecErrorKind::TooLarge(TooLarge::Dimension {
                n: dim,
                max: MAX_DIMENSION,
            }),
        ));
    }
    let e = Estimate::of(dim, types, sandwiches);
    let estimate = e.total();
    if estimate <= BUDGET {
        return Ok(());
    }
    let biggest_sandwich = e.sandwiches.iter().max_by_key(|s| s.1).copied();
    let (cause, location, type_name) = match biggest_sandwich {
        Some((i, units)) if units >= e.pairs.max(e.types).max(e.table) => {
            let s = &sandwiches[i];
            let (v, x) = (&types[s.versor], &types[s.operand]);
            (
                format!(
                    "the sandwich of `{}` ({} blades) by `{}` ({} blades): {units} units; \
                     declare fewer sandwiches or smaller types",
                    x.name,
                    x.fields.len() + x.constants.len(),
                    v.name,
                    v.fields.len() + v.constants.len()
                ),
                SpecLocation::Sandwich(i),
                Some(v.name.clone()),
            )
        }
        _ if e.pairs >= e.types.max(e.table) => (
            format!(
                "the products of every pair of the {} types ({} ordered pairs, {} blades in \
                 all): {} units; declare fewer or smaller types",
                types.len(),
                types.len() * types.len(),
                types
                    .iter()
                    .map(|t| t.fields.len() + t.constants.len())
                    .sum::<usize>(),
                e.pairs
            ),
            SpecLocation::Spec,
            None,
        ),
        _ if e.types >= e.table => (
            format!(
                "the methods of the {} types: {} units",
                types.len(),
                e.types
            ),
            SpecLocation::Spec,
            None,
        ),
        _ => (
            format!("the product table of the 2^{dim} blades: {} units", e.table),
            SpecLocation::BasisList,
            None,
        ),
    };
    let mut err = SpecError::new(
        source,
        location,
        SpecErrorKind::TooLarge(TooLarge::Work {
            estimate,
            budget: BUDGET,
            cause,
        }),
    );
    if let Some(t) = type_name {
        err = err.in_type(&t);
    }
    Err(err)
}
