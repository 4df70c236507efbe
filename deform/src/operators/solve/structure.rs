//! The structure of a Dirichlet problem, from `Q`'s pattern and the constrained set alone:
//! which rows are free, where the upper triangle of `Q_ff` and the entries of `Q_fc` sit in
//! `Q`'s values, and the symbolic Cholesky factor of `Q_ff` (fill-reducing ordering,
//! elimination tree). Nothing here reads a value, so it can run while the values are still
//! being computed ([`DirichletSolver::overlapped`](super::DirichletSolver::overlapped)).

use super::components::check_components;
use super::{DirichletSolver, FactorIndex, Factorization, SolverOptions};
use crate::mesh::IndexList;
use crate::mesh::MeshError;
use crate::operators::laplacian::ensure_finite;
use crate::operators::Result;
use crate::operators::SolveError;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, SymbolicCholesky, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::SymbolicSparseColMatRef;
use faer::Side;
use sprs::CsMat;

/// The symbolic Cholesky factor of the upper triangle `upper` (AMD ordering), laid out as
/// asked.
pub(super) fn analyse(
    upper: SymbolicSparseColMatRef<'_, FactorIndex>,
    factorization: Factorization,
) -> Result<SymbolicCholesky<FactorIndex>> {
    let params = CholeskySymbolicParams {
        supernodal_flop_ratio_threshold: match factorization {
            Factorization::Auto => SupernodalThreshold::AUTO,
            Factorization::Supernodal => SupernodalThreshold::FORCE_SUPERNODAL,
            Factorization::Simplicial => SupernodalThreshold::FORCE_SIMPLICIAL,
        },
        ..Default::default()
    };
    factorize_symbolic_cholesky(upper, Side::Upper, SymmetricOrdering::Amd, params)
        .map_err(|e| SolveError::Solver(format!("{e:?}")))
}

/// Fails with [`SolveError::Solver`] when an `n x n` pattern of `entries` nonzeros is too
/// large for the factor's 32-bit indices.
pub(super) fn fits_factor_index(n: usize, entries: usize) -> Result<()> {
    if FactorIndex::try_from(n.max(entries)).is_err() {
        return Err(SolveError::Solver(format!(
            "a {n} x {n} pattern of {entries} nonzeros exceeds the factor's 32-bit indices"
        )));
    }
    Ok(())
}

/// Marks a row as free in the slots of [`classify`].
pub(super) const FREE: u32 = u32::MAX;

/// The rows of a CSR matrix split by a constrained set (see [`split`]).
pub(super) struct Split {
    /// Per row its position in `constrained`, or [`FREE`].
    pub(super) slot: Vec<u32>,
    /// The matrix's pattern.
    pub(super) indptr: Vec<usize>,
    pub(super) indices: Vec<usize>,
    /// The free rows, increasing.
    pub(super) free: Vec<u32>,
}

/// Classify the rows of the CSR matrix `q` by `constrained` and check, if asked, that every
/// connected component has a constrained row.
pub(super) fn split(q: &CsMat<f64>, constrained: &[u32], options: SolverOptions) -> Result<Split> {
    let n = q.rows();
    let slot = classify(n, constrained)?;
    let indptr = q.indptr().into_raw_storage().to_vec();
    let indices = q.indices().to_vec();
    if options.check_components {
        check_components(n, &indptr, &indices, q.data(), &slot)?;
    }
    let free: Vec<u32> = (0..n as u32)
        .filter(|&v| slot[v as usize] == FREE)
        .collect();
    Ok(Split {
        slot,
        indptr,
        indices,
        free,
    })
}

/// Per row its position in `constrained`, or [`FREE`]; errors for indices out of range or
/// listed twice.
pub(super) fn classify(n: usize, constrained: &[u32]) -> Result<Vec<u32>> {
    let mut slot = vec![FREE; n];
    let mut out_of_range = Vec::new();
    let mut repeated = Vec::new();
    for (k, &v) in constrained.iter().enumerate() {
        match slot.get_mut(v as usize) {
            None => out_of_range.push(v),
            Some(s) if *s != FREE => repeated.push(v),
            Some(s) => *s = k as u32,
        }
    }
    if !out_of_range.is_empty() {
        return Err(MeshError::ConstraintOutOfRange {
            vertices: IndexList(out_of_range),
            vertex_count: n,
        }
        .into());
    }
    if !repeated.is_empty() {
        repeated.sort_unstable();
        repeated.dedup();
        return Err(MeshError::OverlappingConstraints {
            vertices: IndexList(repeated),
        }
        .into());
    }
    Ok(slot)
}

/// The upper triangle of `Q_ff` (compressed columns, equal to CSR rows by symmetry) and
/// `Q_fc` (by free rows, columns are positions in the constrained list), each entry located
/// in `Q`'s values, with the symbolic factor of `Q_ff`.
pub(super) struct Reduced {
    pub(super) free: Vec<u32>,
    pub(super) ff_col_ptr: Vec<FactorIndex>,
    pub(super) ff_row_idx: Vec<FactorIndex>,
    pub(super) ff_src: Vec<usize>,
    pub(super) fc_ptr: Vec<usize>,
    pub(super) fc_col: Vec<u32>,
    pub(super) fc_src: Vec<usize>,
    pub(super) symbolic: SymbolicCholesky<FactorIndex>,
}

impl Reduced {
    /// The structure of `Q` (CSR pattern `indptr`, `indices`, columns sorted in each row)
    /// split by `slot` (from [`classify`]) into the `free` rows (increasing) and the rest,
    /// with the factor laid out as `factorization` says.
    pub(super) fn new(
        indptr: &[usize],
        indices: &[usize],
        slot: &[u32],
        free: Vec<u32>,
        factorization: Factorization,
    ) -> Result<Reduced> {
        let n = slot.len();
        fits_factor_index(n, indices.len())?;
        let mut local = vec![0 as FactorIndex; n];
        for (i, &v) in free.iter().enumerate() {
            // `free` holds vertex indices, so `i` fits.
            local[v as usize] = i as FactorIndex;
        }
        let mut ff_col_ptr = Vec::with_capacity(free.len() + 1);
        let mut ff_row_idx = Vec::new();
        let mut ff_src = Vec::new();
        let mut fc_ptr = Vec::with_capacity(free.len() + 1);
        let mut fc_col = Vec::new();
        let mut fc_src = Vec::new();
        ff_col_ptr.push(0);
        fc_ptr.push(0);
        for (j, &v) in free.iter().enumerate() {
            let row = indptr[v as usize]..indptr[v as usize + 1];
            for (k, &u) in row.clone().zip(&indices[row]) {
                if slot[u] == FREE {
                    if local[u] as usize <= j {
                        ff_row_idx.push(local[u]);
                        ff_src.push(k);
                    }
                } else {
                    fc_col.push(slot[u]);
                    fc_src.push(k);
                }
            }
            // At most `indices.len()`, checked above.
            ff_col_ptr.push(ff_row_idx.len() as FactorIndex);
            fc_ptr.push(fc_col.len());
        }
        let nf = free.len();
        // Columns of a CSR row are sorted and `local` is increasing, so rows are sorted.
        let upper = SymbolicSparseColMatRef::new_checked(nf, nf, &ff_col_ptr, None, &ff_row_idx);
        let symbolic = analyse(upper, factorization)?;
        Ok(Reduced {
            free,
            ff_col_ptr,
            ff_row_idx,
            ff_src,
            fc_ptr,
            fc_col,
            fc_src,
            symbolic,
        })
    }
}

impl DirichletSolver {
    /// [`DirichletSolver::new`] for a `Q` whose CSR pattern (`indptr`, `indices`, columns
    /// sorted) is known before its values: the structure and the symbolic factor are
    /// computed from the pattern on one thread of rayon's pool while `values` computes `Q`
    /// on another (one after the other on a one-thread pool). A `Q` whose pattern turns out
    /// different is analysed again from its own. Errors: those of the constrained set, then
    /// those of `values`, then as [`DirichletSolver::new`].
    pub(crate) fn overlapped(
        indptr: &[usize],
        indices: &[usize],
        constrained: &[u32],
        options: SolverOptions,
        values: impl FnOnce() -> Result<CsMat<f64>> + Send,
    ) -> Result<DirichletSolver> {
        let n = indptr.len().saturating_sub(1);
        let slot = classify(n, constrained)?;
        let free: Vec<u32> = (0..n as u32)
            .filter(|&v| slot[v as usize] == FREE)
            .collect();
        let (reduced, q) = rayon::join(
            || Reduced::new(indptr, indices, &slot, free, options.factorization),
            values,
        );
        let q = q?;
        let same = q.is_csr()
            && q.rows() == n
            && q.cols() == n
            && q.indptr().into_raw_storage() == indptr
            && q.indices() == indices;
        if !same {
            return DirichletSolver::new(&q, constrained, options);
        }
        ensure_finite(&q, "system matrix row")?;
        if options.check_components {
            check_components(n, indptr, indices, q.data(), &slot)?;
        }
        DirichletSolver::from_reduced(
            options,
            constrained,
            indptr.to_vec(),
            indices.to_vec(),
            reduced?,
            q.data(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn patterns_beyond_32_bit_indices_are_refused() {
        let max = FactorIndex::MAX as usize;
        assert!(fits_factor_index(max, max).is_ok());
        for (n, entries) in [(max + 1, 0), (3, max + 1)] {
            match fits_factor_index(n, entries) {
                Err(SolveError::Solver(m)) => {
                    assert!(m.contains("32-bit"), "{m}")
                }
                other => panic!("{n} x {n}, {entries} nonzeros: {other:?}"),
            }
        }
    }
}
