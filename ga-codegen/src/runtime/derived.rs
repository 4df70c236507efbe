//! Products of ga-benchmark's operation set that the generic references do not define
//! themselves: the dot product, the Hestenes inner product, the commutator product, the undual
//! and the regressive product, the complement form of the regressive product, and the inverse
//! geometric product.
//!
//! They are written once, as the definitions read, over the few operations both references
//! have ([`Reference`]: the dense [`Multivector`] and the sparse [`SparseMultivector`]), and
//! share no code with the generator's symbolic engine: they are the reference the generated
//! functions of the same names are checked against. Bring [`DerivedProducts`] into scope to
//! call them.

use crate::runtime::blade::{reorder_sign, Bitmap};
use crate::runtime::multivector::Multivector;
use crate::runtime::sparse::multivector::SparseMultivector;

/// What the derived products need of a generic reference multivector.
pub trait Reference: Sized {
    /// The number of basis vectors.
    fn basis_dim(&self) -> u32;
    /// Whether the metric is degenerate (no pseudoscalar inverse).
    fn degenerate_metric(&self) -> bool;
    /// `x e_b` in the same algebra.
    fn blade_of(&self, b: Bitmap, x: f64) -> Self;
    /// The coefficients that are not zero, with their blades.
    fn nonzero_terms(&self) -> Vec<(Bitmap, f64)>;
    /// The grade-`k` part.
    fn grade_part(&self, k: u32) -> Self;
    /// The geometric product.
    fn geometric(&self, o: &Self) -> Self;
    /// The outer product.
    fn wedge(&self, o: &Self) -> Self;
    /// `self + s o`.
    fn plus_scaled(&self, o: &Self, s: f64) -> Self;
    /// The dual (`x I^-1`, or the right complement in a degenerate metric).
    fn dual_of(&self) -> Self;
    /// The reverse.
    fn reversed(&self) -> Self;
    /// `<x ~x>_0`.
    fn reverse_norm_squared(&self) -> f64;
    /// The inverse, where the reference has one.
    fn inverse_of(&self) -> Option<Self>;
}

/// ga-benchmark's products over any [`Reference`].
pub trait DerivedProducts: Reference {
    /// `sum over i, j with keep(i, j) = Some(k) of <self_i o_j>_k`, for the grade parts
    /// `self_i` and `o_j`.
    fn graded_product(&self, o: &Self, keep: impl Fn(u32, u32) -> Option<u32>) -> Self {
        let n = self.basis_dim();
        let mut out = self.blade_of(0, 0.0);
        for i in 0..=n {
            let a = self.grade_part(i);
            for j in 0..=n {
                if let Some(k) = keep(i, j) {
                    out = out.plus_scaled(&a.geometric(&o.grade_part(j)).grade_part(k), 1.0);
                }
            }
        }
        out
    }

    /// The dot product (Dorst; GATL's `dot`): `sum <a_i b_j>_|i-j|` over the grade parts.
    fn dot_product(&self, o: &Self) -> Self {
        self.graded_product(o, |i, j| Some(i.abs_diff(j)))
    }

    /// The Hestenes inner product (GATL's `hip`): the dot product without the pairs where
    /// either grade is 0: `sum <a_i b_j>_|i-j|` over `i, j > 0`.
    fn hestenes_inner_product(&self, o: &Self) -> Self {
        self.graded_product(o, |i, j| (i > 0 && j > 0).then(|| i.abs_diff(j)))
    }

    /// The commutator product `(a b - b a) / 2`.
    fn commutator_product(&self, o: &Self) -> Self {
        self.geometric(o)
            .plus_scaled(&o.geometric(self), -1.0)
            .scaled(0.5)
    }

    /// `s self`.
    fn scaled(&self, s: f64) -> Self {
        self.blade_of(0, 0.0).plus_scaled(self, s)
    }

    /// The undual, inverse of the dual: `x * I` for a non-degenerate metric (`I` the outer
    /// product of the basis in order), else the inverse of the right complement,
    /// `e_B -> s e_A` with `A` the complement of `B` and `e_A ^ s e_B = I`.
    fn undual(&self) -> Self {
        let full: Bitmap = ((1u64 << self.basis_dim()) - 1) as Bitmap;
        if self.degenerate_metric() {
            let mut out = self.blade_of(0, 0.0);
            for (b, x) in self.nonzero_terms() {
                let comp = full & !b;
                out = out.plus_scaled(&self.blade_of(comp, reorder_sign(comp, b) as f64), x);
            }
            out
        } else {
            self.geometric(&self.blade_of(full, 1.0))
        }
    }

    /// The regressive product `a ∨ b = undual(dual(a) ^ dual(b))`.
    fn regressive_product(&self, o: &Self) -> Self {
        self.dual_of().wedge(&o.dual_of()).undual()
    }

    /// The regressive product in complement form, which reads no metric (GATL's `rp`):
    /// `e_A ∨ e_B = reorder_sign(A \ C, B \ C) e_C` with `C = A ∩ B` when `A ∪ B` is the
    /// whole basis, else 0.
    fn regressive_complement(&self, o: &Self) -> Self {
        let full: Bitmap = ((1u64 << self.basis_dim()) - 1) as Bitmap;
        let mut out = self.blade_of(0, 0.0);
        for (a, x) in self.nonzero_terms() {
            for (b, y) in o.nonzero_terms() {
                if a | b == full {
                    let c = a & b;
                    let s = reorder_sign(a & !c, b & !c) as f64;
                    out = out.plus_scaled(&self.blade_of(c, s * x * y), 1.0);
                }
            }
        }
        out
    }

    /// The inverse geometric product `a * b^-1`, with the reference's inverse of `b` (the
    /// dense one solves for any invertible `b`, the sparse one takes blades and versors);
    /// `None` when `b` has none.
    fn inverse_geometric_product(&self, o: &Self) -> Option<Self> {
        Some(self.geometric(&o.inverse_of()?))
    }

    /// The blade inverse form of the inverse geometric product, `a ~b / <b ~b>_0`: the same
    /// as [`DerivedProducts::inverse_geometric_product`] when `b ~b` is a non-zero scalar
    /// (every blade and versor), and what the generated `inverse_geometric_product` computes
    /// for any `b`.
    fn reverse_quotient(&self, o: &Self) -> Self {
        self.geometric(&o.reversed())
            .scaled(1.0 / o.reverse_norm_squared())
    }
}

impl<M: Reference> DerivedProducts for M {}

/// [`Reference`] for a reference type whose inherent methods have the usual names, with its
/// non-zero terms listed by `$terms`.
macro_rules! reference {
    ($t:ty, $terms:expr) => {
        impl Reference for $t {
            fn basis_dim(&self) -> u32 {
                self.algebra().dim() as u32
            }
            fn degenerate_metric(&self) -> bool {
                self.algebra().is_degenerate()
            }
            fn blade_of(&self, b: Bitmap, x: f64) -> Self {
                <$t>::blade(self.algebra(), b, x)
            }
            fn nonzero_terms(&self) -> Vec<(Bitmap, f64)> {
                let terms: fn(&$t) -> Vec<(Bitmap, f64)> = $terms;
                terms(self)
            }
            fn grade_part(&self, k: u32) -> Self {
                self.grade(k)
            }
            fn geometric(&self, o: &Self) -> Self {
                self.gp(o)
            }
            fn wedge(&self, o: &Self) -> Self {
                self.outer(o)
            }
            fn plus_scaled(&self, o: &Self, s: f64) -> Self {
                self + &o.scale(s)
            }
            fn dual_of(&self) -> Self {
                self.dual()
            }
            fn reversed(&self) -> Self {
                self.rev()
            }
            fn reverse_norm_squared(&self) -> f64 {
                self.norm_squared()
            }
            fn inverse_of(&self) -> Option<Self> {
                self.inverse()
            }
        }
    };
}

reference!(Multivector, |m| {
    let c = m.coeffs().iter().enumerate();
    c.filter(|&(_, &x)| x != 0.0)
        .map(|(b, &x)| (b as Bitmap, x))
        .collect()
});
reference!(SparseMultivector, |m| m
    .terms()
    .filter(|&(_, x)| x != 0.0)
    .collect());

#[cfg(test)]
mod tests {
    use super::*;
    use crate::runtime::algebra::Algebra;
    use crate::runtime::blade::grade;
    use std::sync::Arc;

    fn cga() -> Arc<Algebra> {
        Algebra::new(crate::runtime::metric::Metric::cga_null_basis())
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
