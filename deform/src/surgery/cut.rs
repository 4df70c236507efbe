//! Planar cut (second paper, Algorithm 1).

use super::cap::ear_clip;
use super::split::{assemble, local_loops, new_vertex_data, Assembled, FaceFate, Splitter};
use super::weld::{canonical_ids, share_copies};
use super::{check_snap, FaceBvh, Frame, SkinnedMesh, Surgery, SurgeryError, VertexOrigin};
use crate::mesh::numbers::{short_number, short_point};
use cga::Plane;
use glam::DVec3;

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

impl CutPiece {
    /// The piece's surface and its caps apart, each over its own vertices (a cap gets copies of
    /// its rim, so it can have its own texture coordinates and normals at the crease, as
    /// renderers need); no cap without cap triangles.
    pub fn surface_and_caps(&self) -> (SkinnedMesh, Option<SkinnedMesh>) {
        let is_cap = |f: usize| self.face_origin[f] == u32::MAX;
        let surface = self.mesh.with_triangles(|f| !is_cap(f));
        let caps = (self.cap_triangles > 0).then(|| self.mesh.with_triangles(is_cap));
        (surface, caps)
    }
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

impl Surgery {
    /// Cut by `plane` (Algorithm 1); see the module documentation.
    ///
    /// # Errors
    /// [`SurgeryError::BadTool`] for a non-finite plane, a snap fraction outside `[0, 0.5)`,
    /// or posed positions of the wrong length; [`SurgeryError::Misses`] when the plane leaves
    /// every vertex, or every face, on one side; [`SurgeryError::BadMesh`] when a new vertex
    /// cannot be mapped back to the rest pose (a singular blended skin transform).
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
        check_snap(options.snap)?;
        let src = &self.mesh;
        let n = src.mesh.vertex_count();
        let resolved = self.resolve(frame)?;
        let (positions, bvh) = (resolved.positions, &*resolved.bvh);
        let side = self.classify(plane, positions, bvh, options.snap);
        let s = &side.s;
        if !(s.iter().any(|&x| x > 0.0) && s.iter().any(|&x| x < 0.0)) {
            return Err(SurgeryError::Misses {
                vertices: n,
                where_: plane_whereabouts(s, positions),
            });
        }
        let mut split = self.split_faces(&side, positions);
        let split_faces = split.changed.len();
        // Unchanged faces with an edge on the plane (snapped vertices included): that edge may
        // now be a boundary.
        let near_snapped = if side.snap_margin > side.tiny {
            bvh.faces_near_plane(nrm, d, side.snap_margin * 1.01)
        } else {
            side.candidates.clone()
        };
        let seeds: Vec<u32> = near_snapped
            .iter()
            .copied()
            .filter(|&f| {
                let t = src.mesh.triangles[f as usize];
                t.iter().filter(|&&v| s[v as usize] == 0.0).count() >= 2
            })
            .collect();
        let pieces = self.cut_pieces(&mut split, &side, &seeds, frame, positions, nrm, options)?;
        // Vertices on both sides but every face on one: nothing was cut (an empty piece would
        // also be an empty glTF primitive, which the format does not allow).
        if pieces.iter().any(|p| p.mesh.mesh.triangle_count() == 0) {
            return Err(SurgeryError::Misses {
                vertices: n,
                where_: "; every face lies on one side of the plane".into(),
            });
        }
        Ok(CutResult {
            pieces,
            new_vertices: split.splitter.new_edges.len(),
            split_faces,
            snapped_vertices: side.snap.len(),
            faces_examined: side.candidates.len(),
        })
    }

    /// Classify the vertices by the CGA predicate `X . pi = x . n - d`, coincident vertices as
    /// one, vertices within `snap` of a crossing edge's end (or within rounding of the plane)
    /// snapped onto it.
    fn classify(&self, plane: &Plane, positions: &[DVec3], bvh: &FaceBvh, snap: f64) -> Sides {
        let (nrm, d) = (plane.normal(), plane.distance());
        let src = &self.mesh;
        let n = src.mesh.vertex_count();
        let mut s: Vec<f64> = positions
            .iter()
            .map(|&p| plane.signed_distance(p))
            .collect();
        let weld = self.weld.as_ref();
        // Coincident vertices are classified as one (posed copies can differ in the last
        // bits); each copy's own value still places its edge's new vertex.
        let own = weld.map(|_| s.clone());
        if let Some(w) = weld {
            for v in 0..n {
                s[v] = s[w.canon[v] as usize];
            }
        }
        let tiny = 1e-12 * self.diagonal;
        let candidates = bvh.faces_near_plane(nrm, d, tiny);
        let mut snapped = Vec::new();
        for &f in &candidates {
            let t = src.mesh.triangles[f as usize];
            for k in 0..3 {
                let (i, j) = (t[k] as usize, t[(k + 1) % 3] as usize);
                for v in [i, j] {
                    if s[v] != 0.0 && s[v].abs() <= tiny {
                        snapped.push(v);
                    }
                }
                if s[i] * s[j] < 0.0 {
                    let a = s[i] / (s[i] - s[j]);
                    if a < snap {
                        snapped.push(i);
                    }
                    if 1.0 - a < snap {
                        snapped.push(j);
                    }
                }
            }
        }
        snapped.sort_unstable();
        snapped.dedup();
        let snap_margin = snapped.iter().map(|&v| s[v].abs()).fold(tiny, f64::max);
        for &v in &snapped {
            s[v] = 0.0;
        }
        if let Some(w) = weld {
            // A snapped vertex snaps its coincident copies (whose own edges may not have).
            for &v in &snapped {
                s[w.canon[v] as usize] = 0.0;
            }
            for v in 0..n {
                s[v] = s[w.canon[v] as usize];
            }
        }
        Sides {
            s,
            own,
            snap: snapped,
            snap_margin,
            tiny,
            candidates,
        }
    }

    /// Each face kept on its side or split along the plane.
    fn split_faces<'a>(&self, side: &Sides, positions: &'a [DVec3]) -> SplitFaces<'a> {
        let (s, own) = (&side.s, &side.own);
        let mut splitter = Splitter::new(positions);
        let root = |a: u32, b: u32| {
            let (sa, sb) = match own {
                Some(o) if o[a as usize] * o[b as usize] < 0.0 => (o[a as usize], o[b as usize]),
                _ => (s[a as usize], s[b as usize]),
            };
            sa / (sa - sb)
        };
        let triangles = &self.mesh.mesh.triangles;
        let f = triangles.len();
        let mut faces: [Vec<[u32; 3]>; 2] = [Vec::with_capacity(f), Vec::with_capacity(f)];
        let mut from: [Vec<u32>; 2] = [Vec::with_capacity(f), Vec::with_capacity(f)];
        let mut fate = Vec::with_capacity(f);
        let mut changed = Vec::new();
        let mut produced = Vec::new();
        for (fi, t) in triangles.iter().enumerate() {
            let g = t.map(|v| sign(s[v as usize]));
            let (pos, neg) = (g.contains(&1), g.contains(&-1));
            if !neg || !pos {
                let k = usize::from(!pos && neg);
                faces[k].push(*t);
                from[k].push(fi as u32);
                fate.push(FaceFate::Kept(k as u8));
            } else {
                fate.push(FaceFate::Changed);
                changed.push(fi as u32);
                splitter.split(*t, g, &root, |k, tri| {
                    faces[k].push(tri);
                    from[k].push(fi as u32);
                    produced.push((tri, k as u8));
                });
            }
        }
        SplitFaces {
            splitter,
            faces,
            from,
            fate,
            changed,
            produced,
        }
    }

    /// Both pieces of `split`: their new vertices' data, boundary loops (over welded
    /// vertices when coincident ones exist) and caps.
    #[allow(clippy::too_many_arguments)]
    fn cut_pieces(
        &self,
        split: &mut SplitFaces,
        side: &Sides,
        seeds: &[u32],
        frame: Frame,
        positions: &[DVec3],
        nrm: DVec3,
        options: &CutOptions,
    ) -> Result<[CutPiece; 2], SurgeryError> {
        let src = &self.mesh;
        let n = src.mesh.vertex_count();
        let (s, weld, splitter) = (&side.s, self.weld.as_ref(), &split.splitter);
        let mut new = new_vertex_data(src, &splitter.new_edges, frame, positions)?;
        let on_plane = |g: u32| (g as usize) >= n || s[g as usize] == 0.0;
        // Loops are found over welded vertices when coincident ones exist.
        let canon = weld.map(|w| canonical_ids(&w.canon, &splitter.new_edges));
        if let Some(c) = &canon {
            share_copies(&c[n..], n, &mut new.influences, &mut new.mesh.positions);
        }
        let produced = std::mem::take(&mut split.produced);
        let (topology, triangles, produced) = match (weld, &canon) {
            (Some(w), Some(c)) => (
                &w.topology,
                &w.triangles[..],
                produced
                    .iter()
                    .map(|(t, k)| (t.map(|v| c[v as usize]), *k))
                    .collect(),
            ),
            _ => (&self.topology, &src.mesh.triangles[..], produced),
        };
        let [f0, f1] = std::mem::take(&mut split.faces);
        let [o0, o1] = std::mem::take(&mut split.from);
        let (fate, changed) = (&split.fate, &split.changed);
        Ok([(f0, o0, 0u8), (f1, o1, 1u8)].map(|(f, o, side)| {
            let a = assemble(src, f, splitter, &new);
            let loops = local_loops(
                topology,
                triangles,
                |f| fate[f as usize],
                changed,
                seeds,
                &produced,
                side,
            );
            piece(
                a,
                o,
                loops,
                canon.as_deref(),
                &on_plane,
                &|g| splitter.at(g),
                nrm,
                options.cap,
            )
        }))
    }
}

/// The vertices' sides of the plane (`s`: signed distances, 0 on or snapped onto it; `own`:
/// each coincident copy's own distance where vertices were welded), the snapped vertices,
/// the largest distance snapped, rounding's width and the faces near the plane.
struct Sides {
    s: Vec<f64>,
    own: Option<Vec<f64>>,
    snap: Vec<usize>,
    snap_margin: f64,
    tiny: f64,
    candidates: Vec<u32>,
}

/// The faces of each side (`faces`, each from input face `from`), each input face's fate,
/// the changed faces and the faces their split produced.
struct SplitFaces<'a> {
    splitter: Splitter<'a>,
    faces: [Vec<[u32; 3]>; 2],
    from: [Vec<u32>; 2],
    fate: Vec<FaceFate>,
    changed: Vec<u32>,
    produced: Vec<([u32; 3], u8)>,
}

/// One side: caps, boundary loops (`loops` over global vertices, or over their canonical ids
/// `canon` when coincident vertices were welded).
#[allow(clippy::too_many_arguments)] // the piece, its loops, and how to read their vertices
fn piece(
    a: Assembled,
    mut face_origin: Vec<u32>,
    loops: Vec<Vec<u32>>,
    canon: Option<&[u32]>,
    on_plane: &impl Fn(u32) -> bool,
    at: &impl Fn(u32) -> DVec3,
    normal: DVec3,
    cap: bool,
) -> CutPiece {
    let Assembled {
        mut mesh,
        origin,
        local,
    } = a;
    let mut cap_triangles = 0;
    let mut boundary_loops = loops.len();
    // The piece's local index of a loop vertex: through any of its coincident copies that the
    // piece uses when welded.
    let local_of: Vec<u32> = match canon {
        None => local,
        Some(c) => {
            let mut l = vec![u32::MAX; local.len()];
            for (g, &x) in local.iter().enumerate() {
                let slot = &mut l[c[g] as usize];
                if x != u32::MAX && *slot == u32::MAX {
                    *slot = x;
                }
            }
            l
        }
    };
    if cap {
        for lp in loops {
            if lp.len() < 3 || !lp.iter().all(|&v| on_plane(v)) {
                continue;
            }
            // The cap runs against the loop (whose half-edges the piece's faces use).
            let pts: Vec<DVec3> = lp.iter().rev().map(|&g| at(g)).collect();
            let rev: Vec<u32> = lp.iter().rev().map(|&g| local_of[g as usize]).collect();
            if rev.contains(&u32::MAX) {
                continue;
            }
            if let Some(tris) = ear_clip(&pts, normal) {
                cap_triangles += tris.len();
                mesh.mesh
                    .triangles
                    .extend(tris.iter().map(|t| t.map(|k| rev[k])));
                face_origin.resize(mesh.mesh.triangle_count(), u32::MAX);
                boundary_loops -= 1;
            }
        }
    }
    CutPiece {
        mesh,
        origin,
        face_origin,
        boundary_loops,
        cap_triangles,
    }
}

/// "; every vertex is on one side of the plane, the nearest at distance D, (x, y, z)" from the
/// signed distances `s` of the vertices at `positions`.
fn plane_whereabouts(s: &[f64], positions: &[DVec3]) -> String {
    let nearest = (0..s.len())
        .filter(|&v| s[v] != 0.0)
        .min_by(|&a, &b| s[a].abs().total_cmp(&s[b].abs()));
    match nearest {
        Some(v) => {
            format!(
                "; every vertex is on one side of the plane (or on it), the nearest off it {} \
                 away at {}",
                short_number(s[v].abs()),
                short_point(positions[v])
            )
        }
        None => "; every vertex is on the plane".into(),
    }
}
