//! Meshes, Laplacians, sparse solves, harmonic fields and the CGA mesh deformers of the two
//! papers, in layers; each folder may use only the layers below it (a unit test checks every
//! `crate::` path, see `ARCHITECTURE.md` at the repository root):
//!
//! | layer | what | may use | error |
//! |---|---|---|---|
//! | [`mesh`] | [`Mesh`], adjacency, [`validate()`]/[`clean()`], shapes, files ([`io`]) | - | [`MeshError`] |
//! | [`operators`] | Laplacians, mass matrices, [`DirichletSolver`], [`Harmonic`] fields | mesh | [`SolveError`] |
//! | [`blend`] | [`BlendMethod`], [`KeyWeights`], [`BoundBlend`], [`control`] points | mesh | [`KeyError`], [`BlendError`] |
//! | [`deformers`] | the [`Deformer`] shape; spline, B-spline + FABRIK, handles, ARAP, FFD, cages | mesh, operators, blend | [`DeformError`] |
//! | [`skinning`] | glTF and libigl rigs, animation, skinning by every blend method | mesh, operators, blend, deformers | [`skinning::SkinError`] |
//! | [`surgery`] | cut, tear and drill that stay animatable | mesh, skinning | [`surgery::SurgeryError`] |
//! | [`render`] | the PNG preview renderer | mesh | [`MeshError`] |
//! | [`input`] | motor JSON and selections, one format for every program command | mesh | [`input::InputError`] |
//!
//! Every layer's error converts into [`Error`] with `?`. Deformers bind once and pose many
//! times: a bound deformer is immutable, so threads share it, each posing with its own
//! [`PoseScratch`] (a [`Poser`]); a warm scratch makes a pose allocation-free. The `deform`
//! program is behind the default feature `cli`; depend on `deform` with
//! `default-features = false` for the library alone.
//!
//! Every fallible function returns `Ok` only with finite values. Angles (cotangents, mean-value
//! tangents, the degenerate-triangle test) are computed scale-invariantly, so a mesh scaled by
//! `1e-300` or `1e299` has the unit mesh's cotangent Laplacian and fields; [`validate()`]
//! refuses coordinates beyond [`validate::MAX_COORDINATE`] (where edge vectors would
//! overflow), and quantities with units (masses, mean-value weights) that leave the `f64`
//! range are [`MeshError::Overflow`].
//!
//! ```
//! use deform::{harmonic_field, io, HarmonicOptions};
//! let off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
//! let mesh = io::parse_off(off, "tet").unwrap();
//! let x = harmonic_field(&mesh, &[0], &[3], HarmonicOptions::default()).unwrap();
//! assert_eq!((x[0], x[3]), (0.0, 1.0));
//! assert!(x[1] > 0.0 && x[1] < 1.0);
//! ```

#![warn(missing_docs)]

pub mod blend;
pub mod deformers;
mod error;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod input;
#[cfg(test)]
mod layering;
pub mod mesh;
pub mod operators;
pub mod render;
pub mod skinning;
pub mod surgery;

// The paths users had before the layers became folders.
pub use blend::control;
pub use deformers::{arap, bspline, cage, fabrik, ffd, handles, spline};
pub use mesh::{adjacency, io, shapes, validate};
pub use operators::{harmonic, laplacian, mass, solve};

/// The shape every deformer shares (the path it had before the layers; see
/// [`deformers::deformer`]).
pub mod deformer {
    pub use crate::blend::{KeyError, MAX_KEYS};
    pub use crate::deformers::deformer::{Deformer, PoseScratch, Poser};
}

pub use blend::{simd_level, BlendMethod, BoundBlend, KeyWeights, PreparedKeys};
pub use blend::{BlendError, KeyError, MAX_KEYS};
pub use bspline::{
    bspline_basis, bspline_degree, bspline_motor, fit_bspline, BsplineFit, FitSolver,
};
pub use deformers::{DeformError, Deformer, PoseScratch, Poser};
pub use error::{Error, Result};
pub use fabrik::{
    chain_key_motors, chain_parameters, fabrik, ChainDeformer, ChainPose, FabrikOptions,
    FabrikSolution, FabrikStatus,
};
pub use handles::{HandleOptions, MotorHandles};
pub use harmonic::{
    harmonic_coordinates, harmonic_field, harmonic_system, Harmonic, HarmonicOptions,
    BIHARMONIC_FILL_FLOOR, BIHARMONIC_FILL_PER_NONZERO,
};
pub use laplacian::{
    cotangent_laplacian, laplacian, mean_value_laplacian, mean_value_weights, uniform_laplacian,
    CotangentOptions, DegeneratePolicy, LaplacianKind,
};
pub use mass::{mass_diagonal, mass_matrix, MassKind};
pub use mesh::{Aabb, Mesh};
pub use mesh::{IndexList, MeshError};
pub use operators::SolveError;
pub use solve::{
    DirichletSolver, Factorization, Parallelism, SolveScratch, SolverOptions, SystemAnalysis,
};
pub use spline::{SplineDeformer, SplineOptions, WeightScheme};
pub use validate::{check_elements, check_solvable, clean, Cleaned, ValidationReport};
