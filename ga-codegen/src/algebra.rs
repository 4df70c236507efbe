//! A geometric algebra at run time: basis, metric and the geometric product of basis blades.
//!
//! The product table here is derived independently of the symbolic engine: the metric is
//! diagonalised by congruence (exact rationals), blades are mapped to the orthogonal basis by
//! the outermorphism, multiplied with the diagonal bitmap rule, and mapped back. The symbolic
//! engine instead expands products directly in the user's basis (Chevalley's recursion), so
//! the two routes check each other.

use crate::blade::{grade, reorder_sign, Bitmap};
use crate::metric::{Metric, MetricError};
use crate::rational::Rational;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A sparse multivector with exact coefficients, keyed by blade bitmap.
pub type Exact = BTreeMap<Bitmap, Rational>;

/// An algebra: its metric and the exact product table of its basis blades.
#[derive(Debug)]
pub struct Algebra {
    metric: Metric,
    size: usize,
    /// `table[a * size + b]`: the non-zero terms of `e_a e_b`.
    table: Vec<Vec<(Bitmap, f64)>>,
    degenerate: bool,
}

fn add_term(m: &mut Exact, b: Bitmap, c: Rational) {
    if c.is_zero() {
        return;
    }
    let e = m.entry(b).or_insert(Rational::ZERO);
    *e = *e + c;
    if e.is_zero() {
        m.remove(&b);
    }
}

/// Metric-free outer product of two sparse multivectors in an outer-product basis.
pub fn wedge(x: &Exact, y: &Exact) -> Exact {
    let mut out = Exact::new();
    for (&a, &ca) in x {
        for (&b, &cb) in y {
            if a & b == 0 {
                add_term(
                    &mut out,
                    a | b,
                    ca * cb * Rational::int(reorder_sign(a, b) as i64),
                );
            }
        }
    }
    out
}

fn invert(m: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    let n = m.len();
    let mut a: Vec<Vec<Rational>> = m.to_vec();
    let mut inv: Vec<Vec<Rational>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    if i == j {
                        Rational::ONE
                    } else {
                        Rational::ZERO
                    }
                })
                .collect()
        })
        .collect();
    for col in 0..n {
        let p = (col..n)
            .find(|&r| !a[r][col].is_zero())
            .expect("congruence transform is invertible");
        a.swap(col, p);
        inv.swap(col, p);
        let pv = a[col][col];
        for j in 0..n {
            a[col][j] = a[col][j] / pv;
            inv[col][j] = inv[col][j] / pv;
        }
        for r in 0..n {
            if r != col && !a[r][col].is_zero() {
                let f = a[r][col];
                for j in 0..n {
                    a[r][j] = a[r][j] - f * a[col][j];
                    inv[r][j] = inv[r][j] - f * inv[col][j];
                }
            }
        }
    }
    inv
}

/// Express each outer-basis blade of one basis in another, given vectors `rows[i]` =
/// coordinates of old basis vector `i` in the new basis.
fn blade_transform(rows: &[Vec<Rational>]) -> Vec<Exact> {
    let n = rows.len();
    (0..(1u32 << n))
        .map(|b| {
            let mut acc = Exact::new();
            acc.insert(0, Rational::ONE);
            for (i, row) in rows.iter().enumerate() {
                if b & (1 << i) != 0 {
                    let mut v = Exact::new();
                    for (k, &c) in row.iter().enumerate() {
                        add_term(&mut v, 1 << k, c);
                    }
                    acc = wedge(&acc, &v);
                }
            }
            acc
        })
        .collect()
}

impl Algebra {
    /// Build the algebra of a metric.
    pub fn new(metric: Metric) -> Arc<Algebra> {
        let n = metric.dim();
        let size = 1usize << n;
        let (p, d) = metric.orthogonal_basis();
        let q = invert(&p);
        // e_i = sum_k q[i][k] f_k ; f_k = sum_i p[k][i] e_i
        let to_f = blade_transform(&q);
        let to_e = blade_transform(&p);
        let mut table = vec![Vec::new(); size * size];
        for a in 0..size {
            for b in 0..size {
                let mut prod_f = Exact::new();
                for (&fa, &ca) in &to_f[a] {
                    for (&fb, &cb) in &to_f[b] {
                        let mut c = ca * cb * Rational::int(reorder_sign(fa, fb) as i64);
                        let common = fa & fb;
                        for (k, dk) in d.iter().enumerate() {
                            if common & (1 << k) != 0 {
                                c = c * *dk;
                            }
                        }
                        add_term(&mut prod_f, fa ^ fb, c);
                    }
                }
                let mut prod_e = Exact::new();
                for (&fk, &c) in &prod_f {
                    for (&eb, &ce) in &to_e[fk as usize] {
                        add_term(&mut prod_e, eb, c * ce);
                    }
                }
                table[a * size + b] = prod_e.into_iter().map(|(k, c)| (k, c.to_f64())).collect();
            }
        }
        let degenerate = d.iter().any(|x| x.is_zero());
        Arc::new(Algebra {
            metric,
            size,
            table,
            degenerate,
        })
    }

    /// Build from basis names and `f64` metric entries (each must be exactly representable).
    pub fn from_metric(names: &[&str], g: &[Vec<f64>]) -> Result<Arc<Algebra>, MetricError> {
        let metric = Metric::from_f64(names.iter().map(|s| s.to_string()).collect(), g)?;
        Ok(Algebra::new(metric))
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
    pub fn gp_blades(&self, a: Bitmap, b: Bitmap) -> &[(Bitmap, f64)] {
        &self.table[a as usize * self.size + b as usize]
    }

    /// Canonical blade name.
    pub fn blade_name(&self, b: Bitmap) -> String {
        crate::blade::blade_name(b, self.metric.names())
    }

    /// Bitmap and sign of a blade name in any basis order.
    pub fn parse_blade(&self, name: &str) -> Option<(Bitmap, i32)> {
        crate::blade::parse_blade(name, self.metric.names()).ok()
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
}
