//! Meshes, Laplacians, sparse solves, harmonic fields and the CGA mesh deformers of the two
//! papers, in layers; each folder may use only the layers below it (a unit test checks every
//! `crate::` path, see `ARCHITECTURE.md` at the repository root):
//!
//! | layer | what | may use | error |
//! |---|---|---|---|
//! | [`mesh`] | [`Mesh`], adjacency, [`mesh::validate::validate()`]/[`mesh::validate::clean()`], shapes, files ([`mesh::io`]) | - | [`mesh::MeshError`] |
//! | [`operators`] | Laplacians, mass matrices, [`operators::solve::DirichletSolver`], [`operators::harmonic::Harmonic`] fields | mesh | [`operators::SolveError`] |
//! | [`blend`] | [`BlendMethod`], [`blend::KeyWeights`], [`blend::BoundBlend`], [`blend::control`] points | mesh | [`blend::KeyError`], [`blend::BlendError`] |
//! | [`deformers`] | the [`Deformer`] shape; spline, B-spline + FABRIK, handles, ARAP, FFD, cages | mesh, operators, blend | [`deformers::DeformError`] |
//! | [`skinning`] | glTF and libigl rigs, animation, skinning by every blend method | mesh, operators, blend, deformers | [`skinning::SkinError`] |
//! | [`surgery`] | cut, tear and drill that stay animatable | mesh, skinning | [`surgery::SurgeryError`] |
//! | [`render`] | the PNG preview renderer, the previews every command and the demo draw ([`render::preview`]) and their overlays ([`render::tools`]) | mesh | [`mesh::MeshError`] |
//! | [`methods`] | what the program, its editor and library callers share: each method described once ([`methods::MethodSettings`]), bound and posed ([`methods::BoundMethod`]), the scene catalogue, the showcase the demo writes, the rig frame convention, the work budget | every layer | [`methods::MethodError`], [`methods::MethodsError`] |
//! | [`editor`] | the editor's model: an editing [`editor::Session`] driven by requests, no I/O | every layer | [`editor::EditError`] |
//! | [`input`] | motor JSON and selections, one format for every program command | mesh | [`input::InputError`] |
//!
//! Every layer's error converts into [`Error`] with `?`. Deformers bind once and pose many
//! times: a bound deformer is immutable, so threads share it, each posing with its own
//! scratch ([`Deformer::Scratch`], paired in a [`Poser`]); a warm scratch makes a pose
//! allocation-free. The `deform`
//! program is behind the default feature `cli`; depend on `deform` with
//! `default-features = false` for the library alone.
//!
//! Every fallible function returns `Ok` only with finite values. Angles (cotangents, mean-value
//! tangents, the degenerate-triangle test) are computed scale-invariantly, so a mesh scaled by
//! `1e-300` or `1e299` has the unit mesh's cotangent Laplacian and fields;
//! [`mesh::validate::validate()`] refuses coordinates beyond [`mesh::validate::MAX_COORDINATE`] (where
//! edge vectors would overflow), and quantities with units (masses, mean-value weights) that
//! leave the `f64` range are [`mesh::MeshError::Overflow`].
//!
//! Each item has one public path, in its layer (`deform::operators::harmonic::harmonic_field`,
//! `deform::mesh::io::read_mesh`); the crate root re-exports a small prelude: [`Mesh`],
//! [`Error`], [`Result`], [`Deformer`], [`Poser`], [`BlendMethod`], [`Rig`] and every deformer
//! ([`SplineDeformer`], [`ChainDeformer`], [`MotorHandles`], [`Arap`], [`Ffd`],
//! [`CageDeformer`], [`Skinning`]).
//!
//! ```
//! use deform::mesh::io;
//! use deform::operators::harmonic::{harmonic_field, HarmonicOptions};
//! let off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
//! let mesh = io::parse_off(off, "tet").unwrap();
//! let x = harmonic_field(&mesh, &[0], &[3], HarmonicOptions::default()).unwrap();
//! assert_eq!((x[0], x[3]), (0.0, 1.0));
//! assert!(x[1] > 0.0 && x[1] < 1.0);
//! ```

#![warn(missing_docs)]

pub mod blend;
pub mod deformers;
pub mod editor;
mod error;
#[cfg(feature = "gpu")]
pub mod gpu;
pub mod input;
#[cfg(test)]
mod layering;
pub mod mesh;
pub mod methods;
pub mod operators;
pub mod render;
pub mod skinning;
pub mod surgery;

// The prelude: what nearly every user names, and every deformer. Everything else has one
// path, in its layer.
pub use blend::BlendMethod;
pub use deformers::arap::Arap;
pub use deformers::cage::CageDeformer;
pub use deformers::fabrik::ChainDeformer;
pub use deformers::ffd::Ffd;
pub use deformers::handles::MotorHandles;
pub use deformers::spline::SplineDeformer;
pub use deformers::{Deformer, Poser};
pub use error::{Error, Result};
pub use mesh::Mesh;
pub use skinning::{Rig, Skinning};

/// The `cga` crate this one is built on (motors, rotors, points): `deform::cga::Motor` is the
/// type every deformer takes, whatever version of `cga` the caller depends on.
pub use cga;
/// The `glam` crate of this crate's API (`DVec3`, `DQuat`, `DMat4`): the same as
/// `deform::cga::glam`, for callers who do not depend on glam themselves or whose glam differs.
pub use glam;
