//! The slow generic multivector: dense `2^n` coefficients over any metric.
//!
//! It is slow on purpose and simple enough to trust: every product is the blade table of
//! [`Algebra`] applied term by term, and the other products are grade selections of it. Every
//! function the generator emits is tested against it.

use crate::runtime::algebra::Algebra;
use crate::runtime::blade::{grade, involute_sign, reorder_sign, reverse_sign, Bitmap, Keep};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::Arc;

/// A general multivector of an [`Algebra`]; coefficient `k` multiplies the blade whose
/// bitmap is `k` (basis vector `i` is bit `i`).
#[derive(Clone)]
pub struct Multivector {
    alg: Arc<Algebra>,
    c: Vec<f64>,
}

impl fmt::Debug for Multivector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (b, &x) in self.c.iter().enumerate() {
            if x != 0.0 {
                if !first {
                    write!(f, " + ")?;
                }
                write!(f, "{x}*{}", self.alg.blade_name(b as Bitmap))?;
                first = false;
            }
        }
        if first {
            write!(f, "0")?;
        }
        Ok(())
    }
}

impl PartialEq for Multivector {
    fn eq(&self, o: &Multivector) -> bool {
        Arc::ptr_eq(&self.alg, &o.alg) && self.c == o.c
    }
}

impl Multivector {
    /// Zero.
    pub fn zero(alg: &Arc<Algebra>) -> Multivector {
        Multivector {
            alg: alg.clone(),
            c: vec![0.0; alg.size()],
        }
    }

    /// A scalar.
    pub fn scalar(alg: &Arc<Algebra>, s: f64) -> Multivector {
        let mut m = Multivector::zero(alg);
        m.c[0] = s;
        m
    }

    /// A single blade `x * e_b`.
    ///
    /// # Panics
    /// When `b` names a basis vector past the algebra's (as [`Multivector::get`] and
    /// [`Multivector::set`]).
    pub fn blade(alg: &Arc<Algebra>, b: Bitmap, x: f64) -> Multivector {
        let mut m = Multivector::zero(alg);
        m.c[b as usize] = x;
        m
    }

    /// From coefficients in bitmap order; `None` if the length is not `2^n`.
    pub fn from_coeffs(alg: &Arc<Algebra>, c: Vec<f64>) -> Option<Multivector> {
        (c.len() == alg.size()).then(|| Multivector {
            alg: alg.clone(),
            c,
        })
    }

    /// The algebra.
    pub fn algebra(&self) -> &Arc<Algebra> {
        &self.alg
    }

    /// Coefficients in bitmap order.
    pub fn coeffs(&self) -> &[f64] {
        &self.c
    }

    /// Coefficient of blade `b` (in canonical basis order).
    pub fn get(&self, b: Bitmap) -> f64 {
        self.c[b as usize]
    }

    /// Set the coefficient of blade `b`.
    pub fn set(&mut self, b: Bitmap, x: f64) {
        self.c[b as usize] = x;
    }

    /// Coefficient of a blade by name in any basis order (`e31` gives `-get(e13)`).
    pub fn get_named(&self, name: &str) -> Option<f64> {
        let (b, s) = self.alg.parse_blade(name)?;
        Some(s as f64 * self.c[b as usize])
    }

    fn product(&self, o: &Multivector, keep: Keep) -> Multivector {
        self.same_algebra(o);
        let mut out = Multivector::zero(&self.alg);
        for (a, &x) in self.c.iter().enumerate() {
            if x == 0.0 {
                continue;
            }
            for (b, &y) in o.c.iter().enumerate() {
                if y == 0.0 {
                    continue;
                }
                let (ga, gb) = (grade(a as Bitmap), grade(b as Bitmap));
                for &(k, c) in self.alg.gp_blades(a as Bitmap, b as Bitmap) {
                    if keep.keeps(ga, gb, grade(k)) {
                        out.c[k as usize] += c * x * y;
                    }
                }
            }
        }
        out
    }

    /// Panics unless `o` is of this algebra (the same one, or one of the same metric): a
    /// product, sum or difference across algebras has no meaning, and was read through one
    /// operand's table (a wrong answer, or an index past it).
    fn same_algebra(&self, o: &Multivector) {
        assert!(
            Arc::ptr_eq(&self.alg, &o.alg) || self.alg.metric() == o.alg.metric(),
            "multivectors of two different algebras ({} and {} basis vectors, or other metrics)",
            self.alg.metric().dim(),
            o.alg.metric().dim()
        );
    }

    /// Geometric product.
    ///
    /// # Panics
    /// When `o` is of another algebra (so do every product, `+`, `-` and
    /// [`Multivector::max_diff`]).
    pub fn gp(&self, o: &Multivector) -> Multivector {
        self.product(o, Keep::All)
    }

    /// Outer (wedge) product.
    pub fn outer(&self, o: &Multivector) -> Multivector {
        self.product(o, Keep::Outer)
    }

    /// Left contraction `self ⌋ o`.
    pub fn left_contraction(&self, o: &Multivector) -> Multivector {
        self.product(o, Keep::Left)
    }

    /// Right contraction `self ⌊ o`.
    pub fn right_contraction(&self, o: &Multivector) -> Multivector {
        self.product(o, Keep::Right)
    }

    /// Scalar product `<self o>_0`.
    pub fn scalar_product(&self, o: &Multivector) -> f64 {
        self.product(o, Keep::Scalar).c[0]
    }

    fn map_signs(&self, f: impl Fn(Bitmap) -> i32) -> Multivector {
        let mut out = self.clone();
        for (b, x) in out.c.iter_mut().enumerate() {
            *x *= f(b as Bitmap) as f64;
        }
        out
    }

    /// Reverse.
    pub fn rev(&self) -> Multivector {
        self.map_signs(reverse_sign)
    }

    /// Grade involution.
    pub fn involute(&self) -> Multivector {
        self.map_signs(involute_sign)
    }

    /// Clifford conjugate (reverse of the grade involution).
    pub fn conjugate(&self) -> Multivector {
        self.map_signs(|b| reverse_sign(b) * involute_sign(b))
    }

    /// Grade-`k` part.
    pub fn grade(&self, k: u32) -> Multivector {
        self.map_signs(|b| (grade(b) == k) as i32)
    }

    /// Multiply by a scalar.
    pub fn scale(&self, s: f64) -> Multivector {
        let mut out = self.clone();
        for x in out.c.iter_mut() {
            *x *= s;
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

    /// The unit pseudoscalar `e_{0..n-1}` (outer product of the basis in order).
    pub fn pseudoscalar(alg: &Arc<Algebra>) -> Multivector {
        Multivector::blade(alg, (alg.size() - 1) as Bitmap, 1.0)
    }

    /// Dual. For a non-degenerate metric `self * I^-1` with `I` the pseudoscalar (as in the
    /// Python `clifford` package). For a degenerate metric `I^-1` does not exist and the
    /// right complement is used instead: each blade `e_A` maps to `s e_(~A)` with
    /// `e_A ^ s e_(~A) = I` (the Poincaré dual of PGA).
    pub fn dual(&self) -> Multivector {
        let full = (self.alg.size() - 1) as Bitmap;
        if self.alg.is_degenerate() {
            let mut out = Multivector::zero(&self.alg);
            for (a, &x) in self.c.iter().enumerate() {
                let a = a as Bitmap;
                let comp = full & !a;
                out.c[comp as usize] += reorder_sign(a, comp) as f64 * x;
            }
            out
        } else {
            let i = Multivector::pseudoscalar(&self.alg);
            let ii = i.norm_squared();
            self.gp(&i.rev().scale(1.0 / ii))
        }
    }

    /// The matrix of `x -> self * x` in bitmap order (row = output blade).
    fn left_matrix(&self) -> Vec<Vec<f64>> {
        let n = self.alg.size();
        let mut m = vec![vec![0.0; n]; n];
        for (a, &x) in self.c.iter().enumerate() {
            if x == 0.0 {
                continue;
            }
            for (b, col) in (0..n).enumerate() {
                for &(k, c) in self.alg.gp_blades(a as Bitmap, b as Bitmap) {
                    m[k as usize][col] += c * x;
                }
            }
        }
        m
    }

    /// The inverse `y` with `self * y = 1`, found by solving the linear system of left
    /// multiplication; `None` when it is singular (relative pivot below 1e-13), when a
    /// coefficient is not finite, or when the inverse overflows.
    pub fn inverse(&self) -> Option<Multivector> {
        if self.c.iter().any(|x| !x.is_finite()) {
            return None;
        }
        let n = self.alg.size();
        let mut m = self.left_matrix();
        let scale = m
            .iter()
            .flat_map(|r| r.iter())
            .fold(0.0f64, |a, &x| a.max(x.abs()));
        if scale == 0.0 || !scale.is_finite() {
            return None;
        }
        let mut rhs = vec![0.0; n];
        rhs[0] = 1.0;
        for col in 0..n {
            let p = (col..n).max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs()))?;
            if m[p][col].abs() < 1e-13 * scale {
                return None;
            }
            m.swap(col, p);
            rhs.swap(col, p);
            for r in (col + 1)..n {
                let f = m[r][col] / m[col][col];
                if f != 0.0 {
                    for j in col..n {
                        m[r][j] -= f * m[col][j];
                    }
                    rhs[r] -= f * rhs[col];
                }
            }
        }
        let mut x = vec![0.0; n];
        for r in (0..n).rev() {
            let mut s = rhs[r];
            for j in (r + 1)..n {
                s -= m[r][j] * x[j];
            }
            x[r] = s / m[r][r];
        }
        if x.iter().any(|v| !v.is_finite()) {
            return None;
        }
        Some(Multivector {
            alg: self.alg.clone(),
            c: x,
        })
    }

    /// Largest absolute coefficient.
    pub fn max_abs(&self) -> f64 {
        self.c.iter().fold(0.0f64, |a, &x| a.max(x.abs()))
    }

    /// Exponential by scaling and squaring of the Taylor series (slow, general).
    ///
    /// Accuracy: each of the `k` squarings (about `log2` of the coefficients' sum) doubles the
    /// rounding error, so the result is good to about `eps * norm`: an oracle for arguments
    /// up to about 1e6, not for 1e18 (whose angle `f64` does not hold anyway).
    pub fn exp(&self) -> Multivector {
        let norm: f64 = self.c.iter().map(|x| x.abs()).sum();
        let mut k = 0;
        while norm / f64::powi(2.0, k) > 0.25 && k < 60 {
            k += 1;
        }
        let x = self.scale(1.0 / f64::powi(2.0, k));
        let mut sum = Multivector::scalar(&self.alg, 1.0);
        let mut term = Multivector::scalar(&self.alg, 1.0);
        for i in 1..30 {
            term = term.gp(&x).scale(1.0 / i as f64);
            sum = &sum + &term;
            if term.max_abs() < 1e-18 {
                break;
            }
        }
        for _ in 0..k {
            sum = sum.gp(&sum);
        }
        sum
    }

    /// Largest absolute coefficient difference.
    pub fn max_diff(&self, o: &Multivector) -> f64 {
        self.same_algebra(o);
        self.c
            .iter()
            .zip(&o.c)
            .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()))
    }
}

impl Add for &Multivector {
    type Output = Multivector;
    fn add(self, o: &Multivector) -> Multivector {
        self.same_algebra(o);
        let mut out = self.clone();
        for (x, y) in out.c.iter_mut().zip(&o.c) {
            *x += y;
        }
        out
    }
}

impl Sub for &Multivector {
    type Output = Multivector;
    fn sub(self, o: &Multivector) -> Multivector {
        self.same_algebra(o);
        let mut out = self.clone();
        for (x, y) in out.c.iter_mut().zip(&o.c) {
            *x -= y;
        }
        out
    }
}

impl Neg for &Multivector {
    type Output = Multivector;
    fn neg(self) -> Multivector {
        self.scale(-1.0)
    }
}

impl Mul for &Multivector {
    type Output = Multivector;
    fn mul(self, o: &Multivector) -> Multivector {
        self.gp(o)
    }
}
