//! Rigid motions `M = T R`: construction, composition, action on points (single and batch),
//! and exact renormalisation.
//!
//! A motor is a dual quaternion in disguise: with the rotor's quaternion `q_r` and the dual part
//! `q_d = 0.5 t q_r`, the coefficients are `s, e12, e13, e23 = q_r.w, -q_r.z, q_r.y, -q_r.x` and
//! `e1i, e2i, e3i, e123i = -q_d.x, -q_d.y, -q_d.z, -q_d.w`. Composition is the geometric
//! product: `(b * a)` applies `a` first, like `B * A` for matrices.

use super::*;

impl Motor {
    /// The identity motion.
    pub const IDENTITY: Motor = Motor::new(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);

    /// The motor of a (rotation, dual) quaternion pair, `q_d = 0.5 t q_r`.
    #[inline]
    #[must_use]
    pub(crate) fn from_quats(r: Quat, d: Quat) -> Self {
        let [s, e12, e13, e23] = rotor_coeffs(r);
        let [e1i, e2i, e3i, e123i] = dual_coeffs(d);
        Motor::new(s, e12, e13, e23, e1i, e2i, e3i, e123i)
    }

    /// The rotation quaternion `q_r` (not normalised here).
    #[inline]
    #[must_use]
    pub(crate) fn real_quat(self) -> Quat {
        rotor_quat([self.s, self.e12, self.e13, self.e23])
    }

    /// The dual quaternion part `q_d = 0.5 t q_r` (not normalised here).
    #[inline]
    #[must_use]
    pub(crate) fn dual_quat_part(self) -> Quat {
        dual_quat([self.e1i, self.e2i, self.e3i, self.e123i])
    }

    /// Rotate by `rotation` (a unit quaternion) about the origin, then translate by
    /// `translation`: `x -> rotation * x + translation`, i.e. `M = T R`.
    #[inline]
    #[must_use]
    pub fn from_rotation_translation(rotation: Quat, translation: V3) -> Self {
        let d = Quat::from_vec4((0.5 * translation).extend(0.0)) * rotation;
        Self::from_quats(rotation, d)
    }

    /// [`Motor::from_rotation_translation`] that checks its input and normalises the quaternion.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], or [`CgaError::ZeroAxis`] for a zero quaternion.
    pub fn try_from_rotation_translation(rotation: Quat, translation: V3) -> Result<Self> {
        finite3(translation, "translation")?;
        let r = Rotor::try_from_quat(rotation)?;
        let m = Self::from_rotation_translation(r.to_quat(), translation);
        finite_result(m, &m.to_array(), "motor (translation overflows)")
    }

    /// The pure translation by `t`.
    #[inline]
    #[must_use]
    pub fn from_translation(t: V3) -> Self {
        Translator::from_translation(t).into()
    }

    /// The rotation by `angle` about `axis` through the origin (see [`Rotor::from_axis_angle`]).
    #[inline]
    #[must_use]
    pub fn from_axis_angle(axis: V3, angle: S) -> Self {
        Rotor::from_axis_angle(axis, angle).into()
    }

    /// The rotation part as a unit quaternion (sign as stored).
    #[inline]
    #[must_use]
    pub fn rotation(self) -> Quat {
        self.real_quat()
    }

    /// The rotation part as a rotor.
    #[inline]
    #[must_use]
    pub fn rotor(self) -> Rotor {
        Rotor::new(self.s, self.e12, self.e13, self.e23)
    }

    /// The translation part `t` of `x -> R x + t` (`t = 2 q_d q_r*` for a unit motor).
    #[inline]
    #[must_use]
    pub fn translation(self) -> V3 {
        let t = self.dual_quat_part() * self.real_quat().conjugate();
        2.0 * V3::new(t.x, t.y, t.z)
    }

    /// `(rotation, translation)` with `x -> rotation * x + translation`.
    #[inline]
    #[must_use]
    pub fn to_rotation_translation(self) -> (Quat, V3) {
        (self.rotation(), self.translation())
    }

    /// Apply the motion to a point: `down(M up(x) ~M)` (fused sandwich). Assumes a unit motor.
    #[inline]
    #[must_use]
    pub fn transform_point(self, x: V3) -> V3 {
        self.sandwich(Point::from_vec3(x)).to_vec3()
    }

    /// Apply the rotation part only (for directions and normals).
    #[inline]
    #[must_use]
    pub fn transform_vector(self, v: V3) -> V3 {
        self.rotor().transform_point(v)
    }

    /// Apply the motion to many points through its matrix form ([`Motor::point_matrix`]): one
    /// 3x4 affine map per point, the cost of `DMat4::transform_point3`.
    ///
    /// # Panics
    /// When `src` and `dst` differ in length (see [`Motor::try_transform_points`]).
    pub fn transform_points(self, src: &[V3], dst: &mut [V3]) {
        assert_eq!(src.len(), dst.len(), "transform_points: length mismatch");
        let m = self.point_matrix().rows();
        affine_rows(&m[0], &m[1], &m[2], src, dst);
    }

    /// [`Motor::transform_points`] without the panic, for any finite multiple of a motor
    /// (normalised first), with every output point checked.
    ///
    /// # Errors
    /// [`CgaError::Degenerate`] when the slices differ in length; the errors of
    /// [`Motor::try_normalize_rigid`]; [`CgaError::NonFinite`] for a non-finite source point;
    /// [`CgaError::Overflow`] when a moved point overflows (`dst` then holds partial results).
    pub fn try_transform_points(self, src: &[V3], dst: &mut [V3]) -> Result<()> {
        if src.len() != dst.len() {
            return Err(CgaError::Degenerate {
                why: "source and destination lengths differ",
            });
        }
        let m = self.try_normalize_rigid()?;
        m.transform_points(src, dst);
        if !dst.iter().all(|p| p.is_finite()) {
            if !src.iter().all(|p| p.is_finite()) {
                return Err(CgaError::NonFinite { what: "point" });
            }
            return Err(CgaError::Overflow {
                what: "transformed point",
            });
        }
        Ok(())
    }

    /// `next * self`: the motion that applies `self` first, then `next`.
    #[inline]
    #[must_use]
    pub fn then(self, next: Motor) -> Motor {
        next * self
    }

    /// The inverse motion of a unit motor (its reverse).
    #[inline]
    #[must_use]
    pub fn inverse_motion(self) -> Motor {
        self.rev()
    }

    /// Twice the `e123i` part of `M ~M`: zero exactly for motors (the versor condition).
    #[inline]
    #[must_use]
    pub fn versor_defect(self) -> S {
        self.s * self.e123i - self.e12 * self.e3i + self.e13 * self.e2i - self.e23 * self.e1i
    }

    /// Exact renormalisation `M / sqrt(M ~M)`, with `M ~M = a + b e123i` a dual number: the
    /// result satisfies `M ~M = 1` (both parts), which plain division by the norm does not.
    #[inline]
    #[must_use]
    pub fn normalize_rigid(self) -> Motor {
        let a = self.norm_squared();
        let b = 2.0 * self.versor_defect();
        // 1/sqrt(a + eps b) = a^-1/2 (1 - eps b/(2a)) with eps = e123i; M = q_r - eps q_d, so
        // M (p + eps q) has real part p q_r and dual part p q_d - q q_r.
        let p = 1.0 / a.sqrt();
        // p / a = p^3: one division fewer (this runs once per vertex in motor blending).
        let q = -0.5 * b * (p * p * p);
        let (r, d) = (self.real_quat(), self.dual_quat_part());
        Self::from_quats(r * p, d * p - r * q)
    }

    /// Divide by the norm of the rotor part only, `M / sqrt(<M ~M>_0)`, leaving the `e123i`
    /// defect of `M ~M` in place: the cheap normalisation for a motor that is only applied to
    /// points (as Kavan's dual-quaternion skinning divides by `|q_r|` only).
    ///
    /// The result's [`Motor::transform_point`] equals that of [`Motor::normalize_rigid`]: with
    /// `M = q_r - eps q_d`, the defect is the part of `q_d` along `q_r`, and the translation
    /// `2 vec(q_d ~q_r)` does not see it. Anything else (composition, `log`, `M ~M = 1`) needs
    /// [`Motor::normalize_rigid`].
    #[inline]
    #[must_use]
    pub fn normalize_for_points(self) -> Motor {
        let p = 1.0 / self.norm_squared().sqrt();
        Motor::from_array(self.to_array().map(|c| c * p))
    }

    /// [`Motor::normalize_rigid`] that rejects non-motors.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotAMotor`] when the rotor part is zero or the
    /// versor condition fails by more than a relative tolerance, [`CgaError::Overflow`] when
    /// the translation is too large for the rotor part. Huge and tiny multiples of a motor
    /// (`1e300 M`, `1e-310 M`) are accepted: they are the same motion.
    pub fn try_normalize_rigid(self) -> Result<Motor> {
        let m = self.rescaled()?.normalize_rigid();
        finite_result(m, &m.to_array(), "normalised motor")
    }

    /// This motor divided by the largest coefficient of its rotor part (the same motion, with
    /// a rotor part of order 1), after checking that it is a multiple of a motor: finite, a
    /// rotor part that is not zero, and the versor condition `M ~M` scalar (its `e123i` part
    /// zero to a relative tolerance). Scaling first makes the check work for any finite
    /// multiple, `1e300 M` and `1e-310 M` included.
    pub(crate) fn rescaled(self) -> Result<Motor> {
        let c = self.to_array();
        finite_input(&c, "motor")?;
        let k = max_abs(&c[..4]);
        if !(k > 0.0) {
            return Err(CgaError::NotAMotor {
                what: "motor",
                why: "zero rotor part",
            });
        }
        precise_scale(k, "motor (coefficients so small that its motion is lost)")?;
        let m = Motor::from_array(c.map(|x| x / k));
        let c = m.to_array();
        if !all_finite(&c) {
            return Err(CgaError::Overflow {
                what: "motor (translation too large for its rotor part)",
            });
        }
        // The check in units of the dual part when it is large, so that it cannot overflow.
        let a = m.norm_squared();
        let dk = max_abs(&c[4..]).max(1.0);
        let d = [c[4] / dk, c[5] / dk, c[6] / dk, c[7] / dk];
        let dual2: S = d.iter().map(|x| x * x).sum();
        let defect = Motor::new(c[0], c[1], c[2], c[3], d[0], d[1], d[2], d[3]).versor_defect();
        let tol = TOL_VERSOR * (a * (a / (dk * dk) + dual2)).sqrt();
        if !(defect.abs() <= tol) {
            return Err(CgaError::NotAMotor {
                what: "motor",
                why: "M ~M has a grade-4 part (not a versor)",
            });
        }
        Ok(m)
    }
}

/// `dst[i] = (r0 . p, r1 . p, r2 . p)` with rows `[m_x, m_y, m_z, _, m_const]`: a 3x4 affine map.
#[inline]
pub(crate) fn affine_rows(r0: &[S; 5], r1: &[S; 5], r2: &[S; 5], src: &[V3], dst: &mut [V3]) {
    // glam's matrix (SIMD in f32) applies the rows; columns are e1, e2, e3, translation.
    let m = Mat4::from_cols_array(&[
        r0[0], r1[0], r2[0], 0.0, r0[1], r1[1], r2[1], 0.0, r0[2], r1[2], r2[2], 0.0, r0[4], r1[4],
        r2[4], 1.0,
    ]);
    for (o, p) in dst.iter_mut().zip(src) {
        *o = m.transform_point3(*p);
    }
}

impl From<Translator> for V3 {
    #[inline]
    fn from(t: Translator) -> Self {
        t.translation()
    }
}
