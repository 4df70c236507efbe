//! Planar cut (second paper, Algorithm 1).

use super::cap::ear_clip;
use super::weights::{push_copy, push_interpolated};
use super::{unskin, Frame, SkinnedMesh, Surgery, SurgeryError};
use crate::skinning::Influences;
use crate::Mesh;
use cga::Plane;
use glam::DVec3;
use std::collections::HashMap;

/// Options of [`Surgery::cut`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CutOptions {
    /// A vertex whose crossing edge would be split closer to it than this fraction of the
    /// edge is snapped onto the plane (treated as on it; its position is not changed). In
    /// `[0, 0.5)`; default 0.02. Every triangle made by splitting a face then has at least
    /// `snap^2` of that face's area (the quality bound).
    pub snap: f64,
    /// Close each piece's boundary loops that lie on the plane with a triangulated cap.
    pub cap: bool,
}

impl Default for CutOptions {
    fn default() -> Self {
        CutOptions {
            snap: 0.02,
            cap: false,
        }
    }
}

/// Where a vertex of a piece comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VertexOrigin {
    /// Vertex `0` of the input mesh.
    Original(u32),
    /// A new vertex on the input edge `a b` at `a + t (b - a)` (in the frame of the cut).
    Edge {
        /// First end.
        a: u32,
        /// Second end.
        b: u32,
        /// Parameter from `a`.
        t: f64,
    },
}

/// One side of a cut.
#[derive(Clone, Debug, PartialEq)]
pub struct CutPiece {
    /// The piece, with its influences (input vertices in their input order, then new ones).
    pub mesh: SkinnedMesh,
    /// Where each vertex comes from.
    pub origin: Vec<VertexOrigin>,
    /// The input face each triangle comes from (`u32::MAX` for cap triangles).
    pub face_origin: Vec<u32>,
    /// Boundary loops after the cut (and after capping).
    pub boundary_loops: usize,
    /// Triangles added by capping.
    pub cap_triangles: usize,
}

/// The result of [`Surgery::cut`]: the pieces (the side the plane's normal points to first)
/// and what changed.
#[derive(Clone, Debug, PartialEq)]
pub struct CutResult {
    /// Positive side, negative side.
    pub pieces: [CutPiece; 2],
    /// New vertices (one per crossing edge; each appears in both pieces).
    pub new_vertices: usize,
    /// Input faces that were split (removed and re-triangulated).
    pub split_faces: usize,
    /// Vertices snapped onto the plane.
    pub snapped_vertices: usize,
    /// Faces the face index returned near the plane (the only faces examined for crossings).
    pub faces_examined: usize,
}

/// `-1`, `0` or `1`.
fn sign(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

/// The smallest angle (as its cosine's complement) of a triangle, for choosing diagonals.
fn min_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let ang = |p: DVec3, q: DVec3, r: DVec3| (q - p).angle_between(r - p);
    ang(a, b, c).min(ang(b, c, a)).min(ang(c, a, b))
}

impl Surgery {
    /// Cut by `plane` (Algorithm 1); see the module documentation.
    ///
    /// # Errors
    /// [`SurgeryError::BadTool`] for a non-finite plane, a snap fraction outside `[0, 0.5)`,
    /// or posed positions of the wrong length; [`SurgeryError::Misses`] when the plane leaves
    /// every vertex on one side; [`SurgeryError::BadMesh`] when a new vertex cannot be mapped
    /// back to the rest pose (a singular blended skin transform).
    pub fn cut(
        &self,
        plane: &Plane,
        frame: Frame,
        options: &CutOptions,
    ) -> Result<CutResult, SurgeryError> {
        let (nrm, d) = (plane.normal(), plane.distance());
        if !(nrm.is_finite() && d.is_finite() && (nrm.length() - 1.0).abs() < 1e-9) {
            return Err(SurgeryError::BadTool(format!(
                "the plane is not finite or its normal is not unit: {nrm} . x = {d}"
            )));
        }
        if !(0.0..0.5).contains(&options.snap) {
            return Err(SurgeryError::BadTool(format!(
                "snap fraction {} outside [0, 0.5)",
                options.snap
            )));
        }
        let src = &self.mesh;
        let n = src.mesh.vertex_count();
        let mut refit;
        let (positions, bvh) = match frame {
            Frame::Rest => (&src.mesh.positions[..], &self.bvh),
            Frame::Posed { positions, .. } => {
                if positions.len() != n || positions.iter().any(|p| !p.is_finite()) {
                    return Err(SurgeryError::BadTool(format!(
                        "{} posed positions for {n} vertices (or not finite)",
                        positions.len()
                    )));
                }
                refit = self.bvh.clone();
                refit.refit(&Mesh::new(positions.to_vec(), src.mesh.triangles.clone()));
                (positions, &refit)
            }
        };
        // Classify by the CGA predicate X . pi = x . n - d.
        let mut s: Vec<f64> = positions
            .iter()
            .map(|&p| plane.signed_distance(p))
            .collect();
        let tiny = 1e-12 * self.diagonal;
        let candidates = bvh.faces_near_plane(nrm, d, tiny);
        let mut snap = Vec::new();
        for &f in &candidates {
            let t = src.mesh.triangles[f as usize];
            for k in 0..3 {
                let (i, j) = (t[k] as usize, t[(k + 1) % 3] as usize);
                for v in [i, j] {
                    if s[v] != 0.0 && s[v].abs() <= tiny {
                        snap.push(v);
                    }
                }
                if s[i] * s[j] < 0.0 {
                    let a = s[i] / (s[i] - s[j]);
                    if a < options.snap {
                        snap.push(i);
                    }
                    if 1.0 - a < options.snap {
                        snap.push(j);
                    }
                }
            }
        }
        snap.sort_unstable();
        snap.dedup();
        for &v in &snap {
            s[v] = 0.0;
        }
        if !(s.iter().any(|&x| x > 0.0) && s.iter().any(|&x| x < 0.0)) {
            return Err(SurgeryError::Misses { vertices: n });
        }
        // Split: faces of each side in a global index space (input vertices, then new ones).
        let mut new_edges: Vec<(u32, u32, f64)> = Vec::new();
        let mut edge_index: HashMap<(u32, u32), u32> = HashMap::new();
        let mut new_vertex = |i: u32, j: u32, e: &mut Vec<(u32, u32, f64)>| -> u32 {
            let (a, b) = (i.min(j), i.max(j));
            *edge_index.entry((a, b)).or_insert_with(|| {
                let (sa, sb) = (s[a as usize], s[b as usize]);
                e.push((a, b, sa / (sa - sb)));
                (n + e.len() - 1) as u32
            })
        };
        let mut faces: [Vec<[u32; 3]>; 2] = [Vec::new(), Vec::new()];
        let mut from: [Vec<u32>; 2] = [Vec::new(), Vec::new()];
        let side = |g: i8| usize::from(g < 0);
        let mut split_faces = 0;
        // Positions of new vertices are needed to choose diagonals: computed as they come.
        let lerp = |a: u32, b: u32, t: f64| positions[a as usize].lerp(positions[b as usize], t);
        for (fi, t) in src.mesh.triangles.iter().enumerate() {
            let mut push = |k: usize, tri: [u32; 3]| {
                faces[k].push(tri);
                from[k].push(fi as u32);
            };
            let g = t.map(|v| sign(s[v as usize]));
            let (pos, neg) = (g.contains(&1), g.contains(&-1));
            if !neg {
                push(0, *t);
                continue;
            }
            if !pos {
                push(1, *t);
                continue;
            }
            split_faces += 1;
            if let Some(z) = g.iter().position(|&x| x == 0) {
                let (zv, u, v) = (t[z], t[(z + 1) % 3], t[(z + 2) % 3]);
                let m = new_vertex(u, v, &mut new_edges);
                push(side(g[(z + 1) % 3]), [zv, u, m]);
                push(side(g[(z + 2) % 3]), [zv, m, v]);
                continue;
            }
            // The lone vertex: the one whose sign the other two do not share.
            let lone = (0..3)
                .find(|&k| g[k] != g[(k + 1) % 3] && g[k] != g[(k + 2) % 3])
                .expect("mixed signs");
            let (a, b, c) = (t[lone], t[(lone + 1) % 3], t[(lone + 2) % 3]);
            let p = new_vertex(a, b, &mut new_edges);
            let q = new_vertex(a, c, &mut new_edges);
            push(side(g[lone]), [a, p, q]);
            let other = side(-g[lone]);
            let at = |v: u32, e: &[(u32, u32, f64)]| -> DVec3 {
                if (v as usize) < n {
                    positions[v as usize]
                } else {
                    let (x, y, t) = e[v as usize - n];
                    lerp(x, y, t)
                }
            };
            let (pp, pb, pc, pq) = (
                at(p, &new_edges),
                at(b, &new_edges),
                at(c, &new_edges),
                at(q, &new_edges),
            );
            let one = min_angle(pp, pb, pc).min(min_angle(pp, pc, pq));
            let two = min_angle(pp, pb, pq).min(min_angle(pq, pb, pc));
            if one >= two {
                push(other, [p, b, c]);
                push(other, [p, c, q]);
            } else {
                push(other, [p, b, q]);
                push(other, [q, b, c]);
            }
        }
        // Influences and rest positions of the new vertices.
        let mut new_inf = Influences {
            width: src.influences.width,
            ..Influences::default()
        };
        let mut new_rest = Vec::with_capacity(new_edges.len());
        for (k, &(a, b, t)) in new_edges.iter().enumerate() {
            push_interpolated(&src.influences, &[(a, 1.0 - t), (b, t)], &mut new_inf);
            let rest = match frame {
                Frame::Rest => lerp(a, b, t),
                Frame::Posed { skin, .. } => {
                    let r = k * new_inf.width..(k + 1) * new_inf.width;
                    unskin(
                        lerp(a, b, t),
                        &new_inf.joints[r.clone()],
                        &new_inf.weights[r],
                        skin,
                    )
                    .ok_or_else(|| {
                        SurgeryError::BadMesh(format!(
                            "new vertex on edge {a}-{b}: its blended skin transform is singular"
                        ))
                    })?
                }
            };
            new_rest.push(rest);
        }
        let on_plane = |v: u32| (v as usize) >= n || s[v as usize] == 0.0;
        let [f0, f1] = faces;
        let [o0, o1] = from;
        let pieces = [(f0, o0), (f1, o1)].map(|(f, o)| {
            self.piece(
                f,
                o,
                &new_edges,
                &new_inf,
                &new_rest,
                positions,
                nrm,
                on_plane,
                options.cap,
            )
        });
        Ok(CutResult {
            pieces,
            new_vertices: new_edges.len(),
            split_faces,
            snapped_vertices: snap.len(),
            faces_examined: candidates.len(),
        })
    }

    /// One side: reindex (input vertices in input order, then new ones), influences, caps.
    #[allow(clippy::too_many_arguments)]
    fn piece(
        &self,
        mut faces: Vec<[u32; 3]>,
        mut face_origin: Vec<u32>,
        new_edges: &[(u32, u32, f64)],
        new_inf: &Influences,
        new_rest: &[DVec3],
        frame_positions: &[DVec3],
        normal: DVec3,
        on_plane: impl Fn(u32) -> bool,
        cap: bool,
    ) -> CutPiece {
        let src = &self.mesh;
        let n = src.mesh.vertex_count();
        let total = n + new_edges.len();
        let mut local = vec![u32::MAX; total];
        for t in &faces {
            for &v in t {
                local[v as usize] = 0;
            }
        }
        let mut positions = Vec::new();
        let mut origin = Vec::new();
        let mut influences = Influences {
            width: src.influences.width,
            ..Influences::default()
        };
        let mut frame = Vec::new();
        for (g, slot) in local.iter_mut().enumerate() {
            if *slot == u32::MAX {
                continue;
            }
            *slot = positions.len() as u32;
            if g < n {
                positions.push(src.mesh.positions[g]);
                origin.push(VertexOrigin::Original(g as u32));
                push_copy(&src.influences, g as u32, &mut influences);
                frame.push(frame_positions[g]);
            } else {
                let (a, b, t) = new_edges[g - n];
                positions.push(new_rest[g - n]);
                origin.push(VertexOrigin::Edge { a, b, t });
                let w = new_inf.width;
                let r = (g - n) * w..(g - n + 1) * w;
                influences
                    .joints
                    .extend_from_slice(&new_inf.joints[r.clone()]);
                influences.weights.extend_from_slice(&new_inf.weights[r]);
                frame.push(frame_positions[a as usize].lerp(frame_positions[b as usize], t));
            }
        }
        let plane_vertex: Vec<bool> = (0..total)
            .filter(|&g| local[g] != u32::MAX)
            .map(|g| on_plane(g as u32))
            .collect();
        for t in &mut faces {
            *t = t.map(|v| local[v as usize]);
        }
        let mut cap_triangles = 0;
        if cap {
            let loops = crate::adjacency::boundary_loops(&faces, positions.len());
            for lp in loops {
                if lp.len() < 3 || !lp.iter().all(|&v| plane_vertex[v as usize]) {
                    continue;
                }
                // The cap runs against the loop (whose half-edges the piece's faces use).
                let rev: Vec<u32> = lp.iter().rev().copied().collect();
                let pts: Vec<DVec3> = rev.iter().map(|&v| frame[v as usize]).collect();
                if let Some(tris) = ear_clip(&pts, normal) {
                    cap_triangles += tris.len();
                    faces.extend(tris.iter().map(|t| t.map(|k| rev[k])));
                    face_origin.resize(faces.len(), u32::MAX);
                }
            }
        }
        let boundary_loops = crate::adjacency::boundary_loops(&faces, positions.len()).len();
        CutPiece {
            mesh: SkinnedMesh {
                mesh: Mesh::new(positions, faces),
                influences,
            },
            origin,
            face_origin,
            boundary_loops,
            cap_triangles,
        }
    }
}
