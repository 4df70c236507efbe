//! Products of ga-benchmark's operation set that [`Multivector`] does not define itself: the
//! dot product, the Hestenes inner product, the commutator product, the undual and the
//! regressive product, the complement form of the regressive product, and the inverse
//! geometric product.
//!
//! They are built from the multivector's own public operations (geometric product, grade
//! parts, outer product, dual), as the definitions are written, and share no code with the
//! generator's symbolic engine: they are the reference the generated functions of the same
//! names are checked against.

use crate::runtime::blade::{reorder_sign, Bitmap};
use crate::runtime::multivector::Multivector;

impl Multivector {
    /// `sum over i, j with keep(i, j) = Some(k) of <self_i o_j>_k`, for the grade parts
    /// `self_i` and `o_j`.
    fn graded_product(
        &self,
        o: &Multivector,
        keep: impl Fn(u32, u32) -> Option<u32>,
    ) -> Multivector {
        let n = self.algebra().dim() as u32;
        let mut out = Multivector::zero(self.algebra());
        for i in 0..=n {
            let a = self.grade(i);
            for j in 0..=n {
                if let Some(k) = keep(i, j) {
                    out = &out + &a.gp(&o.grade(j)).grade(k);
                }
            }
        }
        out
    }

    /// The dot product (Dorst; GATL's `dot`): `sum <a_i b_j>_|i-j|` over the grade parts.
    pub fn dot_product(&self, o: &Multivector) -> Multivector {
        self.graded_product(o, |i, j| Some(i.abs_diff(j)))
    }

    /// The Hestenes inner product (GATL's `hip`): the dot product without the pairs where
    /// either grade is 0: `sum <a_i b_j>_|i-j|` over `i, j > 0`.
    pub fn hestenes_inner_product(&self, o: &Multivector) -> Multivector {
        self.graded_product(o, |i, j| (i > 0 && j > 0).then(|| i.abs_diff(j)))
    }

    /// The commutator product `(a b - b a) / 2`.
    pub fn commutator_product(&self, o: &Multivector) -> Multivector {
        (&self.gp(o) - &o.gp(self)).scale(0.5)
    }

    /// The undual, inverse of [`Multivector::dual`]: `x * I` for a non-degenerate metric
    /// (`I` the outer product of the basis in order), else the inverse of the right
    /// complement, `e_B -> s e_A` with `A` the complement of `B` and `e_A ^ s e_B = I`.
    pub fn undual(&self) -> Multivector {
        let alg = self.algebra();
        let full = (alg.size() - 1) as Bitmap;
        if alg.is_degenerate() {
            let mut out = Multivector::zero(alg);
            for b in 0..=full {
                let comp = full & !b;
                out.set(comp, reorder_sign(comp, b) as f64 * self.get(b));
            }
            out
        } else {
            self.gp(&Multivector::pseudoscalar(alg))
        }
    }

    /// The regressive product `a ∨ b = undual(dual(a) ^ dual(b))`, with
    /// [`Multivector::dual`] and [`Multivector::undual`].
    pub fn regressive_product(&self, o: &Multivector) -> Multivector {
        self.dual().outer(&o.dual()).undual()
    }

    /// The regressive product in complement form, which reads no metric (GATL's `rp`):
    /// `e_A ∨ e_B = reorder_sign(A \ C, B \ C) e_C` with `C = A ∩ B` when `A ∪ B` is the
    /// whole basis, else 0.
    pub fn regressive_complement(&self, o: &Multivector) -> Multivector {
        let alg = self.algebra();
        let full = (alg.size() - 1) as Bitmap;
        let mut out = Multivector::zero(alg);
        for a in 0..=full {
            for b in 0..=full {
                let (x, y) = (self.get(a), o.get(b));
                if a | b != full || x == 0.0 || y == 0.0 {
                    continue;
                }
                let c = a & b;
                let s = reorder_sign(a & !c, b & !c) as f64;
                out.set(c, out.get(c) + s * x * y);
            }
        }
        out
    }

    /// The inverse geometric product `a * b^-1`, with the generic inverse of `b`; `None`
    /// when `b` has none (see [`Multivector::inverse`]).
    pub fn inverse_geometric_product(&self, o: &Multivector) -> Option<Multivector> {
        Some(self.gp(&o.inverse()?))
    }

    /// The blade inverse form of the inverse geometric product, `a ~b / <b ~b>_0`: the same
    /// as [`Multivector::inverse_geometric_product`] when `b ~b` is a non-zero scalar (every blade and
    /// versor), and what the generated `inverse_geometric_product` computes for any `b`.
    pub fn reverse_quotient(&self, o: &Multivector) -> Multivector {
        self.gp(&o.rev()).scale(1.0 / o.norm_squared())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::runtime::algebra::Algebra;
    use crate::runtime::blade::grade;
    use std::sync::Arc;

    fn cga() -> Arc<Algebra> {
        let z = 0.0;
        let g = vec![
            vec![z, z, z, z, -1.0],
            vec![z, 1.0, z, z, z],
            vec![z, z, 1.0, z, z],
            vec![z, z, z, 1.0, z],
            vec![-1.0, z, z, z, z],
        ];
        Algebra::from_metric(&["eo", "e1", "e2", "e3", "ei"], &g).unwrap()
    }

    #[test]
    fn undual_inverts_dual_blade_by_blade() {
        let pga = Algebra::from_metric(
            &["e0", "e1", "e2", "e3"],
            &[
                vec![0.0, 0.0, 0.0, 0.0],
                vec![0.0, 1.0, 0.0, 0.0],
                vec![0.0, 0.0, 1.0, 0.0],
                vec![0.0, 0.0, 0.0, 1.0],
            ],
        )
        .unwrap();
        for alg in [cga(), pga] {
            for b in 0..alg.size() as Bitmap {
                let x = Multivector::blade(&alg, b, 1.0);
                assert!(x.dual().undual().max_diff(&x) < 1e-12, "blade {b}");
                assert!(x.undual().dual().max_diff(&x) < 1e-12, "blade {b}");
            }
        }
    }

    /// A diagonal metric.
    fn diagonal(d: &[f64]) -> Arc<Algebra> {
        let names: Vec<String> = (0..d.len()).map(|i| format!("e{i}")).collect();
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let g: Vec<Vec<f64>> = (0..d.len())
            .map(|i| {
                (0..d.len())
                    .map(|j| if i == j { d[i] } else { 0.0 })
                    .collect()
            })
            .collect();
        Algebra::from_metric(&names, &g).unwrap()
    }

    /// `undual(dual a ^ dual b)` against the complement form times `sign(ga, gb)`, blade by
    /// blade.
    fn regressive_matches(alg: &Arc<Algebra>, sign: impl Fn(u32, u32) -> f64) {
        let n = alg.dim() as Bitmap;
        for a in 0..1 << n {
            for b in 0..1 << n {
                let (x, y) = (
                    Multivector::blade(alg, a, 1.0),
                    Multivector::blade(alg, b, 1.0),
                );
                let want = x.regressive_complement(&y).scale(sign(grade(a), grade(b)));
                assert!(
                    x.regressive_product(&y).max_diff(&want) < 1e-12,
                    "e{a} v e{b}"
                );
            }
        }
    }

    /// For a non-degenerate metric (G(4,1) in the null basis, G(3,0), G(1,3), G(2,2)),
    /// `undual(dual a ^ dual b)` is the complement form times `(-1)^((n - ga)(n - gb))`: the
    /// sign of swapping the duals' order. For a degenerate one (G(3,0,1)), where the dual is
    /// the right complement, it is the complement form itself.
    #[test]
    fn regressive_is_the_complement_form_up_to_the_stated_sign() {
        for alg in [
            cga(),
            diagonal(&[1.0; 3]),
            diagonal(&[1.0, -1.0, -1.0, -1.0]),
            diagonal(&[1.0, 1.0, -1.0, -1.0]),
        ] {
            let n = alg.dim() as u32;
            regressive_matches(&alg, |ga, gb| {
                if ((n - ga) * (n - gb)).is_multiple_of(2) {
                    1.0
                } else {
                    -1.0
                }
            });
        }
        regressive_matches(&diagonal(&[0.0, 1.0, 1.0, 1.0]), |_, _| 1.0);
    }
}
