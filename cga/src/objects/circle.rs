//! Circles: the direct trivector `X1 ^ X2 ^ X3`.

use super::*;

/// A circle, stored as the direct trivector `X1 ^ X2 ^ X3`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Circle {
    /// The direct trivector.
    pub direct: Trivector,
}

impl Circle {
    /// The circle through three points.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::Degenerate`] for collinear points (a line),
    /// [`CgaError::Overflow`] when the outer product overflows.
    pub fn through_points(a: V3, b: V3, c: V3) -> Result<Self> {
        Plane::through_points(a, b, c)?;
        let [a, b, c] = up_all([a, b, c])?;
        let direct = a ^ b ^ c;
        finite_result(
            Circle { direct },
            &direct.to_array(),
            "circle (points too far out)",
        )
    }

    /// The carrier plane `(C ^ ei)*`.
    #[must_use]
    pub fn plane(&self) -> Plane {
        let v = (self.direct ^ EI).dual();
        let l = V3::new(v.e1, v.e2, v.e3).length();
        Plane {
            dual_vector: Vector::new(0.0, v.e1, v.e2, v.e3, v.ei) / l,
        }
    }

    /// The centre `C ei C` (normalised).
    #[must_use]
    pub fn center(&self) -> V3 {
        let c = self.direct * EI * self.direct;
        Vector::new(c.eo, c.e1, c.e2, c.e3, c.ei).to_vec3()
    }

    /// The squared radius `(C C^) / (ei . C)^2` (negative for an imaginary circle).
    #[must_use]
    pub fn radius_squared(&self) -> S {
        let num = (self.direct * self.direct.involute()).s;
        let e = EI | self.direct;
        let den = (e * e).s;
        num / den
    }

    /// The radius.
    #[must_use]
    pub fn radius(&self) -> S {
        self.radius_squared().sqrt()
    }

    /// Whether `x` lies on the circle: `X ^ C = 0` up to a relative tolerance.
    #[must_use]
    pub fn contains(&self, x: V3) -> bool {
        let q = Point::from_vec3(x) ^ self.direct;
        let scale = max_abs(&self.direct.to_array()) * (1.0 + x.length_squared());
        max_abs(&q.to_array()) <= TOL * scale
    }

    /// Move the circle by a unit motor (fused sandwich).
    #[must_use]
    pub fn transformed(&self, m: Motor) -> Circle {
        Circle {
            direct: m.sandwich(self.direct),
        }
    }
}
