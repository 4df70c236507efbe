//! Skin weights of new vertices (second paper, section 4.3): interpolate the influences of the
//! vertices a new point is made from, keep the 4 largest, renormalise. The same interpolation
//! records each vertex's sources (the input vertices it is made from, with their coefficients),
//! so any other per-vertex attribute (UVs, colours) follows the weights.

use crate::skinning::Influences;

/// The most influences a new vertex gets.
pub const NEW_VERTEX_INFLUENCES: usize = 4;

/// Append to `out` (rows of `out.width`) the influences of `sum_k c_k * row(v_k)` over
/// `(vertex, coefficient)` pairs of `src`: merged by joint, the 4 largest kept, renormalised,
/// padded with zero weights on joint 0.
pub fn push_interpolated(src: &Influences, parts: &[(u32, f64)], out: &mut Influences) {
    let mut list: Vec<(u32, f64)> = Vec::with_capacity(8);
    for &(v, c) in parts {
        for (j, w) in src.row(v as usize) {
            if w == 0.0 || c == 0.0 {
                continue;
            }
            match list.iter_mut().find(|e| e.0 == j) {
                Some(e) => e.1 += c * w,
                None => list.push((j, c * w)),
            }
        }
    }
    let len = list.len();
    list.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
    let keep = len.min(NEW_VERTEX_INFLUENCES).min(out.width);
    let sum: f64 = list[..keep].iter().map(|e| e.1).sum();
    let any = sum > 0.0;
    for k in 0..out.width {
        let (j, w) = match list.get(k) {
            Some(&(j, w)) if k < keep && any => (j, w / sum),
            // No influence at all (cannot happen for normalised input): bind to joint 0.
            _ if k == 0 && !any => (0, 1.0),
            _ => (0, 0.0),
        };
        out.joints.push(j);
        out.weights.push(w);
    }
}

/// Append vertex `v`'s row of `src` unchanged.
pub fn push_copy(src: &Influences, v: u32, out: &mut Influences) {
    let r = v as usize * src.width..(v as usize + 1) * src.width;
    out.joints.extend_from_slice(&src.joints[r.clone()]);
    out.weights.extend_from_slice(&src.weights[r]);
}

/// Sources of the input vertices themselves: row `v` is `(v, 1)`. Rows are
/// [`NEW_VERTEX_INFLUENCES`] wide; the surgery extends them as it extends the weights
/// ([`push_interpolated`] for new vertices, copies for copied ones), with input vertex indices
/// in place of joints.
pub fn identity_sources(n: usize) -> Influences {
    let width = NEW_VERTEX_INFLUENCES;
    let mut s = Influences {
        width,
        joints: vec![0; n * width],
        weights: vec![0.0; n * width],
    };
    for v in 0..n {
        s.joints[v * width] = v as u32;
        s.weights[v * width] = 1.0;
    }
    s
}
