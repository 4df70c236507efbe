//! The operators' error: systems that cannot be built or solved.

use crate::mesh::{IndexList, MeshError};

/// The part of [`SolveError::Unconstrained`]'s message about single vertices.
fn isolated_note(isolated: usize) -> String {
    if isolated == 0 {
        return String::new();
    }
    format!(
        " ({isolated} of them single vertices without a weighted edge: unreferenced by the \
         triangles, or only in zero-area ones; `clean` drops unreferenced vertices)"
    )
}

/// What can go wrong building or solving a system on a mesh: the mesh's own errors
/// ([`SolveError::Mesh`]), components without constraints, a matrix that is not positive
/// definite, sizes beyond what can be stored.
#[derive(Debug, thiserror::Error)]
pub enum SolveError {
    /// The mesh, a file or an index list is bad (see [`MeshError`]).
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// The system is singular: some connected components contain no constrained vertex.
    #[error("singular system: {components} connected component(s) have no constrained vertex{}; unconstrained vertices {vertices}", isolated_note(*isolated))]
    Unconstrained {
        /// Number of unconstrained components.
        components: usize,
        /// How many of them are single vertices without a weighted edge: unreferenced by the
        /// triangles, or only in zero-area ones ([`crate::mesh::validate::clean()`] drops
        /// unreferenced vertices).
        isolated: usize,
        /// Vertices of those components.
        vertices: IndexList,
    },
    /// The reduced matrix is not numerically positive definite.
    #[error("the constrained system is not positive definite (factorisation failed: {0})")]
    NotPositiveDefinite(String),
    /// A matrix given to [`DirichletSolver::update_values`](crate::operators::solve::DirichletSolver::update_values) has a different sparsity pattern.
    #[error("the matrix's sparsity pattern differs from the one the solver was built with")]
    PatternChanged,
    /// Vertices with zero mass (only in degenerate triangles) where the mass is inverted.
    #[error("vertices {vertices} have zero mass")]
    ZeroMass {
        /// Offending vertices.
        vertices: IndexList,
    },
    /// Forming a matrix product would need too many nonzeros (e.g. `L M^-1 L` on a mesh with a
    /// vertex of huge valence, such as a fan-triangulated polygon with thousands of corners).
    #[error("{what} would have up to {estimated} nonzeros (limit {limit}); a vertex of very high valence makes it dense: split large polygons")]
    TooDense {
        /// Which matrix.
        what: &'static str,
        /// Upper bound of its nonzeros.
        estimated: usize,
        /// The limit.
        limit: usize,
    },
    /// A faer routine failed (out of memory, index overflow).
    #[error("sparse solver error: {0}")]
    Solver(String),
}

/// `Result` with [`SolveError`].
pub type Result<T, E = SolveError> = std::result::Result<T, E>;
