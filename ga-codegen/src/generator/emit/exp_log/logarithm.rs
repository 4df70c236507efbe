//! The emitted closed-form principal logarithm of an even versor (`impl Log`), by the invariant
//! decomposition of its bivector part; see [`crate::generator::emit::exp_log`] for the whole story.

use super::decompose::SpanKind;
use super::{build, grade_part, half, is_bivector, negative_squares, Ctx};
use crate::generator::emit::render::{doc, float, ident};
use crate::generator::emit::{Gen, ScalarType};
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{Poly, Product, SymMv};
use crate::runtime::blade::Bitmap;
use proc_macro2::TokenStream;
use quote::quote;

/// What every closed-form logarithm reads first: the bivector part `p` and grade-4 part `r4`
/// of `V` as locals, `<p p>_0`, `(p ^ p)/2` as the local `wp`, its square and `(W p)/2`.
pub(crate) struct Preamble {
    /// `let p = ..; let r4 = ..; let sp = ..; let wp = ..;`
    pub(crate) stmts: TokenStream,
    pub(crate) p: SymMv,
    pub(crate) r4: SymMv,
    /// `((p ^ p)/2)^2`, a scalar.
    pub(crate) qp: Poly,
    /// `(W p)/2`, `W = p ^ p`.
    pub(crate) wpp: SymMv,
    /// `<p p>_0` is a negative sum of squares and `W W = 0` identically: a rotation plus a null
    /// part (PGA and CGA motors).
    pub(crate) null: bool,
}

impl Gen<'_> {
    /// The first declared bivector type holding every bivector blade of `V`: the spec's order
    /// chooses, so a smaller bivector type declared later (CGA's `DualLine`, for products and
    /// squares of lines) does not change the type a `log` returns.
    pub(crate) fn log_type(&self, vt: &TypeDef) -> Option<usize> {
        let g2: Vec<Bitmap> = grade_part(&SymMv::of_type(vt, 0), 2).support();
        self.spec
            .types
            .iter()
            .position(|t| is_bivector(t) && g2.iter().all(|b| t.blades().any(|x| x == *b)))
    }

    /// The [`Preamble`] of `V` in `cx` (operand 0 is `V`); `sign` multiplies `p` and `r4`
    /// unless the parts are a rotation plus a null part (read as stored).
    pub(crate) fn log_preamble(
        &mut self,
        vt: &TypeDef,
        cx: &mut Ctx<'_>,
        sign: Option<&TokenStream>,
    ) -> Preamble {
        let s = self.s.clone();
        let v = SymMv::of_type(vt, 0);
        // Each local is one field up to sign, so these identities hold for the locals as they
        // do for the fields.
        let g2 = grade_part(&v, 2);
        let g2sq = self.table.product(&g2, &g2, Product::Geometric);
        let g4 = grade_part(&g2sq, 4);
        let null = negative_squares(&g2sq.get(0))
            && self
                .table
                .product(&g4, &g4, Product::Geometric)
                .get(0)
                .is_zero();
        let factor = if null { None } else { sign };
        let (p_stmt, p) = cx.local("p", &g2, factor);
        let (r4_stmt, r4) = cx.local("r4", &grade_part(&v, 4), factor);
        let pp = self.table.product(&p, &p, Product::Geometric);
        let sp = cx.poly(&pp.get(0));
        // `wp` holds (P ^ P)/2, so `wpp` is ((P ^ P) P)/2.
        let (wp_stmt, wp) = cx.local("wp", &half(&grade_part(&pp, 4)), None);
        let qp = self.table.product(&wp, &wp, Product::Geometric).get(0);
        let wpp = grade_part(&self.table.product(&wp, &p, Product::Geometric), 2);
        Preamble {
            stmts: quote!(#p_stmt #r4_stmt let sp: #s = #sp; #wp_stmt),
            p,
            r4,
            qp,
            wpp,
            null,
        }
    }

    /// The general split of a logarithm (not the null form), after [`Gen::log_preamble`]:
    /// `head` computes the squares `mr` (rotation) and `mo` of the commuting parts, `tail` the
    /// rotation part (the local named in the result: `pr`, or in the `long` form `pl`, `pr`
    /// projected on the simple bivectors once more), `kr`, `uo` and `ko`, so that the
    /// logarithm is `kr rot + ko uo`. The `long` form reads `V` as stored (no sign taken out:
    /// the rotation's half-angle `atan2(|pr|, <V>_0)` lies in `[pi/2, pi]` for a negative
    /// scalar part) and splits whatever `mr - mo` is not zero.
    pub(crate) fn log_general(
        &mut self,
        cx: &mut Ctx<'_>,
        pre: &Preamble,
        long: bool,
    ) -> (TokenStream, TokenStream, &'static str) {
        let s = self.s.clone();
        let (p, r4, wpp) = (&pre.p, &pre.r4, &pre.wpp);
        let head = if pre.qp.is_zero() {
            quote!(let (mr, mo) = (sp.min(0.0), sp.max(0.0));)
        } else {
            let qe = cx.poly(&pre.qp);
            quote!(let (mr, mo) = exp_log_squares(sp, 4.0 * (#qe));)
        };
        // p_r = (mr p - (W p)/2) / (mr - mo): the part with the smaller square.
        let pr_vals = p.0.keys().map(|b| {
            let pe = cx.at(p, *b);
            if wpp.0.contains_key(b) {
                let we = cx.at(wpp, *b);
                quote!((mr * #pe - (#we)) * k)
            } else {
                quote!(mr * #pe * k)
            }
        });
        let keys: Vec<Bitmap> = p.0.keys().copied().collect();
        let n = proc_macro2::Literal::usize_unsuffixed(keys.len());
        let tiny = if long { quote!(0.0) } else { self.tiny() };
        let pr_stmt = quote! {
            let d = mr - mo;
            let pr: [#s; #n] = if d.abs() > #tiny { let k = 1.0 / d; [#(#pr_vals),*] } else { [0.0; #n] };
        };
        let mut rot = cx.declare(ident("pr"), keys.iter().copied());
        let mut rot_stmt = TokenStream::new();
        let mut rot_name = "pr";
        if long {
            let (stmt, pl) = self.lines_projection(cx, &rot, &keys, "wr", "pl");
            rot_stmt = stmt;
            rot = pl;
            rot_name = "pl";
        }
        let rot_id = ident(rot_name);
        let prr4 = grade_part(&self.table.product(&rot, r4, Product::Geometric), 2);
        let uo_vals = keys.iter().enumerate().map(|(i, b)| {
            let i = proc_macro2::Literal::usize_unsuffixed(i);
            let pe = cx.at(p, *b);
            if prr4.0.contains_key(b) {
                let re = cx.at(&prr4, *b);
                quote!((r0 * (#pe - #rot_id[#i]) - (#re)) * ic)
            } else {
                quote!(r0 * (#pe - #rot_id[#i]) * ic)
            }
        });
        let uo_stmt = quote!(let ic = 1.0 / co; let uo: [#s; #n] = [#(#uo_vals),*];);
        let uo_sym = cx.declare(ident("uo"), keys.iter().copied());
        let sig = self
            .table
            .product(&uo_sym, &uo_sym, Product::Geometric)
            .get(0);
        let small = float(match self.scalar {
            ScalarType::F64 => 1e-5,
            ScalarType::F32 => 1e-3,
        });
        let ko = if sig.is_zero() {
            quote!(let ko: #s = 1.0;)
        } else {
            let se = cx.poly(&sig);
            quote! {
                let sig: #s = #se;
                let ko: #s = if sig.abs() < #small {
                    1.0 - sig / 6.0 + 0.075 * sig * sig
                } else if sig > 0.0 {
                    let x = sig.sqrt(); x.asinh() / x
                } else {
                    let x = (-sig).sqrt(); x.min(1.0).asin() / x
                };
            }
        };
        // The long form has no rotation to read for `a = 0` (a negative versor without one has
        // no unique root): `kr` is not finite there.
        let kr = if long {
            quote!(let kr = th / a;)
        } else {
            quote!(let kr = if a > 0.0 { th / a } else { 1.0 / r0 };)
        };
        let tail = quote! {
            #pr_stmt
            #rot_stmt
            let a = (-mr).max(0.0).sqrt();
            let th = exp_log_atan2(a, r0);
            let co = (r0 * r0 + a * a).sqrt();
            #kr
            #uo_stmt
            #ko
        };
        (head, tail, rot_name)
    }

    /// `x - (W x)/(2 <x x>_0)`, `W = x ^ x` (the first-order projection of a bivector on the
    /// simple ones, exact for `W W = 0`), as the local `out` with `(x ^ x)/2` in `w_name`.
    pub(crate) fn lines_projection(
        &mut self,
        cx: &mut Ctx<'_>,
        x: &SymMv,
        keys: &[Bitmap],
        w_name: &str,
        out: &str,
    ) -> (TokenStream, SymMv) {
        let s = self.s.clone();
        let xx = self.table.product(x, x, Product::Geometric);
        let sx = cx.poly(&xx.get(0));
        let (w_stmt, w) = cx.local(w_name, &half(&grade_part(&xx, 4)), None);
        let wx = grade_part(&self.table.product(&w, x, Product::Geometric), 2);
        let (stmt, sym) = project_on_lines(cx, &s, x, keys, quote!(#sx), &wx, out);
        (quote!(#w_stmt #stmt), sym)
    }

    /// `impl Log for V`, into the smallest type holding `V`'s bivector blades.
    pub(crate) fn log_impl(&mut self, vt: &TypeDef, kind: SpanKind) -> TokenStream {
        let s = self.s.clone();
        let Some(lo) = self.log_type(vt) else {
            return TokenStream::new();
        };
        let spec = self.spec;
        let lt = &spec.types[lo];
        let mut cx = Ctx::new(vt, s.clone());
        let sg = quote!(sg);
        let r0 = cx.at(&SymMv::of_type(vt, 0), 0);
        // Rotation plus null part: the hemisphere sign goes into one factor (see `log_null`), so
        // the parts are read as stored.
        let pre = self.log_preamble(vt, &mut cx, Some(&sg));
        if pre.null {
            return self.log_null(vt, lt, cx, &pre);
        }
        let (head, tail, rot) = self.log_general(&mut cx, &pre, false);
        let rot = ident(rot);
        let keys: Vec<Bitmap> = pre.p.0.keys().copied().collect();
        let result = build(lt, |x| {
            keys.iter().position(|b| *b == x).map(|i| {
                let i = proc_macro2::Literal::usize_unsuffixed(i);
                quote!(kr * #rot[#i] + ko * uo[#i])
            })
        });
        // Two rotations: by the sum and difference of their angles (`log_double.rs`).
        // Two rotations, or (two directions of each sign) a complex pair of squares or two
        // boosts: by the sum and difference of their angles, real or imaginary.
        let double = if (kind.double_rotation() || kind.complex_squares()) && !pre.r4.0.is_empty() {
            self.log_double_rotation(&mut cx, lt, &pre.p, &pre.r4, kind.complex_squares())
        } else {
            TokenStream::new()
        };
        let (vn, ln) = (ident(&vt.name), ident(&lt.name));
        let pre_stmts = pre.stmts;
        let d = doc(&format!(
            "The principal logarithm of a unit `{}` (normalise first otherwise), in closed \
             form: `exp(log(v)) = ±v`, the sign that makes the scalar part non-negative (the \
             shortest motion; `log(-v) = log(v)`). The bivector part `P` is split into its \
             commuting parts `P = pr + po` by its invariants (`pr` the one with the smaller, \
             non-positive square: the rotation). The rotation's half-angle is \
             `atan2(|pr|, <v>_0)`, in `[0, pi/2]`, exact at zero and at a half turn (no division \
             by the scalar part or by a sine); the other part, `uo = (<v>_0 po - <pr <v>_4>_2) / \
             c` with `c = sqrt(<v>_0^2 + |pr|^2)`, is a translation (kept as it is), a boost \
             (scaled by `asinh(|uo|)/|uo|`) or a second rotation (`asin(|uo|)/|uo|`). A pure \
             translation (`pr = 0`) returns the bivector part itself. Two rotations (`<v>_4` \
             squares positive, not by cancellation, or their squares are within a factor two, \
             or their angles sum past two thirds of a turn) \
             are read from the sum `S` and difference `D` of their angles instead: \
             `log = f(S) (P + Q)/2 + f(D) (P - Q)/2`, `f(x) = x / sin x`, \
             `Q = -<P <v>_4>_2 / |<v>_4|`, exact for equal angles (isoclinic) and near them; the \
             double half turn (`v` a unit 4-blade, whose logarithm is not unique) returns one of \
             its logarithms.{}",
            vt.name,
            if kind.complex_squares() {
                " On this span (two directions of each sign) the two squares may also be a \
                 complex pair or two boosts: then `S` or `D` is imaginary (`cos D = <v>_0 + \
                 |<v>_4| > 1`, `<(P - Q)^2>_0 > 0`) and its factor is `x / sinh x` with \
                 `x = asinh(sqrt(<(P - Q)^2>_0 / 2))`, so the same formula reads them; a rotation \
                 with a boost (`<v>_4` squaring negative) takes the split above."
            } else {
                ""
            }
        ));
        quote! {
            impl Log for #vn {
                type Output = #ln;
                #d
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens, clippy::needless_return)]
                fn log(self) -> #ln {
                    let sg: #s = if #r0 < 0.0 { -1.0 } else { 1.0 };
                    let r0: #s = sg * (#r0);
                    #pre_stmts
                    #head
                    #double
                    #tail
                    #result
                }
            }
        }
    }

    /// Below this, a square of the bivector part of a unit versor (`-sin^2` of a half-angle)
    /// is treated as zero when splitting it: dividing by it would overflow, and taking the
    /// whole of it as one part errs by about a third of it, under the precision.
    fn tiny(&self) -> TokenStream {
        float(match self.scalar {
            ScalarType::F64 => 1e-16,
            ScalarType::F32 => 1e-7,
        })
    }

    /// `impl Log for V` when `<P P>_0` is a negative sum of squares and `W W = 0` identically:
    /// `P` is a rotation (or nothing) plus a null part (PGA and CGA motors), so the squares are
    /// `<P P>_0` and `0` with nothing to solve, and the null part needs no scaling.
    fn log_null(
        &mut self,
        vt: &TypeDef,
        lt: &TypeDef,
        mut cx: Ctx<'_>,
        pre: &Preamble,
    ) -> TokenStream {
        let (p, r4, wpp) = (&pre.p, &pre.r4, &pre.wpp);
        let s = self.s.clone();
        let r0 = cx.at(&SymMv::of_type(vt, 0), 0);
        let keys: Vec<Bitmap> = p.0.keys().copied().collect();
        // pr = p - (W p) / (2 <P P>_0): the rotation part.
        let (pr_stmt, pr_sym) = minus_k_times(&mut cx, &s, p, &keys, wpp, "pr");
        let prr4 = grade_part(&self.table.product(&pr_sym, r4, Product::Geometric), 2);
        let result = build(lt, |x| {
            keys.iter().position(|b| *b == x).map(|i| {
                let il = proc_macro2::Literal::usize_unsuffixed(i);
                let mut t = quote!(kr * pr[#il]);
                if wpp.0.contains_key(&x) {
                    let we = cx.at(wpp, x);
                    t.extend(quote!(+ rk * (#we)));
                }
                if prr4.0.contains_key(&x) {
                    let re = cx.at(&prr4, x);
                    t.extend(quote!(- (#re)));
                }
                t
            })
        });
        let pre_stmts = &pre.stmts;
        let tiny = self.tiny();
        let (vn, ln) = (ident(&vt.name), ident(&lt.name));
        let d = doc(&format!(
            "The principal logarithm of a unit `{}` (normalise first otherwise), in closed form: `exp(log(v)) = ±v`, the sign that makes the scalar part non-negative (the shortest motion; `log(-v) = log(v)`: `v` and `-v` give the same translation term and rotation parts of opposite sign, so the sign of `<v>_0` is a factor of the rotation's). Here the bivector part `P` is a rotation plus a null part (a translation): `<P P>_0 = -sin^2(t) <= 0` and `(P ^ P)^2 = 0`. The rotation is `pr = P - (P ^ P) P / (2 <P P>_0)`, its half-angle `t = atan2(sqrt(-<P P>_0), |<v>_0|)` in `[0, pi/2]` (exact at zero and at a half turn: no division by the scalar part or by a sine), and the translation `<v>_0 (P - pr) - <pr <v>_4>_2`; `log = (t / sin t) pr + translation`. A pure translation (`<P P>_0 = 0`) returns `P` itself; below `sin^2 t = 1e-16` (`1e-7` in f32) the split is skipped, as its effect is under the precision.",
            vt.name
        ));
        quote! {
            impl Log for #vn {
                type Output = #ln;
                #d
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn log(self) -> #ln {
                    let r0: #s = #r0;
                    #pre_stmts
                    let k: #s = if sp < -#tiny { 1.0 / sp } else { 0.0 };
                    let rk = r0 * k;
                    #pr_stmt
                    let a = (-sp).max(0.0).sqrt();
                    let r0a = r0.abs();
                    let kr = (if a > 0.0 { exp_log_atan2(a, r0a) / a } else { 1.0 / r0a }).copysign(r0);
                    #result
                }
            }
        }
    }
}

/// [`Gen::lines_projection`] with `<x x>_0` (an expression) and `(W x)/2` already at hand (the
/// preamble's `sp` and `wpp` for the bivector part itself).
pub(crate) fn project_on_lines(
    cx: &mut Ctx<'_>,
    s: &TokenStream,
    x: &SymMv,
    keys: &[Bitmap],
    sx: TokenStream,
    wx: &SymMv,
    out: &str,
) -> (TokenStream, SymMv) {
    let (stmt, sym) = minus_k_times(cx, s, x, keys, wx, out);
    let stmt = quote! {
        let k: #s = { let sx: #s = #sx; if sx < 0.0 { 1.0 / sx } else { 0.0 } };
        #stmt
    };
    (stmt, sym)
}

/// `let out: [s; n] = [x_b - (W x)_b * k, ...]` over `keys` (`k` declared by the caller), and
/// `out` declared in `cx`: the rotation part's projection shared by `log` and
/// [`project_on_lines`].
fn minus_k_times(
    cx: &mut Ctx<'_>,
    s: &TokenStream,
    x: &SymMv,
    keys: &[Bitmap],
    wx: &SymMv,
    out: &str,
) -> (TokenStream, SymMv) {
    let vals = keys.iter().map(|b| {
        let xe = cx.at(x, *b);
        if wx.0.contains_key(b) {
            let we = cx.at(wx, *b);
            quote!(#xe - (#we) * k)
        } else {
            xe
        }
    });
    let n = proc_macro2::Literal::usize_unsuffixed(keys.len());
    let out_id = ident(out);
    let stmt = quote!(let #out_id: [#s; #n] = [#(#vals),*];);
    (stmt, cx.declare(out_id, keys.iter().copied()))
}
