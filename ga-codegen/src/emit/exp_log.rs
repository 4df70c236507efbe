//! Closed-form exponential, logarithm, square root and normalisation of even versors, by the
//! invariant decomposition ([`super::decompose`]).
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
//!   grade-4 part, in closed form) and `sqrt` (`normalize(1 + V)`).
//!
//! Every intermediate multivector (`W = <B B>_4`, `W B`, ...) is expanded symbolically, so
//! only the blades that can be non-zero are computed; a grade-4 part that squares to zero
//! identically (PGA's `e0123`, CGA's `e123i`) selects the one-rotation-plus-null form with no
//! quadratic to solve. A span the decomposition is not closed form on (more than five basis
//! vectors, or complex squares) gets none of these ([`refusals`] lists them).

use super::decompose::{classify, constant, helpers, span, Refusal, SpanKind};
use super::render::{doc, float, ident, lit};
use super::{Gen, OutType, ScalarType};
use crate::blade::{grade, Bitmap};
use crate::rational::Rational;
use crate::spec::{Spec, TypeDef};
use crate::symbolic::{Poly, Product, SymMv, Var};
use proc_macro2::{Ident, TokenStream};
use quote::quote;

/// The symbolic value of `t`'s fields on the canonical blades in `keep`.
fn of_type_on(t: &TypeDef, keep: impl Fn(Bitmap) -> bool) -> SymMv {
    let mut m = SymMv::of_type(t, 0);
    m.0.retain(|b, _| keep(*b));
    m
}

/// The grade-`k` part.
fn grade_part(m: &SymMv, k: u32) -> SymMv {
    SymMv(
        m.0.iter()
            .filter(|(b, _)| grade(**b) == k)
            .map(|(b, p)| (*b, p.clone()))
            .collect(),
    )
}

/// `m / 2`: the grade-4 locals hold `W/2`, which saves the factors 2 of `B ^ B` and the
/// halves of `W/2` and `(W B)/2`.
fn half(m: &SymMv) -> SymMv {
    SymMv::default().add_scaled(m, Rational::new(1, 2))
}

/// Whether `p` is a sum of squares with negative coefficients (so never positive).
fn negative_squares(p: &Poly) -> bool {
    p.0.iter()
        .all(|(m, c)| m.len() == 2 && m[0] == m[1] && *c < Rational::ZERO)
}

/// Whether a type is a bivector type (fields only, every blade of grade 2).
fn is_bivector(t: &TypeDef) -> bool {
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

/// The types of a spec that get no closed forms, and why (their span is too large or has
/// complex squares). `ga-codegen --exp-log` refuses a spec for which this is not empty.
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
struct Ctx<'a> {
    ty: &'a TypeDef,
    locals: Vec<Ident>,
    s: TokenStream,
}

impl<'a> Ctx<'a> {
    fn new(ty: &'a TypeDef, s: TokenStream) -> Ctx<'a> {
        Ctx {
            ty,
            locals: Vec::new(),
            s,
        }
    }

    fn var(&self, v: Var) -> TokenStream {
        if v.operand == 0 {
            let f = ident(&self.ty.fields[v.field as usize].name);
            quote!(self.#f)
        } else {
            let name = &self.locals[v.operand as usize - 3];
            let i = proc_macro2::Literal::usize_unsuffixed(v.field as usize);
            quote!(#name[#i])
        }
    }

    /// `c1 * m1 + c2 * m2 - ...`, or `0.0`.
    fn poly(&self, p: &Poly) -> TokenStream {
        if p.is_zero() {
            return quote!(0.0);
        }
        let mut s = TokenStream::new();
        for (i, (m, &c)) in p.0.iter().enumerate() {
            let neg = c < Rational::ZERO;
            let mag = if neg { -c } else { c };
            if neg {
                s.extend(quote!(-));
            } else if i > 0 {
                s.extend(quote!(+));
            }
            let mut vars = TokenStream::new();
            for (k, v) in m.iter().enumerate() {
                if k > 0 {
                    vars.extend(quote!(*));
                }
                vars.extend(self.var(*v));
            }
            match (m.is_empty(), mag == Rational::ONE) {
                (true, _) => s.extend(lit(mag)),
                (false, true) => s.extend(vars),
                (false, false) => {
                    let l = lit(mag);
                    s.extend(quote!(#l * #vars));
                }
            }
        }
        s
    }

    /// The coefficient of canonical blade `b` of `m` as an expression.
    fn at(&self, m: &SymMv, b: Bitmap) -> TokenStream {
        self.poly(&m.get(b))
    }

    /// `let name = [..];` holding `factor * m` on its support, and the symbolic local that
    /// stands for it (empty, with no statement, when `m` is zero).
    fn local(
        &mut self,
        name: &str,
        m: &SymMv,
        factor: Option<&TokenStream>,
    ) -> (TokenStream, SymMv) {
        if m.0.is_empty() {
            return (TokenStream::new(), SymMv::default());
        }
        let id = ident(name);
        let vals = m.0.values().map(|p| {
            let e = self.poly(p);
            match factor {
                Some(f) => quote!(#f * (#e)),
                None => e,
            }
        });
        let s = &self.s;
        let n = proc_macro2::Literal::usize_unsuffixed(m.0.len());
        let stmt = quote!(let #id: [#s; #n] = [#(#vals),*];);
        let operand = 3 + self.locals.len() as u8;
        self.locals.push(id);
        let sym = SymMv(
            m.0.keys()
                .enumerate()
                .map(|(i, b)| {
                    let var = Var {
                        operand,
                        field: i as u16,
                    };
                    (*b, Poly::var(var, Rational::ONE))
                })
                .collect(),
        );
        (stmt, sym)
    }
}

/// `terms` summed, or `0.0`.
fn sum(terms: Vec<TokenStream>) -> TokenStream {
    if terms.is_empty() {
        quote!(0.0)
    } else {
        quote!(#(#terms)+*)
    }
}

/// The value of a type's fields from expressions on canonical blades (`None`: zero).
fn build(t: &TypeDef, value: impl Fn(Bitmap) -> Option<TokenStream>) -> TokenStream {
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
    pub(super) fn exp_log(&mut self) {
        let spec = self.spec;
        let mut items = TokenStream::new();
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
        for &(bi, vi) in &pairs {
            let vt = &spec.types[vi];
            let g2: Vec<Bitmap> = vt.blades().filter(|b| grade(*b) == 2).collect();
            let all = self.exp_target(&spec.types[bi], &|_| true) == Some(vi);
            let keep = move |b: Bitmap| all || g2.contains(&b);
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
        for vt in spec.types.iter().filter(|t| is_even_versor(t)) {
            let Ok(kind) = classify(&spec.metric, span(vt.blades())) else {
                continue;
            };
            let log = self.log_impl(vt, kind);
            if !log.is_empty() {
                self.closed_forms.push(format!("{:<12} log", vt.name));
            }
            items.extend(log);
            let root = self.root_impl(vt);
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

            /// Closed-form normalisation and square root of an even versor.
            pub trait EvenVersor: Sized {
                /// `self / sqrt(self ~self)`, where `self ~self` is a scalar plus a grade-4 part.
                fn normalize(self) -> Self;
                /// The square root (half the motion), `normalize(1 + self)`.
                fn sqrt(self) -> Self;
            }
        });
        self.out.extend(helpers(self.scalar));
        self.out.extend(items);
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

    /// `impl Exp<V> for B`.
    fn exp_impl(
        &mut self,
        bt: &TypeDef,
        vt: &TypeDef,
        keep: &dyn Fn(Bitmap) -> bool,
    ) -> TokenStream {
        let s = self.s.clone();
        let mut cx = Ctx::new(bt, s.clone());
        let b = of_type_on(bt, keep);
        let bb = self.table.product(&b, &b, Product::Geometric);
        let sq = cx.poly(&bb.get(0));
        // `w` holds W/2, `wb` then (W B)/2 and `q` is (W W)/4.
        let (w_stmt, w) = cx.local("w", &half(&grade_part(&bb, 4)), None);
        let q = self.table.product(&w, &w, Product::Geometric).get(0);
        let wb = grade_part(&self.table.product(&w, &b, Product::Geometric), 2);
        let (wb_stmt, wb) = cx.local("wb", &wb, None);
        let (bn, vn) = (ident(&bt.name), ident(&vt.name));
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
        let (coeffs, branch) = if w.0.is_empty() {
            (
                quote! {
                    let (c, sn) = exp_log_simple(s);
                    let [alpha, beta, s12]: [#s; 3] = [sn, 0.0, 0.0];
                },
                "`self` is simple (`B B = s` is a scalar): `exp(B) = c + (sin(t)/t) B` with \
                 `c = cos t`, `t = sqrt(-s)` for `s < 0` (a rotation by `2t`), `cosh`/`sinh` for \
                 `s > 0` (a boost), `1 + B` for `s = 0` (a translation)."
                    .to_string(),
            )
        } else if q.is_zero() {
            let third = constant(self.scalar, 1.0 / 3.0);
            (
                quote! {
                    let (c, sn) = exp_log_simple(s);
                    let beta = if s != 0.0 { (c - sn) / s } else { #third };
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
        } else {
            let qe = cx.poly(&q);
            (
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
            )
        };
        let bref = &b;
        let (wref, wbref) = (&w, &wb);
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
        let result = build(vt, value);
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

    /// `impl Log for V`, into the smallest type holding `V`'s bivector blades.
    fn log_impl(&mut self, vt: &TypeDef, kind: SpanKind) -> TokenStream {
        let s = self.s.clone();
        let v = SymMv::of_type(vt, 0);
        // The smallest bivector type holding every bivector blade of `V`.
        let g2: Vec<Bitmap> = grade_part(&v, 2).support();
        let Some(lo) = self.by_size.iter().copied().find(|&i| {
            let t = &self.spec.types[i];
            is_bivector(t) && g2.iter().all(|b| t.blades().any(|x| x == *b))
        }) else {
            return TokenStream::new();
        };
        let spec = self.spec;
        let lt = &spec.types[lo];
        let mut cx = Ctx::new(vt, s.clone());
        let sg = quote!(sg);
        let r0 = cx.at(&v, 0);
        // Rotation plus null part: the hemisphere sign goes into one factor (see `log_null`), so
        // the parts are read as stored. Each local is one field up to sign, so these identities
        // hold for the locals as they do for the fields.
        let g2 = grade_part(&v, 2);
        let g2sq = self.table.product(&g2, &g2, Product::Geometric);
        let g4 = grade_part(&g2sq, 4);
        let fast = negative_squares(&g2sq.get(0))
            && self
                .table
                .product(&g4, &g4, Product::Geometric)
                .get(0)
                .is_zero();
        let factor = (!fast).then_some(&sg);
        let (p_stmt, p) = cx.local("p", &g2, factor);
        let (r4_stmt, r4) = cx.local("r4", &grade_part(&v, 4), factor);
        let pp = self.table.product(&p, &p, Product::Geometric);
        let sp = cx.poly(&pp.get(0));
        // `wp` holds (P ^ P)/2, so `wpp` is ((P ^ P) P)/2.
        let (wp_stmt, wp) = cx.local("wp", &half(&grade_part(&pp, 4)), None);
        let qp = self.table.product(&wp, &wp, Product::Geometric).get(0);
        let wpp = grade_part(&self.table.product(&wp, &p, Product::Geometric), 2);
        if fast {
            return self.log_null(vt, lt, cx, [p_stmt, r4_stmt, wp_stmt], sp, &p, &r4, &wpp);
        }
        let squares = if qp.is_zero() {
            quote!(let (mr, mo) = (sp.min(0.0), sp.max(0.0));)
        } else {
            let qe = cx.poly(&qp);
            quote!(let (mr, mo) = exp_log_squares(sp, 4.0 * (#qe));)
        };
        // p_r = (mr p - (W p)/2) / (mr - mo): the part with the smaller square.
        let pr_vals = p.0.keys().map(|b| {
            let pe = cx.at(&p, *b);
            if wpp.0.contains_key(b) {
                let we = cx.at(&wpp, *b);
                quote!((mr * #pe - (#we)) * k)
            } else {
                quote!(mr * #pe * k)
            }
        });
        let n = proc_macro2::Literal::usize_unsuffixed(p.0.len());
        let tiny = self.tiny();
        let pr_stmt = quote! {
            let d = mr - mo;
            let pr: [#s; #n] = if d.abs() > #tiny { let k = 1.0 / d; [#(#pr_vals),*] } else { [0.0; #n] };
        };
        let pr_sym = SymMv(
            p.0.keys()
                .enumerate()
                .map(|(i, b)| {
                    let var = Var {
                        operand: 3 + cx.locals.len() as u8,
                        field: i as u16,
                    };
                    (*b, Poly::var(var, Rational::ONE))
                })
                .collect(),
        );
        cx.locals.push(ident("pr"));
        let prr4 = grade_part(&self.table.product(&pr_sym, &r4, Product::Geometric), 2);
        let uo_vals = p.0.keys().enumerate().map(|(i, b)| {
            let i = proc_macro2::Literal::usize_unsuffixed(i);
            let pe = cx.at(&p, *b);
            if prr4.0.contains_key(b) {
                let re = cx.at(&prr4, *b);
                quote!((r0 * (#pe - pr[#i]) - (#re)) * ic)
            } else {
                quote!(r0 * (#pe - pr[#i]) * ic)
            }
        });
        let uo_stmt = quote!(let ic = 1.0 / co; let uo: [#s; #n] = [#(#uo_vals),*];);
        let uo_sym = SymMv(
            p.0.keys()
                .enumerate()
                .map(|(i, b)| {
                    let var = Var {
                        operand: 3 + cx.locals.len() as u8,
                        field: i as u16,
                    };
                    (*b, Poly::var(var, Rational::ONE))
                })
                .collect(),
        );
        cx.locals.push(ident("uo"));
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
        let keys: Vec<Bitmap> = p.0.keys().copied().collect();
        let result = build(lt, |x| {
            keys.iter().position(|b| *b == x).map(|i| {
                let i = proc_macro2::Literal::usize_unsuffixed(i);
                quote!(kr * pr[#i] + ko * uo[#i])
            })
        });
        // Isoclinic double rotations: equal squares, the split is not unique; B = theta/a P.
        let isoclinic = if kind.double_rotation() && !r4.0.is_empty() {
            let tol = float(match self.scalar {
                ScalarType::F64 => 1e-12,
                ScalarType::F32 => 1e-5,
            });
            let r4sq = cx.poly(&self.table.product(&r4, &r4, Product::Geometric).get(0));
            let iso = build(lt, |x| {
                keys.iter().position(|b| *b == x).map(|i| {
                    let pe = cx.at(&p, keys[i]);
                    quote!(k * (#pe))
                })
            });
            quote! {
                if mo < 0.0 && (mr - mo).abs() <= #tol * mr.abs() {
                    let a = (-mr).sqrt();
                    let n4 = (#r4sq).max(0.0).sqrt();
                    let k = (2.0 * a).atan2(r0 - n4) / (2.0 * a);
                    return #iso;
                }
            }
        } else {
            TokenStream::new()
        };
        let (vn, ln) = (ident(&vt.name), ident(&lt.name));
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
             translation (`pr = 0`) returns the bivector part itself.",
            vt.name
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
                    #p_stmt
                    #r4_stmt
                    let sp: #s = #sp;
                    #wp_stmt
                    #squares
                    #isoclinic
                    #pr_stmt
                    let a = (-mr).max(0.0).sqrt();
                    let th = a.atan2(r0);
                    let co = (r0 * r0 + a * a).sqrt();
                    let kr = if a > 0.0 { th / a } else { 1.0 / r0 };
                    #uo_stmt
                    #ko
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
    #[allow(clippy::too_many_arguments)]
    fn log_null(
        &mut self,
        vt: &TypeDef,
        lt: &TypeDef,
        mut cx: Ctx<'_>,
        stmts: [TokenStream; 3],
        sp: TokenStream,
        p: &SymMv,
        r4: &SymMv,
        wpp: &SymMv,
    ) -> TokenStream {
        let s = self.s.clone();
        let r0 = cx.at(&SymMv::of_type(vt, 0), 0);
        let keys: Vec<Bitmap> = p.0.keys().copied().collect();
        // pr = p - (W p) / (2 <P P>_0): the rotation part.
        let pr_vals = keys.iter().map(|b| {
            let pe = cx.at(p, *b);
            if wpp.0.contains_key(b) {
                let we = cx.at(wpp, *b);
                quote!(#pe - (#we) * k)
            } else {
                pe
            }
        });
        let n = proc_macro2::Literal::usize_unsuffixed(keys.len());
        let pr_stmt = quote!(let pr: [#s; #n] = [#(#pr_vals),*];);
        let pr_sym = SymMv(
            keys.iter()
                .enumerate()
                .map(|(i, b)| {
                    let var = Var {
                        operand: 3 + cx.locals.len() as u8,
                        field: i as u16,
                    };
                    (*b, Poly::var(var, Rational::ONE))
                })
                .collect(),
        );
        cx.locals.push(ident("pr"));
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
        let [p_stmt, r4_stmt, wp_stmt] = stmts;
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
                    #p_stmt
                    #r4_stmt
                    let sp: #s = #sp;
                    #wp_stmt
                    let k: #s = if sp < -#tiny { 1.0 / sp } else { 0.0 };
                    let rk = r0 * k;
                    #pr_stmt
                    let a = (-sp).max(0.0).sqrt();
                    let r0a = r0.abs();
                    let kr = (if a > 0.0 { a.atan2(r0a) / a } else { 1.0 / r0a }).copysign(r0);
                    #result
                }
            }
        }
    }

    /// `impl EvenVersor for V` when `(a + W) V` stays in `V` for the grade-4 part `W` of
    /// `V ~V`.
    fn root_impl(&mut self, vt: &TypeDef) -> TokenStream {
        let s = self.s.clone();
        let mut cx = Ctx::new(vt, s.clone());
        let v0 = SymMv::of_type(vt, 0);
        let (v_stmt, v) = cx.local("v", &v0, Some(&quote!(k)));
        let vv = self.table.product(&v, &v.rev(), Product::Geometric);
        let n0 = cx.poly(&vv.get(0));
        let (n4_stmt, n4) = cx.local("n4", &grade_part(&vv, 4), None);
        let vn = ident(&vt.name);
        let body = if n4.0.is_empty() {
            let result = build(vt, |x| {
                v.0.contains_key(&x).then(|| {
                    let e = cx.at(&v, x);
                    quote!(#e * r)
                })
            });
            quote! {
                let n0: #s = #n0;
                let r = 1.0 / n0.sqrt();
                #result
            }
        } else {
            // y = a - n4 as a local: [a, -n4...] on blades [0, n4 blades].
            let mut y = SymMv::default();
            let operand = 3 + cx.locals.len() as u8;
            y.0.insert(0, Poly::var(Var { operand, field: 0 }, Rational::ONE));
            for (i, b) in n4.0.keys().enumerate() {
                let var = Var {
                    operand,
                    field: i as u16 + 1,
                };
                y.0.insert(*b, Poly::var(var, -Rational::ONE));
            }
            cx.locals.push(ident("y"));
            // On the left: (y v)(y v)~ = y (v ~v) y = 1, as y is a function of v ~v.
            let vy = self.table.product(&y, &v, Product::Geometric);
            if !vy.support().iter().all(|b| vt.blades().any(|x| x == *b)) {
                return TokenStream::new();
            }
            let qn = cx.poly(&self.table.product(&n4, &n4, Product::Geometric).get(0));
            let ys = (0..n4.0.len()).map(|i| {
                let i = proc_macro2::Literal::usize_unsuffixed(i);
                quote!(n4[#i])
            });
            let m = proc_macro2::Literal::usize_unsuffixed(n4.0.len() + 1);
            let result = build(vt, |x| {
                vy.0.contains_key(&x).then(|| {
                    let e = cx.at(&vy, x);
                    quote!((#e) * r)
                })
            });
            quote! {
                let n0: #s = #n0;
                #n4_stmt
                let sn = (n0 * n0 - (#qn)).max(0.0).sqrt();
                let a = n0 + sn;
                let y: [#s; #m] = [a, #(#ys),*];
                let r = 1.0 / (2.0 * a * sn * sn).sqrt();
                #result
            }
        };
        let scalar_field = ident(
            &vt.fields
                .iter()
                .find(|f| f.bitmap == 0)
                .expect("an even versor stores its scalar")
                .name,
        );
        let first = ident(&vt.fields[0].name);
        let maxes = vt.fields[1..].iter().map(|f| {
            let id = ident(&f.name);
            quote!(self.#id.abs())
        });
        let dn = doc(&format!(
            "`self` divided by the square root of `self ~self`, in closed form. `x = self ~self` \
             is a scalar `n0` plus a grade-4 part `n4` with `n4 n4 = q` a scalar, so \
             `sqrt(x) = (x + sqrt(N)) / sqrt(2 (n0 + sqrt(N)))` with `N = n0^2 - q`, and \
             `self / sqrt(x) = (a - n4) self / sqrt(2 a N)` (on the left, so that the result times its reverse is `x^(-1/2) x x^(-1/2) = 1` even when `n4` does not commute with `self`), `a = n0 + sqrt(N)` (for PGA and \
             CGA motors `q = 0`: `(1 - n4/(2 n0)) self / sqrt(n0)`). `self` is first divided by \
             its largest coefficient, so huge and tiny `{}`s normalise without overflow. Not \
             finite for zero.",
            vt.name
        ));
        let dr = doc(
            "The square root (half the motion): `normalize(1 + self)`, which is `sqrt(self)` for \
             a unit even versor because `1 + v = sqrt(v) (~sqrt(v) + sqrt(v))` and the second \
             factor is a scalar plus a grade-4 part that normalisation removes. Not finite for \
             `-1` (a full turn has no unique half).",
        );
        quote! {
            impl EvenVersor for #vn {
                #dn
                #[inline]
                #[allow(unused_variables, clippy::neg_multiply, clippy::double_parens)]
                fn normalize(self) -> Self {
                    let k: #s = 1.0 / self.#first.abs() #(.max(#maxes))*;
                    #v_stmt
                    #body
                }
                #dr
                #[inline]
                fn sqrt(self) -> Self {
                    let mut v = self;
                    v.#scalar_field += 1.0;
                    v.normalize()
                }
            }
        }
    }
}
