//! The module's preamble (`BASIS`, `METRIC`, `algebra()`, the `Sandwich` trait, `Scalar`),
//! the paths of the generic reference the generated code converts to (the dense `Multivector`,
//! or the sparse one above 8 basis vectors: [`Spec::sparse_reference`]) and `SKIPPED`, the list of
//! what was not emitted for want of a type holding its result.

use super::render::{self, int, lit};
use super::Gen;
#[cfg(doc)]
use crate::generator::spec::Spec;
use crate::generator::spec::MAX_GENERAL_DIMENSION;
use proc_macro2::TokenStream;
use quote::quote;

impl Gen<'_> {
    /// Constants, the generic algebra, the `Sandwich` trait and the `Scalar` alias.
    pub(super) fn header(&mut self) {
        let spec = self.spec;
        let n = spec.metric.dim();
        let s = &self.s;
        let basis = spec
            .metric
            .names()
            .iter()
            .map(|b| proc_macro2::Literal::string(b));
        let rows = (0..n).map(|i| {
            let row = (0..n).map(|j| lit(spec.metric.get(i, j)));
            quote!([#(#row),*])
        });
        let n = int(n);
        let algebra_doc = render::doc(&if spec.sparse_reference() {
            format!(
                "The generic algebra of this module, for the slow sparse reference \
                 [`{}::runtime::sparse::multivector::SparseMultivector`] (the dense \
                 `Multivector`'s table of `2^n x 2^n` blade products is too large here).",
                self.runtime
            )
        } else {
            format!(
                "The generic algebra of this module, for the slow reference [`{}::Multivector`].",
                self.runtime
            )
        });
        let alg = self.algebra_path();
        self.out.extend(quote! {
            /// Names of the basis vectors, in order (blade bitmaps use this order).
            pub const BASIS: [&str; #n] = [#(#basis),*];

            /// The metric: `METRIC[i][j]` is the inner product of basis vectors `i` and `j`.
            pub const METRIC: [[f64; #n]; #n] = [#(#rows),*];

            #algebra_doc
            pub fn algebra() -> ::std::sync::Arc<#alg> {
                static ALGEBRA: ::std::sync::OnceLock<::std::sync::Arc<#alg>> = ::std::sync::OnceLock::new();
                ALGEBRA
                    .get_or_init(|| {
                        let rows: ::std::vec::Vec<::std::vec::Vec<f64>> = METRIC.iter().map(|r| r.to_vec()).collect();
                        #alg::from_metric(&BASIS, &rows).expect("the metric was validated when the code was generated")
                    })
                    .clone()
            }

            /// The sandwich product `self * x * ~self` of a versor with `x`, fused into one expression.
            pub trait Sandwich<X> {
                /// The type of the result.
                type Output;
                /// `self * x * ~self`.
                fn sandwich(&self, x: X) -> Self::Output;
            }

            /// The scalar type of this module.
            pub type Scalar = #s;
        });
    }

    /// The generic algebra's type in the generated code: the dense `{runtime}::Algebra`, or
    /// the sparse one for a spec with [`Spec::sparse_reference`].
    fn algebra_path(&self) -> TokenStream {
        let rt = &self.rt;
        if self.spec.sparse_reference() {
            quote!(#rt::runtime::sparse::multivector::SparseAlgebra)
        } else {
            quote!(#rt::Algebra)
        }
    }

    /// The generic multivector's type in the generated code (see [`Gen::algebra_path`]).
    pub(crate) fn multivector_path(&self) -> TokenStream {
        let rt = &self.rt;
        if self.spec.sparse_reference() {
            quote!(#rt::runtime::sparse::multivector::SparseMultivector)
        } else {
            quote!(#rt::Multivector)
        }
    }

    /// `SKIPPED`, the list of what was not emitted because no declared type holds its
    /// result; nothing when everything was emitted.
    pub(super) fn skipped_list(&mut self) {
        if self.skipped.is_empty() {
            return;
        }
        let n = int(self.skipped.len());
        let items = self.skipped.iter().map(|x| proc_macro2::Literal::string(x));
        let sdoc = render::doc(&format!(
            "What was not emitted because no declared type of `{}` holds its result (the \
             algebra has more than {} basis vectors, so no general multivector is added): \
             each product, method or operator with the grades of its result. Declare a type \
             holding those blades to get one.",
            render::one_line(&self.spec.name),
            MAX_GENERAL_DIMENSION,
        ));
        self.out.extend(quote! {
            #sdoc
            pub const SKIPPED: [&str; #n] = [#(#items),*];
        });
    }
}
