//! Dilators and scaled motors `T R D` (a rigid motion after a uniform scale about the origin).
//!
//! `D = cosh(g/2) + sinh(g/2) eo^ei` with `g = ln d` scales by `d > 0` about the origin. Its raw
//! sandwich of a point is not normalised (the weight becomes `1/d`), so every down-projection
//! here divides by `-X.ei`.

use super::*;

impl Dilator {
    /// The identity scaling.
    pub const IDENTITY: Dilator = Dilator::new(1.0, 0.0);

    /// The uniform scaling by `scale` about the origin. (`Dilator::new` is the generated
    /// coefficient constructor.) A non-positive or non-finite scale gives non-finite
    /// coefficients; see [`Dilator::try_from_scale`].
    #[inline]
    #[must_use]
    pub fn from_scale(scale: S) -> Self {
        let r = scale.sqrt();
        let ri = 1.0 / r;
        Dilator::new(0.5 * (r + ri), 0.5 * (r - ri))
    }

    /// [`Dilator::from_scale`] that rejects bad scales.
    ///
    /// # Errors
    /// [`CgaError::NonPositiveScale`] for `scale <= 0`, NaN, infinity, or a scale whose square
    /// root over- or underflows.
    pub fn try_from_scale(scale: S) -> Result<Self> {
        if !(scale > 0.0) || !scale.is_finite() || !scale.is_normal() {
            return Err(CgaError::NonPositiveScale);
        }
        let d = Self::from_scale(scale);
        if !d.s.is_finite() || !d.eoi.is_finite() {
            return Err(CgaError::NonPositiveScale);
        }
        Ok(d)
    }

    /// The scale factor `d = (s + eoi) / (s - eoi)`.
    #[inline]
    #[must_use]
    pub fn scale(self) -> S {
        (self.s + self.eoi) / (self.s - self.eoi)
    }

    /// Scale a point about the origin: `d x`.
    #[inline]
    #[must_use]
    pub fn transform_point(self, x: V3) -> V3 {
        self.sandwich(Point::from_vec3(x)).to_vec3()
    }
}

/// The parts of a scaled motor: `x -> scale * (rotation * x) + translation`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Similarity {
    pub scale: S,
    /// `ln(scale)`.
    pub log_scale: S,
    pub rotation: Quat,
    pub translation: V3,
}

impl ScaledMotor {
    /// The identity.
    pub const IDENTITY: ScaledMotor =
        ScaledMotor::new(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);

    /// `x -> scale * (rotation * x) + translation`, as `T R D`. See
    /// [`ScaledMotor::try_from_scale_rotation_translation`] for checked input.
    #[inline]
    #[must_use]
    pub fn from_scale_rotation_translation(scale: S, rotation: Quat, translation: V3) -> Self {
        Motor::from_rotation_translation(rotation, translation) * Dilator::from_scale(scale)
    }

    /// Checked [`ScaledMotor::from_scale_rotation_translation`].
    ///
    /// # Errors
    /// [`CgaError::NonPositiveScale`], [`CgaError::NonFinite`], [`CgaError::ZeroAxis`].
    pub fn try_from_scale_rotation_translation(
        scale: S,
        rotation: Quat,
        translation: V3,
    ) -> Result<Self> {
        let d = Dilator::try_from_scale(scale)?;
        Ok(Motor::try_from_rotation_translation(rotation, translation)? * d)
    }

    /// A rigid motion followed by nothing else: the same motion as a scaled motor.
    #[inline]
    #[must_use]
    pub fn from_motor(m: Motor) -> Self {
        m.into()
    }

    /// The decomposition into scale, rotation and translation, for a (multiple of a) scaled
    /// motor. The overall sign of the versor is irrelevant.
    pub(crate) fn similarity(self) -> Similarity {
        let a2 = self.s * self.s + self.e12 * self.e12 + self.e13 * self.e13 + self.e23 * self.e23;
        // k^2 cosh*sinh (g/2)
        let p = self.s * self.eoi
            + self.e12 * self.eo12i
            + self.e13 * self.eo13i
            + self.e23 * self.eo23i;
        let th = p / a2; // tanh(g/2)
        let a = a2.sqrt();
        let rq = Quat::from_xyzw(-self.e23, self.e13, -self.e12, self.s) * (1.0 / a);
        // The ei parts are (cosh - sinh) times those of the rigid motor T R.
        let f = 1.0 / (a * (1.0 - th));
        let dq = Quat::from_xyzw(-self.e1i, -self.e2i, -self.e3i, -self.e123i) * f;
        let t = dq * rq.conjugate();
        let log_scale = ((a2 + p) / (a2 - p)).ln();
        Similarity {
            scale: (a2 + p) / (a2 - p),
            log_scale,
            rotation: rq,
            translation: 2.0 * V3::new(t.x, t.y, t.z),
        }
    }

    /// Check that this is (a multiple of) a scaled motor `T R D`.
    pub(crate) fn check(self) -> Result<()> {
        let c = self.to_array();
        if !c.iter().all(|x| x.is_finite()) {
            return Err(CgaError::NonFinite {
                what: "scaled motor",
            });
        }
        let a2 = self.s * self.s + self.e12 * self.e12 + self.e13 * self.e13 + self.e23 * self.e23;
        let b2 = self.eoi * self.eoi
            + self.eo12i * self.eo12i
            + self.eo13i * self.eo13i
            + self.eo23i * self.eo23i;
        if !(a2 > S::MIN_POSITIVE) || !(a2 - b2 > TOL * a2) {
            return Err(CgaError::NotAMotor {
                what: "scaled motor",
                why: "rotor part zero or dominated by the dilation part",
            });
        }
        // The dilation part must be tanh(g/2) times the rotor part.
        let th = (self.s * self.eoi
            + self.e12 * self.eo12i
            + self.e13 * self.eo13i
            + self.e23 * self.eo23i)
            / a2;
        let dev = (self.eoi - th * self.s).abs()
            + (self.eo12i - th * self.e12).abs()
            + (self.eo13i - th * self.e13).abs()
            + (self.eo23i - th * self.e23).abs();
        let scale = c.iter().fold(0.0, |m: S, x| m.max(x.abs()));
        if dev > TOL_VERSOR * scale {
            return Err(CgaError::NotAMotor {
                what: "scaled motor",
                why: "dilation part not aligned with the rotor part",
            });
        }
        let sim = self.similarity();
        let rigid = Motor::from_quats(
            sim.rotation,
            Quat::from_xyzw(-self.e1i, -self.e2i, -self.e3i, -self.e123i)
                * (1.0 / (a2.sqrt() * (1.0 - th))),
        );
        rigid.check_motor()
    }

    /// The scale factor.
    #[inline]
    #[must_use]
    pub fn scale(self) -> S {
        self.similarity().scale
    }

    /// `(scale, rotation, translation)` with `x -> scale * (rotation * x) + translation`.
    #[inline]
    #[must_use]
    pub fn to_scale_rotation_translation(self) -> (S, Quat, V3) {
        let s = self.similarity();
        (s.scale, s.rotation, s.translation)
    }

    /// The rigid part `T R` (drops the scale).
    #[inline]
    #[must_use]
    pub fn rigid_part(self) -> Motor {
        let s = self.similarity();
        Motor::from_rotation_translation(s.rotation, s.translation)
    }

    /// Apply to a point: the raw sandwich, then down-projection dividing by `-X.ei`.
    #[inline]
    #[must_use]
    pub fn transform_point(self, x: V3) -> V3 {
        self.sandwich(Point::from_vec3(x)).to_vec3()
    }

    /// Apply to many points: one 3x4 affine map (`scale * rotation`, translation) per point.
    ///
    /// # Panics
    /// When `src` and `dst` differ in length.
    pub fn transform_points(self, src: &[V3], dst: &mut [V3]) {
        assert_eq!(src.len(), dst.len(), "transform_points: length mismatch");
        let sim = self.similarity();
        let m = Mat3::from_quat(sim.rotation) * sim.scale;
        let t = sim.translation;
        let r0 = [m.x_axis.x, m.y_axis.x, m.z_axis.x, 0.0, t.x];
        let r1 = [m.x_axis.y, m.y_axis.y, m.z_axis.y, 0.0, t.y];
        let r2 = [m.x_axis.z, m.y_axis.z, m.z_axis.z, 0.0, t.z];
        super::motor::affine_rows(&r0, &r1, &r2, src, dst);
    }

    /// `next * self`: apply `self` first, then `next`.
    #[inline]
    #[must_use]
    pub fn then(self, next: ScaledMotor) -> ScaledMotor {
        next * self
    }

    /// Renormalise so that `S ~S = 1` (the motion is unchanged).
    #[inline]
    #[must_use]
    pub fn normalize_similarity(self) -> ScaledMotor {
        let sim = self.similarity();
        ScaledMotor::from_scale_rotation_translation(sim.scale, sim.rotation, sim.translation)
    }
}
