//! The emitted square root of a screw beyond a half turn: for even versors whose bivector part
//! is a rotation plus a null part (PGA and CGA motors), `sqrt` of a versor with a negative
//! scalar part is `exp(log(v) / 2)` with the logarithm read the long way round.
//!
//! Near a full turn `normalize(1 + v)` fails for these versors even with the scalar part taken
//! without cancelling: `1 + v` is then nearly all translation, a Study number `2 (r0 + r4)`
//! with a tiny scalar part divides it, and terms of size `|translation| / d` cancel at a
//! distance `d` from the full turn (an f32 motor that turns `2 pi - 1e-9` and shifts along its
//! axis got a root whose square was 58 off). The axis of the root is only determined to
//! `eps |translation| / d` by `v`'s coefficients too, but an axis moved by that much changes
//! a motion of nearly a full turn by `eps |translation|` alone; what matters is that the root
//! is an exact screw about some line. So the rotation part `pr` of the bivector part is split
//! off as the logarithm does, projected on the lines once more (the split leaves a moment
//! along the axis of size `eps |translation| / d`, which the long logarithm would scale by
//! `pi / d` into a shift), and `exp` of half the long logarithm, a closed form with no
//! cancellation at a quarter turn, is the root.

use super::exp_log::{build, grade_part, half, is_bivector, negative_squares, Ctx};
use super::render::ident;
use super::Gen;
use crate::blade::Bitmap;
use crate::spec::TypeDef;
use crate::symbolic::{Product, SymMv};
use proc_macro2::TokenStream;
use quote::quote;

/// The name of the emitted inherent method (private to the generated module).
pub(super) const METHOD: &str = "root_beyond_a_half_turn";

impl Gen<'_> {
    /// `impl V { fn root_beyond_a_half_turn(self) -> V }` for a versor type whose bivector
    /// part squares to a negative sum of squares plus a grade-4 part `W` with `W W = 0`
    /// identically and `W` not zero (a rotation plus a translation along its axis), when the
    /// smallest bivector type holding its bivector blades has an `exp` into it; `None`
    /// otherwise (rotors, whose root `normalize(1 + v)` already keeps to rounding, and every
    /// other kind of versor).
    pub(super) fn turn_root(&mut self, vt: &TypeDef) -> Option<TokenStream> {
        let spec = self.spec;
        let v = SymMv::of_type(vt, 0);
        let g2 = grade_part(&v, 2);
        let g2sq = self.table.product(&g2, &g2, Product::Geometric);
        let g4 = grade_part(&g2sq, 4);
        let screw = !g2.0.is_empty()
            && !g2sq.get(0).is_zero()
            && negative_squares(&g2sq.get(0))
            && !g4.0.is_empty()
            && self
                .table
                .product(&g4, &g4, Product::Geometric)
                .get(0)
                .is_zero();
        if !screw {
            return None;
        }
        let keys: Vec<Bitmap> = g2.support();
        let lo = self.by_size.iter().copied().find(|&i| {
            let t = &spec.types[i];
            is_bivector(t) && keys.iter().all(|b| t.blades().any(|x| x == *b))
        })?;
        let vi = spec.types.iter().position(|t| t.name == vt.name)?;
        if !self.exp_pairs().contains(&(lo, vi)) {
            return None;
        }
        let lt = &spec.types[lo];
        let s = self.s.clone();
        let mut cx = Ctx::new(vt, s.clone());
        let r0 = cx.at(&v, 0);
        let (p_stmt, p) = cx.local("p", &g2, None);
        let (r4_stmt, r4) = cx.local("r4", &grade_part(&v, 4), None);
        let n = proc_macro2::Literal::usize_unsuffixed(keys.len());
        // x - (W x)/(2 <x x>_0), W = x ^ x: the rotation part of a bivector `x` of this kind
        // (the projection on the lines), given `x`'s symbolic value and the name of its local
        // holding `(x ^ x)/2`.
        let mut rotation_part = |cx: &mut Ctx<'_>, x: &SymMv, w_name: &str, out: &str| {
            let xx = self.table.product(x, x, Product::Geometric);
            let sx = cx.poly(&xx.get(0));
            let (w_stmt, w) = cx.local(w_name, &half(&grade_part(&xx, 4)), None);
            let wx = grade_part(&self.table.product(&w, x, Product::Geometric), 2);
            let vals = keys.iter().map(|b| {
                let xe = cx.at(x, *b);
                if wx.0.contains_key(b) {
                    let we = cx.at(&wx, *b);
                    quote!(#xe - (#we) * k)
                } else {
                    xe
                }
            });
            let out_id = ident(out);
            let stmt = quote! {
                #w_stmt
                let k: #s = { let sx: #s = #sx; if sx < 0.0 { 1.0 / sx } else { 0.0 } };
                let #out_id: [#s; #n] = [#(#vals),*];
            };
            (stmt, cx.declare(out_id, keys.iter().copied()))
        };
        let (pr_stmt, pr) = rotation_part(&mut cx, &p, "wp", "pr");
        let (pl_stmt, pl) = rotation_part(&mut cx, &pr, "wr", "pl");
        let aa = cx.poly(&self.table.product(&pl, &pl, Product::Geometric).get(0));
        let plr4 = grade_part(&self.table.product(&pl, &r4, Product::Geometric), 2);
        // log = (th / a) pl + r0 (p - pl) - <pl r4>_2, halved.
        let result = build(lt, |x| {
            keys.iter().position(|b| *b == x).map(|i| {
                let il = proc_macro2::Literal::usize_unsuffixed(i);
                let pe = cx.at(&p, x);
                let mut t = quote!(kr * pl[#il] + 0.5 * r0 * (#pe - pl[#il]));
                if plr4.0.contains_key(&x) {
                    let re = cx.at(&plr4, x);
                    t.extend(quote!(- 0.5 * (#re)));
                }
                t
            })
        });
        let (vn, ln) = (ident(&vt.name), ident(&lt.name));
        let method = ident(METHOD);
        Some(quote! {
            impl #vn {
                /// The root of a unit versor whose scalar part is negative (a rotation beyond
                /// a half turn): `exp(log(self) / 2)`, the logarithm read the long way round
                /// from its rotation part projected on the lines twice (see `sqrt`).
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn #method(self) -> #vn {
                    let r0: #s = #r0;
                    #p_stmt
                    #r4_stmt
                    #pr_stmt
                    #pl_stmt
                    let a = (-(#aa)).max(0.0).sqrt();
                    // The half-angle in `[pi/2, pi]`, halved; not finite for a pure
                    // translation times -1 (no unique root).
                    let kr = 0.5 * a.atan2(r0) / a;
                    <#ln as Exp<#vn>>::exp(#result)
                }
            }
        })
    }
}
