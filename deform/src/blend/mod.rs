//! Per-vertex blending of key motors, the core every motor deformer poses with.
//!
//! **May use**: the mesh foundation. **Must not use**: operators, deformers, skinning,
//! surgery, render, input, or the crate-level `Error`; its errors are [`KeyError`] and
//! [`BlendError`].
//!
//! Each vertex `i` has weights `w_ij` over a contiguous run of keys ([`KeyWeights`]); its
//! transform is a blend of the keys `R_j`, by one of these methods ([`BlendMethod`]):
//!
//! * [`BlendMethod::MotorLog`] (the papers' equation (1)): `M_i = exp(sum_j w_ij log R_j)`.
//!   Principal logarithms, so the sign of a key is irrelevant and every key is in effect in
//!   the hemisphere of the identity: each key's rotation is taken as the one of angle at most
//!   pi. A key rotated by more than pi relative to the rest is the shorter rotation the other
//!   way round, and at exactly pi the axis is the one of the stored quaternion, so a blend
//!   through a half-turn is well defined, but keys on either side of pi blend discontinuously.
//!   Scale (keys that are scaled motors) is blended in the log too: geometrically.
//! * [`BlendMethod::MotorLinear`]: `normalise(sum_j w_ij R_j)` after bringing every key into the
//!   hemisphere of the vertex's first key (the motor form of dual-quaternion blending),
//!   with the scales blended geometrically.
//! * [`BlendMethod::DualQuaternion`]: Kavan's dual-quaternion linear blending on glam
//!   quaternion pairs, the same hemisphere rule, a baseline.
//! * [`BlendMethod::Matrix`]: `sum_j w_ij A_j` over 3x4 affine matrices (linear blend
//!   skinning), the baseline that collapses under large rotations;
//!   [`BlendMethod::MatrixF32`] the same in single precision (glam SIMD).
//! * [`BlendMethod::Conformal`] and [`BlendMethod::ConformalProjected`]: the second paper's
//!   equation (17), `sum_j w_ij R_j up(x) ~R_j` down-projected after or before the sum, each
//!   term a normalised conformal point (so that the two orders agree, as the paper says they
//!   do, also when keys dilate: a dilated joint scales its subtree about the joint and blends
//!   with the weight the file gives it, as matrix skinning does).
//!
//! The keys are prepared once per pose into buffers the bound deformer keeps
//! ([`PreparedKeys`]), so posing does not allocate.

mod batch;
pub mod control;
mod error;
mod kernels;
mod keys;

use crate::mesh::MeshError;
pub use batch::simd_level;
use batch::TASK;
use cga::ScaledMotor;
pub(crate) use error::{check_key_count, check_positions};
pub use error::{BlendError, KeyError, Result, MAX_KEYS};
use glam::DVec3;
pub use keys::{ConformalKey, PreparedKeys};
use rayon::prelude::*;

/// How the per-vertex transform is blended from the keys.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BlendMethod {
    /// `exp(sum w log R)`, the papers' method (the default).
    #[default]
    MotorLog,
    /// `normalise(sum w R)` with hemisphere alignment.
    MotorLinear,
    /// Dual-quaternion linear blending on glam quaternions (baseline).
    DualQuaternion,
    /// Linear blending of affine matrices (baseline; linear blend skinning).
    Matrix,
    /// [`BlendMethod::Matrix`] in single precision (glam's SIMD `Affine3A`), the GPU
    /// skinning path.
    MatrixF32,
    /// The second paper's equation (17), adding the conformal points first:
    /// `down(sum w M up(x) ~M)`. For rigid keys the same as [`BlendMethod::Matrix`]; with
    /// dilations each key counts with its weight times its point's `eo` coefficient.
    Conformal,
    /// Equation (17), down-projecting each term first: `sum w down(M up(x) ~M)`.
    ConformalProjected,
}

impl BlendMethod {
    /// Every method, for tables and benches.
    pub const ALL: [BlendMethod; 7] = [
        BlendMethod::MotorLog,
        BlendMethod::MotorLinear,
        BlendMethod::DualQuaternion,
        BlendMethod::Matrix,
        BlendMethod::MatrixF32,
        BlendMethod::Conformal,
        BlendMethod::ConformalProjected,
    ];

    /// A short name (`motor-log`, `motor-linear`, `dual-quaternion`, `matrix`).
    pub fn name(self) -> &'static str {
        match self {
            BlendMethod::MotorLog => "motor-log",
            BlendMethod::MotorLinear => "motor-linear",
            BlendMethod::DualQuaternion => "dual-quaternion",
            BlendMethod::Matrix => "matrix",
            BlendMethod::MatrixF32 => "matrix-f32",
            BlendMethod::Conformal => "conformal",
            BlendMethod::ConformalProjected => "conformal-projected",
        }
    }
}

/// A blend method by its [`BlendMethod::name`]: `"motor-log".parse()`.
impl std::str::FromStr for BlendMethod {
    type Err = UnknownBlendMethod;

    fn from_str(s: &str) -> std::result::Result<BlendMethod, UnknownBlendMethod> {
        BlendMethod::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| UnknownBlendMethod {
                given: s.to_string(),
            })
    }
}

/// A name that is no [`BlendMethod::name`]; the message lists the known names.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown blend method {given:?} (known: {})",
    BlendMethod::ALL.map(BlendMethod::name).join(", ")
)]
pub struct UnknownBlendMethod {
    /// The name given.
    pub given: String,
}

/// Per-vertex weights over keys: vertex `i` blends `width` keys with weights `row(i)`, either
/// a contiguous run `first(i) .. first(i) + width` (splines, dense handle coordinates) or an
/// explicit list of key indices per vertex (lattice blocks of a B-spline FFD, the few largest
/// coordinates of a cage).
#[derive(Clone, Debug, PartialEq)]
pub struct KeyWeights {
    key_count: usize,
    width: usize,
    first: Vec<u32>,
    /// `width` key indices per vertex, when the keys are not a contiguous run.
    keys: Option<Vec<u32>>,
    weights: Vec<f64>,
}

/// The weights of one vertex.
#[derive(Clone, Copy, Debug)]
pub struct Row<'a> {
    first: usize,
    keys: Option<&'a [u32]>,
    /// The weights, one per key of the row.
    pub weights: &'a [f64],
}

impl<'a> Row<'a> {
    /// A row of explicit keys and their weights (equal lengths).
    pub(crate) fn gathered(keys: &'a [u32], weights: &'a [f64]) -> Row<'a> {
        debug_assert_eq!(keys.len(), weights.len());
        Row {
            first: 0,
            keys: Some(keys),
            weights,
        }
    }

    /// The key of the row's `j`-th weight.
    #[inline]
    pub fn key(&self, j: usize) -> usize {
        match self.keys {
            Some(k) => k[j] as usize,
            None => self.first + j,
        }
    }

    /// `(key, weight)` pairs.
    #[inline]
    pub fn pairs(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.weights
            .iter()
            .enumerate()
            .map(|(j, &w)| (self.key(j), w))
    }

    /// Fold `f(acc, key, weight)` over the row, with one loop per storage kind (the kind is
    /// matched once, not per element).
    #[inline(always)]
    pub fn fold<A>(&self, init: A, mut f: impl FnMut(A, usize, f64) -> A) -> A {
        match self.keys {
            None => {
                let first = self.first;
                self.weights
                    .iter()
                    .enumerate()
                    .fold(init, |a, (j, &w)| f(a, first + j, w))
            }
            Some(k) => k
                .iter()
                .zip(self.weights)
                .fold(init, |a, (&k, &w)| f(a, k as usize, w)),
        }
    }
}

impl KeyWeights {
    /// Rows of `width` weights starting at key `first[i]`; `weights` is vertex-major.
    ///
    /// # Errors
    /// [`MeshError::DimensionMismatch`] for inconsistent lengths, [`KeyError::TooMany`],
    /// [`MeshError::InvalidArgument`] for a run past the last key or a non-finite weight.
    pub fn new(key_count: usize, width: usize, first: Vec<u32>, weights: Vec<f64>) -> Result<Self> {
        if let Some(v) = first
            .iter()
            .position(|&f| (f as usize).saturating_add(width) > key_count)
        {
            return Err(MeshError::InvalidArgument(format!(
                "vertex {v}: key run {}..{} past the {key_count} keys",
                first[v],
                (first[v] as usize).saturating_add(width)
            ))
            .into());
        }
        Self::checked(KeyWeights {
            key_count,
            width,
            first,
            keys: None,
            weights,
        })
    }

    /// Rows of `width` `(key, weight)` pairs with explicit keys: `keys` and `weights` are
    /// vertex-major, `width` per vertex.
    ///
    /// # Errors
    /// As [`KeyWeights::new`]; a key index past the last key is
    /// [`MeshError::InvalidArgument`].
    pub fn gathered(
        key_count: usize,
        width: usize,
        keys: Vec<u32>,
        weights: Vec<f64>,
    ) -> Result<Self> {
        if keys.len() != weights.len() {
            return Err(MeshError::DimensionMismatch {
                what: "key indices",
                expected: weights.len(),
                got: keys.len(),
            }
            .into());
        }
        if let Some(k) = keys.iter().position(|&k| k as usize >= key_count) {
            return Err(MeshError::InvalidArgument(format!(
                "vertex {}: key {} past the {key_count} keys",
                k / width.max(1),
                keys[k]
            ))
            .into());
        }
        let n = weights.len().checked_div(width).unwrap_or(0);
        Self::checked(KeyWeights {
            key_count,
            width,
            first: vec![0; n],
            keys: Some(keys),
            weights,
        })
    }

    fn checked(w: KeyWeights) -> Result<Self> {
        KeyError::check_count("keys", w.key_count)?;
        if w.weights.len() != w.first.len() * w.width {
            return Err(MeshError::DimensionMismatch {
                what: "key weights",
                expected: w.first.len() * w.width,
                got: w.weights.len(),
            }
            .into());
        }
        if let Some(k) = w.weights.iter().position(|x| !x.is_finite()) {
            return Err(MeshError::InvalidArgument(format!(
                "vertex {}: non-finite weight",
                k / w.width.max(1)
            ))
            .into());
        }
        Ok(w)
    }

    /// Dense rows: `columns[j][i]` is the weight of key `j` at vertex `i`.
    ///
    /// # Errors
    /// As [`KeyWeights::new`].
    pub fn from_columns(columns: &[Vec<f64>]) -> Result<Self> {
        let n = columns.first().map_or(0, Vec::len);
        if let Some(c) = columns.iter().find(|c| c.len() != n) {
            return Err(MeshError::DimensionMismatch {
                what: "weight columns",
                expected: n,
                got: c.len(),
            }
            .into());
        }
        let m = columns.len();
        let mut weights = vec![0.0; n * m];
        for (j, c) in columns.iter().enumerate() {
            for (i, &w) in c.iter().enumerate() {
                weights[i * m + j] = w;
            }
        }
        Self::new(m, m, vec![0; n], weights)
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.first.len()
    }

    /// Number of keys.
    pub fn key_count(&self) -> usize {
        self.key_count
    }

    /// Weights per vertex.
    pub fn width(&self) -> usize {
        self.width
    }

    /// The weights of vertex `i`.
    #[inline]
    pub fn row(&self, i: usize) -> Row<'_> {
        let range = i * self.width..(i + 1) * self.width;
        Row {
            first: self.first[i] as usize,
            keys: self.keys.as_ref().map(|k| &k[range.clone()]),
            weights: &self.weights[range],
        }
    }

    /// The weight of key `j` at vertex `i` (0 when the row does not hold it).
    pub fn weight(&self, i: usize, j: usize) -> f64 {
        self.row(i)
            .pairs()
            .filter(|&(k, _)| k == j)
            .map(|(_, w)| w)
            .sum()
    }
}

/// Vertices below which posing stays on one thread (the split costs more than it saves).
const PARALLEL_MIN: usize = 2048;

/// `out[i] = f(i)` for every vertex, in parallel (rayon) when there are enough of them: the
/// one per-vertex loop of every pose, in tasks of the batch loop's size. Whether every vertex
/// written is finite (each task checks its own while they are in cache).
#[inline]
pub(crate) fn for_each_vertex(out: &mut [DVec3], f: impl Fn(usize) -> DVec3 + Sync) -> bool {
    let chunk = |(c, o): (usize, &mut [DVec3])| {
        for (k, p) in o.iter_mut().enumerate() {
            *p = f(c * TASK + k);
        }
        all_finite(o)
    };
    if out.len() < PARALLEL_MIN {
        // Every chunk is written, whatever the earlier ones hold (no short circuit).
        let mut finite = true;
        for c in out.chunks_mut(TASK).enumerate() {
            finite &= chunk(c);
        }
        finite
    } else {
        out.par_chunks_mut(TASK)
            .enumerate()
            .map(chunk)
            .reduce(|| true, |a, b| a && b)
    }
}

/// Whether every coordinate of `points` is finite: a count of the coordinates whose exponent
/// bits are all set (infinities and NaN), an integer sum with no early exit and no branch,
/// which the compiler vectorises and unrolls (run on points still in cache).
#[inline]
pub(crate) fn all_finite(points: &[DVec3]) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    // SAFETY: `DVec3` is `#[repr(C)]` with three `f64` fields and no padding (24 bytes,
    // alignment 8), so `points` is `3 * points.len()` contiguous `f64`.
    let coords: &[f64] =
        unsafe { std::slice::from_raw_parts(points.as_ptr().cast::<f64>(), points.len() * 3) };
    let bad: u64 = coords
        .iter()
        .map(|x| u64::from(x.to_bits() & EXPONENT == EXPONENT))
        .sum();
    bad == 0
}

/// The result of a pose whose loop reported `finite`: [`MeshError::Overflow`] naming the
/// first vertex that is not (keys, weights or rest positions too large for `f64`).
pub(crate) fn finite_pose(finite: bool, out: &[DVec3]) -> Result<()> {
    if finite {
        return Ok(());
    }
    let index = out.iter().position(|p| !p.is_finite()).unwrap_or(0);
    Err(MeshError::Overflow {
        what: "posed vertex (keys, weights or rest positions too large for the method's floats)",
        index,
    }
    .into())
}

/// A mesh bound to key weights: the rest points in the frame of their rest transform, ready to
/// be posed by any keys. The shared core of the spline and handle deformers.
#[derive(Debug, Clone)]
pub struct BoundBlend {
    weights: KeyWeights,
    /// `p'_i = M_i^-1 p_i`, with `M_i` the blend of the rest keys.
    local: Vec<DVec3>,
    /// The rows and `local` laid out for the batch loop.
    batches: batch::Batches,
    method: BlendMethod,
}

impl BoundBlend {
    /// Bind `positions` with `weights` to the `rest` keys: `p'_i = M_i^-1 p_i` where `M_i` is
    /// the blend of the rest keys at vertex `i`.
    ///
    /// # Errors
    /// [`MeshError::DimensionMismatch`], [`KeyError`] for bad rest keys,
    /// [`MeshError::InvalidArgument`] when a blended rest transform is singular (possible
    /// only with [`BlendMethod::Matrix`]).
    pub fn bind(
        positions: &[DVec3],
        weights: KeyWeights,
        rest: &[ScaledMotor],
        method: BlendMethod,
    ) -> Result<Self> {
        check_positions(weights.vertex_count(), positions.len())?;
        check_key_count("the rest pose", weights.key_count(), rest.len())?;
        let keys = PreparedKeys::new(rest, method)?;
        let local: Vec<DVec3> = positions
            .par_iter()
            .enumerate()
            .map(|(i, &p)| keys.affine(weights.row(i)).inverse().transform_point3(p))
            .collect();
        if let Some(i) = local.iter().position(|p| !p.is_finite()) {
            return Err(MeshError::InvalidArgument(format!(
                "vertex {i}: the blended rest transform is singular or overflows"
            ))
            .into());
        }
        Ok(BoundBlend {
            batches: batch::Batches::new(&weights, &local),
            weights,
            local,
            method,
        })
    }

    /// The weights.
    pub fn weights(&self) -> &KeyWeights {
        &self.weights
    }

    /// The blend method.
    pub fn method(&self) -> BlendMethod {
        self.method
    }

    /// The rest points in the frame of their blended rest transform (`p'_i = M_i^-1 p_i`):
    /// what `pose` moves.
    pub fn local(&self) -> &[DVec3] {
        &self.local
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.local.len()
    }

    /// Number of keys.
    pub fn key_count(&self) -> usize {
        self.weights.key_count()
    }

    /// Fresh per-pose buffers (the prepared keys) for [`BoundBlend::pose_using`].
    pub fn scratch(&self) -> PreparedKeys {
        PreparedKeys::default()
    }

    /// `p_i = M_i p'_i` with `M_i` the blend of `keys` at vertex `i`, with a fresh scratch
    /// (one allocation of the prepared keys per call; pose loops use
    /// [`BoundBlend::pose_using`]).
    ///
    /// # Errors
    /// As [`BoundBlend::pose_using`].
    pub fn pose(&self, keys: &[ScaledMotor], out: &mut [DVec3]) -> Result<()> {
        self.pose_using(keys, &mut self.scratch(), out)
    }

    /// `p_i = M_i p'_i` with `M_i` the blend of `keys` at vertex `i`, preparing the keys in
    /// the caller's `prepared`: parallel, no allocation once `prepared` has served a pose
    /// with as many keys.
    ///
    /// # Errors
    /// [`KeyError`] for a bad key or a key list of the wrong length,
    /// [`MeshError::DimensionMismatch`] for `out` of the wrong length; `out` is then
    /// untouched. [`MeshError::Overflow`] naming the first vertex whose pose is not finite
    /// (keys, weights and rest positions whose blend leaves the `f64` range, such as weights
    /// of 1100 and -1099 on a key of scale 2); `out` then holds that pose.
    pub fn pose_using(
        &self,
        keys: &[ScaledMotor],
        prepared: &mut PreparedKeys,
        out: &mut [DVec3],
    ) -> Result<()> {
        let prepared = self.checked_prepare(keys, prepared, out)?;
        self.pose_prepared(prepared, out)
    }

    /// [`BoundBlend::pose_using`] with affine maps for keys (any map, not only a
    /// similarity), for the matrix methods ([`PreparedKeys::prepare_affine`]).
    ///
    /// # Errors
    /// As [`BoundBlend::pose_using`], and [`KeyError::Affine`] for a method that blends
    /// motors or a map that is not finite.
    pub fn pose_affine_using(
        &self,
        maps: &[glam::DAffine3],
        prepared: &mut PreparedKeys,
        out: &mut [DVec3],
    ) -> Result<()> {
        check_key_count("this deformer", self.key_count(), maps.len())?;
        check_positions(self.vertex_count(), out.len())?;
        prepared.prepare_affine(maps, self.method)?;
        self.pose_prepared(prepared, out)
    }

    /// Every vertex posed by keys already prepared: the batch loop, or one vertex at a time
    /// where there are no batches.
    fn pose_prepared(&self, prepared: &PreparedKeys, out: &mut [DVec3]) -> Result<()> {
        let single = |i: usize| prepared.transform(self.weights.row(i), self.local[i]);
        let finite = if self.batches.is_empty() {
            for_each_vertex(out, single)
        } else {
            kernels::run(prepared, &self.batches, &single, out)
        };
        finite_pose(finite, out)
    }

    /// The checks of a pose (key count, output length) and the keys prepared in `prepared`.
    fn checked_prepare<'p>(
        &self,
        keys: &[ScaledMotor],
        prepared: &'p mut PreparedKeys,
        out: &[DVec3],
    ) -> Result<&'p PreparedKeys> {
        check_key_count("this deformer", self.key_count(), keys.len())?;
        check_positions(self.vertex_count(), out.len())?;
        prepared.prepare(keys, self.method)?;
        Ok(prepared)
    }

    /// [`BoundBlend::pose_using`] one vertex at a time ([`PreparedKeys::transform`] per
    /// vertex, in parallel), without the batch loop: the reference the batch kernels are
    /// tested against, and the baseline the benchmarks measure them against in the same run.
    ///
    /// # Errors
    /// As [`BoundBlend::pose_using`].
    pub fn pose_vertex_by_vertex(
        &self,
        keys: &[ScaledMotor],
        prepared: &mut PreparedKeys,
        out: &mut [DVec3],
    ) -> Result<()> {
        let prepared = self.checked_prepare(keys, prepared, out)?;
        let finite = for_each_vertex(out, |i| {
            prepared.transform(self.weights.row(i), self.local[i])
        });
        finite_pose(finite, out)
    }
}

#[cfg(test)]
mod name_tests {
    use super::*;

    #[test]
    fn blend_names_round_trip_and_others_are_refused() {
        for m in BlendMethod::ALL {
            assert_eq!(m.name().parse::<BlendMethod>(), Ok(m));
        }
        let e = "Matrix".parse::<BlendMethod>().unwrap_err();
        assert_eq!(e.given, "Matrix");
        let message = e.to_string();
        for m in BlendMethod::ALL {
            assert!(message.contains(m.name()), "{message}");
        }
    }
}
