//! Object File Format (`OFF`, also `COFF`/`NOFF` headers; extra per-vertex values ignored).

use super::{capacity, push_fan, read_text, Ctx};
use crate::mesh::Mesh;
use crate::mesh::Result;
use glam::DVec3;
use std::path::Path;

/// Reads an OFF file; see [`parse_off`].
pub fn read_off(path: impl AsRef<Path>) -> Result<Mesh> {
    let path = path.as_ref();
    parse_off(&read_text(path)?, &path.display().to_string())
}

/// Parses OFF text: a header line (`OFF`, possibly followed by the counts), the counts
/// `V F E`, `V` vertex lines, then `F` face lines `n i_0 .. i_{n-1}` (0-based, polygons are
/// fan-triangulated, trailing colour values ignored). `#` starts a comment. Coordinates
/// must be finite; indices past the last vertex are kept and reported by
/// [`crate::mesh::validate::validate()`].
///
/// ```
/// let m = deform::mesh::io::parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "tri").unwrap();
/// assert_eq!((m.vertex_count(), m.triangles), (3, vec![[0, 1, 2]]));
/// ```
pub fn parse_off(text: &str, name: &str) -> Result<Mesh> {
    // Non-empty, comment-stripped lines with their numbers.
    let mut lines = text.lines().enumerate().filter_map(|(i, l)| {
        let l = l.split('#').next().unwrap_or("").trim();
        (!l.is_empty()).then_some((i + 1, l))
    });
    let mut ctx = Ctx { name, line: 0 };
    let (ln, header) = lines.next().ok_or_else(|| ctx.err("empty file"))?;
    ctx.line = ln;
    let mut toks = header.split_ascii_whitespace();
    let magic = toks.next().unwrap_or("");
    if !magic.ends_with("OFF") {
        return Err(ctx.err(format!("expected an OFF header, found {magic:?}")));
    }
    let rest: Vec<&str> = toks.collect();
    let counts: Vec<&str> = if rest.is_empty() {
        let (ln, l) = lines.next().ok_or_else(|| ctx.err("missing counts"))?;
        ctx.line = ln;
        l.split_ascii_whitespace().collect()
    } else {
        rest
    };
    let nv = ctx.usize(counts.first().copied(), "vertex count")?;
    let nf = ctx.usize(counts.get(1).copied(), "face count")?;
    let mut positions = Vec::with_capacity(capacity(nv, text.len()));
    for _ in 0..nv {
        let (ln, l) = lines
            .next()
            .ok_or_else(|| ctx.err("file ends inside the vertices"))?;
        ctx.line = ln;
        let mut t = l.split_ascii_whitespace();
        let x = ctx.f64(t.next(), "x coordinate")?;
        let y = ctx.f64(t.next(), "y coordinate")?;
        let z = ctx.f64(t.next(), "z coordinate")?;
        positions.push(DVec3::new(x, y, z));
    }
    let mut triangles = Vec::with_capacity(capacity(nf, text.len()));
    let mut poly = Vec::new();
    for _ in 0..nf {
        let (ln, l) = lines
            .next()
            .ok_or_else(|| ctx.err("file ends inside the faces"))?;
        ctx.line = ln;
        let mut t = l.split_ascii_whitespace();
        let k = ctx.usize(t.next(), "corner count")?;
        if k < 3 {
            return Err(ctx.err(format!("face with {k} corners")));
        }
        poly.clear();
        for _ in 0..k {
            poly.push(ctx.index0(t.next(), "vertex index")?);
        }
        push_fan(&poly, &mut triangles);
    }
    Ok(Mesh {
        positions,
        triangles,
    })
}
