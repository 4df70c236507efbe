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
//!
//! **Precision.** The conformal model stores `0.5 |x|^2` beside `x`, so what is read back from
//! an object (a radius, a centre, the points of a pair, a line's point nearest the origin)
//! loses about `eps (d / s)^2` of relative precision for an object of size `s` at distance
//! `d` from the origin: a sphere of radius 1 at 1e6 reads its radius to about 1e-4, at 1e8
//! not at all. The constructors refuse only what overflows (`0.5 |x|^2` beyond the `f64`
//! range, about `|x| > 1e154`) or is degenerate; translate such scenes towards the origin
//! first (the predicates, which compare against points of the same size, fare better).

use super::*;

mod circle;
mod flat_point;
mod line;
mod plane;
mod point_pair;
mod sphere;

pub use circle::Circle;
pub use flat_point::FlatPoint;
pub use line::Line;
pub use plane::Plane;
pub use point_pair::PointPair;
pub use sphere::Sphere;

/// The point at infinity `ei` as a vector.
const EI: Vector = Vector::new(0.0, 0.0, 0.0, 0.0, 1.0);

/// The up-projections of points that build an object: [`CgaError::NonFinite`] for a NaN or
/// infinite coordinate, [`CgaError::Overflow`] when `0.5 |x|^2` overflows.
fn up_all<const N: usize>(points: [V3; N]) -> Result<[Point; N]> {
    let mut out = [Point::ORIGIN; N];
    for (o, p) in out.iter_mut().zip(points) {
        *o = Point::try_from_vec3(p)?;
    }
    Ok(out)
}
