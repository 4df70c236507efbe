//! Items for a module that is a library's public API ([`super::EmitOptions::library`]):
//! `serde` and `bytemuck` impls behind cargo features of those names, and a `types` module
//! listing every generated type for re-export. Written here from the spec, so adding a type to
//! the spec cannot leave a hand-written list stale. A crate that includes such a module should
//! declare the features `serde` and `bytemuck` (optional dependencies of those names); one that
//! does not gets neither impl, and no warning about the unknown `cfg` values.

use super::render::{ident, int};
use super::{Gen, Op};
use quote::quote;

/// serde implements `Serialize`/`Deserialize` for arrays up to this length.
const SERDE_MAX_LEN: usize = 32;

impl Gen<'_> {
    /// The feature-gated impls of every type, then the `types` module.
    pub(super) fn library_items(&mut self) {
        let s = self.s.clone();
        let mut gated = proc_macro2::TokenStream::new();
        for t in &self.spec.types {
            let (name, n) = (ident(&t.name), int(t.fields.len()));
            if t.fields.len() <= SERDE_MAX_LEN {
                gated.extend(quote! {
                    #[cfg(feature = "serde")]
                    impl ::serde::Serialize for #name {
                        fn serialize<Z: ::serde::Serializer>(&self, z: Z) -> ::core::result::Result<Z::Ok, Z::Error> {
                            ::serde::Serialize::serialize(&self.to_array(), z)
                        }
                    }
                    #[cfg(feature = "serde")]
                    impl<'de> ::serde::Deserialize<'de> for #name {
                        fn deserialize<D: ::serde::Deserializer<'de>>(d: D) -> ::core::result::Result<Self, D::Error> {
                            <[#s; #n] as ::serde::Deserialize<'de>>::deserialize(d).map(Self::from_array)
                        }
                    }
                });
            }
            // `#[repr(C)]`, `Copy`, every field the same float type: no padding (checked by
            // the assertion), every bit pattern valid, zero a valid value.
            gated.extend(quote! {
                #[cfg(feature = "bytemuck")]
                unsafe impl ::bytemuck::Zeroable for #name {}
                #[cfg(feature = "bytemuck")]
                unsafe impl ::bytemuck::Pod for #name {}
                #[cfg(feature = "bytemuck")]
                const _: () = assert!(::core::mem::size_of::<#name>() == #name::LEN * ::core::mem::size_of::<Scalar>());
            });
        }
        // In one anonymous const, whose `allow` covers the `cfg`s inside: a crate that
        // includes the module without declaring the features `serde` and `bytemuck` gets no
        // `unexpected_cfgs` warning per impl (an `allow` on the gated item itself does not
        // reach its own `cfg`), just no impls. Trait impls in a const block are global.
        self.out.extend(quote! {
            #[allow(unexpected_cfgs)]
            const _: () = { #gated };
        });
        let types = self.spec.types.iter().map(|t| ident(&t.name));
        let matrices = self
            .ops
            .iter()
            .filter(|o| o.op == Op::Sandwich)
            .map(|o| ident(&format!("{}{}Matrix", o.left, o.right)));
        self.out.extend(quote! {
            /// Every type generated from the spec (with the matrix forms of its sandwiches and
            /// the `Sandwich` trait), for a glob re-export.
            pub mod types {
                pub use super::{#(#types,)* #(#matrices,)* Sandwich};
            }
        });
    }
}
