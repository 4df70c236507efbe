//! Emits a self-check harness for a generated module: every emitted product, method,
//! sandwich, matrix form and conversion is compared with the slow generic [`crate::Multivector`]
//! on seeded random inputs, and the predicates (`is_finite`, `is_nan`, `abs_diff_eq`) are
//! checked on values with a NaN, an infinity and a perturbed coefficient.
//!
//! The harness is Rust code meant to be included next to the generated module (it uses
//! `super::*`); `tests/` builds it for every spec in `algebras/`. Numeric checks made while
//! generating (before the emitter relies on a result) live beside it in `generator::verify`.

use crate::generator::emit::{snake, Generated, Method, Op};
use crate::generator::spec::{Spec, TypeDef};
use crate::runtime::blade::grade;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

fn ident(name: &str) -> Ident {
    Ident::new(name, Span::call_site())
}

/// A string literal (the description of a check).
fn text(s: &str) -> Literal {
    Literal::string(s)
}

/// Emit the check harness for `spec` and the code generated from it (f64 or f32: the harness
/// reads the module's `Scalar`, and compares in f64 with a tolerance for the scalar type).
/// It defines `pub fn check_all(n: usize, seed: u64) -> (usize, Vec<String>)`, returning the
/// number of comparisons made and a description of each failure.
///
/// Above [`MAX_DENSE_REFERENCE_DIMENSION`](crate::generator::spec::MAX_DENSE_REFERENCE_DIMENSION) basis vectors
/// ([`Spec::sparse_reference`]) the reference is the sparse multivector, under the name
/// `Multivector`, and what was not emitted ([`Generated::skipped`]) is not checked.
pub fn emit_checks(spec: &Spec, generated: &Generated, runtime: &str) -> String {
    let rt: TokenStream = runtime.parse().expect("a runtime path");
    let import = if spec.sparse_reference() {
        quote!(use #rt::runtime::sparse::multivector::SparseMultivector as Multivector;)
    } else {
        quote!(use #rt::Multivector;)
    };
    let mut out = quote! {
        use super::*;
        #import
        // ga-benchmark's products of the reference (dot, commutator, regressive...).
        #[allow(unused_imports)]
        use #rt::runtime::derived::DerivedProducts as _;

        /// A small seeded generator (xorshift64*), uniform in [-1, 1).
        pub struct Rng(pub u64);
        impl Rng {
            /// Next value.
            pub fn next(&mut self) -> f64 {
                self.0 ^= self.0 >> 12;
                self.0 ^= self.0 << 25;
                self.0 ^= self.0 >> 27;
                let x = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
                (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
            }
        }

        /// Conversion of a result to the generic multivector.
        pub trait ToMv {
            /// As a generic multivector.
            fn mv(self) -> Multivector;
        }
        impl ToMv for f64 {
            fn mv(self) -> Multivector { Multivector::scalar(&algebra(), self) }
        }
        impl ToMv for f32 {
            fn mv(self) -> Multivector { Multivector::scalar(&algebra(), self as f64) }
        }

        /// Relative tolerance of a comparison: 1e-12 for f64, 1e-4 for f32.
        pub const TOL: f64 = if ::core::mem::size_of::<Scalar>() == 4 { 1e-4 } else { 1e-12 };

        /// A random scalar (uniform in [-1, 1)), the scalar operand of the named products.
        pub fn rand_scalar(rng: &mut Rng) -> Scalar { rng.next() as Scalar }

        /// A random blade of grade `k`: a random scalar times the outer product of `k` random
        /// vectors.
        pub fn rand_blade(rng: &mut Rng, k: u32) -> Multivector {
            let alg = algebra();
            let mut m = Multivector::scalar(&alg, rng.next());
            for _ in 0..k {
                let mut v = Multivector::zero(&alg);
                for i in 0..BASIS.len() { v.set(1 << i, rng.next()); }
                m = m.outer(&v);
            }
            m
        }

        /// Whether `normalized` is well conditioned at `m`: its norm is not small, and in a
        /// mixed or degenerate metric, where `m ~m` sums squares of both signs, not a small
        /// difference of large ones. The rounding of `m ~m` (relative to the sum of squares of
        /// `m`'s coefficients) is multiplied by that ratio, so an f32 result can only be checked
        /// to `TOL` where the ratio is below about 100.
        fn well_conditioned(m: &Multivector) -> bool {
            let squares: f64 = m.coeffs().iter().map(|x| x * x).sum();
            m.norm() > 1e-3 && m.norm() * m.norm() > 1e-2 * squares
        }

        fn check_that(count: &mut usize, fails: &mut Vec<String>, what: &str, ok: bool) {
            *count += 1;
            if !ok && fails.len() < 50 {
                fails.push(format!("{what}: false"));
            }
        }

        fn check(count: &mut usize, fails: &mut Vec<String>, what: &str, got: Multivector, want: Multivector) {
            *count += 1;
            let tol = TOL * (1.0 + want.max_abs());
            let finite = got.coeffs().iter().all(|x| x.is_finite());
            if !finite || got.max_diff(&want) > tol {
                if fails.len() < 50 {
                    fails.push(format!("{what}: generated {got:?}, generic {want:?}"));
                }
            }
        }
    };
    for t in &spec.types {
        out.extend(generators(t));
    }
    let mut body = TokenStream::new();
    for t in &spec.types {
        body.extend(type_checks(spec, t, generated));
    }
    body.extend(scalar_method_checks(generated));
    for o in &generated.ops {
        body.extend(match o.op.trait_name() {
            Some(_) => named_check(spec, o.op, &o.left, &o.right),
            None => op_check(spec, o.op, &o.left, &o.right),
        });
    }
    out.extend(quote! {
        /// Compare every generated function with the generic multivector on `n` random inputs.
        pub fn check_all(n: usize, seed: u64) -> (usize, Vec<String>) {
            let mut rng = Rng(seed.max(1));
            let mut count = 0usize;
            let mut fails = Vec::new();
            let c = &mut count; let f = &mut fails;
            for _ in 0..n { #body }
            (count, fails)
        }
    });
    let file: syn::File = syn::parse2(out).expect("check harness parses");
    prettyplease::unparse(&file)
}

/// `ToMv` for a type, its random generator and, for a versor, its random unit generator.
fn generators(t: &TypeDef) -> TokenStream {
    let name = ident(&t.name);
    let sn = snake(&t.name);
    let (rand, unit) = (ident(&format!("rand_{sn}")), ident(&format!("unit_{sn}")));
    let rand_doc = format!(" A random `{}` (coefficients uniform in [-1, 1)).", t.name);
    let mut out = quote! {
        impl ToMv for #name { fn mv(self) -> Multivector { self.to_multivector() } }
        #[doc = #rand_doc]
        pub fn #rand(rng: &mut Rng) -> #name { #name::from_array(::core::array::from_fn(|_| rng.next() as Scalar)) }
    };
    if t.versor {
        let biv: Vec<Literal> = t
            .fields
            .iter()
            .filter(|f| grade(f.bitmap) == 2)
            .map(|f| Literal::u32_unsuffixed(f.bitmap))
            .collect();
        if biv.is_empty() {
            // No bivector generator (an odd versor such as a reflection): a random element
            // of the type scaled so that its reversion norm a ~a is +-1.
            let doc = format!(
                " A random unit `{}`: a random element scaled so that `|a ~a| = 1`.",
                t.name
            );
            out.extend(quote! {
                #[doc = #doc]
                pub fn #unit(rng: &mut Rng) -> #name { let m = #rand(rng).mv(); let n = m.gp(&m.rev()).get(0).abs().sqrt(); #name::from_multivector(&m.scale(1.0 / n)) }
            });
        } else {
            let doc = format!(
                " A random unit `{}`: the normalised exponential of a random bivector in the type.",
                t.name
            );
            out.extend(quote! {
                #[doc = #doc]
                pub fn #unit(rng: &mut Rng) -> #name { let mut b = Multivector::zero(&algebra()); #(b.set(#biv, rng.next());)* let m = b.exp(); let m = m.scale(1.0 / m.norm()); #name::from_multivector(&m) }
            });
        }
    }
    out
}

/// The checks of one type: negation, scalar products, norm, conversion, predicates, unary
/// methods and, for a versor, the inverse of a unit one.
fn type_checks(spec: &Spec, t: &TypeDef, generated: &Generated) -> TokenStream {
    let n = spec.metric.dim();
    let name = ident(&t.name);
    let tn = &t.name;
    let sn = snake(&t.name);
    let (rand, unit) = (ident(&format!("rand_{sn}")), ident(&format!("unit_{sn}")));
    let w = |s: String| text(&s);
    let (neg, mul, lmul, div, nsq, from) = (
        w(format!("-{tn}")),
        w(format!("{tn} * 1.7")),
        w(format!("1.7 * {tn}")),
        w(format!("{tn} / 1.7")),
        w(format!("{tn}::norm_squared")),
        w(format!("{tn}::from_multivector")),
    );
    let (p_rand, p_nan, p_inf, p_near) = (
        w(format!("{tn}::is_finite/is_nan on a random value")),
        w(format!("{tn}::is_finite/is_nan/abs_diff_eq with a NaN")),
        w(format!("{tn}::is_finite/is_nan with an infinity")),
        w(format!("{tn}::abs_diff_eq")),
    );
    // Skipped (no declared type holds the result) in algebras without a general multivector.
    let skipped = |what: String| {
        generated
            .skipped
            .iter()
            .any(|s| s.split(" -> ").next() == Some(what.as_str()))
    };
    let mut out = TokenStream::new();
    if !skipped(format!("-{tn}")) {
        out.extend(quote!(check(c, f, #neg, (-a).mv(), -&ma);));
    }
    if !skipped(format!("{tn} * scalar")) {
        out.extend(quote! {
            check(c, f, #mul, (a * 1.7).mv(), ma.scale(1.7));
            check(c, f, #lmul, (1.7 * a).mv(), ma.scale(1.7));
            check(c, f, #div, (a / 1.7).mv(), ma.scale(1.0 / 1.7));
        });
    }
    out.extend(quote! {
        check(c, f, #nsq, a.norm_squared().mv(), ma.norm_squared().mv());
        check(c, f, #from, #name::from_multivector(&ma).mv(), ma.clone());
        // The predicates, on a value with one coefficient (chosen at random) changed.
        {
            let i = ((rng.next() + 1.0) * 0.5 * #name::LEN as f64) as usize % #name::LEN;
            let with = |x: Scalar| { let mut c = a.to_array(); c[i] = x; #name::from_array(c) };
            check_that(c, f, #p_rand, a.is_finite() && !a.is_nan() && a.abs_diff_eq(a, 0.0));
            let nan = with(Scalar::NAN);
            check_that(c, f, #p_nan, nan.is_nan() && !nan.is_finite() && !nan.abs_diff_eq(nan, 1.0) && !a.abs_diff_eq(nan, 1.0));
            let inf = with(-Scalar::INFINITY);
            check_that(c, f, #p_inf, !inf.is_finite() && !inf.is_nan() && !inf.abs_diff_eq(a, Scalar::MAX));
            let near = with(a.to_array()[i] + 0.5);
            let e: Scalar = if ::core::mem::size_of::<Scalar>() == 4 { 1e-5 } else { 1e-12 };
            check_that(c, f, #p_near, near.abs_diff_eq(a, 0.5 + e) && a.abs_diff_eq(near, 0.5 + e) && !near.abs_diff_eq(a, 0.499));
        }
    });
    for (_, m) in generated.methods.iter().filter(|(n, _)| n == tn) {
        let what = w(format!("{tn}::{}", m.name()));
        let method = ident(m.name());
        out.extend(match m {
            Method::Rev | Method::Involute | Method::Conjugate | Method::Dual | Method::Undual => {
                quote!(check(c, f, #what, a.#method().mv(), ma.#method());)
            }
            Method::Square => quote!(check(c, f, #what, a.square().mv(), ma.gp(&ma));),
            Method::Grade => (0..=n)
                .map(|k| {
                    let what = w(format!("{tn}::grade({k})"));
                    let k = Literal::usize_unsuffixed(k);
                    quote!(check(c, f, #what, a.grade(#k).mv(), ma.grade(#k));)
                })
                .collect(),
            Method::Normalized => quote! {
                if well_conditioned(&ma) { check(c, f, #what, a.normalized().mv(), ma.scale(1.0 / ma.norm())); }
            },
            Method::Inverse => quote! {
                if ma.norm_squared().abs() > 1e-3 { check(c, f, #what, a.inverse().mv(), ma.rev().scale(1.0 / ma.norm_squared())); }
            },
        });
    }
    if t.versor {
        // On unit versors the versor inverse is the true inverse: check against the generic
        // inverse (a linear solve), which does not assume anything.
        if t.unit {
            // The generator of true unit versors really gives `u ~u = 1`: the reductions of
            // the sandwiches rely on it.
            let what = w(format!("unit {tn}: u ~u = 1"));
            out.extend(quote! {
                { let mu = #unit(&mut rng).mv(); check(c, f, #what, mu.gp(&mu.rev()), Multivector::scalar(&algebra(), 1.0)); }
            });
        }
        let what = w(format!("unit {tn}::inverse vs generic inverse"));
        let none = w(format!("unit {tn} has no generic inverse"));
        out.extend(quote! {
            {
                let u = #unit(&mut rng);
                let mu = u.mv();
                if let Some(inv) = mu.inverse() { check(c, f, #what, u.inverse().mv(), inv); } else { f.push(#none.to_string()); }
            }
        });
    }
    quote!({ let a = #rand(&mut rng); let ma = a.mv(); #out })
}

/// The check of one emitted binary operation, sandwich or conversion.
fn op_check(spec: &Spec, op: Op, left: &str, right: &str) -> TokenStream {
    let (l, r) = (snake(left), snake(right));
    // The scalar on one side (`s ^ x`, `s | x`, ...): `rand_scalar`.
    let (rand_l, rand_r) = (rand_of(left), rand_of(right));
    let body = match op {
        Op::Geometric | Op::Outer | Op::LeftContraction | Op::Add | Op::Sub => {
            let what = text(&format!("{left} {} {right}", op.symbol()));
            match op {
                Op::Geometric => quote!(check(c, f, #what, (a * b).mv(), ma.gp(&mb));),
                Op::Outer => quote!(check(c, f, #what, (a ^ b).mv(), ma.outer(&mb));),
                Op::LeftContraction => {
                    quote!(check(c, f, #what, (a | b).mv(), ma.left_contraction(&mb));)
                }
                Op::Add => quote!(check(c, f, #what, (a + b).mv(), &ma + &mb);),
                _ => quote!(check(c, f, #what, (a - b).mv(), &ma - &mb);),
            }
        }
        Op::RightContraction
        | Op::ScalarProduct
        | Op::DotProduct
        | Op::HestenesInnerProduct
        | Op::CommutatorProduct
        | Op::RegressiveProduct
        | Op::InverseGeometricProduct => unreachable!("checked by named_check"),
        Op::From => {
            let what = text(&format!("{right}::from({left})"));
            let rn = ident(right);
            return quote!({ let a = #rand_l(&mut rng); check(c, f, #what, #rn::from(a).mv(), a.mv()); });
        }
        Op::Sandwich => {
            let vt = spec
                .types
                .iter()
                .find(|t| t.name == left)
                .expect("versor type");
            let gen = ident(&format!("{}_{l}", if vt.unit { "unit" } else { "rand" }));
            let what = text(&format!("{left}.sandwich({right})"));
            let what_m = text(&format!("{left}.{r}_matrix().apply({right})"));
            let matrix = ident(&format!("{r}_matrix"));
            let mut out = quote!({
                let a = #gen(&mut rng); let b = #rand_r(&mut rng); let (ma, mb) = (a.mv(), b.mv()); let want = ma.gp(&mb).gp(&ma.rev());
                check(c, f, #what, a.sandwich(b).mv(), want.clone());
                check(c, f, #what_m, a.#matrix().apply(b).mv(), want);
            });
            if vt.unit {
                // A unit versor's sandwich is reduced with `a ~a = 1` and keeps the grades of
                // the operand: check it also on a product of two true unit versors (a screw, a
                // boost and a rotation, ...), which is again a unit versor, when that product
                // stays in the type.
                let what = text(&format!(
                    "{left}.sandwich({right}) (product of unit versors)"
                ));
                let what_m = text(&format!(
                    "{left}.{r}_matrix().apply({right}) (product of unit versors)"
                ));
                let vn = ident(left);
                out.extend(quote!({
                    let m2 = #gen(&mut rng).mv().gp(&#gen(&mut rng).mv());
                    let a = #vn::from_multivector(&m2);
                    if m2.max_diff(&a.mv()) < 1e-6 {
                        let b = #rand_r(&mut rng); let (ma, mb) = (a.mv(), b.mv()); let want = ma.gp(&mb).gp(&ma.rev());
                        check(c, f, #what, a.sandwich(b).mv(), want.clone());
                        check(c, f, #what_m, a.#matrix().apply(b).mv(), want);
                    }
                }));
            }
            return out;
        }
    };
    quote!({ let a = #rand_l(&mut rng); let b = #rand_r(&mut rng); let (ma, mb) = (a.mv(), b.mv()); #body })
}

/// The random generator of an operand: `rand_scalar` for the scalar type, else the type's.
fn rand_of(name: &str) -> Ident {
    match name {
        "f64" | "f32" => ident("rand_scalar"),
        _ => ident(&format!("rand_{}", snake(name))),
    }
}

/// The check of one named product (called through its trait, so that an inherent method of
/// the same name in the including crate cannot hide it) against the generic multivector's
/// product of the same name; the inverse geometric product also against `a * b^-1` with the
/// generic inverse, on random blades of the right operand's grade.
fn named_check(spec: &Spec, op: Op, left: &str, right: &str) -> TokenStream {
    let (rand_l, rand_r) = (rand_of(left), rand_of(right));
    let (tr, m) = (ident(op.trait_name().expect("named")), ident(op.symbol()));
    let what = text(&format!("{left}.{}({right})", op.symbol()));
    let got = quote!(#tr::#m(a, b).mv());
    let body = match op {
        Op::ScalarProduct => quote!(check(c, f, #what, #got, ma.scalar_product(&mb).mv());),
        Op::InverseGeometricProduct => {
            let blade = text(&format!(
                "{left}.{}(blade {right}) vs a * b^-1",
                op.symbol()
            ));
            let rt = spec.types.iter().find(|t| t.name == right);
            let k = rt
                .and_then(|t| t.fields.first())
                .map_or(0, |f| grade(f.bitmap));
            let k = Literal::u32_unsuffixed(k);
            let from = match rt {
                Some(t) => {
                    let tn = ident(&t.name);
                    quote!(#tn::from_multivector(&mv))
                }
                None => quote!(mv.get(0) as Scalar),
            };
            quote! {
                if mb.norm_squared().abs() > 1e-2 { check(c, f, #what, #got, ma.reverse_quotient(&mb)); }
                let mv = rand_blade(&mut rng, #k);
                let b = #from;
                let mb = b.mv();
                if mv.max_diff(&mb) < TOL * (1.0 + mv.max_abs()) && mb.norm_squared().abs() > 1e-2 {
                    if let Some(want) = ma.inverse_geometric_product(&mb) { check(c, f, #blade, #tr::#m(a, b).mv(), want); }
                }
            }
        }
        // The generic multivector's products have the generated methods' names.
        _ => quote!(check(c, f, #what, #got, ma.#m(&mb));),
    };
    quote!({ let a = #rand_l(&mut rng); let b = #rand_r(&mut rng); let (ma, mb) = (a.mv(), b.mv()); #body })
}

/// The checks of the scalar's methods (`ScalarDual::dual`, `ScalarDual::undual`, called through
/// their trait) against the generic multivector's.
fn scalar_method_checks(generated: &Generated) -> TokenStream {
    let mut out = TokenStream::new();
    for (tn, m) in &generated.methods {
        if !matches!(tn.as_str(), "f64" | "f32") {
            continue;
        }
        let what = text(&format!("{tn}::{}", m.name()));
        let method = ident(m.name());
        let tr = ident(crate::generator::emit::SCALAR_DUAL);
        out.extend(quote!({ let a = rand_scalar(&mut rng); let ma = a.mv(); check(c, f, #what, #tr::#method(a).mv(), ma.#method()); }));
    }
    out
}
