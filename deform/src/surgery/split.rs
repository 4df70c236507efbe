//! The step cut, tear and drill share: splitting triangles along a curve given by the signs of
//! their corners (which side of a plane, inside or outside a drill), with one new vertex per
//! crossing edge, shared by the faces on both sides of the edge; and assembling the result.

use super::weights::{push_copy, push_interpolated};
use super::{unskin, Frame, SkinnedMesh, SurgeryError};
use crate::mesh::Mesh;
use crate::skinning::Influences;
use glam::DVec3;
use std::collections::HashMap;

/// Where a vertex of a piece comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VertexOrigin {
    /// Input vertex `0`.
    Original(u32),
    /// A midpoint added by refinement (a drill thinner than the triangles).
    Refined,
    /// A point of a tear's incision (on the plane of its step), or where the scalpel enters.
    Incision,
    /// The second copy of incision vertex `0` of the result (the other lip of the tear).
    Copy(u32),
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

impl VertexOrigin {
    /// Whether the vertex is an input vertex (not made by a tool).
    pub fn is_input(&self) -> bool {
        matches!(self, VertexOrigin::Original(_))
    }
}

/// New vertices on input edges, created as the faces are split.
pub(crate) struct Splitter<'a> {
    /// Input vertex count: new vertices are numbered from here.
    pub n: usize,
    /// The input vertices in the frame of the tool.
    pub positions: &'a [DVec3],
    /// New vertices: `(a, b, t)` with `a < b`, at `a + t (b - a)`.
    pub new_edges: Vec<(u32, u32, f64)>,
    index: HashMap<(u32, u32), u32>,
}

/// The smallest angle of a triangle.
fn min_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let ang = |p: DVec3, q: DVec3, r: DVec3| (q - p).angle_between(r - p);
    ang(a, b, c).min(ang(b, c, a)).min(ang(c, a, b))
}

impl<'a> Splitter<'a> {
    pub fn new(positions: &'a [DVec3]) -> Self {
        Splitter {
            n: positions.len(),
            positions,
            new_edges: Vec::new(),
            index: HashMap::new(),
        }
    }

    /// The vertex on edge `i j` where `root(a, b)` (`a < b`) puts it, made once per edge.
    pub fn edge_vertex(&mut self, i: u32, j: u32, root: &impl Fn(u32, u32) -> f64) -> u32 {
        let (a, b) = (i.min(j), i.max(j));
        let (n, e) = (self.n, &mut self.new_edges);
        *self.index.entry((a, b)).or_insert_with(|| {
            e.push((a, b, root(a, b)));
            (n + e.len() - 1) as u32
        })
    }

    /// The position of an input or new vertex in the tool's frame.
    pub fn at(&self, v: u32) -> DVec3 {
        match (v as usize).checked_sub(self.n) {
            None => self.positions[v as usize],
            Some(k) => {
                let (a, b, t) = self.new_edges[k];
                self.positions[a as usize].lerp(self.positions[b as usize], t)
            }
        }
    }

    /// Split triangle `t` whose corners have signs `g` (some `1`, some `-1`, maybe a `0`),
    /// calling `push(side, triangle)` with side 0 for the positive part and 1 for the
    /// negative part. Orientation is kept; of the quad's two diagonals the one with the larger
    /// smallest angle is taken.
    pub fn split(
        &mut self,
        t: [u32; 3],
        g: [i8; 3],
        root: &impl Fn(u32, u32) -> f64,
        mut push: impl FnMut(usize, [u32; 3]),
    ) {
        let side = |s: i8| usize::from(s < 0);
        if let Some(z) = g.iter().position(|&x| x == 0) {
            let (zv, u, v) = (t[z], t[(z + 1) % 3], t[(z + 2) % 3]);
            let m = self.edge_vertex(u, v, root);
            push(side(g[(z + 1) % 3]), [zv, u, m]);
            push(side(g[(z + 2) % 3]), [zv, m, v]);
            return;
        }
        // The lone vertex: the one whose sign the other two do not share.
        let lone = (0..3)
            .find(|&k| g[k] != g[(k + 1) % 3] && g[k] != g[(k + 2) % 3])
            .expect("mixed signs");
        let (a, b, c) = (t[lone], t[(lone + 1) % 3], t[(lone + 2) % 3]);
        let p = self.edge_vertex(a, b, root);
        let q = self.edge_vertex(a, c, root);
        push(side(g[lone]), [a, p, q]);
        let other = side(-g[lone]);
        let (pp, pb, pc, pq) = (self.at(p), self.at(b), self.at(c), self.at(q));
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
}

/// New vertices `(a, b, t)` as a triangle-free [`SkinnedMesh`]: influences and sources
/// interpolated (4 largest), rest positions on the rest pose the interpolated rest point, on a
/// posed frame the posed point mapped back through the inverse of its own blended skin
/// transform.
pub(crate) fn new_vertex_data(
    src: &SkinnedMesh,
    new_edges: &[(u32, u32, f64)],
    frame: Frame,
    frame_positions: &[DVec3],
) -> Result<SkinnedMesh, SurgeryError> {
    let empty = |width| Influences {
        width,
        ..Influences::default()
    };
    let mut inf = empty(src.influences.width);
    let mut sources = empty(src.sources.width);
    let mut rest = Vec::with_capacity(new_edges.len());
    for (k, &(a, b, t)) in new_edges.iter().enumerate() {
        let parts = [(a, 1.0 - t), (b, t)];
        push_interpolated(&src.influences, &parts, &mut inf);
        push_interpolated(&src.sources, &parts, &mut sources);
        let (pa, pb) = (a as usize, b as usize);
        rest.push(match frame.posing() {
            None => src.mesh.positions[pa].lerp(src.mesh.positions[pb], t),
            Some(skin) => {
                let r = k * inf.width..(k + 1) * inf.width;
                let p = frame_positions[pa].lerp(frame_positions[pb], t);
                unskin(p, &inf.joints[r.clone()], &inf.weights[r], skin).ok_or_else(|| {
                    SurgeryError::BadMesh(format!(
                        "new vertex on edge {a}-{b}: its blended skin transform is singular"
                    ))
                })?
            }
        });
    }
    Ok(SkinnedMesh {
        mesh: Mesh::new(rest, Vec::new()),
        influences: inf,
        sources,
    })
}

/// One result mesh from triangles over input vertices `0..n` and new vertices `n..`:
/// reindexed (input vertices in input order, then new ones), with influences and origins.
pub(crate) struct Assembled {
    pub mesh: SkinnedMesh,
    pub origin: Vec<VertexOrigin>,
    /// Result index of each global vertex (`u32::MAX`: not in the result).
    pub local: Vec<u32>,
}

pub(crate) fn assemble(
    src: &SkinnedMesh,
    mut faces: Vec<[u32; 3]>,
    splitter: &Splitter,
    new: &SkinnedMesh,
) -> Assembled {
    let n = src.mesh.vertex_count();
    let total = n + splitter.new_edges.len();
    let mut local = vec![u32::MAX; total];
    for t in &faces {
        for &v in t {
            local[v as usize] = 0;
        }
    }
    let kept = local.iter().filter(|&&x| x != u32::MAX).count();
    let w = src.influences.width;
    let mut positions = Vec::with_capacity(kept);
    let mut origin = Vec::with_capacity(kept);
    let mut influences = Influences {
        width: w,
        joints: Vec::with_capacity(kept * w),
        weights: Vec::with_capacity(kept * w),
    };
    let mut sources = Influences {
        width: src.sources.width,
        ..Influences::default()
    };
    for (g, slot) in local.iter_mut().enumerate() {
        if *slot == u32::MAX {
            continue;
        }
        *slot = positions.len() as u32;
        if g < n {
            positions.push(src.mesh.positions[g]);
            origin.push(VertexOrigin::Original(g as u32));
            push_copy(&src.influences, g as u32, &mut influences);
            push_copy(&src.sources, g as u32, &mut sources);
        } else {
            let (a, b, t) = splitter.new_edges[g - n];
            positions.push(new.mesh.positions[g - n]);
            origin.push(VertexOrigin::Edge { a, b, t });
            push_copy(&new.influences, (g - n) as u32, &mut influences);
            push_copy(&new.sources, (g - n) as u32, &mut sources);
        }
    }
    for t in &mut faces {
        *t = t.map(|v| local[v as usize]);
    }
    Assembled {
        mesh: SkinnedMesh {
            mesh: Mesh::new(positions, faces),
            influences,
            sources,
        },
        origin,
        local,
    }
}

/// Bind-time topology: the face across each edge and the boundary, so that a tool can count
/// the boundary loops of its result from the faces it touched alone.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Topology {
    /// `neighbors[f][k]`: the face across the edge opposite corner `k` (`u32::MAX`: none).
    pub neighbors: Vec<[u32; 3]>,
    /// Boundary half-edges `(a, b, face)` as the faces orient them.
    pub boundary: Vec<(u32, u32, u32)>,
    /// Boundary loops of the input.
    pub loops: usize,
    /// One face around each vertex (`u32::MAX` for an unreferenced vertex).
    pub vertex_face: Vec<u32>,
}

impl Topology {
    pub fn new(triangles: &[[u32; 3]], n: usize) -> Topology {
        let edges = crate::mesh::adjacency::edges(triangles, n);
        let mut faces_of = vec![[u32::MAX; 2]; edges.edges.len()];
        for (f, fe) in edges.face_edges.iter().enumerate() {
            for &e in fe {
                let slot = &mut faces_of[e as usize];
                if slot[0] == u32::MAX {
                    slot[0] = f as u32;
                } else {
                    slot[1] = f as u32;
                }
            }
        }
        let mut neighbors = Vec::with_capacity(triangles.len());
        let mut boundary = Vec::new();
        for (f, t) in triangles.iter().enumerate() {
            let fe = edges.face_edges[f];
            let mut nb = [u32::MAX; 3];
            for k in 0..3 {
                let [x, y] = faces_of[fe[k] as usize];
                nb[k] = if x == f as u32 { y } else { x };
                if nb[k] == u32::MAX {
                    boundary.push((t[(k + 1) % 3], t[(k + 2) % 3], f as u32));
                }
            }
            neighbors.push(nb);
        }
        let loops = crate::mesh::adjacency::boundary_loops(triangles, n).len();
        let mut vertex_face = vec![u32::MAX; n];
        for (f, t) in triangles.iter().enumerate() {
            for &v in t {
                vertex_face[v as usize] = f as u32;
            }
        }
        Topology {
            neighbors,
            boundary,
            loops,
            vertex_face,
        }
    }
}

/// What a tool did to an input face.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FaceFate {
    /// Kept unchanged on this side.
    Kept(u8),
    /// Split or removed.
    Changed,
}

/// The boundary loops (as vertex sequences over input and new vertices) of side `side` of a
/// tool's result, found from the changed faces and their neighbours only: `fate` of every
/// input face, the `changed` input faces, unchanged `seeds` whose edges may have become
/// boundary (faces with an edge on a cutting plane), the `produced` triangles with their side.
pub(crate) fn local_loops(
    topo: &Topology,
    triangles: &[[u32; 3]],
    fate: impl Fn(u32) -> FaceFate,
    changed: &[u32],
    seeds: &[u32],
    produced: &[([u32; 3], u8)],
    side: u8,
) -> Vec<Vec<u32>> {
    use std::collections::HashSet;
    // The unchanged faces of this side next to a changed face, and the seeds.
    let mut ring: Vec<u32> = changed
        .iter()
        .flat_map(|&f| topo.neighbors[f as usize])
        .chain(seeds.iter().copied())
        .filter(|&g| g != u32::MAX && fate(g) == FaceFate::Kept(side))
        .collect();
    ring.sort_unstable();
    ring.dedup();
    let mine = produced.iter().filter(|p| p.1 == side).map(|p| p.0);
    let mut half: HashSet<(u32, u32)> = HashSet::new();
    for t in mine
        .clone()
        .chain(ring.iter().map(|&f| triangles[f as usize]))
    {
        for k in 0..3 {
            half.insert((t[k], t[(k + 1) % 3]));
        }
    }
    let mut out: Vec<(u32, u32)> = Vec::new();
    for t in mine {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if !half.contains(&(b, a)) {
                out.push((a, b));
            }
        }
    }
    for &f in &ring {
        let t = triangles[f as usize];
        for k in 0..3 {
            let (a, b) = (t[(k + 1) % 3], t[(k + 2) % 3]);
            let nb = topo.neighbors[f as usize][k];
            let boundary = if nb == u32::MAX {
                true
            } else {
                match fate(nb) {
                    FaceFate::Kept(s) => s != side,
                    FaceFate::Changed => !half.contains(&(b, a)),
                }
            };
            if boundary {
                out.push((a, b));
            }
        }
    }
    let ring_set: HashSet<u32> = ring.iter().copied().collect();
    out.extend(
        topo.boundary
            .iter()
            .filter(|&&(_, _, f)| fate(f) == FaceFate::Kept(side) && !ring_set.contains(&f))
            .map(|&(a, b, _)| (a, b)),
    );
    chain_loops(&out)
}

/// Chain half-edges `a -> b` into closed loops (at a vertex with several outgoing edges, the
/// first unused one is taken).
pub(crate) fn chain_loops(half: &[(u32, u32)]) -> Vec<Vec<u32>> {
    let mut next: HashMap<u32, Vec<(u32, bool)>> = HashMap::new();
    for &(a, b) in half {
        next.entry(a).or_default().push((b, false));
    }
    let mut loops = Vec::new();
    for &(start, _) in half {
        let mut lp = Vec::new();
        let mut v = start;
        while let Some(slot) = next.get_mut(&v).and_then(|l| l.iter_mut().find(|e| !e.1)) {
            slot.1 = true;
            lp.push(v);
            v = slot.0;
            if v == start {
                break;
            }
        }
        if !lp.is_empty() {
            loops.push(lp);
        }
    }
    loops
}
