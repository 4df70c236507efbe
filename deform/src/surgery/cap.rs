//! Caps: a planar boundary loop triangulated by ear clipping, so a cut piece can be closed.

use glam::{DVec2, DVec3};

/// Twice the signed area of the polygon.
fn signed_area2(p: &[DVec2]) -> f64 {
    (0..p.len())
        .map(|i| p[i].perp_dot(p[(i + 1) % p.len()]))
        .sum()
}

/// Whether `x` is inside (or on) the triangle `a b c` of orientation `sign`.
fn inside(a: DVec2, b: DVec2, c: DVec2, x: DVec2, sign: f64) -> bool {
    let e = |p: DVec2, q: DVec2| sign * (q - p).perp_dot(x - p) >= 0.0;
    e(a, b) && e(b, c) && e(c, a)
}

/// Triangulate the simple polygon `loop3` (3-D points on the plane with unit normal `n`, in
/// order) by ear clipping; triangles index `loop3` and keep the polygon's order (winding).
/// `None` when no ear can be found (a self-intersecting loop).
pub fn ear_clip(loop3: &[DVec3], n: DVec3) -> Option<Vec<[usize; 3]>> {
    let k = loop3.len();
    if k < 3 {
        return None;
    }
    let u = n.any_orthonormal_vector();
    let v = n.cross(u);
    let p: Vec<DVec2> = loop3
        .iter()
        .map(|x| DVec2::new(x.dot(u), x.dot(v)))
        .collect();
    let sign = signed_area2(&p).signum();
    if sign == 0.0 {
        return None;
    }
    let mut idx: Vec<usize> = (0..k).collect();
    let mut out = Vec::with_capacity(k - 2);
    while idx.len() > 3 {
        let m = idx.len();
        let ear = (0..m).find(|&i| {
            let (a, b, c) = (idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]);
            let convex = sign * (p[b] - p[a]).perp_dot(p[c] - p[b]) > 0.0;
            convex
                && idx.iter().all(|&o| {
                    o == a
                        || o == b
                        || o == c
                        || p[o] == p[a]
                        || p[o] == p[b]
                        || p[o] == p[c]
                        || !inside(p[a], p[b], p[c], p[o], sign)
                })
        })?;
        let (a, b, c) = (idx[(ear + m - 1) % m], idx[ear], idx[(ear + 1) % m]);
        out.push([a, b, c]);
        idx.remove(ear);
    }
    out.push([idx[0], idx[1], idx[2]]);
    Some(out)
}
