//! What a model looks like, kept from its glTF file so that a written `.glb` looks the same:
//! its per-vertex attributes (UVs, colours, normals...) and its materials, textures, images and
//! samplers. Vertices made by surgery get their attributes interpolated from their sources, as
//! their weights were ([`VertexAttribute::interpolated`]).

use super::influences::Influences;
use glam::DVec3;
use serde_json::Value;

/// One per-vertex attribute of a glTF primitive, by its semantic name (`TEXCOORD_0`,
/// `COLOR_0`, `NORMAL`, `_CUSTOM`...), over every vertex of [`super::Rig::mesh`].
#[derive(Clone, Debug, PartialEq)]
pub struct VertexAttribute {
    /// The glTF semantic.
    pub name: String,
    /// Components per vertex (2 for UVs, 3 or 4 for colours).
    pub width: usize,
    /// `width` values per vertex.
    pub values: Vec<f32>,
}

impl VertexAttribute {
    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.values.len() / self.width.max(1)
    }

    /// Vertex `v`'s values.
    pub fn row(&self, v: usize) -> &[f32] {
        &self.values[v * self.width..(v + 1) * self.width]
    }

    /// The rows of the vertices in `range`.
    pub fn rows(&self, range: std::ops::Range<usize>) -> VertexAttribute {
        VertexAttribute {
            name: self.name.clone(),
            width: self.width,
            values: self.values[range.start * self.width..range.end * self.width].to_vec(),
        }
    }

    /// The attribute of vertices made from `sources` (one row per new vertex: vertices of this
    /// attribute and coefficients, as [`crate::surgery::SkinnedMesh::sources`] records them):
    /// the same weighted sum. A `NORMAL` is renormalised (a zero sum gets `+z`).
    pub fn interpolated(&self, sources: &Influences) -> VertexAttribute {
        let n = sources.vertex_count();
        let mut values = Vec::with_capacity(n * self.width);
        let mut acc = vec![0.0f64; self.width];
        for v in 0..n {
            acc.iter_mut().for_each(|a| *a = 0.0);
            for (s, c) in sources.row(v).filter(|&(_, c)| c != 0.0) {
                for (a, &x) in acc.iter_mut().zip(self.row(s as usize)) {
                    *a += c * f64::from(x);
                }
            }
            if self.name == "NORMAL" && self.width == 3 {
                let n = DVec3::from_slice(&acc).normalize_or_zero();
                let n = if n == DVec3::ZERO { DVec3::Z } else { n };
                acc.copy_from_slice(&n.to_array());
            }
            values.extend(acc.iter().map(|&a| a as f32));
        }
        VertexAttribute {
            name: self.name.clone(),
            width: self.width,
            values,
        }
    }
}

/// An image of the model: its glTF JSON (`name`, `mimeType`; `uri` when it was kept as a
/// link) and its bytes when they are embedded in the written file.
#[derive(Clone, Debug, PartialEq)]
pub struct LookImage {
    /// The image's JSON object without `bufferView`.
    pub json: Value,
    /// The encoded image (PNG, JPEG...), written into the binary chunk.
    pub bytes: Option<Vec<u8>>,
}

/// What a glTF model looks like, beyond its positions and skin.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Look {
    /// Per-vertex attributes other than positions, joints and weights (tangents are not kept:
    /// they no longer fit a deformed surface, and viewers compute them from normals and UVs).
    pub attributes: Vec<VertexAttribute>,
    /// The material of each primitive of [`super::Rig::primitives`] (index into `materials`).
    pub primitive_materials: Vec<Option<usize>>,
    /// glTF `materials`, verbatim (their texture indices refer to `textures`).
    pub materials: Vec<Value>,
    /// glTF `textures`, verbatim (sampler and source indices refer to `samplers`, `images`).
    pub textures: Vec<Value>,
    /// glTF `samplers`, verbatim.
    pub samplers: Vec<Value>,
    /// The images.
    pub images: Vec<LookImage>,
    /// The file's `extensionsUsed` that the kept JSON uses.
    pub extensions_used: Vec<String>,
    /// The file's `extensionsRequired` that the kept JSON uses.
    pub extensions_required: Vec<String>,
    /// The model was read from a glTF file without normals, which viewers shade flat (as the
    /// specification says): none are written, so it keeps that look. Otherwise a rig without
    /// a `NORMAL` attribute (libigl, procedural) is written with smooth normals.
    pub flat: bool,
    /// The default weight of each morph target, whose offsets are the attributes
    /// `TARGET{k}_POSITION` (and `TARGET{k}_NORMAL`); the rig's rest shape has them applied.
    pub morph_weights: Vec<f32>,
}

impl Look {
    /// The attribute named `name`.
    pub fn attribute(&self, name: &str) -> Option<&VertexAttribute> {
        self.attributes.iter().find(|a| a.name == name)
    }

    /// Whether there is anything to keep.
    pub fn is_empty(&self) -> bool {
        self.attributes.is_empty() && self.materials.is_empty()
    }
}

/// Planar texture coordinates for a cap (a flat polygon closing a cut): the rest positions
/// projected onto the plane with unit `normal`, scaled and moved so that the cap's extent
/// covers the box of `around` (the UVs of the cap's boundary, as the surface has them), so
/// the cap takes the colours of the skin it closes.
pub fn planar_uvs(positions: &[DVec3], normal: DVec3, around: &[[f32; 2]]) -> Vec<[f32; 2]> {
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    let flat: Vec<[f64; 2]> = positions.iter().map(|p| [p.dot(u), p.dot(v)]).collect();
    let bounds = |pts: &mut dyn Iterator<Item = [f64; 2]>| {
        pts.fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), p| {
                (
                    [lo[0].min(p[0]), lo[1].min(p[1])],
                    [hi[0].max(p[0]), hi[1].max(p[1])],
                )
            },
        )
    };
    let (lo, hi) = bounds(&mut flat.iter().copied());
    let (ulo, uhi) = bounds(&mut around.iter().map(|t| [f64::from(t[0]), f64::from(t[1])]));
    let (ulo, uhi) = if ulo[0].is_finite() && uhi[0].is_finite() {
        (ulo, uhi)
    } else {
        ([0.0; 2], [1.0; 2])
    };
    flat.iter()
        .map(|p| {
            std::array::from_fn(|k| {
                let span = hi[k] - lo[k];
                let s = if span > 0.0 {
                    (p[k] - lo[k]) / span
                } else {
                    0.5
                };
                (ulo[k] + s * (uhi[k] - ulo[k])) as f32
            })
        })
        .collect()
}

/// Names of the extensions used in `json` (the keys of every `extensions` object in it).
pub(crate) fn extensions_in(json: &Value, out: &mut Vec<String>) {
    match json {
        Value::Object(map) => {
            for (k, v) in map {
                if k == "extensions" {
                    if let Value::Object(e) = v {
                        out.extend(e.keys().cloned());
                    }
                }
                extensions_in(v, out);
            }
        }
        Value::Array(list) => list.iter().for_each(|v| extensions_in(v, out)),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn attributes_follow_their_sources() {
        let uv = VertexAttribute {
            name: "TEXCOORD_0".into(),
            width: 2,
            values: vec![0.0, 0.0, 1.0, 0.0, 0.0, 1.0],
        };
        let sources = Influences {
            width: 4,
            joints: vec![0, 1, 2, 0, 2, 0, 0, 0],
            weights: vec![0.25, 0.25, 0.5, 0.0, 1.0, 0.0, 0.0, 0.0],
        };
        let got = uv.interpolated(&sources);
        assert_eq!(got.values, vec![0.25, 0.5, 0.0, 1.0]);
        let normal = VertexAttribute {
            name: "NORMAL".into(),
            width: 3,
            values: vec![1.0, 0.0, 0.0, 0.0, 1.0, 0.0],
        };
        let half = Influences {
            width: 2,
            joints: vec![0, 1],
            weights: vec![0.5, 0.5],
        };
        let n = normal.interpolated(&half);
        let len = n.values.iter().map(|x| x * x).sum::<f32>().sqrt();
        assert!((len - 1.0).abs() < 1e-6, "{n:?}");
    }

    #[test]
    fn caps_cover_the_uvs_around_them() {
        let square = [
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(2.0, 0.0, 1.0),
            DVec3::new(2.0, 2.0, 1.0),
            DVec3::new(0.0, 2.0, 1.0),
        ];
        let around = [[0.5, 0.25], [0.75, 0.5]];
        let uv = planar_uvs(&square, DVec3::Z, &around);
        for k in 0..2 {
            let lo = uv.iter().map(|t| t[k]).fold(f32::INFINITY, f32::min);
            let hi = uv.iter().map(|t| t[k]).fold(f32::NEG_INFINITY, f32::max);
            assert_eq!((lo, hi), (around[0][k], around[1][k]));
        }
    }
}
