//! One symbolic analysis for every constrained set of a matrix.
//!
//! [`DirichletSolver::new`] factorises the free block `Q_ff`, whose pattern depends on which
//! rows are constrained, so every new constrained set pays for a fill-reducing ordering
//! (AMD) and an elimination tree again: the larger part of a bind on a 50k-vertex mesh. A
//! [`SystemAnalysis`] orders the whole of `Q` once. [`DirichletSolver::with_analysis`] then
//! factorises, for any constrained set, the matrix whose free rows and columns are `Q`'s and
//! whose constrained rows and columns are those of the identity (explicit zeros keep the
//! pattern): `Q_ff x_f = -Q_fc x_c` and `x_c = x_c`, the same solution as the reduced system,
//! with only the numeric factorisation and the solves left per selection.

use super::components::ensure_csr;
use super::structure::{analyse, fits_factor_index, split, Split, FREE};
use super::{DirichletSolver, FactorIndex, Factorization, SolverOptions};
use crate::mesh::MeshError;
use crate::operators::laplacian::ensure_finite;
use crate::operators::Result;
use faer::sparse::linalg::cholesky::SymbolicCholesky;
use faer::sparse::SymbolicSparseColMatRef;
use sprs::CsMat;
use std::sync::Arc;

/// In `ff_src` / `fc_src`: an entry that is 0 (off the diagonal of a constrained row).
const ZERO: usize = usize::MAX;
/// In `ff_src`: the 1 on the diagonal of a constrained row.
const ONE: usize = usize::MAX - 1;
/// In `fc_src`: the `-1` that puts the boundary value of a constrained row into its
/// right-hand side (`y = -sum Q_fc x_c`).
const MINUS_ONE: usize = usize::MAX - 2;

/// The value of an entry whose source is `k` (an index into `Q`'s values or a sentinel).
#[inline]
pub(super) fn value(data: &[f64], k: usize) -> f64 {
    match k {
        ZERO => 0.0,
        ONE => 1.0,
        MINUS_ONE => -1.0,
        k => data[k],
    }
}

/// `Q` with its fill-reducing ordering and symbolic Cholesky factor, computed once and shared
/// by the solvers of every constrained set ([`DirichletSolver::with_analysis`]).
#[derive(Debug, Clone)]
pub struct SystemAnalysis {
    q: CsMat<f64>,
    /// Upper triangle of `Q`, compressed columns (column `v` holds rows `u <= v`), and the
    /// index of each entry in `Q`'s values.
    col_ptr: Vec<FactorIndex>,
    row_idx: Vec<FactorIndex>,
    src: Vec<usize>,
    symbolic: Arc<SymbolicCholesky<FactorIndex>>,
}

impl SystemAnalysis {
    /// Order and analyse `q` (square, symmetric, finite).
    ///
    /// # Errors
    /// [`MeshError::DimensionMismatch`] (not square), [`MeshError::Overflow`] (a non-finite
    /// entry), [`SolveError::Solver`](crate::operators::SolveError::Solver) when the analysis fails.
    pub fn new(q: &CsMat<f64>) -> Result<SystemAnalysis> {
        let n = q.rows();
        if q.cols() != n {
            return Err(MeshError::DimensionMismatch {
                what: "columns of the system matrix",
                expected: n,
                got: q.cols(),
            }
            .into());
        }
        let q = ensure_csr(q).into_owned();
        ensure_finite(&q, "system matrix row")?;
        let indptr = q.indptr().into_raw_storage().to_vec();
        fits_factor_index(n, q.nnz())?;
        let mut col_ptr = Vec::with_capacity(n + 1);
        let (mut row_idx, mut src) = (Vec::new(), Vec::new());
        col_ptr.push(0);
        for v in 0..n {
            for k in indptr[v]..indptr[v + 1] {
                let u = q.indices()[k];
                if u <= v {
                    // Below `n`, which fits (checked above), as does `q.nnz()`.
                    row_idx.push(u as FactorIndex);
                    src.push(k);
                }
            }
            col_ptr.push(row_idx.len() as FactorIndex);
        }
        let sym = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        // Each selection factorises and solves once: the supernodal layout.
        let symbolic = analyse(sym, Factorization::Supernodal)?;
        Ok(SystemAnalysis {
            q,
            col_ptr,
            row_idx,
            src,
            symbolic: Arc::new(symbolic),
        })
    }

    /// Rows (and columns) of the matrix.
    pub fn len(&self) -> usize {
        self.q.rows()
    }

    /// Whether the matrix is empty.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The matrix analysed.
    pub fn matrix(&self) -> &CsMat<f64> {
        &self.q
    }
}

impl DirichletSolver {
    /// [`DirichletSolver::new`] for the analysed matrix, reusing its symbolic analysis: only
    /// the numeric factorisation is computed (see [`SystemAnalysis`]). Solves and
    /// accessors behave as for a solver from [`DirichletSolver::new`].
    ///
    /// # Errors
    /// As [`DirichletSolver::new`].
    pub fn with_analysis(
        analysis: &SystemAnalysis,
        constrained: &[u32],
        options: SolverOptions,
    ) -> Result<DirichletSolver> {
        let q = &analysis.q;
        let n = q.rows();
        let Split {
            slot,
            indptr,
            indices,
            free,
        } = split(q, constrained, options)?;
        // The full pattern, constrained rows and columns masked to the identity.
        let mut ff_src = analysis.src.clone();
        for (v, span) in analysis.col_ptr.windows(2).enumerate() {
            let span = span[0] as usize..span[1] as usize;
            let rows = &analysis.row_idx[span.clone()];
            for (src, &u) in ff_src[span].iter_mut().zip(rows) {
                if slot[u as usize] != FREE || slot[v] != FREE {
                    *src = if u as usize == v { ONE } else { ZERO };
                }
            }
        }
        // Q_fc by rows; a constrained row gets its own boundary value (through -(-1)).
        let mut fc_ptr = Vec::with_capacity(n + 1);
        let (mut fc_col, mut fc_src) = (Vec::new(), Vec::new());
        fc_ptr.push(0);
        for v in 0..n {
            if slot[v] == FREE {
                let row = indptr[v]..indptr[v + 1];
                for (k, &u) in row.clone().zip(&indices[row]) {
                    if slot[u] != FREE {
                        fc_col.push(slot[u]);
                        fc_src.push(k);
                    }
                }
            } else {
                fc_col.push(slot[v]);
                fc_src.push(MINUS_ONE);
            }
            fc_ptr.push(fc_col.len());
        }
        let mut s = DirichletSolver {
            n,
            options,
            constrained: constrained.to_vec(),
            free,
            q_indptr: indptr,
            q_indices: indices,
            ff_col_ptr: analysis.col_ptr.clone(),
            ff_row_idx: analysis.row_idx.clone(),
            ff_values: vec![0.0; ff_src.len()],
            ff_src,
            fc_ptr,
            fc_values: vec![0.0; fc_src.len()],
            fc_col,
            fc_src,
            symbolic: Arc::clone(&analysis.symbolic),
            l_values: Vec::new(),
            unknowns: Some((0..n as u32).collect()),
        };
        s.fill_values(q.data());
        s.factorize()?;
        Ok(s)
    }
}
