//! Closed-form exponential and logarithm of rigid and scaled motors (no series).
//!
//! The rigid ones ([`Bivector::exp_motor`], [`Motor::log`]) are the generator's closed forms
//! (`Exp`, `Log` of the generated module, after [`Motor::normalize_rigid`] for the log); the
//! scaled ones (dilations too) are written here, as follows.
//!
//! A generator is a bivector `B = B_E + b ei + l eo^ei` with `B_E` Euclidean (`e12, e13, e23`)
//! and `b` a Euclidean vector (the `e1i, e2i, e3i` coefficients). It corresponds to the affine
//! generator `[[2l I + W, v], [0, 0]]` with `v = -2b` and `W` the cross-product matrix of
//! `w = theta n`, where `B_E = -(theta/2) n I3` (so `exp(B_E)` rotates by `theta` about `n`).
//!
//! With `u = w/2 = phi n`, `exp(B) = T R D` with `R = cos(phi) + sin(phi)/phi B_E`,
//! `D = cosh(l) + sinh(l) eo^ei`, and the translation `t = V v`, where `V` is
//! `integral_0^1 exp(s(2l + W)) ds`: on the axis `expm1(s)/s` (`s = 2l`), in the plane
//! orthogonal to `n` the complex number `z = (e^q - 1)/q`, `q = s + i theta`. The logarithm
//! inverts each step (`phi = atan2(|q_r.xyz|, q_r.w)` on the hemisphere `q_r.w >= 0`, and
//! `v = V^-1 t`). Every quotient that tends to `0/0` is written so that it does not divide by a
//! vanishing quantity (`phi/sin(phi)` with `atan2`, `1/z` from `expm1`), and the few terms of the
//! form `(f - g)/phi^2` are multiplied by `phi^2 |v|`, so their rounding stays at `eps |v|`.
//! Pure translations, zero, rotations by `pi` and pure dilations are ordinary inputs.

use super::*;

/// `sin(x)/x`, exactly 1 at 0.
#[inline]
fn sinc(x: S) -> S {
    if x == 0.0 {
        1.0
    } else {
        x.sin() / x
    }
}

/// `(exp(l), exp(l) - 1)`, each to full relative precision from one call: the dilation part
/// of the closed-form exponentials (scalar and over lanes).
#[inline]
pub(crate) fn exp_pair(l: S) -> (S, S) {
    if l == 0.0 {
        (1.0, 0.0)
    } else if l.abs() < 0.5 {
        let em = l.exp_m1();
        (1.0 + em, em)
    } else {
        let e = l.exp();
        (e, e - 1.0)
    }
}

/// `cosh` and `sinh` of half the log-scale, and the scale, of a dilator.
#[derive(Clone, Copy)]
struct DilationParts {
    cosh_half: S,
    sinh_half: S,
    scale: S,
}

/// `expm1(x)/x`, exactly 1 at 0.
#[inline]
fn expm1_over(x: S) -> S {
    if x == 0.0 {
        1.0
    } else {
        x.exp_m1() / x
    }
}

/// The generator of a rotation quaternion on its `w >= 0` hemisphere: returns `(u, f, a)` with
/// `u = phi n` (half the rotation vector), `f = phi / sin(phi)` and `a = phi cot(phi)`.
#[inline]
fn quat_log(q: Quat) -> (V3, S, S, S) {
    let xyz = V3::new(q.x, q.y, q.z);
    let sv = xyz.length();
    let phi = sv.atan2(q.w);
    let f = if sv == 0.0 { 1.0 } else { phi / sv };
    (xyz * f, f, f * q.w, sv)
}

impl Bivector {
    /// The rigid generator with rotation part `B_E` from `u = phi n` (half rotation vector),
    /// translation part `b`, dilation part `l`.
    #[inline]
    fn from_parts(u: V3, b: V3, l: S) -> Bivector {
        let [e12, e13, e23] = quat_map::rotation_plane(u);
        Bivector::new(0.0, 0.0, 0.0, l, e12, e13, e23, b.x, b.y, b.z)
    }

    /// The half rotation vector `u = phi n` of the Euclidean part.
    #[inline]
    fn half_rotation(self) -> V3 {
        quat_map::rotation_vector([self.e12, self.e13, self.e23])
    }

    /// The rotation generator of a rotation by `angle` about `axis`: `-(angle/2) n I3`.
    #[must_use]
    pub fn rotation_generator(axis: V3, angle: S) -> Bivector {
        let n = axis.normalize_or_zero();
        Bivector::from_parts(0.5 * angle * n, V3::ZERO, 0.0)
    }

    /// The translation generator `-0.5 t ei` (`exp` of it translates by `t`).
    #[must_use]
    pub fn translation_generator(t: V3) -> Bivector {
        Bivector::from_parts(V3::ZERO, -0.5 * t, 0.0)
    }

    /// The dilation generator `0.5 ln(d) eo^ei` (`exp` of it scales by `d`).
    #[must_use]
    pub fn dilation_generator(d: S) -> Bivector {
        Bivector::from_parts(V3::ZERO, V3::ZERO, 0.5 * d.ln())
    }

    /// The exponential of a rigid-body generator (`e12, e13, e23, e1i, e2i, e3i`), in closed
    /// form: a unit motor. The `eo1, eo2, eo3, eoi` parts are ignored; see
    /// [`Bivector::try_exp_motor`].
    #[must_use]
    pub fn exp_motor(self) -> Motor {
        // The generated closed form (`Exp<Motor> for Bivector`), which reads the blades of
        // `Motor` only (the rigid part).
        Exp::exp(self)
    }

    /// Checked [`Bivector::exp_motor`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotAGenerator`] when an `eo` part is not zero,
    /// [`CgaError::Overflow`] when the generator is too large for a finite result.
    pub fn try_exp_motor(self) -> Result<Motor> {
        finite_input(&self.to_array(), "bivector")?;
        if self.eo1 != 0.0 || self.eo2 != 0.0 || self.eo3 != 0.0 || self.eoi != 0.0 {
            return Err(CgaError::NotAGenerator {
                what: "rigid motion",
                why: "eo^ek or eo^ei part present",
            });
        }
        let m = self.exp_motor();
        finite_result(m, &m.to_array(), "exp (generator too large)")?;
        m.rescaled()
            .map_err(|_| CgaError::Overflow {
                what: "exp (generator too large for a valid motor)",
            })
            .map(|_| m)
    }

    /// The exponential of a similarity generator (rigid part plus `eoi` dilation part), in
    /// closed form: a unit scaled motor `T R D`. The `eo1, eo2, eo3` parts are ignored.
    #[must_use]
    pub fn exp_scaled(self) -> ScaledMotor {
        let (qr, t, d) = self.exp_parts();
        let qd = Quat::from_vec4((0.5 * t).extend(0.0)) * qr;
        Motor::from_quats(qr, qd) * Dilator::new(d.cosh_half, d.sinh_half)
    }

    /// [`Bivector::exp_scaled`] in quaternion form: the same motion as a [`Similarity`]
    /// (`x -> d R x + t`), without building the versor. The cheapest way to apply `exp(B)`
    /// to a point when `B` changes from point to point (blends, skinning); for rigid
    /// generators it is [`Bivector::exp_motor`]'s motion.
    #[inline]
    #[must_use]
    pub fn exp_similarity(self) -> Similarity {
        let (rotation, translation, d) = self.exp_parts();
        Similarity {
            scale: d.scale,
            log_scale: 2.0 * self.eoi,
            rotation,
            translation,
        }
    }

    /// The closed form behind [`Bivector::exp_scaled`]: one `sin_cos` and at most one
    /// exponential. Returns the rotation, the translation and the dilation.
    #[inline]
    fn exp_parts(self) -> (Quat, V3, DilationParts) {
        let u = self.half_rotation();
        let v = -2.0 * V3::new(self.e1i, self.e2i, self.e3i);
        let l = self.eoi;
        let sg = 2.0 * l;
        let phi2 = u.length_squared();
        let phi = phi2.sqrt();
        let (sn, c) = phi.sin_cos();
        let sc = sinc(phi);
        let qr = Quat::from_xyzw(sc * u.x, sc * u.y, sc * u.z, c);
        let (e, em) = exp_pair(l);
        let eg = e * e; // exp(sg)
        let egm1 = em * (1.0 + e); // expm1(sg)
        let ax = if sg == 0.0 { 1.0 } else { egm1 / sg };
        // e^q - 1 = er + i ei with q = sg + i theta, theta = 2 phi.
        let er = egm1 * (c * c - sn * sn) - 2.0 * sn * sn;
        let theta = 2.0 * phi;
        let w2 = sg * sg + theta * theta;
        // z = (e^q - 1)/q; zi/phi computed without dividing by phi.
        let (zr, zi_phi) = if w2 > S::MIN_POSITIVE {
            let ei_phi = 2.0 * eg * sc * c; // ei / phi
            (
                (er * sg + eg * 2.0 * sn * c * theta) / w2,
                (ei_phi * sg - 2.0 * er) / w2,
            )
        } else {
            (1.0, 1.0)
        };
        let k = if phi2 > S::MIN_POSITIVE {
            (ax - zr) / phi2
        } else {
            0.0
        };
        let t = zr * v + (k * u.dot(v)) * u + zi_phi * u.cross(v);
        // sinh l = (em + em / e) / 2, cosh l = 1 + em^2 / (2 e): exact for small l.
        let parts = DilationParts {
            sinh_half: 0.5 * (em + em / e),
            cosh_half: 1.0 + 0.5 * em * em / e,
            scale: eg,
        };
        (qr, t, parts)
    }

    /// Checked [`Bivector::exp_scaled`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotAGenerator`] when an `eo^ek` part is not zero,
    /// [`CgaError::Overflow`] when the result overflows or its dilation is too large to be
    /// read back.
    pub fn try_exp_scaled(self) -> Result<ScaledMotor> {
        finite_input(&self.to_array(), "bivector")?;
        if self.eo1 != 0.0 || self.eo2 != 0.0 || self.eo3 != 0.0 {
            return Err(CgaError::NotAGenerator {
                what: "similarity",
                why: "eo^ek part present",
            });
        }
        let m = self.exp_scaled();
        finite_result(m, &m.to_array(), "exp (generator too large)")?;
        m.rescaled()
            .map_err(|_| CgaError::Overflow {
                what: "exp (dilation too large for a valid scaled motor)",
            })
            .map(|_| m)
    }
}

impl Motor {
    /// The principal logarithm in closed form: the rigid generator `B` with `exp(B) = +-M` and
    /// rotation angle in `[0, pi]`. `M` is normalised first; the result is not finite when the
    /// rotor part is zero (see [`Motor::try_log`]).
    #[must_use]
    pub fn log(self) -> Bivector {
        // `normalize_rigid` (a unit motor, the versor defect removed), then the generated
        // closed form (`Log`); the generated `EvenVersor::normalize` gives the same motor but
        // costs twice the whole log here.
        Log::log(self.normalize_rigid())
    }

    /// Checked [`Motor::log`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotAMotor`] when the value is not (a multiple
    /// of) a motor, [`CgaError::Overflow`] when the translation is too large for a finite
    /// logarithm, or for a multiple so small that its subnormal coefficients no longer hold
    /// the motion (`1e-45 M` in `f32`). Any other finite multiple of a motor works
    /// (`1e300 M` is the motion of `M`: its logarithm is `M`'s).
    pub fn try_log(self) -> Result<Bivector> {
        let b = self.rescaled()?.log();
        finite_result(b, &b.to_array(), "log")
    }

    /// `exp(B)` for a rigid generator; the same as [`Bivector::exp_motor`].
    #[inline]
    #[must_use]
    pub fn exp(b: Bivector) -> Motor {
        b.exp_motor()
    }
}

impl ScaledMotor {
    /// The principal logarithm in closed form: `B = B_E + b ei + l eo^ei` with `exp(B) = +-S`.
    /// Not finite when `S` is not a scaled motor (see [`ScaledMotor::try_log`]).
    #[must_use]
    pub fn log(self) -> Bivector {
        let sim = self.similarity();
        let mut qr = sim.rotation;
        if qr.w < 0.0 {
            qr = -qr;
        }
        let t = sim.translation;
        let sg = sim.log_scale;
        let (u, f, _a, sv) = quat_log(qr);
        let phi = sv.atan2(qr.w);
        let c = qr.w;
        let xyz = V3::new(qr.x, qr.y, qr.z);
        let ax_inv = 1.0 / expm1_over(sg);
        let eg = sg.exp();
        let er = sg.exp_m1() * (c * c - sv * sv) - 2.0 * sv * sv;
        let ei = eg * 2.0 * sv * c;
        let theta = 2.0 * phi;
        let den = er * er + ei * ei;
        // 1/z = q / (e^q - 1) = (sg + i theta)(er - i ei)/den; zi/sv without dividing by sv.
        let (zr, zi_sv) = if den > S::MIN_POSITIVE {
            let ei_sv = eg * 2.0 * c;
            let theta_sv = 2.0 * f;
            (
                (sg * er + theta * ei) / den,
                (theta_sv * er - sg * ei_sv) / den,
            )
        } else {
            (1.0, -f)
        };
        let sv2 = sv * sv;
        let k = if sv2 > S::MIN_POSITIVE {
            (ax_inv - zr) / sv2
        } else {
            0.0
        };
        let v = zr * t + (k * xyz.dot(t)) * xyz + zi_sv * xyz.cross(t);
        Bivector::from_parts(u, -0.5 * v, 0.5 * sg)
    }

    /// Checked [`ScaledMotor::log`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotAMotor`] when the value is not (a multiple
    /// of) a scaled motor, [`CgaError::Overflow`] for a result that is not finite or a multiple
    /// so small that its subnormal coefficients no longer hold the motion. `k S` for any
    /// other finite `k` has the logarithm of `S`.
    pub fn try_log(self) -> Result<Bivector> {
        let b = self.rescaled()?.log();
        finite_result(b, &b.to_array(), "log")
    }

    /// `exp(B)` for a similarity generator; the same as [`Bivector::exp_scaled`].
    #[inline]
    #[must_use]
    pub fn exp(b: Bivector) -> ScaledMotor {
        b.exp_scaled()
    }
}
