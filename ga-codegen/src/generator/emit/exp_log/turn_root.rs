//! The emitted square root beyond a half turn of a versor with a rotation and a commuting part
//! that is not one: a translation along its axis (PGA and CGA motors, the null form), a boost
//! (STA's Lorentz rotors) or a dilation (CGA's similarities). Its `sqrt` of a versor with a
//! negative scalar part is `exp(log(v) / 2)` with the logarithm read the long way round.
//!
//! Near a full turn `normalize(1 + v)` fails for these versors even with the scalar part taken
//! without cancelling: `1 + v` is then nearly all the other part, normalising it divides by a
//! number with a tiny scalar part, and terms of size `|other| / d` cancel at a distance `d`
//! from the full turn (an f32 motor that turns `2 pi - 1e-9` and shifts along its axis got a
//! root whose square was 58 off; an f64 similarity with a dilation of 0.3, 2e-4 off at
//! `d = 1e-7`). The axis of the root is only determined to `eps |other| / d` by `v`'s
//! coefficients too, but an axis moved by that much changes a motion of nearly a full turn by
//! `eps |other|` alone; what matters is that the root is an exact versor. So the rotation part
//! is split off as the logarithm does, projected on the simple bivectors once more (the split
//! leaves an error of size `eps |other| / d` off them, which the long logarithm would scale by
//! `pi / d` into a motion), and `exp` of half the long logarithm, a closed form with no
//! cancellation at a quarter turn, is the root.

use super::logarithm::project_on_lines;
use super::{build, grade_part, negative_squares, Ctx};
use crate::generator::emit::render::ident;
use crate::generator::emit::Gen;
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{Poly, Product, SymMv};
use crate::runtime::blade::Bitmap;
use crate::runtime::rational::Rational;
use proc_macro2::TokenStream;
use quote::quote;

/// The name of the emitted inherent method (private to the generated module).
pub(crate) const METHOD: &str = "root_beyond_a_half_turn";

/// The emitted root and when `sqrt` takes it.
pub(crate) struct TurnRoot {
    /// `impl V { fn root_beyond_a_half_turn(self) -> V }`.
    pub(crate) item: TokenStream,
    /// `<V>_4 <V>_4` over `V`'s fields, where it may be positive (two rotations): the root is
    /// taken only where it is not. `None`: always (for a negative scalar part).
    pub(crate) guard: Option<Poly>,
}

impl Gen<'_> {
    /// `impl V { fn root_beyond_a_half_turn(self) -> V }` for a versor type with a rotation
    /// and another commuting part that is not a rotation: a translation along its axis (the
    /// null form, PGA and CGA motors) or a boost or dilation (STA rotors, CGA similarities),
    /// when the smallest bivector type holding its bivector blades has an `exp` into it.
    /// In a type that may also hold two rotations (CGA's `Even`) it is taken only where the
    /// grade-4 part does not square positive (two rotations keep `normalize(1 + v)` and their
    /// half-turn cut's own form). `None` for every other type: rotors alone (whose root
    /// `normalize(1 + v)` keeps to rounding), types whose grade-4 part only squares positive
    /// (G(4,0)) and types without a logarithm.
    /// `pairs` are [`Gen::exp_pairs`].
    pub(crate) fn turn_root(&mut self, vt: &TypeDef, pairs: &[(usize, usize)]) -> Option<TurnRoot> {
        let spec = self.spec;
        let lo = self.log_type(vt)?;
        let vi = spec.types.iter().position(|t| t.name == vt.name)?;
        if !pairs.contains(&(lo, vi)) {
            return None;
        }
        let s = self.s.clone();
        let mut cx = Ctx::new(vt, s.clone());
        let r0 = cx.at(&SymMv::of_type(vt, 0), 0);
        let pre = self.log_preamble(vt, &mut cx, None);
        let (p, r4) = (&pre.p, &pre.r4);
        let keys: Vec<Bitmap> = p.0.keys().copied().collect();
        // A rotation needs a square of a bivector blade that is negative.
        let sp = self.table.product(p, p, Product::Geometric).get(0);
        let rotation =
            sp.0.iter()
                .any(|(m, c)| m.len() == 2 && m[0] == m[1] && *c < Rational::ZERO);
        let r4sq = self.table.product(r4, r4, Product::Geometric).get(0);
        let other_part = !pre.wpp.0.is_empty() || !r4.0.is_empty();
        // A grade-4 part that only squares positive belongs to two rotations (G(4,0)).
        let positive = !r4sq.is_zero()
            && r4sq
                .0
                .iter()
                .all(|(m, c)| m.len() == 2 && m[0] == m[1] && *c > Rational::ZERO);
        if !rotation || !other_part || positive {
            return None;
        }
        // Where the grade-4 part may square positive (two rotations, CGA's `Even`), the root
        // is taken here only when it does not: then the other part is not a rotation.
        let guard = if r4sq.is_zero() || negative_squares(&r4sq) {
            None
        } else {
            let u4 = grade_part(&SymMv::of_type(vt, 0), 4);
            Some(self.table.product(&u4, &u4, Product::Geometric).get(0))
        };
        let pre_stmts = pre.stmts.clone();
        let (body, halved) = if pre.null {
            // The rotation part split off as `log` does (from the preamble's `sp` and `wpp`),
            // then projected on the lines again.
            let (pr_stmt, pr) = project_on_lines(&mut cx, &s, p, &keys, quote!(sp), &pre.wpp, "pr");
            let (pl_stmt, pl) = self.lines_projection(&mut cx, &pr, &keys, "wr", "pl");
            let aa = cx.poly(&self.table.product(&pl, &pl, Product::Geometric).get(0));
            let plr4 = grade_part(&self.table.product(&pl, r4, Product::Geometric), 2);
            // log = (th / a) pl + r0 (p - pl) - <pl r4>_2, halved.
            let halved = build(&spec.types[lo], |x| {
                keys.iter().position(|b| *b == x).map(|i| {
                    let il = proc_macro2::Literal::usize_unsuffixed(i);
                    let pe = cx.at(p, x);
                    let mut t = quote!(kr * pl[#il] + 0.5 * r0 * (#pe - pl[#il]));
                    if plr4.0.contains_key(&x) {
                        let re = cx.at(&plr4, x);
                        t.extend(quote!(- 0.5 * (#re)));
                    }
                    t
                })
            });
            let body = quote! {
                #pr_stmt
                #pl_stmt
                let a = (-(#aa)).max(0.0).sqrt();
                // Half the half-angle in `[pi/2, pi]`; not finite for a pure translation times
                // -1 (no unique root).
                let kr = 0.5 * exp_log_atan2(a, r0) / a;
            };
            (body, halved)
        } else {
            let (head, tail, rot) = self.log_general(&mut cx, &pre, true);
            let rot = ident(rot);
            let halved = build(&spec.types[lo], |x| {
                keys.iter().position(|b| *b == x).map(|i| {
                    let i = proc_macro2::Literal::usize_unsuffixed(i);
                    quote!(0.5 * (kr * #rot[#i] + ko * uo[#i]))
                })
            });
            (quote!(#head #tail), halved)
        };
        let (vn, ln) = (ident(&vt.name), ident(&spec.types[lo].name));
        let method = ident(METHOD);
        let item = quote! {
            impl #vn {
                /// The root of a unit versor whose scalar part is negative (a rotation beyond
                /// a half turn): `exp(log(self) / 2)`, the logarithm read the long way round,
                /// its rotation part projected on the simple bivectors once more (see `sqrt`).
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn #method(self) -> #vn {
                    let r0: #s = #r0;
                    #pre_stmts
                    #body
                    <#ln as Exp<#vn>>::exp(#halved)
                }
            }
        };
        Some(TurnRoot { item, guard })
    }
}
