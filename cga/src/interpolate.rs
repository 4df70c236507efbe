//! Blending and interpolation of motors and scaled motors.
//!
//! * Linear blend: `normalise(sum_i w_i M_i)`, after bringing every motor into the hemisphere of
//!   the first (`M` and `-M` are the same motion; without this a blend can take the long way
//!   round), as dual-quaternion skinning does.
//! * Log blend: `exp(sum_i w_i log M_i)` (equation (1) of the seed papers) with principal logs.
//! * `interpolate(a, b, t) = a exp(t log(~a b))`: constant-speed screw motion from `a` to `b`.
//!
//! All blends return the key motor exactly (up to rounding and sign) when its weight is 1 and
//! the others 0, and equal motors with weights summing to 1 return that motor.

use super::*;

fn check_blend(n_motors: usize, n_weights: usize, weights: &[S]) -> Result<()> {
    if n_motors == 0 {
        return Err(CgaError::BadBlend { why: "no motors" });
    }
    if n_motors != n_weights {
        return Err(CgaError::BadBlend {
            why: "motors and weights differ in length",
        });
    }
    if !weights.iter().all(|w| w.is_finite()) {
        return Err(CgaError::NonFinite { what: "weight" });
    }
    Ok(())
}

impl Bivector {
    /// `sum_i w_i B_i` over the rigid and dilation parts (zips the slices).
    #[must_use]
    pub fn weighted_sum(bivectors: &[Bivector], weights: &[S]) -> Bivector {
        let mut acc = Bivector::default();
        for (b, &w) in bivectors.iter().zip(weights) {
            acc = acc + *b * w;
        }
        acc
    }
}

impl Motor {
    /// `sum_i w_i M_i` with every `M_i` brought into the hemisphere of `motors[0]`, then
    /// [`Motor::normalize_rigid`]. Zips the slices; an empty input or a sum with zero rotor part
    /// gives the identity (see [`Motor::try_blend_linear`]).
    #[must_use]
    pub fn blend_linear(motors: &[Motor], weights: &[S]) -> Motor {
        let Some(first) = motors.first() else {
            return Motor::IDENTITY;
        };
        let r0 = first.real_quat();
        let mut acc = Motor::default();
        for (m, &w) in motors.iter().zip(weights) {
            let w = if m.real_quat().dot(r0) < 0.0 { -w } else { w };
            acc = acc + *m * w;
        }
        if !(acc.norm_squared() > S::MIN_POSITIVE) {
            return Motor::IDENTITY;
        }
        acc.normalize_rigid()
    }

    /// Checked [`Motor::blend_linear`].
    ///
    /// # Errors
    /// [`CgaError::BadBlend`] for empty or mismatched slices, [`CgaError::NonFinite`],
    /// [`CgaError::NotAMotor`] for an input that is not a motor or a blend that cancels.
    pub fn try_blend_linear(motors: &[Motor], weights: &[S]) -> Result<Motor> {
        check_blend(motors.len(), weights.len(), weights)?;
        for m in motors {
            m.check_motor()?;
        }
        let r0 = motors[0].real_quat();
        let mut acc = Motor::default();
        for (m, &w) in motors.iter().zip(weights) {
            let w = if m.real_quat().dot(r0) < 0.0 { -w } else { w };
            acc = acc + *m * w;
        }
        acc.try_normalize_rigid()
    }

    /// `exp(sum_i w_i log M_i)` with principal logarithms. Zips the slices (empty: identity).
    #[must_use]
    pub fn blend_log(motors: &[Motor], weights: &[S]) -> Motor {
        let mut acc = Bivector::default();
        for (m, &w) in motors.iter().zip(weights) {
            acc = acc + m.log() * w;
        }
        acc.exp_motor()
    }

    /// Checked [`Motor::blend_log`].
    ///
    /// # Errors
    /// [`CgaError::BadBlend`], [`CgaError::NonFinite`], [`CgaError::NotAMotor`].
    pub fn try_blend_log(motors: &[Motor], weights: &[S]) -> Result<Motor> {
        check_blend(motors.len(), weights.len(), weights)?;
        let mut acc = Bivector::default();
        for (m, &w) in motors.iter().zip(weights) {
            acc = acc + m.try_log()? * w;
        }
        acc.try_exp_motor()
    }

    /// Screw interpolation `a exp(t log(~a b))`: `a` at `t = 0`, `+-b` at `t = 1`, constant
    /// rotational and translational speed along the screw between them.
    #[must_use]
    pub fn interpolate(a: Motor, b: Motor, t: S) -> Motor {
        a * (a.rev() * b).log().mul_scalar(t).exp_motor()
    }

    /// Checked [`Motor::interpolate`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotAMotor`].
    pub fn try_interpolate(a: Motor, b: Motor, t: S) -> Result<Motor> {
        a.check_motor()?;
        b.check_motor()?;
        if !t.is_finite() {
            return Err(CgaError::NonFinite {
                what: "interpolation parameter",
            });
        }
        let (a, b) = (a.normalize_rigid(), b.normalize_rigid());
        Ok(a * (a.rev() * b).try_log()?.mul_scalar(t).try_exp_motor()?)
    }
}

impl Bivector {
    /// `self * t` (a method, for chaining).
    #[inline]
    #[must_use]
    pub fn mul_scalar(self, t: S) -> Bivector {
        self * t
    }
}

impl ScaledMotor {
    /// `exp(sum_i w_i log S_i)`: blends rotation, translation and log-scale. Zips the slices.
    #[must_use]
    pub fn blend_log(motors: &[ScaledMotor], weights: &[S]) -> ScaledMotor {
        let mut acc = Bivector::default();
        for (m, &w) in motors.iter().zip(weights) {
            acc = acc + m.log() * w;
        }
        acc.exp_scaled()
    }

    /// Checked [`ScaledMotor::blend_log`].
    ///
    /// # Errors
    /// [`CgaError::BadBlend`], [`CgaError::NonFinite`], [`CgaError::NotAMotor`].
    pub fn try_blend_log(motors: &[ScaledMotor], weights: &[S]) -> Result<ScaledMotor> {
        check_blend(motors.len(), weights.len(), weights)?;
        let mut acc = Bivector::default();
        for (m, &w) in motors.iter().zip(weights) {
            acc = acc + m.try_log()? * w;
        }
        acc.try_exp_scaled()
    }

    /// `a exp(t log(a^-1 b))`: from `a` at `t = 0` to `+-b` at `t = 1`, scale interpolated
    /// geometrically.
    #[must_use]
    pub fn interpolate(a: ScaledMotor, b: ScaledMotor, t: S) -> ScaledMotor {
        a * (a.inverse_similarity() * b)
            .log()
            .mul_scalar(t)
            .exp_scaled()
    }

    /// The inverse similarity `S^-1 = ~S / (S ~S)` (for a unit scaled motor, the reverse).
    #[inline]
    #[must_use]
    pub fn inverse_similarity(self) -> ScaledMotor {
        self.rev() * (1.0 / self.norm_squared())
    }
}
