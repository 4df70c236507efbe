//! What ga-benchmark times on grade-0 operands that the operators between declared types and
//! the named products do not cover: the outer product and the left contraction with the scalar
//! on either side (`s ^ x`, `x ^ s`, `s | x`; `x | s` is zero unless `x` has grade 0), and the
//! dual and undual of the scalar (trait `ScalarDual`, as the scalar type has no inherent
//! methods of ours). The operands are the declared types of one grade, as for the named
//! products; every impl is checked against the generic multivector like the operators.

use super::infer::terms;
use crate::generator::emit::render::{doc, ident, Names};
use crate::generator::emit::{Gen, Op, OpSummary, OutType};
use crate::generator::symbolic::SymMv;
use quote::quote;

/// The name of the trait of the scalar's dual and undual.
pub(crate) const SCALAR_DUAL: &str = "ScalarDual";

impl Gen<'_> {
    /// `s ^ x`, `x ^ s`, `s | x` and `x | s` for every declared type `x` of one grade (those not
    /// identically zero), then [`Gen::scalar_duals`].
    pub(crate) fn grade_zero_operators(&mut self) {
        for t in self.one_grade_types() {
            for op in [Op::Outer, Op::LeftContraction] {
                for scalar_left in [true, false] {
                    self.scalar_operator(op, t, scalar_left);
                }
            }
        }
        self.scalar_duals();
    }

    /// One operator between the scalar and type `ti`, the scalar on the left when `scalar_left`.
    fn scalar_operator(&mut self, op: Op, ti: usize, scalar_left: bool) {
        let spec = self.spec;
        let t = &spec.types[ti];
        let (sv, tv) = (SymMv::scalar_var(), SymMv::of_type(t, 0));
        let m = if scalar_left {
            self.apply(op, &sv, &tv)
        } else {
            self.apply(op, &tv, &sv)
        };
        let o = self.infer(&m);
        if o == OutType::Zero {
            self.zero_ops += 1;
            return;
        }
        let sname = self.scalar.name().to_string();
        let (left, right) = if scalar_left {
            (sname.clone(), t.name.clone())
        } else {
            (t.name.clone(), sname.clone())
        };
        if self.skip_unfit(o, &m, &format!("{left} {op} {right}")) {
            return;
        }
        // The type's fields read as `a.field`, the scalar as `s`.
        let names = Names::new(t, None);
        let body = self.build(o, &m, &names);
        let (s, tn, on) = (self.s.clone(), ident(&t.name), self.out_type(o));
        let (tr, method) = match op {
            Op::Outer => (quote!(BitXor), quote!(bitxor)),
            _ => (quote!(BitOr), quote!(bitor)),
        };
        let fdoc = doc(&format!(
            "{} with the scalar: `{left} {op} {right}`.",
            if op == Op::Outer {
                "Outer product"
            } else {
                "Left contraction"
            }
        ));
        let (lt, rt, lets) = if scalar_left {
            (s.clone(), quote!(#tn), quote!(let (s, a) = (self, b);))
        } else {
            (quote!(#tn), s.clone(), quote!(let (a, s) = (self, b);))
        };
        self.out.extend(quote! {
            impl ::core::ops::#tr<#rt> for #lt {
                type Output = #on;
                #fdoc
                #[inline]
                #[allow(clippy::suspicious_arithmetic_impl)]
                fn #method(self, b: #rt) -> #on { #lets #body }
            }
        });
        self.ops.push(OpSummary {
            op,
            left,
            right,
            output: self.out_name(o),
            terms: terms(&m),
            matrix_form: None,
        });
    }

    /// The trait [`SCALAR_DUAL`] and its impl for the scalar type: `s.dual()` is `s I^-1` (the
    /// right complement in a degenerate metric) and `s.undual()` its inverse, as the types'
    /// `dual` and `undual`; not emitted when no declared type holds the pseudoscalar (above
    /// [`MAX_GENERAL_DIMENSION`](crate::generator::spec::MAX_GENERAL_DIMENSION) basis vectors).
    fn scalar_duals(&mut self) {
        let sv = SymMv::scalar_var();
        let (d, u) = (self.dual(&sv), self.undual(&sv));
        let (od, ou) = (self.infer(&d), self.infer(&u));
        let sname = self.scalar.name().to_string();
        if self.skip_unfit(od, &d, &format!("{sname}::dual"))
            | self.skip_unfit(ou, &u, &format!("{sname}::undual"))
        {
            return;
        }
        // A scalar reads no field; any declared type serves for the names.
        let names = Names::new(&self.spec.types[0], None);
        let (bd, bu) = (self.build(od, &d, &names), self.build(ou, &u, &names));
        let (s, tr) = (self.s.clone(), ident(SCALAR_DUAL));
        let (tod, tou) = (self.out_type(od), self.out_type(ou));
        let (ddoc, udoc) = (doc(self.dual_doc()), doc(self.undual_doc()));
        self.out.extend(quote! {
            /// The dual and undual of a scalar (a multiple of the pseudoscalar), as the types'
            /// `dual` and `undual`.
            pub trait #tr {
                /// The type of the dual.
                type Dual;
                /// The type of the undual.
                type Undual;
                #ddoc
                fn dual(self) -> Self::Dual;
                #udoc
                fn undual(self) -> Self::Undual;
            }
            impl #tr for #s {
                type Dual = #tod;
                type Undual = #tou;
                #[inline] fn dual(self) -> #tod { let s = self; #bd }
                #[inline] fn undual(self) -> #tou { let s = self; #bu }
            }
        });
        for m in [
            crate::generator::emit::Method::Dual,
            crate::generator::emit::Method::Undual,
        ] {
            self.methods.push((sname.clone(), m));
        }
    }
}
