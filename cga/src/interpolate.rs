//! Blending and interpolation of motors and scaled motors.
//!
//! * Linear blend: `normalise(sum_i w_i M_i)`, after bringing every motor into the hemisphere of
//!   the first (`M` and `-M` are the same motion; without this a blend can take the long way
//!   round), as dual-quaternion skinning does.
//! * Log blend: `exp(sum_i w_i log M_i)` (equation (1) of the seed papers) with principal logs,
//!   summed by [`Bivector::weighted_sum`].
//! * `interpolate(a, b, t) = a exp(t log(~a b))`: constant-speed screw motion from `a` to `b`.
//!
//! All blends return the key motor exactly (up to rounding and sign) when its weight is 1 and
//! the others 0, and equal motors with weights summing to 1 return that motor.

use super::*;

/// The checks every fallible blend makes on its slices.
fn check_blend(n_motors: usize, n_weights: usize, weights: &[S]) -> Result<()> {
    if n_motors == 0 {
        return Err(CgaError::BadBlend { why: "no motors" });
    }
    if n_motors != n_weights {
        return Err(CgaError::BadBlend {
            why: "motors and weights differ in length",
        });
    }
    finite_input(weights, "weight")
}

impl Bivector {
    /// `sum_i w_i B_i` over every part (zips the iterator with the weights). Every log blend of
    /// this crate is this sum followed by an exponential.
    #[must_use]
    pub fn weighted_sum(bivectors: impl IntoIterator<Item = Bivector>, weights: &[S]) -> Bivector {
        let mut acc = Bivector::default();
        for (b, &w) in bivectors.into_iter().zip(weights) {
            acc = acc + b * w;
        }
        acc
    }

    /// [`Bivector::weighted_sum`] of fallible terms: the first error is returned, and a sum
    /// that overflows is [`CgaError::Overflow`].
    ///
    /// # Errors
    /// The first term's error, [`CgaError::NonFinite`] for a non-finite weight,
    /// [`CgaError::BadBlend`] when the lengths differ, [`CgaError::Overflow`].
    pub fn try_weighted_sum(
        bivectors: impl IntoIterator<Item = Result<Bivector>>,
        weights: &[S],
    ) -> Result<Bivector> {
        finite_input(weights, "weight")?;
        let mut first_err = None;
        let mut count = 0;
        let terms = bivectors.into_iter().map_while(|b| {
            count += 1;
            b.map_err(|e| first_err = Some(e)).ok()
        });
        let sum = Bivector::weighted_sum(terms, weights);
        if let Some(e) = first_err {
            return Err(e);
        }
        if count != weights.len() {
            return Err(CgaError::BadBlend {
                why: "bivectors and weights differ in length",
            });
        }
        finite_result(sum, &sum.to_array(), "weighted sum of bivectors")
    }

    /// `self * t` (a method, for chaining).
    #[inline]
    #[must_use]
    pub fn mul_scalar(self, t: S) -> Bivector {
        self * t
    }
}

impl Motor {
    /// `sum_i w_i M_i` with every `M_i` brought into the hemisphere of the first motor (the
    /// one loop behind the linear blends).
    fn hemisphere_sum(motors: impl IntoIterator<Item = Motor>, weights: &[S]) -> Motor {
        Self::hemisphere_sum_pairs(motors.into_iter().zip(weights.iter().copied()))
    }

    /// [`Motor::hemisphere_sum`] over `(motor, weight)` pairs.
    fn hemisphere_sum_pairs(pairs: impl IntoIterator<Item = (Motor, S)>) -> Motor {
        let mut first = None;
        let mut acc = Motor::default();
        for (m, w) in pairs {
            let r = m.real_quat();
            let r0 = *first.get_or_insert(r);
            let w = if r.dot(r0) < 0.0 { -w } else { w };
            acc = acc + m * w;
        }
        acc
    }

    /// `sum_i w_i M_i` with every `M_i` brought into the hemisphere of `motors[0]`, then
    /// [`Motor::normalize_rigid`]. Zips the slices; an empty input or a sum with zero rotor part
    /// gives the identity (see [`Motor::try_blend_linear`]).
    #[must_use]
    pub fn blend_linear(motors: &[Motor], weights: &[S]) -> Motor {
        Self::blend_linear_pairs(motors.iter().copied().zip(weights.iter().copied()))
    }

    /// [`Motor::blend_linear`] over `(motor, weight)` pairs (for gathering the motors of a
    /// blend from a larger table without copying them into a slice).
    #[must_use]
    pub fn blend_linear_pairs(pairs: impl IntoIterator<Item = (Motor, S)>) -> Motor {
        let acc = Self::hemisphere_sum_pairs(pairs);
        if !(acc.norm_squared() > S::MIN_POSITIVE) {
            return Motor::IDENTITY;
        }
        acc.normalize_rigid()
    }

    /// Checked [`Motor::blend_linear`]. The inputs may be any finite multiples of motors: they
    /// are normalised first, so the weights act on motions, not on coefficient scales.
    ///
    /// # Errors
    /// [`CgaError::BadBlend`] for empty or mismatched slices, [`CgaError::NonFinite`],
    /// [`CgaError::NotAMotor`] for an input that is not a motor or a blend that cancels,
    /// [`CgaError::Overflow`] when the weighted sum overflows.
    pub fn try_blend_linear(motors: &[Motor], weights: &[S]) -> Result<Motor> {
        check_blend(motors.len(), weights.len(), weights)?;
        let mut first_err = None;
        let unit = motors.iter().map_while(|m| {
            m.try_normalize_rigid()
                .map_err(|e| first_err = Some(e))
                .ok()
        });
        let acc = Self::hemisphere_sum(unit, weights);
        if let Some(e) = first_err {
            return Err(e);
        }
        finite_result((), &acc.to_array(), "linear blend (weighted sum)")?;
        acc.try_normalize_rigid()
    }

    /// `exp(sum_i w_i log M_i)` with principal logarithms. Zips the slices (empty: identity).
    ///
    /// Not the same as [`Motor::interpolate`] in general: `blend_log(&[a, b], &[1 - t, t])`
    /// equals `interpolate(a, b, t)` only when `a` and `b` commute (the same screw axis: two
    /// rotations about one axis, two translations, a rotation and a translation along its
    /// axis). For motors that do not commute, `log a + log b` is not `log(a b)`, and the log
    /// blend, a weighted mean of logarithms taken about the identity rather than along the
    /// screw from `a` to `b`, takes another path between them (still `a` at `t = 0` and `+-b`
    /// at `t = 1`); `cga/examples/motors_and_matrices.rs` shows both cases.
    #[must_use]
    pub fn blend_log(motors: &[Motor], weights: &[S]) -> Motor {
        Bivector::weighted_sum(motors.iter().map(|m| m.log()), weights).exp_motor()
    }

    /// Checked [`Motor::blend_log`].
    ///
    /// # Errors
    /// [`CgaError::BadBlend`], [`CgaError::NonFinite`], [`CgaError::NotAMotor`],
    /// [`CgaError::Overflow`] when the weighted logarithms are too large to exponentiate.
    pub fn try_blend_log(motors: &[Motor], weights: &[S]) -> Result<Motor> {
        check_blend(motors.len(), weights.len(), weights)?;
        Bivector::try_weighted_sum(motors.iter().map(|m| m.try_log()), weights)?.try_exp_motor()
    }

    /// Screw interpolation `a exp(t log(~a b))`: `a` at `t = 0`, `+-b` at `t = 1`, constant
    /// rotational and translational speed along the screw between them. Equals
    /// [`Motor::blend_log`] with weights `[1 - t, t]` only for commuting `a` and `b` (see there).
    #[must_use]
    pub fn interpolate(a: Motor, b: Motor, t: S) -> Motor {
        a * (a.rev() * b).log().mul_scalar(t).exp_motor()
    }

    /// Checked [`Motor::interpolate`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::NotAMotor`], [`CgaError::Overflow`] when `t` is so
    /// far outside `[0, 1]` that the motion overflows.
    pub fn try_interpolate(a: Motor, b: Motor, t: S) -> Result<Motor> {
        finite_input(&[t], "interpolation parameter")?;
        let (a, b) = (a.try_normalize_rigid()?, b.try_normalize_rigid()?);
        let g = Bivector::try_weighted_sum([(a.rev() * b).try_log()], &[t])?;
        let m = a * g.try_exp_motor()?;
        finite_result(m, &m.to_array(), "interpolated motor")
    }
}

impl ScaledMotor {
    /// `exp(sum_i w_i log S_i)`: blends rotation, translation and log-scale. Zips the slices.
    /// Equals [`ScaledMotor::interpolate`] with weights `[1 - t, t]` only when the two commute
    /// (as for [`Motor::blend_log`]).
    #[must_use]
    pub fn blend_log(motors: &[ScaledMotor], weights: &[S]) -> ScaledMotor {
        Bivector::weighted_sum(motors.iter().map(|m| m.log()), weights).exp_scaled()
    }

    /// Checked [`ScaledMotor::blend_log`].
    ///
    /// # Errors
    /// [`CgaError::BadBlend`], [`CgaError::NonFinite`], [`CgaError::NotAMotor`],
    /// [`CgaError::Overflow`].
    pub fn try_blend_log(motors: &[ScaledMotor], weights: &[S]) -> Result<ScaledMotor> {
        check_blend(motors.len(), weights.len(), weights)?;
        Bivector::try_weighted_sum(motors.iter().map(|m| m.try_log()), weights)?.try_exp_scaled()
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
