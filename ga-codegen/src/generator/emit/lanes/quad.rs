//! f32 geometric products in 4-lane form ([`crate::runtime::f32x4::F32x4`]).
//!
//! The output fields are taken four by four. Each output quad is a sum of
//! `splat(a.x) * (b.y0, b.y1, b.y2, b.y3)` terms, where the operand quad is a quad of the
//! operand's storage (`b.s, b.e12, b.e13, b.e23`) loaded once, or a shuffle of it. Terms are
//! grouped by their vector of coefficients, so that each group is signed (an exact sign-bit
//! flip) or scaled once. The f64 twin is the paired-lane form in `lanes.rs`, which also finds the terms.

use super::{lane_terms, lead_with_added, signed_sum, LaneTerms};
use crate::generator::emit::render::{ident, lit};
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::SymMv;
use crate::runtime::rational::Rational;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

/// One lane term: operand field index per lane (`None`: the lane has no term).
type Tuple = [Option<u16>; 4];

/// A signed lane term (`true`: subtracted): the versor field splatted and the operand tuple.
type SignedTerm = (bool, (u16, Tuple));

/// The lane terms of one output quad, keyed by their vector of coefficients (first non-zero
/// positive) with the terms signed.
type QuadGroups = BTreeMap<[Rational; 4], Vec<SignedTerm>>;

/// What a 4-lane body loads up front: the versor fields it splats, the operand quads (by
/// index) and the shuffles of them, as `(quad, lanes)`; identity shuffles use the quad itself.
#[derive(Default)]
pub(crate) struct QuadLoads {
    splats: BTreeSet<u16>,
    quads: BTreeSet<usize>,
    shuffles: BTreeSet<(usize, [u8; 4])>,
}

impl QuadLoads {
    /// The statements that load them: the runtime's `F32x4` (`rt` is the runtime crate path),
    /// the splats of versor `ta`'s fields, the quads of operand `tb` (`0.0` past its last
    /// field), then the shuffles.
    pub(crate) fn tokens(&self, rt: &TokenStream, ta: &TypeDef, tb: &TypeDef) -> TokenStream {
        let mut body = quote!(use #rt::runtime::f32x4::F32x4;);
        for j in &self.splats {
            let (aj, x) = (splat_name(ta, *j), ident(&ta.fields[*j as usize].name));
            body.extend(quote!(let #aj = F32x4::splat(a.#x);));
        }
        for &q in &self.quads {
            let f = |i: usize| {
                tb.fields.get(4 * q + i).map_or(quote!(0.0), |f| {
                    let x = ident(&f.name);
                    quote!(b.#x)
                })
            };
            let (bq, f0, f1, f2, f3) = (ident(&format!("b_q{q}")), f(0), f(1), f(2), f(3));
            body.extend(quote!(let #bq = F32x4::new(#f0, #f1, #f2, #f3);));
        }
        for (q, lanes) in &self.shuffles {
            let imm = Literal::i32_unsuffixed(crate::runtime::f32x4::shuffle_imm(*lanes));
            let (bq, name) = (ident(&format!("b_q{q}")), shuffle_name(*q, lanes));
            body.extend(quote!(let #name = #bq.shuffle::<#imm>();));
        }
        body
    }
}

/// The body of `a * b` (types `ta`, `tb`, result `t`, symbolic product `m`) in 4-lane form;
/// `None` when the product does not qualify (constants, fewer than four fields, a term that
/// is not `a.x * b.y`, or too little saved). The emitter writes the doc with the scalar
/// expansion.
///
/// `rt` is the runtime crate path.
pub(crate) fn build(
    ta: &TypeDef,
    tb: &TypeDef,
    t: &TypeDef,
    m: &SymMv,
    rt: &TokenStream,
) -> Option<TokenStream> {
    let lanes = lane_terms(ta, tb, t, m)?;
    let scalar_terms: usize = lanes.iter().flat_map(|l| l.values()).map(Vec::len).sum();
    let mut loads = QuadLoads::default();
    let mut outputs = Vec::new();
    let mut vector_ops = 0usize;
    for (pi, quad) in t.fields.chunks(4).enumerate() {
        let lanes = &lanes[4 * pi..4 * pi + quad.len()];
        let (expr, ops) = quad_sum(lanes, ta, tb, [false; 4], &mut loads);
        vector_ops += ops;
        let o = ident(&format!("o{pi}"));
        outputs.push(quote!(let #o = #expr; let #o = #o.to_array();));
    }
    // The slot form (shuffles on both sides) where it costs less.
    let broadcast_ops = vector_ops + loads.splats.len() + loads.shuffles.len();
    if let Some((body, ops)) = super::slots::build(ta, tb, t, &lanes, rt) {
        if ops < broadcast_ops && ops <= scalar_terms {
            return Some(body);
        }
    }
    // Worth it only when the lanes do at most half the scalar work.
    if vector_ops > scalar_terms {
        return None;
    }
    let mut body = loads.tokens(rt, ta, tb);
    body.extend(outputs);
    body.extend(quad_result(t));
    Some(body)
}

/// One output quad (`quad`: its lanes' terms, up to four) as a sum of signed groups of
/// `splat(a.x) * b quad` terms, with the vector operations it costs; the loads it needs go to
/// `loads`. The lanes marked `free` are discarded by the caller: a term may put anything there
/// (so an operand quad with a free lane can still be a shuffle).
pub(crate) fn quad_sum(
    quad: &[LaneTerms],
    ta: &TypeDef,
    tb: &TypeDef,
    free: [bool; 4],
    loads: &mut QuadLoads,
) -> (TokenStream, usize) {
    let groups = quad_groups(quad, &mut loads.splats);
    let alone = groups.len() == 1;
    let mut parts: Vec<(bool, TokenStream)> = Vec::new();
    let mut vector_ops = 0;
    for (coef, terms) in groups {
        let (part, ops) = group_part(&coef, terms, (ta, tb), (free, alone), loads);
        vector_ops += ops;
        parts.push(part);
    }
    (signed_sum(parts, &quote!(F32x4::splat(0.0))), vector_ops)
}

/// Group the terms of one output quad (`quad`: its lanes' terms, up to four) by coefficient
/// vector; a lane without a term takes the first coefficient of the others. The versor fields
/// used are added to `splats`.
fn quad_groups(quad: &[LaneTerms], splats: &mut BTreeSet<u16>) -> QuadGroups {
    let empty = BTreeMap::new();
    let l: Vec<&LaneTerms> = (0..4).map(|i| quad.get(i).unwrap_or(&empty)).collect();
    let mut groups = QuadGroups::new();
    let js: BTreeSet<u16> = l.iter().flat_map(|x| x.keys().copied()).collect();
    for j in js {
        let t: Vec<&[(u16, Rational)]> = l
            .iter()
            .map(|x| x.get(&j).map_or(&[][..], |v| v.as_slice()))
            .collect();
        let depth = t.iter().map(|v| v.len()).max().unwrap_or(0);
        for i in 0..depth {
            let tuple: Tuple = std::array::from_fn(|lane| t[lane].get(i).map(|x| x.0));
            let fill = t
                .iter()
                .find_map(|v| v.get(i).map(|x| x.1))
                .expect("a term");
            let coef: [Rational; 4] =
                std::array::from_fn(|lane| t[lane].get(i).map_or(fill, |x| x.1));
            let neg = coef[0] < Rational::ZERO;
            let key = if neg { coef.map(|c| -c) } else { coef };
            splats.insert(j);
            groups.entry(key).or_default().push((neg, (j, tuple)));
        }
    }
    groups
}

/// One group of an output quad (`alone`: the quad's only group) as a signed part (`true`:
/// subtracted): its terms summed (led by an added one) and signed (sign-bit flips) or scaled
/// once by `coef`; with the vector operations it costs. The operand quads and shuffles used go to `loads`.
fn group_part(
    coef: &[Rational; 4],
    mut terms: Vec<SignedTerm>,
    (ta, tb): (&TypeDef, &TypeDef),
    (free, alone): ([bool; 4], bool),
    loads: &mut QuadLoads,
) -> ((bool, TokenStream), usize) {
    let mut vector_ops = 0usize;
    let all_neg = lead_with_added(&mut terms);
    let mut sum = TokenStream::new();
    for (i, (neg, (j, tuple))) in terms.iter().enumerate() {
        let tuple = fill_free(tuple, free);
        let (bvec, built) = operand_quad(&tuple, tb, &mut loads.quads, &mut loads.shuffles);
        if i > 0 {
            sum.extend(if *neg { quote!(-) } else { quote!(+) });
        }
        let aj = splat_name(ta, *j);
        sum.extend(quote!(#aj * #bvec));
        // A quad built lane by lane costs about as much as the scalar terms it saves.
        vector_ops += if built { 4 } else { 2 };
    }
    // Parenthesised unless it is the whole expression (one group, added, not scaled).
    let whole = alone && !all_neg && is_unscaled(coef);
    let grouped = if terms.len() > 1 && !whole {
        quote!((#sum))
    } else {
        sum
    };
    let (part, ops) = scale_group(coef, grouped);
    ((all_neg, part), vector_ops + ops)
}

/// A group's sum times its coefficient vector: as it is for `(1, 1, 1, 1)`, an exact sign-bit
/// flip for `±1` lanes, else a multiply by the constant vector; with the vector operations
/// that costs (0 or 1). Shared by the broadcast and slot forms.
pub(super) fn scale_group(coef: &[Rational; 4], grouped: TokenStream) -> (TokenStream, usize) {
    if is_unscaled(coef) {
        (grouped, 0)
    } else if coef
        .iter()
        .all(|c| *c == Rational::ONE || *c == -Rational::ONE)
    {
        let mask: i32 = (0..4)
            .filter(|&i| coef[i] < Rational::ZERO)
            .map(|i| 1 << i)
            .sum();
        let mask = syn::LitInt::new(&format!("{mask:#06b}"), Span::call_site());
        (quote!(#grouped.flip::<#mask>()), 1)
    } else {
        let c = coef.map(lit);
        (quote!(#grouped * F32x4::new(#(#c),*)), 1)
    }
}

/// A group whose coefficients are all 1 (no flip or scaling).
pub(super) fn is_unscaled(coef: &[Rational; 4]) -> bool {
    coef.iter().all(|c| *c == Rational::ONE)
}

/// The result `T { x: o0[0], y: o0[1], .. }` from the output quads `o0, o1, ..` (as arrays).
pub(super) fn quad_result(t: &TypeDef) -> TokenStream {
    let fields = t.fields.iter().enumerate().map(|(i, f)| {
        let (x, o, lane) = (
            ident(&f.name),
            ident(&format!("o{}", i / 4)),
            Literal::usize_unsuffixed(i % 4),
        );
        quote!(#x: #o[#lane])
    });
    let tn = ident(&t.name);
    quote!(#tn { #(#fields),* })
}

/// `a_x`: field `j` of the versor `ta` splatted to the four lanes.
fn splat_name(ta: &TypeDef, j: u16) -> Ident {
    ident(&format!("a_{}", ta.fields[j as usize].name))
}

fn shuffle_name(q: usize, lanes: &[u8; 4]) -> Ident {
    ident(&format!(
        "b_q{q}_{}{}{}{}",
        lanes[0], lanes[1], lanes[2], lanes[3]
    ))
}

/// A lane term with its free lanes (no term, result discarded) taking the first field the
/// term uses, so that they do not stop the quad from being one shuffle.
fn fill_free(tuple: &Tuple, free: [bool; 4]) -> Tuple {
    let first = tuple.iter().flatten().next().copied();
    std::array::from_fn(|i| match tuple[i] {
        None if free[i] => first,
        x => x,
    })
}

/// The operand quad of a lane term over operand type `tb`: a loaded quad, a shuffle of one, or
/// built lane by lane (then `true`).
fn operand_quad(
    tuple: &Tuple,
    tb: &TypeDef,
    used_quads: &mut BTreeSet<usize>,
    used_shuffles: &mut BTreeSet<(usize, [u8; 4])>,
) -> (TokenStream, bool) {
    let nbq = tb.fields.len().div_ceil(4);
    let quads: BTreeSet<usize> = tuple.iter().flatten().map(|k| *k as usize / 4).collect();
    if tuple.iter().all(Option::is_some) && quads.len() == 1 {
        let q = *quads.iter().next().expect("one quad");
        if q < nbq {
            let lanes: [u8; 4] = tuple.map(|k| (k.expect("full") as usize - 4 * q) as u8);
            used_quads.insert(q);
            if lanes == [0, 1, 2, 3] {
                let bq = ident(&format!("b_q{q}"));
                return (quote!(#bq), false);
            }
            used_shuffles.insert((q, lanes));
            let name = shuffle_name(q, &lanes);
            return (quote!(#name), false);
        }
    }
    let f = |k: Option<u16>| {
        k.map_or(quote!(0.0), |k| {
            let x = ident(&tb.fields[k as usize].name);
            quote!(b.#x)
        })
    };
    let (f0, f1, f2, f3) = (f(tuple[0]), f(tuple[1]), f(tuple[2]), f(tuple[3]));
    (quote!(F32x4::new(#f0, #f1, #f2, #f3)), true)
}
