//! The sparsity pattern every Laplacian of a mesh shares (the diagonal plus every edge), built
//! once from the triangles, and the assembly of per-triangle edge weights into it.
//!
//! Splitting the two lets a solver order and analyse the pattern while the weights are still
//! being computed ([`crate::operators::harmonic::Harmonic::new`] does both at once on two
//! threads).

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
