//! Flat points: the direct bivector `X ^ ei`.

use super::*;

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
