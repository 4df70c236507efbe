//! Mesh and matrix files: OBJ (read, write), PLY (write), OFF, MEDIT `.mesh`, libigl DMAT and
//! TGF; [`read_mesh`] reads and [`write_mesh_to`] writes by the file name's extension.

mod bounded;
mod dmat;
mod medit;
mod obj;
mod obj_input;
mod off;
mod ply;
mod tgf;
mod write;

pub use bounded::{is_device, read_limited, MAX_FILE_BYTES};
pub use dmat::{parse_dmat, read_dmat, write_dmat, Dmat};
pub use medit::{parse_medit, read_medit, MeditMesh};
mod glb;
pub use glb::{glb_bytes, write_glb};
pub(crate) use glb::{unit_normals, GlbBuilder};
pub use obj::{
    parse_obj, parse_obj_textured, read_obj, write_obj, write_obj_to, write_obj_with_to, ObjExtras,
    ObjTexture,
};
pub use obj_input::ObjInputExtras;
pub use off::{parse_off, read_off};
pub use ply::{ply_header, write_ply, write_ply_to};
pub use tgf::{parse_tgf, read_tgf, Skeleton};
pub use write::{write_mesh_to, MeshFormat};

use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::mesh::Result;
use std::path::Path;

/// Reads a triangle mesh, choosing the format by extension (`obj`, `off`, `mesh`; any case).
///
/// Polygons are fan-triangulated; for MEDIT files the `Triangles` section is returned. Every
/// reader of this module takes files (and pipes) of at most [`MAX_FILE_BYTES`]; a larger one
/// is [`MeshError::Io`] of kind [`std::io::ErrorKind::FileTooLarge`].
pub fn read_mesh(path: impl AsRef<Path>) -> Result<Mesh> {
    let path = path.as_ref();
    let name = path.display().to_string();
    match extension(&name).as_str() {
        "obj" | "off" | "mesh" => parse_mesh(&read_bytes(path)?, &name),
        ext => Err(MeshError::UnsupportedFormat(ext.into())),
    }
}

/// Parses the bytes of a mesh file named `name` (an upload, say), choosing the format by the
/// name's extension as [`read_mesh`] does; the bytes must be UTF-8 text.
///
/// ```
/// let m = deform::mesh::io::parse_mesh(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tri.OBJ").unwrap();
/// assert_eq!(m.triangles, vec![[0, 1, 2]]);
/// assert!(deform::mesh::io::parse_mesh(b"", "tri.stl").is_err());
/// ```
pub fn parse_mesh(bytes: &[u8], name: &str) -> Result<Mesh> {
    let ext = extension(name);
    if !matches!(ext.as_str(), "obj" | "off" | "mesh") {
        return Err(MeshError::UnsupportedFormat(ext));
    }
    let text = std::str::from_utf8(bytes).map_err(|e| MeshError::Parse {
        path: name.to_string(),
        line: 0,
        message: format!("not UTF-8: {e}"),
    })?;
    match ext.as_str() {
        "obj" => parse_obj(text, name),
        "off" => parse_off(text, name),
        _ => Ok(parse_medit(text, name)?.surface()),
    }
}

/// The lowercase extension of a file name (empty without one).
fn extension(name: &str) -> String {
    Path::new(name)
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase()
}

pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>> {
    read_limited(path, MAX_FILE_BYTES).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    })
}

pub(crate) fn read_text(path: &Path) -> Result<String> {
    let bytes = read_bytes(path)?;
    String::from_utf8(bytes).map_err(|e| MeshError::Parse {
        path: path.display().to_string(),
        line: 0,
        message: format!("not UTF-8: {e}"),
    })
}

/// Parse-error helper carrying the source name and the current line.
#[derive(Clone, Copy)]
pub(crate) struct Ctx<'a> {
    pub name: &'a str,
    pub line: usize,
}

impl Ctx<'_> {
    pub(crate) fn err(&self, message: impl Into<String>) -> MeshError {
        MeshError::Parse {
            path: self.name.to_string(),
            line: self.line,
            message: message.into(),
        }
    }

    /// A finite number: NaN, infinities and values that overflow (`1e400`) are errors.
    pub(crate) fn f64(&self, tok: Option<&str>, what: &str) -> Result<f64> {
        let tok = tok.ok_or_else(|| self.err(format!("missing {what}")))?;
        let x = tok
            .parse::<f64>()
            .map_err(|_| self.err(format!("bad {what} {}", shown(tok))))?;
        if x.is_finite() {
            return Ok(x);
        }
        // Written as an infinity (or NaN), or a number past the range ("1e400").
        if x.is_nan() || tok.bytes().any(|b| b.eq_ignore_ascii_case(&b'i')) {
            Err(self.err(format!("non-finite {what} {}", shown(tok))))
        } else {
            Err(self.err(format!("{what} {} overflows f64", shown(tok))))
        }
    }

    pub(crate) fn usize(&self, tok: Option<&str>, what: &str) -> Result<usize> {
        let tok = tok.ok_or_else(|| self.err(format!("missing {what}")))?;
        tok.parse::<usize>()
            .map_err(|_| self.err(format!("bad {what} {}", shown(tok))))
    }

    /// A 1-based index converted to 0-based `u32`.
    pub(crate) fn index1(&self, tok: Option<&str>, what: &str) -> Result<u32> {
        let i = self.usize(tok, what)?;
        if i == 0 || i > u32::MAX as usize {
            return Err(self.err(format!("{what} {i} is not a valid 1-based index")));
        }
        Ok((i - 1) as u32)
    }

    /// A 0-based index as `u32`.
    pub(crate) fn index0(&self, tok: Option<&str>, what: &str) -> Result<u32> {
        let i = self.usize(tok, what)?;
        u32::try_from(i).map_err(|_| self.err(format!("{what} {i} is too large")))
    }
}

/// A token as an error message shows it: quoted, and cut after 40 characters (a line of a
/// hundred thousand digits is named, not printed).
pub(crate) fn shown(tok: &str) -> String {
    const MAX: usize = 40;
    match tok.char_indices().nth(MAX) {
        None => format!("{tok:?}"),
        Some((cut, _)) => format!("{:?}... ({} bytes)", &tok[..cut], tok.len()),
    }
}

/// A capacity to reserve for `count` items announced by a file of `len` bytes: never more
/// items than bytes, so a lying header cannot make us allocate gigabytes up front.
pub(crate) fn capacity(count: usize, len: usize) -> usize {
    count.min(len)
}

/// Appends the fan triangulation of a polygon.
pub(crate) fn push_fan(poly: &[u32], out: &mut Vec<[u32; 3]>) {
    for k in 1..poly.len().saturating_sub(1) {
        out.push([poly[0], poly[k], poly[k + 1]]);
    }
}
