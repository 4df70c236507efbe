//! Mean value coordinates for closed triangle cages (Ju, Schaefer and Warren 2005), in the
//! closed form of their paper's pseudo-code: for a point `x` and cage vertices `p_j` at
//! distances `d_j` in unit directions `u_j`, each face contributes through the angles
//! `theta_i` its edges subtend at `x`. Special cases, as in CGAL's `Mean_value_coordinates_3`
//! and delfem2:
//!
//! * `x` at a cage vertex (closer than [`NEAR_VERTEX`] times the cage diagonal): the
//!   coordinate of that vertex is 1, the others 0;
//! * `x` on a face (`pi - h` below [`NEAR_FACE`] and closer to its plane than [`NEAR_VERTEX`]
//!   times the cage diagonal): the face's 2-D barycentric coordinates
//!   (`sin theta_i d_{i-1} d_{i+1}`), the others 0 (this also covers the edges);
//! * `x` in the plane of a face but outside it: the face contributes nothing.
//!
//! Coordinates are a partition of unity and reproduce affine maps of the cage (linear
//! precision); inside a non-convex cage some may be negative.

use super::CageError;
use crate::deformers::Result;
use crate::mesh::Mesh;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// Relative distance below which a point is at a cage vertex.
pub const NEAR_VERTEX: f64 = 1e-12;
/// Angular gap `pi - h` below which a point may be on a face (it then is when its distance to
/// the face's plane is below [`NEAR_VERTEX`] times the cage diagonal). The gap is of second
/// order in the distance, so it alone would snap points up to `1e-4` cage diagonals away.
pub const NEAR_FACE: f64 = 1e-8;
/// `|det(u_1, u_2, u_3)|` below which a point is in the plane of a face.
const COPLANAR: f64 = 1e-14;

/// The mean value coordinates of every point in `points` with respect to `cage` (closed,
/// checked by [`super::check_cage`]): vertex-major, `cage.vertex_count()` per point.
///
/// # Errors
/// [`CageError::TooSmall`], [`CageError::NonFinite`] or [`CageError::BadFaces`] for a cage
/// whose faces cannot be read (the first checks of [`super::check_cage`]; closedness is the
/// caller's); [`CageError::Coordinates`] naming a point whose weights do not normalise (the
/// weights sum to zero or overflow: a point far outside a degenerate cage).
pub fn mean_value_coordinates(cage: &Mesh, points: &[DVec3]) -> Result<Vec<f64>> {
    Ok(coordinates_and_winding(cage, points)?.0)
}

/// [`mean_value_coordinates`] and, from the same unit vectors, the winding number of the cage
/// at every point (1/2 for a point at a cage vertex or on a face), so that containment costs
/// almost nothing more.
///
/// # Errors
/// As [`mean_value_coordinates`].
pub fn coordinates_and_winding(cage: &Mesh, points: &[DVec3]) -> Result<(Vec<f64>, Vec<f64>)> {
    super::check::check_cage_elements(cage)?;
    let m = cage.vertex_count();
    let scale = cage.bounding_box().map_or(1.0, |b| b.diagonal());
    let mut out = vec![0.0; points.len() * m];
    let mut winding = vec![0.0; points.len()];
    let edges = Edges::new(cage);
    let failed = out
        .par_chunks_mut(m.max(1))
        .with_min_len(64)
        .zip(winding.par_iter_mut())
        .zip(points.par_iter())
        .enumerate()
        .map_init(
            || Scratch {
                d: vec![0.0; m],
                u: vec![DVec3::ZERO; m],
                angles: vec![[0.0; 3]; edges.ends.len()],
            },
            |scratch, (i, ((w, wn), &x))| {
                let (ok, n) = point_coordinates(cage, &edges, scale, x, scratch, w);
                *wn = n;
                (!ok).then_some(i)
            },
        )
        .flatten()
        .min();
    match failed {
        Some(index) => Err(CageError::Coordinates { index }.into()),
        None => Ok((out, winding)),
    }
}

/// The cage's edges, each once, and the edge opposite each corner of each face.
struct Edges {
    ends: Vec<[u32; 2]>,
    opposite: Vec<[u32; 3]>,
}

impl Edges {
    fn new(cage: &Mesh) -> Edges {
        let mut index = std::collections::HashMap::new();
        let mut ends = Vec::new();
        let opposite = cage
            .triangles
            .iter()
            .map(|t| {
                std::array::from_fn(|i| {
                    let (a, b) = (t[(i + 1) % 3], t[(i + 2) % 3]);
                    *index.entry((a.min(b), a.max(b))).or_insert_with(|| {
                        ends.push([a, b]);
                        ends.len() as u32 - 1
                    })
                })
            })
            .collect();
        Edges { ends, opposite }
    }
}

/// Per-thread scratch: distances and unit vectors to the cage vertices, and per edge the angle
/// it subtends with its sine and cosine.
struct Scratch {
    d: Vec<f64>,
    u: Vec<DVec3>,
    angles: Vec<[f64; 3]>,
}

/// The coordinates of one point into `w` (length `m`). Returns whether they normalised, and
/// the winding number.
fn point_coordinates(
    cage: &Mesh,
    edges: &Edges,
    scale: f64,
    x: DVec3,
    scratch: &mut Scratch,
    w: &mut [f64],
) -> (bool, f64) {
    let Scratch { d, u, angles } = scratch;
    w.fill(0.0);
    let mut solid = 0.0;
    for (j, &p) in cage.positions.iter().enumerate() {
        let r = p - x;
        d[j] = r.length();
        if d[j] <= NEAR_VERTEX * scale {
            w[j] = 1.0;
            return (true, 0.5);
        }
        u[j] = r / d[j];
    }
    // theta = 2 asin(l / 2) for the chord l between unit vectors, so
    // sin theta = l sqrt(1 - l^2 / 4) and cos theta = 1 - l^2 / 2.
    for (e, &[a, b]) in edges.ends.iter().enumerate() {
        let l = (u[a as usize] - u[b as usize]).length().min(2.0);
        angles[e] = [
            2.0 * (0.5 * l).asin(),
            l * (1.0 - 0.25 * l * l).max(0.0).sqrt(),
            1.0 - 0.5 * l * l,
        ];
    }
    for (t, opposite) in cage.triangles.iter().zip(&edges.opposite) {
        let v = [t[0] as usize, t[1] as usize, t[2] as usize];
        let [a0, a1, a2] = opposite.map(|e| angles[e as usize]);
        let theta = [a0[0], a1[0], a2[0]];
        let sin_t = [a0[1], a1[1], a2[1]];
        let cos_t = [a0[2], a1[2], a2[2]];
        let h = 0.5 * (theta[0] + theta[1] + theta[2]);
        if PI - h < NEAR_FACE && on_plane(cage, t, x, scale) {
            // On the face: 2-D barycentric coordinates.
            w.fill(0.0);
            let mut sum = 0.0;
            for i in 0..3 {
                let b = sin_t[i] * d[v[(i + 2) % 3]] * d[v[(i + 1) % 3]];
                w[v[i]] = b;
                sum += b;
            }
            if sum.is_nan() || sum <= 0.0 {
                return (false, 0.5);
            }
            w.iter_mut().for_each(|x| *x /= sum);
            return (true, 0.5);
        }
        let det = u[v[0]].dot(u[v[1]].cross(u[v[2]]));
        // Van Oosterom-Strackee: the face's signed solid angle at x (u_i . u_j is the cosine
        // of the angle opposite corner k).
        solid += 2.0 * det.atan2(1.0 + cos_t[0] + cos_t[1] + cos_t[2]);
        if det.abs() < COPLANAR {
            continue; // in the face's plane, outside the face
        }
        let sign = det.signum();
        let (sin_h, cos_h) = h.sin_cos();
        let mut c = [0.0; 3];
        let mut s = [0.0; 3];
        for i in 0..3 {
            let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
            // sin(h - theta_i) = sin h cos theta_i - cos h sin theta_i
            let sin_h_t = sin_h * cos_t[i] - cos_h * sin_t[i];
            c[i] = (2.0 * sin_h * sin_h_t / (sin_t[i1] * sin_t[i2]) - 1.0).clamp(-1.0, 1.0);
            s[i] = sign * (1.0 - c[i] * c[i]).sqrt();
        }
        if s.iter().any(|s| s.abs() <= COPLANAR) {
            continue;
        }
        for i in 0..3 {
            let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
            let num = theta[i] - c[i1] * theta[i2] - c[i2] * theta[i1];
            w[v[i]] += num / (d[v[i]] * sin_t[i1] * s[i2]);
        }
    }
    let winding = solid / (4.0 * PI);
    let sum: f64 = w.iter().sum();
    if !(sum.is_finite() && sum.abs() > 0.0) {
        return (false, winding);
    }
    let inv = 1.0 / sum;
    w.iter_mut().for_each(|x| *x *= inv);
    (w.iter().all(|x| x.is_finite()), winding)
}

/// Whether `x` lies in the plane of face `t` (relative to `scale`).
fn on_plane(cage: &Mesh, t: &[u32; 3], x: DVec3, scale: f64) -> bool {
    let [a, b, c] = t.map(|v| cage.positions[v as usize]);
    let n = (b - a).cross(c - a).normalize_or_zero();
    (x - a).dot(n).abs() <= NEAR_VERTEX * scale
}
