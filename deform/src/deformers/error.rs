//! The deformers' error: everything binding or posing a deformer can report.

use crate::blend::{BlendError, KeyError};
use crate::mesh::{IndexList, MeshError};
use crate::operators::SolveError;

/// Constraint sets ARAP cannot work with.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ArapError {
    /// Neither fixed nor handle vertices: the energy is invariant under rigid motions, so the
    /// system is singular.
    #[error("no fixed or handle vertices: the ARAP system is singular up to a rigid motion")]
    NoConstraints,
    /// Every vertex of a connected component is constrained: nothing is left to deform.
    #[error("every vertex of a connected component is fixed or in a handle, nothing is left to deform: vertices {vertices}")]
    NothingToDeform {
        /// The vertices of those components.
        vertices: IndexList,
    },
}

/// What is wrong with a cage.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CageError {
    /// Too few vertices or faces to enclose anything.
    #[error("the cage has {vertices} vertices and {faces} faces: at least 4 of each")]
    TooSmall {
        /// Vertices.
        vertices: usize,
        /// Faces.
        faces: usize,
    },
    /// Cage vertices that are not finite.
    #[error("cage vertices {vertices} are not finite")]
    NonFinite {
        /// The vertices.
        vertices: IndexList,
    },
    /// Faces with an index out of range or a repeated corner.
    #[error("cage faces {faces} have out-of-range or repeated corners")]
    BadFaces {
        /// The faces.
        faces: IndexList,
    },
    /// Edges on one face only: the cage has holes.
    #[error("the cage is open: boundary edges at vertices {vertices}")]
    Open {
        /// Endpoints of boundary edges.
        vertices: IndexList,
    },
    /// Edges shared by more than two faces.
    #[error("the cage is not manifold: edges shared by 3 or more faces at vertices {vertices}")]
    NonManifold {
        /// Endpoints of those edges.
        vertices: IndexList,
    },
    /// Faces that cross each other.
    #[error("the cage intersects itself: {pairs} pairs of faces cross, e.g. faces {} and {}", first[0], first[1])]
    SelfIntersecting {
        /// How many pairs cross.
        pairs: usize,
        /// The lowest crossing pair.
        first: [u32; 2],
    },
    /// Faces of (numerically) zero area.
    #[error("degenerate (zero-area) cage faces {faces}")]
    Degenerate {
        /// The faces.
        faces: IndexList,
    },
    /// Model vertices outside the cage.
    #[error("the cage does not enclose the model: {count} vertices outside (winding number down to {lowest:.3}), e.g. {vertices}")]
    NotEnclosing {
        /// How many.
        count: usize,
        /// The vertices.
        vertices: IndexList,
        /// The lowest winding number among them.
        lowest: f64,
    },
    /// A point whose coordinates could not be normalised.
    #[error("vertex {index}: the cage coordinates do not normalise")]
    Coordinates {
        /// The vertex.
        index: usize,
    },
    /// A harmonic-coordinate grid that cannot be built.
    #[error("harmonic grid: {0}")]
    Grid(String),
}

/// Which rule of [`FfdError::Dims`] `dims` breaks.
fn lattice_dims_problem(dims: &[usize; 3]) -> String {
    let max = crate::blend::MAX_KEYS;
    if dims.iter().any(|&d| d < 2) {
        return "every axis needs at least 2 control points".into();
    }
    match dims.iter().try_fold(1usize, |a, &d| a.checked_mul(d)) {
        Some(n) => format!("{n} control points, more than the {max} supported"),
        None => format!("more control points than the {max} supported"),
    }
}

/// Why the interval `min .. max` of [`FfdError::ZeroExtent`] is not a box side.
fn box_problem(min: f64, max: f64) -> &'static str {
    if !(min.is_finite() && max.is_finite()) {
        "not finite"
    } else if max < min {
        "inverted (its maximum below its minimum)"
    } else if max == min {
        "zero extent"
    } else {
        "an extent too large for double precision"
    }
}

/// What is wrong with a lattice or the mesh inside it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FfdError {
    /// An axis with fewer than 2 control points, or too many points in all.
    #[error("lattice {dims:?}: {}", lattice_dims_problem(dims))]
    Dims {
        /// Control points per axis.
        dims: [usize; 3],
    },
    /// The box has no extent (or is not finite) along an axis.
    #[error("lattice box {min} .. {max} along axis {axis}: {}; give a box", box_problem(*min, *max))]
    ZeroExtent {
        /// 0, 1 or 2.
        axis: usize,
        /// Lower bound.
        min: f64,
        /// Upper bound.
        max: f64,
    },
    /// A B-spline degree outside 1..=3.
    #[error("B-spline lattice degree {0}: 1, 2 or 3 are supported")]
    Degree(usize),
    /// A mesh vertex outside the lattice's box.
    #[error("vertex {vertex} at {position:?} lies outside the lattice box")]
    Outside {
        /// The vertex.
        vertex: usize,
        /// Its position.
        position: [f64; 3],
    },
}

/// What can go wrong binding or posing a deformer: the mesh and its systems, the keys, and
/// each deformer's own conditions. Lower layers' errors convert into it with `?`
/// (a [`SolveError::Mesh`] or [`BlendError::Mesh`] becomes [`DeformError::Mesh`]).
#[derive(Debug, thiserror::Error)]
pub enum DeformError {
    /// A bad mesh, file, index list or size (see [`MeshError`]).
    #[error(transparent)]
    Mesh(MeshError),
    /// A system that cannot be built or solved (see [`SolveError`]; never its `Mesh` case).
    #[error(transparent)]
    Solve(SolveError),
    /// Bad keys, handle sets or parameters.
    #[error(transparent)]
    Keys(#[from] KeyError),
    /// Constraint sets ARAP cannot work with.
    #[error(transparent)]
    Arap(#[from] ArapError),
    /// A bad FFD lattice, or a vertex outside it.
    #[error(transparent)]
    Ffd(#[from] FfdError),
    /// A bad cage, or one that does not enclose the model.
    #[error(transparent)]
    Cage(#[from] CageError),
}

impl From<MeshError> for DeformError {
    fn from(e: MeshError) -> Self {
        DeformError::Mesh(e)
    }
}

impl From<SolveError> for DeformError {
    fn from(e: SolveError) -> Self {
        match e {
            SolveError::Mesh(m) => DeformError::Mesh(m),
            e => DeformError::Solve(e),
        }
    }
}

impl From<BlendError> for DeformError {
    fn from(e: BlendError) -> Self {
        match e {
            BlendError::Keys(k) => DeformError::Keys(k),
            BlendError::Mesh(m) => DeformError::Mesh(m),
        }
    }
}

/// `Result` with [`DeformError`].
pub type Result<T, E = DeformError> = std::result::Result<T, E>;
