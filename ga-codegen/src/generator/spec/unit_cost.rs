//! What the checks of a unit versor's sandwich cost, for the size budget ([`super::budget`]).
//!
//! A sandwich by a `unit` versor is reduced modulo `a ~a = 1` and its stray blades are checked
//! on sample unit versors: 32 exponentials `exp(B)` of random bivectors `B` of the type
//! ([`crate::generator::unit_versor`]). Each exponential multiplies multivectors whose blades
//! are those that products of the type's bivector blades reach: its *closure*. A motor's
//! closure is the motor; a general rotor of a large algebra reaches most of its even blades
//! (a general QCGA rotor: about 16,000), and its samples alone would take hours. The closure
//! is found here on bitmaps (no products computed), so a spec is refused before that work.

use super::TypeDef;
use crate::runtime::blade::{grade, Bitmap};
use crate::runtime::metric::Metric;
use std::collections::HashSet;

/// The blades a product `e_a e_b` of a blade by a basis bivector `b` can have: by Wick's
/// expansion, the union of the two after contracting zero, one or two pairs of basis vectors
/// whose inner product is not zero (`nz[i]`: the vectors not orthogonal to `e_i`), where what
/// is left has no vector twice. A superset: cancellations are not seen.
fn bivector_product_blades(a: Bitmap, b: Bitmap, nz: &[Bitmap], out: &mut Vec<Bitmap>) {
    let p = b.trailing_zeros() as usize;
    let q = (b & !(1 << p)).trailing_zeros() as usize;
    if a & b == 0 {
        out.push(a | b);
    }
    let bits: Vec<usize> = (0..nz.len()).filter(|&i| a & (1 << i) != 0).collect();
    for &i in &bits {
        let rest = a & !(1 << i);
        for (x, y) in [(p, q), (q, p)] {
            if nz[i] & (1 << x) != 0 && rest & (1 << y) == 0 {
                out.push(rest | 1 << y);
            }
        }
    }
    for (k, &i) in bits.iter().enumerate() {
        for &j in &bits[k + 1..] {
            let meets = |x: usize, y: usize| nz[i] & (1 << x) != 0 && nz[j] & (1 << y) != 0;
            if meets(p, q) || meets(q, p) {
                out.push(a & !(1 << i | 1 << j));
            }
        }
    }
}

/// The number of blades in the closure of `{1}` under products by the bivector blades of `t`
/// (what its exponentials can span), counted up to `cap` (a larger closure returns a number
/// over `cap`, no more of it computed).
pub(crate) fn exp_closure(metric: &Metric, t: &TypeDef, cap: usize) -> usize {
    closure_blades(metric, t, cap).len()
}

/// The blades of [`exp_closure`] (stopped one past `cap`).
fn closure_blades(metric: &Metric, t: &TypeDef, cap: usize) -> HashSet<Bitmap> {
    let n = metric.dim();
    let nz: Vec<Bitmap> = (0..n)
        .map(|i| {
            (0..n)
                .filter(|&j| !metric.get(i, j).is_zero())
                .fold(0, |m, j| m | 1 << j)
        })
        .collect();
    let bivectors: Vec<Bitmap> = t
        .fields
        .iter()
        .map(|f| f.bitmap)
        .filter(|&b| grade(b) == 2)
        .collect();
    let mut seen: HashSet<Bitmap> = HashSet::from([0]);
    let mut todo = vec![0];
    let mut terms = Vec::new();
    while let Some(a) = todo.pop() {
        for &b in &bivectors {
            terms.clear();
            bivector_product_blades(a, b, &nz, &mut terms);
            for &c in &terms {
                if seen.insert(c) {
                    if seen.len() > cap {
                        return seen;
                    }
                    todo.push(c);
                }
            }
        }
    }
    seen
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::generator::spec::{shipped_spec as spec, Spec};

    fn closure(s: &Spec, name: &str) -> HashSet<Bitmap> {
        let t = s.types.iter().find(|t| t.name == name).expect("type");
        closure_blades(&s.metric, t, 1 << 16)
    }

    /// A closed versor type is its own closure (the motor's 8 blades, the GL+(3) rotor's 20);
    /// QCGA's translator, whose products of null bivectors cancel in its exponentials, has a
    /// larger closure that holds all its 51 blades.
    #[test]
    fn closures_hold_the_versor_and_count_what_products_reach() {
        let cga = spec("cga");
        let motor: HashSet<Bitmap> = cga
            .types
            .iter()
            .find(|t| t.name == "Motor")
            .unwrap()
            .blades()
            .collect();
        assert_eq!(closure(&cga, "Motor"), motor);
        assert_eq!(closure(&spec("mother"), "Linear").len(), 20);
        let qcga = spec("qcga");
        let translator = closure(&qcga, "Translator");
        let t = qcga.types.iter().find(|t| t.name == "Translator").unwrap();
        assert!(t.blades().all(|b| translator.contains(&b)));
        assert_eq!(translator.len(), 184);
        // Stopped one past the cap.
        assert_eq!(closure_blades(&qcga.metric, t, 100).len(), 101);
    }
}
