//! The first triangle a ray meets, through the face BVH: the pick of an interactive editor
//! (a click is a ray from the eye), answered in O(log F) instead of a scan of every face.

use super::bvh::FaceBvh;
use crate::mesh::{Aabb, Mesh};
use glam::DVec3;

/// Where a ray first meets a mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit {
    /// The triangle hit.
    pub face: u32,
    /// The ray parameter: the hit is `origin + t * direction`.
    pub t: f64,
    /// The hit point.
    pub point: DVec3,
    /// Barycentric coordinates of the hit in the triangle's corners.
    pub barycentric: [f64; 3],
}

impl RayHit {
    /// The triangle corner nearest the hit (the largest barycentric coordinate).
    pub fn nearest_corner(&self, mesh: &Mesh) -> u32 {
        let b = self.barycentric;
        let k = if b[0] >= b[1] && b[0] >= b[2] {
            0
        } else if b[1] >= b[2] {
            1
        } else {
            2
        };
        mesh.triangles[self.face as usize][k]
    }
}

/// Whether the ray `origin + t d` (`t >= 0`, `inv = 1 / d` per axis) meets `b` before `t_max`.
fn ray_meets_box(b: &Aabb, origin: DVec3, inv: DVec3, t_max: f64) -> bool {
    let t1 = (b.min - origin) * inv;
    let t2 = (b.max - origin) * inv;
    // NaN (0 * inf, a ray in a box's face plane) counts as a hit: min/max ignore it.
    let near = t1.min(t2).max_element().max(0.0);
    let far = t1.max(t2).min_element().min(t_max);
    near <= far
}

/// Möller-Trumbore: the ray parameter and barycentrics of the hit with triangle `abc`, both
/// sides counted; `None` for a miss, a parallel ray or a degenerate triangle.
pub(crate) fn ray_triangle(
    origin: DVec3,
    d: DVec3,
    [a, b, c]: [DVec3; 3],
) -> Option<(f64, [f64; 3])> {
    let (e1, e2) = (b - a, c - a);
    let p = d.cross(e2);
    let det = e1.dot(p);
    if det.abs() <= 1e-300 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let s = origin - a;
    let u = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = d.dot(q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inv;
    (t >= 0.0).then_some((t, [1.0 - u - v, u, v]))
}

impl FaceBvh {
    /// The first triangle of `mesh` (the mesh this tree was built or refitted for) that the ray
    /// `origin + t direction`, `t >= 0`, meets; `None` when it meets none, or when the ray is
    /// not finite or has no direction.
    pub fn ray_hit(&self, mesh: &Mesh, origin: DVec3, direction: DVec3) -> Option<RayHit> {
        if !origin.is_finite() || !direction.is_finite() || direction == DVec3::ZERO {
            return None;
        }
        let inv = direction.recip();
        let best = std::cell::Cell::new(f64::INFINITY);
        let mut hit = None;
        self.query(
            |b| ray_meets_box(b, origin, inv, best.get()),
            |f| {
                if let Some((t, barycentric)) =
                    ray_triangle(origin, direction, mesh.corners(f as usize))
                {
                    if t < best.get() {
                        best.set(t);
                        hit = Some(RayHit {
                            face: f,
                            t,
                            point: origin + t * direction,
                            barycentric,
                        });
                    }
                }
            },
        );
        hit
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes::icosphere;

    /// The nearest hit by scanning every face.
    fn scan(mesh: &Mesh, o: DVec3, d: DVec3) -> Option<(u32, f64)> {
        (0..mesh.triangle_count())
            .filter_map(|f| ray_triangle(o, d, mesh.corners(f)).map(|(t, _)| (f as u32, t)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }

    #[test]
    fn the_tree_finds_the_same_first_hit_as_a_scan_of_every_face() {
        let mesh = icosphere(1.0, 3);
        let bvh = FaceBvh::new(&mesh);
        let mut hits = 0;
        for i in 0..400 {
            let a = i as f64 * 0.731;
            let o = DVec3::new(3.0 * a.cos(), 0.37 * (i % 7) as f64 - 1.2, 3.0 * a.sin());
            // Aim across the sphere, some rays past it.
            let target = DVec3::new((i % 5) as f64 * 0.75 - 1.5, (i % 3) as f64 * 1.2 - 1.2, 0.1);
            let d = target - o;
            let got = bvh.ray_hit(&mesh, o, d);
            let want = scan(&mesh, o, d);
            match (got, want) {
                (Some(h), Some((_, t))) => {
                    hits += 1;
                    assert!((h.t - t).abs() < 1e-12, "ray {i}: {} vs {t}", h.t);
                    assert!((h.point.length() - 1.0).abs() < 0.02, "on the sphere");
                    let [a, b, c] = mesh.corners(h.face as usize);
                    let [u, v, w] = h.barycentric;
                    assert!((u * a + v * b + w * c - h.point).length() < 1e-12);
                }
                (None, None) => {}
                (g, w) => panic!("ray {i}: tree {g:?}, scan {w:?}"),
            }
        }
        assert!(hits > 100 && hits < 400, "{hits} hits: both cases tested");
    }

    #[test]
    fn rays_that_are_not_rays_meet_nothing() {
        let mesh = icosphere(1.0, 2);
        let bvh = FaceBvh::new(&mesh);
        let o = DVec3::new(0.0, 0.0, 5.0);
        assert!(bvh.ray_hit(&mesh, o, DVec3::ZERO).is_none());
        assert!(bvh
            .ray_hit(&mesh, o, DVec3::new(f64::NAN, 0.0, -1.0))
            .is_none());
        assert!(bvh
            .ray_hit(&mesh, DVec3::splat(f64::INFINITY), -DVec3::Z)
            .is_none());
        // Pointing away.
        assert!(bvh.ray_hit(&mesh, o, DVec3::Z).is_none());
        // Axis-aligned (zero components, infinite inverses) still hits.
        let h = bvh.ray_hit(&mesh, o, -DVec3::Z).expect("hits the sphere");
        assert!((h.t - 4.0).abs() < 0.02);
        assert!(mesh.triangles[h.face as usize].contains(&h.nearest_corner(&mesh)));
    }
}
