//! Numeric verification at generation time, next to the emitted check harness
//! ([`crate::generator::checks`]): what the symbolic engine cannot prove exactly is checked on random
//! values with the sparse generic
//! [`SparseMultivector`](crate::runtime::sparse::multivector::SparseMultivector) (blade pairs only, any dimension) before the emitter relies on it.

use crate::generator::spec::Spec;
use crate::generator::symbolic::SymMv;
use crate::generator::unit_versor::{eval, unit_versor_samples};
use crate::runtime::sparse::multivector::SparseAlgebra;

/// True when, on random unit versors of type `vi` (exponentials of random bivectors in the
/// type, normalised), every blade of the sandwich `r` (of an operand of type `xi`) that output
/// type `oi` does not store is zero and every constant of `oi` is met, to 1e-9.
///
/// This is what lets a sandwich by a `unit` versor drop the blades that vanish because
/// `x ~x = 1` (e.g. the grade-5 part of a motor sandwich).
pub fn unit_versor_drop_ok(
    alg: &std::sync::Arc<SparseAlgebra>,
    spec: &Spec,
    vi: usize,
    xi: usize,
    r: &SymMv,
    oi: usize,
) -> bool {
    let (tv, tx, to) = (&spec.types[vi], &spec.types[xi], &spec.types[oi]);
    let Some(samples) = unit_versor_samples(alg, tv, tx, 0x9e37_79b9_7f4a_7c15) else {
        return false;
    };
    samples.iter().all(|(vals0, vals1)| {
        let off = |bm, target: f64| (eval(&r.get(bm), vals0, vals1) - target).abs() > 1e-9;
        let stray = r.support().into_iter().any(|bm| {
            to.field(bm).is_none() && off(bm, to.constant(bm).map_or(0.0, |c| c.to_f64()))
        });
        !stray && !to.constants.iter().any(|&(bm, c)| off(bm, c.to_f64()))
    })
}
