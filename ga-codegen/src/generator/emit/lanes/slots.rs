//! f32 geometric products in 4-lane form with shuffles on both sides ("slots").
//!
//! The broadcast form of `quad.rs` computes an output quad as a sum of
//! `splat(a.x) * shuffle(b quad)`: one product per left field, each with its own sign
//! pattern. Here a product may take a different left field in each lane: slot `s` of an
//! output quad is `shuffle(a quad) * shuffle(b quad)`, lane `i` holding one term `c a.x b.y` of
//! output field `i`. The terms of each lane are split by the quads their factors come from and
//! ordered added-first, so that slots line up sign patterns: slots with the same coefficient
//! vector are summed and signed once (klein's motor product has this shape: 12 multiplies and
//! two sign flips). [`build`] returns the body with its cost so the caller keeps the cheaper
//! of the two forms.

use super::{signed_sum, LaneTerms};
use crate::generator::emit::render::ident;
use crate::generator::spec::TypeDef;
use crate::runtime::rational::Rational;
use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

/// A term of one lane: left field, right field, coefficient.
type Term = (u16, u16, Rational);

/// A slot: per lane the term it holds (`None`: a free lane, whose result is discarded).
type Slot = [Option<Term>; 4];

/// A quad of one operand (`0`: left `a`, `1`: right `b`): its index and the lanes picked.
type QuadPick = (u8, usize, [u8; 4]);

/// Loads and shuffles a slot body uses.
#[derive(Default)]
struct Loads {
    quads: BTreeSet<(u8, usize)>,
    shuffles: BTreeSet<QuadPick>,
}

impl Loads {
    /// `a_q0`, `b_q1_1032`: the name of a quad or a shuffle of it.
    fn name(pick: &QuadPick) -> Ident {
        let (side, q, lanes) = pick;
        let s = if *side == 0 { "a" } else { "b" };
        if *lanes == [0, 1, 2, 3] {
            ident(&format!("{s}_q{q}"))
        } else {
            ident(&format!(
                "{s}_q{q}_{}{}{}{}",
                lanes[0], lanes[1], lanes[2], lanes[3]
            ))
        }
    }

    /// Register a pick and return its name.
    fn pick(&mut self, pick: QuadPick) -> Ident {
        self.quads.insert((pick.0, pick.1));
        if pick.2 != [0, 1, 2, 3] {
            self.shuffles.insert(pick);
        }
        Loads::name(&pick)
    }

    /// The statements: the quads of `ta` (side 0) and `tb` (side 1) as stored (`0.0` past the
    /// last field), then the shuffles.
    fn tokens(&self, rt: &TokenStream, ta: &TypeDef, tb: &TypeDef) -> TokenStream {
        let mut body = quote!(use #rt::runtime::f32x4::F32x4;);
        for &(side, q) in &self.quads {
            let (t, v) = if side == 0 {
                (ta, quote!(a))
            } else {
                (tb, quote!(b))
            };
            let lanes = (0..4).map(|i| {
                t.fields.get(4 * q + i).map_or(quote!(0.0), |f| {
                    let x = ident(&f.name);
                    quote!(#v.#x)
                })
            });
            let name = Loads::name(&(side, q, [0, 1, 2, 3]));
            body.extend(quote!(let #name = F32x4::new(#(#lanes),*);));
        }
        for pick in &self.shuffles {
            let imm = Literal::i32_unsuffixed(crate::runtime::f32x4::shuffle_imm(pick.2));
            let (name, src) = (
                Loads::name(pick),
                Loads::name(&(pick.0, pick.1, [0, 1, 2, 3])),
            );
            body.extend(quote!(let #name = #src.shuffle::<#imm>();));
        }
        body
    }
}

/// The slots of one output quad, or `None` when a lane cannot be lined up (a class of terms
/// with more terms in one lane than another that is not free). `seen` holds the quad picks
/// already loaded (the slots chosen here add theirs).
fn quad_slots(quad: &[LaneTerms], seen: &mut BTreeSet<QuadPick>) -> Option<Vec<Slot>> {
    // Terms by class (left quad, right quad), per lane, added first.
    let mut classes: BTreeMap<(usize, usize), [Vec<Term>; 4]> = BTreeMap::new();
    for (i, lane) in quad.iter().enumerate() {
        for (&x, ys) in lane {
            for &(y, c) in ys {
                let class = classes.entry((x as usize / 4, y as usize / 4)).or_default();
                class[i].push((x, y, c));
            }
        }
    }
    // Lanes past the last output field are free; every other lane needs its terms.
    let used: [bool; 4] = std::array::from_fn(|i| i < quad.len());
    let mut slots = Vec::new();
    let mut keys: BTreeSet<[Rational; 4]> = BTreeSet::new();
    for lanes in classes.values_mut() {
        let depth = lanes.iter().map(Vec::len).max().unwrap_or(0);
        if (0..4).any(|i| used[i] && lanes[i].len() != depth) {
            return None;
        }
        for l in lanes.iter_mut() {
            l.sort_by_key(|&(x, y, c)| (c < Rational::ZERO, x, y));
        }
        for left in (1..=depth).rev() {
            let slot = best_slot(lanes, left, seen, &keys);
            let (pa, pb, coef) = slot_parts(&slot);
            seen.extend([pa, pb]);
            keys.insert(group_key(coef).1);
            slots.push(slot);
        }
    }
    Some(slots)
}

/// The next slot from the terms left in each lane (`left` of them in every used lane): the
/// choice of one term per lane that reuses the most loaded quad picks and group sign
/// patterns (searched in full while that is at most 4,096 choices, else the first terms). The
/// terms taken are removed.
fn best_slot(
    lanes: &mut [Vec<Term>; 4],
    left: usize,
    seen: &BTreeSet<QuadPick>,
    keys: &BTreeSet<[Rational; 4]>,
) -> Slot {
    let used: Vec<usize> = (0..4).filter(|&i| !lanes[i].is_empty()).collect();
    let mut best: (i32, Vec<usize>) = (i32::MIN, vec![0; used.len()]);
    if left.pow(used.len() as u32) <= 4096 {
        let mut choice = vec![0usize; used.len()];
        loop {
            let mut slot: Slot = [None; 4];
            for (k, &i) in used.iter().enumerate() {
                slot[i] = Some(lanes[i][choice[k]]);
            }
            let (pa, pb, coef) = slot_parts(&slot);
            let known = |p: &QuadPick| p.2 == [0, 1, 2, 3] || seen.contains(p);
            let score = 2 * i32::from(keys.contains(&group_key(coef).1))
                + i32::from(known(&pa))
                + i32::from(known(&pb));
            if score > best.0 {
                best = (score, choice.clone());
            }
            // The next choice, odometer-style.
            let mut k = 0;
            while k < choice.len() {
                choice[k] += 1;
                if choice[k] < left {
                    break;
                }
                choice[k] = 0;
                k += 1;
            }
            if k == choice.len() {
                break;
            }
        }
    }
    let mut slot: Slot = [None; 4];
    for (k, &i) in used.iter().enumerate() {
        slot[i] = Some(lanes[i].remove(best.1[k]));
    }
    slot
}

/// A coefficient vector as a group key: made positive in its first lane (`true`: negated).
fn group_key(coef: [Rational; 4]) -> (bool, [Rational; 4]) {
    let neg = coef[0] < Rational::ZERO;
    (neg, if neg { coef.map(|c| -c) } else { coef })
}

/// A slot's factors as quad picks (free lanes repeat lane 0's pick) and its coefficients.
fn slot_parts(slot: &Slot) -> (QuadPick, QuadPick, [Rational; 4]) {
    let first = slot.iter().flatten().next().copied().expect("a term");
    let t = |i: usize| slot[i].unwrap_or(first);
    let a = (
        0u8,
        first.0 as usize / 4,
        std::array::from_fn(|i| (t(i).0 % 4) as u8),
    );
    let b = (
        1u8,
        first.1 as usize / 4,
        std::array::from_fn(|i| (t(i).1 % 4) as u8),
    );
    (a, b, std::array::from_fn(|i| t(i).2))
}

/// The body of `a * b` in slot form and its cost in vector operations (shuffles, multiplies,
/// adds, sign flips and scalings); `None` when an output quad's terms do not line up.
/// `lanes` are the terms per output field of `t`; `rt` the runtime crate path.
pub(super) fn build(
    ta: &TypeDef,
    tb: &TypeDef,
    t: &TypeDef,
    lanes: &[LaneTerms],
    rt: &TokenStream,
) -> Option<(TokenStream, usize)> {
    let mut seen = BTreeSet::new();
    let mut quads = Vec::new();
    for (qi, fields) in t.fields.chunks(4).enumerate() {
        quads.push(quad_slots(
            &lanes[4 * qi..4 * qi + fields.len()],
            &mut seen,
        )?);
    }
    refine(&mut quads);
    let mut loads = Loads::default();
    let mut outputs = Vec::new();
    let mut ops = 0usize;
    for (qi, slots) in quads.iter().enumerate() {
        // Slots grouped by coefficient vector, made positive in its first lane.
        let mut groups: BTreeMap<[Rational; 4], Vec<(bool, TokenStream)>> = BTreeMap::new();
        for slot in slots {
            let (pa, pb, coef) = slot_parts(slot);
            let (na, nb) = (loads.pick(pa), loads.pick(pb));
            let (neg, key) = group_key(coef);
            groups
                .entry(key)
                .or_default()
                .push((neg, quote!(#na * #nb)));
            ops += 2; // the multiply and its add
        }
        let mut parts = Vec::new();
        for (coef, mut terms) in groups {
            let all_neg = super::lead_with_added(&mut terms);
            let sum = signed_sum(terms.clone(), &quote!(F32x4::splat(0.0)));
            let grouped = if terms.len() > 1 { quote!((#sum)) } else { sum };
            let (part, scale_ops) = super::quad::scale_group(&coef, grouped);
            ops += scale_ops;
            parts.push((all_neg, part));
        }
        let expr = signed_sum(parts, &quote!(F32x4::splat(0.0)));
        let o = ident(&format!("o{qi}"));
        outputs.push(quote!(let #o = (#expr).to_array();));
    }
    ops += loads.shuffles.len();
    let mut body = loads.tokens(rt, ta, tb);
    body.extend(outputs);
    body.extend(super::quad::quad_result(t));
    Some((body, ops))
}

/// The vector operations that depend on how terms are placed in slots: the shuffles (picks
/// other than a quad as stored, shared by every output quad) and the scalings of each output
/// quad's coefficient groups.
fn placement_cost(quads: &[Vec<Slot>]) -> usize {
    let mut shuffles = BTreeSet::new();
    let mut scalings = 0;
    for slots in quads {
        let mut keys = BTreeSet::new();
        for slot in slots {
            let (pa, pb, coef) = slot_parts(slot);
            shuffles.extend([pa, pb].into_iter().filter(|p| p.2 != [0, 1, 2, 3]));
            keys.insert(group_key(coef).1);
        }
        scalings += keys.iter().filter(|k| !super::quad::is_unscaled(k)).count();
    }
    shuffles.len() + scalings
}

/// Improve the greedy placement by local search: swap the terms two slots of one output quad
/// and one class (the same left and right quads) hold in one lane, keep the swap when the
/// [`placement_cost`] does not grow (moves along equal cost let it leave a plateau), and end
/// with the cheapest placement seen. Deterministic (a fixed-seed generator), bounded: at most
/// 200 tries per slot and 4,000 in all, none above 96 slots.
fn refine(quads: &mut [Vec<Slot>]) {
    let total: usize = quads.iter().map(Vec::len).sum();
    if !(2..=96).contains(&total) {
        return;
    }
    let class = |slot: &Slot| {
        let t = slot.iter().flatten().next().expect("a term");
        (t.0 / 4, t.1 / 4)
    };
    // Swappable pairs: (quad, slot, slot) of one class.
    let mut pairs = Vec::new();
    for (q, slots) in quads.iter().enumerate() {
        for i in 0..slots.len() {
            for j in i + 1..slots.len() {
                if class(&slots[i]) == class(&slots[j]) {
                    pairs.push((q, i, j));
                }
            }
        }
    }
    if pairs.is_empty() {
        return;
    }
    let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = |n: usize| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) as usize) % n
    };
    let mut cost = placement_cost(quads);
    let mut best = (cost, quads.to_vec());
    for _ in 0..(200 * total).min(4000) {
        let (q, i, j) = pairs[next(pairs.len())];
        let lane = next(4);
        if quads[q][i][lane].is_none() {
            continue;
        }
        let swap = |quads: &mut [Vec<Slot>]| {
            let (a, b) = (quads[q][i][lane], quads[q][j][lane]);
            quads[q][i][lane] = b;
            quads[q][j][lane] = a;
        };
        swap(quads);
        let new = placement_cost(quads);
        if new <= cost {
            cost = new;
            if cost < best.0 {
                best = (cost, quads.to_vec());
            }
        } else {
            swap(quads);
        }
    }
    quads.clone_from_slice(&best.1);
}
