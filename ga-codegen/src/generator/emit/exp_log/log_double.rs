//! The double-rotation branch of the emitted logarithm (`impl Log` on spans with four or more
//! directions of one sign): two rotations in orthogonal planes, read from the sum and the
//! difference of their angles so that nearly equal angles (isoclinic rotations) lose nothing;
//! see [`crate::generator::emit::exp_log`] for the whole story.

use super::{build, grade_part, negative_squares, Ctx};
use crate::generator::emit::render::{float, ident};
use crate::generator::emit::{Gen, ScalarType};
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{Poly, Product, SymMv};
use crate::runtime::blade::Bitmap;
use crate::runtime::rational::Rational;
use proc_macro2::TokenStream;
use quote::quote;

impl Gen<'_> {
    /// The statements of the double-rotation branch, which `return`s the logarithm when the
    /// grade-4 part `r4` squares positive (`v = (c1 + s1 u1)(c2 + s2 u2)` with `u1 u1 = u2 u2 =
    /// -1`, `r4 = s1 s2 u1 u2`), or nothing when the fallback of the exact double half turn
    /// cannot be written in `lt`.
    ///
    /// With `sig = sqrt(<r4 r4>_0) = s1 s2` and `Q = -<P r4>_2 / sig = c1 s2 u1 + c2 s1 u2`:
    /// `P + Q = sin(S) (u1 + u2)` and `P - Q = sin(D) (u1 - u2)` for `S = t1 + t2`,
    /// `D = t1 - t2`, so `log = t1 u1 + t2 u2 = f(S) (P + Q)/2 + f(D) (P - Q)/2` with
    /// `f(x) = x / sin x`, smooth at `D = 0` (isoclinic: no division by the difference of the
    /// squares). `cos S = r0 - sig`, `cos D = r0 + sig`, and the sines are the norms
    /// `sin^2 S = -<(P + Q)^2>_0 / 2`, `sin^2 D = -<(P - Q)^2>_0 / 2` (not `-<P P>_0 ± 2 r0 sig`,
    /// which loses the precision of `r0` near the double half turn).
    ///
    /// The branch is not taken where `r4sq` is far below the squares of `r4`'s coefficients
    /// (under 1/16 of them) unless the squares of `P`'s commuting parts (`mr`, `mo`) are within a
    /// factor two (where the split by them would divide by their small difference): a grade-4
    /// part that is nearly null (a screw motion, perturbed) has a `sig` made of cancelling
    /// terms, and `1 / sig` multiplies their rounding (2e-10 in f64 on a case the property tests
    /// found), while the split by the squares is exact to the precision there. It is always
    /// taken where the angles sum to more than two thirds of a turn (`sig - r0 > 1/2`, `cos S <
    /// -1/2`), which a nearly null `r4` never does: towards the double half turn only this
    /// branch reads `v`, and a boost (in CGA, G(3,2)) makes `r4`'s coefficients large while
    /// `r4sq` stays near 1, so the test by the coefficients alone once sent turned double half
    /// turns to the split by the squares, whose logarithm was off by the size of `v`.
    pub(crate) fn log_double_rotation(
        &mut self,
        cx: &mut Ctx<'_>,
        lt: &TypeDef,
        p: &SymMv,
        r4: &SymMv,
        imaginary: bool,
    ) -> TokenStream {
        let s = self.s.clone();
        let keys: Vec<Bitmap> = p.0.keys().copied().collect();
        // A type whose grade-4 part never squares positive (CGA's similarities: a negative sum
        // of squares) holds no double rotation.
        let r4sq = self.table.product(r4, r4, Product::Geometric).get(0);
        if r4sq.is_zero() || negative_squares(&r4sq) {
            return TokenStream::new();
        }
        let r4sq = cx.poly(&r4sq);
        let pr4 = grade_part(&self.table.product(p, r4, Product::Geometric), 2);
        if pr4.0.keys().any(|b| !keys.contains(b)) {
            return TokenStream::new();
        }
        let Some(fallback) = self.double_half_turn(cx, lt, &keys, r4) else {
            return TokenStream::new();
        };
        // Q = -<P r4>_2 / sig, then P + Q and P - Q.
        let q_vals = keys.iter().map(|b| {
            let e = cx.at(&pr4, *b);
            quote!(-(#e) * isg)
        });
        let n = proc_macro2::Literal::usize_unsuffixed(keys.len());
        let q_stmt = quote!(let q: [#s; #n] = [#(#q_vals),*];);
        let q = cx.declare(ident("q"), keys.iter().copied());
        // P's part in the 4-space, -<Q J>_2 (J = r4 / sig): P itself in exact arithmetic,
        // without the rounding of `v` outside the 4-space, which `(P + Q) / sin S` would
        // multiply near the double half turn.
        let qr4 = grade_part(&self.table.product(&q, r4, Product::Geometric), 2);
        if qr4.0.keys().any(|b| !keys.contains(b)) {
            return TokenStream::new();
        }
        let pin_vals = keys.iter().map(|b| {
            let e = cx.at(&qr4, *b);
            quote!(-(#e) * isg)
        });
        let pin_stmt = quote!(let pin: [#s; #n] = [#(#pin_vals),*];);
        let idx: Vec<_> = (0..keys.len())
            .map(proc_macro2::Literal::usize_unsuffixed)
            .collect();
        let (pa_vals, pd_vals): (Vec<_>, Vec<_>) = idx
            .iter()
            .map(|i| (quote!(pin[#i] + q[#i]), quote!(pin[#i] - q[#i])))
            .unzip();
        let pa = cx.declare(ident("pa"), keys.iter().copied());
        let pd = cx.declare(ident("pd"), keys.iter().copied());
        let pa2 = cx.poly(&self.table.product(&pa, &pa, Product::Geometric).get(0));
        let pd2 = cx.poly(&self.table.product(&pd, &pd, Product::Geometric).get(0));
        let _ = (q, pd);
        let result = build(lt, |x| {
            keys.iter().position(|b| *b == x).map(|i| {
                let i = &idx[i];
                quote!(fs * pa[#i] + fd * pd[#i])
            })
        });
        // Below this `sig`, `1/sig` could overflow; the single-rotation path is exact there.
        let min_sq = float(match self.scalar {
            ScalarType::F64 => 1e-280,
            ScalarType::F32 => 1e-30,
        });
        // Within this `sin S` of the double half turn the squares of `P + Q` near underflow,
        // and the exact double half turn's logarithm (the fallback, off by at most this) is
        // taken. Above it the formula keeps its precision however small `sin S` is: `r0 >= 0`
        // puts `S` near a half turn only where `D` is near zero, so `P` is as small as
        // `P + Q`, and `P + Q = pin + Q` is made from the 4-space's part of `P` (rounding of
        // `v` outside it once reached the logarithm multiplied by `1 / sin S`, which took the
        // fallback up to `sin S = 1e-8` and an error of that size).
        let near = float(match self.scalar {
            ScalarType::F64 => 1e-150,
            ScalarType::F32 => 1e-18,
        });
        // Where the metric is indefinite, `P + Q` near the double half turn may be rounding
        // that is not a rotation (its square a small difference of its coefficients'): the
        // formula's normalisation by `sin S` then errs by about `eps |P + Q|_2 / sin^2 S`, the
        // fallback by `|P + Q|_2`; the fallback is taken where it errs less (about four
        // units of roundoff).
        let noise = float(match self.scalar {
            ScalarType::F64 => 1e-15,
            ScalarType::F32 => 5e-7,
        });
        // On spans with two directions of each sign, `S` or `D` may be imaginary (a complex
        // pair of squares: `cos D = r0 + sig > 1`; two boosts: both): `x / sinh x` of its
        // `sinh x`, and the branch is the only one that reads them.
        let (hyperbolic, f_s, f_d) = if imaginary {
            (
                quote!(|| r0 + r4sq.max(0.0).sqrt() > 1.0),
                quote!(exp_log_x_over_sin_or_sinh(-0.5 * (#pa2), r0 - sig)),
                quote!(exp_log_x_over_sin_or_sinh(-0.5 * (#pd2), r0 + sig)),
            )
        } else {
            (
                TokenStream::new(),
                quote!(exp_log_x_over_sin(exp_log_atan2(ss, r0 - sig), ss)),
                quote!(exp_log_x_over_sin(exp_log_atan2(sd, r0 + sig), sd)),
            )
        };
        quote! {
            let r4sq: #s = #r4sq;
            let r4n: #s = r4.iter().map(|x| x * x).sum();
            if r4sq > #min_sq
                && (r4sq >= 0.0625 * r4n
                    || (mr - mo).abs() <= 0.5 * mr.abs().max(mo.abs())
                    || r4sq.sqrt() - r0 > 0.5 #hyperbolic)
            {
                let sig = r4sq.sqrt();
                let isg = 1.0 / sig;
                #q_stmt
                #pin_stmt
                let pa: [#s; #n] = [#(#pa_vals),*];
                let pd: [#s; #n] = [#(#pd_vals),*];
                let ss = (-0.5 * (#pa2)).max(0.0).sqrt();
                let sd = (-0.5 * (#pd2)).max(0.0).sqrt();
                let pn: #s = pa.iter().map(|x| x * x).sum();
                if (ss < #near || ss * ss < #noise * pn.sqrt()) && r0 < sig {
                    #fallback
                }
                let fs = 0.5 * #f_s;
                let fd = 0.5 * #f_d;
                return #result;
            }
        }
    }

    /// `return` a logarithm of the double half turn `v = r4` (`P = 0`, `r0 = 0`: every
    /// `(pi/2)(u + v)` with `u v = r4` is one): `u` the unit 2-blade `<E r4>_2` of the basis
    /// bivector `E` whose square is the most negative, `v = -u r4`. `None` when `lt` cannot
    /// hold them.
    fn double_half_turn(
        &mut self,
        cx: &mut Ctx<'_>,
        lt: &TypeDef,
        keys: &[Bitmap],
        r4: &SymMv,
    ) -> Option<TokenStream> {
        let s = self.s.clone();
        let mut cands = Vec::new();
        for &e in keys {
            let mut em = SymMv::default();
            em.0.insert(e, Poly::constant(Rational::ONE));
            let c = grade_part(&self.table.product(&em, r4, Product::Geometric), 2);
            if c.0.keys().any(|b| !keys.contains(b)) {
                return None;
            }
            if c.0.is_empty() {
                continue;
            }
            let vals = keys.iter().map(|b| cx.at(&c, *b));
            cands.push(quote!([#(#vals),*]));
        }
        let (n, m) = (keys.len(), cands.len());
        if m == 0 {
            return None;
        }
        let u = cx.declare(ident("u"), keys.iter().copied());
        let uu = cx.poly(&self.table.product(&u, &u, Product::Geometric).get(0));
        let ur4 = grade_part(&self.table.product(&u, r4, Product::Geometric), 2);
        if ur4.0.keys().any(|b| !keys.contains(b)) {
            return None;
        }
        let result = build(lt, |x| {
            keys.iter().position(|b| *b == x).map(|i| {
                let i = proc_macro2::Literal::usize_unsuffixed(i);
                if ur4.0.contains_key(&x) {
                    let ve = cx.at(&ur4, x);
                    quote!(h * (u[#i] - (#ve)))
                } else {
                    quote!(h * u[#i])
                }
            })
        });
        let (n, m) = (
            proc_macro2::Literal::usize_unsuffixed(n),
            proc_macro2::Literal::usize_unsuffixed(m),
        );
        let half_pi = match self.scalar {
            ScalarType::F64 => quote!(::core::f64::consts::FRAC_PI_2),
            ScalarType::F32 => quote!(::core::f32::consts::FRAC_PI_2),
        };
        Some(quote! {
            let cands: [[#s; #n]; #m] = [#(#cands),*];
            // `-u u` of a candidate: the most rotation-like one (where the metric is
            // indefinite, a candidate large in its coefficients may be nearly null).
            let rot = |u: [#s; #n]| -> #s { -(#uu) };
            let mut u = cands[0];
            let mut best: #s = 0.0;
            for c in cands {
                let n2 = rot(c);
                if n2 > best {
                    best = n2;
                    u = c;
                }
            }
            let k = 1.0 / best.sqrt();
            for x in u.iter_mut() {
                *x *= k;
            }
            let h: #s = #half_pi;
            return #result;
        })
    }
}
