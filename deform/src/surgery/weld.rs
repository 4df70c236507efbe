//! Coincident vertices, for the topology of a cut. glTF splits a vertex wherever its UV
//! coordinates (or normals) change, so a textured model such as CesiumMan is, vertex by
//! vertex, a set of open patches: a plane cut then meets hundreds of seam loops and no cap can
//! close. Welding vertices at bit-identical positions recovers the closed surface for finding
//! boundary loops and caps, while the pieces keep every input vertex (and so the UVs a viewer
//! maps through them).

use super::split::Topology;
use crate::mesh::Mesh;
use crate::skinning::Influences;
use glam::DVec3;
use std::collections::{HashMap, HashSet};

/// The mesh with every vertex replaced by the first vertex at its position.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Weld {
    /// `canon[v]`: the smallest index of a vertex at `v`'s position.
    pub canon: Vec<u32>,
    /// The triangles over canonical vertices.
    pub triangles: Vec<[u32; 3]>,
    /// Their topology (face indices are those of the input).
    pub topology: Topology,
}

impl Weld {
    /// `None` when no two vertices coincide, or when welding would not give a consistently
    /// oriented edge-manifold mesh without degenerate triangles (the input's own topology is
    /// used then).
    pub fn new(mesh: &Mesh) -> Option<Weld> {
        let n = mesh.vertex_count();
        let mut first: HashMap<[u64; 3], u32> = HashMap::with_capacity(n);
        let canon: Vec<u32> = mesh
            .positions
            .iter()
            .enumerate()
            .map(|(i, p)| {
                // +0.0 and -0.0 are the same point.
                let key = [p.x + 0.0, p.y + 0.0, p.z + 0.0].map(f64::to_bits);
                *first.entry(key).or_insert(i as u32)
            })
            .collect();
        if first.len() == n {
            return None;
        }
        let triangles: Vec<[u32; 3]> = mesh
            .triangles
            .iter()
            .map(|t| t.map(|v| canon[v as usize]))
            .collect();
        let mut half = HashSet::with_capacity(3 * triangles.len());
        for t in &triangles {
            if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
                return None;
            }
            for k in 0..3 {
                if !half.insert((t[k], t[(k + 1) % 3])) {
                    return None;
                }
            }
        }
        if crate::mesh::adjacency::edges(&triangles, n)
            .non_manifold()
            .next()
            .is_some()
        {
            return None;
        }
        let topology = Topology::new(&triangles, n);
        Some(Weld {
            canon,
            triangles,
            topology,
        })
    }
}

/// The canonical id of every input and new vertex: `canon` for input vertices, and for a new
/// vertex the first new vertex on an edge between the same canonical ends (the copies of a
/// seam edge are split at the same point).
pub(crate) fn canonical_ids(canon: &[u32], new_edges: &[(u32, u32, f64)]) -> Vec<u32> {
    let n = canon.len();
    let mut first: HashMap<(u32, u32), u32> = HashMap::with_capacity(new_edges.len());
    let mut out = Vec::with_capacity(n + new_edges.len());
    out.extend_from_slice(canon);
    for (k, &(a, b, _)) in new_edges.iter().enumerate() {
        let (ca, cb) = (canon[a as usize], canon[b as usize]);
        let key = (ca.min(cb), ca.max(cb));
        out.push(*first.entry(key).or_insert((n + k) as u32));
    }
    out
}

/// Give the copies of a new vertex (one per copy of a seam edge) the rest position and
/// influences of the first, so that they coincide exactly and pose alike: `canon_new[k]` is
/// the canonical global id of new vertex `k` (new ids start at `n`).
pub(crate) fn share_copies(canon_new: &[u32], n: usize, inf: &mut Influences, rest: &mut [DVec3]) {
    let w = inf.width;
    for (k, &c) in canon_new.iter().enumerate() {
        let c = c as usize - n;
        if c != k {
            rest[k] = rest[c];
            inf.joints.copy_within(c * w..(c + 1) * w, k * w);
            inf.weights.copy_within(c * w..(c + 1) * w, k * w);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// Two triangles of a square, with the shared edge's vertices duplicated (a UV seam).
    fn seamed_square() -> Mesh {
        let p = [
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::Y,
            DVec3::ZERO,
            DVec3::new(1.0, 1.0, 0.0),
        ];
        Mesh::new(p.to_vec(), vec![[0, 1, 2], [4, 5, 3]])
    }

    #[test]
    fn seams_close_and_plain_meshes_are_left_alone() {
        let w = Weld::new(&seamed_square()).expect("duplicates");
        assert_eq!(w.canon, vec![0, 1, 2, 3, 0, 2]);
        assert_eq!(w.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        // One loop around the square, not two around the halves.
        assert_eq!(w.topology.loops, 1);
        let plain = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
        assert!(Weld::new(&plain).is_none());
    }

    #[test]
    fn welds_that_break_the_surface_are_refused() {
        // The duplicate copy is wound the other way: welding would orient the edge twice.
        let mut m = seamed_square();
        m.triangles[1] = [4, 3, 5];
        assert!(Weld::new(&m).is_none());
        // A triangle whose corners coincide after welding.
        let mut m = seamed_square();
        m.triangles.push([0, 4, 1]);
        assert!(Weld::new(&m).is_none());
    }
}
