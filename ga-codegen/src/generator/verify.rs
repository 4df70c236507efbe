//! Numeric verification at generation time, next to the emitted check harness
//! ([`crate::generator::checks`]): what the symbolic engine cannot prove exactly is checked on random
//! values with the sparse generic
//! [`SparseMultivector`] (blade pairs only, any dimension) before the emitter relies on it.

use crate::generator::spec::Spec;
use crate::generator::symbolic::{Poly, SymMv};
use crate::runtime::blade::grade;
use crate::runtime::sparse::multivector::{SparseAlgebra, SparseMultivector};

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
    let mut rng = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let bivector_fields: Vec<usize> = (0..tv.fields.len())
        .filter(|&i| grade(tv.fields[i].bitmap) == 2)
        .collect();
    if bivector_fields.is_empty() {
        return false;
    }
    for _ in 0..16 {
        let mut bv = SparseMultivector::zero(alg);
        for &i in &bivector_fields {
            bv.set(tv.fields[i].bitmap, next());
        }
        let mut m = bv.exp();
        let n = m.norm();
        if n.is_nan() || n <= 1e-6 {
            return false;
        }
        m = m.scale(1.0 / n);
        // The exponential must lie in the type.
        let outside: f64 = m
            .terms()
            .filter(|(b, _)| !tv.blades().any(|x| x == *b))
            .map(|(_, c)| c.abs())
            .fold(0.0, f64::max);
        if outside > 1e-9 {
            return false;
        }
        let vals0: Vec<f64> = tv
            .fields
            .iter()
            .map(|f| f.sign as f64 * m.get(f.bitmap))
            .collect();
        let vals1: Vec<f64> = tx.fields.iter().map(|_| next()).collect();
        let eval = |p: &Poly| -> f64 {
            p.0.iter()
                .map(|(mono, c)| {
                    mono.iter().fold(c.to_f64(), |acc, v| {
                        acc * if v.operand == 0 {
                            vals0[v.field as usize]
                        } else {
                            vals1[v.field as usize]
                        }
                    })
                })
                .sum()
        };
        for bm in r.support() {
            let target = if to.field(bm).is_some() {
                continue;
            } else {
                to.constant(bm).map(|c| c.to_f64()).unwrap_or(0.0)
            };
            if (eval(&r.get(bm)) - target).abs() > 1e-9 {
                return false;
            }
        }
        for &(bm, c) in &to.constants {
            if (eval(&r.get(bm)) - c.to_f64()).abs() > 1e-9 {
                return false;
            }
        }
    }
    true
}
