//! Type emission: one `#[repr(C)]` struct per declared type, its constructors and array
//! conversions, unary methods, norms, conversions to and from the generic multivector, and the
//! scalar operators (negation, scalar product and quotient).

use crate::generator::emit::render::{doc, ident, int, lit, Names};
use crate::generator::emit::{Gen, Method, OutType};
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{Product, SymMv};
use crate::runtime::blade::{blade_name, grade, Bitmap};
use crate::runtime::rational::Rational;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

impl Gen<'_> {
    /// The struct of type `ti` and its inherent and scalar-operator impls.
    pub(crate) fn type_def(&mut self, ti: usize) {
        let spec = self.spec;
        let t = &spec.types[ti];
        let s = self.s.clone();
        let name = ident(&t.name);
        let struct_doc = doc(&self.type_doc(t));
        let fields: Vec<_> = t.fields.iter().map(|f| ident(&f.name)).collect();
        let field_docs = t
            .fields
            .iter()
            .map(|f| doc(&format!("Coefficient of `{}`.", f.name)));
        self.out.extend(quote! {
            #struct_doc
            #[repr(C)]
            #[derive(Clone, Copy, Debug, PartialEq, Default)]
            pub struct #name {
                #(#field_docs pub #fields: #s,)*
            }
        });

        let nf = int(t.fields.len());
        let blade_list = t.fields.iter().map(|f| Literal::string(&f.name));
        let idx = (0..t.fields.len()).map(int);
        let mut body = quote! {
            /// Number of stored coefficients.
            pub const LEN: usize = #nf;
            /// Field (blade) names in storage order.
            pub const BLADES: [&'static str; #nf] = [#(#blade_list),*];
            /// A value from its coefficients, in storage order.
            #[inline]
            #[must_use]
            #[allow(clippy::too_many_arguments)]
            pub const fn new(#(#fields: #s),*) -> Self { Self { #(#fields),* } }
            /// The coefficients in storage order.
            #[inline]
            #[must_use]
            pub const fn to_array(self) -> [#s; #nf] { [#(self.#fields),*] }
            /// A value from coefficients in storage order.
            #[inline]
            #[must_use]
            pub const fn from_array(c: [#s; #nf]) -> Self { Self { #(#fields: c[#idx]),* } }
        };
        body.extend(self.predicates(t));
        body.extend(self.unary_methods(t));
        body.extend(self.multivector_conversions(t));
        let mv = self.multivector_path();
        self.out.extend(quote! {
            impl #name { #body }
            impl ::core::convert::From<#name> for #mv {
                fn from(x: #name) -> Self { x.to_multivector() }
            }
        });
        self.scalar_operators(t);
    }

    /// The doc of a type: its own, then its blades, constants and normalisation.
    fn type_doc(&self, t: &TypeDef) -> String {
        let basis = self.spec.metric.names();
        let mut doc = t
            .doc
            .clone()
            .unwrap_or_else(|| format!("The `{}` type.", t.name));
        doc.push_str(&format!(
            "\n\nStored blades: {}.",
            t.fields
                .iter()
                .map(|f| format!("`{}`", f.name))
                .collect::<Vec<_>>()
                .join(", ")
        ));
        if !t.constants.is_empty() {
            doc.push_str(&format!(
                " Constant blades (not stored): {}.",
                t.constants
                    .iter()
                    .map(|&(b, c)| format!("`{}` = {}", blade_name(b, basis), c))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
        if t.unit {
            doc.push_str(" Assumed normalised (`x * ~x = 1`) by its sandwich products.");
        }
        doc
    }

    /// `is_finite`, `is_nan` and `abs_diff_eq`, as glam's (constant blades are equal and
    /// finite, so only stored coefficients are compared).
    fn predicates(&self, t: &TypeDef) -> TokenStream {
        let s = &self.s;
        let fields: Vec<_> = t.fields.iter().map(|f| ident(&f.name)).collect();
        quote! {
            /// Whether every coefficient is finite (not infinite and not NaN).
            #[inline] #[must_use] pub fn is_finite(self) -> bool { #(self.#fields.is_finite())&&* }
            /// Whether any coefficient is NaN.
            #[inline] #[must_use] pub fn is_nan(self) -> bool { #(self.#fields.is_nan())||* }
            /// Whether every coefficient differs from `other`'s by at most `max_abs_diff`, as
            /// glam's `abs_diff_eq`; false when a coefficient of either is NaN.
            #[inline] #[must_use] pub fn abs_diff_eq(self, other: Self, max_abs_diff: #s) -> bool {
                #((self.#fields - other.#fields).abs() <= max_abs_diff)&&*
            }
        }
    }

    /// `rev`, `involute`, `conjugate`, `dual`, `undual`, `square` (result types inferred), the
    /// norms, and for types without constants `grade`, `normalized` and `inverse`.
    fn unary_methods(&mut self, t: &TypeDef) -> TokenStream {
        let s = self.s.clone();
        let a = SymMv::of_type(t, 0);
        let unary: [(Method, &str, SymMv); 6] = [
            (
                Method::Rev,
                "The reverse (reverses the order of every outer product).",
                a.rev(),
            ),
            (
                Method::Involute,
                "The grade involution (negates odd grades).",
                a.involute(),
            ),
            (
                Method::Conjugate,
                "The Clifford conjugate (reverse of the grade involution).",
                a.conjugate(),
            ),
            (Method::Dual, self.dual_doc(), self.dual(&a)),
            (Method::Undual, self.undual_doc(), self.undual(&a)),
            (
                Method::Square,
                "The geometric square `x * x`, expanded in one set of coefficients: the terms \
                 `x_i x_j` and `x_j x_i` of anticommuting blades cancel before any code is \
                 emitted (a bivector's square keeps no bivector part), and the result takes \
                 the smallest type that holds what is left.",
                self.table.product(&a, &a, Product::Geometric),
            ),
        ];
        let mut out = TokenStream::new();
        for (method, fdoc, m) in unary.iter() {
            // The square of a versor is a versor: the smallest versor type, as `x * x`.
            let o = if *method == Method::Square && t.versor {
                self.infer_versor_product(m)
            } else {
                self.infer(m)
            };
            if o == OutType::Zero
                || self.skip_unfit(o, m, &format!("{}::{}", t.name, method.name()))
            {
                continue;
            }
            self.methods.push((t.name.clone(), *method));
            let names = Names::new(t, None);
            let body = bind_self(self.build(o, m, &names), &names);
            let (fdoc, fname, on) = (doc(fdoc), ident(method.name()), self.out_type(o));
            out.extend(quote! {
                #fdoc #[inline] #[must_use] pub fn #fname(self) -> #on { #body }
            });
        }
        let nsq = self.table.product(&a, &a.rev(), Product::Scalar);
        let names = Names::new(t, None);
        let nsq = bind_self(names.poly(&nsq.get(0)), &names);
        out.extend(quote! {
            /// `<x ~x>_0`, the squared norm (zero for null elements such as conformal points).
            #[inline] #[must_use] pub fn norm_squared(self) -> #s { #nsq }
            /// `sqrt(|<x ~x>_0|)`.
            #[inline] #[must_use] pub fn norm(self) -> #s { self.norm_squared().abs().sqrt() }
        });
        if t.constants.is_empty() {
            for m in [Method::Grade, Method::Normalized, Method::Inverse] {
                self.methods.push((t.name.clone(), m));
            }
            let scaled = |sign: &dyn Fn(Bitmap) -> i32| -> TokenStream {
                let parts = t.fields.iter().map(|f| {
                    let id = ident(&f.name);
                    if sign(f.bitmap) < 0 {
                        quote!(#id: -self.#id * r)
                    } else {
                        quote!(#id: self.#id * r)
                    }
                });
                quote!(Self { #(#parts),* })
            };
            let grades = t.fields.iter().map(|f| {
                let (id, g) = (ident(&f.name), int(grade(f.bitmap) as usize));
                quote!(#id: if k == #g { self.#id } else { 0.0 })
            });
            let normed = scaled(&|_| 1);
            let inv = scaled(&crate::runtime::blade::reverse_sign);
            out.extend(quote! {
                /// The grade-`k` part.
                #[inline] #[must_use] pub fn grade(self, k: u32) -> Self { Self { #(#grades),* } }
                /// `x / norm(x)`; not finite when the norm is zero.
                #[inline] #[must_use] pub fn normalized(self) -> Self { let r = 1.0 / self.norm(); #normed }
                /// The versor (and blade) inverse `~x / <x ~x>_0`. It is the inverse of `x` whenever
                /// `x ~x` is a scalar, as for every versor and blade; not finite when that scalar is zero.
                #[inline] #[must_use] pub fn inverse(self) -> Self { let r = 1.0 / self.norm_squared(); #inv }
            });
        }
        out
    }

    /// `to_multivector` and `from_multivector`.
    fn multivector_conversions(&self, t: &TypeDef) -> TokenStream {
        let mv = self.multivector_path();
        let f32 = self.scalar == crate::generator::emit::ScalarType::F32;
        let mut to_mv = TokenStream::new();
        for f in &t.fields {
            let (id, bm) = (ident(&f.name), Literal::u32_unsuffixed(f.bitmap));
            let neg = (f.sign < 0).then(|| quote!(-));
            // The generic multivector is f64: widen f32 coefficients, leave f64 ones alone.
            let widen = f32.then(|| quote!(as f64));
            to_mv.extend(quote!(m.set(#bm, #neg self.#id #widen);));
        }
        for &(b, c) in &t.constants {
            let (bm, c) = (Literal::u32_unsuffixed(b), lit(c));
            to_mv.extend(quote!(m.set(#bm, #c);));
        }
        let s = &self.s;
        let from_mv = t.fields.iter().map(|f| {
            let (id, bm) = (ident(&f.name), Literal::u32_unsuffixed(f.bitmap));
            let neg = (f.sign < 0).then(|| quote!(-));
            if f32 {
                quote!(#id: (#neg m.get(#bm)) as #s)
            } else {
                quote!(#id: #neg m.get(#bm))
            }
        });
        quote! {
            /// This value as a generic multivector (constant blades included).
            #[must_use] pub fn to_multivector(self) -> #mv { let mut m = #mv::zero(&algebra()); #to_mv m }
            /// The stored blades of a generic multivector; other blades and constant blades are ignored.
            #[must_use] pub fn from_multivector(m: &#mv) -> Self { Self { #(#from_mv),* } }
        }
    }

    /// `-a`, `a * s`, `s * a` and `a / s`.
    fn scalar_operators(&mut self, t: &TypeDef) {
        let (s, name) = (self.s.clone(), ident(&t.name));
        let names = Names::new(t, None);
        let a = SymMv::of_type(t, 0);
        let neg = a.add_scaled(&a, Rational::int(-2));
        let o = self.infer(&neg);
        if !self.skip_unfit(o, &neg, &format!("-{}", t.name)) {
            let on = self.out_type(o);
            let body = self.build(o, &neg, &names);
            self.out.extend(quote! {
                impl ::core::ops::Neg for #name { type Output = #on; #[inline] fn neg(self) -> #on { let a = self; #body } }
            });
        }
        let m = self
            .table
            .product(&a, &SymMv::scalar_var(), Product::Geometric);
        let o = self.infer(&m);
        if self.skip_unfit(o, &m, &format!("{} * scalar", t.name)) {
            return;
        }
        let on = self.out_type(o);
        let body = self.build(o, &m, &names);
        self.out.extend(quote! {
            impl ::core::ops::Mul<#s> for #name { type Output = #on; #[inline] fn mul(self, s: #s) -> #on { let a = self; #body } }
            impl ::core::ops::Mul<#name> for #s { type Output = #on; #[inline] fn mul(self, a: #name) -> #on { let s = self; #body } }
            impl ::core::ops::Div<#s> for #name { type Output = #on; #[inline] #[allow(clippy::suspicious_arithmetic_impl)] fn div(self, s: #s) -> #on { let a = self; let s = 1.0 / s; #body } }
        });
    }
}

/// `let a = self;` in front of a method body, when the body reads `a` at all.
fn bind_self(body: TokenStream, names: &Names) -> TokenStream {
    if names.reads_a() {
        quote!(let a = self; #body)
    } else {
        body
    }
}
