//! The caller-owned workspace of a solve.

use faer::dyn_stack::MemBuffer;

/// Workspace of [`DirichletSolver::solve_into`](super::DirichletSolver::solve_into), from
/// [`DirichletSolver::scratch`](super::DirichletSolver::scratch).
pub struct SolveScratch {
    /// The reduced right-hand sides / free unknowns, `free x ncols`.
    pub(super) y: Vec<f64>,
    /// faer's triangular-solve workspace.
    pub(super) mem: MemBuffer,
    /// Free rows of the solver it was made for.
    pub(super) free: usize,
    /// Most columns it holds.
    pub(super) ncols: usize,
    /// Size and alignment of `mem`.
    pub(super) size: usize,
    pub(super) align: usize,
}

impl std::fmt::Debug for SolveScratch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SolveScratch")
            .field("free", &self.free)
            .field("ncols", &self.ncols)
            .field("bytes", &self.size)
            .finish()
    }
}

impl SolveScratch {
    /// The most columns one solve may have with this scratch.
    pub fn columns(&self) -> usize {
        self.ncols
    }
}
