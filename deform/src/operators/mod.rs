//! The operators on a mesh: Laplacians, mass matrices, prefactored sparse solves with
//! Dirichlet conditions, and harmonic fields and coordinates (section VIII of the first
//! paper).
//!
//! * [`laplacian`]: cotangent, mean-value and uniform Laplacians as `sprs::CsMat<f64>`;
//! * [`mass`]: barycentric and Voronoi mass matrices;
//! * [`solve`]: [`DirichletSolver`](solve::DirichletSolver), faer's sparse Cholesky with
//!   explicit scratch;
//! * [`harmonic`]: harmonic and biharmonic fields.
//!
//! **May use**: the mesh foundation ([`crate::mesh`]). **Must not use**: blend, deformers,
//! skinning, surgery, render, input, or the crate-level `Error`.

mod error;
pub mod harmonic;
pub mod laplacian;
pub mod mass;
mod pattern;
pub mod solve;

pub use error::{Result, SolveError};
