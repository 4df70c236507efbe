//! Binary operators between declared types (`*`, `^`, `|`, `+`, `-`) and conversions into a
//! type that holds every blade of another.

use super::infer::terms;
use crate::generator::emit::render::{doc, ident, Names};
use crate::generator::emit::{Gen, Op, OpSummary, OutType, ScalarType};
use crate::generator::symbolic::{Product, SymMv};
use crate::runtime::rational::Rational;
use quote::quote;

impl Op {
    /// The `core::ops` trait and its method, for the five operators.
    fn trait_method(self) -> Option<(&'static str, &'static str)> {
        Some(match self {
            Op::Geometric => ("Mul", "mul"),
            Op::Outer => ("BitXor", "bitxor"),
            Op::LeftContraction => ("BitOr", "bitor"),
            Op::Add => ("Add", "add"),
            Op::Sub => ("Sub", "sub"),
            _ => return None,
        })
    }

    /// The doc of the operator's method (for the five operators).
    fn doc(self) -> &'static str {
        match self {
            Op::Geometric => "Geometric product.",
            Op::Outer => "Outer product.",
            Op::LeftContraction => "Left contraction.",
            Op::Add => "Sum.",
            Op::Sub => "Difference.",
            _ => unreachable!("not an operator"),
        }
    }
}

impl Gen<'_> {
    /// The symbolic result of `a op b`.
    pub(crate) fn apply(&mut self, op: Op, a: &SymMv, b: &SymMv) -> SymMv {
        match op {
            Op::Geometric => self.table.product(a, b, Product::Geometric),
            Op::Outer => self.table.product(a, b, Product::Outer),
            Op::LeftContraction => self.table.product(a, b, Product::Left),
            Op::Add => a.add_scaled(b, Rational::ONE),
            Op::Sub => a.add_scaled(b, -Rational::ONE),
            _ => unreachable!("not an operator"),
        }
    }

    /// Every operator between types `ai` and `bi` that is not identically zero, and the
    /// conversion from `ai` into `bi` when `bi` holds every blade of `ai`.
    pub(crate) fn binary(&mut self, ai: usize, bi: usize) {
        let spec = self.spec;
        let (ta, tb) = (&spec.types[ai], &spec.types[bi]);
        let names = Names::new(ta, Some(tb));
        let a = SymMv::of_type(ta, 0);
        let b = SymMv::of_type(tb, 1);
        let (an, bn) = (ident(&ta.name), ident(&tb.name));
        for op in Op::OPERATORS {
            let m = self.apply(op, &a, &b);
            let o = self.infer_op(&m, op, (ta, tb));
            if o == OutType::Zero {
                self.zero_ops += 1;
                continue;
            }
            if self.skip_unfit(o, &m, &format!("{} {op} {}", ta.name, tb.name)) {
                continue;
            }
            let (tr, method) = op.trait_method().expect("an operator");
            let (tr, method) = (ident(tr), ident(method));
            let on = self.out_type(o);
            // A type closed under the product with a 2 x 2 matrix factor: the matrix form.
            let blocks = match o {
                OutType::Type(ti) if op == Op::Geometric && ai == bi && ti == ai => {
                    self.build_matrix_form(ti, &m)
                }
                _ => None,
            };
            let paired = match o {
                OutType::Type(ti) if op == Op::Geometric && blocks.is_none() => {
                    self.build_paired(ti, &m, ta, tb)
                }
                _ => None,
            };
            // f32 products between versor types in 4-lane form (see `lanes/quad.rs`).
            let quad = match o {
                OutType::Type(ti)
                    if paired.is_none()
                        && blocks.is_none()
                        && op == Op::Geometric
                        && self.scalar == ScalarType::F32 =>
                {
                    crate::generator::emit::lanes::quad::build(
                        ta,
                        tb,
                        &spec.types[ti],
                        &m,
                        &self.rt,
                    )
                }
                _ => None,
            };
            let lane_form = if let Some((_, form, _)) = &blocks {
                Some(form.as_str())
            } else if paired.is_some() {
                Some("paired-lane form: two output fields per `F64x2`")
            } else if quad.is_some() {
                Some("4-lane form: four output fields per `F32x4`")
            } else {
                None
            };
            let fdoc = doc(&match lane_form {
                Some(form) => format!(
                    "Geometric product ({form}).\n\n\
                     Scalar expansion (`a` the left operand, `b` the right one):\n{}",
                    self.expansion(o, &m, &names)
                ),
                None => op.doc().to_string(),
            });
            let matrix_form = blocks.as_ref().map(|b| b.2);
            let paired = blocks.map(|b| b.0).or(paired).or(quad);
            let body = paired.unwrap_or_else(|| self.build(o, &m, &names));
            // `^` and `|` are products written with `*`: say that this is meant.
            let allow = matches!(op, Op::Outer | Op::LeftContraction)
                .then(|| quote!(#[allow(clippy::suspicious_arithmetic_impl)]));
            self.out.extend(quote! {
                impl ::core::ops::#tr<#bn> for #an { type Output = #on; #fdoc #[inline] #allow fn #method(self, b: #bn) -> #on { let a = self; #body } }
            });
            self.ops.push(OpSummary {
                op,
                left: ta.name.clone(),
                right: tb.name.clone(),
                output: self.out_name(o),
                terms: terms(&m),
                matrix_form,
            });
        }
        // Conversion into a type that holds every blade of this one.
        if ai != bi && tb.constants.is_empty() && ta.blades().all(|x| tb.field(x).is_some()) {
            let names = Names::new(ta, None);
            self.ops.push(OpSummary {
                op: Op::From,
                left: ta.name.clone(),
                right: tb.name.clone(),
                output: tb.name.clone(),
                terms: 0,
                matrix_form: None,
            });
            let body = self.build(OutType::Type(bi), &a, &names);
            self.out.extend(quote! {
                impl ::core::convert::From<#an> for #bn { #[inline] fn from(a: #an) -> #bn { #body } }
            });
        }
    }
}
