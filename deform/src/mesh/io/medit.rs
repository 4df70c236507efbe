//! INRIA MEDIT meshes (`.mesh`, ASCII): vertices, triangles, tetrahedra.

use super::{capacity, read_text, Ctx};
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::mesh::Result;
use glam::DVec3;
use std::path::Path;

/// The content of a MEDIT file (0-based indices; reference labels dropped).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MeditMesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// The `Triangles` section (for a tet mesh: its boundary surface).
    pub triangles: Vec<[u32; 3]>,
    /// The `Tetrahedra` section.
    pub tetrahedra: Vec<[u32; 4]>,
}

impl MeditMesh {
    /// The triangle surface (all vertices kept, so interior tet vertices are unreferenced).
    pub fn surface(self) -> Mesh {
        Mesh {
            positions: self.positions,
            triangles: self.triangles,
        }
    }
}

/// Reads a MEDIT file; see [`parse_medit`].
pub fn read_medit(path: impl AsRef<Path>) -> Result<MeditMesh> {
    let path = path.as_ref();
    parse_medit(&read_text(path)?, &path.display().to_string())
}

/// Parses ASCII MEDIT: `MeshVersionFormatted`, `Dimension 3`, then sections `Vertices`,
/// `Triangles`, `Quadrilaterals` (split into two triangles), `Tetrahedra`, `Edges`, each a
/// count followed by entries with a trailing reference label; `End` stops. Coordinates must
/// be finite and tetrahedra must refer to existing vertices (nothing else checks them);
/// triangle indices past the last vertex are kept and reported by [`crate::mesh::validate::validate()`].
///
/// ```
/// let t = "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\n0 1 0 0\nTriangles\n1\n1 2 3 0\nEnd\n";
/// let m = deform::mesh::io::parse_medit(t, "t").unwrap();
/// assert_eq!(m.triangles, vec![[0, 1, 2]]);
/// ```
pub fn parse_medit(text: &str, name: &str) -> Result<MeditMesh> {
    // Tokens with their line numbers, comments stripped.
    let toks = text.lines().enumerate().flat_map(|(i, l)| {
        l.split('#')
            .next()
            .unwrap_or("")
            .split_ascii_whitespace()
            .map(move |t| (i + 1, t))
    });
    let mut t = Tokens {
        it: toks,
        ctx: Ctx { name, line: 0 },
    };
    let mut out = MeditMesh::default();
    let mut dim = 3usize;
    while let Some(kw) = t.next() {
        match kw {
            "MeshVersionFormatted" => {
                t.usize("version")?;
            }
            "Dimension" => {
                dim = t.usize("dimension")?;
                if dim != 2 && dim != 3 {
                    return Err(t.ctx.err(format!("dimension {dim}")));
                }
            }
            "Vertices" => {
                let n = t.usize("vertex count")?;
                out.positions.reserve(capacity(n, text.len()));
                for _ in 0..n {
                    let x = t.f64("x coordinate")?;
                    let y = t.f64("y coordinate")?;
                    let z = if dim == 3 {
                        t.f64("z coordinate")?
                    } else {
                        0.0
                    };
                    t.f64("reference")?;
                    out.positions.push(DVec3::new(x, y, z));
                }
            }
            "Triangles" | "Quadrilaterals" | "Tetrahedra" | "Edges" => {
                let k = match kw {
                    "Triangles" => 3,
                    "Quadrilaterals" | "Tetrahedra" => 4,
                    _ => 2,
                };
                let n = t.usize("element count")?;
                for _ in 0..n {
                    let mut e = [0u32; 4];
                    for slot in e.iter_mut().take(k) {
                        *slot = t.index1("vertex index")?;
                    }
                    t.f64("reference")?;
                    match kw {
                        "Triangles" => out.triangles.push([e[0], e[1], e[2]]),
                        "Quadrilaterals" => {
                            out.triangles.push([e[0], e[1], e[2]]);
                            out.triangles.push([e[0], e[2], e[3]]);
                        }
                        "Tetrahedra" => out.tetrahedra.push(e),
                        _ => {}
                    }
                }
            }
            "End" => break,
            other => return Err(t.ctx.err(format!("unsupported MEDIT keyword {other:?}"))),
        }
    }
    let n = out.positions.len();
    if let Some(k) = out
        .tetrahedra
        .iter()
        .position(|e| e.iter().any(|&v| v as usize >= n))
    {
        return Err(MeshError::Parse {
            path: name.to_string(),
            line: 0,
            message: format!(
                "tetrahedron {k} refers to vertex {} but there are {n} vertices",
                out.tetrahedra[k].iter().max().map_or(0, |&v| v as u64 + 1)
            ),
        });
    }
    Ok(out)
}

/// A token stream that tracks the current line for error messages.
struct Tokens<'a, I> {
    it: I,
    ctx: Ctx<'a>,
}

impl<'a, I: Iterator<Item = (usize, &'a str)>> Tokens<'a, I> {
    fn next(&mut self) -> Option<&'a str> {
        let (l, tok) = self.it.next()?;
        self.ctx.line = l;
        Some(tok)
    }

    fn usize(&mut self, what: &str) -> Result<usize> {
        let tok = self.next();
        self.ctx.usize(tok, what)
    }

    fn f64(&mut self, what: &str) -> Result<f64> {
        let tok = self.next();
        self.ctx.f64(tok, what)
    }

    fn index1(&mut self, what: &str) -> Result<u32> {
        let tok = self.next();
        self.ctx.index1(tok, what)
    }
}
