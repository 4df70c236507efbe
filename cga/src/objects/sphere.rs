//! Spheres: the dual vector `C - 0.5 r^2 ei`.

use super::*;

/// A sphere, stored as its normalised dual vector `sigma = up(c) - 0.5 r^2 ei`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Sphere {
    /// The dual (inner product null space) vector, with `eo` coefficient 1.
    ///
    /// Named `dual_vector`, not `dual`: the generated `.dual()` method of every type is the
    /// algebraic dual (times the inverse pseudoscalar), while this field is the object's dual
    /// (inner product null space) *representation*; `self.dual_vector.dual()` is its direct form.
    pub dual_vector: Vector,
}

impl Sphere {
    /// The sphere with `center` and `radius` (not checked; see [`Sphere::try_new`]).
    #[must_use]
    pub fn new(center: V3, radius: S) -> Self {
        let c = Point::from_vec3(center);
        Sphere {
            dual_vector: Vector::new(1.0, c.e1, c.e2, c.e3, c.ei - 0.5 * radius * radius),
        }
    }

    /// Checked [`Sphere::new`].
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::Degenerate`] for a negative radius,
    /// [`CgaError::Overflow`] when `0.5 |c|^2` or `0.5 r^2` overflows.
    pub fn try_new(center: V3, radius: S) -> Result<Self> {
        finite3(center, "sphere centre")?;
        finite_input(&[radius], "sphere radius")?;
        if radius < 0.0 {
            return Err(CgaError::Degenerate {
                why: "negative radius",
            });
        }
        let s = Self::new(center, radius);
        finite_result(
            s,
            &s.dual_vector.to_array(),
            "sphere (centre or radius too large)",
        )
    }

    /// The sphere through four points: `(X1 ^ X2 ^ X3 ^ X4)*`, normalised.
    ///
    /// # Errors
    /// [`CgaError::NonFinite`], [`CgaError::Degenerate`] when the points are coplanar (or
    /// coincide), [`CgaError::Overflow`] when the outer product overflows.
    pub fn through_points(a: V3, b: V3, c: V3, d: V3) -> Result<Self> {
        let [a, b, c, d] = up_all([a, b, c, d])?;
        let s = (a ^ b ^ c ^ d).dual();
        finite_result((), &s.to_array(), "sphere (outer product of the points)")?;
        let size = max_abs(&[s.e1, s.e2, s.e3]);
        if !(s.eo.abs() > TOL * size) || s.eo == 0.0 {
            return Err(CgaError::Degenerate {
                why: "coplanar or coincident points",
            });
        }
        let w = s.eo;
        let dual = Vector::new(1.0, s.e1 / w, s.e2 / w, s.e3 / w, s.ei / w);
        finite_result(
            Sphere { dual_vector: dual },
            &dual.to_array(),
            "sphere (normalisation)",
        )
    }

    /// The direct (outer product null space) form: a quadvector.
    #[must_use]
    pub fn direct(&self) -> Quadvector {
        // dual() maps quadvectors to vectors and back up to sign; the sign is irrelevant.
        self.dual_vector.dual()
    }

    /// The centre.
    #[must_use]
    pub fn center(&self) -> V3 {
        V3::new(
            self.dual_vector.e1,
            self.dual_vector.e2,
            self.dual_vector.e3,
        )
    }

    /// The squared radius `sigma.sigma` (negative for an imaginary sphere).
    #[must_use]
    pub fn radius_squared(&self) -> S {
        self.dual_vector.dot(self.dual_vector)
    }

    /// The radius (NaN for an imaginary sphere).
    #[must_use]
    pub fn radius(&self) -> S {
        self.radius_squared().sqrt()
    }

    /// `X.sigma = 0.5 (r^2 - |x - c|^2)`: positive inside, zero on, negative outside.
    #[must_use]
    pub fn power(&self, x: V3) -> S {
        Point::from_vec3(x).dot_vector(self.dual_vector)
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
            direct: (self.dual_vector ^ plane.dual_vector).dual(),
        };
        (c.radius_squared() >= 0.0).then_some(c)
    }

    /// The point pair where a line pierces this sphere: `sigma . L`; `None` when it misses.
    #[must_use]
    pub fn meet_line(&self, line: &Line) -> Option<PointPair> {
        let p = PointPair {
            direct: self.dual_vector | line.direct,
        };
        p.points().map(|_| p)
    }

    /// Move the sphere by a unit motor.
    #[must_use]
    pub fn transformed(&self, m: Motor) -> Sphere {
        Sphere::new(m.transform_point(self.center()), self.radius())
    }
}
