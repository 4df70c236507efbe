//! Wide twins: the versor types and the types they act on, in structure-of-arrays form over a
//! [`crate::runtime::wide_lanes::Lane`] `W` (`pub mod wide`, with [`crate::generator::emit::EmitOptions::wide`]).
//!
//! `wide::Motor<W>` holds one `W` per field; lane `i` of every field is operand `i`. The
//! sums, differences, reverses, geometric products between the twins and the fused sandwiches
//! are the same expressions as the scalar module's (the same symbolic products, zero terms
//! dropped, the same factored sandwich kernels), with every constant `c` written `W::constant(c)`.
//! So `W = f64` gives the scalar results bit for bit, and each lane of `F64x4` too.

use crate::generator::emit::render::{doc, ident, Names};
use crate::generator::emit::{Gen, GenError, Op, OutType};
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{Poly, SymMv};
use crate::runtime::rational::Rational;
use proc_macro2::{Group, Literal, TokenStream, TokenTree};
use quote::quote;
use std::collections::BTreeSet;

/// Every float literal of `t` as `W::splat(literal)`.
fn splat_literals(t: TokenStream) -> TokenStream {
    t.into_iter()
        .map(|tt| match tt {
            TokenTree::Group(g) => {
                let mut n = Group::new(g.delimiter(), splat_literals(g.stream()));
                n.set_span(g.span());
                TokenTree::Group(n)
            }
            TokenTree::Literal(l) if is_float(&l) => {
                let text = l.to_string();
                let bare = text.trim_end_matches("f64").trim_end_matches("f32");
                let l: TokenStream = bare.parse().expect("a float literal");
                let g = Group::new(proc_macro2::Delimiter::None, quote!(W::constant(#l)));
                TokenTree::Group(g)
            }
            other => other,
        })
        .collect()
}

fn is_float(l: &Literal) -> bool {
    let s = l.to_string();
    s.chars().next().is_some_and(|c| c.is_ascii_digit())
        && (s.contains('.') || s.contains('e') || s.ends_with("f64") || s.ends_with("f32"))
}

/// An expression of the scalar module with its constants splatted.
fn wide_expr(t: TokenStream) -> TokenStream {
    splat_literals(t)
}

impl Gen<'_> {
    /// The types that get a wide twin: versor types and the operands and outputs of their
    /// declared sandwiches, in declaration order.
    fn wide_types(&mut self) -> Result<Vec<usize>, GenError> {
        let spec = self.spec;
        let mut set: BTreeSet<usize> = (0..spec.types.len())
            .filter(|&i| spec.types[i].versor)
            .collect();
        for d in &spec.sandwiches {
            let parts = self.sandwich_parts(d)?;
            set.extend([parts.versor, parts.operand, parts.output]);
        }
        Ok(set.into_iter().collect())
    }

    /// The `wide` module.
    pub(crate) fn wide_module(&mut self) -> Result<(), GenError> {
        let spec = self.spec;
        let rt = self.rt.clone();
        let kept = self.wide_types()?;
        let mut items = TokenStream::new();
        for &ti in &kept {
            items.extend(self.wide_type(&spec.types[ti]));
        }
        for &ai in &kept {
            for &bi in &kept {
                items.extend(self.wide_product(ai, bi, &kept));
            }
        }
        for d in &spec.sandwiches {
            let parts = self.sandwich_parts(d)?;
            let (tv, tx, to) = parts.types(spec);
            let (vn, xn, on) = (ident(&tv.name), ident(&tx.name), ident(&to.name));
            let lets = parts.kernel.temps.iter().map(|(n, e)| {
                let e = wide_expr(e.clone());
                quote!(let #n = #e;)
            });
            let outs = parts.kernel.outputs.iter().map(|(f, e)| {
                let e = wide_expr(e.clone());
                quote!(#f: #e)
            });
            let sdoc = doc(&format!(
                "Lane-wise `{}::sandwich` of `{}`: the same kernel.\n\n{}",
                tv.name, tx.name, parts.doc
            ));
            items.extend(quote! {
                impl<W: Lane> super::Sandwich<#xn<W>> for #vn<W> {
                    type Output = #on<W>;
                    #sdoc
                    #[inline(always)]
                    fn sandwich(&self, b: #xn<W>) -> #on<W> {
                        let a = self;
                        #(#lets)*
                        #on { #(#outs,)* }
                    }
                }
            });
        }
        let mdoc = doc(
            "Wide (structure-of-arrays) twins of the versor types and of the types they act on: \
             each field is a [`Lane`](wide::Lane) value `W` whose lane `i` belongs to operand `i`, so one \
             product or sandwich computes `W::LANES` of them. The expressions are those of the \
             scalar types, constants splatted; `W = f64` is the scalar type itself.",
        );
        self.out.extend(quote! {
            #mdoc
            pub mod wide {
                pub use #rt::runtime::wide_lanes::{Lane, F32x8, F64x4};
                #items
            }
        });
        Ok(())
    }

    /// The struct of a wide twin and its lane conversions, reverse, sum, difference and scale.
    fn wide_type(&self, t: &TypeDef) -> TokenStream {
        let name = ident(&t.name);
        let fields: Vec<_> = t.fields.iter().map(|f| ident(&f.name)).collect();
        let fdocs = t
            .fields
            .iter()
            .map(|f| doc(&format!("Coefficients of `{}`, one per lane.", f.name)));
        let sdoc = doc(&format!(
            "`W::LANES` values of [`super::{0}`], field by field: lane `i` of each field is \
             operand `i`.",
            t.name
        ));
        let rev = {
            let names = Names::new(t, None);
            let m = SymMv::of_type(t, 0).rev();
            let exprs = t.fields.iter().map(|f| {
                let mut p = Poly::default();
                p.add_scaled(&m.get(f.bitmap), Rational::int(f.sign as i64));
                wide_expr(names.poly(&p))
            });
            quote!(let a = self; #name { #(#fields: #exprs,)* })
        };
        quote! {
            #sdoc
            #[repr(C)]
            #[derive(Clone, Copy, Debug, PartialEq, Default)]
            pub struct #name<W> {
                #(#fdocs pub #fields: W,)*
            }
            impl<W: Lane<Scalar = super::Scalar>> #name<W> {
                /// Every lane `v`.
                #[inline(always)]
                #[must_use]
                pub fn splat(v: super::#name) -> Self {
                    #name { #(#fields: W::splat(v.#fields),)* }
                }
                /// Lane `i` from `v[i]` (the first `W::LANES` values of `v`; panics when `v` is
                /// shorter).
                #[inline(always)]
                #[must_use]
                pub fn gather(v: &[super::#name]) -> Self {
                    let v = &v[..W::LANES];
                    #name { #(#fields: W::from_fn(|i| v[i].#fields),)* }
                }
                /// Lane `i` from `f(i)` (a gather: `f` is called once per field and lane, and
                /// inlined, so only the fields are loaded).
                #[inline(always)]
                #[must_use]
                pub fn from_fn(f: impl Fn(usize) -> super::#name) -> Self {
                    #name { #(#fields: W::from_fn(|i| f(i).#fields),)* }
                }
                /// Lane `i` as a scalar value.
                #[inline(always)]
                #[must_use]
                pub fn lane(&self, i: usize) -> super::#name {
                    super::#name { #(#fields: self.#fields.lane(i),)* }
                }
            }
            impl<W: Lane> #name<W> {
                /// Lane-wise reverse.
                #[inline(always)]
                #[must_use]
                pub fn rev(self) -> Self { #rev }
                /// Every field times `w`, lane by lane.
                #[inline(always)]
                #[must_use]
                pub fn scale(self, w: W) -> Self {
                    #name { #(#fields: self.#fields * w,)* }
                }
            }
            impl<W: Lane> ::core::ops::Add for #name<W> {
                type Output = Self;
                #[inline(always)]
                fn add(self, b: Self) -> Self { #name { #(#fields: self.#fields + b.#fields,)* } }
            }
            impl<W: Lane> ::core::ops::Sub for #name<W> {
                type Output = Self;
                #[inline(always)]
                fn sub(self, b: Self) -> Self { #name { #(#fields: self.#fields - b.#fields,)* } }
            }
        }
    }

    /// The geometric product of two twins, when its result is a twin too.
    fn wide_product(&mut self, ai: usize, bi: usize, kept: &[usize]) -> TokenStream {
        let spec = self.spec;
        let (ta, tb) = (&spec.types[ai], &spec.types[bi]);
        if !(ta.versor && tb.versor) {
            return TokenStream::new();
        }
        let m = self.apply(
            Op::Geometric,
            &SymMv::of_type(ta, 0),
            &SymMv::of_type(tb, 1),
        );
        let OutType::Type(oi) = self.infer_versor_product(&m) else {
            return TokenStream::new();
        };
        if !kept.contains(&oi) {
            return TokenStream::new();
        }
        let to = &spec.types[oi];
        let names = Names::new(ta, Some(tb));
        let exprs: Vec<TokenStream> = to
            .fields
            .iter()
            .map(|f| {
                let mut p = Poly::default();
                p.add_scaled(&m.get(f.bitmap), Rational::int(f.sign as i64));
                wide_expr(names.poly(&p))
            })
            .collect();
        let fields = to.fields.iter().map(|f| ident(&f.name));
        let (an, bn, on) = (ident(&ta.name), ident(&tb.name), ident(&to.name));
        let pdoc = doc(&format!(
            "Lane-wise geometric product `{} * {}`, the expressions of the scalar product.",
            ta.name, tb.name
        ));
        quote! {
            impl<W: Lane> ::core::ops::Mul<#bn<W>> for #an<W> {
                type Output = #on<W>;
                #pdoc
                #[inline(always)]
                fn mul(self, b: #bn<W>) -> #on<W> {
                    let a = self;
                    #on { #(#fields: #exprs,)* }
                }
            }
        }
    }
}
