//! Exact products of basis blades one pair at a time, in any metric (null bases included),
//! without the table of the whole algebra.
//!
//! The metric is diagonalised by congruence once (an `n x n` problem), and each blade is
//! expanded in the orthogonal basis (and back) only when a product asks for it, then
//! memoised. A product of two blades costs the sizes of their expansions, never `2^n`. The
//! dense [`Algebra`](crate::runtime::algebra::Algebra) builds its whole table with it.

use crate::runtime::algebra::{add_term, checked_wedge, invert, signed, Exact};
use crate::runtime::blade::{reorder_sign, Bitmap};
use crate::runtime::metric::Metric;
use crate::runtime::rational::Rational;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

/// The orthogonal basis of a metric and the blade expansions computed so far.
#[derive(Debug)]
pub struct BladeProducts {
    /// `to_f_rows[i]`: basis vector `e_i` in the orthogonal basis.
    to_f_rows: Vec<Exact>,
    /// `to_e_rows[k]`: orthogonal vector `f_k` in the user's basis.
    to_e_rows: Vec<Exact>,
    squares: Vec<Rational>,
    to_f: Mutex<HashMap<Bitmap, Arc<Exact>>>,
    to_e: Mutex<HashMap<Bitmap, Arc<Exact>>>,
}

/// Rows of a matrix as sparse vectors (`row[k]` multiplies basis vector `k`).
fn sparse_rows(m: &[Vec<Rational>]) -> Vec<Exact> {
    m.iter()
        .map(|row| {
            row.iter()
                .enumerate()
                .filter(|(_, c)| !c.is_zero())
                .map(|(k, &c)| (1 << k, c))
                .collect()
        })
        .collect()
}

/// The outer product of the vectors `rows[i]` for every bit `i` of `b`, memoised in `memo`
/// (shared, not copied, by every product that asks for it).
fn expand(
    rows: &[Exact],
    memo: &Mutex<HashMap<Bitmap, Arc<Exact>>>,
    b: Bitmap,
) -> Option<Arc<Exact>> {
    if let Some(x) = memo.lock().ok()?.get(&b) {
        return Some(x.clone());
    }
    let x = if b == 0 {
        Arc::new(Exact::from([(0, Rational::ONE)]))
    } else {
        let i = b.trailing_zeros() as usize;
        let rest = expand(rows, memo, b & !(1 << i))?;
        Arc::new(checked_wedge(&rows[i], &rest)?)
    };
    memo.lock().ok()?.insert(b, x.clone());
    Some(x)
}

impl BladeProducts {
    /// The orthogonal basis of `metric`; `None` when exact arithmetic overflows.
    pub fn new(metric: &Metric) -> Option<BladeProducts> {
        let (p, squares) = metric.checked_orthogonal_basis()?;
        let q = invert(&p)?;
        Some(BladeProducts {
            to_f_rows: sparse_rows(&q),
            to_e_rows: sparse_rows(&p),
            squares,
            to_f: Mutex::new(HashMap::new()),
            to_e: Mutex::new(HashMap::new()),
        })
    }

    /// The squares of the orthogonal basis vectors (a zero for each degenerate direction).
    pub fn squares(&self) -> &[Rational] {
        &self.squares
    }

    /// Blade `e_a` of the user's basis in the orthogonal basis; `None` on overflow.
    pub fn to_orthogonal(&self, a: Bitmap) -> Option<Arc<Exact>> {
        expand(&self.to_f_rows, &self.to_f, a)
    }

    /// Orthogonal blade `f_k` in the user's basis; `None` on overflow.
    pub fn to_user(&self, k: Bitmap) -> Option<Arc<Exact>> {
        expand(&self.to_e_rows, &self.to_e, k)
    }

    /// The exact product `e_a e_b`, zero terms dropped; `None` on overflow.
    pub fn product(&self, a: Bitmap, b: Bitmap) -> Option<Exact> {
        let (fa, fb) = (self.to_orthogonal(a)?, self.to_orthogonal(b)?);
        let mut prod_f = Exact::new();
        for (&x, &cx) in fa.iter() {
            for (&y, &cy) in fb.iter() {
                let mut c = signed(cx.checked_mul(cy)?, reorder_sign(x, y));
                let common = x & y;
                for (k, dk) in self.squares.iter().enumerate() {
                    if common & (1 << k) != 0 {
                        c = c.checked_mul(*dk)?;
                    }
                }
                add_term(&mut prod_f, x ^ y, c)?;
            }
        }
        let mut prod_e = Exact::new();
        for (&k, &c) in &prod_f {
            for (&e, &ce) in self.to_user(k)?.iter() {
                add_term(&mut prod_e, e, c.checked_mul(ce)?)?;
            }
        }
        Some(prod_e)
    }
}

#[cfg(all(test, feature = "codegen"))]
mod tests {
    use super::*;
    use crate::generator::spec::RawSpec;
    use crate::generator::symbolic::BladeTable;
    use crate::runtime::blade::parse_blade;

    /// The generator's route (Chevalley's recursion in the user's basis) and this one (a
    /// change to an orthogonal basis) agree exactly on every pair of the DCGA types' blades.
    #[test]
    fn agrees_with_chevalley_on_every_dcga_blade_pair() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/dcga.toml");
        let raw: RawSpec = toml::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let metric = Metric::from_f64(raw.basis.clone(), raw.metric.as_ref().unwrap()).unwrap();
        let mut chevalley = BladeTable::new(&metric);
        let congruence = BladeProducts::new(&metric).unwrap();
        let mut blades: Vec<Bitmap> = raw
            .types
            .iter()
            .flat_map(|t| t.blades.iter())
            .filter(|b| b.as_str() != "s")
            .map(|b| parse_blade(b, &raw.basis).unwrap().0)
            .chain([0])
            .collect();
        blades.sort_unstable();
        blades.dedup();
        assert!(blades.len() > 100, "{}", blades.len());
        for &a in &blades {
            for &b in &blades {
                assert_eq!(
                    chevalley.gp(a, b),
                    congruence.product(a, b).unwrap(),
                    "{a:#b} {b:#b}"
                );
            }
        }
    }
}
