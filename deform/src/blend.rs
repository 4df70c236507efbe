//! Per-vertex blending of key motors, the core every motor deformer poses with.
//!
//! Each vertex `i` has weights `w_ij` over a contiguous run of keys ([`KeyWeights`]); its
//! transform is a blend of the keys `R_j`, by one of four methods ([`BlendMethod`]):
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
//!   skinning), the baseline that collapses under large rotations.
//!
//! The keys are prepared once per pose ([`PreparedKeys`], on the stack: no allocation).

use crate::deformer::{check_key_count, check_positions, KeyError, MAX_KEYS};
use crate::Result;
use cga::{Bivector, Motor, ScaledMotor};
use glam::{DAffine3, DMat3, DQuat, DVec3};
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
    /// Linear blending of affine matrices (baseline).
    Matrix,
}

impl BlendMethod {
    /// Every method, for tables and benches.
    pub const ALL: [BlendMethod; 4] = [
        BlendMethod::MotorLog,
        BlendMethod::MotorLinear,
        BlendMethod::DualQuaternion,
        BlendMethod::Matrix,
    ];

    /// A short name (`motor-log`, `motor-linear`, `dual-quaternion`, `matrix`).
    pub fn name(self) -> &'static str {
        match self {
            BlendMethod::MotorLog => "motor-log",
            BlendMethod::MotorLinear => "motor-linear",
            BlendMethod::DualQuaternion => "dual-quaternion",
            BlendMethod::Matrix => "matrix",
        }
    }
}

/// Per-vertex weights over a contiguous run of keys: vertex `i` blends keys
/// `first(i) .. first(i) + width` with weights `row(i)`.
#[derive(Clone, Debug, PartialEq)]
pub struct KeyWeights {
    key_count: usize,
    width: usize,
    first: Vec<u32>,
    weights: Vec<f64>,
}

impl KeyWeights {
    /// Rows of `width` weights starting at key `first[i]`; `weights` is vertex-major.
    ///
    /// # Errors
    /// [`crate::Error::DimensionMismatch`] for inconsistent lengths, [`KeyError::TooMany`],
    /// [`crate::Error::InvalidArgument`] for a run past the last key or a non-finite weight.
    pub fn new(key_count: usize, width: usize, first: Vec<u32>, weights: Vec<f64>) -> Result<Self> {
        if key_count > MAX_KEYS {
            return Err(KeyError::TooMany {
                got: key_count,
                max: MAX_KEYS,
            }
            .into());
        }
        if weights.len() != first.len() * width {
            return Err(crate::Error::DimensionMismatch {
                what: "key weights",
                expected: first.len() * width,
                got: weights.len(),
            });
        }
        if let Some(v) = first.iter().position(|&f| f as usize + width > key_count) {
            return Err(crate::Error::InvalidArgument(format!(
                "vertex {v}: key run {}..{} past the {key_count} keys",
                first[v],
                first[v] as usize + width
            )));
        }
        if let Some(k) = weights.iter().position(|w| !w.is_finite()) {
            return Err(crate::Error::InvalidArgument(format!(
                "vertex {}: non-finite weight",
                k / width.max(1)
            )));
        }
        Ok(KeyWeights {
            key_count,
            width,
            first,
            weights,
        })
    }

    /// Dense rows: `columns[j][i]` is the weight of key `j` at vertex `i`.
    ///
    /// # Errors
    /// As [`KeyWeights::new`].
    pub fn from_columns(columns: &[Vec<f64>]) -> Result<Self> {
        let n = columns.first().map_or(0, Vec::len);
        if let Some(c) = columns.iter().find(|c| c.len() != n) {
            return Err(crate::Error::DimensionMismatch {
                what: "weight columns",
                expected: n,
                got: c.len(),
            });
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

    /// The first key and the weights of vertex `i`.
    #[inline]
    pub fn row(&self, i: usize) -> (usize, &[f64]) {
        (
            self.first[i] as usize,
            &self.weights[i * self.width..(i + 1) * self.width],
        )
    }

    /// The dense weight of key `j` at vertex `i`.
    pub fn weight(&self, i: usize, j: usize) -> f64 {
        let (f, w) = self.row(i);
        if j >= f && j < f + self.width {
            w[j - f]
        } else {
            0.0
        }
    }
}

/// The keys in the form one blend method needs, prepared once per pose on the stack.
pub struct PreparedKeys {
    method: BlendMethod,
    /// Whether any key scales (otherwise the cheaper rigid paths are taken).
    scaled: bool,
    logs: [Bivector; MAX_KEYS],
    motors: [Motor; MAX_KEYS],
    log_scales: [f64; MAX_KEYS],
    quats: [(DQuat, DQuat); MAX_KEYS],
    affines: [DAffine3; MAX_KEYS],
}

impl PreparedKeys {
    /// Check the keys and prepare them for `method`.
    ///
    /// # Errors
    /// [`KeyError::TooMany`], or [`KeyError::Invalid`] naming the first key that is not a
    /// finite scaled motor.
    pub fn new(keys: &[ScaledMotor], method: BlendMethod) -> Result<Self> {
        if keys.len() > MAX_KEYS {
            return Err(KeyError::TooMany {
                got: keys.len(),
                max: MAX_KEYS,
            }
            .into());
        }
        let mut p = PreparedKeys {
            method,
            scaled: false,
            logs: [Bivector::default(); MAX_KEYS],
            motors: [Motor::IDENTITY; MAX_KEYS],
            log_scales: [0.0; MAX_KEYS],
            quats: [(DQuat::IDENTITY, DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)); MAX_KEYS],
            affines: [DAffine3::IDENTITY; MAX_KEYS],
        };
        for (j, k) in keys.iter().enumerate() {
            let log = k
                .try_log()
                .map_err(|source| KeyError::Invalid { index: j, source })?;
            p.logs[j] = log;
            p.log_scales[j] = 2.0 * log.eoi;
            p.scaled |= log.eoi != 0.0;
            if method != BlendMethod::MotorLog {
                let (s, q, t) = k.to_scale_rotation_translation();
                let q = q.normalize();
                let rigid = Motor::from_rotation_translation(q, t);
                p.motors[j] = rigid;
                let d = DQuat::from_vec4((0.5 * t).extend(0.0)) * q;
                p.quats[j] = (q, d);
                p.affines[j] = DAffine3::from_scale_rotation_translation(DVec3::splat(s), q, t);
            }
        }
        Ok(p)
    }

    /// The blend method.
    pub fn method(&self) -> BlendMethod {
        self.method
    }

    /// Apply the blend of keys `first ..` with weights `w` to the point `p`.
    #[inline]
    pub fn transform(&self, first: usize, w: &[f64], p: DVec3) -> DVec3 {
        match self.method {
            BlendMethod::MotorLog => {
                // exp of the blended generator, applied in its quaternion form (the motor's
                // action `M X ~M` without building M).
                let g = Bivector::weighted_sum(self.logs[first..].iter().copied(), w);
                g.exp_similarity().transform_point(p)
            }
            BlendMethod::MotorLinear => {
                let m = Motor::blend_linear(&self.motors[first..first + w.len()], w);
                m.transform_point(self.scale_of(first, w) * p)
            }
            BlendMethod::DualQuaternion => {
                let (q, t) = self.dual_quaternion_blend(first, w);
                q * (self.scale_of(first, w) * p) + t
            }
            BlendMethod::Matrix => self.affine_blend(first, w).transform_point3(p),
        }
    }

    /// The blended transform of keys `first ..` with weights `w` as an affine map (for the
    /// bind, which applies its inverse).
    pub fn affine(&self, first: usize, w: &[f64]) -> DAffine3 {
        match self.method {
            BlendMethod::MotorLog => {
                let g = Bivector::weighted_sum(self.logs[first..].iter().copied(), w);
                let (s, q, t) = g.exp_scaled().to_scale_rotation_translation();
                DAffine3::from_scale_rotation_translation(DVec3::splat(s), q.normalize(), t)
            }
            BlendMethod::MotorLinear => {
                let m = Motor::blend_linear(&self.motors[first..first + w.len()], w);
                let (q, t) = m.to_rotation_translation();
                let s = self.scale_of(first, w);
                DAffine3::from_scale_rotation_translation(DVec3::splat(s), q.normalize(), t)
            }
            BlendMethod::DualQuaternion => {
                let (q, t) = self.dual_quaternion_blend(first, w);
                let s = self.scale_of(first, w);
                DAffine3::from_scale_rotation_translation(DVec3::splat(s), q, t)
            }
            BlendMethod::Matrix => self.affine_blend(first, w),
        }
    }

    /// `exp(sum w ln s)`: the geometric blend of the key scales.
    #[inline]
    fn scale_of(&self, first: usize, w: &[f64]) -> f64 {
        if !self.scaled {
            return 1.0;
        }
        let l: f64 = w
            .iter()
            .zip(&self.log_scales[first..])
            .map(|(w, l)| w * l)
            .sum();
        l.exp()
    }

    /// Kavan's dual-quaternion linear blend: `(rotation, translation)`.
    #[inline]
    fn dual_quaternion_blend(&self, first: usize, w: &[f64]) -> (DQuat, DVec3) {
        let q0 = self.quats[first].0;
        let (mut r, mut d) = (r0(), r0());
        for (&(q, dq), &wk) in self.quats[first..].iter().zip(w) {
            let wk = if q.dot(q0) < 0.0 { -wk } else { wk };
            r += q * wk;
            d += dq * wk;
        }
        let n = r.length();
        let (r, d) = (r * (1.0 / n), d * (1.0 / n));
        let t = d * r.conjugate();
        (r, 2.0 * DVec3::new(t.x, t.y, t.z))
    }

    /// `sum w A`.
    #[inline]
    fn affine_blend(&self, first: usize, w: &[f64]) -> DAffine3 {
        let mut m = DMat3::ZERO;
        let mut t = DVec3::ZERO;
        for (a, &wk) in self.affines[first..].iter().zip(w) {
            m += a.matrix3 * wk;
            t += a.translation * wk;
        }
        DAffine3::from_mat3_translation(m, t)
    }
}

/// The zero quaternion.
#[inline]
fn r0() -> DQuat {
    DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)
}

/// Vertices below which posing stays on one thread (the split costs more than it saves).
const PARALLEL_MIN: usize = 2048;

/// A mesh bound to key weights: the rest points in the frame of their rest transform, ready to
/// be posed by any keys. The shared core of the spline and handle deformers.
#[derive(Clone, Debug)]
pub struct BoundBlend {
    weights: KeyWeights,
    /// `p'_i = M_i^-1 p_i`, with `M_i` the blend of the rest keys.
    local: Vec<DVec3>,
    method: BlendMethod,
}

impl BoundBlend {
    /// Bind `positions` with `weights` to the `rest` keys: `p'_i = M_i^-1 p_i` where `M_i` is
    /// the blend of the rest keys at vertex `i`.
    ///
    /// # Errors
    /// [`crate::Error::DimensionMismatch`], [`KeyError`] for bad rest keys,
    /// [`crate::Error::InvalidArgument`] when a blended rest transform is singular (possible
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
            .map(|(i, &p)| {
                let (f, w) = weights.row(i);
                let a = keys.affine(f, w);
                a.inverse().transform_point3(p)
            })
            .collect();
        if let Some(i) = local.iter().position(|p| !p.is_finite()) {
            return Err(crate::Error::InvalidArgument(format!(
                "vertex {i}: the blended rest transform is singular or overflows"
            )));
        }
        Ok(BoundBlend {
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

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.local.len()
    }

    /// Number of keys.
    pub fn key_count(&self) -> usize {
        self.weights.key_count()
    }

    /// `p_i = M_i p'_i` with `M_i` the blend of `keys` at vertex `i`: parallel, no allocation.
    ///
    /// # Errors
    /// As [`crate::Deformer::pose`].
    pub fn pose(&self, keys: &[ScaledMotor], out: &mut [DVec3]) -> Result<()> {
        check_key_count("this deformer", self.key_count(), keys.len())?;
        check_positions(self.vertex_count(), out.len())?;
        let prepared = PreparedKeys::new(keys, self.method)?;
        let one = |(i, o): (usize, &mut DVec3)| {
            let (f, w) = self.weights.row(i);
            *o = prepared.transform(f, w, self.local[i]);
        };
        if out.len() < PARALLEL_MIN {
            out.iter_mut().enumerate().for_each(one);
        } else {
            out.par_iter_mut()
                .enumerate()
                .with_min_len(1024)
                .for_each(one);
        }
        Ok(())
    }
}
