//! What an OBJ input had beside positions and faces, kept for a deformed OBJ output.

use crate::mesh::{Mesh, MeshError, Result};
use std::path::Path;

/// What an OBJ input had beside positions and faces: its texture coordinates by face corner,
/// and whether it had normals. A deformed OBJ output keeps the first and recomputes the
/// second.
#[derive(Clone, Debug, Default)]
pub struct ObjInputExtras {
    /// Texture coordinates by face corner, as the file gave them.
    pub texture: Option<super::ObjTexture>,
    /// Whether the file had normals (`vn`).
    pub normals: bool,
}

impl ObjInputExtras {
    /// The mesh of `path`, as [`super::read_mesh`] reads it (same formats and errors), with
    /// the extras of an OBJ file (none for the other formats), from one read of the file.
    pub fn read_with_mesh(path: &Path) -> Result<(Mesh, ObjInputExtras)> {
        let obj = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("obj"));
        if !obj {
            return Ok((super::read_mesh(path)?, ObjInputExtras::default()));
        }
        let name = path.display().to_string();
        let bytes =
            super::read_limited(path, super::MAX_FILE_BYTES).map_err(|source| MeshError::Io {
                path: path.to_path_buf(),
                source,
            })?;
        let Ok(text) = std::str::from_utf8(&bytes) else {
            // The library's own message for bytes that are not text.
            let mesh = super::parse_mesh(&bytes, &name)?;
            return Ok((mesh, ObjInputExtras::default()));
        };
        let (mesh, texture) = super::parse_obj_textured(text, &name)?;
        let normals = text.lines().any(|l| l.starts_with("vn "));
        Ok((mesh, ObjInputExtras { texture, normals }))
    }
}
