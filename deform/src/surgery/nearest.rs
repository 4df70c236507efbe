//! Where a tool that misses the surface is: the surface point nearest to a segment (a blade,
//! a drill's axis), for the error that says how far the tool is and where to aim.

use super::ray::ray_triangle;
use crate::mesh::numbers::{short_number, short_point};
use glam::DVec3;

/// The surface point nearest to a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Nearest {
    /// The distance between the segment and the surface.
    pub distance: f64,
    /// The point of the surface.
    pub surface: DVec3,
    /// The point of the segment.
    pub tool: DVec3,
}

impl Nearest {
    /// "passes D from the surface (nearest surface point (x, y, z), from (x, y, z) on the
    /// tool)".
    pub fn describe(&self) -> String {
        format!(
            "it passes {} from the surface (nearest surface point {}, from {} on the tool)",
            short_number(self.distance),
            short_point(self.surface),
            short_point(self.tool)
        )
    }
}

/// The point of the triangles nearest to the segment `a b` (by brute force: an error path):
/// the nearest of the ends to each face, of the face's edges to the segment, and where the
/// segment crosses the face.
/// `None` for a mesh without triangles or non-finite input.
pub(crate) fn nearest_to_segment(
    triangles: &[[u32; 3]],
    positions: &[DVec3],
    a: DVec3,
    b: DVec3,
) -> Option<Nearest> {
    let mut best: Option<Nearest> = None;
    let mut offer = |surface: DVec3, tool: DVec3| {
        let distance = (surface - tool).length();
        if distance.is_finite() && best.is_none_or(|n| distance < n.distance) {
            best = Some(Nearest {
                distance,
                surface,
                tool,
            });
        }
    };
    for t in triangles {
        let [p, q, r] = t.map(|v| positions[v as usize]);
        for end in [a, b] {
            offer(closest_on_triangle(end, p, q, r), end);
        }
        for (s, e) in [(p, q), (q, r), (r, p)] {
            let (on_edge, on_tool) = closest_between_segments(s, e, a, b);
            offer(on_edge, on_tool);
        }
        // A segment through the face: the corners and edges are not the nearest then.
        if let Some((t, _)) = ray_triangle(a, b - a, [p, q, r]).filter(|&(t, _)| t <= 1.0) {
            let hit = a + t * (b - a);
            offer(hit, hit);
        }
    }
    best
}

/// The distance from `x` to the convex hull of four points (the union of the four triangles
/// they make), e.g. the quad a blade sweeps between two time steps.
pub(crate) fn distance_to_hull(x: DVec3, corners: &[DVec3; 4]) -> f64 {
    let [a, b, c, d] = *corners;
    [(a, b, c), (a, c, d), (a, b, d), (b, c, d)]
        .iter()
        .map(|&(p, q, r)| x.distance(closest_on_triangle(x, p, q, r)))
        .fold(f64::INFINITY, f64::min)
}

/// The point of triangle `p q r` nearest to `x` (Ericson, "Real-Time Collision Detection",
/// 5.1.5: by the Voronoi regions of the corners, edges and face).
fn closest_on_triangle(x: DVec3, p: DVec3, q: DVec3, r: DVec3) -> DVec3 {
    let (ab, ac, ap) = (q - p, r - p, x - p);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return p;
    }
    let bp = x - q;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return q;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return p + d1 / (d1 - d3) * ab;
    }
    let cp = x - r;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return r;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return p + d2 / (d2 - d6) * ac;
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return q + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (r - q);
    }
    let denom = va + vb + vc;
    if denom.abs() < f64::MIN_POSITIVE {
        return p; // A degenerate triangle: its corners and edges were offered already.
    }
    p + vb / denom * ab + vc / denom * ac
}

/// The closest points of segments `p1 q1` and `p2 q2` (Ericson 5.1.9).
fn closest_between_segments(p1: DVec3, q1: DVec3, p2: DVec3, q2: DVec3) -> (DVec3, DVec3) {
    let (d1, d2, r) = (q1 - p1, q2 - p2, p1 - p2);
    let (a, e, f) = (d1.length_squared(), d2.length_squared(), d2.dot(r));
    let tiny = f64::MIN_POSITIVE;
    let (s, t) = if a <= tiny && e <= tiny {
        (0.0, 0.0)
    } else if a <= tiny {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(r);
        if e <= tiny {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(d2);
            let denom = a * e - b * b;
            let mut s = if denom > tiny {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
            (s, t)
        }
    };
    (p1 + s * d1, p2 + t * d2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearest_point_of_a_square_to_segments_above_and_beside_it() {
        let positions = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let tris = [[0, 1, 2], [0, 2, 3]];
        // Straight above the middle, pointing up: the face below its lower end.
        let n = nearest_to_segment(
            &tris,
            &positions,
            DVec3::new(0.5, 0.4, 2.0),
            DVec3::new(0.5, 0.4, 3.0),
        )
        .expect("a point");
        assert!((n.distance - 2.0).abs() < 1e-12);
        assert!((n.surface - DVec3::new(0.5, 0.4, 0.0)).length() < 1e-12);
        // Beside the square, crossing over the edge x = 1 at height 1: the edge.
        let n = nearest_to_segment(
            &tris,
            &positions,
            DVec3::new(2.0, 0.5, 1.0),
            DVec3::new(3.0, 0.5, -1.0),
        )
        .expect("a point");
        let want = 3.0 / 5f64.sqrt();
        assert!((n.distance - want).abs() < 1e-12, "{n:?} vs {want}");
        assert!((n.surface - DVec3::new(1.0, 0.5, 0.0)).length() < 1e-12);
        // Through the square's interior, far from its corners and edges: where it crosses.
        let n = nearest_to_segment(
            &tris,
            &positions,
            DVec3::new(0.3, 0.6, -1.0),
            DVec3::new(0.3, 0.6, 1.0),
        )
        .expect("a point");
        assert_eq!(n.distance, 0.0, "{n:?}");
        assert!((n.surface - DVec3::new(0.3, 0.6, 0.0)).length() < 1e-12);
        assert_eq!(
            nearest_to_segment(&[], &positions, DVec3::ZERO, DVec3::X),
            None
        );
    }
}
