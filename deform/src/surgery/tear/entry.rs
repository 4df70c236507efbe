//! Where a blade enters the skin: the first face it hits, and that point made a vertex.

use super::super::soup::Soup;
use super::super::{FaceBvh, SurgeryError};
use super::seams::Seams;
use glam::DVec3;

/// The first face the segment `a -> b` hits, with the point (Moller-Trumbore over the faces
/// the index returns for the segment's box).
pub(super) fn first_hit(
    bvh: &FaceBvh,
    tris: &[[u32; 3]],
    pos: &[DVec3],
    a: DVec3,
    b: DVec3,
) -> Option<(u32, DVec3)> {
    let (lo, hi) = (a.min(b), a.max(b));
    let d = b - a;
    let mut best: Option<(f64, u32)> = None;
    bvh.query(
        |bx| bx.min.cmple(hi).all() && bx.max.cmpge(lo).all(),
        |f| {
            let [p, q, r] = tris[f as usize].map(|v| pos[v as usize]);
            let (e1, e2) = (q - p, r - p);
            let h = d.cross(e2);
            let det = e1.dot(h);
            if det.abs() < 1e-300 {
                return;
            }
            let s = a - p;
            let u = s.dot(h) / det;
            let qv = s.cross(e1);
            let v = d.dot(qv) / det;
            let t = e2.dot(qv) / det;
            if (0.0..=1.0).contains(&u)
                && v >= 0.0
                && u + v <= 1.0
                && (0.0..=1.0).contains(&t)
                && best.is_none_or(|b| t < b.0)
            {
                best = Some((t, f));
            }
        },
    );
    best.map(|(t, f)| (f, a + t * d))
}

/// Make the point `p` on input face `f0` a vertex: a corner within `snap` of it, a point on
/// an edge when it is that close to the edge (the edge's seam twin split too), else a new
/// vertex splitting its face in three (a point on an edge is `p` moved onto the edge).
pub(super) fn insert_point(
    soup: &mut Soup,
    seams: &mut Seams,
    f0: u32,
    p: DVec3,
    snap: f64,
) -> Result<u32, SurgeryError> {
    // The face (of those made from f0 so far) that holds p.
    let candidates: Vec<u32> = (0..soup.tris.len() as u32)
        .filter(|&f| soup.root(f) == f0)
        .collect();
    let mut best = (f64::INFINITY, candidates[0], [0.0; 3]);
    for &f in &candidates {
        let [a, b, c] = soup.tris[f as usize].map(|v| soup.at(v));
        let bary = barycentric(p, a, b, c);
        let outside = -bary.iter().copied().fold(0.0, f64::min);
        if outside < best.0 {
            best = (outside, f, bary);
        }
    }
    let (_, f, bary) = best;
    let t = soup.tris[f as usize];
    if let Some(k) = (0..3).find(|&k| bary[k] > 1.0 - snap) {
        return Ok(t[k]);
    }
    if let Some(k) = (0..3).find(|&k| bary[k] < snap) {
        // On the edge opposite corner k.
        let (a, b) = (t[(k + 1) % 3], t[(k + 2) % 3]);
        let u = bary[(k + 2) % 3] / (bary[(k + 1) % 3] + bary[(k + 2) % 3]);
        let q = soup.at(a).lerp(soup.at(b), u);
        let v = soup.add_vertex(q, &[(a, 1.0 - u), (b, u)])?;
        seams.push(v, v);
        seams.split_edge(soup, f, k, v)?;
        return Ok(v);
    }
    let v = soup.add_vertex(p, &[(t[0], bary[0]), (t[1], bary[1]), (t[2], bary[2])])?;
    seams.push(v, v);
    seams.split_face(soup, f, v);
    Ok(v)
}

/// Barycentric coordinates of `p` (projected) in the triangle `a b c`.
fn barycentric(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> [f64; 3] {
    let (v0, v1, v2) = (b - a, c - a, p - a);
    let (d00, d01, d11) = (v0.dot(v0), v0.dot(v1), v1.dot(v1));
    let (d20, d21) = (v2.dot(v0), v2.dot(v1));
    let den = d00 * d11 - d01 * d01;
    let v = (d11 * d20 - d01 * d21) / den;
    let w = (d00 * d21 - d01 * d20) / den;
    [1.0 - v - w, v, w]
}
