//! A node's local transform as glTF stores it: translation, rotation, scale.

use super::SkinError;
use cga::ScaledMotor;
use glam::{DMat4, DQuat, DVec3};

/// Relative tolerance within which a scale counts as uniform (a similarity).
pub(crate) const UNIFORM_SCALE_TOLERANCE: f64 = 1e-4;

/// Relative difference between a matrix and its `T R S` decomposition up to which the matrix
/// counts as decomposable: single-precision rounding, as exporters leave it.
pub(crate) const DECOMPOSITION_NOISE: f64 = 1e-5;

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
    /// is not `T R S` (shear, projection) beyond single-precision rounding (a relative 1e-5):
    /// glTF requires node matrices to be decomposable.
    pub fn from_matrix(m: &DMat4, what: &str) -> Result<Trs, SkinError> {
        let (trs, residual) = Trs::decompose(m, what)?;
        if residual > DECOMPOSITION_NOISE {
            return Err(SkinError::BadTransform {
                what: what.to_string(),
                message: format!(
                    "not a translation * rotation * scale (shear or projection: it differs \
                     from its decomposition by {residual:.1e} of its largest entry)"
                ),
            });
        }
        Ok(trs)
    }

    /// Decompose a matrix into `T R S` as viewers do (three.js's `Matrix4.decompose`: the
    /// scales are the column lengths, the first negated for a mirror, the rotation that of the
    /// normalised columns), with the largest difference between the matrix and the
    /// decomposition's, relative to the matrix's largest entry: about 1e-7 for a decomposable
    /// matrix stored in single precision, more for shear or projection.
    ///
    /// # Errors
    /// [`SkinError::BadTransform`] for a non-finite matrix or one with a zero scale.
    pub fn decompose(m: &DMat4, what: &str) -> Result<(Trs, f64), SkinError> {
        let bad = |message: &str| SkinError::BadTransform {
            what: what.to_string(),
            message: message.to_string(),
        };
        if !m.is_finite() {
            return Err(bad("not finite"));
        }
        let (scale, rotation, translation) = scale_rotation_translation(m);
        let trs = Trs {
            translation,
            rotation: rotation.normalize(),
            scale,
        };
        if scale.min_element().abs() <= f64::MIN_POSITIVE || !trs.rotation.is_finite() {
            return Err(bad("singular (zero scale)"));
        }
        let norm = m
            .abs()
            .to_cols_array()
            .iter()
            .fold(0.0f64, |a, &b| a.max(b));
        let err = (trs.matrix() - *m)
            .abs()
            .to_cols_array()
            .iter()
            .fold(0.0f64, |a, &b| a.max(b));
        Ok((trs, err / norm.max(f64::MIN_POSITIVE)))
    }

    /// The uniform scale (their geometric mean, taken without overflow), when the three scales agree within a
    /// relative 1e-4 (single-precision files carry noise of about 1e-6).
    pub fn uniform_scale(&self) -> Option<f64> {
        let s = self.scale;
        let m = s.abs().max_element();
        (s.min_element() > 0.0 && m - s.min_element() <= UNIFORM_SCALE_TOLERANCE * m)
            .then(|| s.x.cbrt() * s.y.cbrt() * s.z.cbrt())
    }

    /// The transform as a scaled motor `T R D`.
    ///
    /// # Errors
    /// [`SkinError::NotSimilarity`] for a non-uniform or negative scale;
    /// [`SkinError::BadTransform`] for a similarity beyond a scaled motor's range (a scale
    /// past about `1e10` or under `1e-10`, a translation that overflows with it).
    pub fn motor(&self, what: &str) -> Result<ScaledMotor, SkinError> {
        let s = self
            .uniform_scale()
            .ok_or_else(|| SkinError::NotSimilarity {
                what: what.to_string(),
                message: format!("scale {:?}", self.scale),
            })?;
        ScaledMotor::try_from_scale_rotation_translation(s, self.rotation, self.translation)
            .map_err(|e| SkinError::BadTransform {
                what: what.to_string(),
                message: format!(
                    "a similarity of scale {s:e} that a scaled motor cannot hold: {e}"
                ),
            })
    }
}

/// `m` as scale, rotation and translation, like glam's `to_scale_rotation_translation` but
/// without its squares: each axis is divided by its largest component before its length is
/// taken, so that scales near the ends of the f64 range (1e300, 1e-300) are measured, not
/// overflowed to infinity or flushed to zero. A zero axis gives a zero scale and a NaN
/// rotation.
fn scale_rotation_translation(m: &DMat4) -> (DVec3, DQuat, DVec3) {
    let axes = [
        m.x_axis.truncate(),
        m.y_axis.truncate(),
        m.z_axis.truncate(),
    ];
    let unit = axes.map(|a| {
        let big = a.abs().max_element();
        if big == 0.0 {
            return (DVec3::NAN, 0.0);
        }
        let a = a / big;
        (a.normalize(), big * a.length())
    });
    let sign = unit[0].0.cross(unit[1].0).dot(unit[2].0).signum();
    let scale = DVec3::new(sign * unit[0].1, unit[1].1, unit[2].1);
    let rotation = DQuat::from_mat3(&glam::DMat3::from_cols(
        sign * unit[0].0,
        unit[1].0,
        unit[2].0,
    ));
    (scale, rotation, m.w_axis.truncate())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scales_near_the_ends_of_the_range_are_measured() {
        let rotation = DQuat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0);
        for s in [1e300, 1e200, 1e-200, 1e-300, 1.0, -2.0] {
            let t = Trs {
                translation: DVec3::new(1.0, -2.0, 3.0),
                rotation,
                scale: DVec3::new(s, s, s),
            };
            let back = Trs::from_matrix(&t.matrix(), "x").unwrap();
            let m = t.matrix();
            let err = (back.matrix() - m).abs().to_cols_array();
            assert!(err.iter().all(|e| *e <= 1e-14 * s.abs().max(3.0)), "{s}");
            assert_eq!(back.translation, t.translation);
            if s > 0.0 {
                let u = back.uniform_scale().unwrap();
                assert!((u - s).abs() <= 1e-14 * s, "{s}: uniform {u}");
                assert!(
                    ((back.scale - t.scale) / s).abs().max_element() < 1e-14,
                    "{s}"
                );
                let turn = back.rotation * rotation.conjugate();
                assert!(turn.w.abs() > 1.0 - 1e-14, "{s}: {turn:?}");
            }
        }
        let mut zero = DMat4::IDENTITY;
        zero.y_axis = glam::DVec4::ZERO;
        let e = Trs::from_matrix(&zero, "x").unwrap_err().to_string();
        assert!(e.contains("singular"), "{e}");
        let far = Trs {
            scale: DVec3::splat(1e300),
            ..Trs::IDENTITY
        };
        let e = far.motor("x").unwrap_err().to_string();
        assert!(e.starts_with("x: a similarity of scale 1e300"), "{e}");
        let shear = DMat4::from_cols_array(&[
            1.0, 0.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ]);
        let e = Trs::from_matrix(&shear, "x").unwrap_err().to_string();
        assert!(e.contains("shear"), "{e}");
    }
}
