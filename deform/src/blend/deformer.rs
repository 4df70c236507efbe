//! The shape every deformer shares: bind once, pose many times.
//!
//! A deformer has two phases:
//!
//! * `bind(mesh, ..., options) -> Bound`: every precomputation (harmonic fields, per-vertex
//!   weights, the rest points expressed in the frame of their rest motor). Fallible: bad
//!   meshes, bad handle sets, key lists of the wrong length are typed errors here.
//! * [`Deformer::pose`]`(&keys, &mut positions)`: cheap, allocation-free, parallel over the
//!   vertices with rayon; fallible only on bad keys (a key that is not finite or not a motor,
//!   the wrong number of keys, an output slice of the wrong length). The positions are
//!   written only when every key is valid, so an error leaves them as they were.
//!
//! Spline-aligned deformation ([`crate::SplineDeformer`]), motor handles
//! ([`crate::MotorHandles`]) and every later deformer implement [`Deformer`], so tools (the
//! `deform` program, benches) drive them the same way.
//!
//! ```
//! use deform::{Deformer, MotorHandles, HarmonicOptions, Mesh};
//! use cga::ScaledMotor;
//! use glam::{DQuat, DVec3};
//! // A strip of 2 x 4 vertices; the left end is handle 0, the right end handle 1.
//! let p: Vec<DVec3> = (0..8).map(|i| DVec3::new((i % 4) as f64, (i / 4) as f64, 0.0)).collect();
//! let t = vec![[0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6]];
//! let mesh = Mesh::new(p, t);
//! let bound = MotorHandles::bind(&mesh, &[&[0, 4], &[3, 7]], HarmonicOptions::default()).unwrap();
//! let lift = ScaledMotor::from_scale_rotation_translation(1.0, DQuat::IDENTITY, DVec3::Z);
//! let mut out = vec![DVec3::ZERO; 8];
//! bound.pose(&[ScaledMotor::IDENTITY, lift], &mut out).unwrap();
//! assert!((out[3] - DVec3::new(3.0, 0.0, 1.0)).length() < 1e-12); // handle 1 moved rigidly
//! assert!(out[0].abs_diff_eq(DVec3::ZERO, 1e-12)); // handle 0 stayed
//! assert!(out[1].z > 0.0 && out[1].z < out[2].z); // the rest follows smoothly
//! ```

use cga::{CgaError, ScaledMotor};
use glam::DVec3;

/// The most keys one deformer takes (a sanity limit on key lists and lattices; per-key data
/// lives in buffers the bound deformer reuses from pose to pose).
pub const MAX_KEYS: usize = 1 << 16;

/// A deformer after `bind`: poses its mesh from a list of keys.
pub trait Deformer {
    /// The number of vertices it poses.
    fn vertex_count(&self) -> usize;

    /// The number of keys [`Deformer::pose`] takes.
    fn key_count(&self) -> usize;

    /// Write the posed positions into `positions` (length [`Deformer::vertex_count`]).
    ///
    /// # Errors
    /// [`crate::Error::Keys`] for a bad key or a key list of the wrong length,
    /// [`crate::Error::DimensionMismatch`] when `positions` has the wrong length. On error the
    /// positions are left untouched.
    fn pose(&self, keys: &[ScaledMotor], positions: &mut [DVec3]) -> crate::Result<()>;
}

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
    #[error("{got} keys: at most {max} are supported")]
    TooMany {
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
}

/// `impl Deformer for $t` by delegating to its field `$field` (a [`crate::BoundBlend`], or any
/// bound form with the same `vertex_count`, `key_count` and `pose`).
macro_rules! deformer_via_blend {
    ($t:ty, $field:ident) => {
        impl $crate::blend::deformer::Deformer for $t {
            fn vertex_count(&self) -> usize {
                self.$field.vertex_count()
            }

            fn key_count(&self) -> usize {
                self.$field.key_count()
            }

            fn pose(
                &self,
                keys: &[cga::ScaledMotor],
                positions: &mut [glam::DVec3],
            ) -> $crate::Result<()> {
                self.$field.pose(keys, positions)
            }
        }
    };
}
pub(crate) use deformer_via_blend;

/// Check a key count against what a deformer takes.
pub(crate) fn check_key_count(
    what: &'static str,
    expected: usize,
    got: usize,
) -> crate::Result<()> {
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
pub(crate) fn check_positions(expected: usize, got: usize) -> crate::Result<()> {
    if got != expected {
        return Err(crate::Error::DimensionMismatch {
            what: "posed positions",
            expected,
            got,
        });
    }
    Ok(())
}
