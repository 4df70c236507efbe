//! Closed-form exponential, logarithm, square root and normalisation of even versors, by the
//! invariant decomposition ([`decompose`]).
//!
//! For every declared type whose blades are all bivectors (`Bivector`, PGA's `Line`), and every
//! even versor type (`versor = true`, even grades only, a stored scalar: rotors, motors,
//! Lorentz rotors, CGA similarities), the emitter writes:
//!
//! - `impl Exp<V> for B`: `exp` of the bivector into `V`, once for the smallest type that holds
//!   the full exponential and once for each even versor type whose bivector blades `B` holds
//!   (`exp` of the part of `B` on those blades: `let m: Motor = b.exp();`);
//! - `impl Log for V`: the principal logarithm of a unit versor, into the smallest type that holds
//!   its bivector blades;
//! - `impl EvenVersor for V`: `normalize` (divide by the square root of `V ~V`, a scalar plus a
//!   grade-4 part, in closed form) and `sqrt` (`normalize(1 + V)`, or per half of the grade-4
//!   part's `J` where that cancels: `normalize.rs`; for a rotation with a translation, boost or
//!   dilation beyond a half turn `exp(log / 2)` the long way round: `turn_root.rs`).
//!
//! Every intermediate multivector (`W = <B B>_4`, `W B`, ...) is expanded symbolically, so
//! only the blades that can be non-zero are computed; a grade-4 part that squares to zero
//! identically (PGA's `e0123`, CGA's `e123i`) selects the one-rotation-plus-null form with no
//! quadratic to solve. On a span with two directions of each sign the two squares may be a
//! complex pair: `exp` computes its coefficients in complex arithmetic, `log` reads an imaginary
//! angle with `x / sinh x`, `sqrt` takes split-complex halves. A span the decomposition is not
//! closed form on (more than five basis vectors) gets none of these ([`refusals`] lists them).

pub(crate) mod decompose;
mod log_double;
mod logarithm;
mod normalize;
mod turn_root;

use super::render::{doc, ident};
use super::{Gen, OutType};
use crate::generator::spec::{Spec, TypeDef};
use crate::generator::symbolic::{Poly, Product, SymMv, Var};
use crate::runtime::blade::{grade, Bitmap};
use crate::runtime::rational::Rational;
use decompose::{classify, complex_helpers, helpers, span, Refusal};
use proc_macro2::{Ident, TokenStream};
use quote::quote;

/// The symbolic value of `t`'s fields on the canonical blades in `keep`.
pub(super) fn of_type_on(t: &TypeDef, keep: impl Fn(Bitmap) -> bool) -> SymMv {
    let mut m = SymMv::of_type(t, 0);
    m.0.retain(|b, _| keep(*b));
    m
}

/// The grade-`k` part.
pub(super) fn grade_part(m: &SymMv, k: u32) -> SymMv {
    SymMv(
        m.0.iter()
            .filter(|(b, _)| grade(**b) == k)
            .map(|(b, p)| (*b, p.clone()))
            .collect(),
    )
}

/// `m / 2`: the grade-4 locals hold `W/2`, which saves the factors 2 of `B ^ B` and the
/// halves of `W/2` and `(W B)/2`.
pub(super) fn half(m: &SymMv) -> SymMv {
    SymMv::default().add_scaled(m, Rational::new(1, 2))
}

/// Whether `p` is a sum of squares with negative coefficients (so never positive).
pub(super) fn negative_squares(p: &Poly) -> bool {
    p.0.iter()
        .all(|(m, c)| m.len() == 2 && m[0] == m[1] && *c < Rational::ZERO)
}

/// Whether a type is a bivector type (fields only, every blade of grade 2).
pub(super) fn is_bivector(t: &TypeDef) -> bool {
    t.constants.is_empty() && !t.fields.is_empty() && t.fields.iter().all(|f| grade(f.bitmap) == 2)
}

/// Whether a type is an even versor with a stored scalar and some bivector blade.
fn is_even_versor(t: &TypeDef) -> bool {
    t.versor
        && t.constants.is_empty()
        && t.fields.iter().all(|f| grade(f.bitmap).is_multiple_of(2))
        && t.fields.iter().any(|f| f.bitmap == 0 && f.sign == 1)
        && t.fields.iter().any(|f| grade(f.bitmap) == 2)
}

/// The types of a spec that get no closed forms, and why (their span is too large).
/// `ga-codegen --exp-log` refuses a spec for which this is not empty.
pub fn refusals(spec: &Spec) -> Vec<(String, Refusal)> {
    spec.types
        .iter()
        .filter(|t| is_bivector(t) || is_even_versor(t))
        .filter_map(|t| {
            classify(&spec.metric, span(t.blades()))
                .err()
                .map(|r| (t.name.clone(), r))
        })
        .collect()
}

/// Renders polynomials whose variables are `self`'s fields (operand 0) or elements of local
/// arrays (operands from 3 on).
pub(super) struct Ctx<'a> {
    ty: &'a TypeDef,
    pub(super) locals: Vec<Ident>,
    s: TokenStream,
}

impl<'a> Ctx<'a> {
    pub(super) fn new(ty: &'a TypeDef, s: TokenStream) -> Ctx<'a> {
        Ctx {
            ty,
            locals: Vec::new(),
            s,
        }
    }

    pub(super) fn var(&self, v: Var) -> TokenStream {
        if v.operand == 0 {
            let f = ident(&self.ty.fields[v.field as usize].name);
            quote!(self.#f)
        } else {
            let name = &self.locals[v.operand as usize - 3];
            let i = proc_macro2::Literal::usize_unsuffixed(v.field as usize);
            quote!(#name[#i])
        }
    }

    /// `c1 * m1 + c2 * m2 - ...`, or `0.0` ([`super::render::poly_tokens`] over this
    /// context's fields and locals).
    pub(super) fn poly(&self, p: &Poly) -> TokenStream {
        super::render::poly_tokens(p, |m| {
            let mut vars = TokenStream::new();
            for (k, v) in m.iter().enumerate() {
                if k > 0 {
                    vars.extend(quote!(*));
                }
                vars.extend(self.var(*v));
            }
            vars
        })
    }

    /// The coefficient of canonical blade `b` of `m` as an expression.
    pub(super) fn at(&self, m: &SymMv, b: Bitmap) -> TokenStream {
        self.poly(&m.get(b))
    }

    /// `let name = [..];` holding `factor * m` on its support, and the symbolic local that
    /// stands for it (empty, with no statement, when `m` is zero).
    pub(super) fn local(
        &mut self,
        name: &str,
        m: &SymMv,
        factor: Option<&TokenStream>,
    ) -> (TokenStream, SymMv) {
        let (vals, sym) = self.local_values(name, m);
        let vals: Vec<TokenStream> = match factor {
            Some(f) => vals.into_iter().map(|e| quote!(#f * (#e))).collect(),
            None => vals,
        };
        (array_let(name, &vals, &self.s), sym)
    }

    /// The elements of a local array `name` holding `m` on its support (rendered, for any
    /// language's statement), and the symbolic local that stands for it; nothing when `m` is
    /// zero.
    pub(super) fn local_values(&mut self, name: &str, m: &SymMv) -> (Vec<TokenStream>, SymMv) {
        if m.0.is_empty() {
            return (Vec::new(), SymMv::default());
        }
        let vals = m.0.values().map(|p| self.poly(p)).collect();
        let sym = self.declare(ident(name), m.0.keys().copied());
        (vals, sym)
    }

    /// Name the next local array `id` (its statement is the caller's) and return the symbolic
    /// multivector standing for it: element `i` holds the coefficient of the `i`-th blade of
    /// `blades`.
    pub(super) fn declare(&mut self, id: Ident, blades: impl Iterator<Item = Bitmap>) -> SymMv {
        let operand = 3 + self.locals.len() as u8;
        self.locals.push(id);
        SymMv(
            blades
                .enumerate()
                .map(|(i, b)| {
                    let var = Var {
                        operand,
                        field: i as u16,
                    };
                    (b, Poly::var(var, Rational::ONE))
                })
                .collect(),
        )
    }
}

/// `let name: [s; n] = [vals];`, or nothing for no values.
pub(super) fn array_let(name: &str, vals: &[TokenStream], s: &TokenStream) -> TokenStream {
    if vals.is_empty() {
        return TokenStream::new();
    }
    let id = ident(name);
    let n = proc_macro2::Literal::usize_unsuffixed(vals.len());
    quote!(let #id: [#s; #n] = [#(#vals),*];)
}

/// `terms` summed, or `0.0`.
pub(super) fn sum(terms: Vec<TokenStream>) -> TokenStream {
    if terms.is_empty() {
        quote!(0.0)
    } else {
        quote!(#(#terms)+*)
    }
}

/// The value of a type's fields from expressions on canonical blades (`None`: zero).
pub(super) fn build(t: &TypeDef, value: impl Fn(Bitmap) -> Option<TokenStream>) -> TokenStream {
    let name = ident(&t.name);
    let fields = t.fields.iter().map(|f| {
        let id = ident(&f.name);
        match value(f.bitmap) {
            Some(v) if f.sign < 0 => quote!(#id: -(#v)),
            Some(v) => quote!(#id: #v),
            None => quote!(#id: 0.0),
        }
    });
    quote!(#name { #(#fields),* })
}

impl Gen<'_> {
    /// The exp, log, sqrt and normalisation impls of every eligible type, and (when any is
    /// emitted) the three traits and the shared helpers.
    /// Every (bivector type, versor type) pair that gets an `exp`.
    pub(super) fn exp_pairs(&mut self) -> Vec<(usize, usize)> {
        let spec = self.spec;
        let mut pairs: Vec<(usize, usize)> = Vec::new();
        for (bi, bt) in spec.types.iter().enumerate() {
            if !is_bivector(bt) || classify(&spec.metric, span(bt.blades())).is_err() {
                continue;
            }
            // The full exponential, into the smallest type that holds it.
            if let Some(vi) = self.exp_target(bt, &|_| true) {
                pairs.push((bi, vi));
            }
            // The exponential of the part on each even versor type's bivector blades.
            for (vi, vt) in spec.types.iter().enumerate() {
                if !is_even_versor(vt) || pairs.contains(&(bi, vi)) {
                    continue;
                }
                let g2: Vec<Bitmap> = vt.blades().filter(|b| grade(*b) == 2).collect();
                if !g2.iter().all(|b| bt.blades().any(|x| x == *b)) {
                    continue;
                }
                let keep = |b: Bitmap| g2.contains(&b);
                if self.exp_fits(bt, &keep, vt) {
                    pairs.push((bi, vi));
                }
            }
        }
        pairs
    }

    /// The blades of `B` that the `exp` of a pair of [`Gen::exp_pairs`] reads: all of them
    /// (`true`) for the smallest type holding the full exponential, else `V`'s bivector blades.
    pub(super) fn exp_keep(
        &mut self,
        bi: usize,
        vi: usize,
    ) -> (bool, impl Fn(Bitmap) -> bool + use<>) {
        let spec = self.spec;
        let g2: Vec<Bitmap> = spec.types[vi].blades().filter(|b| grade(*b) == 2).collect();
        let all = self.exp_target(&spec.types[bi], &|_| true) == Some(vi);
        (all, move |b: Bitmap| all || g2.contains(&b))
    }

    pub(super) fn exp_log(&mut self) {
        let spec = self.spec;
        let mut items = TokenStream::new();
        let pairs = self.exp_pairs();
        for &(bi, vi) in &pairs {
            let vt = &spec.types[vi];
            let (all, keep) = self.exp_keep(bi, vi);
            let part = if all {
                ""
            } else {
                " (its part on the versor's blades)"
            };
            self.closed_forms.push(format!(
                "{:<12} exp  -> {}{part}",
                spec.types[bi].name, vt.name
            ));
            items.extend(self.exp_impl(&spec.types[bi], vt, &keep));
        }
        let mut complex_log = false;
        for vt in spec.types.iter().filter(|t| is_even_versor(t)) {
            let Ok(kind) = classify(&spec.metric, span(vt.blades())) else {
                continue;
            };
            let log = self.log_impl(vt, kind);
            if !log.is_empty() {
                self.closed_forms.push(format!("{:<12} log", vt.name));
                complex_log |= kind.complex_squares();
            }
            items.extend(log);
            let root = self.root_impl(vt, &pairs);
            if !root.is_empty() {
                self.closed_forms
                    .push(format!("{:<12} sqrt, normalize", vt.name));
            }
            items.extend(root);
        }
        if items.is_empty() {
            return;
        }
        self.out.extend(quote! {
            /// The closed-form exponential of a bivector into a versor type (see each impl for
            /// the branch it takes). A bivector type may have several: name the result type,
            /// `let m: Motor = b.exp();`.
            pub trait Exp<V> {
                /// `exp(self)`, in closed form.
                fn exp(self) -> V;
            }

            /// The closed-form principal logarithm of a unit even versor.
            pub trait Log {
                /// The bivector type of the logarithm.
                type Output;
                /// `log(self)`: the bivector `B` of the shortest motion with `exp(B) = ±self`.
                fn log(self) -> Self::Output;
            }

            /// Closed-form normalisation and square root of an even versor (its inverse is the
            /// type's inherent `inverse`, `~self / <self ~self>_0`).
            pub trait EvenVersor: ::core::marker::Sized {
                /// `self / sqrt(self ~self)`, where `self ~self` is a scalar plus a grade-4 part.
                fn normalize(self) -> Self;
                /// The square root (half the motion): `normalize(1 + self)`, or where that
                /// cancels the root of each half of the grade-4 part's `J` in the stable form
                /// (two rotations whose angles sum to nearly a half turn) or, for a rotation with
                /// a translation, boost or dilation beyond a half turn, `exp(log(self) / 2)` with
                /// the logarithm read the long way round.
                fn sqrt(self) -> Self;
            }
        });
        self.out.extend(helpers(self.scalar, &self.rt));
        if complex_log || self.any_complex_exp(&pairs) {
            self.out.extend(complex_helpers(self.scalar));
        }
        self.out.extend(items);
    }

    /// Whether the squares of `B` (restricted to `keep`) may be a complex pair.
    pub(super) fn complex_squares(&self, bt: &TypeDef, keep: &dyn Fn(Bitmap) -> bool) -> bool {
        classify(&self.spec.metric, span(bt.blades().filter(|b| keep(*b))))
            .is_ok_and(|k| k.complex_squares())
    }

    /// Whether any `exp` of `pairs` takes [`ExpBranch::Complex`].
    fn any_complex_exp(&mut self, pairs: &[(usize, usize)]) -> bool {
        pairs.iter().any(|&(bi, vi)| {
            let (_, keep) = self.exp_keep(bi, vi);
            let spec = self.spec;
            let p = self.exp_parts(&spec.types[bi], &spec.types[vi], &keep);
            matches!(p.branch, ExpBranch::Complex(_))
        })
    }

    /// Symbolic `B` (restricted to `keep`), `W = <B B>_4` and the blades of `exp(B)`.
    fn exp_support(&mut self, bt: &TypeDef, keep: &dyn Fn(Bitmap) -> bool) -> SymMv {
        let b = of_type_on(bt, keep);
        let bb = self.table.product(&b, &b, Product::Geometric);
        let w = grade_part(&bb, 4);
        let wb = grade_part(&self.table.product(&w, &b, Product::Geometric), 2);
        let mut all = b.add_scaled(&w, Rational::ONE);
        all = all.add_scaled(&wb, Rational::int(7));
        all.0.insert(0, Poly::constant(Rational::ONE));
        all
    }

    /// The smallest declared type holding `exp` of `B` restricted to `keep`.
    fn exp_target(&mut self, bt: &TypeDef, keep: &dyn Fn(Bitmap) -> bool) -> Option<usize> {
        let m = self.exp_support(bt, keep);
        match self.infer(&m) {
            OutType::Type(vi) if self.spec.types[vi].constants.is_empty() => Some(vi),
            _ => None,
        }
    }

    /// Whether `vt` holds every blade of `exp` of `B` restricted to `keep`.
    fn exp_fits(&mut self, bt: &TypeDef, keep: &dyn Fn(Bitmap) -> bool, vt: &TypeDef) -> bool {
        let m = self.exp_support(bt, keep);
        m.support().iter().all(|b| vt.blades().any(|x| x == *b))
    }

    /// The pieces of `exp` of `B` (restricted to `keep`) into `V`, shared by the Rust
    /// (`impl Exp<V> for B`) and the WGSL renderers: the expressions over `self`'s fields and
    /// the locals `w` (`W/2`) and `wb` (`(W B)/2`), the branch, and each field of `V`.
    pub(super) fn exp_parts(
        &mut self,
        bt: &TypeDef,
        vt: &TypeDef,
        keep: &dyn Fn(Bitmap) -> bool,
    ) -> ExpParts {
        let s = self.s.clone();
        let mut cx = Ctx::new(bt, s);
        let b = of_type_on(bt, keep);
        let bb = self.table.product(&b, &b, Product::Geometric);
        let square = cx.poly(&bb.get(0));
        // `w` holds W/2, `wb` then (W B)/2 and `q` is (W W)/4.
        let (w_vals, w) = cx.local_values("w", &half(&grade_part(&bb, 4)));
        let q = self.table.product(&w, &w, Product::Geometric).get(0);
        let wbm = grade_part(&self.table.product(&w, &b, Product::Geometric), 2);
        let (wb_vals, wb) = cx.local_values("wb", &wbm);
        let branch = if w.0.is_empty() {
            ExpBranch::Simple
        } else if q.is_zero() {
            ExpBranch::Null
        } else if self.complex_squares(bt, keep) {
            ExpBranch::Complex(cx.poly(&q))
        } else {
            ExpBranch::General(cx.poly(&q))
        };
        let restricted = bt.blades().any(|x| !keep(x));
        let part = if restricted {
            let names: Vec<String> = bt
                .fields
                .iter()
                .filter(|f| keep(f.bitmap))
                .map(|f| format!("`{}`", f.name))
                .collect();
            format!(
                " of the part of `self` on {} (the blades of `{}`; the others are ignored)",
                names.join(", "),
                vt.name
            )
        } else {
            String::new()
        };
        let (bref, wref, wbref) = (&b, &w, &wb);
        let value = |x: Bitmap| -> Option<TokenStream> {
            match grade(x) {
                0 => Some(quote!(c)),
                2 => {
                    let mut t = Vec::new();
                    if bref.0.contains_key(&x) {
                        let e = cx.at(bref, x);
                        t.push(quote!(alpha * (#e)));
                    }
                    if wbref.0.contains_key(&x) {
                        let e = cx.at(wbref, x);
                        t.push(quote!(beta * #e));
                    }
                    (!t.is_empty()).then(|| sum(t))
                }
                4 if wref.0.contains_key(&x) => {
                    let e = cx.at(wref, x);
                    Some(quote!(s12 * #e))
                }
                _ => None,
            }
        };
        let fields = vt
            .fields
            .iter()
            .map(|f| match value(f.bitmap) {
                Some(v) if f.sign < 0 => quote!(-(#v)),
                Some(v) => v,
                None => quote!(0.0),
            })
            .collect();
        ExpParts {
            square,
            w: w_vals,
            wb: wb_vals,
            branch,
            fields,
            part,
        }
    }

    /// `impl Exp<V> for B`.
    fn exp_impl(
        &mut self,
        bt: &TypeDef,
        vt: &TypeDef,
        keep: &dyn Fn(Bitmap) -> bool,
    ) -> TokenStream {
        let s = self.s.clone();
        let parts = self.exp_parts(bt, vt, keep);
        let sq = &parts.square;
        let (w_stmt, wb_stmt) = (array_let("w", &parts.w, &s), array_let("wb", &parts.wb, &s));
        let (bn, vn) = (ident(&bt.name), ident(&vt.name));
        let part = &parts.part;
        let (coeffs, branch) = match &parts.branch {
            ExpBranch::Simple => (
                quote! {
                    let (c, sn) = exp_log_simple(s);
                    let [alpha, beta, s12]: [#s; 3] = [sn, 0.0, 0.0];
                },
                "`self` is simple (`B B = s` is a scalar): `exp(B) = c + (sin(t)/t) B` with \
                 `c = cos t`, `t = sqrt(-s)` for `s < 0` (a rotation by `2t`), `cosh`/`sinh` for \
                 `s > 0` (a boost), `1 + B` for `s = 0` (a translation)."
                    .to_string(),
            ),
            ExpBranch::Null => {
                (
                    quote! {
                        let (c, sn, beta) = exp_log_simple_slope(s);
                        let [alpha, s12] = [sn, sn];
                    },
                    "`W = <B B>_4` squares to zero identically, so `B = B1 + B2` with `B1 B1 = s` \
                     and `B2` null (a rotation or boost plus a translation along its axis): \
                     `exp(B) = c + (sin(t)/t) (B + W/2) + ((c - sin(t)/t)/s) W B/2`, `t = sqrt(-s)` \
                     (`cosh`/`sinh` for `s > 0`); at `s = 0` (a pure translation) the last \
                     coefficient is its limit `1/3` (and `W B = 0`), the quotient's rounding is \
                     multiplied by `W B / 2 = s B2`, so it stays at the precision of `B2`."
                        .to_string(),
                )
            }
            ExpBranch::General(qe) => (
                quote! {
                    let q: #s = 4.0 * (#qe);
                    let (l1, l2) = exp_log_squares(s, q);
                    let [c, alpha, beta, s12] = exp_log_coefficients(l1, l2);
                },
                "General: `B B = s + W`, `W W = q`; the commuting parts square to the roots \
                 `l1, l2` of `l^2 - s l + q/4` (real on this span) and \
                 `exp(B) = c1 c2 + alpha B + beta (W B)/2 + s1 s2 W/2` with the coefficients \
                 of `exp_log_coefficients` (each part a rotation, boost or translation by the \
                 sign of its square; equal squares by the limit)."
                    .to_string(),
            ),
            ExpBranch::Complex(qe) => (
                quote! {
                    let q: #s = 4.0 * (#qe);
                    let [c, alpha, beta, s12] = exp_log_coefficients_of(s, q);
                },
                "General, on a span with two or more directions of each sign: `B B = s + W`, \
                 `W W = q`; the commuting parts square to the roots of `l^2 - s l + q/4`, which \
                 may be a complex pair `a ± i b`. \
                 `exp(B) = c1 c2 + alpha B + beta (W B)/2 + s1 s2 W/2` with coefficients that \
                 are symmetric in the two roots, so real: `exp_log_coefficients_of` takes them \
                 from `exp_log_coefficients` for real roots, and in complex arithmetic \
                 (`cosh` and `sinh(z)/z` of `z = sqrt(l)`) for a complex pair."
                    .to_string(),
            ),
        };
        let fields = vt.fields.iter().map(|f| ident(&f.name));
        let values = &parts.fields;
        let result = quote!(#vn { #(#fields: #values),* });
        let d = doc(&format!(
            "The exponential{part}, in closed form (invariant decomposition). {branch} \
             Exact to rounding for every finite bivector whose square does not overflow."
        ));
        quote! {
            impl Exp<#vn> for #bn {
                #d
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn exp(self) -> #vn {
                    let s: #s = #sq;
                    #w_stmt
                    #wb_stmt
                    #coeffs
                    #result
                }
            }
        }
    }
}

/// Which closed form an `exp` takes (see [`Gen::exp_parts`]).
pub(super) enum ExpBranch {
    /// `B` is simple.
    Simple,
    /// `W W = 0`: a rotation or boost plus a null part.
    Null,
    /// Two commuting parts with real squares; `(W W)/4` as an expression.
    General(TokenStream),
    /// Two commuting parts whose squares may be a complex pair; `(W W)/4` as an expression.
    Complex(TokenStream),
}

/// The pieces of one `exp`, see [`Gen::exp_parts`].
pub(super) struct ExpParts {
    /// `<B B>_0`.
    pub square: TokenStream,
    /// The elements of the local `w` (`W/2`), empty when `W = 0`.
    pub w: Vec<TokenStream>,
    /// The elements of the local `wb` (`(W B)/2`).
    pub wb: Vec<TokenStream>,
    /// The closed form taken.
    pub branch: ExpBranch,
    /// Each field of the result type, in terms of `c`, `alpha`, `beta`, `s12` and the locals.
    pub fields: Vec<TokenStream>,
    /// " of the part of `self` on ..." when `B` is restricted, else empty.
    pub part: String,
}
