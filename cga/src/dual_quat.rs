//! A unit dual quaternion on glam quaternions, `real + eps dual` with `dual = 0.5 t real`, and
//! its exact correspondence with [`Motor`] (a sign map of the coefficients).

use super::*;

/// A unit dual quaternion `real + eps dual` (`dual = 0.5 t real`): the rigid motion
/// `x -> real x real* + t`, the form used by dual-quaternion skinning.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DualQuat {
    /// The rotation quaternion.
    pub real: Quat,
    /// The dual part `0.5 t real`.
    pub dual: Quat,
}

impl DualQuat {
    /// The identity.
    pub const IDENTITY: DualQuat = DualQuat {
        real: Quat::IDENTITY,
        dual: Quat::from_xyzw(0.0, 0.0, 0.0, 0.0),
    };

    /// `x -> rotation x + translation`.
    #[must_use]
    pub fn from_rotation_translation(rotation: Quat, translation: V3) -> Self {
        DualQuat {
            real: rotation,
            dual: Quat::from_vec4((0.5 * translation).extend(0.0)) * rotation,
        }
    }

    /// `(rotation, translation)`.
    #[must_use]
    pub fn to_rotation_translation(self) -> (Quat, V3) {
        let t = self.dual * self.real.conjugate();
        (self.real, 2.0 * V3::new(t.x, t.y, t.z))
    }

    /// Apply to a point.
    #[must_use]
    pub fn transform_point(self, x: V3) -> V3 {
        let (q, t) = self.to_rotation_translation();
        q * x + t
    }

    /// Exact normalisation (unit real part, dual part orthogonal to it).
    #[must_use]
    pub fn normalize(self) -> Self {
        Motor::from(self).normalize_rigid().into()
    }
}

impl core::ops::Mul for DualQuat {
    type Output = DualQuat;
    /// Composition: `(a * b)` applies `b` first.
    fn mul(self, b: DualQuat) -> DualQuat {
        DualQuat {
            real: self.real * b.real,
            dual: self.real * b.dual + self.dual * b.real,
        }
    }
}

impl From<Motor> for DualQuat {
    fn from(m: Motor) -> Self {
        DualQuat {
            real: m.real_quat(),
            dual: m.dual_quat_part(),
        }
    }
}

impl From<DualQuat> for Motor {
    fn from(d: DualQuat) -> Self {
        Motor::from_quats(d.real, d.dual)
    }
}
