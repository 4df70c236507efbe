//! The crate's error: every layer's error converts into it with `?`.

use crate::blend::{BlendError, KeyError};
use crate::deformers::arap::ArapError;
use crate::deformers::cage::CageError;
use crate::deformers::ffd::FfdError;
use crate::deformers::DeformError;
use crate::input::InputError;
use crate::mesh::MeshError;
use crate::operators::SolveError;
use crate::skinning::SkinError;
use crate::surgery::SurgeryError;

/// Everything that can go wrong in `deform`. Each layer reports its own error
/// ([`MeshError`], [`SolveError`], [`BlendError`], [`DeformError`], [`SkinError`],
/// [`SurgeryError`], [`InputError`]); all convert into this one with `?`, the wrappers
/// flattened (a [`SolveError::Mesh`] is an [`Error::Mesh`], a [`DeformError::Keys`] an
/// [`Error::Keys`]), so one `match` sees every case with its offending indices.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A bad mesh, file, index list or size.
    #[error(transparent)]
    Mesh(MeshError),
    /// A system that cannot be built or solved.
    #[error(transparent)]
    Solve(SolveError),
    /// Bad keys, handle sets or parameters of a deformer.
    #[error(transparent)]
    Keys(KeyError),
    /// Constraint sets ARAP cannot work with.
    #[error(transparent)]
    Arap(ArapError),
    /// A bad FFD lattice, or a vertex outside it.
    #[error(transparent)]
    Ffd(FfdError),
    /// A bad cage, or one that does not enclose the model.
    #[error(transparent)]
    Cage(CageError),
    /// A bad rig file, rig or animation request.
    #[error(transparent)]
    Skin(#[from] SkinError),
    /// A cut, tear or drill that cannot be made.
    #[error(transparent)]
    Surgery(#[from] SurgeryError),
    /// A bad motor or selection file.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A request over the work budget, refused before any work.
    #[error(transparent)]
    Budget(#[from] crate::methods::budget::BudgetError),
    /// A method, option or pose request that cannot be taken.
    #[error(transparent)]
    Method(crate::methods::MethodError),
}

impl From<MeshError> for Error {
    fn from(e: MeshError) -> Self {
        Error::Mesh(e)
    }
}

impl From<SolveError> for Error {
    fn from(e: SolveError) -> Self {
        match e {
            SolveError::Mesh(m) => Error::Mesh(m),
            e => Error::Solve(e),
        }
    }
}

impl From<KeyError> for Error {
    fn from(e: KeyError) -> Self {
        Error::Keys(e)
    }
}

impl From<BlendError> for Error {
    fn from(e: BlendError) -> Self {
        DeformError::from(e).into()
    }
}

impl From<DeformError> for Error {
    fn from(e: DeformError) -> Self {
        match e {
            DeformError::Mesh(m) => Error::Mesh(m),
            DeformError::Solve(s) => Error::Solve(s),
            DeformError::Keys(k) => Error::Keys(k),
            DeformError::Arap(a) => Error::Arap(a),
            DeformError::Ffd(f) => Error::Ffd(f),
            DeformError::Cage(c) => Error::Cage(c),
        }
    }
}

impl From<crate::methods::MethodError> for Error {
    fn from(e: crate::methods::MethodError) -> Self {
        Error::Method(e)
    }
}

impl From<crate::methods::MethodsError> for Error {
    fn from(e: crate::methods::MethodsError) -> Self {
        use crate::methods::MethodsError as M;
        match e {
            M::Method(m) => Error::Method(m),
            M::Budget(b) => Error::Budget(b),
            M::Deform(d) => d.into(),
            M::Skin(s) => Error::Skin(s),
            M::Surgery(s) => Error::Surgery(s),
            M::Input(i) => Error::Input(i),
        }
    }
}

/// `Result` with [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
