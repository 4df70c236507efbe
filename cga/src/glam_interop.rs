//! Conversions between motors and glam: `(quaternion, translation)`, 4x4 matrices and affine
//! transforms. Rigid conversions from matrices check that the linear part is a rotation (to a
//! relative tolerance) and fail with [`CgaError::NotRigid`] otherwise.

use super::*;

/// Rotation of a 3x3 matrix, or why it is not one.
fn rotation_of(m: Mat3) -> Result<Quat> {
    if !m.is_finite() {
        return Err(CgaError::NonFinite { what: "matrix" });
    }
    let mtm = m.transpose() * m;
    let e = mtm - Mat3::IDENTITY;
    let err = e
        .x_axis
        .abs()
        .max_element()
        .max(e.y_axis.abs().max_element())
        .max(e.z_axis.abs().max_element());
    // `!(err <= tol)`: an overflowed (NaN or infinite) product fails too.
    if !(err <= TOL_MATRIX) || !mtm.is_finite() {
        return Err(CgaError::NotRigid {
            why: "linear part is not orthonormal (scale or shear)",
        });
    }
    if m.determinant() < 0.0 {
        return Err(CgaError::NotRigid {
            why: "linear part is a reflection",
        });
    }
    Ok(Quat::from_mat3(&m).normalize())
}

/// Uniform scale and rotation of a 3x3 matrix, or why it is not a similarity.
fn scaled_rotation_of(m: Mat3) -> Result<(S, Quat)> {
    if !m.is_finite() {
        return Err(CgaError::NonFinite { what: "matrix" });
    }
    let det = m.determinant();
    if !(det > 0.0) {
        return Err(CgaError::NonPositiveScale);
    }
    if !det.is_finite() {
        return Err(CgaError::Overflow {
            what: "determinant of the linear part",
        });
    }
    let s = det.cbrt();
    let q = rotation_of(m * (1.0 / s)).map_err(|_| CgaError::NotRigid {
        why: "linear part is not a uniformly scaled rotation",
    })?;
    Ok((s, q))
}

impl Motor {
    /// The 4x4 matrix of this (unit) motor.
    #[must_use]
    pub fn to_mat4(self) -> Mat4 {
        Mat4::from_rotation_translation(self.rotation().normalize(), self.translation())
    }

    /// The affine transform of this (unit) motor.
    #[must_use]
    pub fn to_affine(self) -> Affine {
        Affine::from_rotation_translation(self.rotation().normalize(), self.translation())
    }

    /// The motor of a rigid 4x4 matrix.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`]; [`CgaError::NotRigid`] for a projective last row, a scale, a
    /// shear or a reflection.
    pub fn try_from_mat4(m: Mat4) -> Result<Self> {
        if !m.is_finite() {
            return Err(CgaError::NonFinite { what: "matrix" });
        }
        let row3 = m.row(3);
        if !((row3 - Vec4::new(0.0, 0.0, 0.0, 1.0)).abs().max_element() <= TOL_MATRIX) {
            return Err(CgaError::NotRigid {
                why: "last row is not (0, 0, 0, 1)",
            });
        }
        let q = rotation_of(Mat3::from_mat4(m))?;
        let r = Self::from_rotation_translation(q, m.w_axis.truncate().into());
        finite_result(r, &r.to_array(), "motor of a matrix")
    }

    /// The motor of a rigid affine transform.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotRigid`].
    pub fn try_from_affine(a: Affine) -> Result<Self> {
        let q = rotation_of(Mat3::from(a.matrix3))?;
        let t = V3::from(a.translation);
        finite3(t, "translation")?;
        let r = Self::from_rotation_translation(q, t);
        finite_result(r, &r.to_array(), "motor of an affine transform")
    }
}

impl ScaledMotor {
    /// The 4x4 matrix `T * R * S` of this scaled motor.
    #[must_use]
    pub fn to_mat4(self) -> Mat4 {
        let (s, q, t) = self.to_scale_rotation_translation();
        Mat4::from_scale_rotation_translation(V3::splat(s), q.normalize(), t)
    }

    /// The scaled motor of a 4x4 matrix with a uniformly scaled rotation.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NonPositiveScale`], [`CgaError::NotRigid`] for
    /// non-uniform scale, shear, reflection or a projective row.
    pub fn try_from_mat4(m: Mat4) -> Result<Self> {
        if !m.is_finite() {
            return Err(CgaError::NonFinite { what: "matrix" });
        }
        let row3 = m.row(3);
        if !((row3 - Vec4::new(0.0, 0.0, 0.0, 1.0)).abs().max_element() <= TOL_MATRIX) {
            return Err(CgaError::NotRigid {
                why: "last row is not (0, 0, 0, 1)",
            });
        }
        let (s, q) = scaled_rotation_of(Mat3::from_mat4(m))?;
        Self::try_from_scale_rotation_translation(s, q, m.w_axis.truncate().into())
    }
}

impl From<(Quat, V3)> for Motor {
    /// `(rotation, translation)`: see [`Motor::from_rotation_translation`].
    fn from((q, t): (Quat, V3)) -> Self {
        Motor::from_rotation_translation(q, t)
    }
}

impl From<Motor> for (Quat, V3) {
    fn from(m: Motor) -> Self {
        m.to_rotation_translation()
    }
}

impl From<Motor> for Mat4 {
    fn from(m: Motor) -> Self {
        m.to_mat4()
    }
}

impl From<Motor> for Affine {
    fn from(m: Motor) -> Self {
        m.to_affine()
    }
}

impl TryFrom<Mat4> for Motor {
    type Error = CgaError;
    fn try_from(m: Mat4) -> Result<Self> {
        Motor::try_from_mat4(m)
    }
}

impl TryFrom<Affine> for Motor {
    type Error = CgaError;
    fn try_from(a: Affine) -> Result<Self> {
        Motor::try_from_affine(a)
    }
}

impl From<ScaledMotor> for Mat4 {
    fn from(m: ScaledMotor) -> Self {
        m.to_mat4()
    }
}

impl TryFrom<Mat4> for ScaledMotor {
    type Error = CgaError;
    fn try_from(m: Mat4) -> Result<Self> {
        ScaledMotor::try_from_mat4(m)
    }
}
