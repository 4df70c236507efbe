//! # ga-macros
//!
//! [`algebra!`] declares a geometric algebra inline and expands to the specialised types that
//! the `ga-codegen` binary generates for the same spec: the expansion *is* the tokens of
//! `ga_codegen::generate`, which the binary formats. This crate is a thin front end:
//! tokens -> spec -> `ga-codegen` -> tokens.
//!
//! ## Dependencies
//!
//! The generated items name the runtime crate as `::ga_codegen` (for the reference
//! `Multivector` and `Algebra`), so a crate that calls `algebra!` depends on both:
//!
//! ```toml
//! [dependencies]
//! ga-macros = { path = "../ga-macros" }
//! # The runtime only: the generator itself is not needed at run time.
//! ga-codegen = { path = "../ga-codegen", default-features = false }
//! ```
//!
//! If the runtime is reachable under another path (re-exported by another crate), say so with
//! `runtime = some::path`.
//!
//! `examples/pga.rs` (G(3,0,1): points, planes, rotors, translators, motors) and
//! `examples/sta.rs` (G(1,3): boosts and rotations) are runnable checks to start from
//! (`cargo run -p ga-macros --example pga`); they also state the sign conventions of those
//! algebras.
//!
//! ## Use
//!
//! The macro expands to items (constants, structs, impls, the `Sandwich` trait), as the binary
//! writes a module's content, so wrap it in a module of its own. The generated code is
//! documented and clippy-clean, so the module needs no `allow`:
//!
//! ```
//! mod g3 {
//!     // Relative to this crate's Cargo.toml: the workspace's `algebras/g3.toml`.
//!     ga_macros::algebra!(path = "../algebras/g3.toml");
//! }
//!
//! mod g2 {
//!     ga_macros::algebra! {
//!         //! The Euclidean plane G(2,0,0).
//!         name = "g2";
//!         basis = [e1, e2];
//!         diagonal = [1, 1];
//!         type Vector { blades = [e1, e2] }
//!         /// A rotor: a unit complex number in disguise.
//!         type Rotor { blades = [s, e12], versor = true, unit = true }
//!         sandwich Rotor(Vector) -> Vector;
//!     }
//! }
//!
//! use g2::Sandwich;
//! let r = g2::Rotor::new(0.6, 0.8); // unit: 0.6^2 + 0.8^2 = 1
//! let x = g2::Vector::new(1.0, 0.0);
//! let y: g2::Vector = r.sandwich(x);
//! // The generated sandwich agrees with the slow generic multivector.
//! let slow = r.to_multivector().gp(&x.to_multivector()).gp(&r.rev().to_multivector());
//! assert!(y.to_multivector().max_diff(&slow) < 1e-12);
//!
//! let q = g3::Rotor::new(1.0, 0.0, 0.0, 0.0);
//! assert_eq!((q * g3::Vector::new(1.0, 2.0, 3.0)).to_array(), [1.0, 2.0, 3.0, 0.0]);
//! ```
//!
//! ## The two input forms
//!
//! **From a file**: `algebra!(path = "spec.toml")`, the path relative to the directory of the
//! calling crate's `Cargo.toml` (`CARGO_MANIFEST_DIR`), in the TOML format of
//! `ga_codegen::generator::spec`. `scalar = f32` and `runtime = path` may follow. The file is tracked
//! (the expansion adds `const _: &[u8] = include_bytes!(..)`), so editing it re-expands.
//!
//! **Inline**: the fields of the TOML spec written as tokens. Top-level entries end with `;`
//! (a `,` works too; after a `type { .. }` item neither is needed):
//!
//! ```text
//! input     := inner-doc? entry*
//! inner-doc := //! ...                              (the algebra's doc, as `doc = ".."`)
//! entry     := name     = "string"      ;           (used in generated docs; default "algebra")
//!            | doc      = "string"      ;
//!            | basis    = [ Name, .. ]  ;           (`e` + suffix: e1, eo, ei)
//!            | metric   = [ [Number, ..], .. ] ;    (full symmetric matrix), or
//!            | diagonal = [ Number, .. ] ;          (squares of an orthogonal basis)
//!            | scalar   = f64 | f32     ;           (default f64)
//!            | runtime  = path          ;           (default ::ga_codegen)
//!            | exp_log  = required | optional ;     (default optional: see below)
//!            | path     = "file.toml"   ;           (the file form)
//!            | ///doc* type TypeName { field, .. }
//!            | sandwich Versor(Operand) -> Output ; (`-> Output` optional: inferred)
//! field     := blades    = [ Name, .. ]             (`s` is the scalar; any order: e31 = -e13)
//!            | constants = { Name = Number, .. }    (fixed coefficients, not stored)
//!            | versor    = true | false             (gets `sandwich`)
//!            | unit      = true | false             (assumed normalised: x ~x = 1)
//!            | doc       = "string"                 (or `///` comments before `type`)
//! Name      := identifier | "string"
//! Number    := -? integer-or-float literal
//! ```
//!
//! Every key may be given once; `metric` and `diagonal` exclude each other. With
//! `path = ...` only `scalar`, `runtime` and `exp_log` may be added.
//!
//! Bivector and even versor types get closed-form `exp`, `log`, `sqrt` and `normalize` (the
//! `Exp`, `Log` and `EvenVersor` traits, as from the binary) wherever their span allows it (at
//! most five basis vectors, real squares); `exp_log = required` makes a type that cannot have
//! them a compile error at its name instead of an omission.
//!
//! ## Errors
//!
//! Spec errors are compile errors at the offending token: an unknown or repeated blade at the
//! blade name, a bad metric at its row or entry, a duplicate type at its second declaration,
//! a constant on a blade the type does not list at that constant, an unknown type at the
//! sandwich naming it. Messages name the type and the blade, as the binary's do:
//!
//! ```text
//! error: type `Vector`: `e4`: unknown blade: not made of the basis names
//!   |
//!   |     type Vector { blades = [e1, e2, e4] }
//!   |                                     ^^
//! ```
//!
//! For the file form, errors point at the path literal and name the file.

#![warn(missing_docs)]

mod expand;
mod grammar;
mod locate;
#[cfg(test)]
mod tests;

use proc_macro::TokenStream;

/// Declare a geometric algebra and expand to its specialised types, exactly as the
/// `ga-codegen` binary generates them for the same spec.
///
/// Either read a TOML spec file (relative to the calling crate's `Cargo.toml`):
///
/// ```
/// mod g3_f32 {
///     ga_macros::algebra!(path = "../algebras/g3.toml", scalar = f32);
/// }
/// let v: g3_f32::Vector = g3_f32::Vector::new(1.0, 2.0, 3.0);
/// assert_eq!(v.norm_squared(), 14.0f32);
/// ```
///
/// or write the spec inline:
///
/// ```
/// mod g3 {
///     ga_macros::algebra! {
///         name = "g3";
///         basis = [e1, e2, e3];
///         diagonal = [1, 1, 1];            // or metric = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
///         type Vector { blades = [e1, e2, e3] }
///         type Rotor { blades = [s, e12, e13, e23], versor = true, unit = true }
///         sandwich Rotor(Vector) -> Vector;
///     }
/// }
/// use g3::Sandwich;
/// // A quarter turn in the e1e2 plane: cos(pi/4) - sin(pi/4) e12.
/// let h = std::f64::consts::FRAC_1_SQRT_2;
/// let r = g3::Rotor::new(h, -h, 0.0, 0.0);
/// let y: g3::Vector = r.sandwich(g3::Vector::new(1.0, 0.0, 0.0));
/// assert!((y.e2.abs() - 1.0).abs() < 1e-12 && y.e1.abs() < 1e-12);
/// ```
///
/// The grammar, the options and the errors are described in the [crate] documentation.
/// The caller needs `ga-codegen` as a dependency (`default-features = false` is enough): the
/// generated code names it as `::ga_codegen` unless `runtime = path` says otherwise.
#[proc_macro]
pub fn algebra(input: TokenStream) -> TokenStream {
    expand::expand(input.into())
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}
