//! Writing a mesh in the format its file name's extension names, next to [`super::read_mesh`]
//! which reads by extension: OBJ (with texture coordinates and normals when given), binary
//! PLY, or a static binary glTF with smooth normals.

use super::{glb_bytes, write_obj_with_to, write_ply_to, ObjExtras};
use crate::mesh::validate::check_elements;
use crate::mesh::{Mesh, MeshError, Result};
use std::io::Write;
use std::path::Path;

/// A format a mesh is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    /// Wavefront OBJ (text).
    Obj,
    /// Binary little-endian PLY.
    Ply,
    /// A static binary glTF (`.glb`) with smooth normals.
    Glb,
}

impl MeshFormat {
    /// The extensions of the formats (lowercase).
    pub const EXTENSIONS: [&'static str; 3] = ["obj", "glb", "ply"];

    /// The format `path`'s extension names (any case), or `None` for another extension.
    ///
    /// ```
    /// use deform::mesh::io::MeshFormat;
    /// assert_eq!(MeshFormat::from_path("a/b.PLY"), Some(MeshFormat::Ply));
    /// assert_eq!(MeshFormat::from_path("b.stl"), None);
    /// ```
    pub fn from_path(path: impl AsRef<Path>) -> Option<MeshFormat> {
        let ext = path.as_ref().extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "obj" => Some(MeshFormat::Obj),
            "glb" => Some(MeshFormat::Glb),
            "ply" => Some(MeshFormat::Ply),
            _ => None,
        }
    }
}

/// Write `mesh` as `format` to `w`, the vertex order and count as given; `extras` (texture
/// coordinates, normals) go into an OBJ and are ignored by the other formats. A mesh with an
/// index out of range, a non-finite vertex or one beyond
/// [`MAX_COORDINATE`](crate::mesh::validate::MAX_COORDINATE) (which no reader here takes back)
/// is an error before anything is written.
///
/// ```
/// use deform::mesh::io::{write_mesh_to, MeshFormat, ObjExtras};
/// use deform::Mesh;
/// use glam::DVec3;
/// let tri = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
/// let mut obj = Vec::new();
/// write_mesh_to(&tri, MeshFormat::Obj, ObjExtras::default(), &mut obj).unwrap();
/// assert!(String::from_utf8(obj).unwrap().contains("f 1 2 3"));
/// let bad = Mesh::new(vec![DVec3::NAN, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
/// let mut ply = Vec::new();
/// assert!(write_mesh_to(&bad, MeshFormat::Ply, ObjExtras::default(), &mut ply).is_err());
/// assert!(ply.is_empty());
/// ```
pub fn write_mesh_to(
    mesh: &Mesh,
    format: MeshFormat,
    extras: ObjExtras,
    mut w: impl Write,
) -> Result<()> {
    check_elements(mesh)?;
    let io = |source| MeshError::Io {
        path: "the output".into(),
        source,
    };
    match format {
        MeshFormat::Obj => write_obj_with_to(mesh, extras, w).map_err(io),
        MeshFormat::Ply => write_ply_to(mesh, w).map_err(io),
        MeshFormat::Glb => w.write_all(&glb_bytes(mesh)?).map_err(io),
    }
}
