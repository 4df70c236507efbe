//! The runtime: what generated code links against, built with or without the `codegen`
//! feature.
//!
//! - [`algebra`], [`metric`], [`rational`], [`blade`]: an algebra at run time, its exact metric
//!   and the blades of its basis; [`ident`]: which basis names can become Rust identifiers;
//! - [`multivector`]: the slow generic dense [`Multivector`](multivector::Multivector), the
//!   reference every generated function is checked against;
//! - [`sparse`]: the sparse generic reference of large algebras (blades present only, blade
//!   products one pair at a time);
//! - [`derived`]: products of ga-benchmark's set built from the multivector's own (dot,
//!   Hestenes inner, commutator, undual, regressive, inverse geometric product), the
//!   reference of the generated functions of those names;
//! - [`f64x2`]: two `f64` lanes ([`F64x2`](f64x2::F64x2)), for generated products in
//!   paired-lane form;
//! - [`f32x4`]: four `f32` lanes ([`F32x4`](f32x4::F32x4)), for generated f32 products in
//!   4-lane form;
//! - [`trig`]: inlined `f32` sine, cosine and arctangent (evaluated in `f64`) for the
//!   generated `exp` and `log`;
//! - [`wide_lanes`]: the [`Lane`](wide_lanes::Lane) types of the generated structure-of-arrays
//!   (`wide`) twins ([`F64x4`](wide_lanes::F64x4), [`F32x8`](wide_lanes::F32x8), or the scalar).

pub mod algebra;
pub mod blade;
pub mod derived;
pub mod f32x4;
pub mod f64x2;
pub mod ident;
pub mod metric;
pub mod multivector;
pub mod rational;
pub mod sparse;
pub mod trig;
pub mod wide_lanes;
