//! The sparsity pattern every Laplacian of a mesh shares (the diagonal plus every edge), built
//! once from the triangles, and the assembly of per-triangle edge weights into it.
//!
//! Splitting the two lets a solver order and analyse the pattern while the weights are still
//! being computed ([`crate::operators::harmonic::Harmonic::new`] does both at once on two
//! threads).

use crate::mesh::adjacency::Edges;
use sprs::CsMat;

/// Compressed rows of a Laplacian's pattern: row `i` holds `i` and every vertex sharing a
/// triangle edge with it, increasing; with the place of each triangle's edge entries in it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct LaplacianPattern {
    /// Row `i` is `indices[indptr[i]..indptr[i + 1]]`.
    pub(crate) indptr: Vec<usize>,
    pub(crate) indices: Vec<usize>,
    /// The position of each row's diagonal entry in `indices`.
    diagonal: Vec<usize>,
    /// `places[2 (3 f + k) + s]`: where the entry of the edge opposite corner `k` of triangle
    /// `f` lies in row `a` (`s = 0`, column `b`) and in row `b` (`s = 1`, column `a`); `a, b`
    /// are the next corners in order. [`NOWHERE`] for an edge from a vertex to itself.
    places: Vec<u32>,
}

/// In the rows being sorted: the diagonal entry (no triangle corner).
const DIAGONAL: u32 = u32::MAX;
/// In `places`: an edge from a vertex to itself (a triangle with a repeated index).
const NOWHERE: u32 = u32::MAX;

impl LaplacianPattern {
    /// The pattern of `n` vertices and these triangles (indices must be in range; fewer
    /// than 2^32 entries and 2^31 / 3 triangles). Edges of a triangle with a repeated index
    /// that join a vertex to itself add nothing.
    pub(crate) fn new(n: usize, triangles: &[[u32; 3]]) -> LaplacianPattern {
        // Row capacities: the diagonal plus two slots per incident triangle.
        let mut offsets = vec![0usize; n + 1];
        for t in triangles {
            for &v in t {
                offsets[v as usize + 1] += 2;
            }
        }
        for i in 0..n {
            offsets[i + 1] += offsets[i] + 1;
        }
        // Each slot: the column in the high half, the triangle corner and side it came from
        // in the low half, so that sorting a row sorts by column.
        let key = |column: usize, code: u32| (column as u64) << 32 | code as u64;
        let mut slots = vec![0u64; offsets[n]];
        let mut fill: Vec<usize> = offsets[..n].to_vec();
        for (i, f) in fill.iter_mut().enumerate() {
            slots[*f] = key(i, DIAGONAL);
            *f += 1;
        }
        let mut places = vec![NOWHERE; 6 * triangles.len()];
        for (f, t) in triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[(k + 1) % 3] as usize, t[(k + 2) % 3] as usize);
                if a == b {
                    continue;
                }
                let code = 2 * (3 * f + k) as u32;
                slots[fill[a]] = key(b, code);
                fill[a] += 1;
                slots[fill[b]] = key(a, code + 1);
                fill[b] += 1;
            }
        }
        let mut indptr = Vec::with_capacity(n + 1);
        let mut indices = Vec::with_capacity(offsets[n]);
        let mut diagonal = Vec::with_capacity(n);
        indptr.push(0);
        for i in 0..n {
            let row = &mut slots[offsets[i]..fill[i]];
            row.sort_unstable();
            let mut last = usize::MAX;
            for &slot in row.iter() {
                let (column, code) = ((slot >> 32) as usize, slot as u32);
                if column != last {
                    if column == i {
                        diagonal.push(indices.len());
                    }
                    indices.push(column);
                    last = column;
                }
                if code != DIAGONAL {
                    places[code as usize] = (indices.len() - 1) as u32;
                }
            }
            indptr.push(indices.len());
        }
        LaplacianPattern {
            indptr,
            indices,
            diagonal,
            places,
        }
    }

    /// [`LaplacianPattern::new`] from the triangles' edge table (`edges` must be
    /// [`crate::mesh::adjacency::edges`] of these `triangles`, whose indices must be in range and distinct):
    /// the edges come sorted, so every row is laid out in order without sorting.
    pub(crate) fn from_edges(n: usize, triangles: &[[u32; 3]], edges: &Edges) -> LaplacianPattern {
        let mut indptr = vec![0usize; n + 1];
        for &[a, b] in &edges.edges {
            indptr[a as usize + 1] += 1;
            indptr[b as usize + 1] += 1;
        }
        for i in 0..n {
            indptr[i + 1] += indptr[i] + 1;
        }
        let mut indices = vec![0usize; indptr[n]];
        let mut fill: Vec<usize> = indptr[..n].to_vec();
        // Edges `[a, b]` run by `a`, then `b`: row `b` receives its columns `a < b` in order,
        // then its diagonal, then (second pass) its columns above `b` in order.
        let mut lower = Vec::with_capacity(edges.edges.len());
        for &[a, b] in &edges.edges {
            let at = &mut fill[b as usize];
            indices[*at] = a as usize;
            lower.push(*at as u32);
            *at += 1;
        }
        let mut diagonal = Vec::with_capacity(n);
        for (i, at) in fill.iter_mut().enumerate() {
            indices[*at] = i;
            diagonal.push(*at);
            *at += 1;
        }
        let mut upper = Vec::with_capacity(edges.edges.len());
        for &[a, b] in &edges.edges {
            let at = &mut fill[a as usize];
            indices[*at] = b as usize;
            upper.push(*at as u32);
            *at += 1;
        }
        let mut places = vec![NOWHERE; 6 * triangles.len()];
        for (f, (t, e)) in triangles.iter().zip(&edges.face_edges).enumerate() {
            for k in 0..3 {
                let e = e[k] as usize;
                // Row `a` column `b` first: the upper entry when `a < b`.
                let (ab, ba) = if t[(k + 1) % 3] < t[(k + 2) % 3] {
                    (upper[e], lower[e])
                } else {
                    (lower[e], upper[e])
                };
                places[6 * f + 2 * k] = ab;
                places[6 * f + 2 * k + 1] = ba;
            }
        }
        LaplacianPattern {
            indptr,
            indices,
            diagonal,
            places,
        }
    }

    /// Rows (and columns).
    pub(crate) fn len(&self) -> usize {
        self.diagonal.len()
    }

    /// Assembles `L` from per-triangle edge weights (`triangles` must be the pattern's):
    /// `weights[f][k] = [w_ab, w_ba]` belongs to the edge `(a, b)` opposite corner `k` of
    /// triangle `f` (`a, b` the next corners in order); `w_ab` is added to `L_ab` and
    /// subtracted from `L_aa`, `w_ba` likewise in row `b`.
    pub(crate) fn assemble(&self, triangles: &[[u32; 3]], weights: &[[[f64; 2]; 3]]) -> CsMat<f64> {
        self.assemble_with(triangles, |f, _| weights.get(f).copied())
    }

    /// [`LaplacianPattern::assemble`] with the weights of triangle `f` (its index and
    /// corners) computed as they are added (`None`: it adds nothing), so that no array of
    /// them is stored.
    pub(crate) fn assemble_with(
        &self,
        triangles: &[[u32; 3]],
        mut weight: impl FnMut(usize, [u32; 3]) -> Option<[[f64; 2]; 3]>,
    ) -> CsMat<f64> {
        let n = self.len();
        let mut data = vec![0.0; self.indices.len()];
        let mut diag = vec![0.0f64; n];
        for (f, t) in triangles.iter().enumerate() {
            let Some(w) = weight(f, *t) else {
                continue;
            };
            for k in 0..3 {
                let at = &self.places[6 * f + 2 * k..6 * f + 2 * k + 2];
                if at[0] == NOWHERE {
                    continue;
                }
                let (a, b) = (t[(k + 1) % 3] as usize, t[(k + 2) % 3] as usize);
                let [wab, wba] = w[k];
                data[at[0] as usize] += wab;
                data[at[1] as usize] += wba;
                diag[a] -= wab;
                diag[b] -= wba;
            }
        }
        for (i, &d) in self.diagonal.iter().enumerate() {
            data[d] = diag[i];
        }
        CsMat::new((n, n), self.indptr.clone(), self.indices.clone(), data)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::adjacency::edges;
    use crate::mesh::shapes::{icosphere, tube};

    /// The edge table's pattern is the sorted one: rows, diagonals and the place of every
    /// triangle's entries, on closed, open and non-manifold meshes (an edge of three
    /// triangles, a bow-tie vertex) and a mesh with unreferenced vertices.
    #[test]
    fn the_edge_table_gives_the_sorted_pattern() {
        let fin = vec![[0, 1, 2], [1, 0, 3], [0, 1, 4], [4, 5, 6], [4, 7, 8]];
        let meshes: Vec<(usize, Vec<[u32; 3]>)> = vec![
            (
                icosphere(1.0, 2).vertex_count(),
                icosphere(1.0, 2).triangles,
            ),
            (
                tube(1.0, 2.0, 7, 5).vertex_count(),
                tube(1.0, 2.0, 7, 5).triangles,
            ),
            (12, fin),
            (3, vec![]),
        ];
        for (n, t) in meshes {
            let sorted = LaplacianPattern::new(n, &t);
            assert_eq!(LaplacianPattern::from_edges(n, &t, &edges(&t, n)), sorted);
            // The rows do hold the diagonal and each triangle's two entries per edge.
            for (f, tri) in t.iter().enumerate() {
                for k in 0..3 {
                    let (a, b) = (tri[(k + 1) % 3] as usize, tri[(k + 2) % 3] as usize);
                    let at = &sorted.places[6 * f + 2 * k..6 * f + 2 * k + 2];
                    let (ra, rb) = (
                        sorted.indptr[a]..sorted.indptr[a + 1],
                        sorted.indptr[b]..sorted.indptr[b + 1],
                    );
                    assert!(ra.contains(&(at[0] as usize)) && sorted.indices[at[0] as usize] == b);
                    assert!(rb.contains(&(at[1] as usize)) && sorted.indices[at[1] as usize] == a);
                }
            }
        }
    }
}
