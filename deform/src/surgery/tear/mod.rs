//! Tearing (second paper, Algorithm 2): a scalpel at successive time steps opens an incision.
//!
//! For each step the point `S_i` where the blade `A_i B_i` enters the skin is found with the
//! face index (the first hit from `A_i`) and inserted as a vertex (snapped onto a corner or an
//! edge within [`TearOptions::snap`] of it). The plane through `S_i` and the next blade
//! `A_{i+1} B_{i+1}` is then followed over the skin from `S_i` to `S_{i+1}`: each edge the
//! plane crosses is split at the crossing (both its faces), corners within the snap fraction
//! are taken instead, so the incision becomes a chain of mesh edges. A sequence of steps makes
//! one longer incision. Every incision vertex but the two ends is then duplicated: the faces
//! on one side of the incision keep it, those on the other side get the copy, so the surface
//! opens; [`TearOptions::open`] moves the two lips apart along the planes' normals (tapered to
//! zero at the ends). New vertices get interpolated weights (4 largest, renormalised).

use super::nearest::nearest_to_segment;
use super::soup::Soup;
use super::split::{local_loops, FaceFate};
use super::{check_snap, Frame, SkinnedMesh, Surgery, SurgeryError, VertexOrigin};
use crate::mesh::Mesh;
use glam::DVec3;
use std::collections::{HashMap, HashSet};

/// The blade at one time step: the segment from `a` to `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scalpel {
    /// One end of the blade (the handle side).
    pub a: DVec3,
    /// The other end.
    pub b: DVec3,
}

/// Options of [`Surgery::tear`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TearOptions {
    /// Corners closer to the incision than this fraction of an edge are taken as incision
    /// vertices instead of splitting the edge (no slivers). In `[0, 0.5)`; default 0.02.
    pub snap: f64,
    /// How far the two lips are pulled apart at the incision's middle (0: a closed slit).
    pub open: f64,
}

impl Default for TearOptions {
    fn default() -> Self {
        TearOptions {
            snap: 0.02,
            open: 0.0,
        }
    }
}

/// The torn mesh and what changed.
#[derive(Clone, Debug, PartialEq)]
pub struct TearResult {
    /// The torn mesh: the input vertices in input order, then the new ones.
    pub mesh: SkinnedMesh,
    /// Where each vertex comes from.
    pub origin: Vec<VertexOrigin>,
    /// The incision: its vertices from the first scalpel point to the last (one lip).
    pub incision: Vec<u32>,
    /// Each step's plane, as `(unit normal, point on it)`.
    pub planes: Vec<(DVec3, DVec3)>,
    /// Vertices added (incision points and copies).
    pub new_vertices: usize,
    /// Incision vertices duplicated (the inner ones).
    pub duplicated: usize,
    /// Input faces re-triangulated.
    pub changed_faces: usize,
    /// Boundary loops of the result.
    pub boundary_loops: usize,
}

/// Where a step of the walk goes next.
enum Next {
    Vertex(u32),
    Edge { f: u32, k: usize, t: f64 },
}

/// The largest opening of a tear, in bounding-box diagonals of the model.
pub const MAX_OPEN_PER_DIAGONAL: f64 = 100.0;

impl Surgery {
    /// Tear along the scalpel positions (at least two); see the module documentation.
    ///
    /// # Errors
    /// [`SurgeryError::BadTool`] for fewer than two positions, a non-finite or zero-length
    /// blade, a plane that is not defined (the blade moved along itself), an incision that
    /// cannot be followed from one scalpel point to the next (steps too large for the mesh),
    /// an opening over [`MAX_OPEN_PER_DIAGONAL`] bounding-box diagonals;
    /// [`SurgeryError::Misses`] when a blade does not touch the surface;
    /// [`SurgeryError::Broken`] when the mesh bookkeeping breaks an invariant (a bug).
    pub fn tear(
        &self,
        scalpel: &[Scalpel],
        frame: Frame,
        options: &TearOptions,
    ) -> Result<TearResult, SurgeryError> {
        if scalpel.len() < 2 {
            return Err(SurgeryError::BadTool(
                "a tear needs at least two scalpel positions".into(),
            ));
        }
        if let Some(i) = scalpel
            .iter()
            .position(|s| !(s.a.is_finite() && s.b.is_finite()) || s.a == s.b)
        {
            return Err(SurgeryError::BadTool(format!(
                "scalpel {i} is not a finite, non-empty segment"
            )));
        }
        check_snap(options.snap)?;
        if !options.open.is_finite() {
            return Err(SurgeryError::BadTool("the opening is not finite".into()));
        }
        // An opening far beyond the model's size would only push the lips out of range (and
        // past what f64 and the f32 of a .glb hold); the model's scale bounds it.
        if options.open.abs() > MAX_OPEN_PER_DIAGONAL * self.diagonal {
            return Err(SurgeryError::BadTool(format!(
                "the opening {:.3e} is over {MAX_OPEN_PER_DIAGONAL} times the model's size \
                 (bounding-box diagonal {:.3e})",
                options.open, self.diagonal
            )));
        }
        let src = &self.mesh;
        let n0 = src.mesh.vertex_count();
        let resolved = self.resolve(frame)?;
        let (positions, skin, bvh) = (resolved.positions, resolved.skin, &*resolved.bvh);
        // Where each blade enters the skin, on the input mesh.
        let mut hits = Vec::with_capacity(scalpel.len());
        for (i, s) in scalpel.iter().enumerate() {
            let Some(hit) = first_hit(bvh, &src.mesh.triangles, positions, s.a, s.b) else {
                let p = |v: DVec3| format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z);
                let whereabouts = nearest_to_segment(&src.mesh.triangles, positions, s.a, s.b)
                    .map_or(String::new(), |n| format!(": {}", n.describe()));
                return Err(SurgeryError::BadTool(format!(
                    "scalpel {i}, the blade from {} to {}, does not touch the surface{whereabouts}",
                    p(s.a),
                    p(s.b)
                )));
            };
            hits.push(hit);
        }
        let mut soup = Soup::new(
            &src.mesh.triangles,
            &self.topology.neighbors,
            &self.topology.vertex_face,
            &src.mesh.positions,
            positions,
            &src.influences,
            skin,
        );
        let points: Vec<u32> = hits
            .iter()
            .map(|&(f, p)| insert_point(&mut soup, f, p, options.snap))
            .collect::<Result<_, _>>()?;
        // Follow each step's plane from one scalpel point to the next.
        let mut incision = vec![points[0]];
        let mut planes = Vec::new();
        for i in 0..points.len() - 1 {
            let s = soup.at(points[i]);
            let next = scalpel[i + 1];
            let normal = (next.a - s).cross(next.b - s);
            let len = normal.length();
            let scale = (next.a - s).length() * (next.b - s).length();
            if len.is_nan() || len <= 1e-12 * scale {
                return Err(SurgeryError::BadTool(format!(
                    "step {i}: the scalpel point and the next blade are collinear: no plane"
                )));
            }
            let normal = normal / len;
            planes.push((normal, s));
            if points[i] == points[i + 1] {
                continue;
            }
            let path = walk(&mut soup, points[i], points[i + 1], normal, s, options.snap)?;
            incision.extend_from_slice(&path[1..]);
        }
        // Open: the faces on one side of the incision get copies of its inner vertices.
        let duplicated = open_incision(&mut soup, &incision, &planes, options.open)?;
        let new_vertices = soup.rest.len() - n0;
        let changed: Vec<u32> = (0..src.mesh.triangle_count() as u32)
            .filter(|&f| soup.touched[f as usize])
            .collect();
        let produced: Vec<([u32; 3], u8)> = (0..soup.tris.len() as u32)
            .filter(|&f| soup.touched[soup.root(f) as usize])
            .map(|f| (soup.tris[f as usize], 0u8))
            .collect();
        let fate = |f: u32| {
            if soup.touched[f as usize] {
                FaceFate::Changed
            } else {
                FaceFate::Kept(0)
            }
        };
        let boundary_loops = local_loops(
            &self.topology,
            &src.mesh.triangles,
            fate,
            &changed,
            &[],
            &produced,
            0,
        )
        .len();
        Ok(TearResult {
            mesh: SkinnedMesh {
                mesh: Mesh::new(soup.rest, soup.tris),
                influences: soup.influences,
            },
            origin: soup.origin,
            incision,
            planes,
            new_vertices,
            duplicated,
            changed_faces: changed.len(),
            boundary_loops,
        })
    }
}

/// The first face the segment `a -> b` hits, with the point (Moller-Trumbore over the faces
/// the index returns for the segment's box).
fn first_hit(
    bvh: &super::FaceBvh,
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
/// an edge when it is that close to the edge, else a new vertex splitting its face in three.
fn insert_point(soup: &mut Soup, f0: u32, p: DVec3, snap: f64) -> Result<u32, SurgeryError> {
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
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let s = bary[i] + bary[j];
        let v = soup.add_vertex(p, &[(t[i], bary[i] / s), (t[j], bary[j] / s)])?;
        soup.split_edge(f, k, v)?;
        return Ok(v);
    }
    let v = soup.add_vertex(p, &[(t[0], bary[0]), (t[1], bary[1]), (t[2], bary[2])])?;
    soup.split_face(f, v);
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

/// Follow the plane `(normal, point)` over the surface from vertex `from` to vertex `to`,
/// splitting the edges it crosses; returns the incision's vertices.
fn walk(
    soup: &mut Soup,
    from: u32,
    to: u32,
    normal: DVec3,
    point: DVec3,
    snap: f64,
) -> Result<Vec<u32>, SurgeryError> {
    let mut sd: HashMap<u32, f64> = HashMap::new();
    sd.insert(from, 0.0);
    sd.insert(to, 0.0);
    let mut path = vec![from];
    let (mut v, mut prev) = (from, u32::MAX);
    let target = soup.at(to);
    let limit = 4 * soup.tris.len() + 16;
    for _ in 0..limit {
        if v == to {
            return Ok(path);
        }
        let here = soup.at(v);
        let toward = target - here;
        let mut best: Option<(f64, Next)> = None;
        let consider = |score: f64, next: Next, best: &mut Option<(f64, Next)>| {
            if best.as_ref().is_none_or(|b| score < b.0) {
                *best = Some((score, next));
            }
        };
        for f in soup.fan(v)? {
            let t = soup.tris[f as usize];
            let k = soup.corner(f, v)?;
            let (a, b) = (t[(k + 1) % 3], t[(k + 2) % 3]);
            let mut s = |x: u32| {
                *sd.entry(x)
                    .or_insert_with(|| normal.dot(soup.at(x) - point))
            };
            let (sa, sb) = (s(a), s(b));
            let score = |p: DVec3| {
                let ahead = (p - here).dot(toward) > 0.0;
                p.distance(target) + if ahead { 0.0 } else { 1e300 }
            };
            for (x, sx) in [(a, sa), (b, sb)] {
                if sx == 0.0 && x != prev {
                    consider(score(soup.at(x)), Next::Vertex(x), &mut best);
                }
            }
            if sa * sb < 0.0 {
                let t_ab = sa / (sa - sb);
                if t_ab < snap && a != prev {
                    sd.insert(a, 0.0);
                    consider(score(soup.at(a)), Next::Vertex(a), &mut best);
                } else if 1.0 - t_ab < snap && b != prev {
                    sd.insert(b, 0.0);
                    consider(score(soup.at(b)), Next::Vertex(b), &mut best);
                } else {
                    let p = soup.at(a).lerp(soup.at(b), t_ab);
                    consider(score(p), Next::Edge { f, k, t: t_ab }, &mut best);
                }
            }
        }
        let Some((score, next)) = best else {
            break;
        };
        if score >= 1e299 {
            break;
        }
        prev = v;
        v = match next {
            Next::Vertex(x) => x,
            Next::Edge { f, k, t } => {
                let tri = soup.tris[f as usize];
                let (a, b) = (tri[(k + 1) % 3], tri[(k + 2) % 3]);
                let p = soup.at(a).lerp(soup.at(b), t);
                let m = soup.add_vertex(p, &[(a, 1.0 - t), (b, t)])?;
                sd.insert(m, 0.0);
                soup.split_edge(f, k, m)?;
                m
            }
        };
        path.push(v);
    }
    Err(SurgeryError::BadTool(
        "the incision could not be followed from one scalpel point to the next: take smaller steps"
            .into(),
    ))
}

/// Duplicate the incision's inner vertices: the faces right of it (seen along the incision
/// with the surface's orientation) get the copies. Then pull the lips apart by `open`.
fn open_incision(
    soup: &mut Soup,
    incision: &[u32],
    planes: &[(DVec3, DVec3)],
    open: f64,
) -> Result<usize, SurgeryError> {
    let m = incision.len();
    if m < 3 {
        return Ok(0);
    }
    let mut path_edges: HashSet<(u32, u32)> = HashSet::new();
    for w in incision.windows(2) {
        path_edges.insert((w[0].min(w[1]), w[0].max(w[1])));
    }
    let total: f64 = incision
        .windows(2)
        .map(|w| soup.at(w[0]).distance(soup.at(w[1])))
        .sum();
    let mut arc = 0.0;
    let mut copies = 0;
    for j in 1..m - 1 {
        let v = incision[j];
        arc += soup.at(incision[j - 1]).distance(soup.at(v));
        let fan = soup.fan(v)?;
        // The left face: the one holding the half-edge v -> next.
        let next = incision[j + 1];
        let Some(&left) = fan.iter().find(|&&f| {
            let t = soup.tris[f as usize];
            (0..3).any(|k| t[k] == v && t[(k + 1) % 3] == next)
        }) else {
            continue;
        };
        let mut side: HashSet<u32> = HashSet::new();
        let mut stack = vec![left];
        while let Some(f) = stack.pop() {
            if !side.insert(f) {
                continue;
            }
            let t = soup.tris[f as usize];
            let k = soup.corner(f, v)?;
            for (x, across) in [(t[(k + 1) % 3], (k + 2) % 3), (t[(k + 2) % 3], (k + 1) % 3)] {
                if path_edges.contains(&(v.min(x), v.max(x))) {
                    continue;
                }
                let g = soup.nb[f as usize][across];
                if g != u32::MAX && fan.contains(&g) {
                    stack.push(g);
                }
            }
        }
        let right: Vec<u32> = fan.iter().copied().filter(|f| !side.contains(f)).collect();
        if right.is_empty() {
            continue;
        }
        let c = soup.copy_vertex(v);
        copies += 1;
        for &f in &right {
            for x in soup.tris[f as usize].iter_mut() {
                if *x == v {
                    *x = c;
                }
            }
            soup.mark(f);
        }
        // The lips are no longer neighbours: a later fan of `v` (the incision may come back to
        // it) stays on the left, one of `c` on the right.
        for &f in &right {
            for g in soup.nb[f as usize] {
                if side.contains(&g) {
                    soup.unlink(f, g);
                }
            }
        }
        soup.vf[c as usize] = right[0];
        soup.vf[v as usize] = left;
        if open != 0.0 {
            // This vertex's step plane, its normal turned towards the left face.
            let step = planes
                .iter()
                .min_by(|a, b| {
                    a.0.dot(soup.at(v) - a.1)
                        .abs()
                        .total_cmp(&b.0.dot(soup.at(v) - b.1).abs())
                })
                .expect("a plane per step");
            let lt = soup.tris[left as usize].map(|x| soup.at(x));
            let centre = (lt[0] + lt[1] + lt[2]) / 3.0;
            let n = if step.0.dot(centre - soup.at(v)) >= 0.0 {
                step.0
            } else {
                -step.0
            };
            let w = 0.5 * open * (std::f64::consts::PI * arc / total).sin();
            for (x, sign) in [(v, 1.0), (c, -1.0)] {
                let p = soup.at(x) + sign * w * n;
                soup.move_to(x, p)?;
            }
        }
    }
    Ok(copies)
}
