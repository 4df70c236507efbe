//! A triangle mesh under local edits: each face knows the face across each of its edges, each
//! vertex one face around it, so edges and faces can be split in constant time and a vertex's
//! fan walked without a global adjacency rebuild. Used by the tear.

use super::weights::{push_copy, push_interpolated};
use super::{unskin, Posing, SurgeryError, VertexOrigin};
use crate::skinning::Influences;
use glam::DVec3;

/// A mesh being edited, with per-vertex data in both frames.
pub(crate) struct Soup<'a> {
    pub tris: Vec<[u32; 3]>,
    /// `nb[f][k]`: the face across the edge opposite corner `k` (`u32::MAX`: boundary).
    pub nb: Vec<[u32; 3]>,
    /// One face around each vertex.
    pub vf: Vec<u32>,
    /// Input face count: faces from here on are new.
    pub input_faces: usize,
    /// The input face each new face comes from.
    root_new: Vec<u32>,
    /// Whether each input face was edited.
    pub touched: Vec<bool>,
    /// Positions in the tool's frame (empty on the rest pose: they are `rest`).
    frame: Vec<DVec3>,
    pub rest: Vec<DVec3>,
    pub influences: Influences,
    /// Sources of every vertex ([`super::SkinnedMesh::sources`]).
    pub sources: Influences,
    pub origin: Vec<VertexOrigin>,
    /// How a posed frame was posed.
    pub skin: Option<Posing<'a>>,
}

impl<'a> Soup<'a> {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        tris: &[[u32; 3]],
        nb: &[[u32; 3]],
        vf: &[u32],
        rest: &[DVec3],
        frame: &[DVec3],
        src_influences: &Influences,
        src_sources: &Influences,
        skin: Option<Posing<'a>>,
    ) -> Soup<'a> {
        let influences = src_influences;
        // Room for the edits of a typical tear without regrowing.
        let extra = 256;
        let grown = |n: usize| n + extra;
        let mut influences = Influences {
            width: influences.width,
            joints: Vec::with_capacity(grown(rest.len()) * influences.width),
            weights: Vec::with_capacity(grown(rest.len()) * influences.width),
        };
        influences.joints.extend_from_slice(&src_influences.joints);
        influences
            .weights
            .extend_from_slice(&src_influences.weights);
        let with_room = |v: &[[u32; 3]]| {
            let mut out = Vec::with_capacity(grown(v.len()));
            out.extend_from_slice(v);
            out
        };
        let mut rest_v = Vec::with_capacity(grown(rest.len()));
        rest_v.extend_from_slice(rest);
        let mut origin = Vec::with_capacity(grown(rest.len()));
        origin.extend((0..rest.len() as u32).map(VertexOrigin::Original));
        Soup {
            tris: with_room(tris),
            nb: with_room(nb),
            vf: vf.to_vec(),
            input_faces: tris.len(),
            root_new: Vec::new(),
            touched: vec![false; tris.len()],
            frame: if skin.is_some() {
                frame.to_vec()
            } else {
                Vec::new()
            },
            rest: rest_v,
            influences,
            sources: src_sources.clone(),
            origin,
            skin,
        }
    }

    /// A new vertex at frame position `p`, its influences interpolated from `parts`.
    pub fn add_vertex(&mut self, p: DVec3, parts: &[(u32, f64)]) -> Result<u32, SurgeryError> {
        let mut row = Influences {
            width: self.influences.width,
            ..Influences::default()
        };
        push_interpolated(&self.influences, parts, &mut row);
        let rest = match self.skin {
            None => parts.iter().map(|&(v, w)| w * self.rest[v as usize]).sum(),
            Some(skin) => unskin(p, &row.joints, &row.weights, skin).ok_or_else(|| {
                SurgeryError::BadMesh("a new vertex's blended skin transform is singular".into())
            })?,
        };
        self.influences.joints.extend_from_slice(&row.joints);
        self.influences.weights.extend_from_slice(&row.weights);
        let mut from = Influences {
            width: self.sources.width,
            ..Influences::default()
        };
        push_interpolated(&self.sources, parts, &mut from);
        self.sources.joints.extend_from_slice(&from.joints);
        self.sources.weights.extend_from_slice(&from.weights);
        if self.skin.is_some() {
            self.frame.push(p);
        }
        self.rest.push(rest);
        self.origin.push(VertexOrigin::Incision);
        self.vf.push(u32::MAX);
        Ok((self.rest.len() - 1) as u32)
    }

    /// Re-derive vertex `v`'s sources from `parts`: a seam copy of a new vertex lies on its own
    /// side's edge, and its attributes (UVs) come from that side's vertices.
    pub fn set_sources(&mut self, v: u32, parts: &[(u32, f64)]) {
        let mut from = Influences {
            width: self.sources.width,
            ..Influences::default()
        };
        push_interpolated(&self.sources, parts, &mut from);
        let w = self.sources.width;
        let r = v as usize * w..(v as usize + 1) * w;
        self.sources.joints[r.clone()].copy_from_slice(&from.joints);
        self.sources.weights[r].copy_from_slice(&from.weights);
    }

    /// Vertex `v`'s position in the tool's frame.
    #[inline]
    pub fn at(&self, v: u32) -> DVec3 {
        if self.skin.is_some() {
            self.frame[v as usize]
        } else {
            self.rest[v as usize]
        }
    }

    /// Move vertex `v` to `p` in the tool's frame (its rest position follows).
    pub fn move_to(&mut self, v: u32, p: DVec3) -> Result<(), SurgeryError> {
        match self.skin {
            None => self.rest[v as usize] = p,
            Some(skin) => {
                self.frame[v as usize] = p;
                let (j, w) = self.influences.clone_row(v);
                self.rest[v as usize] = unskin(p, &j, &w, skin).ok_or_else(|| {
                    SurgeryError::BadMesh("a moved vertex's skin transform is singular".into())
                })?;
            }
        }
        Ok(())
    }

    /// A second copy of vertex `v` (same influences and positions).
    pub fn copy_vertex(&mut self, v: u32) -> u32 {
        let src = self.influences.clone_row(v);
        self.influences.joints.extend_from_slice(&src.0);
        self.influences.weights.extend_from_slice(&src.1);
        let from = self.sources.clone_row(v);
        self.sources.joints.extend_from_slice(&from.0);
        self.sources.weights.extend_from_slice(&from.1);
        if self.skin.is_some() {
            self.frame.push(self.frame[v as usize]);
        }
        self.rest.push(self.rest[v as usize]);
        self.origin.push(VertexOrigin::Copy(v));
        self.vf.push(u32::MAX);
        (self.rest.len() - 1) as u32
    }

    /// The input face face `f` comes from.
    pub fn root(&self, f: u32) -> u32 {
        match (f as usize).checked_sub(self.input_faces) {
            None => f,
            Some(k) => self.root_new[k],
        }
    }

    fn new_face(&mut self, t: [u32; 3], nb: [u32; 3], root: u32) -> u32 {
        self.tris.push(t);
        self.nb.push(nb);
        self.root_new.push(root);
        (self.tris.len() - 1) as u32
    }

    /// Mark face `f`'s input face as edited.
    pub fn mark(&mut self, f: u32) {
        let r = self.root(f) as usize;
        self.touched[r] = true;
    }

    /// In face `g`, the neighbour pointer `old` becomes `new`.
    fn repoint(&mut self, g: u32, old: u32, new: u32) {
        if g == u32::MAX {
            return;
        }
        if let Some(slot) = self.nb[g as usize].iter_mut().find(|x| **x == old) {
            *slot = new;
        }
    }

    /// Face `f` rotated so that corner `k` comes first: `(tri, neighbours)`.
    fn rotated(&self, f: u32, k: usize) -> ([u32; 3], [u32; 3]) {
        let (t, n) = (self.tris[f as usize], self.nb[f as usize]);
        (
            [t[k], t[(k + 1) % 3], t[(k + 2) % 3]],
            [n[k], n[(k + 1) % 3], n[(k + 2) % 3]],
        )
    }

    /// Split the edge opposite corner `k` of face `f` at the new vertex `v` (both faces of the
    /// edge are split in two).
    ///
    /// # Errors
    /// [`SurgeryError::Broken`] when the neighbour across the edge does not hold it.
    pub fn split_edge(&mut self, f: u32, k: usize, v: u32) -> Result<(), SurgeryError> {
        let ([c, p, q], [g, b_nb, a_nb]) = self.rotated(f, k);
        self.mark(f);
        let f2 = self.new_face([c, v, q], [u32::MAX, b_nb, f], self.root(f));
        self.tris[f as usize] = [c, p, v];
        self.nb[f as usize] = [u32::MAX, f2, a_nb];
        self.repoint(b_nb, f, f2);
        self.vf[v as usize] = f;
        self.vf[q as usize] = f2;
        self.vf[c as usize] = f;
        self.vf[p as usize] = f;
        if g != u32::MAX {
            self.mark(g);
            let tg = self.tris[g as usize];
            let Some(kg) = (0..3).find(|&i| tg[i] != p && tg[i] != q) else {
                return Err(SurgeryError::Broken(format!(
                    "face {g}, across an edge of face {f}, has no third corner"
                )));
            };
            let ([c2, q2, p2], [_, b2, a2]) = self.rotated(g, kg);
            debug_assert!(q2 == q && p2 == p, "consistent orientation");
            // g = (c2, q, p) becomes (c2, q, v) and g2 = (c2, v, p).
            let g2 = self.new_face([c2, v, p], [f, b2, g], self.root(g));
            self.tris[g as usize] = [c2, q, v];
            self.nb[g as usize] = [f2, g2, a2];
            self.repoint(b2, g, g2);
            self.nb[f as usize][0] = g2;
            self.nb[f2 as usize][0] = g;
            self.vf[c2 as usize] = g;
        }
        Ok(())
    }

    /// Split face `f` into three at the new vertex `v` inside it.
    pub fn split_face(&mut self, f: u32, v: u32) {
        let [a, b, c] = self.tris[f as usize];
        let [na, nb_, nc] = self.nb[f as usize];
        self.mark(f);
        let root = self.root(f);
        let f2 = self.new_face([b, c, v], [u32::MAX, u32::MAX, na], root);
        let f3 = self.new_face([c, a, v], [u32::MAX, u32::MAX, nb_], root);
        self.tris[f as usize] = [a, b, v];
        self.nb[f as usize] = [f2, f3, nc];
        self.nb[f2 as usize][0] = f3;
        self.nb[f2 as usize][1] = f;
        self.nb[f3 as usize][0] = f;
        self.nb[f3 as usize][1] = f2;
        self.repoint(na, f, f2);
        self.repoint(nb_, f, f3);
        self.vf[v as usize] = f;
        self.vf[a as usize] = f;
        self.vf[b as usize] = f;
        self.vf[c as usize] = f2;
    }

    /// The corner of face `f` that is vertex `v`.
    ///
    /// # Errors
    /// [`SurgeryError::Broken`] when `f` does not hold `v` (a stale vertex-face or neighbour
    /// link: a bug, reported rather than panicking).
    pub fn corner(&self, f: u32, v: u32) -> Result<usize, SurgeryError> {
        let t = self.tris[f as usize];
        t.iter().position(|&x| x == v).ok_or_else(|| {
            SurgeryError::Broken(format!("vertex {v} is not a corner of face {f} {t:?}"))
        })
    }

    /// Faces `f` and `g` stop being neighbours (the edge between them became a boundary).
    pub fn unlink(&mut self, f: u32, g: u32) {
        self.repoint(f, g, u32::MAX);
        self.repoint(g, f, u32::MAX);
    }
}

impl Influences {
    /// Vertex `v`'s joints and weights.
    pub(crate) fn clone_row(&self, v: u32) -> (Vec<u32>, Vec<f64>) {
        let mut tmp = Influences {
            width: self.width,
            ..Influences::default()
        };
        push_copy(self, v, &mut tmp);
        (tmp.joints, tmp.weights)
    }
}
