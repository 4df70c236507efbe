//! Planes: the dual vector `n + d ei`.

use super::*;

/// A plane, stored as its normalised dual vector `pi = n + d ei`: the points with `x.n = d`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Plane {
    /// The dual vector (`eo = 0`, `|(e1, e2, e3)| = 1`).
    ///
    /// Named `dual_vector`, not `dual`: the generated `.dual()` method of every type is the
    /// algebraic dual (times the inverse pseudoscalar), while this field is the object's dual
    /// (inner product null space) *representation*; `self.dual_vector.dual()` is its direct form.
    pub dual_vector: Vector,
}

impl Plane {
    /// The plane `x.n = d` (`normal` is normalised here; a zero normal gives NaNs, see
    /// [`Plane::try_from_normal_distance`]).
    #[must_use]
    pub fn from_normal_distance(normal: V3, distance: S) -> Self {
        let l = normal.length();
        let n = normal / l;
        Plane {
            dual_vector: Vector::new(0.0, n.x, n.y, n.z, distance),
        }
    }

    /// Checked [`Plane::from_normal_distance`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] or [`CgaError::ZeroAxis`] (a normal of any other finite length
    /// is normalised without overflow).
    pub fn try_from_normal_distance(normal: V3, distance: S) -> Result<Self> {
        let n = try_unit_direction(normal, "plane normal")?;
        finite_input(&[distance], "plane distance")?;
        Ok(Self::from_normal_distance(n, distance))
    }

    /// The plane of the equation `normal . x = d` for a normal of any finite, non-zero length
    /// (both sides divided by its length, scaled first so that no square overflows: a normal
    /// of `1e308` in each component works).
    ///
    /// ```
    /// use cga::Plane;
    /// use glam::DVec3;
    /// let p = Plane::try_from_equation(DVec3::new(0.0, 2.0, 0.0), 4.0).unwrap();
    /// assert_eq!((p.normal(), p.distance()), (DVec3::Y, 2.0));
    /// assert!(Plane::try_from_equation(DVec3::ZERO, 1.0).is_err());
    /// ```
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] or [`CgaError::ZeroAxis`] (a zero normal).
    pub fn try_from_equation(normal: V3, d: S) -> Result<Self> {
        finite3(normal, "plane normal")?;
        finite_input(&[d], "plane equation's right-hand side")?;
        let scale = normal.abs().max_element();
        if !(scale > 0.0) {
            return Err(CgaError::ZeroAxis {
                what: "plane normal",
            });
        }
        let (n, d) = (normal / scale, d / scale);
        let l = n.length();
        Self::try_from_normal_distance(n / l, d / l)
    }

    /// Checked [`Plane::from_point_normal`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] or [`CgaError::ZeroAxis`] (a zero normal), and
    /// [`CgaError::Overflow`] where `point . normal` overflows.
    pub fn try_from_point_normal(point: V3, normal: V3) -> Result<Self> {
        finite3(point, "plane point")?;
        let n = try_unit_direction(normal, "plane normal")?;
        let d = n.dot(point);
        finite_result((), &[d], "plane distance")?;
        Ok(Self::from_normal_distance(n, d))
    }

    /// The plane through `point` with `normal`.
    #[must_use]
    pub fn from_point_normal(point: V3, normal: V3) -> Self {
        let n = normal.normalize();
        Self::from_normal_distance(n, n.dot(point))
    }

    /// The plane through three points, `(X1 ^ X2 ^ X3 ^ ei)*`, oriented so that its normal is
    /// along `(b - a) x (c - a)`.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::Degenerate`] for collinear points,
    /// [`CgaError::Overflow`] when the outer product overflows.
    pub fn through_points(a: V3, b: V3, c: V3) -> Result<Self> {
        for p in [a, b, c] {
            finite3(p, "point")?;
        }
        let q = Point::from_vec3(a) ^ Point::from_vec3(b) ^ Point::from_vec3(c) ^ EI;
        let v = q.dual();
        let n = V3::new(v.e1, v.e2, v.e3);
        let l = n.length();
        let span = (b - a).length() * (c - a).length();
        finite_result(
            (),
            &[v.e1, v.e2, v.e3, v.ei, l, span],
            "plane (points too far out)",
        )?;
        if !(l > TOL * span) || l == 0.0 {
            return Err(CgaError::Degenerate {
                why: "collinear or coincident points",
            });
        }
        let sign = if (n / l).dot((b - a).cross(c - a)) < 0.0 {
            -1.0
        } else {
            1.0
        };
        let dual = Vector::new(0.0, v.e1 / l, v.e2 / l, v.e3 / l, v.ei / l) * sign;
        finite_result(
            Plane { dual_vector: dual },
            &dual.to_array(),
            "plane (normalisation)",
        )
    }

    /// The direct form, a quadvector `X1 ^ X2 ^ X3 ^ ei` (up to scale).
    #[must_use]
    pub fn direct(&self) -> Quadvector {
        self.dual_vector.dual()
    }

    /// The unit normal.
    #[must_use]
    pub fn normal(&self) -> V3 {
        V3::new(
            self.dual_vector.e1,
            self.dual_vector.e2,
            self.dual_vector.e3,
        )
    }

    /// The signed distance of the plane from the origin along its normal.
    #[must_use]
    pub fn distance(&self) -> S {
        self.dual_vector.ei
    }

    /// The signed distance of `x` from the plane: `X.pi = x.n - d` (positive on the normal's
    /// side).
    #[must_use]
    pub fn signed_distance(&self, x: V3) -> S {
        Point::from_vec3(x).dot_vector(self.dual_vector)
    }

    /// The meet with a line, `pi . L` (a flat point); `None` when the line is parallel to the
    /// plane (within a relative tolerance).
    #[must_use]
    pub fn meet_line(&self, line: &Line) -> Option<FlatPoint> {
        let f = self.dual_vector | line.direct;
        let u = line.direction();
        if !(f.eoi.abs() > TOL * u.length()) {
            return None;
        }
        Some(FlatPoint { direct: f })
    }

    /// The point where the segment `a b` crosses the plane, with its parameter `s` in `[0, 1]`
    /// (`a + s (b - a)`); `None` when both ends are strictly on the same side or the segment
    /// lies in the plane. An endpoint on the plane is returned exactly.
    #[must_use]
    pub fn meet_segment(&self, a: V3, b: V3) -> Option<(S, V3)> {
        let (da, db) = (self.signed_distance(a), self.signed_distance(b));
        if da == 0.0 && db == 0.0 {
            return None;
        }
        if da == 0.0 {
            return Some((0.0, a));
        }
        if db == 0.0 {
            return Some((1.0, b));
        }
        if (da > 0.0) == (db > 0.0) {
            return None;
        }
        let s = da / (da - db);
        Some((s, a + s * (b - a)))
    }

    /// The line where two planes meet, `(pi1 ^ pi2)*`; `None` when they are parallel.
    #[must_use]
    pub fn meet_plane(&self, other: &Plane) -> Option<Line> {
        if !(self.normal().cross(other.normal()).length() > TOL) {
            return None;
        }
        Some(Line {
            direct: (self.dual_vector ^ other.dual_vector).dual(),
        })
    }

    /// Move the plane by a unit motor.
    #[must_use]
    pub fn transformed(&self, m: Motor) -> Plane {
        let n = m.transform_vector(self.normal());
        let p = m.transform_point(self.normal() * self.distance());
        Plane::from_normal_distance(n, n.dot(p))
    }
}
