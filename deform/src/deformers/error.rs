//! The deformers' error: everything binding or posing a deformer can report.

use crate::blend::{BlendError, KeyError};
use crate::deformers::arap::ArapError;
use crate::deformers::cage::CageError;
use crate::deformers::ffd::FfdError;
use crate::mesh::MeshError;
use crate::operators::SolveError;

/// What can go wrong binding or posing a deformer: the mesh and its systems, the keys, and
/// each deformer's own conditions. Lower layers' errors convert into it with `?`
/// (a [`SolveError::Mesh`] or [`BlendError::Mesh`] becomes [`DeformError::Mesh`]).
#[derive(Debug, thiserror::Error)]
pub enum DeformError {
    /// A bad mesh, file, index list or size (see [`MeshError`]).
    #[error(transparent)]
    Mesh(MeshError),
    /// A system that cannot be built or solved (see [`SolveError`]; never its `Mesh` case).
    #[error(transparent)]
    Solve(SolveError),
    /// Bad keys, handle sets or parameters.
    #[error(transparent)]
    Keys(#[from] KeyError),
    /// Constraint sets ARAP cannot work with.
    #[error(transparent)]
    Arap(#[from] ArapError),
    /// A bad FFD lattice, or a vertex outside it.
    #[error(transparent)]
    Ffd(#[from] FfdError),
    /// A bad cage, or one that does not enclose the model.
    #[error(transparent)]
    Cage(#[from] CageError),
}

impl From<MeshError> for DeformError {
    fn from(e: MeshError) -> Self {
        DeformError::Mesh(e)
    }
}

impl From<SolveError> for DeformError {
    fn from(e: SolveError) -> Self {
        match e {
            SolveError::Mesh(m) => DeformError::Mesh(m),
            e => DeformError::Solve(e),
        }
    }
}

impl From<BlendError> for DeformError {
    fn from(e: BlendError) -> Self {
        match e {
            BlendError::Keys(k) => DeformError::Keys(k),
            BlendError::Mesh(m) => DeformError::Mesh(m),
        }
    }
}

/// `Result` with [`DeformError`].
pub type Result<T, E = DeformError> = std::result::Result<T, E>;
