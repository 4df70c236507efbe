//! The symbolic engine: multivectors whose coefficients are polynomials in the fields of the
//! operands, with exact rational coefficients, expanded and simplified at generation time.
//!
//! Blade products are expanded directly in the user's (possibly non-orthogonal) basis with
//! Chevalley's recursion `e_i ^ A = e_i A - e_i ⌋ A`, so a null basis needs no change of basis
//! and every coefficient stays rational: terms that cancel vanish exactly.

use crate::generator::spec::TypeDef;
use crate::runtime::algebra::Exact;
use crate::runtime::blade::{grade, involute_sign, reverse_sign, Bitmap};
use crate::runtime::metric::Metric;
use crate::runtime::rational::Rational;
use std::collections::{BTreeMap, HashMap};

/// A variable: field `field` of operand `operand` (0 = left/versor, 1 = right/operand, 2 = an
/// extra scalar, 3 = a scalar factor).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Var {
    /// Which operand.
    pub operand: u8,
    /// Which field of it.
    pub field: u16,
}

/// A monomial: a sorted product of variables (empty for a constant).
pub type Monomial = Vec<Var>;

/// A polynomial with exact coefficients.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Poly(pub BTreeMap<Monomial, Rational>);

impl Poly {
    /// The constant `c`.
    pub fn constant(c: Rational) -> Poly {
        let mut p = Poly::default();
        p.add_term(Vec::new(), c);
        p
    }

    /// `c * v`.
    pub fn var(v: Var, c: Rational) -> Poly {
        let mut p = Poly::default();
        p.add_term(vec![v], c);
        p
    }

    /// True when identically zero.
    pub fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// Add `c * m`, dropping the term if it cancels.
    pub fn add_term(&mut self, m: Monomial, c: Rational) {
        if c.is_zero() {
            return;
        }
        match self.0.entry(m) {
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(c);
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                let s = *o.get() + c;
                if s.is_zero() {
                    o.remove();
                } else {
                    *o.get_mut() = s;
                }
            }
        }
    }

    /// `self += c * other`.
    pub fn add_scaled(&mut self, other: &Poly, c: Rational) {
        for (m, &k) in &other.0 {
            self.add_term(m.clone(), k * c);
        }
    }

    /// `self * other`.
    pub fn mul(&self, other: &Poly) -> Poly {
        let mut out = Poly::default();
        for (ma, &ca) in &self.0 {
            for (mb, &cb) in &other.0 {
                let mut m = ma.clone();
                m.extend_from_slice(mb);
                m.sort();
                out.add_term(m, ca * cb);
            }
        }
        out
    }

    /// `self * m` for a monomial `m`.
    pub fn mul_monomial(&self, m: &Monomial) -> Poly {
        let mut out = Poly::default();
        for (k, &c) in &self.0 {
            let mut mm = k.clone();
            mm.extend_from_slice(m);
            mm.sort();
            out.add_term(mm, c);
        }
        out
    }

    /// The constant value, if the polynomial has no variables.
    pub fn as_constant(&self) -> Option<Rational> {
        match self.0.len() {
            0 => Some(Rational::ZERO),
            1 => self.0.get(&Vec::new()).copied(),
            _ => None,
        }
    }
}

/// A multivector with polynomial coefficients, keyed by canonical blade bitmap.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SymMv(pub BTreeMap<Bitmap, Poly>);

impl SymMv {
    /// The symbolic value of a type: field `i` of operand `operand` on its blade, constants
    /// as constants.
    pub fn of_type(t: &TypeDef, operand: u8) -> SymMv {
        let mut m = SymMv::default();
        for (i, f) in t.fields.iter().enumerate() {
            m.add(
                f.bitmap,
                &Poly::var(
                    Var {
                        operand,
                        field: i as u16,
                    },
                    Rational::int(f.sign as i64),
                ),
            );
        }
        for &(b, c) in &t.constants {
            m.add(b, &Poly::constant(c));
        }
        m
    }

    /// A scalar variable (operand 2).
    pub fn scalar_var() -> SymMv {
        SymMv::scalar_operand(2)
    }

    /// The scalar variable of operand `operand` (2: the scalar `s`, 3: the factor `r`).
    pub fn scalar_operand(operand: u8) -> SymMv {
        let mut m = SymMv::default();
        m.add(0, &Poly::var(Var { operand, field: 0 }, Rational::ONE));
        m
    }

    fn add(&mut self, b: Bitmap, p: &Poly) {
        let e = self.0.entry(b).or_default();
        e.add_scaled(p, Rational::ONE);
        if e.is_zero() {
            self.0.remove(&b);
        }
    }

    /// Blades with a non-zero coefficient.
    pub fn support(&self) -> Vec<Bitmap> {
        self.0.keys().copied().collect()
    }

    /// Coefficient of a blade (zero if absent).
    pub fn get(&self, b: Bitmap) -> Poly {
        self.0.get(&b).cloned().unwrap_or_default()
    }

    /// Apply a sign per blade.
    pub fn map_signs(&self, f: impl Fn(Bitmap) -> i32) -> SymMv {
        let mut out = SymMv::default();
        for (&b, p) in &self.0 {
            let s = f(b);
            if s != 0 {
                let mut q = Poly::default();
                q.add_scaled(p, Rational::int(s as i64));
                out.add(b, &q);
            }
        }
        out
    }

    /// Reverse.
    pub fn rev(&self) -> SymMv {
        self.map_signs(reverse_sign)
    }

    /// Grade involution.
    pub fn involute(&self) -> SymMv {
        self.map_signs(involute_sign)
    }

    /// Clifford conjugate.
    pub fn conjugate(&self) -> SymMv {
        self.map_signs(|b| reverse_sign(b) * involute_sign(b))
    }

    /// `self + c * other`.
    pub fn add_scaled(&self, other: &SymMv, c: Rational) -> SymMv {
        let mut out = self.clone();
        for (&b, p) in &other.0 {
            let mut q = Poly::default();
            q.add_scaled(p, c);
            out.add(b, &q);
        }
        out
    }

    /// Map each blade to a linear combination of blades (dual, complement).
    pub fn map_blades(&self, f: impl Fn(Bitmap) -> Vec<(Bitmap, Rational)>) -> SymMv {
        let mut out = SymMv::default();
        for (&b, p) in &self.0 {
            for (k, c) in f(b) {
                let mut q = Poly::default();
                q.add_scaled(p, c);
                out.add(k, &q);
            }
        }
        out
    }
}

/// Which grades of a blade product a product keeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Product {
    /// Geometric product.
    Geometric,
    /// Outer product.
    Outer,
    /// Left contraction `a ⌋ b`: grade `gb - ga` of each pair of grade parts, `ga <= gb`.
    Left,
    /// Scalar product `<a b>_0`.
    Scalar,
    /// Right contraction `a ⌊ b`: grade `ga - gb` of each pair of grade parts, `ga >= gb`.
    Right,
    /// Dot product (Dorst's, as GATL's `dot`): grade `|ga - gb|` of each pair of grade parts.
    Dot,
    /// Hestenes inner product (GATL's `hip`): the dot product, zero when either grade is 0.
    Hestenes,
}

impl Product {
    fn keeps(self, ga: u32, gb: u32, gk: u32) -> bool {
        match self {
            Product::Geometric => true,
            Product::Outer => gk == ga + gb,
            Product::Left => gb >= ga && gk == gb - ga,
            Product::Scalar => gk == 0,
            Product::Right => ga >= gb && gk == ga - gb,
            Product::Dot => gk == ga.abs_diff(gb),
            Product::Hestenes => ga != 0 && gb != 0 && gk == ga.abs_diff(gb),
        }
    }
}

/// Exact products of basis blades in the user's basis, by Chevalley's recursion, memoised.
pub struct BladeTable {
    metric: Metric,
    memo: HashMap<(Bitmap, Bitmap), Exact>,
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

impl BladeTable {
    /// A table for a metric.
    pub fn new(metric: &Metric) -> BladeTable {
        BladeTable {
            metric: metric.clone(),
            memo: HashMap::new(),
        }
    }

    /// The metric.
    pub fn metric(&self) -> &Metric {
        &self.metric
    }

    /// `e_i ⌋ e_B`.
    fn vec_lc(&self, i: usize, b: Bitmap) -> Exact {
        let mut out = Exact::new();
        let mut pos = 0;
        for j in 0..self.metric.dim() {
            if b & (1 << j) != 0 {
                let g = self.metric.get(i, j);
                if !g.is_zero() {
                    let s = if pos % 2 == 0 { g } else { -g };
                    add_term(&mut out, b & !(1 << j), s);
                }
                pos += 1;
            }
        }
        out
    }

    /// `e_i e_B = e_i ⌋ e_B + e_i ^ e_B`.
    fn vec_gp(&self, i: usize, x: &Exact) -> Exact {
        let mut out = Exact::new();
        for (&b, &c) in x {
            for (k, v) in self.vec_lc(i, b) {
                add_term(&mut out, k, c * v);
            }
            if b & (1 << i) == 0 {
                let below = (b & ((1 << i) - 1)).count_ones();
                let s = if below.is_multiple_of(2) { c } else { -c };
                add_term(&mut out, b | (1 << i), s);
            }
        }
        out
    }

    /// The geometric product `e_a e_b` of two outer-product basis blades.
    pub fn gp(&mut self, a: Bitmap, b: Bitmap) -> Exact {
        if let Some(r) = self.memo.get(&(a, b)) {
            return r.clone();
        }
        let r = if a == 0 {
            let mut m = Exact::new();
            m.insert(b, Rational::ONE);
            m
        } else {
            let i = a.trailing_zeros() as usize;
            let rest = a & !(1 << i);
            // e_a = e_i ^ e_rest = e_i e_rest - e_i ⌋ e_rest
            let inner = self.gp(rest, b);
            let mut out = self.vec_gp(i, &inner);
            for (c, v) in self.vec_lc(i, rest) {
                for (k, w) in self.gp(c, b) {
                    add_term(&mut out, k, -(v * w));
                }
            }
            out
        };
        self.memo.insert((a, b), r.clone());
        r
    }

    /// A product of two symbolic multivectors.
    pub fn product(&mut self, x: &SymMv, y: &SymMv, kind: Product) -> SymMv {
        let mut out = SymMv::default();
        for (&a, pa) in &x.0 {
            for (&b, pb) in &y.0 {
                let terms = self.gp(a, b);
                let pab = pa.mul(pb);
                for (k, c) in terms {
                    if kind.keeps(grade(a), grade(b), grade(k)) {
                        let mut q = Poly::default();
                        q.add_scaled(&pab, c);
                        out.add(k, &q);
                    }
                }
            }
        }
        out
    }
}

/// The magnitude every one of `cs` shares (`|c|` the same for all), or `None` when they differ
/// or there are none.
pub(crate) fn shared_magnitude(cs: impl IntoIterator<Item = Rational>) -> Option<Rational> {
    let mut cs = cs.into_iter().map(Rational::abs);
    let first = cs.next()?;
    cs.all(|c| c == first).then_some(first)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chevalley_matches_congruence_route_on_null_basis() {
        let metric = Metric::cga_null_basis();
        let alg = crate::Algebra::new(metric.clone());
        let mut t = BladeTable::new(&metric);
        for a in 0..32 {
            for b in 0..32 {
                let sym: Vec<(Bitmap, f64)> = t
                    .gp(a, b)
                    .into_iter()
                    .map(|(k, c)| (k, c.to_f64()))
                    .collect();
                assert_eq!(sym.as_slice(), alg.gp_blades(a, b), "e_{a} e_{b}");
            }
        }
    }
}
