//! A geometric algebra at run time: basis, metric and the geometric product of basis blades.
//!
//! The product table here is derived independently of the symbolic engine: the metric is
//! diagonalised by congruence (exact rationals), blades are mapped to the orthogonal basis by
//! the outermorphism, multiplied with the diagonal bitmap rule, and mapped back
//! ([`BladeProducts`], which the sparse reference shares). The symbolic
//! engine instead expands products directly in the user's basis (Chevalley's recursion), so
//! the two routes check each other.

use crate::runtime::blade::{grade, reorder_sign, Bitmap};
use crate::runtime::metric::{Metric, MetricError};
use crate::runtime::rational::Rational;
use crate::runtime::sparse::blades::BladeProducts;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A sparse multivector with exact coefficients, keyed by blade bitmap.
pub(crate) type Exact = BTreeMap<Bitmap, Rational>;

/// An algebra: its metric and the exact product table of its basis blades.
#[derive(Debug)]
pub struct Algebra {
    metric: Metric,
    size: usize,
    /// `table[a * size + b]`: the non-zero terms of `e_a e_b`.
    table: Vec<Vec<(Bitmap, f64)>>,
    degenerate: bool,
}

/// `m[b] += c`, dropping the term if it cancels; `None` on overflow.
pub(crate) fn add_term(m: &mut Exact, b: Bitmap, c: Rational) -> Option<()> {
    if c.is_zero() {
        return Some(());
    }
    let e = m.entry(b).or_insert(Rational::ZERO);
    *e = e.checked_add(c)?;
    if e.is_zero() {
        m.remove(&b);
    }
    Some(())
}

/// `c * (-1 or 1)`.
pub(crate) fn signed(c: Rational, sign: i32) -> Rational {
    if sign < 0 {
        -c
    } else {
        c
    }
}

/// Metric-free outer product of two sparse multivectors in an outer-product basis, or `None`
/// when exact arithmetic overflows.
pub(crate) fn checked_wedge(x: &Exact, y: &Exact) -> Option<Exact> {
    let mut out = Exact::new();
    for (&a, &ca) in x {
        for (&b, &cb) in y {
            if a & b == 0 {
                add_term(
                    &mut out,
                    a | b,
                    signed(ca.checked_mul(cb)?, reorder_sign(a, b)),
                )?;
            }
        }
    }
    Some(out)
}

pub(crate) fn invert(m: &[Vec<Rational>]) -> Option<Vec<Vec<Rational>>> {
    let n = m.len();
    let mut a: Vec<Vec<Rational>> = m.to_vec();
    let mut inv = Rational::identity_matrix(n);
    for col in 0..n {
        // The congruence transform is invertible, so a pivot always exists.
        let p = (col..n).find(|&r| !a[r][col].is_zero())?;
        a.swap(col, p);
        inv.swap(col, p);
        let pv = a[col][col];
        for j in 0..n {
            a[col][j] = a[col][j].checked_div(pv)?;
            inv[col][j] = inv[col][j].checked_div(pv)?;
        }
        for r in 0..n {
            if r != col && !a[r][col].is_zero() {
                let f = a[r][col];
                for j in 0..n {
                    a[r][j] = a[r][j].checked_sub(f.checked_mul(a[col][j])?)?;
                    inv[r][j] = inv[r][j].checked_sub(f.checked_mul(inv[col][j])?)?;
                }
            }
        }
    }
    Some(inv)
}

/// The exact geometric product of every pair of basis blades of a metric, by congruence:
/// `table[a * 2^n + b]` holds the non-zero terms of `e_a e_b`, and the squares of the
/// orthogonal basis come second. `None` when exact arithmetic overflows.
pub(crate) fn exact_products(metric: &Metric) -> Option<(Vec<Exact>, Vec<Rational>)> {
    let size = 1u32 << metric.dim();
    let c = BladeProducts::new(metric)?;
    let mut table = Vec::with_capacity((size * size) as usize);
    for a in 0..size {
        for b in 0..size {
            table.push(c.product(a, b)?);
        }
    }
    Some((table, c.squares().to_vec()))
}

impl Algebra {
    /// Build the algebra of a metric. Panics when exact arithmetic overflows, which a metric
    /// of a validated spec never does; [`Algebra::try_new`] reports it instead.
    pub fn new(metric: Metric) -> Arc<Algebra> {
        Algebra::try_new(metric).expect("the metric's exact products fit in 128 bits")
    }

    /// Build the algebra of a metric, or say which entry makes exact products overflow.
    pub fn try_new(metric: Metric) -> Result<Arc<Algebra>, MetricError> {
        let Some((exact, d)) = exact_products(&metric) else {
            return Err(metric.overflow_error());
        };
        let size = 1usize << metric.dim();
        let table = exact
            .into_iter()
            .map(|m| m.into_iter().map(|(k, c)| (k, c.to_f64())).collect())
            .collect();
        let degenerate = d.iter().any(|x| x.is_zero());
        Ok(Arc::new(Algebra {
            metric,
            size,
            table,
            degenerate,
        }))
    }

    /// Build from basis names and `f64` metric entries (each read as the decimal it prints
    /// as, and held exactly).
    pub fn from_metric(names: &[&str], g: &[Vec<f64>]) -> Result<Arc<Algebra>, MetricError> {
        let metric = Metric::from_f64(names.iter().map(|s| s.to_string()).collect(), g)?;
        Algebra::try_new(metric)
    }

    /// The metric.
    pub fn metric(&self) -> &Metric {
        &self.metric
    }

    /// Number of basis vectors.
    pub fn dim(&self) -> usize {
        self.metric.dim()
    }

    /// Number of blades, `2^dim`.
    pub fn size(&self) -> usize {
        self.size
    }

    /// True when some vector is orthogonal to every vector (a zero square after
    /// diagonalisation), as in PGA.
    pub fn is_degenerate(&self) -> bool {
        self.degenerate
    }

    /// The non-zero terms of the geometric product of blades `a` and `b`.
    ///
    /// # Panics
    /// When `a` or `b` names a basis vector past the algebra's (it read another row).
    pub fn gp_blades(&self, a: Bitmap, b: Bitmap) -> &[(Bitmap, f64)] {
        assert!(
            (a as usize) < self.size && (b as usize) < self.size,
            "blades {a:#b} and {b:#b} in an algebra of {} blades",
            self.size
        );
        &self.table[a as usize * self.size + b as usize]
    }

    /// Canonical blade name.
    pub fn blade_name(&self, b: Bitmap) -> String {
        crate::runtime::blade::blade_name(b, self.metric.names())
    }

    /// Bitmap and sign of a blade name in any basis order.
    pub fn parse_blade(&self, name: &str) -> Option<(Bitmap, i32)> {
        crate::runtime::blade::parse_blade(name, self.metric.names()).ok()
    }

    /// Grade of blade `b`.
    pub fn grade(&self, b: Bitmap) -> u32 {
        grade(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn null_basis_products() {
        let z = 0.0;
        let alg = Algebra::from_metric(
            &["eo", "e1", "e2", "e3", "ei"],
            &[
                vec![z, z, z, z, -1.0],
                vec![z, 1.0, z, z, z],
                vec![z, z, 1.0, z, z],
                vec![z, z, z, 1.0, z],
                vec![-1.0, z, z, z, z],
            ],
        )
        .unwrap();
        let eo = 1;
        let ei = 16;
        // eo ei = -1 + eo^ei ; ei eo = -1 - eo^ei ; eo eo = 0
        assert_eq!(alg.gp_blades(eo, ei), &[(0, -1.0), (17, 1.0)]);
        assert_eq!(alg.gp_blades(ei, eo), &[(0, -1.0), (17, -1.0)]);
        assert!(alg.gp_blades(eo, eo).is_empty());
        // (eo^ei)^2 = 1
        assert_eq!(alg.gp_blades(17, 17), &[(0, 1.0)]);
    }

    #[test]
    fn overflowing_metrics_are_errors() {
        let e = Algebra::from_metric(&["e1", "e2", "e3"], &diag(&[1e13, 1e13, 1e13])).unwrap_err();
        assert!(matches!(e, MetricError::Overflow { .. }), "{e}");
        let e = Algebra::from_metric(&["e1", "e2", "e3"], &diag(&[1e30, 1e30, 1.0])).unwrap_err();
        assert!(matches!(e, MetricError::Overflow { i: 0, j: 0, .. }), "{e}");
        let third = 0.3333333333333333;
        let e =
            Algebra::from_metric(&["e1", "e2", "e3"], &diag(&[third, third, third])).unwrap_err();
        assert!(matches!(e, MetricError::Overflow { .. }), "{e}");
    }

    #[test]
    fn decimal_metrics_are_exact() {
        let alg = Algebra::from_metric(&["e1", "e2", "e3"], &diag(&[0.1, 0.3, 0.7])).unwrap();
        // e123 e123 = -(0.1 * 0.3 * 0.7) = -0.021, exactly as a decimal.
        assert_eq!(alg.gp_blades(7, 7), &[(0, -0.021)]);
        assert_eq!(alg.gp_blades(3, 3), &[(0, -0.03)]);
        let alg = Algebra::from_metric(
            &["e1", "e2", "e3"],
            &[
                vec![0.1, 0.3, 0.0],
                vec![0.3, 0.1, 0.0],
                vec![0.0, 0.0, 0.3],
            ],
        )
        .unwrap();
        // e1 e2 = 0.3 + e12 ; (e12)^2 = (g12)^2 - g11 g22 = 0.09 - 0.01 = 0.08
        assert_eq!(alg.gp_blades(1, 2), &[(0, 0.3), (3, 1.0)]);
        assert_eq!(alg.gp_blades(3, 3), &[(0, 0.08)]);
    }

    fn diag(d: &[f64]) -> Vec<Vec<f64>> {
        (0..d.len())
            .map(|i| {
                (0..d.len())
                    .map(|j| if i == j { d[i] } else { 0.0 })
                    .collect()
            })
            .collect()
    }
}
