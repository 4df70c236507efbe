//! Conformal points: up- and down-projection, and distances through the inner product.
//!
//! `X = x + 0.5 |x|^2 ei + eo` ([`Point::from_vec3`]); a general (unnormalised) point is a
//! [`Vector`] whose weight `-X.ei` (its `eo` coefficient) is not 1, and down-projection divides
//! by that weight ([`Vector::to_vec3`]). For normalised points `X.Y = -0.5 |x - y|^2`.

use super::*;

impl Point {
    /// The conformal origin `eo` (the point `x = 0`).
    pub const ORIGIN: Point = Point::new(0.0, 0.0, 0.0, 0.0);

    /// Up-projection: `X = x + 0.5 |x|^2 ei + eo`.
    #[inline]
    #[must_use]
    pub fn from_vec3(x: V3) -> Self {
        Point::new(x.x, x.y, x.z, 0.5 * x.length_squared())
    }

    /// Up-projection that rejects non-finite coordinates.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] when a coordinate is NaN or infinite, [`CgaError::Overflow`]
    /// when `0.5 |x|^2` overflows (beyond about `1.3e154` in `f64`, `1.8e19` in `f32`).
    pub fn try_from_vec3(x: V3) -> Result<Self> {
        finite3(x, "point")?;
        let p = Self::from_vec3(x);
        finite_result(p, &[p.ei], "point (0.5 |x|^2 overflows)")
    }

    /// Down-projection. A normalised point has weight `-X.ei = 1`, so this reads `e1, e2, e3`.
    #[inline]
    #[must_use]
    pub fn to_vec3(self) -> V3 {
        V3::new(self.e1, self.e2, self.e3)
    }

    /// The inner product `X.Y` of two normalised points: `-0.5 |x - y|^2` when both `ei`
    /// coefficients are `0.5 |x|^2`.
    #[inline]
    #[must_use]
    pub fn dot(self, other: Point) -> S {
        // X.Y = x.y - X.eo Y.ei - X.ei Y.eo with eo = 1 on both sides.
        self.e1 * other.e1 + self.e2 * other.e2 + self.e3 * other.e3 - self.ei - other.ei
    }

    /// The inner product of a normalised point with any vector (sphere, plane, point).
    #[inline]
    #[must_use]
    pub fn dot_vector(self, v: Vector) -> S {
        self.e1 * v.e1 + self.e2 * v.e2 + self.e3 * v.e3 - v.ei - self.ei * v.eo
    }

    /// Squared Euclidean distance from the inner product: `-2 X.Y` (clamped at 0 against
    /// rounding).
    #[inline]
    #[must_use]
    pub fn distance_squared(self, other: Point) -> S {
        (-2.0 * self.dot(other)).max(0.0)
    }

    /// Euclidean distance from the inner product: `sqrt(-2 X.Y)`.
    #[inline]
    #[must_use]
    pub fn distance(self, other: Point) -> S {
        self.distance_squared(other).sqrt()
    }

    /// This point as a general [`Vector`] (with its `eo = 1`).
    #[inline]
    #[must_use]
    pub fn to_vector(self) -> Vector {
        Vector::new(1.0, self.e1, self.e2, self.e3, self.ei)
    }
}

impl From<V3> for Point {
    #[inline]
    fn from(x: V3) -> Self {
        Point::from_vec3(x)
    }
}

impl From<Point> for V3 {
    #[inline]
    fn from(p: Point) -> Self {
        p.to_vec3()
    }
}

impl Vector {
    /// The weight `-X.ei` of a point (its `eo` coefficient): 1 for normalised points, `1/d`
    /// after the raw sandwich with a dilator by `d`, 0 for planes.
    #[inline]
    #[must_use]
    pub fn weight(self) -> S {
        self.eo
    }

    /// The inner product `a.b` of two vectors (`eo.ei = -1`).
    #[inline]
    #[must_use]
    pub fn dot(self, o: Vector) -> S {
        self.e1 * o.e1 + self.e2 * o.e2 + self.e3 * o.e3 - self.eo * o.ei - self.ei * o.eo
    }

    /// Down-projection of a (possibly unnormalised) point: `x_k = X[e_k] / (-X.ei)`.
    /// Not finite when the weight is zero; see [`Vector::try_to_point`].
    #[inline]
    #[must_use]
    pub fn to_vec3(self) -> V3 {
        V3::new(self.e1, self.e2, self.e3) / self.eo
    }

    /// Normalise a point-like vector so that its weight is 1.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] for non-finite coefficients, [`CgaError::Degenerate`] when the
    /// weight is zero (a plane, or a point at infinity), [`CgaError::Overflow`] when the
    /// weight is so small (subnormal, say) that the point's coordinates overflow.
    pub fn try_to_point(self) -> Result<Point> {
        finite_input(&self.to_array(), "vector")?;
        if self.eo == 0.0 {
            return Err(CgaError::Degenerate {
                why: "zero weight: not a finite point",
            });
        }
        let w = self.eo;
        let p = Point::new(self.e1 / w, self.e2 / w, self.e3 / w, self.ei / w);
        finite_result(
            p,
            &p.to_array(),
            "point (weight too small for its coordinates)",
        )
    }
}
