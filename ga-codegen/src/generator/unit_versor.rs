//! Sandwiches of unit versors: grade-preserving and reduced modulo `a ~a = 1`.
//!
//! For a versor `a` with `a ~a = ~a a = 1`, the sandwich `a x ~a` is an outermorphism: it keeps
//! the grades of `x`, and many of its polynomial terms cancel once the identities of
//! `a ~a = 1` are used (the scalar part is 1, every other part is 0). This module finds those
//! identities exactly, as polynomials in the versor's fields ([`UnitIdeal`]), and rewrites
//! every coefficient of a symbolic sandwich into an equivalent one with the fewest terms.
//! Blades whose coefficients become zero (the odd grades of a motor acting on a vector, say)
//! are dropped; if a blade outside the operand's grades is not reduced to zero by the degree-2
//! identities, it is dropped only after checking numerically on true unit versors
//! (exponentials of random generators in the type).

use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{BladeTable, Monomial, Poly, Product, SymMv, Var};
use crate::runtime::blade::grade;
use crate::runtime::rational::Rational;
use std::collections::BTreeSet;

/// The linear span of the polynomial identities of `a ~a = 1` and `~a a = 1` for the fields
/// of a versor type (operand 0), in reduced row-echelon form.
#[derive(Clone, Debug, Default)]
pub struct UnitIdeal {
    /// (pivot monomial, row): the row has coefficient 1 on its pivot, and no other row
    /// has a term on that pivot.
    rows: Vec<(Monomial, Poly)>,
}

impl UnitIdeal {
    /// The identities of a unit versor type. Empty when the type is not `unit`, or when
    /// `a ~a = 1` is inconsistent for the type (its scalar part cannot be 1, as for a null
    /// type): then nothing is reduced.
    pub fn of_type(table: &mut BladeTable, t: &TypeDef, operand: u8) -> UnitIdeal {
        let mut id = UnitIdeal::default();
        if !t.unit {
            return id;
        }
        let a = SymMv::of_type(t, operand);
        for prod in [
            table.product(&a, &a.rev(), Product::Geometric),
            table.product(&a.rev(), &a, Product::Geometric),
        ] {
            let mut blades: BTreeSet<u32> = prod.support().into_iter().collect();
            blades.insert(0);
            for b in blades {
                let mut p = prod.get(b);
                if b == 0 {
                    p.add_term(Vec::new(), -Rational::ONE);
                }
                if !id.insert(p) {
                    return UnitIdeal::default();
                }
            }
        }
        id
    }

    /// Number of independent identities.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// True when there is nothing to reduce with.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// `p` minus the multiples of the rows that clear every pivot monomial.
    fn eliminate(&self, p: &Poly) -> Poly {
        let mut q = p.clone();
        for (piv, row) in &self.rows {
            if let Some(&c) = q.0.get(piv) {
                q.add_scaled(row, -c);
            }
        }
        q
    }

    /// Add an identity; false when it makes the span contain a non-zero constant.
    fn insert(&mut self, p: Poly) -> bool {
        let q = self.eliminate(&p);
        let Some((piv, &c)) = q.0.iter().next_back() else {
            return true;
        };
        if piv.is_empty() {
            return false;
        }
        let piv = piv.clone();
        let mut row = Poly::default();
        row.add_scaled(&q, Rational::ONE / c);
        for (_, other) in &mut self.rows {
            if let Some(&k) = other.0.get(&piv) {
                other.add_scaled(&row, -k);
            }
        }
        self.rows.push((piv, row));
        true
    }

    /// True when `p` vanishes for every unit versor by the identities (`p` is in their span).
    pub fn contains(&self, p: &Poly) -> bool {
        self.eliminate(p).is_zero()
    }

    /// True when `p` and `q` are equal for every unit versor by the identities.
    #[cfg(test)]
    pub fn equivalent(&self, p: &Poly, q: &Poly) -> bool {
        let mut d = p.clone();
        d.add_scaled(q, -Rational::ONE);
        self.contains(&d)
    }

    /// An equivalent polynomial with the fewest terms (`p` itself when nothing is shorter).
    ///
    /// Every equivalent is `base + sum c_i row_i` with `base` the pivot-free form of `p`. With
    /// `m` rows, a shortest one zeroes `m` independent monomials: every choice of `m` of the
    /// monomials the rows touch is solved when there are few; otherwise a coordinate descent
    /// over the `c_i` is used. A `base` of at most one term is returned at once: no
    /// equivalent is shorter (only a `p` in the span has an equivalent of no terms, and then
    /// `base` is zero).
    pub fn reduce(&self, p: &Poly) -> Poly {
        if self.rows.is_empty() || p.is_zero() {
            return p.clone();
        }
        let base = self.eliminate(p);
        let shortest = |q: Poly| if q.0.len() < p.0.len() { q } else { p.clone() };
        if base.0.len() <= 1 {
            return shortest(base);
        }
        let m = self.rows.len();
        // Monomials the rows touch; only these can change.
        let touched: Vec<Monomial> = self
            .rows
            .iter()
            .flat_map(|(_, r)| r.0.keys().cloned())
            .collect::<BTreeSet<_>>()
            .into_iter()
            .collect();
        if binomial(touched.len(), m) <= 4096 {
            return self.reduce_by_choices(p, &base, &touched);
        }
        let best = shortest(base.clone());
        let q = self.reduce_by_descent(base);
        if q.0.len() < best.0.len() {
            q
        } else {
            best
        }
    }

    /// `base + sum c_i row_i`.
    fn combine(&self, base: &Poly, c: &[Rational]) -> Poly {
        let mut q = base.clone();
        for (ci, (_, row)) in c.iter().zip(&self.rows) {
            if !ci.is_zero() {
                q.add_scaled(row, *ci);
            }
        }
        q
    }

    /// The shortest of `p`, `base` and the equivalents that zero each choice of `m` of the
    /// `touched` monomials (the first found among equally short ones).
    fn reduce_by_choices(&self, p: &Poly, base: &Poly, touched: &[Monomial]) -> Poly {
        let (m, n) = (self.rows.len(), touched.len());
        let mut best = p.clone();
        let consider = |q: Poly, best: &mut Poly| {
            if q.0.len() < best.0.len() {
                *best = q;
            }
        };
        consider(base.clone(), &mut best);
        // Row coefficient of row i on monomial u, and base's value there.
        let mut idx: Vec<usize> = (0..m).collect();
        loop {
            let mut a: Vec<Vec<Rational>> = idx
                .iter()
                .map(|&u| {
                    let mono = &touched[u];
                    let mut eq: Vec<Rational> = self
                        .rows
                        .iter()
                        .map(|(_, r)| r.0.get(mono).copied().unwrap_or(Rational::ZERO))
                        .collect();
                    eq.push(-base.0.get(mono).copied().unwrap_or(Rational::ZERO));
                    eq
                })
                .collect();
            if let Some(c) = solve(&mut a, m) {
                consider(self.combine(base, &c), &mut best);
            }
            // Next combination.
            let mut i = m;
            loop {
                if i == 0 {
                    return best;
                }
                i -= 1;
                if idx[i] < n - m + i {
                    idx[i] += 1;
                    for j in i + 1..m {
                        idx[j] = idx[j - 1] + 1;
                    }
                    break;
                }
            }
        }
    }

    /// Coordinate descent from `base` (all `c_i` zero): for each row in turn, try the
    /// coefficients that cancel one of its monomials and keep one that makes fewer terms;
    /// at most 8 passes. The polynomial is updated by one row per accepted step and each
    /// trial only counts terms, so a pass costs the rows' terms, not `m` full combinations.
    fn reduce_by_descent(&self, base: Poly) -> Poly {
        let m = self.rows.len();
        let mut c = vec![Rational::ZERO; m];
        let mut now = base;
        for _ in 0..8 {
            let mut improved = false;
            for i in 0..m {
                let row = &self.rows[i].1;
                // `now` is the combination with `c[i]` at `start`; a trial `v` adds
                // `(v - start) row`.
                let start = c[i];
                let cands: Vec<Rational> = row
                    .0
                    .iter()
                    .map(|(mono, &r)| {
                        start - now.0.get(mono).copied().unwrap_or(Rational::ZERO) / r
                    })
                    .collect();
                let mut cur = now.0.len();
                for v in cands {
                    let k = terms_after(&now, row, v - start);
                    if k < cur {
                        cur = k;
                        c[i] = v;
                        improved = true;
                    }
                }
                if c[i] != start {
                    now.add_scaled(row, c[i] - start);
                }
            }
            if !improved {
                break;
            }
        }
        now
    }
}

/// The number of terms of `now + d row`, without building it.
fn terms_after(now: &Poly, row: &Poly, d: Rational) -> usize {
    if d.is_zero() {
        return now.0.len();
    }
    let mut k = now.0.len();
    for (mono, &r) in &row.0 {
        match now.0.get(mono) {
            Some(&x) if (x + r * d).is_zero() => k -= 1,
            Some(_) => {}
            None => k += 1,
        }
    }
    k
}

fn binomial(n: usize, k: usize) -> usize {
    if k > n {
        return 0;
    }
    let mut r: usize = 1;
    for i in 0..k {
        r = r.saturating_mul(n - i) / (i + 1);
        if r > 1 << 20 {
            return r;
        }
    }
    r
}

/// Solve the `m x m` system whose rows are `[coefficients..., rhs]`; `None` when singular.
fn solve(a: &mut [Vec<Rational>], m: usize) -> Option<Vec<Rational>> {
    for col in 0..m {
        let piv = (col..m).find(|&r| !a[r][col].is_zero())?;
        a.swap(col, piv);
        let inv = Rational::ONE / a[col][col];
        for k in col..=m {
            a[col][k] = a[col][k] * inv;
        }
        for r in 0..m {
            if r != col && !a[r][col].is_zero() {
                let f = a[r][col];
                for k in col..=m {
                    let v = a[col][k];
                    a[r][k] = a[r][k] - f * v;
                }
            }
        }
    }
    Some((0..m).map(|r| a[r][m]).collect())
}

/// Split `p` by its monomial in the variables other than `operand`'s: (rest, factor in
/// `operand`'s variables) pairs.
fn columns(p: &Poly, operand: u8) -> Vec<(Monomial, Poly)> {
    let mut out: std::collections::BTreeMap<Monomial, Poly> = Default::default();
    for (m, &c) in &p.0 {
        let rest: Monomial = m.iter().copied().filter(|v| v.operand != operand).collect();
        let own: Monomial = m.iter().copied().filter(|v| v.operand == operand).collect();
        out.entry(rest).or_default().add_term(own, c);
    }
    out.into_iter().collect()
}

/// Reduce every coefficient of `r`, column by column (a column is the part multiplying one
/// monomial of the other operands), modulo `ideal` in `operand`'s variables; drop blades that
/// vanish.
pub fn reduce_mv(ideal: &UnitIdeal, r: &SymMv, operand: u8) -> SymMv {
    let mut out = SymMv::default();
    for (&b, p) in &r.0 {
        let mut q = Poly::default();
        for (rest, col) in columns(p, operand) {
            let red = ideal.reduce(&col);
            q.add_scaled(&red.mul_monomial(&rest), Rational::ONE);
        }
        if !q.is_zero() {
            out.0.insert(b, q);
        }
    }
    out
}

/// True when `p` (polynomial in operand 0, the versor, and operand 1) equals `q` column by
/// column modulo the identities.
pub fn equivalent_mv_coeff(ideal: &UnitIdeal, p: &Poly, q: &Poly, operand: u8) -> bool {
    let mut d = p.clone();
    d.add_scaled(q, -Rational::ONE);
    columns(&d, operand)
        .iter()
        .all(|(_, col)| ideal.contains(col))
}

/// The sandwich `a x ~a` of a unit versor type `tv` (operand 0) with `tx` (operand 1):
/// every coefficient reduced modulo `a ~a = 1`, and only the grades of `tx` kept.
///
/// Blades outside the grades of `tx` that the degree-2 identities do not clear are dropped
/// only when they vanish numerically on true unit versors of the type; otherwise they are kept
/// (so that the result is never wrong). Returns the reduced sandwich and the identities used.
pub fn unit_sandwich(
    table: &mut BladeTable,
    alg: &std::sync::Arc<crate::runtime::sparse::multivector::SparseAlgebra>,
    tv: &TypeDef,
    tx: &TypeDef,
) -> (SymMv, UnitIdeal) {
    let a = SymMv::of_type(tv, 0);
    let x = SymMv::of_type(tx, 1);
    let ax = table.product(&a, &x, Product::Geometric);
    let r = table.product(&ax, &a.rev(), Product::Geometric);
    let ideal = UnitIdeal::of_type(table, tv, 0);
    if ideal.is_empty() {
        return (r, ideal);
    }
    let mut red = reduce_mv(&ideal, &r, 0);
    let grades: BTreeSet<u32> = tx.blades().map(grade).collect();
    let stray: Vec<u32> = red
        .support()
        .into_iter()
        .filter(|b| !grades.contains(&grade(*b)))
        .collect();
    if !stray.is_empty() {
        // The same 16 unit versors and operands for every stray blade: drawn once.
        if let Some(samples) = unit_versor_samples(alg, tv, tx, SAMPLES_SEED) {
            for b in stray {
                let p = red.get(b);
                if samples
                    .iter()
                    .all(|(v0, v1)| eval(&p, v0, v1).abs() <= 1e-9)
                {
                    red.0.remove(&b);
                }
            }
        }
    }
    (red, ideal)
}

/// The seed of the samples that decide which stray blades of a unit sandwich are dropped.
const SAMPLES_SEED: u64 = 0x2545_f491_4f6c_dd1d;

/// Terms of a sample exponential's products below this fraction of their largest
/// coefficient are rounding noise, dropped ([`SparseMultivector::exp_pruned`]).
///
/// [`SparseMultivector::exp_pruned`]: crate::runtime::sparse::multivector::SparseMultivector::exp_pruned
const EXP_NOISE: f64 = 1e-13;

/// The fields of 16 unit versors `exp(B)` of `tv` (random generators `B` among its bivector
/// fields, normalised), each with random fields of an operand of type `tx`, drawn from
/// `seed` (the same samples on every call with it). `None` when the type has no bivector
/// fields or an exponential leaves the type (or is too small to normalise).
pub fn unit_versor_samples(
    alg: &std::sync::Arc<crate::runtime::sparse::multivector::SparseAlgebra>,
    tv: &TypeDef,
    tx: &TypeDef,
    seed: u64,
) -> Option<Vec<(Vec<f64>, Vec<f64>)>> {
    let mut rng = seed;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let biv: Vec<u32> = tv
        .fields
        .iter()
        .map(|f| f.bitmap)
        .filter(|&b| grade(b) == 2)
        .collect();
    if biv.is_empty() {
        return None;
    }
    let mut samples = Vec::with_capacity(16);
    for _ in 0..16 {
        let mut bv = crate::runtime::sparse::multivector::SparseMultivector::zero(alg);
        for &b in &biv {
            bv.set(b, next());
        }
        let m = bv.exp_pruned(EXP_NOISE);
        let n = m.norm();
        if n.is_nan() || n <= 1e-6 {
            return None;
        }
        let m = m.scale(1.0 / n);
        let outside = m
            .terms()
            .filter(|(b, _)| !tv.blades().any(|x| x == *b))
            .map(|(_, c)| c.abs())
            .fold(0.0, f64::max);
        if outside > 1e-9 {
            return None;
        }
        let v0: Vec<f64> = tv
            .fields
            .iter()
            .map(|f| f.sign as f64 * m.get(f.bitmap))
            .collect();
        let v1: Vec<f64> = tx.fields.iter().map(|_| next()).collect();
        samples.push((v0, v1));
    }
    Some(samples)
}

/// Evaluate `p` with operand 0 fields `v0` and operand 1 fields `v1` (other operands 1.0).
pub fn eval(p: &Poly, v0: &[f64], v1: &[f64]) -> f64 {
    p.0.iter()
        .map(|(mono, c)| {
            mono.iter().fold(c.to_f64(), |acc, v: &Var| {
                acc * match v.operand {
                    0 => v0[v.field as usize],
                    1 => v1[v.field as usize],
                    _ => 1.0,
                }
            })
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generator::spec::Spec;

    use crate::generator::spec::shipped_spec as spec;

    fn ty<'a>(s: &'a Spec, name: &str) -> &'a TypeDef {
        s.types.iter().find(|t| t.name == name).expect("type")
    }

    #[test]
    fn motor_identities_are_the_norm_and_the_quadvector_part() {
        let s = spec("cga");
        let mut table = BladeTable::new(&s.metric);
        let id = UnitIdeal::of_type(&mut table, ty(&s, "Motor"), 0);
        assert_eq!(id.len(), 2, "{:?}", id.rows);
        // s^2 + e12^2 + e13^2 + e23^2 = 1.
        let m = SymMv::of_type(ty(&s, "Motor"), 0);
        let n = table.product(&m, &m.rev(), Product::Scalar).get(0);
        assert!(id.equivalent(&n, &Poly::constant(Rational::ONE)));
    }

    #[test]
    fn reduction_keeps_the_grade_in_every_algebra() {
        for name in ["cga", "pga3d", "g3", "sta"] {
            let s = spec(name);
            let alg = crate::runtime::sparse::multivector::SparseAlgebra::try_new(s.metric.clone())
                .unwrap();
            let mut table = BladeTable::new(&s.metric);
            for d in &s.sandwiches {
                let (tv, tx) = (&s.types[d.versor], &s.types[d.operand]);
                if !tv.unit {
                    continue;
                }
                let (r, _) = unit_sandwich(&mut table, &alg, tv, tx);
                let grades: BTreeSet<u32> = tx.blades().map(grade).collect();
                for b in r.support() {
                    assert!(
                        grades.contains(&grade(b)),
                        "{name}: {} sandwich {}: grade {} left",
                        tv.name,
                        tx.name,
                        grade(b)
                    );
                }
            }
        }
    }

    /// QCGA's translator generator `B = sum e_i u_i` (`u_i` among the null `ei` vectors) is
    /// nilpotent (`B^4 = 0`), so `exp(B) = 1 + B + B^2/2 + B^3/6` exactly: the pruned
    /// exponential the samples use equals that polynomial and has no blade outside the type
    /// (the unpruned one carries about 90 blades of rounding noise).
    #[test]
    fn pruned_exponential_of_a_qcga_translator_is_its_polynomial() {
        let s = spec("qcga");
        let alg =
            crate::runtime::sparse::multivector::SparseAlgebra::try_new(s.metric.clone()).unwrap();
        let tv = ty(&s, "Translator");
        let mut bv = crate::runtime::sparse::multivector::SparseMultivector::zero(&alg);
        for (i, f) in tv
            .fields
            .iter()
            .filter(|f| grade(f.bitmap) == 2)
            .enumerate()
        {
            bv.set(f.bitmap, 0.9 - 0.23 * i as f64);
        }
        let m = bv.exp_pruned(EXP_NOISE);
        let b2 = bv.gp(&bv);
        let b3 = b2.gp(&bv);
        assert!(b3.gp(&bv).max_abs() < 1e-12, "B^4 = 0 up to rounding");
        let poly = crate::runtime::sparse::multivector::SparseMultivector::scalar(&alg, 1.0)
            .add_scaled(&bv, 1.0)
            .add_scaled(&b2, 0.5)
            .add_scaled(&b3, 1.0 / 6.0);
        assert!(m.max_diff(&poly) < 1e-12, "{}", m.max_diff(&poly));
        let blades: BTreeSet<u32> = tv.blades().collect();
        for (b, c) in m.terms() {
            assert!(blades.contains(&b), "blade {b:#b} ({c:e}) outside the type");
        }
    }

    #[test]
    fn inconsistent_unit_type_reduces_nothing() {
        let text = r#"
basis = ["e1", "e2", "e3", "e4"]
diagonal = [1, 1, 1, 0]
[[type]]
name = "Null"
blades = ["e14", "e24"]
versor = true
unit = true
"#;
        let s = Spec::from_toml(text, "null.toml").expect("valid");
        let mut table = BladeTable::new(&s.metric);
        assert!(UnitIdeal::of_type(&mut table, &s.types[0], 0).is_empty());
    }
}
