//! Binary glTF 2.0 (`.glb`) out: the container (a JSON chunk and a binary chunk of aligned
//! views and accessors) that every `.glb` this crate writes is built with, and static meshes
//! (positions, smooth normals, triangles) for results without a rig.

use super::super::{Mesh, MeshError};
use serde_json::{json, Value};
use std::path::Path;

/// A binary glTF under construction: its buffer (4-byte aligned views), views and accessors.
#[derive(Default)]
pub(crate) struct GlbBuilder {
    data: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl GlbBuilder {
    /// Append `bytes` as a new buffer view (with `target` when given); its index.
    pub(crate) fn view(&mut self, bytes: &[u8], target: Option<u32>) -> usize {
        while !self.data.len().is_multiple_of(4) {
            self.data.push(0);
        }
        let mut view =
            json!({"buffer": 0, "byteOffset": self.data.len(), "byteLength": bytes.len()});
        if let Some(t) = target {
            view["target"] = json!(t);
        }
        self.data.extend_from_slice(bytes);
        self.views.push(view);
        self.views.len() - 1
    }

    /// Append `bytes` as a new buffer view (with `target` when given) and an accessor over it.
    pub(crate) fn push(&mut self, bytes: &[u8], target: Option<u32>, accessor: Value) -> usize {
        let view = self.view(bytes, target);
        let mut a = accessor;
        a["bufferView"] = json!(view);
        self.accessors.push(a);
        self.accessors.len() - 1
    }

    /// `f32` elements of `dim` components (with min/max when `bounds`).
    ///
    /// # Errors
    /// When a value is not finite in single precision (a coordinate beyond the f32 range, or
    /// NaN), naming `what`: glTF holds finite f32 only.
    pub(crate) fn floats(
        &mut self,
        v: &[f32],
        dim: usize,
        kind: &str,
        target: Option<u32>,
        bounds: bool,
        what: &str,
    ) -> Result<usize, String> {
        if v.is_empty() {
            return Err(format!(
                "{what}: no elements (a glTF accessor holds at least one)"
            ));
        }
        if let Some(i) = v.iter().position(|x| !x.is_finite()) {
            return Err(format!(
                "{what}: element {} is {} in single precision; glTF holds finite f32 values \
                 only (coordinates beyond about 3.4e38, or NaN)",
                i / dim,
                v[i]
            ));
        }
        let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
        let mut a = json!({"componentType": 5126, "count": v.len() / dim, "type": kind});
        if bounds {
            let mut lo = vec![f32::INFINITY; dim];
            let mut hi = vec![f32::NEG_INFINITY; dim];
            for e in v.chunks_exact(dim) {
                for c in 0..dim {
                    lo[c] = lo[c].min(e[c]);
                    hi[c] = hi[c].max(e[c]);
                }
            }
            a["min"] = json!(lo);
            a["max"] = json!(hi);
        }
        Ok(self.push(&bytes, target, a))
    }
}

impl GlbBuilder {
    /// The file: `doc` (whose `buffers`, `bufferViews` and `accessors` are set here) as the
    /// JSON chunk, then the binary chunk.
    ///
    /// # Errors
    /// When the JSON cannot be written or the file would pass 4 GiB.
    pub(crate) fn finish(mut self, mut doc: Value) -> Result<Vec<u8>, String> {
        while !self.data.len().is_multiple_of(4) {
            self.data.push(0);
        }
        doc["buffers"] = json!([{"byteLength": self.data.len()}]);
        doc["bufferViews"] = json!(self.views);
        doc["accessors"] = json!(self.accessors);
        let mut text = serde_json::to_vec(&doc).map_err(|e| e.to_string())?;
        while !text.len().is_multiple_of(4) {
            text.push(b' ');
        }
        let total = 12 + 8 + text.len() + 8 + self.data.len();
        let total32 = u32::try_from(total)
            .map_err(|_| format!("{total} bytes: a .glb holds at most 4 GiB"))?;
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&total32.to_le_bytes());
        out.extend_from_slice(&(text.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&text);
        out.extend_from_slice(&(self.data.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&self.data);
        Ok(out)
    }
}

/// Unit normals in single precision ([`Mesh::seamless_vertex_normals`]; `+z` for a vertex
/// without a non-degenerate face).
pub(crate) fn unit_normals(mesh: &Mesh) -> Vec<[f32; 3]> {
    mesh.seamless_vertex_normals()
        .into_iter()
        .map(|n| {
            let n = n.as_vec3().normalize_or_zero();
            if n == glam::Vec3::ZERO {
                [0.0, 0.0, 1.0]
            } else {
                n.to_array()
            }
        })
        .collect()
}

/// A static mesh as binary glTF: one node, one mesh of one primitive with positions, smooth
/// normals and 32-bit indices, in single precision as glTF stores them.
///
/// # Errors
/// [`MeshError::InvalidArgument`] for a mesh without triangles, an index past the vertices or
/// a coordinate that is not finite in single precision.
pub fn glb_bytes(mesh: &Mesh) -> Result<Vec<u8>, MeshError> {
    let n = mesh.vertex_count();
    if mesh.triangle_count() == 0 {
        return Err(MeshError::InvalidArgument(
            "the mesh has no triangles: nothing to write".into(),
        ));
    }
    if let Some(t) = mesh
        .triangles
        .iter()
        .find(|t| t.iter().any(|&v| v as usize >= n))
    {
        return Err(MeshError::InvalidArgument(format!(
            "triangle {t:?} refers to a vertex past {n}"
        )));
    }
    let mut bin = GlbBuilder::default();
    let pos: Vec<f32> = mesh
        .positions
        .iter()
        .flat_map(|p| p.as_vec3().to_array())
        .collect();
    let position = bin
        .floats(&pos, 3, "VEC3", Some(34962), true, "POSITION")
        .map_err(MeshError::InvalidArgument)?;
    let nrm: Vec<f32> = unit_normals(mesh).into_iter().flatten().collect();
    let normal = bin
        .floats(&nrm, 3, "VEC3", Some(34962), false, "NORMAL")
        .map_err(MeshError::InvalidArgument)?;
    let idx: Vec<u8> = mesh
        .triangles
        .iter()
        .flatten()
        .flat_map(|i| i.to_le_bytes())
        .collect();
    let indices = bin.push(
        &idx,
        Some(34963),
        json!({"componentType": 5125, "count": 3 * mesh.triangle_count(), "type": "SCALAR"}),
    );
    let doc = json!({
        "asset": {"version": "2.0", "generator": "deform (cga mesh deformers)"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "mesh", "mesh": 0}],
        "meshes": [{"primitives": [{
            "attributes": {"POSITION": position, "NORMAL": normal},
            "indices": indices,
            "mode": 4
        }]}],
    });
    bin.finish(doc).map_err(MeshError::InvalidArgument)
}

/// Write [`glb_bytes`] to `path`.
///
/// # Errors
/// As [`glb_bytes`], and [`MeshError::Io`].
pub fn write_glb(mesh: &Mesh, path: impl AsRef<Path>) -> Result<(), MeshError> {
    let path = path.as_ref();
    let bytes = glb_bytes(mesh)?;
    std::fs::write(path, bytes).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    })
}
