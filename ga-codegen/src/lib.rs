//! # ga-codegen
//!
//! A Gaigen-style geometric algebra generator. From an algebra spec (basis names, any
//! symmetric metric including null and degenerate ones, and a list of specialised types) it
//! expands every product symbolically with exact coefficients, drops every term that is
//! identically zero, and emits `#[repr(C)]` Rust types with straight-line products.
//!
//! The crate has two parts, one folder each:
//!
//! - [`runtime`]: what generated code links against, always built: the algebra and its exact
//!   metric ([`runtime::algebra`], [`runtime::metric`], [`runtime::rational`],
//!   [`runtime::blade`]), the slow generic [`runtime::multivector::Multivector`] that every
//!   generated function is tested against, and the lane types of the generated lane forms
//!   ([`runtime::f64x2`], [`runtime::f32x4`], [`runtime::wide_lanes`]).
//! - `generator` (the default `codegen` feature): spec parsing and validation
//!   (`generator::spec`), the symbolic engine, the Rust and WGSL emitter (`generator::emit`)
//!   and the check harness (`generator::checks`).
//!
//! Every item has one path, in its part, except this small prelude at the root: the front door
//! of each part, [`Algebra`] and [`Multivector`] (the two runtime items non-lane generated code
//! names, as `{runtime}::Algebra` and `{runtime}::Multivector`: a module passed as the
//! generator's `runtime` path must provide them), and, with `codegen`, `Spec`, `SpecError`,
//! `generate`, `generate_wgsl`, `EmitOptions`, `ScalarType` and `GenError`. Lane forms name
//! their lane types by their one path under `{runtime}::runtime`.
//!
//! ## Using generated code
//!
//! A module written by the `ga-codegen` binary (`ga-codegen SPEC.toml -o src/my_algebra.rs`)
//! or expanded by `ga-macros`' `algebra!` names this crate as `::ga_codegen`, so the crate that
//! compiles it depends on the runtime part alone:
//!
//! ```toml
//! [dependencies]
//! ga-codegen = { version = "0.1", default-features = false }
//! ```
//!
//! Declare the file as a public module of a library (`pub mod my_algebra;`); `--library`
//! output also wants the features `serde` and `bytemuck` declared (optional dependencies of
//! those names), and without them has neither impl. The file's header is the command that
//! regenerates it, every flag included. `tests/cli_flow.rs` does all of this in a fresh crate.

#![warn(missing_docs)]
// Matrices and blade tables are indexed by position on purpose: the index loops read like the
// formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod runtime;

#[cfg(feature = "codegen")]
pub mod generator;

// The prelude (see the crate docs): the only items with a second path.
pub use runtime::algebra::Algebra;
pub use runtime::multivector::Multivector;

#[cfg(feature = "codegen")]
pub use generator::emit::{generate, generate_wgsl, EmitOptions, GenError, ScalarType};
#[cfg(feature = "codegen")]
pub use generator::spec::{Spec, SpecError};
