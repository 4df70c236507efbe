//! Lines: the direct trivector `X1 ^ X2 ^ ei`.

use super::*;

/// A line, stored as the direct trivector `X1 ^ X2 ^ ei = eo^u^ei + (a^b)^ei` (`u = b - a`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Line {
    /// The direct (outer product null space) trivector.
    pub direct: Trivector,
}

impl Line {
    /// The line through `a` and `b` (direction `b - a`).
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::Degenerate`] when `a == b`,
    /// [`CgaError::Overflow`] when the points are so far out that the line overflows.
    pub fn through_points(a: V3, b: V3) -> Result<Self> {
        let [pa, pb] = up_all([a, b])?;
        if a == b {
            return Err(CgaError::Degenerate {
                why: "coincident points",
            });
        }
        let direct = pa ^ pb ^ EI;
        finite_result(
            Line { direct },
            &direct.to_array(),
            "line (points too far out)",
        )
    }

    /// The line through `point` along `direction` (any finite non-zero length; the line is
    /// stored with the unit direction, so [`Line::direction`] returns it normalised).
    ///
    /// # Errors
    /// As [`Line::through_points`]; a zero direction is [`CgaError::ZeroAxis`].
    pub fn from_point_direction(point: V3, direction: V3) -> Result<Self> {
        finite3(point, "point")?;
        let u = try_unit_direction(direction, "line direction")?;
        let [p] = up_all([point])?;
        let direct = p ^ Vector::new(0.0, u.x, u.y, u.z, 0.0) ^ EI;
        finite_result(
            Line { direct },
            &direct.to_array(),
            "line (point too far out)",
        )
    }

    /// The dual (inner product null space) form, a bivector.
    #[must_use]
    pub fn dual(&self) -> Bivector {
        self.direct.dual()
    }

    /// The direction `u` (not normalised: `b - a` for a line through `a`, `b`, up to the scale
    /// of the trivector).
    #[must_use]
    pub fn direction(&self) -> V3 {
        V3::new(self.direct.eo1i, self.direct.eo2i, self.direct.eo3i)
    }

    /// The moment `m = a x u` (the `e_jk ^ ei` part).
    #[must_use]
    pub fn moment(&self) -> V3 {
        V3::new(self.direct.e23i, -self.direct.e13i, self.direct.e12i)
    }

    /// The point of the line closest to the origin: `u x m / |u|^2`.
    #[must_use]
    pub fn closest_to_origin(&self) -> V3 {
        let u = self.direction();
        u.cross(self.moment()) / u.length_squared()
    }

    /// The Euclidean distance from `x` to the line.
    #[must_use]
    pub fn distance_to_point(&self, x: V3) -> S {
        let u = self.direction().normalize();
        (x - self.closest_to_origin()).cross(u).length()
    }

    /// Move the line by a unit motor (fused sandwich).
    #[must_use]
    pub fn transformed(&self, m: Motor) -> Line {
        Line {
            direct: m.sandwich(self.direct),
        }
    }
}
