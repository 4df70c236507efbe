//! Point pairs: the direct bivector `X1 ^ X2`.

use super::*;

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
    /// [`CgaError::NonFinite`], [`CgaError::Overflow`] when the points are so far out that
    /// the outer product overflows.
    pub fn from_points(a: V3, b: V3) -> Result<Self> {
        let [a, b] = up_all([a, b])?;
        let direct = a ^ b;
        finite_result(
            PointPair { direct },
            &direct.to_array(),
            "point pair (points too far out)",
        )
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
