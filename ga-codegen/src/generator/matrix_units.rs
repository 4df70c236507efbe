//! The matrix-unit basis of a Clifford algebra or of its even subalgebra, found at generation
//! time: a dense product costs half its multiplies for each 2 x 2 matrix factor split off.
//!
//! Two blades `u`, `v` of an orthogonal basis with `u u = r^2` (a rational square), `v v = l`
//! (any non-zero rational) and `u v = -v u` span a copy of the 2 x 2 real matrices:
//! `E11 = (1 + u/r)/2`, `E22 = (1 - u/r)/2`, `E12 = E11 v`, `E21 = E22 v / l`, with
//! `Eij Ejk = Eik` and `Eij Ekl = 0` for `j != k`. The blades that commute with both form the
//! algebra `C` beside them (a quarter of the blades), and every element is a 2 x 2 matrix over
//! `C`: its product is 8 products in `C` where the blade form has 16. Repeated while `C` holds
//! such a pair: `G(4,1)` is 4 x 4 matrices over a 2-dimensional `C` (256 multiplies for the full
//! product instead of 1024), its even subalgebra 2 x 2 matrices over the quaternions (128
//! instead of 256). The structure constants in the new basis are computed exactly from the
//! blade products in the user's basis, so null bases and rational metrics need nothing special;
//! degenerate directions simply stay in `C`.

use crate::runtime::algebra::{add_term, invert, Exact};
use crate::runtime::blade::{grade, Bitmap};
use crate::runtime::rational::Rational;
use crate::runtime::sparse::blades::BladeProducts;
use std::collections::BTreeMap;

use super::symbolic::BladeTable;

/// The product of a blade set in its matrix-unit basis.
#[derive(Debug)]
pub(crate) struct MatrixUnits {
    /// The name of each new coordinate (`m12_c3`: row 1, column 2, blade 3 of `C`).
    pub names: Vec<String>,
    /// New coordinate `k` from the blade coordinates: `(blade index in the given order, c)`.
    pub to_units: Vec<Vec<(usize, Rational)>>,
    /// Blade coordinate `b` (in the given order) from the new coordinates: `(k, c)`.
    pub from_units: Vec<Vec<(usize, Rational)>>,
    /// Product terms per new output coordinate: `(i, j, c)` for `c y_i w_j`.
    pub products: Vec<Vec<(usize, usize, Rational)>>,
    /// The size of the matrices (`2^levels`).
    pub size: usize,
    /// Each element of `C` in the user's blades, for docs: `(bitmap, c)` terms.
    pub c_basis: Vec<Exact>,
}

/// The largest type given a matrix form (see [`matrix_units`]).
const MAX_COORDINATES: usize = 64;

/// `sqrt(q)` when `q` is the square of a positive rational.
fn rational_sqrt(q: Rational) -> Option<Rational> {
    if q <= Rational::ZERO {
        return None;
    }
    let root = |n: i128| -> Option<i128> {
        let r = (n as f64).sqrt().round() as i128;
        (r - 1..=r + 1).find(|&x| x >= 0 && x.checked_mul(x) == Some(n))
    };
    Some(Rational::new(root(q.numer())?, root(q.denom())?))
}

/// `G_S G_S` for the blade `S` of an orthogonal basis whose vectors square to `squares` (zero
/// when `S` holds a null vector); `None` on overflow.
fn square(squares: &[Rational], s: Bitmap) -> Option<Rational> {
    let g = grade(s);
    let mut q = if (g * g.saturating_sub(1) / 2).is_multiple_of(2) {
        Rational::ONE
    } else {
        -Rational::ONE
    };
    for (k, &d) in squares.iter().enumerate() {
        if s & (1 << k) != 0 {
            q = q.checked_mul(d)?;
        }
    }
    Some(q)
}

/// True when the blades `S`, `T` of an orthogonal basis commute.
fn commute(s: Bitmap, t: Bitmap) -> bool {
    (grade(s) * grade(t) + grade(s & t)).is_multiple_of(2)
}

/// The exact product of two sparse multivectors in the user's basis; `None` on overflow.
fn product(table: &mut BladeTable, x: &Exact, y: &Exact) -> Option<Exact> {
    let mut out = Exact::new();
    for (&a, &ca) in x {
        for (&b, &cb) in y {
            for (k, c) in table.gp(a, b) {
                add_term(&mut out, k, ca.checked_mul(cb)?.checked_mul(c)?)?;
            }
        }
    }
    Some(out)
}

/// `x * c`; `None` on overflow.
fn scaled(x: &Exact, c: Rational) -> Option<Exact> {
    x.iter()
        .map(|(&b, &v)| Some((b, v.checked_mul(c)?)))
        .collect()
}

/// `x + y`; `None` on overflow.
fn sum(x: &Exact, y: &Exact) -> Option<Exact> {
    let mut out = x.clone();
    for (&b, &v) in y {
        add_term(&mut out, b, v)?;
    }
    Some(out)
}

/// One 2 x 2 factor: the orthogonal blades `u` (square `r^2`) and `v` (square `l`).
struct Split {
    u: Bitmap,
    r: Rational,
    v: Bitmap,
    l: Rational,
}

/// The next split inside `group` (orthogonal blades that commute with every earlier pair), or
/// `None`. The first pair in index order, so the choice is reproducible.
fn next_split(squares: &[Rational], group: &[Bitmap]) -> Option<Split> {
    for &u in group.iter().filter(|&&u| u != 0) {
        let Some(r) = square(squares, u).and_then(rational_sqrt) else {
            continue;
        };
        let found = group.iter().find_map(|&v| {
            let l = square(squares, v).filter(|l| !l.is_zero())?;
            (!commute(u, v)).then_some((v, l))
        });
        if let Some((v, l)) = found {
            return Some(Split { u, r, v, l });
        }
    }
    None
}

/// The matrix-unit basis of the blades `blades` (canonical bitmaps, in field order), or `None`
/// when they are not a whole subalgebra of that kind (every blade, or every even blade), no
/// 2 x 2 factor splits off, or exact arithmetic overflows.
pub(crate) fn matrix_units(table: &mut BladeTable, blades: &[Bitmap]) -> Option<MatrixUnits> {
    let n = table.metric().dim();
    let all: Vec<Bitmap> = (0..1u32 << n).collect();
    let even_only = blades.iter().all(|&b| grade(b).is_multiple_of(2));
    let parity_ok = |s: Bitmap| !even_only || grade(s).is_multiple_of(2);
    let wanted = all.iter().filter(|&&s| parity_ok(s)).count();
    let mut sorted = blades.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    if sorted.len() != blades.len() || blades.len() != wanted || blades.len() < 4 {
        return None;
    }
    // The change of basis is inverted and its structure constants computed densely (`dim^2`
    // products, a `dim^3` inversion): up to 64 coordinates (every blade of six vectors, or the
    // even blades of seven) that stays within milliseconds. Larger types keep the blade form.
    if blades.len() > MAX_COORDINATES {
        return None;
    }
    // The orthogonal basis, its squares and its blades in the user's basis.
    let o = BladeProducts::new(table.metric())?;
    let blade = |s: Bitmap| o.to_user(s).map(|x| (*x).clone());
    let mut group: Vec<Bitmap> = all.into_iter().filter(|&s| parity_ok(s)).collect();
    let mut splits = Vec::new();
    while let Some(s) = next_split(o.squares(), &group) {
        group.retain(|&t| commute(t, s.u) && commute(t, s.v));
        splits.push(s);
    }
    if splits.is_empty() {
        return None;
    }
    // Matrix units of each level: E[i][j] in the user's blades.
    let half = Rational::new(1, 2);
    let mut levels = Vec::new();
    for s in &splits {
        let one: Exact = [(0, Rational::ONE)].into_iter().collect();
        let u = scaled(&blade(s.u)?, Rational::ONE.checked_div(s.r)?)?;
        let v = blade(s.v)?;
        let e11 = scaled(&sum(&one, &u)?, half)?;
        let e22 = scaled(&sum(&one, &scaled(&u, -Rational::ONE)?)?, half)?;
        let e12 = product(table, &e11, &v)?;
        let e21 = scaled(&product(table, &e22, &v)?, Rational::ONE.checked_div(s.l)?)?;
        levels.push([[e11, e12], [e21, e22]]);
    }
    let size = 1usize << splits.len();
    let c_basis: Vec<Exact> = group.iter().map(|&c| blade(c)).collect::<Option<_>>()?;
    // New basis element (row, column, c): the product of each level's unit and `c`.
    let mut names = Vec::new();
    let mut basis = Vec::new();
    for row in 0..size {
        for col in 0..size {
            let mut unit: Exact = [(0, Rational::ONE)].into_iter().collect();
            for (l, level) in levels.iter().enumerate() {
                let (i, j) = ((row >> l) & 1, (col >> l) & 1);
                unit = product(table, &unit, &level[i][j])?;
            }
            for (ci, c) in c_basis.iter().enumerate() {
                basis.push(product(table, &unit, c)?);
                names.push(format!("m{}{}_c{ci}", row + 1, col + 1));
            }
        }
    }
    let index: BTreeMap<Bitmap, usize> = blades.iter().enumerate().map(|(i, &b)| (b, i)).collect();
    let dim = blades.len();
    // T: column k holds basis element k in the blade coordinates.
    let mut t = vec![vec![Rational::ZERO; dim]; dim];
    for (k, f) in basis.iter().enumerate() {
        for (b, &c) in f {
            t[*index.get(b)?][k] = c;
        }
    }
    let t_inv = invert(&t)?;
    let sparse = |m: &[Vec<Rational>]| -> Vec<Vec<(usize, Rational)>> {
        m.iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .filter(|(_, c)| !c.is_zero())
                    .map(|(j, &c)| (j, c))
                    .collect()
            })
            .collect()
    };
    let mut products = vec![Vec::new(); dim];
    for (i, fi) in basis.iter().enumerate() {
        for (j, fj) in basis.iter().enumerate() {
            let p = product(table, fi, fj)?;
            if p.is_empty() {
                continue;
            }
            // Coordinates of the product in the new basis: T^-1 times its blade coordinates.
            for (k, row) in t_inv.iter().enumerate() {
                let mut c = Rational::ZERO;
                for (b, &x) in &p {
                    c = c.checked_add(row[*index.get(b)?].checked_mul(x)?)?;
                }
                if !c.is_zero() {
                    products[k].push((i, j, c));
                }
            }
        }
    }
    Some(MatrixUnits {
        names,
        to_units: sparse(&t_inv),
        from_units: sparse(&t),
        products,
        size,
        c_basis,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::runtime::metric::Metric;

    fn cga() -> Metric {
        Metric::cga_null_basis()
    }

    fn terms(m: &MatrixUnits) -> usize {
        m.products.iter().map(Vec::len).sum()
    }

    #[test]
    fn cga_splits_into_matrices_with_the_expected_multiply_counts() {
        let metric = cga();
        let mut table = BladeTable::new(&metric);
        let all: Vec<Bitmap> = (0..32).collect();
        let m = matrix_units(&mut table, &all).expect("G(4,1) splits");
        // 4 x 4 matrices over a 2-dimensional algebra (the complex numbers).
        assert_eq!((m.size, m.c_basis.len()), (4, 2));
        assert_eq!(terms(&m), 256);
        let even: Vec<Bitmap> = (0..32).filter(|&b| grade(b).is_multiple_of(2)).collect();
        let e = matrix_units(&mut table, &even).expect("its even subalgebra splits");
        // 2 x 2 matrices over the quaternions.
        assert_eq!((e.size, e.c_basis.len()), (2, 4));
        assert_eq!(terms(&e), 128);
    }

    /// The conversions of `m` (the matrix units of `blades`) are inverse to each other, and
    /// every pair of blades multiplied through the new basis gives its blade product (exact).
    fn assert_exact(table: &mut BladeTable, blades: &[Bitmap], m: &MatrixUnits) {
        let even = blades;
        let dim = even.len();
        // to_units after from_units is the identity.
        for k in 0..dim {
            for l in 0..dim {
                let mut c = Rational::ZERO;
                for &(b, x) in &m.to_units[k] {
                    for &(l2, y) in &m.from_units[b] {
                        if l2 == l {
                            c = c + x * y;
                        }
                    }
                }
                let want = if k == l {
                    Rational::ONE
                } else {
                    Rational::ZERO
                };
                assert_eq!(c, want, "({k}, {l})");
            }
        }
        // Two blades multiplied through the new basis give their blade product.
        for (ai, &a) in even.iter().enumerate() {
            for (bi, &b) in even.iter().enumerate() {
                let unit = |i: usize| -> Vec<Rational> {
                    (0..dim)
                        .map(|k| {
                            m.to_units[k]
                                .iter()
                                .filter(|t| t.0 == i)
                                .map(|t| t.1)
                                .fold(Rational::ZERO, |s, c| s + c)
                        })
                        .collect()
                };
                let (y, w) = (unit(ai), unit(bi));
                let z: Vec<Rational> = m
                    .products
                    .iter()
                    .map(|ts| {
                        ts.iter()
                            .fold(Rational::ZERO, |s, &(i, j, c)| s + c * y[i] * w[j])
                    })
                    .collect();
                let want = table.gp(a, b);
                for (bk, &blade) in even.iter().enumerate() {
                    let got = m.from_units[bk]
                        .iter()
                        .fold(Rational::ZERO, |s, &(k, c)| s + c * z[k]);
                    let w = want.get(&blade).copied().unwrap_or(Rational::ZERO);
                    assert_eq!(got, w, "e{a} e{b} on e{blade}");
                }
            }
        }
    }

    #[test]
    fn the_conversions_are_inverse_and_the_table_is_the_product() {
        let metric = cga();
        let mut table = BladeTable::new(&metric);
        let even: Vec<Bitmap> = (0..32).filter(|&b| grade(b).is_multiple_of(2)).collect();
        let m = matrix_units(&mut table, &even).unwrap();
        assert_exact(&mut table, &even, &m);
        let all: Vec<Bitmap> = (0..32).collect();
        let m = matrix_units(&mut table, &all).unwrap();
        assert_exact(&mut table, &all, &m);
    }

    #[test]
    fn a_non_orthogonal_rational_metric_splits_exactly() {
        // Off-diagonal rational entries: the orthogonal squares are 1, 3/4 and a fraction;
        // the split is found in the orthogonalised basis and checked in the user's one.
        let r = |n, d| Rational::new(n, d);
        let z = Rational::ZERO;
        let g = vec![
            vec![Rational::ONE, r(1, 2), z, r(2, 5)],
            vec![r(1, 2), Rational::ONE, r(1, 3), z],
            vec![z, r(1, 3), -Rational::ONE, r(1, 7)],
            vec![r(2, 5), z, r(1, 7), r(3, 2)],
        ];
        let names = ["e1", "e2", "e3", "e4"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let metric = Metric::new(names, g).unwrap();
        let mut table = BladeTable::new(&metric);
        let all: Vec<Bitmap> = (0..16).collect();
        let m = matrix_units(&mut table, &all).expect("1 is a square and 3/4 is not zero");
        assert_exact(&mut table, &all, &m);
    }

    #[test]
    fn degenerate_and_small_algebras() {
        // PGA's even subalgebra has no blade of positive square: no split.
        let pga = Metric::diagonal(
            ["e0", "e1", "e2", "e3"]
                .iter()
                .map(|s| s.to_string())
                .collect(),
            &[Rational::ZERO, Rational::ONE, Rational::ONE, Rational::ONE],
        )
        .unwrap();
        let mut table = BladeTable::new(&pga);
        let even: Vec<Bitmap> = (0..16).filter(|&b| grade(b).is_multiple_of(2)).collect();
        assert!(matrix_units(&mut table, &even).is_none());
        // The whole of PGA splits once; the degenerate direction stays in C.
        let all: Vec<Bitmap> = (0..16).collect();
        let m = matrix_units(&mut table, &all).expect("e1, e2 split off");
        assert_eq!((m.size, m.c_basis.len()), (2, 4));
        // A set that is not a subalgebra of that kind: none.
        assert!(matrix_units(&mut table, &[0, 3, 5, 6, 9]).is_none());
    }
}
