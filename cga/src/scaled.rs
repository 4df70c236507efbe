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
    /// [`CgaError::NonPositiveScale`] for `scale <= 0`, NaN or infinity;
    /// [`CgaError::Overflow`] for a scale this form cannot hold: `D` stores `cosh` and `sinh`
    /// of `ln(d)/2`, so the scale read back, `(s + eoi)/(s - eoi)`, loses about `eps * max(d,
    /// 1/d)` of relative precision. Scales whose read-back differs by more than the crate's
    /// versor tolerance (about `1e-10 < d < 1e10` passes in `f64`, `1e-3 < d < 1e3` in `f32`)
    /// are refused.
    pub fn try_from_scale(scale: S) -> Result<Self> {
        if !(scale > 0.0) || !scale.is_finite() {
            return Err(CgaError::NonPositiveScale);
        }
        let d = Self::from_scale(scale);
        let back = d.scale();
        if !all_finite(&d.to_array()) || !((back - scale).abs() <= TOL_VERSOR * scale) {
            return Err(CgaError::Overflow {
                what: "dilator (scale outside the range a dilator can hold)",
            });
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

/// The action of a scaled motor in quaternion form: `x -> scale * (rotation * x) +
/// translation` (the same map as the sandwich `S up(x) ~S`, down-projected). What
/// [`ScaledMotor::to_similarity`] and [`Bivector::exp_similarity`] return, for applying one
/// motion to many points at the cost of a quaternion rotation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Similarity {
    /// The uniform scale `d > 0`.
    pub scale: S,
    /// `ln(scale)`.
    pub log_scale: S,
    /// The rotation, a unit quaternion.
    pub rotation: Quat,
    /// The translation, applied last.
    pub translation: V3,
}

impl Similarity {
    /// `scale * (rotation * x) + translation`.
    #[inline]
    #[must_use]
    pub fn transform_point(&self, x: V3) -> V3 {
        self.rotation * (self.scale * x) + self.translation
    }
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
    /// [`CgaError::NonPositiveScale`], [`CgaError::NonFinite`], [`CgaError::ZeroAxis`],
    /// [`CgaError::Overflow`] (see [`Dilator::try_from_scale`]; also when the product
    /// overflows).
    pub fn try_from_scale_rotation_translation(
        scale: S,
        rotation: Quat,
        translation: V3,
    ) -> Result<Self> {
        let d = Dilator::try_from_scale(scale)?;
        let m = Motor::try_from_rotation_translation(rotation, translation)? * d;
        finite_result(
            m,
            &m.to_array(),
            "scaled motor (translation times scale overflows)",
        )
    }

    /// A rigid motion followed by nothing else: the same motion as a scaled motor.
    #[inline]
    #[must_use]
    pub fn from_motor(m: Motor) -> Self {
        m.into()
    }

    /// The decomposition into scale, rotation and translation, for a (multiple of a) scaled
    /// motor. The overall sign of the versor is irrelevant.
    #[must_use]
    pub fn to_similarity(self) -> Similarity {
        self.similarity()
    }

    /// See [`ScaledMotor::to_similarity`].
    pub(crate) fn similarity(self) -> Similarity {
        let (a2, p) = self.rotor_and_dilation();
        let th = p / a2; // tanh(g/2)
        let a = a2.sqrt();
        let rq = self.rotor_quat() * (1.0 / a);
        // The ei parts are (cosh - sinh) times those of the rigid motor T R.
        let f = 1.0 / (a * (1.0 - th));
        let dq = self.dual_quat_part() * f;
        let t = dq * rq.conjugate();
        let log_scale = ((a2 + p) / (a2 - p)).ln();
        Similarity {
            scale: (a2 + p) / (a2 - p),
            log_scale,
            rotation: rq,
            translation: 2.0 * V3::new(t.x, t.y, t.z),
        }
    }

    /// For `M = k T R D` (`D` of half log-scale `g/2`): the rotor part's squared norm
    /// `a^2 = k^2 cosh^2(g/2)` and its product with the dilation part, `p = k^2 cosh(g/2)
    /// sinh(g/2)`.
    #[inline]
    fn rotor_and_dilation(self) -> (S, S) {
        let a2 = self.s * self.s + self.e12 * self.e12 + self.e13 * self.e13 + self.e23 * self.e23;
        let p = self.s * self.eoi
            + self.e12 * self.eo12i
            + self.e13 * self.eo13i
            + self.e23 * self.eo23i;
        (a2, p)
    }

    /// The `eo` coefficient of `M up(x) ~M`, the same for every point `x`: `k^2 / d` for
    /// `M = k T R D` of scale `d`, computed in factored form, `(a^2 - p)^2 / a^2` (see
    /// [`ScaledMotor::point_matrix`] for the rest of the image). It keeps the precision of the
    /// scale itself (about `eps d` relative); the expanded entry of the point matrix loses
    /// about `eps d^2` (1e-6 at a scale of 1e5), which down-projection then divides by.
    #[inline]
    #[must_use]
    pub fn origin_weight(self) -> S {
        let (a2, p) = self.rotor_and_dilation();
        let q = a2 - p;
        q * q / a2
    }

    /// The rotation quaternion of the rotor part (not normalised here).
    #[inline]
    fn rotor_quat(self) -> Quat {
        rotor_quat([self.s, self.e12, self.e13, self.e23])
    }

    /// The dual quaternion part `(e1i, e2i, e3i, e123i)` (not normalised here).
    #[inline]
    fn dual_quat_part(self) -> Quat {
        dual_quat([self.e1i, self.e2i, self.e3i, self.e123i])
    }

    /// This scaled motor divided by the largest coefficient of its rotor part (the same
    /// similarity), after checking that it is a multiple of `T R D`: finite, a rotor part that
    /// is not zero and dominates the dilation part, the dilation part aligned with the rotor
    /// part, and a rigid part that is a motor.
    pub(crate) fn rescaled(self) -> Result<ScaledMotor> {
        let c = self.to_array();
        finite_input(&c, "scaled motor")?;
        let k = max_abs(&[self.s, self.e12, self.e13, self.e23]);
        if !(k > 0.0) {
            return Err(CgaError::NotAMotor {
                what: "scaled motor",
                why: "zero rotor part",
            });
        }
        precise_scale(
            k,
            "scaled motor (coefficients so small that its motion is lost)",
        )?;
        let m = ScaledMotor::from_array(c.map(|x| x / k));
        if !all_finite(&m.to_array()) {
            return Err(CgaError::Overflow {
                what: "scaled motor (too large for its rotor part)",
            });
        }
        let a2 = m.s * m.s + m.e12 * m.e12 + m.e13 * m.e13 + m.e23 * m.e23;
        let b2 = m.eoi * m.eoi + m.eo12i * m.eo12i + m.eo13i * m.eo13i + m.eo23i * m.eo23i;
        if !(a2 - b2 > 0.0) {
            return Err(CgaError::NotAMotor {
                what: "scaled motor",
                why: "rotor part dominated by the dilation part",
            });
        }
        // The scale is read back with a relative precision of about eps a2 / (a2 - b2)
        // (`eps max(d, 1/d)`): the same limit as `Dilator::try_from_scale`, a little wider.
        if !(S::EPSILON * a2 <= TOL_VERSOR * (a2 - b2)) {
            return Err(CgaError::Overflow {
                what: "scaled motor (scale outside the range a dilator can hold)",
            });
        }
        // The dilation part must be tanh(g/2) times the rotor part.
        let th = (m.s * m.eoi + m.e12 * m.eo12i + m.e13 * m.eo13i + m.e23 * m.eo23i) / a2;
        let dev = (m.eoi - th * m.s).abs()
            + (m.eo12i - th * m.e12).abs()
            + (m.eo13i - th * m.e13).abs()
            + (m.eo23i - th * m.e23).abs();
        if !(dev <= TOL_VERSOR) {
            return Err(CgaError::NotAMotor {
                what: "scaled motor",
                why: "dilation part not aligned with the rotor part",
            });
        }
        let rigid = Motor::from_quats(
            m.rotor_quat() * (1.0 / a2.sqrt()),
            m.dual_quat_part() * (1.0 / (a2.sqrt() * (1.0 - th))),
        );
        rigid.rescaled()?;
        Ok(m)
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
