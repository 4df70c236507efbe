//! Local 1-to-4 refinement (red-green, so no T-junctions appear) of the faces a tool needs
//! denser: new midpoints get interpolated weights (section 4.3) and rest positions through
//! the frame, like every new vertex.

use super::weights::push_interpolated;
use super::{unskin, Posing, SurgeryError};
use crate::skinning::Influences;
use glam::DVec3;
use std::collections::{HashMap, HashSet};

/// A mesh being refined: rest and frame positions, influences, triangles.
#[derive(Clone, Debug)]
pub(crate) struct Work<'a> {
    pub rest: Vec<DVec3>,
    pub frame: Vec<DVec3>,
    pub influences: Influences,
    /// Sources of every vertex ([`super::SkinnedMesh::sources`]).
    pub sources: Influences,
    pub triangles: Vec<[u32; 3]>,
    /// How the frame was posed, when it was.
    pub skin: Option<Posing<'a>>,
}

impl Work<'_> {
    /// Refine the faces `red` 1-to-4, closing with 1-to-4 (two or more split edges) and 1-to-2
    /// (one split edge) neighbours. Returns how many faces were replaced.
    pub fn refine(&mut self, red: &[u32]) -> Result<usize, SurgeryError> {
        let mut red: HashSet<u32> = red.iter().copied().collect();
        let mut edge_faces: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        for (f, t) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                edge_faces
                    .entry((a.min(b), a.max(b)))
                    .or_default()
                    .push(f as u32);
            }
        }
        let key = |a: u32, b: u32| (a.min(b), a.max(b));
        let mut marked: HashSet<(u32, u32)> = HashSet::new();
        let mut todo: Vec<u32> = red.iter().copied().collect();
        while let Some(f) = todo.pop() {
            let t = self.triangles[f as usize];
            for k in 0..3 {
                let e = key(t[k], t[(k + 1) % 3]);
                if !marked.insert(e) {
                    continue;
                }
                for &g in &edge_faces[&e] {
                    if red.contains(&g) {
                        continue;
                    }
                    let tg = self.triangles[g as usize];
                    let count = (0..3)
                        .filter(|&k| marked.contains(&key(tg[k], tg[(k + 1) % 3])))
                        .count();
                    if count >= 2 {
                        red.insert(g);
                        todo.push(g);
                    }
                }
            }
        }
        // Midpoints.
        let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
        let mut edges: Vec<(u32, u32)> = marked.into_iter().collect();
        edges.sort_unstable();
        for (a, b) in edges {
            let v = self.rest.len() as u32;
            let mut row = Influences {
                width: self.influences.width,
                ..Influences::default()
            };
            push_interpolated(&self.influences, &[(a, 0.5), (b, 0.5)], &mut row);
            self.influences.joints.extend_from_slice(&row.joints);
            self.influences.weights.extend_from_slice(&row.weights);
            let mut from = Influences {
                width: self.sources.width,
                ..Influences::default()
            };
            push_interpolated(&self.sources, &[(a, 0.5), (b, 0.5)], &mut from);
            self.sources.joints.extend_from_slice(&from.joints);
            self.sources.weights.extend_from_slice(&from.weights);
            let p = 0.5 * (self.frame[a as usize] + self.frame[b as usize]);
            let rest = match self.skin {
                None => 0.5 * (self.rest[a as usize] + self.rest[b as usize]),
                Some(skin) => {
                    let w = self.influences.width;
                    let r = v as usize * w..(v as usize + 1) * w;
                    unskin(
                        p,
                        &self.influences.joints[r.clone()],
                        &self.influences.weights[r],
                        skin,
                    )
                    .ok_or_else(|| {
                        SurgeryError::BadMesh(format!(
                            "refining edge {a}-{b}: singular skin transform"
                        ))
                    })?
                }
            };
            self.rest.push(rest);
            self.frame.push(p);
            mid.insert((a, b), v);
        }
        let m = |a: u32, b: u32| mid.get(&key(a, b)).copied();
        let mut replaced = 0;
        let old = std::mem::take(&mut self.triangles);
        for (f, t) in old.into_iter().enumerate() {
            let [a, b, c] = t;
            if red.contains(&(f as u32)) {
                let (ab, bc, ca) = (m(a, b).unwrap(), m(b, c).unwrap(), m(c, a).unwrap());
                self.triangles
                    .extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
                replaced += 1;
                continue;
            }
            let split = (0..3).find_map(|k| m(t[k], t[(k + 1) % 3]).map(|x| (k, x)));
            match split {
                Some((k, x)) => {
                    let (u, v, w) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
                    self.triangles.extend([[w, u, x], [w, x, v]]);
                    replaced += 1;
                }
                None => self.triangles.push(t),
            }
        }
        Ok(replaced)
    }
}
