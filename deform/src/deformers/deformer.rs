//! The shape every deformer shares: bind once, pose many times.
//!
//! A deformer has two phases:
//!
//! * `bind(mesh, ..., options) -> Bound`: every precomputation (harmonic fields, per-vertex
//!   weights, the rest points expressed in the frame of their rest motor). Fallible: bad
//!   meshes, bad handle sets, key lists of the wrong length are typed errors here.
//! * [`Deformer::pose_using`]`(&keys, &mut scratch, &mut positions)`: cheap,
//!   allocation-free, parallel over the vertices with rayon; fallible only on bad keys (a key
//!   that is not finite or not a motor, the wrong number of keys, an output slice of the
//!   wrong length). The positions are written only when every key is valid, so an error
//!   leaves them as they were.
//!
//! The per-pose buffers live in a scratch the caller owns (one per thread), never in the bound
//! deformer: a bound deformer is immutable after `bind`, so any number of threads pose it at
//! once. Each deformer names its scratch type ([`Deformer::Scratch`]), so the scratch of
//! another kind of deformer does not compile. A [`Poser`] pairs a deformer with its scratch;
//! [`Deformer::pose`] is the one-off form that makes a fresh scratch each call. Deformers
//! chosen at run time that share a scratch type are `dyn Deformer<Scratch = S>` (lattices and
//! cages share [`ControlScratch`]).
//!
//! ```compile_fail
//! # use deform::{Deformer, Mesh, MotorHandles};
//! # use deform::operators::harmonic::HarmonicOptions;
//! # use deform::deformers::arap::{Arap, ArapOptions};
//! # use cga::ScaledMotor;
//! # fn wrong(handles: &MotorHandles, arap: &Arap, out: &mut [glam::DVec3]) {
//! let mut scratch = handles.scratch(); // prepared keys
//! // An ARAP pose with the handles' scratch: a type error, not a silent replacement.
//! Deformer::pose_using(arap, &[ScaledMotor::IDENTITY], &mut scratch, out).unwrap();
//! # }
//! ```
//!
//! Spline-aligned deformation ([`crate::SplineDeformer`]), motor handles
//! ([`crate::MotorHandles`]) and every later deformer implement [`Deformer`], so tools (the
//! `deform` program, benches) drive them the same way.
//!
//! ```
//! use deform::{Deformer, MotorHandles, Mesh};
//! use deform::operators::harmonic::HarmonicOptions;
//! use cga::ScaledMotor;
//! use glam::{DQuat, DVec3};
//! // A strip of 2 x 4 vertices; the left end is handle 0, the right end handle 1.
//! let p: Vec<DVec3> = (0..8).map(|i| DVec3::new((i % 4) as f64, (i / 4) as f64, 0.0)).collect();
//! let t = vec![[0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6]];
//! let mesh = Mesh::new(p, t);
//! let bound = MotorHandles::bind(&mesh, &[&[0, 4], &[3, 7]], HarmonicOptions::default()).unwrap();
//! let lift = ScaledMotor::from_scale_rotation_translation(1.0, DQuat::IDENTITY, DVec3::Z);
//! let mut out = vec![DVec3::ZERO; 8];
//! let mut poser = bound.poser(); // per-pose buffers, reused by every pose of this thread
//! poser.pose(&[ScaledMotor::IDENTITY, lift], &mut out).unwrap();
//! assert!((out[3] - DVec3::new(3.0, 0.0, 1.0)).length() < 1e-12); // handle 1 moved rigidly
//! assert!(out[0].abs_diff_eq(DVec3::ZERO, 1e-12)); // handle 0 stayed
//! assert!(out[1].z > 0.0 && out[1].z < out[2].z); // the rest follows smoothly
//! ```

use super::error::{DeformError, Result};
use crate::blend::control::{ControlBinding, ControlScratch};
use cga::ScaledMotor;
use glam::DVec3;

/// A deformer after `bind`: poses its mesh from a list of keys.
///
/// Immutable once bound (`Send + Sync`): the buffers a pose needs are the caller's
/// [`Deformer::Scratch`].
pub trait Deformer: Send + Sync {
    /// The per-pose buffers, owned by the caller: one per thread that poses.
    type Scratch: Send;

    /// The number of vertices it poses.
    fn vertex_count(&self) -> usize;

    /// The number of keys [`Deformer::pose`] takes.
    fn key_count(&self) -> usize;

    /// Fresh per-pose buffers for this deformer (allocated here, reused by every
    /// [`Deformer::pose_using`] that gets them).
    fn scratch(&self) -> Self::Scratch;

    /// Write the posed positions into `positions` (length [`Deformer::vertex_count`]), using
    /// the caller's `scratch`: no allocation once the scratch has served one pose. A scratch
    /// made by another deformer of the same type (another mesh) is resized or replaced,
    /// never misread.
    ///
    /// # Errors
    /// [`DeformError::Keys`] for a bad key or a key list of the wrong length,
    /// [`DeformError::Mesh`] with [`crate::mesh::MeshError::DimensionMismatch`] when
    /// `positions` has the wrong length. On error the positions are left untouched.
    fn pose_using(
        &self,
        keys: &[ScaledMotor],
        scratch: &mut Self::Scratch,
        positions: &mut [DVec3],
    ) -> Result<()>;

    /// [`Deformer::pose_using`] with a fresh scratch: one allocation of the per-pose buffers
    /// per call. Pose loops use a [`Poser`].
    ///
    /// # Errors
    /// As [`Deformer::pose_using`].
    fn pose(&self, keys: &[ScaledMotor], positions: &mut [DVec3]) -> Result<()> {
        let mut scratch = self.scratch();
        self.pose_using(keys, &mut scratch, positions)
    }

    /// This deformer with its own scratch, for a pose loop on one thread.
    fn poser(&self) -> Poser<'_, Self>
    where
        Self: Sized,
    {
        Poser::new(self)
    }
}

/// A deformer and a scratch of its own: the form for a pose loop. Make one per thread;
/// the deformer itself is shared.
///
/// ```
/// # use deform::{Deformer, Mesh, MotorHandles};
/// # use deform::operators::harmonic::HarmonicOptions;
/// # use cga::ScaledMotor;
/// # use glam::DVec3;
/// # let p: Vec<DVec3> = (0..8).map(|i| DVec3::new((i % 4) as f64, (i / 4) as f64, 0.0)).collect();
/// # let t = vec![[0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6]];
/// # let bound = MotorHandles::bind(&Mesh::new(p, t), &[&[0, 4], &[3, 7]], HarmonicOptions::default()).unwrap();
/// let keys = [ScaledMotor::IDENTITY; 2];
/// std::thread::scope(|s| {
///     for _ in 0..2 {
///         s.spawn(|| {
///             let mut poser = bound.poser();
///             let mut out = vec![DVec3::ZERO; bound.vertex_count()];
///             poser.pose(&keys, &mut out).unwrap();
///         });
///     }
/// });
/// ```
pub struct Poser<'a, D: Deformer + ?Sized> {
    deformer: &'a D,
    scratch: D::Scratch,
}

impl<D: Deformer + ?Sized> std::fmt::Debug for Poser<'_, D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Poser(..)")
    }
}

impl<'a, D: Deformer + ?Sized> Poser<'a, D> {
    /// `deformer` with a fresh scratch (works for `dyn Deformer<Scratch = S>` too).
    pub fn new(deformer: &'a D) -> Self {
        Poser {
            deformer,
            scratch: deformer.scratch(),
        }
    }

    /// The deformer.
    pub fn deformer(&self) -> &'a D {
        self.deformer
    }

    /// Pose into `positions`; no allocation after the first pose.
    ///
    /// # Errors
    /// As [`Deformer::pose_using`].
    pub fn pose(&mut self, keys: &[ScaledMotor], positions: &mut [DVec3]) -> Result<()> {
        self.deformer.pose_using(keys, &mut self.scratch, positions)
    }

    /// The best of `runs` poses (at least one) in milliseconds: the first fills the scratch
    /// and warms the caches, as a pose loop runs.
    pub fn best_time_ms(
        &mut self,
        keys: &[ScaledMotor],
        positions: &mut [DVec3],
        runs: usize,
    ) -> Result<f64> {
        let mut best = f64::INFINITY;
        for _ in 0..runs.max(1) {
            let t = std::time::Instant::now();
            self.pose(keys, positions)?;
            best = best.min(t.elapsed().as_secs_f64() * 1e3);
        }
        Ok(best)
    }
}

/// `impl Deformer for $t` by delegating to its field `$field`, a
/// [`BoundBlend`](crate::blend::BoundBlend) (scratch `$scratch`: its prepared keys) or a
/// control binding.
macro_rules! deformer_via_blend {
    ($t:ty, $field:ident, $scratch:ty) => {
        impl $crate::deformers::Deformer for $t {
            type Scratch = $scratch;

            fn vertex_count(&self) -> usize {
                self.$field.vertex_count()
            }

            fn key_count(&self) -> usize {
                self.$field.key_count()
            }

            fn scratch(&self) -> $scratch {
                self.$field.scratch()
            }

            // `BoundBlend` reports a `BlendError`, a wrapped deformer a `DeformError`.
            #[allow(clippy::needless_question_mark)]
            fn pose_using(
                &self,
                keys: &[cga::ScaledMotor],
                scratch: &mut $scratch,
                positions: &mut [glam::DVec3],
            ) -> $crate::deformers::Result<()> {
                Ok(self.$field.pose_using(keys, scratch, positions)?)
            }
        }
    };
}
pub(crate) use deformer_via_blend;

/// Cages and lattices: control points moved by motors (or by the motors' action on the
/// points, in the positional form).
impl Deformer for ControlBinding {
    type Scratch = ControlScratch;

    fn vertex_count(&self) -> usize {
        ControlBinding::vertex_count(self)
    }

    fn key_count(&self) -> usize {
        self.rest_points().len()
    }

    fn scratch(&self) -> ControlScratch {
        ControlBinding::scratch(self)
    }

    fn pose_using(
        &self,
        keys: &[ScaledMotor],
        scratch: &mut ControlScratch,
        positions: &mut [DVec3],
    ) -> Result<()> {
        ControlBinding::pose_using(self, keys, scratch, positions).map_err(DeformError::from)
    }
}
