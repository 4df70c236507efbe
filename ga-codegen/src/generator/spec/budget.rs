//! Phase 4: refuse, before any product is expanded, a spec too large to generate.
//!
//! The estimate counts the work the generator does, in units of about one term inserted in a
//! symbolic polynomial (a few microseconds and about a kilobyte at the peak, on a laptop core),
//! and is proportional to the code emitted. It counts the blade pairs of the declared types,
//! never the `2^n x 2^n` table of the algebra (which the generator does not build). With `m`
//! the mean number of terms of a product of two of the declared blades (1 for a diagonal
//! metric, more for a dense one; measured exactly on a sample of those pairs, see
//! `MetricCost`):
//!
//! - each type of `w` blades (stored and constant): `3 m w^2 + 8 w` for its unary methods
//!   (reverse, dual, norm and square, scalar products) plus `ITEMS_PER_TYPE` emitted items;
//! - each ordered pair of types: `3 m w_a w_b` for the geometric and outer products and the
//!   left contraction, plus `ITEMS_PER_PAIR` emitted items (`*`, `^`, `|`, `+`, `-`, `From`);
//! - each sandwich of a versor of `v` blades on an operand of `x`: `m v x + 2 m^2 v^2 x` (the
//!   product `V X` and then `(V X) ~V`), plus its matrix form; for a `unit` versor also
//!   `2 m v^2` (the identities of `V ~V = 1`) and `SAMPLE_UNITS m c^2` for its check on 32
//!   sample unit versors, exponentials whose products span the `c` blades of the versor's
//!   closure (`spec/unit_cost.rs`): a motor's 8, QCGA's translator 184 (51 reached), a general
//!   QCGA rotor 16,384;
//! - each emitted item costs `ITEM` units (formatting, parsing, printing).
//!
//! Measured (release build, one core): `algebras/cga.toml` is about 0.13 million units
//! (0.5 s), `--signature 7,0,0` 1.45 million (3.4 s, 830 MB), 80 two-blade types about 1.7
//! million (2.8 s, 870 MB); refused: `--signature 8,0,0` (about 10 million units; it took 50 s
//! and 4.7 GB), 150 two-blade types (5.8 million; 2.8 GB). The budget is `BUDGET`. Unit
//! versors in QCGA (`algebras/qcga.toml` plus a rotor of the first `k` basis vectors, on
//! vectors): `k = 9` (closure 256) generates in 3.8 s of CPU and is accepted; `k = 11`
//! (closure 1,024) took 19 s of CPU (39 s on a loaded machine), almost all of it the samples,
//! and is refused (about 7.7 million units, 6.3 million of them the samples); the general
//! rotor (all 15) ran for more than 5 minutes and is refused in milliseconds.

use super::error::{SpecError, SpecErrorKind, SpecLocation, TooLarge};
use super::unit_cost::exp_closure;
use super::{SandwichDef, TypeDef};
use crate::runtime::blade::Bitmap;
use crate::runtime::metric::Metric;
use crate::runtime::sparse::blades::BladeProducts;

/// What a metric costs per blade product, measured on a sample of the declared blade pairs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct MetricCost {
    /// Mean number of terms of a blade product (at least 1).
    pub terms: f64,
}

/// Blade pairs sampled (all of them when the declared blades make at most this many pairs).
const SAMPLE: u64 = 256;

impl MetricCost {
    /// Measure a metric on the blades of `types`; `None` when its exact products overflow
    /// (reported by the exactness phase).
    pub fn of(metric: &Metric, types: &[TypeDef]) -> Option<MetricCost> {
        let c = BladeProducts::new(metric)?;
        let mut blades: Vec<Bitmap> = types.iter().flat_map(TypeDef::blades).collect();
        blades.sort_unstable();
        blades.dedup();
        if blades.is_empty() {
            return Some(MetricCost { terms: 1.0 });
        }
        let size = blades.len() as u64;
        let pairs: Vec<(Bitmap, Bitmap)> = if size * size <= SAMPLE {
            blades
                .iter()
                .flat_map(|&a| blades.iter().map(move |&b| (a, b)))
                .collect()
        } else {
            // A fixed pseudo-random sample (64-bit LCG, high bits), the same on every run.
            let mut x = 0x9e37_79b9_7f4a_7c15u64;
            let mut next = move || {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                blades[((x >> 33) % size) as usize]
            };
            (0..SAMPLE).map(|_| (next(), next())).collect()
        };
        let mut terms = 0.0;
        for &(a, b) in &pairs {
            terms += c.product(a, b)?.len().max(1) as f64;
        }
        Some(MetricCost {
            terms: terms / pairs.len() as f64,
        })
    }
}

/// Largest number of basis vectors the generator takes (blades are 32-bit bitmaps, and the
/// runtime [`Metric`] takes up to 16). What a spec of that many costs is the budget's to say:
/// it counts the declared types, not the `2^n` blades of the algebra.
pub const MAX_DIMENSION: usize = 16;

/// Largest estimate accepted, in units of work (about 5 s and 1.2 GB).
pub(crate) const BUDGET: u64 = 2_000_000;

/// Units of work per emitted item (an impl or a method).
pub(crate) const ITEM: u64 = 40;

/// Emitted items per type (struct, constructors, unary methods, conversions).
pub(crate) const ITEMS_PER_TYPE: u64 = 13;

/// Emitted items per ordered pair of types.
pub(crate) const ITEMS_PER_PAIR: u64 = 6;

/// Units per blade pair of a unit versor's closure for its sandwich's sample check (32
/// exponentials, each some ten products of multivectors on the closure, and the exact blade
/// products they meet); measured on QCGA rotors (see the module doc).
pub(crate) const SAMPLE_UNITS: f64 = 5.0;

/// Closures are counted up to this many blades: past it the samples alone are over
/// [`BUDGET`].
pub(crate) const CLOSURE_CAP: usize = 1024;

/// The estimate of one sandwich.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct SandwichCost {
    /// Its index in the spec.
    pub index: usize,
    /// All its units.
    pub units: u64,
    /// For a unit versor: the blades of its closure (over [`CLOSURE_CAP`]: more than that)
    /// and the units of the sample check.
    pub samples: Option<(usize, u64)>,
}

/// The estimate of one spec, by part.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Estimate {
    /// The unary methods of every type.
    pub types: u64,
    /// The binary operators of every ordered pair of types.
    pub pairs: u64,
    /// Every sandwich.
    pub sandwiches: Vec<SandwichCost>,
}

impl Estimate {
    /// The estimate of a spec: the cost of its metric, its types and sandwiches.
    pub fn of(
        cost: MetricCost,
        metric: &Metric,
        types: &[TypeDef],
        sandwiches: &[SandwichDef],
    ) -> Estimate {
        let width = |t: &TypeDef| (t.fields.len() + t.constants.len()) as f64;
        let widths: Vec<f64> = types.iter().map(width).collect();
        let sum: f64 = widths.iter().sum();
        let count = types.len() as f64;
        let (m, item) = (cost.terms, ITEM as f64);
        let units = |x: f64| x.min(u64::MAX as f64 / 8.0) as u64;
        // The closure of each unit versor type, once.
        let mut closures: Vec<Option<usize>> = vec![None; types.len()];
        for s in sandwiches {
            if types[s.versor].unit && closures[s.versor].is_none() {
                closures[s.versor] = Some(exp_closure(metric, &types[s.versor], CLOSURE_CAP));
            }
        }
        Estimate {
            types: units(
                widths
                    .iter()
                    .map(|w| 3.0 * m * w * w + 8.0 * w + ITEMS_PER_TYPE as f64 * item)
                    .sum(),
            ),
            pairs: units(3.0 * m * sum * sum + count * count * ITEMS_PER_PAIR as f64 * item),
            sandwiches: sandwiches
                .iter()
                .enumerate()
                .map(|(index, s)| {
                    let (v, x) = (widths[s.versor], widths[s.operand]);
                    let product = m * v * x + 2.0 * m * m * v * v * x + 3.0 * item;
                    let samples = closures[s.versor].map(|c| {
                        let c_units = SAMPLE_UNITS * m * (c as f64) * (c as f64);
                        (c, units(c_units))
                    });
                    let unit = samples.map_or(0.0, |(_, u)| 2.0 * m * v * v + u as f64);
                    SandwichCost {
                        index,
                        units: units(product + unit),
                        samples,
                    }
                })
                .collect(),
        }
    }

    /// The total.
    pub fn total(&self) -> u64 {
        self.types
            + self.pairs
            + self
                .sandwiches
                .iter()
                .map(|s| s.units)
                .fold(0u64, u64::saturating_add)
    }
}

/// Refuse a spec over [`MAX_DIMENSION`] or over [`BUDGET`], saying why.
pub(super) fn check(
    metric: &Metric,
    types: &[TypeDef],
    sandwiches: &[SandwichDef],
    source: &str,
) -> Result<(), SpecError> {
    let dim = metric.dim();
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
    let Some(cost) = MetricCost::of(metric, types) else {
        // Exact products overflow: the exactness phase says which entry.
        return Ok(());
    };
    let e = Estimate::of(cost, metric, types, sandwiches);
    let estimate = e.total();
    if estimate <= BUDGET {
        return Ok(());
    }
    let biggest_sandwich = e.sandwiches.iter().max_by_key(|s| s.units);
    let blades: usize = types
        .iter()
        .map(|t| t.fields.len() + t.constants.len())
        .sum();
    let (cause, location, type_name) = match biggest_sandwich {
        Some(sc) if sc.units >= e.pairs.max(e.types) => {
            let s = &sandwiches[sc.index];
            let (v, x) = (&types[s.versor], &types[s.operand]);
            (
                sandwich_cause(sc, v, x),
                SpecLocation::Sandwich(sc.index),
                Some(v.name.clone()),
            )
        }
        _ if e.pairs >= e.types => (
            format!(
                "the products of every pair of the {} types ({} ordered pairs, {} blades in \
                 all): {} units; declare fewer or smaller types",
                types.len(),
                types.len() * types.len(),
                blades,
                e.pairs
            ),
            SpecLocation::Spec,
            None,
        ),
        _ => (
            format!(
                "the methods of the {} types ({} blades in all, {:.1} terms per blade \
                 product): {} units; declare fewer or smaller types",
                types.len(),
                blades,
                cost.terms,
                e.types
            ),
            SpecLocation::Spec,
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

/// Why a sandwich is too costly, in words: its product, or the sample check of its unit
/// versor.
fn sandwich_cause(sc: &SandwichCost, v: &TypeDef, x: &TypeDef) -> String {
    let blades = |t: &TypeDef| t.fields.len() + t.constants.len();
    let units = sc.units;
    match sc.samples {
        Some((c, samples)) if samples >= units / 2 => {
            let reach = if c > CLOSURE_CAP {
                format!("more than {CLOSURE_CAP}")
            } else {
                c.to_string()
            };
            format!(
                "the sandwich of `{}` ({} blades) by the unit versor `{}` ({} blades): {units} \
                 units, {samples} of them its check on sample unit versors, exponentials of \
                 its bivectors that span {reach} blades, multiplied pair by pair; declare a \
                 versor type whose bivectors generate fewer blades, or drop `unit` (its \
                 sandwiches are then neither reduced by `{} ~{} = 1` nor checked)",
                x.name,
                blades(x),
                v.name,
                blades(v),
                v.name,
                v.name
            )
        }
        _ => format!(
            "the sandwich of `{}` ({} blades) by `{}` ({} blades): {units} units; declare \
             fewer sandwiches or smaller types",
            x.name,
            blades(x),
            v.name,
            blades(v)
        ),
    }
}
