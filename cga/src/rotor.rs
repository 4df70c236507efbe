//! Rotors and translators: construction from axis/angle, quaternions and vectors.
//!
//! A rotor `R = cos(a/2) - sin(a/2) B` with `B = n I3 = n1 e23 - n2 e13 + n3 e12` rotates by `a`
//! about the unit axis `n` (right-hand rule). It is the quaternion `w + x i + y j + z k` with
//! `s = w`, `e12 = -z`, `e13 = y`, `e23 = -x`. A translator `T = 1 - 0.5 t ei` translates by `t`.

use super::*;

impl Rotor {
    /// The identity rotation.
    pub const IDENTITY: Rotor = Rotor::new(1.0, 0.0, 0.0, 0.0);

    /// The rotation by `angle` (radians, right-hand rule) about `axis`. The axis is normalised
    /// here (any finite length, `1e300` and `1e-310` included); a zero or non-finite axis gives
    /// the identity (see [`Rotor::try_from_axis_angle`]).
    #[inline]
    #[must_use]
    pub fn from_axis_angle(axis: V3, angle: S) -> Self {
        let Some(n) = unit_direction(axis) else {
            return Self::IDENTITY;
        };
        let (sn, c) = (0.5 * angle).sin_cos();
        Self::from_quat(Quat::from_xyzw(sn * n.x, sn * n.y, sn * n.z, c))
    }

    /// [`Rotor::from_axis_angle`] that rejects bad input.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] for a non-finite axis or angle, [`CgaError::ZeroAxis`] for a
    /// zero axis.
    pub fn try_from_axis_angle(axis: V3, angle: S) -> Result<Self> {
        finite_input(&[angle], "rotation angle")?;
        try_unit_direction(axis, "rotation axis")?;
        Ok(Self::from_axis_angle(axis, angle))
    }

    /// The rotor of a unit quaternion (not normalised here).
    #[inline]
    #[must_use]
    pub fn from_quat(q: Quat) -> Self {
        Rotor::from_array(rotor_coeffs(q))
    }

    /// The rotor of a quaternion of any finite, non-zero length, normalised.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] or [`CgaError::ZeroAxis`] (a zero quaternion).
    pub fn try_from_quat(q: Quat) -> Result<Self> {
        let c = q.to_array();
        finite_input(&c, "quaternion")?;
        let k = max_abs(&c);
        if !(k > 0.0) {
            return Err(CgaError::ZeroAxis { what: "quaternion" });
        }
        let q = Quat::from_array(c.map(|x| x / k));
        Ok(Self::from_quat(q / q.length()))
    }

    /// The unit quaternion of this rotor (the same sign convention as glam).
    #[inline]
    #[must_use]
    pub fn to_quat(self) -> Quat {
        rotor_quat(self.to_array())
    }

    /// Rotate a point (or direction) about the origin: `down(R up(x) ~R)`.
    #[inline]
    #[must_use]
    pub fn transform_point(self, x: V3) -> V3 {
        self.sandwich(Point::from_vec3(x)).to_vec3()
    }
}

impl From<Quat> for Rotor {
    #[inline]
    fn from(q: Quat) -> Self {
        Rotor::from_quat(q)
    }
}

impl From<Rotor> for Quat {
    #[inline]
    fn from(r: Rotor) -> Self {
        r.to_quat()
    }
}

impl Translator {
    /// The identity translation.
    pub const IDENTITY: Translator = Translator::new(1.0, 0.0, 0.0, 0.0);

    /// The translation by `t`: `T = 1 - 0.5 t ei`. (`Translator::new` is the generated
    /// coefficient constructor.)
    #[inline]
    #[must_use]
    pub fn from_translation(t: V3) -> Self {
        Translator::new(1.0, -0.5 * t.x, -0.5 * t.y, -0.5 * t.z)
    }

    /// [`Translator::from_translation`] that rejects non-finite input.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`].
    pub fn try_from_translation(t: V3) -> Result<Self> {
        finite3(t, "translation")?;
        Ok(Self::from_translation(t))
    }

    /// The translation vector `t` (`-2 e_ki / s`).
    #[inline]
    #[must_use]
    pub fn translation(self) -> V3 {
        V3::new(self.e1i, self.e2i, self.e3i) * (-2.0 / self.s)
    }

    /// Translate a point: `x + t`.
    #[inline]
    #[must_use]
    pub fn transform_point(self, x: V3) -> V3 {
        self.sandwich(Point::from_vec3(x)).to_vec3()
    }
}

impl From<V3> for Translator {
    #[inline]
    fn from(t: V3) -> Self {
        Translator::from_translation(t)
    }
}
