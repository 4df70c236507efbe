//! Wavefront OBJ: vertices (`v`) and faces (`f`); polygons are fan-triangulated.
//!
//! A small dedicated parser rather than `tobj`: `tobj` renumbers vertices in order of first
//! use and drops unreferenced ones, which would break per-vertex selection files (libigl DMAT)
//! and the vertex counts of raw scans.

use super::{push_fan, read_text, Ctx};
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::mesh::Result;
use glam::DVec3;
use std::io::Write;
use std::path::Path;

/// Reads an OBJ file; see [`parse_obj`].
pub fn read_obj(path: impl AsRef<Path>) -> Result<Mesh> {
    let path = path.as_ref();
    parse_obj(&read_text(path)?, &path.display().to_string())
}

/// Parses OBJ text. Vertices keep their file order (unreferenced ones included); face
/// corners may be `v`, `v/t`, `v//n` or `v/t/n`, with negative (relative) indices allowed;
/// polygons become triangle fans. Texture coordinates ([`parse_obj_textured`] reads them),
/// normals, groups, materials, lines and points are ignored. Coordinates must be finite. Indices past the last vertex are kept and
/// reported by [`crate::mesh::validate::validate()`].
///
/// ```
/// let m = deform::mesh::io::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "quad").unwrap();
/// assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3]]);
/// ```
pub fn parse_obj(text: &str, name: &str) -> Result<Mesh> {
    Ok(parse_obj_textured(text, name)?.0)
}

/// An OBJ file's texture coordinates, by face corner: OBJ indexes them apart from the
/// vertices, so a vertex on a UV seam has one per side.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ObjTexture {
    /// The `vt` lines (`u v`, OBJ's origin bottom left), in file order.
    pub uvs: Vec<[f64; 2]>,
    /// Per triangle of the parsed mesh (fans as [`parse_obj`] makes them), the `vt` index of
    /// each corner.
    pub corners: Vec<[u32; 3]>,
}

/// [`parse_obj`], and the texture coordinates of every face corner when every face has them
/// (in range); `None` when the file has none or some face lacks them.
pub fn parse_obj_textured(text: &str, name: &str) -> Result<(Mesh, Option<ObjTexture>)> {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    let mut poly: Vec<u32> = Vec::new();
    let mut uvs: Vec<[f64; 2]> = Vec::new();
    let mut corners: Vec<[u32; 3]> = Vec::new();
    let mut poly_uv: Vec<u32> = Vec::new();
    let mut textured = true;
    for (ln, line) in text.lines().enumerate() {
        let ctx = Ctx { name, line: ln + 1 };
        let mut toks = line.split_ascii_whitespace();
        match toks.next() {
            Some("v") => {
                let x = ctx.f64(toks.next(), "x coordinate")?;
                let y = ctx.f64(toks.next(), "y coordinate")?;
                let z = ctx.f64(toks.next(), "z coordinate")?;
                positions.push(DVec3::new(x, y, z));
            }
            Some("vt") => {
                let u = ctx.f64(toks.next(), "u texture coordinate")?;
                // A missing v is 0, as the format allows.
                let v = toks
                    .next()
                    .map_or(Ok(0.0), |t| ctx.f64(Some(t), "v texture coordinate"))?;
                uvs.push([u, v]);
            }
            Some("f") => {
                poly.clear();
                poly_uv.clear();
                for tok in toks {
                    let mut parts = tok.split('/');
                    let v = parts.next().unwrap_or("");
                    let i: i64 = v
                        .parse()
                        .map_err(|_| ctx.err(format!("bad face index {}", super::shown(tok))))?;
                    let idx = if i > 0 {
                        i - 1
                    } else if i < 0 {
                        positions.len() as i64 + i
                    } else {
                        return Err(ctx.err("face index 0 (OBJ indices start at 1)"));
                    };
                    let idx = u32::try_from(idx)
                        .map_err(|_| ctx.err(format!("face index {i} is out of range")))?;
                    poly.push(idx);
                    let t = parts.next().and_then(|t| t.parse::<i64>().ok());
                    let t = match t {
                        Some(t) if t > 0 => Some(t - 1),
                        Some(t) if t < 0 => Some(uvs.len() as i64 + t),
                        _ => None,
                    };
                    match t.and_then(|t| u32::try_from(t).ok()) {
                        Some(t) if (t as usize) < uvs.len() => poly_uv.push(t),
                        _ => textured = false,
                    }
                }
                if poly.len() < 3 {
                    return Err(ctx.err(format!("face with {} corners", poly.len())));
                }
                push_fan(&poly, &mut triangles);
                if textured {
                    push_fan(&poly_uv, &mut corners);
                }
            }
            _ => {}
        }
    }
    let texture = (textured && !uvs.is_empty() && corners.len() == triangles.len())
        .then_some(ObjTexture { uvs, corners });
    Ok((
        Mesh {
            positions,
            triangles,
        },
        texture,
    ))
}

/// Writes `v` and `f` lines (shortest round-trip decimal form) to a writer.
pub fn write_obj_to(mesh: &Mesh, mut w: impl Write) -> std::io::Result<()> {
    let mut buf = std::io::BufWriter::new(&mut w);
    for p in &mesh.positions {
        writeln!(buf, "v {} {} {}", p.x, p.y, p.z)?;
    }
    for t in &mesh.triangles {
        writeln!(buf, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1)?;
    }
    buf.flush()
}

/// What [`write_obj_with_to`] writes besides positions and faces: per-vertex texture
/// coordinates and normals, each indexed like the vertices.
#[derive(Clone, Copy, Debug, Default)]
pub struct ObjExtras<'a> {
    /// glTF-style UVs (origin top left), two per vertex: written as `vt u (1 - v)`, OBJ's
    /// origin being bottom left.
    pub uvs: Option<&'a [f32]>,
    /// Unit normals, one per vertex (`vn`).
    pub normals: Option<&'a [glam::DVec3]>,
    /// Texture coordinates by face corner, as an OBJ input had them (written as given, in
    /// place of `uvs`).
    pub texture: Option<&'a ObjTexture>,
}

/// Writes `v`, `vt`, `vn` and `f v/vt/vn` lines; `vt` and `vn` only where given (each
/// checked to have one entry per vertex: a mismatch is an `InvalidInput` error).
pub fn write_obj_with_to(mesh: &Mesh, extras: ObjExtras, mut w: impl Write) -> std::io::Result<()> {
    let n = mesh.positions.len();
    let bad = |what: &str, len: usize| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!("{len} {what} for {n} vertices"),
        )
    };
    if let Some(uv) = extras.uvs.filter(|uv| uv.len() != 2 * n) {
        return Err(bad("texture coordinates", uv.len() / 2));
    }
    if let Some(nr) = extras.normals.filter(|nr| nr.len() != n) {
        return Err(bad("normals", nr.len()));
    }
    if let Some(t) = extras.texture {
        let fits = t.corners.len() == mesh.triangles.len()
            && t.corners
                .iter()
                .flatten()
                .all(|&c| (c as usize) < t.uvs.len());
        if !fits {
            return Err(bad(
                "texture corners (or past the vt list)",
                t.corners.len(),
            ));
        }
    }
    let mut buf = std::io::BufWriter::new(&mut w);
    for p in &mesh.positions {
        writeln!(buf, "v {} {} {}", p.x, p.y, p.z)?;
    }
    if let Some(t) = extras.texture {
        for [u, v] in &t.uvs {
            writeln!(buf, "vt {u} {v}")?;
        }
    } else if let Some(uv) = extras.uvs {
        for t in uv.chunks_exact(2) {
            writeln!(buf, "vt {} {}", t[0], 1.0 - t[1])?;
        }
    }
    if let Some(nr) = extras.normals {
        for v in nr {
            writeln!(buf, "vn {} {} {}", v.x, v.y, v.z)?;
        }
    }
    let textured = extras.uvs.is_some() || extras.texture.is_some();
    let normals = extras.normals.is_some();
    for (f, t) in mesh.triangles.iter().enumerate() {
        // The texture index of a corner: its own (OBJ input) or the vertex's.
        let c = extras.texture.map_or(*t, |x| x.corners[f]);
        buf.write_all(b"f")?;
        for (v, t) in t.iter().zip(c).map(|(v, t)| (v + 1, t + 1)) {
            match (textured, normals) {
                (false, false) => write!(buf, " {v}")?,
                (true, false) => write!(buf, " {v}/{t}")?,
                (false, true) => write!(buf, " {v}//{v}")?,
                (true, true) => write!(buf, " {v}/{t}/{v}")?,
            }
        }
        buf.write_all(b"\n")?;
    }
    buf.flush()
}

/// Writes an OBJ file.
pub fn write_obj(mesh: &Mesh, path: impl AsRef<Path>) -> Result<()> {
    let path = path.as_ref();
    let io = |source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::create(path).map_err(io)?;
    write_obj_to(mesh, file).map_err(io)
}
