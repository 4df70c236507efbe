//! A sparse generic multivector: a map from the blades present to their coefficients.
//!
//! It computes what the dense [`Multivector`](crate::runtime::multivector::Multivector)
//! computes, term by term in the same order (so on small algebras the two agree to the last
//! bit), but stores only non-zero blades and asks [`BladeProducts`] for the product of each
//! blade pair it meets: the reference for algebras of up to 16 basis vectors.

use crate::runtime::blade::{grade, involute_sign, reorder_sign, reverse_sign, Bitmap, Keep};
use crate::runtime::metric::{Metric, MetricError};
use crate::runtime::sparse::blades::BladeProducts;
use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::sync::{Arc, Mutex};

/// The products of one blade pair, as `f64` terms.
type Terms = Arc<[(Bitmap, f64)]>;

/// An algebra whose blade products are computed on demand and memoised per pair.
#[derive(Debug)]
pub struct SparseAlgebra {
    metric: Metric,
    blades: BladeProducts,
    memo: Mutex<HashMap<(Bitmap, Bitmap), Terms>>,
}

impl SparseAlgebra {
    /// The algebra of a metric, or which entry makes exact products overflow. Costs the
    /// diagonalisation of the `n x n` metric, nothing per blade.
    pub fn try_new(metric: Metric) -> Result<Arc<SparseAlgebra>, MetricError> {
        let Some(blades) = BladeProducts::new(&metric) else {
            return Err(metric.overflow_error());
        };
        Ok(Arc::new(SparseAlgebra {
            metric,
            blades,
            memo: Mutex::new(HashMap::new()),
        }))
    }

    /// Build from basis names and `f64` metric entries (each read as the decimal it prints
    /// as, and held exactly).
    pub fn from_metric(names: &[&str], g: &[Vec<f64>]) -> Result<Arc<SparseAlgebra>, MetricError> {
        let metric = Metric::from_f64(names.iter().map(|s| s.to_string()).collect(), g)?;
        SparseAlgebra::try_new(metric)
    }

    /// The metric.
    pub fn metric(&self) -> &Metric {
        &self.metric
    }

    /// Bitmap and sign of a blade name in any basis order (`e21` is `-e12`).
    pub fn parse_blade(&self, name: &str) -> Option<(Bitmap, i32)> {
        crate::runtime::blade::parse_blade(name, self.metric.names()).ok()
    }

    /// Number of basis vectors.
    pub fn dim(&self) -> usize {
        self.metric.dim()
    }

    /// The non-zero terms of `e_a e_b`.
    ///
    /// # Panics
    /// When a blade names a basis vector past the algebra's, or exact arithmetic overflows
    /// (a metric of a validated spec never does).
    pub fn gp_blades(&self, a: Bitmap, b: Bitmap) -> Terms {
        let size = 1u64 << self.dim();
        assert!(
            u64::from(a) < size && u64::from(b) < size,
            "blades {a:#b} and {b:#b} in an algebra of {} basis vectors",
            self.dim()
        );
        if let Some(t) = self.memo.lock().expect("not poisoned").get(&(a, b)) {
            return t.clone();
        }
        let exact = self
            .blades
            .product(a, b)
            .expect("the metric's exact products fit in 128 bits");
        let t: Terms = exact.into_iter().map(|(k, c)| (k, c.to_f64())).collect();
        self.memo
            .lock()
            .expect("not poisoned")
            .insert((a, b), t.clone());
        t
    }
}

/// A multivector of a [`SparseAlgebra`]: the coefficients of the blades present.
#[derive(Clone)]
pub struct SparseMultivector {
    alg: Arc<SparseAlgebra>,
    c: BTreeMap<Bitmap, f64>,
}

impl fmt::Debug for SparseMultivector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.c.is_empty() {
            return write!(f, "0");
        }
        for (i, (&b, x)) in self.c.iter().enumerate() {
            let sep = if i == 0 { "" } else { " + " };
            let name = crate::runtime::blade::blade_name(b, self.alg.metric.names());
            write!(f, "{sep}{x}*{name}")?;
        }
        Ok(())
    }
}

impl SparseMultivector {
    /// Zero.
    pub fn zero(alg: &Arc<SparseAlgebra>) -> SparseMultivector {
        SparseMultivector {
            alg: alg.clone(),
            c: BTreeMap::new(),
        }
    }

    /// A scalar.
    pub fn scalar(alg: &Arc<SparseAlgebra>, s: f64) -> SparseMultivector {
        SparseMultivector::blade(alg, 0, s)
    }

    /// `x e_b`.
    pub fn blade(alg: &Arc<SparseAlgebra>, b: Bitmap, x: f64) -> SparseMultivector {
        let mut m = SparseMultivector::zero(alg);
        m.set(b, x);
        m
    }

    /// The algebra.
    pub fn algebra(&self) -> &Arc<SparseAlgebra> {
        &self.alg
    }

    /// Coefficient of blade `b` (zero when absent).
    pub fn get(&self, b: Bitmap) -> f64 {
        self.c.get(&b).copied().unwrap_or(0.0)
    }

    /// Set the coefficient of blade `b` (a zero removes it).
    pub fn set(&mut self, b: Bitmap, x: f64) {
        if x == 0.0 {
            self.c.remove(&b);
        } else {
            self.c.insert(b, x);
        }
    }

    /// The blades present with their coefficients, in bitmap order.
    pub fn terms(&self) -> impl Iterator<Item = (Bitmap, f64)> + '_ {
        self.c.iter().map(|(&b, &x)| (b, x))
    }

    fn product(&self, o: &SparseMultivector, keep: Keep) -> SparseMultivector {
        assert!(
            Arc::ptr_eq(&self.alg, &o.alg) || self.alg.metric == o.alg.metric,
            "multivectors of two different algebras"
        );
        let mut out: BTreeMap<Bitmap, f64> = BTreeMap::new();
        for (&a, &x) in &self.c {
            for (&b, &y) in &o.c {
                let (ga, gb) = (grade(a), grade(b));
                for &(k, c) in self.alg.gp_blades(a, b).iter() {
                    if keep.keeps(ga, gb, grade(k)) {
                        *out.entry(k).or_insert(0.0) += c * x * y;
                    }
                }
            }
        }
        out.retain(|_, x| *x != 0.0);
        SparseMultivector {
            alg: self.alg.clone(),
            c: out,
        }
    }

    /// Geometric product.
    ///
    /// # Panics
    /// When `o` is of another algebra.
    pub fn gp(&self, o: &SparseMultivector) -> SparseMultivector {
        self.product(o, Keep::All)
    }

    /// Outer (wedge) product.
    pub fn outer(&self, o: &SparseMultivector) -> SparseMultivector {
        self.product(o, Keep::Outer)
    }

    /// Left contraction `self ⌋ o`.
    pub fn left_contraction(&self, o: &SparseMultivector) -> SparseMultivector {
        self.product(o, Keep::Left)
    }

    /// Right contraction `self ⌊ o`.
    pub fn right_contraction(&self, o: &SparseMultivector) -> SparseMultivector {
        self.product(o, Keep::Right)
    }

    /// Scalar product `<self o>_0`.
    pub fn scalar_product(&self, o: &SparseMultivector) -> f64 {
        self.product(o, Keep::Scalar).get(0)
    }

    fn map(&self, f: impl Fn(Bitmap, f64) -> f64) -> SparseMultivector {
        let mut out = SparseMultivector::zero(&self.alg);
        for (&b, &x) in &self.c {
            out.set(b, f(b, x));
        }
        out
    }

    /// Reverse.
    pub fn rev(&self) -> SparseMultivector {
        self.map(|b, x| x * reverse_sign(b) as f64)
    }

    /// Grade involution.
    pub fn involute(&self) -> SparseMultivector {
        self.map(|b, x| x * involute_sign(b) as f64)
    }

    /// Clifford conjugate (reverse of the grade involution).
    pub fn conjugate(&self) -> SparseMultivector {
        self.map(|b, x| x * (reverse_sign(b) * involute_sign(b)) as f64)
    }

    /// Grade-`k` part.
    pub fn grade(&self, k: u32) -> SparseMultivector {
        self.map(|b, x| if grade(b) == k { x } else { 0.0 })
    }

    /// Multiply by a scalar.
    pub fn scale(&self, s: f64) -> SparseMultivector {
        self.map(|_, x| x * s)
    }

    /// `self + s o`.
    pub fn add_scaled(&self, o: &SparseMultivector, s: f64) -> SparseMultivector {
        let mut out = self.clone();
        for (&b, &y) in &o.c {
            let x = out.get(b) + s * y;
            out.set(b, x);
        }
        out
    }

    /// `<self rev(self)>_0`.
    pub fn norm_squared(&self) -> f64 {
        self.scalar_product(&self.rev())
    }

    /// `sqrt(|<self rev(self)>_0|)`.
    pub fn norm(&self) -> f64 {
        self.norm_squared().abs().sqrt()
    }

    /// Largest absolute coefficient.
    pub fn max_abs(&self) -> f64 {
        self.c.values().fold(0.0f64, |a, &x| a.max(x.abs()))
    }

    /// Largest absolute coefficient difference.
    pub fn max_diff(&self, o: &SparseMultivector) -> f64 {
        self.add_scaled(o, -1.0).max_abs()
    }

    /// Exponential by scaling and squaring of the Taylor series, as the dense
    /// [`Multivector::exp`](crate::runtime::multivector::Multivector::exp).
    pub fn exp(&self) -> SparseMultivector {
        self.exp_pruned(0.0)
    }

    /// [`exp`](Self::exp) with every product's terms below `rel` times its largest
    /// coefficient dropped as they are made (`rel = 0` drops nothing: `exp` itself).
    ///
    /// In a null basis the rounding of `f64` sums leaves terms of about `1e-17` on blades
    /// whose exact coefficient is zero; every squaring multiplies them into more blades, each
    /// a new blade pair to compute exactly (QCGA's 51-blade translator: 145 blades and 21,000
    /// pairs instead of 51 and 2,600). A `rel` of `1e-13` drops that noise and nothing of
    /// the size a true coefficient has.
    pub fn exp_pruned(&self, rel: f64) -> SparseMultivector {
        let norm: f64 = self.c.values().map(|x| x.abs()).sum();
        let mut k = 0;
        while norm / f64::powi(2.0, k) > 0.25 && k < 60 {
            k += 1;
        }
        let x = self.scale(1.0 / f64::powi(2.0, k));
        let mut sum = SparseMultivector::scalar(&self.alg, 1.0);
        let mut term = SparseMultivector::scalar(&self.alg, 1.0);
        for i in 1..30 {
            term = term.gp(&x).pruned(rel).scale(1.0 / i as f64);
            sum = sum.add_scaled(&term, 1.0);
            if term.max_abs() < 1e-18 {
                break;
            }
        }
        for _ in 0..k {
            sum = sum.gp(&sum).pruned(rel);
        }
        sum
    }

    /// Without the terms below `rel` times the largest coefficient (`self` for `rel = 0`).
    fn pruned(mut self, rel: f64) -> SparseMultivector {
        if rel > 0.0 {
            let floor = rel * self.max_abs();
            self.c.retain(|_, x| x.abs() >= floor);
        }
        self
    }
}

impl SparseAlgebra {
    /// Whether the metric is degenerate (a vector of its orthogonal basis squares to zero).
    pub fn is_degenerate(&self) -> bool {
        self.blades.squares().iter().any(|d| d.is_zero())
    }
}

impl SparseMultivector {
    /// The coefficients of the blades present, in bitmap order (not all `2^n` of them, as
    /// the dense [`Multivector::coeffs`](crate::runtime::multivector::Multivector::coeffs)).
    pub fn coeffs(&self) -> Vec<f64> {
        self.c.values().copied().collect()
    }

    /// Dual, as the dense [`Multivector::dual`](crate::runtime::multivector::Multivector::dual):
    /// `self * I^-1` for a non-degenerate metric, the right complement (`e_A` to `s e_(~A)`
    /// with `e_A ^ s e_(~A) = I`) for a degenerate one.
    pub fn dual(&self) -> SparseMultivector {
        let full: Bitmap = ((1u64 << self.alg.dim()) - 1) as Bitmap;
        if self.alg.is_degenerate() {
            let mut out = SparseMultivector::zero(&self.alg);
            for (&a, &x) in &self.c {
                let comp = full & !a;
                let y = out.get(comp) + reorder_sign(a, comp) as f64 * x;
                out.set(comp, y);
            }
            out
        } else {
            let i = SparseMultivector::blade(&self.alg, full, 1.0);
            let ii = i.norm_squared();
            self.gp(&i.rev().scale(1.0 / ii))
        }
    }

    /// The inverse of a versor (of any element whose `self ~self` is a scalar):
    /// `~self / (self ~self)`, which then is a true inverse. `None` when a coefficient is not
    /// finite, or `self ~self` is not a scalar (another grade above `1e-9` relative) or is
    /// zero. (The dense [`Multivector::inverse`](crate::runtime::multivector::Multivector::inverse)
    /// solves the `2^n x 2^n` system of left multiplication instead, for any element.)
    pub fn inverse(&self) -> Option<SparseMultivector> {
        if self.c.values().any(|x| !x.is_finite()) {
            return None;
        }
        let r = self.rev();
        let n = self.gp(&r);
        let s = n.get(0);
        let scale = self.max_abs() * self.max_abs();
        let others = n.add_scaled(&SparseMultivector::scalar(&self.alg, s), -1.0);
        if scale == 0.0 || s.abs() < 1e-13 * scale || others.max_abs() > 1e-9 * scale {
            return None;
        }
        let inv = r.scale(1.0 / s);
        inv.c.values().all(|x| x.is_finite()).then_some(inv)
    }
}

impl std::ops::Add for &SparseMultivector {
    type Output = SparseMultivector;
    fn add(self, o: &SparseMultivector) -> SparseMultivector {
        self.add_scaled(o, 1.0)
    }
}

impl std::ops::Sub for &SparseMultivector {
    type Output = SparseMultivector;
    fn sub(self, o: &SparseMultivector) -> SparseMultivector {
        self.add_scaled(o, -1.0)
    }
}

impl std::ops::Neg for &SparseMultivector {
    type Output = SparseMultivector;
    fn neg(self) -> SparseMultivector {
        self.scale(-1.0)
    }
}

impl std::ops::Mul for &SparseMultivector {
    type Output = SparseMultivector;
    fn mul(self, o: &SparseMultivector) -> SparseMultivector {
        self.gp(o)
    }
}
