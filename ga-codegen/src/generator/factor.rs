//! Factorisation of fused sandwiches into a short straight-line program.
//!
//! The expanded sandwich `a x ~a` is a quadratic form in the versor for each output
//! coefficient; evaluated term by term it costs about one multiply per term. Written as two
//! half products it can be much cheaper, because the second half shares the first half's
//! results between outputs. For a unit versor (`a ~a = 1`) the cheapest split is usually the
//! commutator form of quaternion rotation (`v + 2 q x (q x v + w v)`):
//!
//! ```text
//! a x ~a = x (a ~a) + (a x - x a) ~a = x + 2 <c ~a>,   c = (a x - x a) / 2
//! ```
//!
//! where the commutator `c` drops every part of `a` that commutes with `x` (the scalar, for a
//! start). This module builds such candidate programs (the commutator on either side, and the
//! two plain half products), proves each one equal to the reduced expansion (exactly, modulo
//! the identities of `a ~a = 1` from [`crate::generator::unit_versor`]), and returns the cheapest,
//! counting multiplies and adds. Nothing here is specific to one algebra.

use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{
    shared_magnitude, BladeTable, Monomial, Poly, Product, SymMv, Var,
};
use crate::generator::unit_versor::{equivalent_mv_coeff, UnitIdeal};
use crate::runtime::blade::{blade_name, Bitmap};
use crate::runtime::rational::Rational;
use proc_macro2::{Literal, TokenStream};
use quote::quote;
use std::collections::BTreeMap;

/// The operand number of temporaries inside [`Poly`] monomials.
const TEMP: u8 = 3;

/// An operand of a product in a [`Program`]: a field of an operand, or a temporary.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Atom {
    /// A field of the versor (operand 0) or of the operand (operand 1).
    Var(Var),
    /// A temporary, by index into [`Program::temps`].
    Temp(usize),
}

/// `sum c_i * prod atoms_i`: a sum of products with exact coefficients.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sum(pub Vec<(Rational, Vec<Atom>)>);

impl Sum {
    fn from_poly(p: &Poly) -> Sum {
        Sum(p
            .0
            .iter()
            .map(|(m, &c)| {
                let atoms = m
                    .iter()
                    .map(|v| {
                        if v.operand == TEMP {
                            Atom::Temp(v.field as usize)
                        } else {
                            Atom::Var(*v)
                        }
                    })
                    .collect();
                (c, atoms)
            })
            .collect())
    }

    /// Multiplies and adds, with the terms grouped by the magnitude of their coefficient
    /// (one multiply per group whose magnitude is not 1).
    pub fn ops(&self) -> (usize, usize) {
        let mut muls = 0;
        let mut mags = std::collections::BTreeSet::new();
        for (c, atoms) in &self.0 {
            muls += atoms.len().saturating_sub(1);
            let mag = c.abs();
            if !atoms.is_empty() && mag != Rational::ONE {
                mags.insert(mag);
            }
        }
        (muls + mags.len(), self.0.len().saturating_sub(1))
    }

    /// Rust tokens: terms grouped by coefficient magnitude, `2.0 * (x - y) + z`.
    pub fn render(&self, atom: &dyn Fn(Atom) -> TokenStream) -> TokenStream {
        if self.0.is_empty() {
            return quote!(0.0);
        }
        // magnitude -> (negative?, product) terms; constants form their own group.
        let mut groups: BTreeMap<Rational, Vec<(bool, TokenStream)>> = BTreeMap::new();
        let mut constant = Rational::ZERO;
        for (c, atoms) in &self.0 {
            if atoms.is_empty() {
                constant = constant + *c;
                continue;
            }
            let neg = *c < Rational::ZERO;
            let mag = if neg { -*c } else { *c };
            let mut prod = TokenStream::new();
            for (i, a) in atoms.iter().enumerate() {
                if i > 0 {
                    prod.extend(quote!(*));
                }
                prod.extend(atom(*a));
            }
            groups.entry(mag).or_default().push((neg, prod));
        }
        // (negative?, tokens, a sum of several terms?) per group.
        let mut parts: Vec<(bool, TokenStream, bool)> = Vec::new();
        // Magnitude 1 first.
        let mut order: Vec<Rational> = groups.keys().copied().collect();
        order.sort_by_key(|m| *m != Rational::ONE);
        for mag in order {
            let mut terms = groups.remove(&mag).expect("group");
            let all_neg = terms.iter().all(|t| t.0);
            if all_neg {
                terms.iter_mut().for_each(|t| t.0 = false);
            }
            if let Some(i) = terms.iter().position(|t| !t.0) {
                let first = terms.remove(i);
                terms.insert(0, first);
            }
            let mut sum = TokenStream::new();
            for (i, (neg, p)) in terms.iter().enumerate() {
                if i > 0 {
                    sum.extend(if *neg { quote!(-) } else { quote!(+) });
                }
                sum.extend(p.clone());
            }
            let (tokens, compound) = if mag == Rational::ONE {
                (sum, terms.len() > 1)
            } else {
                let c = lit(mag);
                if terms.len() > 1 {
                    (quote!(#c * (#sum)), false)
                } else {
                    (quote!(#c * #sum), false)
                }
            };
            parts.push((all_neg, tokens, compound));
        }
        if !constant.is_zero() {
            let neg = constant < Rational::ZERO;
            parts.push((neg, lit(if neg { -constant } else { constant }), false));
        }
        if let Some(i) = parts.iter().position(|p| !p.0) {
            let first = parts.remove(i);
            parts.insert(0, first);
        }
        let mut out = TokenStream::new();
        for (i, (neg, p, compound)) in parts.iter().enumerate() {
            if i == 0 {
                if *neg {
                    out.extend(quote!(-));
                }
            } else {
                out.extend(if *neg { quote!(-) } else { quote!(+) });
            }
            // A leading minus before a sum needs parentheses (`-(x + y)` is not `-x + y`).
            if i == 0 && *neg && *compound {
                out.extend(quote!((#p)));
            } else {
                out.extend(p.clone());
            }
        }
        out
    }
}

/// A non-negative exact coefficient as a float literal.
fn lit(c: Rational) -> TokenStream {
    let l = Literal::f64_unsuffixed(c.to_f64());
    quote!(#l)
}

/// A straight-line program: temporaries, then one expression per output field.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Temporaries, in evaluation order: (name, expression over fields and earlier temps).
    pub temps: Vec<(String, Sum)>,
    /// One expression per output field, in storage order.
    pub outputs: Vec<Sum>,
    /// How the program computes the sandwich, for the doc comment.
    pub form: String,
}

impl Program {
    /// Multiplies and adds of the whole program.
    pub fn ops(&self) -> (usize, usize) {
        self.temps
            .iter()
            .map(|t| &t.1)
            .chain(&self.outputs)
            .map(Sum::ops)
            .fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
    }

    /// The temporaries as (name, expression), given how to write a field of operand 0 / 1.
    pub fn render_temps(
        &self,
        var: &dyn Fn(Var) -> TokenStream,
    ) -> Vec<(proc_macro2::Ident, TokenStream)> {
        let atom = |a: Atom| self.atom(a, var);
        self.temps
            .iter()
            .map(|(n, e)| (temp_ident(n), e.render(&atom)))
            .collect()
    }

    /// The expression of output field `k`.
    pub fn render_output(&self, k: usize, var: &dyn Fn(Var) -> TokenStream) -> TokenStream {
        let atom = |a: Atom| self.atom(a, var);
        self.outputs[k].render(&atom)
    }

    fn atom(&self, a: Atom, var: &dyn Fn(Var) -> TokenStream) -> TokenStream {
        match a {
            Atom::Var(v) => var(v),
            Atom::Temp(i) => {
                let id = temp_ident(&self.temps[i].0);
                quote!(#id)
            }
        }
    }
}

/// The identifier of a temporary (its name is a prefix and a blade name, checked up front by
/// the emitter like every generated name).
fn temp_ident(name: &str) -> proc_macro2::Ident {
    proc_macro2::Ident::new(name, proc_macro2::Span::call_site())
}

/// Multiplies and adds of the term-by-term form: every product of two versor fields once,
/// then each output coefficient as `sum_j x_j * (quadratic form)`.
pub fn direct_ops(r: &SymMv, to: &TypeDef) -> (usize, usize) {
    let mut pairs = std::collections::BTreeSet::new();
    let (mut muls, mut adds) = (0, 0);
    for f in &to.fields {
        let p = r.get(f.bitmap);
        let mut cols: BTreeMap<Monomial, Vec<(Monomial, Rational)>> = BTreeMap::new();
        for (m, &c) in &p.0 {
            let rest: Monomial = m.iter().copied().filter(|v| v.operand != 0).collect();
            let own: Monomial = m.iter().copied().filter(|v| v.operand == 0).collect();
            cols.entry(rest).or_default().push((own, c));
        }
        adds += cols.len().saturating_sub(1);
        for (rest, terms) in cols {
            muls += rest.len();
            adds += terms.len() - 1;
            for (own, c) in terms {
                if own.len() >= 2 {
                    pairs.insert(own.clone());
                    muls += own.len() - 2;
                }
                if !own.is_empty() && c != Rational::ONE && c != -Rational::ONE {
                    muls += 1;
                }
            }
        }
    }
    (muls + pairs.len(), adds)
}

/// The candidate splits of `a x ~a`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Split {
    /// `x + <c ~a>` with `c = a x - x a` (needs `a ~a = 1`).
    LeftCommutator,
    /// `x + <a d>` with `d = x ~a - ~a x` (needs `~a a = 1`).
    RightCommutator,
    /// `<(a x) ~a>`.
    LeftHalf,
    /// `<a (x ~a)>`.
    RightHalf,
}

/// One fused sandwich to factor: the versor type `tv` (operand 0) on `tx` (operand 1) into
/// `to`, with `reduced` the expansion reduced modulo `ideal` (the unit identities of `tv`).
pub struct SandwichCase<'a> {
    /// The basis vector names (for the temporaries' names).
    pub basis: &'a [String],
    /// The versor type.
    pub tv: &'a TypeDef,
    /// The operand type.
    pub tx: &'a TypeDef,
    /// The output type.
    pub to: &'a TypeDef,
    /// The reduced expansion every program must equal.
    pub reduced: &'a SymMv,
    /// The unit identities of the versor.
    pub ideal: &'a UnitIdeal,
}

/// The cheapest straight-line program for the sandwich `case`, proven equal to its reduced
/// expansion on every output field; `None` when no split is cheaper than the term-by-term form.
pub fn sandwich_program(table: &mut BladeTable, case: &SandwichCase) -> Option<Program> {
    let SandwichCase {
        tv,
        to,
        reduced,
        ideal,
        ..
    } = *case;
    if !bounded_norm(table, tv) {
        return None;
    }
    let (dm, da) = direct_ops(reduced, to);
    let mut best: Option<(usize, Program)> = None;
    let splits: &[Split] = if ideal.is_empty() {
        &[Split::LeftHalf, Split::RightHalf]
    } else {
        &[
            Split::LeftCommutator,
            Split::RightCommutator,
            Split::LeftHalf,
            Split::RightHalf,
        ]
    };
    for &split in splits {
        let Some(p) = split_program(table, case, split) else {
            continue;
        };
        let (m, a) = p.ops();
        let cost = m + a;
        if cost < dm + da && best.as_ref().is_none_or(|b| cost < b.0) {
            best = Some((cost, p));
        }
    }
    best.map(|b| b.1)
}

/// True when the norm `<a ~a>_0` of the versor type is a sum of squares of its fields with
/// positive coefficients (rotors, motors: the scalar and rotation parts are then at most 1 for
/// a unit versor, and the other fields, such as translations, do not enter the norm).
///
/// Otherwise (dilators, Lorentz boosts: `cosh^2 - sinh^2 = 1`) the fields of a unit versor
/// grow without bound, and a split form such as `x + 2 <c ~a>` adds terms of size `|a|^2` that
/// cancel to the small result, losing relative precision that the term-by-term form keeps
/// (measured on `Dilator`: 1.5e-12 against 6.7e-13 for scale 100), so only the term-by-term
/// form is emitted for them.
fn bounded_norm(table: &mut BladeTable, tv: &TypeDef) -> bool {
    let a = SymMv::of_type(tv, 0);
    let n = table.product(&a, &a.rev(), Product::Scalar).get(0);
    n.0.iter()
        .all(|(m, c)| *c > Rational::ZERO && m.len() == 2 && m[0] == m[1])
}

/// Substitute the temporaries (operand [`TEMP`]) of `p` by their expansions.
fn substitute(p: &Poly, temps: &[Poly]) -> Poly {
    let mut out = Poly::default();
    for (m, &c) in &p.0 {
        let mut term = Poly::constant(c);
        let mut plain: Monomial = Vec::new();
        for v in m {
            if v.operand == TEMP {
                term = term.mul(&temps[v.field as usize]);
            } else {
                plain.push(*v);
            }
        }
        out.add_scaled(&term.mul_monomial(&plain), Rational::ONE);
    }
    out
}

/// The program of one `split` of the sandwich `case`, or `None` when an output field does not
/// reduce to the expansion. Phases: the first half product, its temporaries, the second half
/// (checked field by field), trivial temporaries folded into their uses, unused ones dropped.
fn split_program(table: &mut BladeTable, case: &SandwichCase, split: Split) -> Option<Program> {
    let a = SymMv::of_type(case.tv, 0);
    let x = SymMv::of_type(case.tx, 1);
    let ar = a.rev();
    let (first, prefix, what) = first_half(table, &a, &x, &ar, split);
    let mut temps = temporaries(&first, prefix, case.basis);
    let g = Product::Geometric;
    let second = match split {
        Split::LeftCommutator | Split::LeftHalf => table.product(&temps.sym, &ar, g),
        Split::RightCommutator | Split::RightHalf => table.product(&a, &temps.sym, g),
    };
    let with_x = matches!(split, Split::LeftCommutator | Split::RightCommutator);
    let outputs = checked_outputs(case, &second, with_x.then_some(&x), &temps.polys)?;
    let folds = fold_trivial_temps(&mut temps.polys);
    let outputs: Vec<Poly> = outputs
        .iter()
        .map(|p| substitute_folded(p, &folds))
        .collect();
    let (temps, outputs) = keep_used(&temps, &outputs);
    Some(Program {
        temps,
        outputs,
        form: what.to_string(),
    })
}

/// The first half of `split` for the versor `a` (reverse `ar`) and operand `x`: the commutator
/// (`a x - x a` or `x ~a - ~a x`) or the plain half product (`a x` or `x ~a`), with the prefix
/// of its temporaries' names and the form the program's doc names.
fn first_half(
    table: &mut BladeTable,
    a: &SymMv,
    x: &SymMv,
    ar: &SymMv,
    split: Split,
) -> (SymMv, &'static str, &'static str) {
    let g = Product::Geometric;
    match split {
        Split::LeftCommutator => {
            let ax = table.product(a, x, g);
            let xa = table.product(x, a, g);
            (
                ax.add_scaled(&xa, -Rational::ONE),
                "c",
                "x + <c ~a> with the commutator c = a x - x a",
            )
        }
        Split::RightCommutator => {
            let xa = table.product(x, ar, g);
            let ax = table.product(ar, x, g);
            (
                xa.add_scaled(&ax, -Rational::ONE),
                "d",
                "x + <a d> with the commutator d = x ~a - ~a x",
            )
        }
        Split::LeftHalf => (table.product(a, x, g), "h", "<h ~a> with h = a x"),
        Split::RightHalf => (table.product(x, ar, g), "h", "<a h> with h = x ~a"),
    }
}

/// The temporaries of a first half, one per blade, before folding and pruning.
struct Temps {
    /// Each temporary's expansion, with the common magnitude of its coefficients factored out.
    polys: Vec<Poly>,
    /// Each temporary's name: the prefix and the blade's name.
    names: Vec<String>,
    /// The first half as a multivector of temporaries (operand [`TEMP`]) times their magnitudes.
    sym: SymMv,
}

/// One temporary per blade of `first`, with the common magnitude of its coefficients factored
/// out (the commutator's factor 2), named `prefix_blade` over the basis names `basis`.
fn temporaries(first: &SymMv, prefix: &str, basis: &[String]) -> Temps {
    let mut temps = Temps {
        polys: Vec::new(),
        names: Vec::new(),
        sym: SymMv::default(),
    };
    for (i, (&b, p)) in first.0.iter().enumerate() {
        let mag = common_magnitude(p);
        let mut q = Poly::default();
        q.add_scaled(p, Rational::ONE / mag);
        temps.polys.push(q);
        temps
            .names
            .push(format!("{prefix}_{}", blade_name(b as Bitmap, basis)));
        temps.sym.0.insert(
            b,
            Poly::var(
                Var {
                    operand: TEMP,
                    field: i as u16,
                },
                mag,
            ),
        );
    }
    temps
}

/// The output fields of `case.to` from the second half (plus the operand `x` for a commutator
/// form), signed by the fields' signs; `None` unless each one, with the temporaries expanded
/// (`temps`), equals the reduced expansion modulo the unit identities.
fn checked_outputs(
    case: &SandwichCase,
    second: &SymMv,
    x: Option<&SymMv>,
    temps: &[Poly],
) -> Option<Vec<Poly>> {
    let mut outputs = Vec::new();
    for f in &case.to.fields {
        let mut p = second.get(f.bitmap);
        if let Some(x) = x {
            p.add_scaled(&x.get(f.bitmap), Rational::ONE);
        }
        let mut signed = Poly::default();
        signed.add_scaled(&p, Rational::int(f.sign as i64));
        let expanded = substitute(&p, temps);
        if !equivalent_mv_coeff(case.ideal, &expanded, &case.reduced.get(f.bitmap), 0) {
            return None;
        }
        outputs.push(signed);
    }
    Some(outputs)
}

/// Fold trivial temporaries: one that is one field (times a constant) is to be written in
/// place, and one whose terms are all negative is negated here and its uses negated instead.
/// Returns, per temporary, what its uses become (`None`: kept as is).
fn fold_trivial_temps(polys: &mut [Poly]) -> Vec<Option<Poly>> {
    let mut folds: Vec<Option<Poly>> = vec![None; polys.len()];
    for (i, t) in polys.iter_mut().enumerate() {
        let tv = Var {
            operand: TEMP,
            field: i as u16,
        };
        if t.0.len() == 1 && t.0.keys().next().is_some_and(|m| m.len() <= 1) {
            folds[i] = Some(t.clone());
        } else if t.0.values().all(|c| *c < Rational::ZERO) {
            let mut n = Poly::default();
            n.add_scaled(t, -Rational::ONE);
            *t = n;
            folds[i] = Some(Poly::var(tv, -Rational::ONE));
        }
    }
    folds
}

/// `p` with each temporary that has a fold in `folds` replaced by it.
fn substitute_folded(p: &Poly, folds: &[Option<Poly>]) -> Poly {
    let mut out = Poly::default();
    for (m, &c) in &p.0 {
        let mut term = Poly::constant(c);
        let mut plain: Monomial = Vec::new();
        for v in m {
            match (v.operand == TEMP).then(|| folds[v.field as usize].as_ref()) {
                Some(Some(q)) => term = term.mul(q),
                _ => plain.push(*v),
            }
        }
        out.add_scaled(&term.mul_monomial(&plain), Rational::ONE);
    }
    out
}

/// The temporaries the outputs use, renumbered in order and named, and the outputs over the
/// new numbers.
fn keep_used(temps: &Temps, outputs: &[Poly]) -> (Vec<(String, Sum)>, Vec<Sum>) {
    let mut used = vec![false; temps.polys.len()];
    for p in outputs {
        for m in p.0.keys() {
            for v in m {
                if v.operand == TEMP {
                    used[v.field as usize] = true;
                }
            }
        }
    }
    let mut renum = vec![0u16; temps.polys.len()];
    let mut kept = Vec::new();
    for i in 0..temps.polys.len() {
        if used[i] {
            renum[i] = kept.len() as u16;
            kept.push((temps.names[i].clone(), Sum::from_poly(&temps.polys[i])));
        }
    }
    let outputs = outputs.iter().map(|p| renumbered(p, &renum)).collect();
    (kept, outputs)
}

/// `p` with temporary `i` renamed `renum[i]`, as a [`Sum`].
fn renumbered(p: &Poly, renum: &[u16]) -> Sum {
    let mut q = Poly::default();
    for (m, &c) in &p.0 {
        let mut mm: Monomial = m
            .iter()
            .map(|v| {
                if v.operand == TEMP {
                    Var {
                        operand: TEMP,
                        field: renum[v.field as usize],
                    }
                } else {
                    *v
                }
            })
            .collect();
        mm.sort();
        q.add_term(mm, c);
    }
    Sum::from_poly(&q)
}

/// The magnitude shared by every coefficient of `p`, or 1 when they differ.
fn common_magnitude(p: &Poly) -> Rational {
    shared_magnitude(p.0.values().copied()).unwrap_or(Rational::ONE)
}
