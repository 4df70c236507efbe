//! Geometric objects of the conformal model and their predicates.
//!
//! | object | stored as | built from |
//! |---|---|---|
//! | [`Sphere`] | dual vector `C - 0.5 r^2 ei` (weight 1) | centre + radius, or 4 points `(X1^X2^X3^X4)*` |
//! | [`Plane`] | dual vector `n + d ei`, `|n| = 1` | normal + distance, or 3 points `(X1^X2^X3^ei)*` |
//! | [`Line`] | direct trivector `X1^X2^ei` | 2 points, point + direction, or two planes meeting |
//! | [`Circle`] | direct trivector `X1^X2^X3` | 3 points, or a sphere meeting a plane |
//! | [`PointPair`] | direct bivector `X1^X2` | 2 points, or a sphere meeting a line |
//! | [`FlatPoint`] | direct bivector `X^ei` | a point, or a plane meeting a line |
//!
//! Predicates are inner products with normalised points: `X.pi` is the signed distance to a
//! plane, `X.sigma = 0.5 (r^2 - |x - c|^2)` is positive inside a sphere.

use super::*;

/// The point at infinity `ei` as a vector.
const EI: Vector = Vector::new(0.0, 0.0, 0.0, 0.0, 1.0);

fn finite3(v: V3, what: &'static str) -> Result<()> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(CgaError::NonFinite { what })
    }
}

fn max_abs(c: &[S]) -> S {
    c.iter().fold(0.0, |m: S, x| m.max(x.abs()))
}

/// A sphere, stored as its normalised dual vector `sigma = up(c) - 0.5 r^2 ei`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Sphere {
    /// The dual (inner product null space) vector, with `eo` coefficient 1.
    pub dual: Vector,
}

impl Sphere {
    /// The sphere with `center` and `radius` (not checked; see [`Sphere::try_new`]).
    #[must_use]
    pub fn new(center: V3, radius: S) -> Self {
        let c = Point::from_vec3(center);
        Sphere {
            dual: Vector::new(1.0, c.e1, c.e2, c.e3, c.ei - 0.5 * radius * radius),
        }
    }

    /// Checked [`Sphere::new`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], or [`CgaError::Degenerate`] for a negative radius.
    pub fn try_new(center: V3, radius: S) -> Result<Self> {
        finite3(center, "sphere centre")?;
        if !radius.is_finite() {
            return Err(CgaError::NonFinite {
                what: "sphere radius",
            });
        }
        if radius < 0.0 {
            return Err(CgaError::Degenerate {
                why: "negative radius",
            });
        }
        Ok(Self::new(center, radius))
    }

    /// The sphere through four points: `(X1 ^ X2 ^ X3 ^ X4)*`, normalised.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], or [`CgaError::Degenerate`] when the points are coplanar (or
    /// coincide).
    pub fn through_points(a: V3, b: V3, c: V3, d: V3) -> Result<Self> {
        for p in [a, b, c, d] {
            finite3(p, "point")?;
        }
        let q =
            Point::from_vec3(a) ^ Point::from_vec3(b) ^ Point::from_vec3(c) ^ Point::from_vec3(d);
        let s = q.dual();
        let size = V3::new(s.e1, s.e2, s.e3).length();
        if !(s.eo.abs() > TOL * size) || s.eo == 0.0 {
            return Err(CgaError::Degenerate {
                why: "coplanar or coincident points",
            });
        }
        Ok(Sphere { dual: s / s.eo })
    }

    /// The direct (outer product null space) form: a quadvector.
    #[must_use]
    pub fn direct(&self) -> Quadvector {
        // dual() maps quadvectors to vectors and back up to sign; the sign is irrelevant.
        self.dual.dual()
    }

    /// The centre.
    #[must_use]
    pub fn center(&self) -> V3 {
        V3::new(self.dual.e1, self.dual.e2, self.dual.e3)
    }

    /// The squared radius `sigma.sigma` (negative for an imaginary sphere).
    #[must_use]
    pub fn radius_squared(&self) -> S {
        self.dual.dot(self.dual)
    }

    /// The radius (NaN for an imaginary sphere).
    #[must_use]
    pub fn radius(&self) -> S {
        self.radius_squared().sqrt()
    }

    /// `X.sigma = 0.5 (r^2 - |x - c|^2)`: positive inside, zero on, negative outside.
    #[must_use]
    pub fn power(&self, x: V3) -> S {
        Point::from_vec3(x).dot_vector(self.dual)
    }

    /// Whether `x` is inside or on the sphere.
    #[must_use]
    pub fn contains(&self, x: V3) -> bool {
        self.power(x) >= 0.0
    }

    /// The signed distance from the sphere surface (negative inside).
    #[must_use]
    pub fn signed_distance(&self, x: V3) -> S {
        (x - self.center()).length() - self.radius()
    }

    /// The circle where this sphere meets a plane: `(sigma ^ pi)*`; `None` when they do not
    /// meet (the circle would be imaginary).
    #[must_use]
    pub fn meet_plane(&self, plane: &Plane) -> Option<Circle> {
        let c = Circle {
            direct: (self.dual ^ plane.dual).dual(),
        };
        (c.radius_squared() >= 0.0).then_some(c)
    }

    /// The point pair where a line pierces this sphere: `sigma . L`; `None` when it misses.
    #[must_use]
    pub fn meet_line(&self, line: &Line) -> Option<PointPair> {
        let p = PointPair {
            direct: self.dual | line.direct,
        };
        p.points().map(|_| p)
    }

    /// Move the sphere by a unit motor.
    #[must_use]
    pub fn transformed(&self, m: Motor) -> Sphere {
        Sphere::new(m.transform_point(self.center()), self.radius())
    }
}

/// A plane, stored as its normalised dual vector `pi = n + d ei`: the points with `x.n = d`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Plane {
    /// The dual vector (`eo = 0`, `|(e1, e2, e3)| = 1`).
    pub dual: Vector,
}

impl Plane {
    /// The plane `x.n = d` (`normal` is normalised here; a zero normal gives NaNs, see
    /// [`Plane::try_from_normal_distance`]).
    #[must_use]
    pub fn from_normal_distance(normal: V3, distance: S) -> Self {
        let l = normal.length();
        let n = normal / l;
        Plane {
            dual: Vector::new(0.0, n.x, n.y, n.z, distance),
        }
    }

    /// Checked [`Plane::from_normal_distance`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`] or [`CgaError::ZeroAxis`].
    pub fn try_from_normal_distance(normal: V3, distance: S) -> Result<Self> {
        finite3(normal, "plane normal")?;
        if !distance.is_finite() {
            return Err(CgaError::NonFinite {
                what: "plane distance",
            });
        }
        if !normal.length_squared().is_normal() {
            return Err(CgaError::ZeroAxis {
                what: "plane normal",
            });
        }
        Ok(Self::from_normal_distance(normal, distance))
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
    /// [`CgaError::NonFinite`], or [`CgaError::Degenerate`] for collinear points.
    pub fn through_points(a: V3, b: V3, c: V3) -> Result<Self> {
        for p in [a, b, c] {
            finite3(p, "point")?;
        }
        let q = Point::from_vec3(a) ^ Point::from_vec3(b) ^ Point::from_vec3(c) ^ EI;
        let v = q.dual();
        let n = V3::new(v.e1, v.e2, v.e3);
        let l = n.length();
        let span = (b - a).length() * (c - a).length();
        if !(l > TOL * span) || l == 0.0 {
            return Err(CgaError::Degenerate {
                why: "collinear or coincident points",
            });
        }
        let sign = if n.dot((b - a).cross(c - a)) < 0.0 {
            -1.0
        } else {
            1.0
        };
        Ok(Plane {
            dual: Vector::new(0.0, v.e1, v.e2, v.e3, v.ei) * (sign / l),
        })
    }

    /// The direct form, a quadvector `X1 ^ X2 ^ X3 ^ ei` (up to scale).
    #[must_use]
    pub fn direct(&self) -> Quadvector {
        self.dual.dual()
    }

    /// The unit normal.
    #[must_use]
    pub fn normal(&self) -> V3 {
        V3::new(self.dual.e1, self.dual.e2, self.dual.e3)
    }

    /// The signed distance of the plane from the origin along its normal.
    #[must_use]
    pub fn distance(&self) -> S {
        self.dual.ei
    }

    /// The signed distance of `x` from the plane: `X.pi = x.n - d` (positive on the normal's
    /// side).
    #[must_use]
    pub fn signed_distance(&self, x: V3) -> S {
        Point::from_vec3(x).dot_vector(self.dual)
    }

    /// The meet with a line, `pi . L` (a flat point); `None` when the line is parallel to the
    /// plane (within a relative tolerance).
    #[must_use]
    pub fn meet_line(&self, line: &Line) -> Option<FlatPoint> {
        let f = self.dual | line.direct;
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
            direct: (self.dual ^ other.dual).dual(),
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
    /// [`CgaError::NonFinite`], or [`CgaError::Degenerate`] when `a == b`.
    pub fn through_points(a: V3, b: V3) -> Result<Self> {
        finite3(a, "point")?;
        finite3(b, "point")?;
        if a == b {
            return Err(CgaError::Degenerate {
                why: "coincident points",
            });
        }
        Ok(Line {
            direct: Point::from_vec3(a) ^ Point::from_vec3(b) ^ EI,
        })
    }

    /// The line through `point` along `direction`.
    ///
    /// # Errors
    /// As [`Line::through_points`]; a zero direction is [`CgaError::ZeroAxis`].
    pub fn from_point_direction(point: V3, direction: V3) -> Result<Self> {
        finite3(direction, "direction")?;
        if direction.length_squared() == 0.0 {
            return Err(CgaError::ZeroAxis {
                what: "line direction",
            });
        }
        Self::through_points(point, point + direction)
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
    /// [`CgaError::NonFinite`], or [`CgaError::Degenerate`] for collinear points (a line).
    pub fn through_points(a: V3, b: V3, c: V3) -> Result<Self> {
        Plane::through_points(a, b, c)?;
        Ok(Circle {
            direct: Point::from_vec3(a) ^ Point::from_vec3(b) ^ Point::from_vec3(c),
        })
    }

    /// The carrier plane `(C ^ ei)*`.
    #[must_use]
    pub fn plane(&self) -> Plane {
        let v = (self.direct ^ EI).dual();
        let l = V3::new(v.e1, v.e2, v.e3).length();
        Plane {
            dual: Vector::new(0.0, v.e1, v.e2, v.e3, v.ei) / l,
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

/// A point pair, stored as the direct bivector `X1 ^ X2`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PointPair {
    /// The direct bivector.
    pub direct: Bivector,
}

impl PointPair {
    /// The pair `{a, b}`.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`].
    pub fn from_points(a: V3, b: V3) -> Result<Self> {
        finite3(a, "point")?;
        finite3(b, "point")?;
        Ok(PointPair {
            direct: Point::from_vec3(a) ^ Point::from_vec3(b),
        })
    }

    /// The two points `(T -+ sqrt(T^2)) (-ei . T)`, or `None` for an imaginary or degenerate
    /// pair.
    #[must_use]
    pub fn points(&self) -> Option<(V3, V3)> {
        let t = self.direct;
        let t2 = (t * t).s;
        if !(t2 >= 0.0) {
            return None;
        }
        let r = t2.sqrt();
        let v = -(EI | t);
        let p = |sgn: S| -> Option<V3> {
            let mut e: Even = t.into();
            e.s += sgn * r;
            let o = e * v;
            Vector::new(o.eo, o.e1, o.e2, o.e3, o.ei)
                .try_to_point()
                .ok()
                .map(Point::to_vec3)
        };
        Some((p(-1.0)?, p(1.0)?))
    }
}

/// A flat point (a point together with the point at infinity), the direct bivector `X ^ ei`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FlatPoint {
    /// The direct bivector `w (eo^ei + x^ei)`.
    pub direct: Bivector,
}

impl FlatPoint {
    /// The flat point at `x`.
    #[must_use]
    pub fn new(x: V3) -> Self {
        FlatPoint {
            direct: Point::from_vec3(x) ^ EI,
        }
    }

    /// The Euclidean point: `(e1i, e2i, e3i) / eoi`.
    #[must_use]
    pub fn point(&self) -> V3 {
        V3::new(self.direct.e1i, self.direct.e2i, self.direct.e3i) / self.direct.eoi
    }
}
