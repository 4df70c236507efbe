//! The generator (the default `codegen` feature): spec -> symbolic products -> Rust source.
//!
//! - [`spec`]: a TOML spec (or the macro's tokens) -> a validated `Spec`, in phases;
//! - `symbolic`: polynomial coefficients in the operands' fields, expanded in the user's basis;
//! - `unit_versor`, `factor`, `verify`: sandwiches of unit versors reduced modulo `a ~a = 1`,
//!   fused sandwiches factored into short straight-line programs, numeric checks at generation
//!   time of what the symbolic engine cannot prove;
//! - [`emit`]: the Rust and WGSL emitter;
//! - [`checks`]: the check harness comparing every generated function with the generic
//!   `Multivector`.

pub mod checks;
pub mod emit;
pub(crate) mod factor;
pub(crate) mod matrix_units;
pub mod spec;
pub(crate) mod symbolic;
pub(crate) mod unit_versor;
pub(crate) mod verify;
