//! The module's types and products: result types of symbolic products (`infer.rs`), one struct
//! per declared type with its methods (`types.rs`), binary operators and conversions
//! (`operators.rs`), the named products of ga-benchmark's set between blade types
//! (`named.rs`), the outer product and left contraction with the scalar and the scalar's dual
//! (`scalar_ops.rs`), and fused sandwiches with their matrix form (`sandwich.rs`).

pub(crate) mod infer;
mod matrix;
mod matrix_form;
mod named;
mod operators;
pub(crate) mod sandwich;
pub(crate) mod scalar_ops;
mod types;
