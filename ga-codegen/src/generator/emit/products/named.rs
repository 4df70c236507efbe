//! Named products: ga-benchmark's binary operations that are not operators (right
//! contraction, scalar, dot, Hestenes inner, commutator, regressive and inverse geometric
//! products). Each is a trait of the same name, emitted once, with one impl per pair of
//! operands whose product is not identically zero; result types are inferred as for the
//! operators.
//!
//! The operands are the declared types of one grade (every stored and constant blade of the
//! same grade: the blades ga-benchmark times, e.g. CGA's `Vector`, `Point`, `Bivector`,
//! `Trivector`, `Quadvector`, `Pseudoscalar`) and the scalar type, on either side.

use super::infer::terms;
use crate::generator::emit::render::{doc, ident, Names};
use crate::generator::emit::{Gen, Op, OpSummary, OutType};
use crate::generator::symbolic::{Product, SymMv};
use crate::runtime::blade::grade;
use crate::runtime::rational::Rational;
use proc_macro2::TokenStream;
use quote::quote;

/// An operand of a named product.
#[derive(Clone, Copy, PartialEq)]
enum Operand {
    /// The scalar type (`f64` or `f32`).
    Scalar,
    /// A declared type of one grade.
    Type(usize),
}

impl Gen<'_> {
    /// The operands of the named products: the scalar, then every declared type whose stored
    /// and constant blades all have one grade, in spec order.
    fn named_operands(&self) -> Vec<Operand> {
        std::iter::once(Operand::Scalar)
            .chain(self.one_grade_types().into_iter().map(Operand::Type))
            .collect()
    }

    /// The declared types whose stored and constant blades all have one grade, in spec order
    /// (the operands of the named products besides the scalar).
    pub(crate) fn one_grade_types(&self) -> Vec<usize> {
        let one_grade = |t: &crate::generator::spec::TypeDef| {
            let mut grades = t
                .fields
                .iter()
                .map(|f| f.bitmap)
                .chain(t.constants.iter().map(|&(b, _)| b))
                .map(grade);
            let first = grades.next();
            first.is_some() && grades.all(|g| Some(g) == first)
        };
        (0..self.spec.types.len())
            .filter(|&t| one_grade(&self.spec.types[t]))
            .collect()
    }

    /// The symbolic value of an operand: operand `i` (0 left, 1 right) of a declared type, or
    /// the scalar variable `s`.
    fn operand_value(&self, o: Operand, i: u8) -> SymMv {
        match o {
            Operand::Scalar => SymMv::scalar_var(),
            Operand::Type(t) => SymMv::of_type(&self.spec.types[t], i),
        }
    }

    /// The symbolic result of a named product. The inverse geometric product is `a ~b r`,
    /// with the factor `r = 1 / <b ~b>_0` a variable of its own.
    fn named_value(&mut self, op: Op, a: &SymMv, b: &SymMv) -> SymMv {
        let t = &mut self.table;
        match op {
            Op::RightContraction => t.product(a, b, Product::Right),
            Op::ScalarProduct => t.product(a, b, Product::Scalar),
            Op::DotProduct => t.product(a, b, Product::Dot),
            Op::HestenesInnerProduct => t.product(a, b, Product::Hestenes),
            Op::CommutatorProduct => {
                let ab = t.product(a, b, Product::Geometric);
                let ba = t.product(b, a, Product::Geometric);
                SymMv::default()
                    .add_scaled(&ab, Rational::new(1, 2))
                    .add_scaled(&ba, Rational::new(-1, 2))
            }
            Op::RegressiveProduct => {
                let (da, db) = (self.dual(a), self.dual(b));
                let w = self.table.product(&da, &db, Product::Outer);
                self.undual(&w)
            }
            Op::InverseGeometricProduct => {
                let ab = t.product(a, &b.rev(), Product::Geometric);
                t.product(&ab, &SymMv::scalar_operand(3), Product::Geometric)
            }
            _ => unreachable!("not a named product"),
        }
    }

    /// The doc of a named product's trait: what it computes, with its formula.
    fn named_doc(&self, op: Op) -> String {
        match op {
            Op::RightContraction => "The right contraction `a ⌊ b`: for grade parts `a_i`, `b_j` with `i >= j`, the grade `i - j` part of `a_i b_j` (zero when `i < j`).".into(),
            Op::ScalarProduct => "The scalar product `<a b>_0`, the scalar part of the geometric product.".into(),
            Op::DotProduct => "The dot product (Dorst's; GATL's `dot`): `sum <a_i b_j>_|i - j|` over the grade parts `a_i`, `b_j`, scalars included.".into(),
            Op::HestenesInnerProduct => "The Hestenes inner product (GATL's `hip`): `sum <a_i b_j>_|i - j|` over the grade parts with `i, j > 0` (zero when either operand is a scalar).".into(),
            Op::CommutatorProduct => "The commutator product `(a b - b a) / 2`.".into(),
            Op::RegressiveProduct if self.degenerate() => "The regressive product `a ∨ b = undual(dual(a) ^ dual(b))`, `dual` the right complement and `undual` its inverse (the metric is degenerate): `e_A ∨ e_B = sign(A \\ C, B \\ C) e_C` with `C = A ∩ B` when `A ∪ B` is the whole basis, else 0 (`sign` that of reordering `e_(A \\ C) e_(B \\ C)`; GATL's `rp`).".into(),
            Op::RegressiveProduct => "The regressive product `a ∨ b = undual(dual(a) ^ dual(b)) = (a I^-1 ^ b I^-1) I`, with `dual(x) = x I^-1` and `undual(x) = x I` (`I` the outer product of the basis in order; `I^-1` exact). It reads no metric: on grades `ga`, `gb` it is GATL's complement form `rp` times `(-1)^((n - ga)(n - gb))`, `n` the dimension.".into(),
            Op::InverseGeometricProduct => "The inverse geometric product `a b^-1`, computed as `a ~b / <b ~b>_0`: `a b^-1` whenever `b ~b` is a non-zero scalar, as for every blade and versor (ga-benchmark's operands are blades). Not finite when `<b ~b>_0 = 0` (a null `b`), and not `a b^-1` when `b ~b` has other grades (a `b` that is neither a blade nor a versor).".into(),
            _ => unreachable!("not a named product"),
        }
    }

    /// The traits of the named products, then their impls for every pair of operands
    /// (`inverse_geometric_product` only by types without constants, as `inverse`).
    pub(crate) fn named_products(&mut self) {
        let s = self.s.clone();
        for op in Op::NAMED {
            let (tr, m) = (ident(op.trait_name().expect("named")), ident(op.symbol()));
            let tdoc = doc(&self.named_doc(op));
            let mdoc = doc(&format!("`{}`: see [`{tr}`].", op.symbol()));
            self.out.extend(quote! {
                #tdoc
                pub trait #tr<B> {
                    /// The type of the result.
                    type Output;
                    #mdoc
                    fn #m(self, b: B) -> Self::Output;
                }
            });
        }
        let operands = self.named_operands();
        for op in Op::NAMED {
            for &l in &operands {
                for &r in &operands {
                    let no_inverse = match r {
                        Operand::Scalar => false,
                        Operand::Type(t) => !self.spec.types[t].constants.is_empty(),
                    };
                    if (l, r) == (Operand::Scalar, Operand::Scalar)
                        || (op == Op::InverseGeometricProduct && no_inverse)
                    {
                        continue;
                    }
                    self.named_impl(op, l, r, &s);
                }
            }
        }
    }

    /// The impl of named product `op` between operands `l` and `r`, unless it is
    /// identically zero.
    fn named_impl(&mut self, op: Op, l: Operand, r: Operand, s: &TokenStream) {
        let spec = self.spec;
        let (a, b) = (self.operand_value(l, 0), self.operand_value(r, 1));
        let m = self.named_value(op, &a, &b);
        let o = self.infer(&m);
        if o == OutType::Zero {
            self.zero_ops += 1;
            return;
        }
        let name = |x: Operand| match x {
            Operand::Scalar => self.scalar.name().to_string(),
            Operand::Type(t) => spec.types[t].name.clone(),
        };
        let what = format!("{}.{}({})", name(l), op.symbol(), name(r));
        if self.skip_unfit(o, &m, &what) {
            return;
        }
        let ty = |x: Operand| match x {
            Operand::Scalar => (s.clone(), self.scalar.name().to_string()),
            Operand::Type(t) => {
                let id = ident(&spec.types[t].name);
                (quote!(#id), spec.types[t].name.clone())
            }
        };
        let ((ln, lname), (rn, rname)) = (ty(l), ty(r));
        // The scalar is the variable `s`; a type reads `a.field` / `b.field`.
        let (ta, tb) = match (l, r) {
            (Operand::Type(x), Operand::Type(y)) => (&spec.types[x], Some(&spec.types[y])),
            (Operand::Type(x), Operand::Scalar) => (&spec.types[x], None),
            (Operand::Scalar, Operand::Type(y)) => (&spec.types[y], Some(&spec.types[y])),
            (Operand::Scalar, Operand::Scalar) => unreachable!("skipped"),
        };
        let names = Names::new(ta, tb);
        let body = self.build(o, &m, &names);
        let mut lets = TokenStream::new();
        if l == Operand::Scalar {
            lets.extend(quote!(let s = self;));
        } else if names.reads_a() {
            lets.extend(quote!(let a = self;));
        }
        if r == Operand::Scalar {
            lets.extend(quote!(let s = b;));
        }
        if op == Op::InverseGeometricProduct {
            let nsq = self.named_value(Op::ScalarProduct, &b, &b.rev());
            let nsq = names.poly(&nsq.get(0));
            lets.extend(quote!(let r = 1.0 / (#nsq);));
        }
        let on = self.out_type(o);
        let (tr, method) = (ident(op.trait_name().expect("named")), ident(op.symbol()));
        let fdoc = doc(&format!("`{lname}.{}({rname})`.", op.symbol()));
        self.out.extend(quote! {
            impl #tr<#rn> for #ln { type Output = #on; #fdoc #[inline] fn #method(self, b: #rn) -> #on { #lets #body } }
        });
        self.ops.push(OpSummary {
            op,
            left: lname,
            right: rname,
            output: self.out_name(o),
            terms: terms(&m),
            matrix_form: None,
        });
    }
}
