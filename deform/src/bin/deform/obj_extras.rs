//! What an OBJ input had beside positions and faces, kept for a deformed OBJ output.

use deform::Mesh;
use std::path::Path;

/// What an OBJ input had beside positions and faces: its texture coordinates by face corner,
/// and whether it had normals. A deformed OBJ output keeps the first and recomputes the
/// second.
#[derive(Clone, Debug, Default)]
pub struct ObjInputExtras {
    pub texture: Option<deform::mesh::io::ObjTexture>,
    pub normals: bool,
}

impl ObjInputExtras {
    /// The mesh of `path`, as `deform::mesh::io::read_mesh` reads it (same formats and errors), with
    /// the extras of an OBJ file (none for the other formats), from one read of the file.
    pub fn read_with_mesh(path: &Path) -> deform::mesh::Result<(Mesh, ObjInputExtras)> {
        let obj = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("obj"));
        if !obj {
            return Ok((
                deform::mesh::io::read_mesh(path)?,
                ObjInputExtras::default(),
            ));
        }
        let name = path.display().to_string();
        let bytes = deform::mesh::io::read_limited(path, deform::mesh::io::MAX_FILE_BYTES)
            .map_err(|source| deform::mesh::MeshError::Io {
                path: path.to_path_buf(),
                source,
            })?;
        let Ok(text) = std::str::from_utf8(&bytes) else {
            // The library's own message for bytes that are not text.
            let mesh = deform::mesh::io::parse_mesh(&bytes, &name)?;
            return Ok((mesh, ObjInputExtras::default()));
        };
        let (mesh, texture) = deform::mesh::io::parse_obj_textured(text, &name)?;
        let normals = text.lines().any(|l| l.starts_with("vn "));
        Ok((mesh, ObjInputExtras { texture, normals }))
    }
}
