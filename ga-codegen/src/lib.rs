//! # ga-codegen
//!
//! A Gaigen-style geometric algebra generator. From an algebra spec (basis names, any
//! symmetric metric including null and degenerate ones, and a list of specialised types) it
//! expands every product symbolically with exact coefficients, drops every term that is
//! identically zero, and emits `#[repr(C)]` Rust types with straight-line products.
//!
//! It also holds the slow generic [`Multivector`] that every generated function is tested
//! against. The runtime part ([`Algebra`], [`Multivector`]) is always built; the generator
//! itself is behind the default `codegen` feature.

#![warn(missing_docs)]
// Matrices and blade tables are indexed by position on purpose: the index loops read like the
// formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod algebra;
pub mod blade;
pub mod ident;
pub mod lanes;
pub mod lanes4;
pub mod metric;
pub mod multivector;
pub mod rational;
pub mod wide;

pub use algebra::Algebra;
pub use metric::{Metric, MetricError};
pub use multivector::Multivector;
pub use rational::Rational;

#[cfg(feature = "codegen")]
pub mod spec;
#[cfg(feature = "codegen")]
pub mod symbolic;

#[cfg(feature = "codegen")]
pub use spec::{Spec, SpecError};
#[cfg(feature = "codegen")]
pub mod emit;
#[cfg(feature = "codegen")]
pub use emit::{generate, generate_wgsl, EmitOptions, GenError, Generated, Method, Op, ScalarType};
#[cfg(feature = "codegen")]
pub mod checks;
#[cfg(feature = "codegen")]
pub mod factor;
#[cfg(feature = "codegen")]
pub mod unit_versor;
#[cfg(feature = "codegen")]
pub mod verify;
