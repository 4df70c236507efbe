//! The blend core's errors: bad keys ([`KeyError`]) and inputs that do not fit the bound
//! mesh ([`BlendError::Mesh`]).

use crate::mesh::MeshError;
use cga::CgaError;

/// The most keys one deformer takes (a sanity limit on key lists and lattices; per-key data
/// lives in buffers the bound deformer reuses from pose to pose).
pub const MAX_KEYS: usize = 1 << 16;
/// What is wrong with the keys, handle sets or parameters of a deformer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum KeyError {
    /// A key list of the wrong length for the scheme (or the bound deformer).
    #[error("{what} takes {expected} keys, got {got}")]
    WrongCount {
        /// The scheme or deformer.
        what: &'static str,
        /// How many it takes (`"exactly 3"`, `"at least 2"`).
        expected: String,
        /// How many were given.
        got: usize,
    },
    /// A key that is not finite or not a (scaled) motor.
    #[error("key {index}: {source}")]
    Invalid {
        /// The key's position in the list.
        index: usize,
        /// Why it was rejected.
        source: CgaError,
    },
    /// More keys than [`MAX_KEYS`].
    #[error("{got} {what}: at most {max} are supported")]
    TooMany {
        /// What they are (`"keys"`, `"joints"`, `"handle sets"`).
        what: &'static str,
        /// How many were given.
        got: usize,
        /// The limit.
        max: usize,
    },
    /// A spline parameter outside `[0, 1]` (or not finite).
    #[error("parameter at item {index} is {value}, outside [0, 1]")]
    ParameterOutOfRange {
        /// Vertex (or key) index.
        index: usize,
        /// The value.
        value: f64,
    },
    /// An empty handle set.
    #[error("handle set {set} is empty")]
    EmptyHandle {
        /// The set's position in the list.
        set: usize,
    },
    /// A chain or fit that cannot be set up (too few joints, zero-length bones, parameters not
    /// increasing, fewer samples than control keys).
    #[error("{0}")]
    BadSetup(String),
    /// Affine maps given as the keys of a method that blends motors, or an affine key that is
    /// not finite.
    #[error("{0}")]
    Affine(String),
}

impl KeyError {
    /// `Ok` for at most [`MAX_KEYS`] of `what` (`"keys"`, `"joints"`, `"handle sets"`), else
    /// [`KeyError::TooMany`]: the one check of every key list, rig and handle selection.
    pub fn check_count(what: &'static str, got: usize) -> Result<(), KeyError> {
        if got > MAX_KEYS {
            return Err(KeyError::TooMany {
                what,
                got,
                max: MAX_KEYS,
            });
        }
        Ok(())
    }
}
/// What can go wrong binding or posing a [`BoundBlend`](crate::blend::BoundBlend) or a
/// [`ControlBinding`](crate::blend::control::ControlBinding).
#[derive(Debug, thiserror::Error)]
pub enum BlendError {
    /// Bad keys (see [`KeyError`]).
    #[error(transparent)]
    Keys(#[from] KeyError),
    /// Positions or weights that do not fit, or a singular blended rest transform.
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

/// `Result` with [`BlendError`].
pub type Result<T, E = BlendError> = std::result::Result<T, E>;

/// Check a key count against what a deformer takes.
pub(crate) fn check_key_count(what: &'static str, expected: usize, got: usize) -> Result<()> {
    if got != expected {
        return Err(KeyError::WrongCount {
            what,
            expected: format!("exactly {expected}"),
            got,
        }
        .into());
    }
    Ok(())
}

/// Check the output slice length.
pub(crate) fn check_positions(expected: usize, got: usize) -> Result<()> {
    if got != expected {
        return Err(MeshError::DimensionMismatch {
            what: "posed positions",
            expected,
            got,
        }
        .into());
    }
    Ok(())
}
