//! A node's local transform as glTF stores it: translation, rotation, scale.

use super::SkinError;
use cga::ScaledMotor;
use glam::{DMat4, DQuat, DVec3};

/// Relative tolerance within which a scale counts as uniform (a similarity).
pub(crate) const UNIFORM_SCALE_TOLERANCE: f64 = 1e-4;

/// A node's local transform: `T * R * S` applied to a point (glTF's order).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trs {
    /// Translation.
    pub translation: DVec3,
    /// Rotation (unit quaternion).
    pub rotation: DQuat,
    /// Scale per axis.
    pub scale: DVec3,
}

impl Default for Trs {
    fn default() -> Self {
        Trs::IDENTITY
    }
}

impl Trs {
    /// The identity.
    pub const IDENTITY: Trs = Trs {
        translation: DVec3::ZERO,
        rotation: DQuat::IDENTITY,
        scale: DVec3::ONE,
    };

    /// The matrix `T R S`.
    pub fn matrix(&self) -> DMat4 {
        DMat4::from_scale_rotation_translation(self.scale, self.rotation, self.translation)
    }

    /// Decompose a matrix into `T R S`.
    ///
    /// # Errors
    /// [`SkinError::BadTransform`] for a non-finite matrix, one with a zero scale, or one that
    /// is not `T R S` (shear, projection): glTF requires node matrices to be decomposable.
    pub fn from_matrix(m: &DMat4, what: &str) -> Result<Trs, SkinError> {
        let bad = |message: &str| SkinError::BadTransform {
            what: what.to_string(),
            message: message.to_string(),
        };
        if !m.is_finite() {
            return Err(bad("not finite"));
        }
        let (scale, rotation, translation) = m.to_scale_rotation_translation();
        let trs = Trs {
            translation,
            rotation: rotation.normalize(),
            scale,
        };
        let norm = m
            .abs()
            .to_cols_array()
            .iter()
            .fold(0.0f64, |a, &b| a.max(b));
        let back = trs.matrix();
        let err = (back - *m)
            .abs()
            .to_cols_array()
            .iter()
            .fold(0.0f64, |a, &b| a.max(b));
        if scale.min_element().abs() <= f64::MIN_POSITIVE || !trs.rotation.is_finite() {
            return Err(bad("singular (zero scale)"));
        }
        if err > 1e-6 * norm.max(1.0) {
            return Err(bad(
                "not a translation * rotation * scale (shear or projection)",
            ));
        }
        Ok(trs)
    }

    /// The uniform scale (their geometric mean), when the three scales agree within a
    /// relative 1e-4 (single-precision files carry noise of about 1e-6).
    pub fn uniform_scale(&self) -> Option<f64> {
        let s = self.scale;
        let m = s.abs().max_element();
        (s.min_element() > 0.0 && m - s.min_element() <= UNIFORM_SCALE_TOLERANCE * m)
            .then(|| (s.x * s.y * s.z).cbrt())
    }

    /// The transform as a scaled motor `T R D`.
    ///
    /// # Errors
    /// [`SkinError::NotSimilarity`] for a non-uniform or negative scale.
    pub fn motor(&self, what: &str) -> Result<ScaledMotor, SkinError> {
        let s = self
            .uniform_scale()
            .ok_or_else(|| SkinError::NotSimilarity {
                what: what.to_string(),
                message: format!("scale {:?}", self.scale),
            })?;
        ScaledMotor::try_from_scale_rotation_translation(s, self.rotation, self.translation)
            .map_err(|e| SkinError::NotSimilarity {
                what: what.to_string(),
                message: e.to_string(),
            })
    }
}
