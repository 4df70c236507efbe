//! The tear's soup seen over welded vertices. glTF splits a vertex wherever its UV coordinates
//! change, so along a seam two faces that meet on the surface share no edge index: the soup
//! links them as boundary. The walk and the opening look through such seams by labels: every
//! soup vertex carries the label of its coincident copies (the welded input's canonical vertex,
//! or the first of a new vertex's copies), and an edge whose soup link is a boundary is joined
//! to the face holding the same edge by labels, its seam twin. Splitting a seam edge splits the
//! twin too, at an exact copy of the new vertex, so the copies coincide and pose alike.
//!
//! The faces around each soup vertex are kept here as a list, updated by every edit the tear
//! makes, so a fan never depends on walking the soup's links (which stop at seams and at the
//! incision's already opened edges).

use super::super::soup::Soup;
use super::super::SurgeryError;
use std::collections::HashMap;

/// The first label given to the far lip of an opened incision vertex (labels below it are soup
/// vertices: the copy that stands for the others).
pub(super) const LIP: u32 = 1 << 31;

/// Labels of coincident soup vertices.
pub(super) struct Seams {
    /// `label[v]`: the label of soup vertex `v`.
    label: Vec<u32>,
    /// The soup vertices of each label that has more than one, or whose group was set.
    copies: HashMap<u32, Vec<u32>>,
    /// `faces[v]`: the faces around soup vertex `v`.
    faces: Vec<Vec<u32>>,
}

impl Seams {
    /// Labels of the input vertices of the triangles `tris`: `canon` (the weld's first vertex
    /// at each position), or each vertex its own (`n` of them) when nothing was welded.
    pub fn new(canon: Option<&[u32]>, n: usize, tris: &[[u32; 3]]) -> Seams {
        let label: Vec<u32> = match canon {
            Some(c) => c.to_vec(),
            None => (0..n as u32).collect(),
        };
        let mut copies: HashMap<u32, Vec<u32>> = HashMap::new();
        for (v, &l) in label.iter().enumerate() {
            if l != v as u32 {
                copies.entry(l).or_insert_with(|| vec![l]).push(v as u32);
            }
        }
        let mut faces = vec![Vec::new(); label.len()];
        for (f, t) in tris.iter().enumerate() {
            for &v in t {
                faces[v as usize].push(f as u32);
            }
        }
        Seams {
            label,
            copies,
            faces,
        }
    }

    /// The label of soup vertex `v`.
    #[inline]
    pub fn label(&self, v: u32) -> u32 {
        self.label[v as usize]
    }

    /// Every soup vertex's label.
    pub fn labels(&self) -> &[u32] {
        &self.label
    }

    /// The soup vertices labelled `l`.
    pub fn copies(&self, l: u32) -> Vec<u32> {
        self.copies.get(&l).cloned().unwrap_or_else(|| vec![l])
    }

    /// Register the new soup vertex `v` (the next one) with label `l`.
    pub fn push(&mut self, v: u32, l: u32) {
        debug_assert_eq!(
            v as usize,
            self.label.len(),
            "vertices are registered in order"
        );
        self.label.push(l);
        self.faces.push(Vec::new());
        if l != v {
            self.copies.entry(l).or_insert_with(|| vec![l]).push(v);
        }
    }

    /// Split label `l`: the vertices `near` keep it, the vertices `far` get label `lip`.
    pub fn divide(&mut self, l: u32, near: Vec<u32>, far: Vec<u32>, lip: u32) {
        for &v in &far {
            self.label[v as usize] = lip;
        }
        self.copies.insert(l, near);
        self.copies.insert(lip, far);
    }

    /// The faces around label `l` (every copy's), each with the copy it holds.
    pub fn fan(&self, l: u32) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for c in self.copies(l) {
            out.extend(self.faces[c as usize].iter().map(|&f| (f, c)));
        }
        out
    }

    /// Record that faces `edited` (with their corners before the edit) changed and faces from
    /// `first_new` on are new.
    fn refresh(&mut self, soup: &Soup, edited: &[(u32, [u32; 3])], first_new: usize) {
        for &(f, old) in edited {
            let now = soup.tris[f as usize];
            for x in old.into_iter().filter(|x| !now.contains(x)) {
                self.faces[x as usize].retain(|&g| g != f);
            }
            for x in now.into_iter().filter(|x| !old.contains(x)) {
                self.faces[x as usize].push(f);
            }
        }
        for f in first_new..soup.tris.len() {
            for x in soup.tris[f] {
                self.faces[x as usize].push(f as u32);
            }
        }
    }

    /// Split face `f` into three at the new vertex `v` (registered) inside it.
    pub fn split_face(&mut self, soup: &mut Soup, f: u32, v: u32) {
        let (old, first_new) = (soup.tris[f as usize], soup.tris.len());
        soup.split_face(f, v);
        self.refresh(soup, &[(f, old)], first_new);
    }

    /// In face `f`, vertex `c` becomes `d`.
    pub fn replace(&mut self, soup: &mut Soup, f: u32, c: u32, d: u32) {
        let old = soup.tris[f as usize];
        for x in soup.tris[f as usize].iter_mut() {
            if *x == c {
                *x = d;
            }
        }
        self.refresh(soup, &[(f, old)], soup.tris.len());
    }

    /// Split the soup edge opposite corner `k` of face `f` (both its linked faces) at `v`.
    fn split_linked(
        &mut self,
        soup: &mut Soup,
        f: u32,
        k: usize,
        v: u32,
    ) -> Result<(), SurgeryError> {
        let g = soup.nb[f as usize][k];
        let mut edited = vec![(f, soup.tris[f as usize])];
        if g != u32::MAX {
            edited.push((g, soup.tris[g as usize]));
        }
        let first_new = soup.tris.len();
        soup.split_edge(f, k, v)?;
        self.refresh(soup, &edited, first_new);
        Ok(())
    }

    /// The face across the edge `a b` of face `f`: its soup neighbour, else its seam twin;
    /// `None` on the surface's boundary.
    ///
    /// # Errors
    /// [`SurgeryError::Broken`] when `f` has no such edge.
    pub fn across(&self, soup: &Soup, f: u32, a: u32, b: u32) -> Result<Option<u32>, SurgeryError> {
        let t = soup.tris[f as usize];
        let Some(k) = (0..3).find(|&k| t[k] != a && t[k] != b) else {
            return Err(SurgeryError::Broken(format!(
                "face {f} {t:?} has no edge {a} {b}"
            )));
        };
        let g = soup.nb[f as usize][k];
        if g != u32::MAX {
            return Ok(Some(g));
        }
        Ok(self.twin(soup, f, k).map(|(g, _)| g))
    }

    /// The other face holding, by labels, the edge opposite corner `k` of face `f`, with its
    /// corner opposite that edge.
    fn twin(&self, soup: &Soup, f: u32, k: usize) -> Option<(u32, usize)> {
        let t = soup.tris[f as usize];
        let (la, lb) = (self.label(t[(k + 1) % 3]), self.label(t[(k + 2) % 3]));
        if !self.copies.contains_key(&la) && !self.copies.contains_key(&lb) {
            return None;
        }
        self.fan(la).into_iter().find_map(|(g, _)| {
            let l = soup.tris[g as usize].map(|x| self.label(x));
            let kg = (0..3).find(|&i| l[i] != la && l[i] != lb)?;
            (g != f && l.contains(&lb)).then_some((g, kg))
        })
    }

    /// Split the edge opposite corner `k` of face `f` at the new vertex `v` (registered), and
    /// its seam twin, if any, at an exact copy of `v`.
    ///
    /// # Errors
    /// [`SurgeryError::Broken`] when the soup's links are inconsistent.
    pub fn split_edge(
        &mut self,
        soup: &mut Soup,
        f: u32,
        k: usize,
        v: u32,
    ) -> Result<(), SurgeryError> {
        let twin = if soup.nb[f as usize][k] == u32::MAX {
            self.twin(soup, f, k)
        } else {
            None
        };
        self.split_linked(soup, f, k, v)?;
        if let Some((g, kg)) = twin {
            let c = soup.copy_vertex(v);
            // A copy on the other side of a seam, not a lip: it is the same incision point,
            // made from the twin edge's own vertices (its side of the seam's UVs).
            soup.origin[c as usize] = soup.origin[v as usize];
            let tg = soup.tris[g as usize];
            let (p, q) = (tg[(kg + 1) % 3], tg[(kg + 2) % 3]);
            let (xp, xq) = (soup.rest[p as usize], soup.rest[q as usize]);
            let d = xq - xp;
            let t = if d.length_squared() > 0.0 {
                ((soup.rest[c as usize] - xp).dot(d) / d.length_squared()).clamp(0.0, 1.0)
            } else {
                0.5
            };
            soup.set_sources(c, &[(p, 1.0 - t), (q, t)]);
            self.push(c, self.label(v));
            self.split_linked(soup, g, kg, c)?;
        }
        Ok(())
    }

    /// A new vertex on the soup edge `a b` at `a + t (b - a)`, splitting the edge and its seam
    /// twin; returns the vertex on `a b`'s side.
    ///
    /// # Errors
    /// [`SurgeryError::Broken`] when no face holds the edge; [`SurgeryError::BadMesh`] when the
    /// new vertex cannot be mapped back to the rest pose.
    pub fn split_at(
        &mut self,
        soup: &mut Soup,
        a: u32,
        b: u32,
        t: f64,
    ) -> Result<u32, SurgeryError> {
        let Some(&f) = self.faces[a as usize]
            .iter()
            .find(|&&f| soup.tris[f as usize].contains(&b))
        else {
            return Err(SurgeryError::Broken(format!(
                "no face holds the edge {a} {b}"
            )));
        };
        let tri = soup.tris[f as usize];
        let Some(k) = (0..3).find(|&i| tri[i] != a && tri[i] != b) else {
            return Err(SurgeryError::Broken(format!(
                "face {f} {tri:?} is degenerate"
            )));
        };
        let p = soup.at(a).lerp(soup.at(b), t);
        let m = soup.add_vertex(p, &[(a, 1.0 - t), (b, t)])?;
        self.push(m, m);
        self.split_edge(soup, f, k, m)?;
        Ok(m)
    }
}
