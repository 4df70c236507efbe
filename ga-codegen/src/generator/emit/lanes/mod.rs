//! Paired-lane forms: dense geometric products between versor types computed two output
//! fields at a time in one [`crate::runtime::f64x2::F64x2`].

pub(crate) mod quad;
mod slots;
mod wide;

use super::render::{float, ident, lit};
use super::{Gen, ScalarType};
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::SymMv;
use crate::runtime::rational::Rational;
use proc_macro2::{Ident, TokenStream};
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

/// One term of a paired-lane product: `splat(a_j) * bvec`, where `bvec` holds the operand
/// fields of the two lanes (`None`: that lane has no term).
struct LaneTerm {
    a: u16,
    b: [Option<u16>; 2],
}

/// A group of lane terms sharing one pair of coefficients: `(t1 + t2 - t3) * (c0, c1)`.
struct Part {
    /// The group is subtracted.
    neg: bool,
    /// The sum of the terms, without parentheses.
    sum: TokenStream,
    /// More than one term (parenthesised when scaled or combined).
    several: bool,
    /// The coefficient pair, `None` for `(1, 1)`.
    scale: Option<TokenStream>,
}

impl Part {
    fn tokens(&self, alone: bool) -> TokenStream {
        let sum = &self.sum;
        let grouped = if self.several && !(alone && self.scale.is_none()) {
            quote!((#sum))
        } else {
            sum.clone()
        };
        match &self.scale {
            None => grouped,
            Some(sc) => quote!(#grouped * #sc),
        }
    }
}

/// The terms of one output field of a lane-form product: `a_j -> [(b_k, c)]`.
pub(super) type LaneTerms = BTreeMap<u16, Vec<(u16, Rational)>>;

/// The terms of a lane-form product, per output field of `t`: `a_j -> [(b_k, c)]` for each
/// term `c a_j b_k` (the output field's sign applied). `None` when the product does not
/// qualify for a lane form: operands that are not versors, constants, fewer than four fields,
/// or a term that is not `a.x * b.y`. Shared by the paired (f64) and 4-lane (f32) builders.
pub(super) fn lane_terms(
    ta: &TypeDef,
    tb: &TypeDef,
    t: &TypeDef,
    m: &SymMv,
) -> Option<Vec<LaneTerms>> {
    let qualifies = ta.versor
        && tb.versor
        && ta.constants.is_empty()
        && tb.constants.is_empty()
        && ta.fields.len() >= 4
        && tb.fields.len() >= 4
        && t.fields.len() >= 4;
    if !qualifies {
        return None;
    }
    let mut lanes = Vec::with_capacity(t.fields.len());
    for f in &t.fields {
        let mut by_a = LaneTerms::new();
        for (mono, &c) in &m.get(f.bitmap).0 {
            match mono.as_slice() {
                [x, y] if x.operand == 0 && y.operand == 1 => by_a
                    .entry(x.field)
                    .or_default()
                    .push((y.field, c * Rational::int(f.sign as i64))),
                _ => return None,
            }
        }
        lanes.push(by_a);
    }
    Some(lanes)
}

/// Order a group of signed terms (`true`: subtracted) to lead with an added one. When every
/// term is subtracted, the signs are flipped and `true` is returned: the group is negated.
pub(super) fn lead_with_added<T>(terms: &mut [(bool, T)]) -> bool {
    let all_neg = terms.iter().all(|t| t.0);
    if all_neg {
        terms.iter_mut().for_each(|t| t.0 = false);
    }
    if let Some(first) = terms.iter().position(|t| !t.0) {
        terms.swap(0, first);
    }
    all_neg
}

/// `p0 + p1 - p2 ...` over signed parts (`true`: subtracted), led by an added part where there
/// is one (else `zero - p0 ...`); `zero` when there are no parts. Shared by the paired (f64) and
/// 4-lane (f32) builders, with `zero` the lane type's zero.
pub(super) fn signed_sum(mut parts: Vec<(bool, TokenStream)>, zero: &TokenStream) -> TokenStream {
    // Start with a group that is added, so that no negation is needed up front.
    if let Some(first) = parts.iter().position(|p| !p.0) {
        parts.swap(0, first);
    }
    let mut expr = TokenStream::new();
    for (i, (neg, part)) in parts.into_iter().enumerate() {
        if i == 0 {
            expr = if neg { quote!(#zero - #part) } else { part };
        } else if neg {
            expr.extend(quote!(- #part));
        } else {
            expr.extend(quote!(+ #part));
        }
    }
    if expr.is_empty() {
        expr = zero.clone();
    }
    expr
}

/// The lane terms of one output pair, keyed by their coefficient pair (first one positive) with
/// the terms signed; `(c0, c1)` and `(-c0, -c1)` share a group.
type PairGroups = BTreeMap<(Rational, Rational), Vec<(bool, LaneTerm)>>;

/// The names of a paired-lane body: the operand fields, the splatted versor fields (`a_x`) and
/// the operand pairs (`b_x_y`).
struct PairNames<'t> {
    ta: &'t TypeDef,
    tb: &'t TypeDef,
}

impl PairNames<'_> {
    /// The name of field `j` of the versor (operand `a`).
    fn af(&self, j: u16) -> &str {
        self.ta.fields[j as usize].name.as_str()
    }

    /// The name of field `k` of operand `b`.
    fn bf(&self, k: u16) -> &str {
        self.tb.fields[k as usize].name.as_str()
    }

    /// `a_x`: versor field `j` splatted to both lanes.
    fn a_lane(&self, j: u16) -> Ident {
        ident(&format!("a_{}", self.af(j)))
    }

    /// `b_x_y`: the operand fields `k0`, `k1` as one pair.
    fn b_pair(&self, k0: u16, k1: u16) -> Ident {
        ident(&format!("b_{}_{}", self.bf(k0), self.bf(k1)))
    }
}

/// What a paired-lane body loads up front: the versor fields it splats, and the operand pairs
/// it uses, as `(first field, swapped)`.
#[derive(Default)]
struct PairLoads {
    splats: BTreeSet<u16>,
    pairs: BTreeSet<(u16, bool)>,
}

impl PairLoads {
    /// The statements that load them: the runtime's `F64x2`, the splats, the pairs as stored,
    /// then the swapped pairs from those.
    fn tokens(&self, rt: &TokenStream, names: &PairNames<'_>) -> TokenStream {
        let mut body = quote!(use #rt::runtime::f64x2::F64x2;);
        for &j in &self.splats {
            let (al, f) = (names.a_lane(j), ident(names.af(j)));
            body.extend(quote!(let #al = F64x2::splat(a.#f);));
        }
        for &(k, swapped) in &self.pairs {
            if !swapped || !self.pairs.contains(&(k, false)) {
                let (p, f0, f1) = (
                    names.b_pair(k, k + 1),
                    ident(names.bf(k)),
                    ident(names.bf(k + 1)),
                );
                body.extend(quote!(let #p = F64x2::new(b.#f0, b.#f1);));
            }
        }
        for &(k, swapped) in &self.pairs {
            if swapped {
                let (p, q) = (names.b_pair(k + 1, k), names.b_pair(k, k + 1));
                body.extend(quote!(let #p = #q.swap();));
            }
        }
        body
    }
}

/// Group the terms of one output pair (lanes `l0`, `l1`) by coefficient pair; a lane without a
/// term takes the other lane's coefficient. The versor fields used are added to `splats`.
fn pair_groups(l0: &LaneTerms, l1: &LaneTerms, splats: &mut BTreeSet<u16>) -> PairGroups {
    let mut groups = PairGroups::new();
    let js: BTreeSet<u16> = l0.keys().chain(l1.keys()).copied().collect();
    for j in js {
        let (t0, t1) = (
            l0.get(&j).map_or(&[][..], |v| v),
            l1.get(&j).map_or(&[][..], |v| v),
        );
        for i in 0..t0.len().max(t1.len()) {
            let (x0, x1) = (t0.get(i), t1.get(i));
            let c0 = x0.or(x1).map(|x| x.1).expect("a term");
            let c1 = x1.or(x0).map(|x| x.1).expect("a term");
            let neg = c0 < Rational::ZERO;
            let key = if neg { (-c0, -c1) } else { (c0, c1) };
            splats.insert(j);
            groups.entry(key).or_default().push((
                neg,
                LaneTerm {
                    a: j,
                    b: [x0.map(|x| x.0), x1.map(|x| x.0)],
                },
            ));
        }
    }
    groups
}

/// The operand pair of a lane term: a stored pair of adjacent fields (`b_s_e12`, or that pair
/// swapped; noted in `pairs`), or `F64x2::new(b.x, b.y)` with `0.0` for a lane without a term.
fn operand_pair(
    b: [Option<u16>; 2],
    names: &PairNames<'_>,
    pairs: &mut BTreeSet<(u16, bool)>,
) -> TokenStream {
    match b {
        [Some(k0), Some(k1)] if k0 % 2 == 0 && k1 == k0 + 1 => {
            pairs.insert((k0, false));
            let p = names.b_pair(k0, k1);
            quote!(#p)
        }
        [Some(k0), Some(k1)] if k1 % 2 == 0 && k0 == k1 + 1 => {
            pairs.insert((k1, true));
            let p = names.b_pair(k0, k1);
            quote!(#p)
        }
        [k0, k1] => {
            let lane = |k: Option<u16>| match k {
                Some(k) => {
                    let f = ident(names.bf(k));
                    quote!(b.#f)
                }
                None => float(0.0),
            };
            let (x0, x1) = (lane(k0), lane(k1));
            quote!(F64x2::new(#x0, #x1))
        }
    }
}

/// One group of an output pair as a [`Part`]: its terms summed (led by an added one) and
/// scaled once by the coefficient pair `(c0, c1)`. The operand pairs used go to `loads`.
fn group_part(
    (c0, c1): (Rational, Rational),
    mut terms: Vec<(bool, LaneTerm)>,
    names: &PairNames<'_>,
    loads: &mut PairLoads,
) -> Part {
    let all_neg = lead_with_added(&mut terms);
    let mut sum = TokenStream::new();
    for (i, (neg, lt)) in terms.iter().enumerate() {
        let bvec = operand_pair(lt.b, names, &mut loads.pairs);
        if i > 0 {
            sum.extend(if *neg { quote!(-) } else { quote!(+) });
        }
        let al = names.a_lane(lt.a);
        sum.extend(quote!(#al * #bvec));
    }
    let scale = if c0 == c1 && c0 == Rational::ONE {
        None
    } else if c0 == c1 {
        let c = lit(c0);
        Some(quote!(F64x2::splat(#c)))
    } else {
        let (c0, c1) = (lit(c0), lit(c1));
        Some(quote!(F64x2::new(#c0, #c1)))
    };
    Part {
        neg: all_neg,
        sum,
        several: terms.len() > 1,
        scale,
    }
}

/// The expression of one output pair from its groups' parts.
fn pair_expr(parts: &[Part]) -> TokenStream {
    let alone = parts.len() == 1;
    let signed = parts
        .iter()
        .map(|p| (p.neg, p.tokens(alone && !p.neg)))
        .collect();
    signed_sum(signed, &quote!(F64x2::splat(0.0)))
}

/// The result `T { x: o0.lo(), y: o0.hi(), .. }` from the output pairs `o0, o1, ..`.
fn paired_result(t: &TypeDef) -> TokenStream {
    let name = ident(&t.name);
    let fields = t.fields.iter().enumerate().map(|(i, f)| {
        let (id, o) = (ident(&f.name), ident(&format!("o{}", i / 2)));
        if i % 2 == 0 {
            quote!(#id: #o.lo(),)
        } else {
            quote!(#id: #o.hi(),)
        }
    });
    quote!(#name { #(#fields)* })
}

impl Gen<'_> {
    /// The body of a geometric product between two versor types in paired-lane form, or `None`
    /// when the product does not qualify (f32, constants, small types, non-bilinear terms).
    ///
    /// The output fields are taken two by two; each pair is one [`crate::runtime::f64x2::F64x2`]
    /// computed as a sum of `splat(a.x) * (b.y, b.z)` terms, grouped by their pair of
    /// coefficients so that each group is scaled once. Operand fields that sit next to each
    /// other in storage (`b.s, b.e12`) load as one pair, or as that pair swapped.
    pub(super) fn build_paired(
        &self,
        ti: usize,
        m: &SymMv,
        ta: &TypeDef,
        tb: &TypeDef,
    ) -> Option<TokenStream> {
        self.build_paired_into(&self.spec.types[ti], m, ta, tb)
    }

    /// [`Gen::build_paired`] into any result type `t` (a declared one, or the local matrix-unit
    /// type of a matrix-form product).
    pub(super) fn build_paired_into(
        &self,
        t: &TypeDef,
        m: &SymMv,
        ta: &TypeDef,
        tb: &TypeDef,
    ) -> Option<TokenStream> {
        if self.scalar != ScalarType::F64 {
            return None;
        }
        let lanes = lane_terms(ta, tb, t, m)?;
        let names = PairNames { ta, tb };
        let mut loads = PairLoads::default();
        let mut outputs = Vec::new();
        let mut lane_terms = 0usize;
        let empty = LaneTerms::new();
        for (pi, pair) in t.fields.chunks(2).enumerate() {
            let l1 = lanes
                .get(2 * pi + 1)
                .filter(|_| pair.len() == 2)
                .unwrap_or(&empty);
            let groups = pair_groups(&lanes[2 * pi], l1, &mut loads.splats);
            lane_terms += groups.values().map(Vec::len).sum::<usize>();
            let parts: Vec<Part> = groups
                .into_iter()
                .map(|(c, terms)| group_part(c, terms, &names, &mut loads))
                .collect();
            let (o, expr) = (ident(&format!("o{pi}")), pair_expr(&parts));
            outputs.push(quote!(let #o = #expr;));
        }
        // Worth it only when pairing saves most multiplies (sparse products stay scalar).
        let scalar_terms: usize = lanes.iter().flat_map(|l| l.values()).map(Vec::len).sum();
        if 5 * lane_terms > 3 * scalar_terms {
            return None;
        }
        let mut body = loads.tokens(&self.rt, &names);
        body.extend(outputs);
        body.extend(paired_result(t));
        Some(body)
    }
}
