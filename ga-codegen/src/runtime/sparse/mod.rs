//! The sparse generic reference for large algebras: multivectors that hold only the blades
//! present, and blade products computed one pair at a time (never the `2^n x 2^n` table).
//!
//! - [`blades`]: exact products of basis blades by a lazy change to an orthogonal basis
//!   ([`BladeProducts`](blades::BladeProducts)), in any metric, null bases included;
//! - [`multivector`]: [`SparseAlgebra`](multivector::SparseAlgebra) (the `f64` products,
//!   memoised per blade pair) and [`SparseMultivector`](multivector::SparseMultivector),
//!   with the products and unary operations of the dense
//!   [`Multivector`](crate::runtime::multivector::Multivector), checked against it on small
//!   algebras.

pub mod blades;
pub mod multivector;
