//! What an OBJ input had beside positions and faces, kept for a deformed OBJ output.

use std::path::Path;

/// What an OBJ input had beside positions and faces: its texture coordinates by face corner,
/// and whether it had normals. A deformed OBJ output keeps the first and recomputes the
/// second.
#[derive(Clone, Debug, Default)]
pub struct ObjInputExtras {
    pub texture: Option<deform::io::ObjTexture>,
    pub normals: bool,
}

impl ObjInputExtras {
    /// Read them from an OBJ file (none for other formats or unreadable files: the mesh
    /// itself was read and checked before).
    pub fn read(path: &Path) -> ObjInputExtras {
        let obj = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("obj"));
        let text = obj
            .then(|| deform::io::read_limited(path, deform::io::MAX_FILE_BYTES).ok())
            .flatten()
            .and_then(|b| String::from_utf8(b).ok());
        let Some(text) = text else {
            return ObjInputExtras::default();
        };
        let texture = deform::io::parse_obj_textured(&text, "")
            .ok()
            .and_then(|(_, t)| t);
        let normals = text.lines().any(|l| l.starts_with("vn "));
        ObjInputExtras { texture, normals }
    }
}
