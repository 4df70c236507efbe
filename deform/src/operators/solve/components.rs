//! Checks of the matrix before factorisation: its storage, and a constrained row in every
//! connected component.

use crate::mesh::union_find::UnionFind;
use crate::mesh::IndexList;
use crate::operators::{Result, SolveError};
use sprs::CsMat;

/// `q` in CSR storage (borrowed when it already is).
pub(super) fn ensure_csr(q: &CsMat<f64>) -> std::borrow::Cow<'_, CsMat<f64>> {
    if q.is_csr() {
        std::borrow::Cow::Borrowed(q)
    } else {
        std::borrow::Cow::Owned(q.to_csr())
    }
}

/// Fails when a connected component of the graph of `q`'s nonzero off-diagonal entries has no
/// constrained row (`slot != u32::MAX`).
pub(super) fn check_components(
    n: usize,
    indptr: &[usize],
    indices: &[usize],
    data: &[f64],
    slot: &[u32],
) -> Result<()> {
    let mut uf = UnionFind::new(n);
    for i in 0..n {
        for k in indptr[i]..indptr[i + 1] {
            if indices[k] != i && data[k] != 0.0 {
                uf.union(i as u32, indices[k] as u32);
            }
        }
    }
    let comps = uf.labels();
    let mut anchored = vec![false; comps.count];
    for v in 0..n {
        if slot[v] != u32::MAX {
            anchored[comps.labels[v] as usize] = true;
        }
    }
    let unanchored = anchored.iter().filter(|a| !**a).count();
    if unanchored == 0 {
        return Ok(());
    }
    let vertices: Vec<u32> = (0..n as u32)
        .filter(|&v| !anchored[comps.labels[v as usize] as usize])
        .collect();
    let mut sizes = vec![0usize; comps.count];
    for &v in &vertices {
        sizes[comps.labels[v as usize] as usize] += 1;
    }
    Err(SolveError::Unconstrained {
        components: unanchored,
        isolated: sizes.iter().filter(|&&k| k == 1).count(),
        vertices: IndexList(vertices),
    })
}
