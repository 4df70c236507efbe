//! The mesh foundation's error: bad files, bad meshes, bad index lists, numbers out of range.

use std::fmt;
use std::path::PathBuf;

/// A list of vertex (or face) indices carried by an error; its `Display` shows at most ten.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct IndexList(pub Vec<u32>);

impl fmt::Display for IndexList {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const SHOWN: usize = 10;
        write!(f, "[")?;
        for (k, i) in self.0.iter().take(SHOWN).enumerate() {
            if k > 0 {
                write!(f, ", ")?;
            }
            write!(f, "{i}")?;
        }
        if self.0.len() > SHOWN {
            write!(f, ", ... ({} in all)", self.0.len())?;
        }
        write!(f, "]")
    }
}

impl From<Vec<u32>> for IndexList {
    fn from(v: Vec<u32>) -> Self {
        IndexList(v)
    }
}

/// What can go wrong in the mesh foundation: reading files, bad meshes (with the offending
/// indices), index lists that do not fit the mesh, quantities out of range.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// The file could not be opened or read.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The file's content is malformed.
    #[error("{path}:{line}: {message}")]
    Parse {
        /// The file (or `<memory>`).
        path: String,
        /// 1-based line number (0 when not line-oriented).
        line: usize,
        /// What was wrong.
        message: String,
    },
    /// The file extension is not one of the known mesh formats.
    #[error("unsupported mesh file extension {0:?} (known: obj, off, mesh)")]
    UnsupportedFormat(String),
    /// The mesh has no vertices or no triangles.
    #[error("the mesh is empty ({vertices} vertices, {triangles} triangles)")]
    EmptyMesh {
        /// Number of vertices.
        vertices: usize,
        /// Number of triangles.
        triangles: usize,
    },
    /// Triangles refer to vertices that do not exist.
    #[error("triangles {faces} refer to vertices outside 0..{vertex_count}")]
    FaceIndexOutOfRange {
        /// Offending triangles.
        faces: IndexList,
        /// Number of vertices of the mesh.
        vertex_count: usize,
    },
    /// Vertices with NaN or infinite coordinates.
    #[error("vertices {vertices} have non-finite coordinates")]
    NonFinite {
        /// Offending vertices.
        vertices: IndexList,
    },
    /// Edges shared by more than two triangles, or vertices whose triangles form several fans.
    #[error("non-manifold mesh: {}", non_manifold(vertices, edge_vertices))]
    NonManifold {
        /// Non-manifold vertices (bow-ties).
        vertices: IndexList,
        /// Endpoints of edges with more than two triangles.
        edge_vertices: IndexList,
    },
    /// Triangles whose area is (numerically) zero, where the caller asked for an error.
    #[error("degenerate (zero-area) triangles {faces}")]
    DegenerateTriangles {
        /// Offending triangles.
        faces: IndexList,
    },
    /// Constraint (handle or fixed) indices outside the mesh.
    #[error(
        "constraint vertices {vertices} are out of range (the mesh has {vertex_count} vertices)"
    )]
    ConstraintOutOfRange {
        /// Offending indices.
        vertices: IndexList,
        /// Number of vertices of the mesh.
        vertex_count: usize,
    },
    /// A vertex appears in two constraint sets (or twice in one).
    #[error("vertices {vertices} appear in more than one constraint set (or twice)")]
    OverlappingConstraints {
        /// Offending vertices.
        vertices: IndexList,
    },
    /// Sizes of inputs do not match.
    #[error("dimension mismatch for {what}: expected {expected}, got {got}")]
    DimensionMismatch {
        /// Which input.
        what: &'static str,
        /// Expected length.
        expected: usize,
        /// Actual length.
        got: usize,
    },
    /// Vertices asked for after [`clean()`](crate::mesh::validate::clean) removed them (they were unreferenced).
    #[error("vertices {vertices} were removed by cleaning (unreferenced)")]
    RemovedVertices {
        /// Offending (original) indices.
        vertices: IndexList,
    },
    /// A computed quantity left the `f64` range (overflow to infinity or NaN, or underflow to
    /// zero where zero is invalid); rescale the input.
    #[error(
        "{what} at index {index} is outside the floating-point range (overflow); rescale the input"
    )]
    Overflow {
        /// What was computed.
        what: &'static str,
        /// Row, vertex or triangle where it happened.
        index: usize,
    },
    /// Vertices with a coordinate beyond [`MAX_COORDINATE`](crate::mesh::validate::MAX_COORDINATE) in magnitude,
    /// where edge vectors could overflow.
    #[error(
        "vertices {vertices} have coordinates beyond +-{limit:e} (edge vectors would overflow)"
    )]
    CoordinateRange {
        /// Offending vertices.
        vertices: IndexList,
        /// The largest usable magnitude.
        limit: f64,
    },
    /// Parameters outside their domain.
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
}

/// `Result` with [`MeshError`].
pub type Result<T, E = MeshError> = std::result::Result<T, E>;

/// What a non-manifold mesh has, naming only the kinds it has.
fn non_manifold(vertices: &IndexList, edge_vertices: &IndexList) -> String {
    let mut parts = Vec::new();
    if !vertices.0.is_empty() {
        parts.push(format!(
            "vertices whose triangles form several fans {vertices}"
        ));
    }
    if !edge_vertices.0.is_empty() {
        parts.push(format!(
            "edges of more than two triangles, touching vertices {edge_vertices}"
        ));
    }
    parts.join("; ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_manifold_names_only_what_the_mesh_has() {
        let edges = MeshError::NonManifold {
            vertices: IndexList(vec![]),
            edge_vertices: IndexList(vec![1, 4]),
        };
        assert_eq!(
            edges.to_string(),
            "non-manifold mesh: edges of more than two triangles, touching vertices [1, 4]"
        );
        let both = MeshError::NonManifold {
            vertices: IndexList(vec![7]),
            edge_vertices: IndexList(vec![1, 4]),
        };
        assert!(
            both.to_string().contains("several fans [7]; edges"),
            "{both}"
        );
    }
}
