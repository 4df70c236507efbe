//! The sparsity pattern every Laplacian of a mesh shares (the diagonal plus every edge), built
//! once from the triangles, and the assembly of per-triangle edge weights into it.
//!
//! Splitting the two lets a solver order and analyse the pattern while the weights are still
//! being computed ([`crate::operators::harmonic::Harmonic::new`] does both at once on two
//! threads).

use sprs::CsMat;

/// Compressed rows of a Laplacian's pattern: row `i` holds `i` and every vertex sharing a
/// triangle edge with it, increasing.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct LaplacianPattern {
    /// Row `i` is `indices[indptr[i]..indptr[i + 1]]`.
    pub(crate) indptr: Vec<usize>,
    pub(crate) indices: Vec<usize>,
    /// The position of each row's diagonal entry in `indices`.
    diagonal: Vec<usize>,
}

impl LaplacianPattern {
    /// The pattern of `n` vertices and these triangles (indices must be in range). Edges of a
    /// triangle with a repeated index that join a vertex to itself add nothing.
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
        let mut slots = vec![0u32; offsets[n]];
        let mut fill: Vec<usize> = offsets[..n].to_vec();
        for (i, f) in fill.iter_mut().enumerate() {
            slots[*f] = i as u32;
            *f += 1;
        }
        for t in triangles {
            for k in 0..3 {
                let (a, b) = (t[(k + 1) % 3] as usize, t[(k + 2) % 3] as usize);
                slots[fill[a]] = b as u32;
                fill[a] += 1;
                slots[fill[b]] = a as u32;
                fill[b] += 1;
            }
        }
        let mut indptr = Vec::with_capacity(n + 1);
        let mut indices = Vec::with_capacity(offsets[n]);
        let mut diagonal = Vec::with_capacity(n);
        indptr.push(0);
        for i in 0..n {
            let row = &mut slots[offsets[i]..offsets[i + 1]];
            row.sort_unstable();
            let mut last = u32::MAX;
            for &c in row.iter() {
                if c != last {
                    if c as usize == i {
                        diagonal.push(indices.len());
                    }
                    indices.push(c as usize);
                    last = c;
                }
            }
            indptr.push(indices.len());
        }
        LaplacianPattern {
            indptr,
            indices,
            diagonal,
        }
    }

    /// Rows (and columns).
    pub(crate) fn len(&self) -> usize {
        self.diagonal.len()
    }

    /// The position of column `c` in row `r` (both in the pattern).
    #[inline]
    fn position(&self, r: usize, c: usize) -> usize {
        let (lo, hi) = (self.indptr[r], self.indptr[r + 1]);
        lo + self.indices[lo..hi]
            .iter()
            .position(|&x| x == c)
            .expect("the pattern holds every edge of its triangles")
    }

    /// Assembles `L` from per-triangle edge weights (`triangles` must be the pattern's):
    /// `weights[f][k] = [w_ab, w_ba]` belongs to the edge `(a, b)` opposite corner `k` of
    /// triangle `f` (`a, b` the next corners in order); `w_ab` is added to `L_ab` and
    /// subtracted from `L_aa`, `w_ba` likewise in row `b`.
    pub(crate) fn assemble(&self, triangles: &[[u32; 3]], weights: &[[[f64; 2]; 3]]) -> CsMat<f64> {
        let n = self.len();
        let mut data = vec![0.0; self.indices.len()];
        let mut diag = vec![0.0f64; n];
        for (t, w) in triangles.iter().zip(weights) {
            for k in 0..3 {
                let (a, b) = (t[(k + 1) % 3] as usize, t[(k + 2) % 3] as usize);
                if a == b {
                    continue;
                }
                let [wab, wba] = w[k];
                data[self.position(a, b)] += wab;
                data[self.position(b, a)] += wba;
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
