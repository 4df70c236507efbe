//! ga-benchmark's products that [`SparseMultivector`] does not define itself, as the dense
//! reference defines them (`runtime/derived.rs`): the dot and Hestenes inner products, the
//! commutator, the undual, the regressive product and the inverse geometric product, built
//! from the sparse multivector's own operations, so the named products of large algebras are
//! checked as the small ones are.

use crate::runtime::blade::{reorder_sign, Bitmap};
use crate::runtime::sparse::multivector::SparseMultivector;

impl SparseMultivector {
    /// `sum over i, j with keep(i, j) = Some(k) of <self_i o_j>_k`, for the grade parts
    /// `self_i` and `o_j`.
    fn graded_product(
        &self,
        o: &SparseMultivector,
        keep: impl Fn(u32, u32) -> Option<u32>,
    ) -> SparseMultivector {
        let n = self.algebra().dim() as u32;
        let mut out = SparseMultivector::zero(self.algebra());
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
    pub fn dot_product(&self, o: &SparseMultivector) -> SparseMultivector {
        self.graded_product(o, |i, j| Some(i.abs_diff(j)))
    }

    /// The Hestenes inner product (GATL's `hip`): `sum <a_i b_j>_|i-j|` over `i, j > 0`.
    pub fn hestenes_inner_product(&self, o: &SparseMultivector) -> SparseMultivector {
        self.graded_product(o, |i, j| (i > 0 && j > 0).then(|| i.abs_diff(j)))
    }

    /// The commutator product `(a b - b a) / 2`.
    pub fn commutator_product(&self, o: &SparseMultivector) -> SparseMultivector {
        (&self.gp(o) - &o.gp(self)).scale(0.5)
    }

    /// The undual, inverse of [`SparseMultivector::dual`]: `x * I` for a non-degenerate
    /// metric, else the inverse of the right complement.
    pub fn undual(&self) -> SparseMultivector {
        let alg = self.algebra();
        let full: Bitmap = ((1u64 << alg.dim()) - 1) as Bitmap;
        if alg.is_degenerate() {
            let mut out = SparseMultivector::zero(alg);
            for (b, x) in self.terms() {
                let comp = full & !b;
                let y = out.get(comp) + reorder_sign(comp, b) as f64 * x;
                out.set(comp, y);
            }
            out
        } else {
            self.gp(&SparseMultivector::blade(alg, full, 1.0))
        }
    }

    /// The regressive product `a ∨ b = undual(dual(a) ^ dual(b))`.
    pub fn regressive_product(&self, o: &SparseMultivector) -> SparseMultivector {
        self.dual().outer(&o.dual()).undual()
    }

    /// The inverse geometric product `a * b^-1`; `None` when `b` has no inverse of the form
    /// [`SparseMultivector::inverse`] takes (a blade or versor).
    pub fn inverse_geometric_product(&self, o: &SparseMultivector) -> Option<SparseMultivector> {
        Some(self.gp(&o.inverse()?))
    }

    /// `a ~b / <b ~b>_0`: what the generated `inverse_geometric_product` computes.
    pub fn reverse_quotient(&self, o: &SparseMultivector) -> SparseMultivector {
        self.gp(&o.rev()).scale(1.0 / o.norm_squared())
    }
}
