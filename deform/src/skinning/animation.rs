//! Animations: keyframed node translations, rotations and scales, sampled at any time.
//!
//! Sampling follows glTF 2.0: times before the first key or after the last clamp to them;
//! `LINEAR` lerps translations and scales and slerps rotations along the shortest path
//! (keyframe quaternions are normalised first, as the specification requires unit keys);
//! `STEP` holds the last key at or before the time; `CUBICSPLINE` is the Hermite spline with
//! the in and out tangents scaled by the key interval, rotations normalised after.
//!
//! [`KeyframeBlend::MotorLog`] instead blends a node's two neighbouring keyframes as motors,
//! `M_1 exp(a log(M_1^-1 M_2))` (the paper's logarithmic blending of existing keyframes).

use super::{SkinError, Trs};
use cga::ScaledMotor;
use glam::{DQuat, DVec3, DVec4};

/// How a sampler interpolates between keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// Linear (slerp for rotations).
    Linear,
    /// Constant until the next key.
    Step,
    /// Cubic Hermite with stored tangents.
    CubicSpline,
}

/// The node property a channel animates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Property {
    /// Translation (3 values per key).
    Translation,
    /// Rotation (a quaternion `x, y, z, w` per key).
    Rotation,
    /// Scale (3 values per key).
    Scale,
}

/// How keyframes are blended in between.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum KeyframeBlend {
    /// Each property by its sampler, as glTF specifies (the default; what viewers show).
    #[default]
    Gltf,
    /// Logarithmic blending of the node's neighbouring keyframes as motors (the paper's
    /// choice for existing keyframes). Falls back to [`KeyframeBlend::Gltf`] for a node
    /// whose keyframes are not similarities.
    MotorLog,
}

/// One animated property of one node.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// The target node.
    pub node: usize,
    /// The property.
    pub property: Property,
    /// The interpolation.
    pub interpolation: Interpolation,
    /// Key times, strictly increasing.
    pub times: Vec<f64>,
    /// Key values as `x, y, z, w` (`w = 0` for vectors); for [`Interpolation::CubicSpline`]
    /// three per key: in-tangent, value, out-tangent.
    pub values: Vec<DVec4>,
}

/// A named set of channels.
#[derive(Clone, Debug, PartialEq)]
pub struct Animation {
    /// Its name (`animation N` when the file gives none).
    pub name: String,
    /// Its channels.
    pub channels: Vec<Channel>,
}

impl Channel {
    /// Check the keys: at least one, strictly increasing finite times, finite values, the
    /// right number of values; rotation keys are normalised (non-zero).
    ///
    /// # Errors
    /// [`SkinError::BadTransform`] naming the channel.
    pub fn new(
        node: usize,
        property: Property,
        interpolation: Interpolation,
        times: Vec<f64>,
        mut values: Vec<DVec4>,
        what: &str,
    ) -> Result<Channel, SkinError> {
        let bad = |message: String| SkinError::BadTransform {
            what: what.to_string(),
            message,
        };
        if times.is_empty() {
            return Err(bad("no keyframes".into()));
        }
        if let Some(k) = times.iter().position(|t| !t.is_finite()) {
            return Err(bad(format!("key {k}: time is not finite")));
        }
        if let Some(k) = times.windows(2).position(|w| w[1] <= w[0]) {
            return Err(bad(format!("key {}: times do not increase", k + 1)));
        }
        let per_key = if interpolation == Interpolation::CubicSpline {
            3
        } else {
            1
        };
        if values.len() != times.len() * per_key {
            return Err(bad(format!(
                "{} values for {} keys",
                values.len(),
                times.len()
            )));
        }
        if let Some(k) = values.iter().position(|v| !v.is_finite()) {
            return Err(bad(format!("key {}: value is not finite", k / per_key)));
        }
        if property == Property::Rotation {
            for (k, v) in values.iter_mut().enumerate() {
                let is_value = per_key == 1 || k % 3 == 1;
                if is_value {
                    let n = v.length();
                    if n.is_nan() || n <= 1e-12 {
                        return Err(bad(format!(
                            "key {}: zero rotation quaternion",
                            k / per_key
                        )));
                    }
                    *v /= n;
                }
            }
        }
        Ok(Channel {
            node,
            property,
            interpolation,
            times,
            values,
        })
    }

    /// The first and last key times.
    pub fn range(&self) -> (f64, f64) {
        (self.times[0], self.times[self.times.len() - 1])
    }

    /// The key value `k` (the value, not a tangent, for cubic splines).
    fn value(&self, k: usize) -> DVec4 {
        match self.interpolation {
            Interpolation::CubicSpline => self.values[3 * k + 1],
            _ => self.values[k],
        }
    }

    /// The key interval holding `t` (clamped) and the fraction within it.
    fn locate(&self, t: f64) -> (usize, f64) {
        let n = self.times.len();
        let (t0, t1) = self.range();
        // NaN is not after the first key: it gets the first key, never an index before it.
        if n == 1 || t <= t0 || t.is_nan() {
            return (0, 0.0);
        }
        if t >= t1 {
            return (n - 1, 0.0);
        }
        let k = self.times.partition_point(|&x| x <= t) - 1;
        let a = (t - self.times[k]) / (self.times[k + 1] - self.times[k]);
        (k, a)
    }

    /// The interpolated value at time `t`.
    pub fn sample(&self, t: f64) -> DVec4 {
        let (k, a) = self.locate(t);
        if a == 0.0 || self.interpolation == Interpolation::Step {
            return self.value(k);
        }
        let (v0, v1) = (self.value(k), self.value(k + 1));
        match (self.interpolation, self.property) {
            (Interpolation::Linear, Property::Rotation) => {
                let q = DQuat::from_vec4(v0).slerp(DQuat::from_vec4(v1), a);
                DVec4::from(q)
            }
            (Interpolation::Linear, _) => v0.lerp(v1, a),
            (_, p) => {
                let dt = self.times[k + 1] - self.times[k];
                let b0 = self.values[3 * k + 2] * dt;
                let a1 = self.values[3 * (k + 1)] * dt;
                let (a2, a3) = (a * a, a * a * a);
                let v = v0 * (2.0 * a3 - 3.0 * a2 + 1.0)
                    + b0 * (a3 - 2.0 * a2 + a)
                    + v1 * (-2.0 * a3 + 3.0 * a2)
                    + a1 * (a3 - a2);
                if p == Property::Rotation {
                    v.normalize_or(v0)
                } else {
                    v
                }
            }
        }
    }

    /// Write the value at `t` into the node's transform.
    fn apply(&self, value: DVec4, trs: &mut Trs) {
        match self.property {
            Property::Translation => trs.translation = value.truncate(),
            Property::Rotation => trs.rotation = DQuat::from_vec4(value),
            Property::Scale => trs.scale = value.truncate(),
        }
    }
}

impl Animation {
    /// The first and last key times over every channel (`(0, 0)` without channels).
    pub fn range(&self) -> (f64, f64) {
        self.channels
            .iter()
            .map(Channel::range)
            .reduce(|a, b| (a.0.min(b.0), a.1.max(b.1)))
            .unwrap_or((0.0, 0.0))
    }

    /// Overwrite the animated properties of `locals` (one per node) with their values at `t`.
    pub fn apply(&self, t: f64, blend: KeyframeBlend, locals: &mut [Trs]) {
        for c in &self.channels {
            c.apply(c.sample(t), &mut locals[c.node]);
        }
        if blend == KeyframeBlend::MotorLog {
            self.apply_motor_log(t, locals);
        }
    }

    /// Re-blend each animated node between its neighbouring keyframes (over all its channels)
    /// as motors: `M_1 exp(a log(M_1^-1 M_2))`.
    fn apply_motor_log(&self, t: f64, locals: &mut [Trs]) {
        let mut nodes: Vec<usize> = self.channels.iter().map(|c| c.node).collect();
        nodes.sort_unstable();
        nodes.dedup();
        for node in nodes {
            let channels = || self.channels.iter().filter(move |c| c.node == node);
            let before = channels()
                .flat_map(|c| c.times.iter().copied().filter(|&x| x <= t))
                .fold(f64::NEG_INFINITY, f64::max);
            let after = channels()
                .flat_map(|c| c.times.iter().copied().filter(|&x| x > t))
                .fold(f64::INFINITY, f64::min);
            if !before.is_finite() || !after.is_finite() {
                continue;
            }
            let at = |time: f64| {
                let mut trs = locals[node];
                for c in channels() {
                    c.apply(c.sample(time), &mut trs);
                }
                trs
            };
            let (k0, k1) = (at(before), at(after));
            let (Ok(m0), Ok(m1)) = (k0.motor("key"), k1.motor("key")) else {
                continue;
            };
            let m = ScaledMotor::interpolate(m0, m1, (t - before) / (after - before));
            let (s, q, tr) = m.to_scale_rotation_translation();
            locals[node] = Trs {
                translation: tr,
                rotation: q.normalize(),
                scale: DVec3::splat(s),
            };
        }
    }
}
