//! Self-intersection of a cage: pairs of faces whose interiors cross. Faces are swept along
//! `x` by their bounding boxes; two faces with no common vertex intersect when an edge of one
//! crosses the other strictly; two faces sharing one vertex, when the edge of one opposite that
//! vertex crosses the other. Faces sharing an edge, touching contacts and coplanar overlaps
//! are not reported.

use crate::mesh::Mesh;
use glam::DVec3;

/// `det(b - a, c - a, d - a)`: positive when `d` is above the plane of `a b c`.
#[inline]
fn orient(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> f64 {
    (b - a).cross(c - a).dot(d - a)
}

/// Whether the segment `p q` crosses the triangle `t` strictly.
fn segment_crosses(p: DVec3, q: DVec3, t: [DVec3; 3]) -> bool {
    let [a, b, c] = t;
    let (sp, sq) = (orient(a, b, c, p), orient(a, b, c, q));
    if sp * sq >= 0.0 {
        return false;
    }
    let (x, y, z) = (orient(p, q, a, b), orient(p, q, b, c), orient(p, q, c, a));
    (x > 0.0 && y > 0.0 && z > 0.0) || (x < 0.0 && y < 0.0 && z < 0.0)
}

/// Whether faces `f` and `g` of `cage` cross (see the module docs).
fn faces_cross(cage: &Mesh, f: usize, g: usize) -> bool {
    let (tf, tg) = (cage.triangles[f], cage.triangles[g]);
    let shared: Vec<u32> = tf.iter().filter(|v| tg.contains(v)).copied().collect();
    let (cf, cg) = (cage.corners(f), cage.corners(g));
    match shared.len() {
        0 => (0..3).any(|k| {
            segment_crosses(cf[k], cf[(k + 1) % 3], cg)
                || segment_crosses(cg[k], cg[(k + 1) % 3], cf)
        }),
        1 => {
            let opposite = |t: [u32; 3], c: [DVec3; 3]| {
                let k = t.iter().position(|&v| v == shared[0]).unwrap_or(0);
                (c[(k + 1) % 3], c[(k + 2) % 3])
            };
            let (p, q) = opposite(tf, cf);
            let (r, s) = opposite(tg, cg);
            segment_crosses(p, q, cg) || segment_crosses(r, s, cf)
        }
        _ => false,
    }
}

/// The pairs of faces of `cage` that cross, lowest first (at most `limit` pairs).
pub fn self_intersections(cage: &Mesh, limit: usize) -> Vec<[u32; 2]> {
    let boxes: Vec<(DVec3, DVec3)> = (0..cage.triangle_count())
        .map(|f| {
            let [a, b, c] = cage.corners(f);
            (a.min(b).min(c), a.max(b).max(c))
        })
        .collect();
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_by(|&i, &j| boxes[i].0.x.total_cmp(&boxes[j].0.x));
    let mut out = Vec::new();
    for (k, &f) in order.iter().enumerate() {
        for &g in &order[k + 1..] {
            if boxes[g].0.x > boxes[f].1.x {
                break;
            }
            let overlap = (boxes[f].0.cmple(boxes[g].1) & boxes[g].0.cmple(boxes[f].1)).all();
            if overlap && faces_cross(cage, f, g) {
                out.push([f.min(g) as u32, f.max(g) as u32]);
                if out.len() >= limit {
                    out.sort_unstable();
                    return out;
                }
            }
        }
    }
    out.sort_unstable();
    out
}
