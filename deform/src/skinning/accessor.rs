//! glTF buffers and accessors, read with every offset checked against the data (a corrupt
//! file is an error, never a panic or an out-of-bounds read).

use super::compressed::{decode_draco, decode_meshopt_views, is_fallback_buffer, DracoValues};
use super::SkinError;
use base64::Engine;
use gltf::accessor::{DataType, Dimensions};
use gltf::buffer::Source;
use std::collections::HashMap;
use std::path::Path;

/// The bytes of every buffer of a document, with its compressed geometry decoded
/// ([`super::compressed`]).
pub(crate) struct Buffers {
    data: Vec<Vec<u8>>,
    /// Meshopt-compressed buffer views, decoded.
    views: HashMap<usize, Vec<u8>>,
    /// The accessors of Draco-compressed primitives, decoded.
    draco: DracoValues,
    /// [`GltfReadOptions::max_buffer_bytes`], which also bounds accessors without a view.
    max_bytes: usize,
}

impl Buffers {
    /// Resolve every buffer: the GLB binary chunk, `data:` URIs, or files beside the model
    /// (a meshopt fallback buffer may have none); then decode the compressed views and
    /// primitives.
    pub(crate) fn load(
        doc: &gltf::Document,
        blob: Option<&[u8]>,
        base: Option<&Path>,
        name: &str,
        options: &GltfReadOptions,
    ) -> Result<Buffers, SkinError> {
        let err = |message: String| SkinError::Data {
            name: name.to_string(),
            message,
        };
        let root = doc.as_json();
        let mut data = Vec::new();
        let mut total = 0usize;
        for b in doc.buffers() {
            total = total.saturating_add(b.length());
            if total > options.max_buffer_bytes {
                return Err(err(format!(
                    "buffer {}: the buffers declare more than {} bytes in all, over the limit \
                     of {} (GltfReadOptions::max_buffer_bytes)",
                    b.index(),
                    total,
                    options.max_buffer_bytes
                )));
            }
            let fallback = is_fallback_buffer(&root.buffers[b.index()]);
            let bytes = match b.source() {
                // A meshopt fallback buffer without a URI holds no data: every view of it is
                // compressed elsewhere (a GLB's binary chunk belongs to another buffer).
                Source::Bin if fallback => Vec::new(),
                Source::Bin => blob
                    .ok_or_else(|| err(format!("buffer {}: no binary chunk", b.index())))?
                    .to_vec(),
                Source::Uri(uri) if uri.starts_with("data:") => {
                    let payload = uri.split_once(";base64,").map(|(_, p)| p).ok_or_else(|| {
                        err(format!("buffer {}: data URI is not base64", b.index()))
                    })?;
                    base64::engine::general_purpose::STANDARD
                        .decode(payload.trim())
                        .map_err(|e| err(format!("buffer {}: bad base64: {e}", b.index())))?
                }
                Source::Uri(uri) => {
                    let base = base.ok_or_else(|| {
                        err(format!(
                            "buffer {}: external file {uri:?} without a base folder",
                            b.index()
                        ))
                    })?;
                    read_external(base, uri, b.length(), options.allow_external)
                        .map_err(|e| err(format!("buffer {}: {e}", b.index())))?
                }
            };
            if bytes.len() < b.length() && !(fallback && bytes.is_empty()) {
                return Err(err(format!(
                    "buffer {}: {} bytes, the file declares {}",
                    b.index(),
                    bytes.len(),
                    b.length()
                )));
            }
            data.push(bytes);
        }
        let views = decode_meshopt_views(root, &data).map_err(err)?;
        let decoded: u64 = views.values().map(|v| v.len() as u64).sum();
        if decoded > options.max_buffer_bytes as u64 {
            return Err(err(format!(
                "the compressed buffer views decode to {decoded} bytes, over the limit of {} \
                 (GltfReadOptions::max_buffer_bytes)",
                options.max_buffer_bytes
            )));
        }
        let mut buffers = Buffers {
            data,
            views,
            draco: DracoValues::new(),
            max_bytes: options.max_buffer_bytes,
        };
        let draco = decode_draco(root, &|v| {
            doc.views()
                .nth(v)
                .and_then(|view| buffers.view_bytes(&view).map(<[u8]>::to_vec))
        })
        .map_err(err)?;
        buffers.draco = draco;
        Ok(buffers)
    }

    /// The accessor's elements as `f64`, `dimension` components each (normalised integers
    /// mapped to [0, 1] or [-1, 1] as glTF specifies), sparse substitutions applied; the
    /// decoded values for an accessor of a Draco-compressed primitive.
    pub(crate) fn read(
        &self,
        a: &gltf::Accessor,
        name: &str,
    ) -> Result<(Vec<f64>, usize), SkinError> {
        let err = |message: String| SkinError::Data {
            name: name.to_string(),
            message: format!("accessor {}: {message}", a.index()),
        };
        if let Some(values) = self.draco.get(&a.index()) {
            return Ok(values.clone());
        }
        let dim = a.dimensions().multiplicity();
        if matches!(a.dimensions(), Dimensions::Mat2 | Dimensions::Mat3) && a.data_type().size() < 4
        {
            return Err(SkinError::Unsupported {
                name: name.to_string(),
                message: format!("padded matrix accessor {}", a.index()),
            });
        }
        let count = a.count();
        let normalized = a.normalized();
        let mut out = match a.view() {
            // No buffer view: all zeros (glTF 2.0, 3.6.2.3), sparse values aside. The count
            // is still bounded like a buffer's bytes.
            None => {
                let values = count
                    .checked_mul(dim)
                    .filter(|n| n.saturating_mul(8) <= self.max_bytes)
                    .ok_or_else(|| {
                        err(format!(
                            "{count} elements without a buffer view, over the limit of {} bytes \
                             (GltfReadOptions::max_buffer_bytes)",
                            self.max_bytes
                        ))
                    })?;
                vec![0.0; values]
            }
            Some(view) => {
                let elem = a.data_type().size() * dim;
                let stride = view.stride().unwrap_or(elem);
                self.elements(&view, a.offset(), count, elem, stride)
                    .map_err(err)?
                    .flat_map(|b| {
                        (0..dim).map(move |c| {
                            let size = a.data_type().size();
                            component(a.data_type(), &b[c * size..(c + 1) * size], normalized)
                        })
                    })
                    .collect()
            }
        };
        if let Some(sparse) = a.sparse() {
            self.apply_sparse(&sparse, a, dim, &mut out).map_err(err)?;
        }
        Ok((out, dim))
    }

    /// `count` elements of `elem` bytes, `stride` apart from `offset` in `view`: each
    /// element's bytes, every one checked to lie inside the view.
    fn elements<'s>(
        &'s self,
        view: &gltf::buffer::View,
        offset: usize,
        count: usize,
        elem: usize,
        stride: usize,
    ) -> Result<impl Iterator<Item = &'s [u8]> + 's, String> {
        if stride < elem {
            return Err(format!("stride {stride} below the element size {elem}"));
        }
        let bytes = self.view_bytes(view).ok_or_else(|| {
            format!(
                "buffer view {} past the end of its buffer (or in a fallback buffer without data)",
                view.index()
            )
        })?;
        if count > 0 {
            let last = (count - 1)
                .checked_mul(stride)
                .and_then(|x| x.checked_add(offset))
                .and_then(|x| x.checked_add(elem))
                .ok_or_else(|| "size overflows".to_string())?;
            if last > bytes.len() {
                return Err(format!(
                    "{count} elements of {elem} bytes (stride {stride}) reach past the buffer view"
                ));
            }
        }
        Ok((0..count).map(move |i| &bytes[offset + i * stride..offset + i * stride + elem]))
    }

    /// Replace the elements a sparse accessor lists by its values.
    fn apply_sparse(
        &self,
        sparse: &gltf::accessor::sparse::Sparse,
        a: &gltf::Accessor,
        dim: usize,
        out: &mut [f64],
    ) -> Result<(), String> {
        let n = sparse.count();
        let indices = sparse.indices();
        let index_size = match indices.index_type() {
            gltf::accessor::sparse::IndexType::U8 => 1,
            gltf::accessor::sparse::IndexType::U16 => 2,
            gltf::accessor::sparse::IndexType::U32 => 4,
        };
        let index_type = match index_size {
            1 => DataType::U8,
            2 => DataType::U16,
            _ => DataType::U32,
        };
        let at: Vec<usize> = self
            .elements(&indices.view(), indices.offset(), n, index_size, index_size)
            .map_err(|e| format!("sparse indices: {e}"))?
            .map(|b| component(index_type, b, false) as usize)
            .collect();
        let size = a.data_type().size();
        let values = sparse.values();
        let elem = size * dim;
        let values: Vec<&[u8]> = self
            .elements(&values.view(), values.offset(), n, elem, elem)
            .map_err(|e| format!("sparse values: {e}"))?
            .collect();
        for (&i, v) in at.iter().zip(values) {
            let slot = out.get_mut(i * dim..(i + 1) * dim).ok_or_else(|| {
                format!(
                    "sparse index {i} past the accessor's {} elements",
                    a.count()
                )
            })?;
            for (c, x) in slot.iter_mut().enumerate() {
                *x = component(a.data_type(), &v[c * size..(c + 1) * size], a.normalized());
            }
        }
        Ok(())
    }
}

/// How glTF 2.0 lets an accessor of one use be stored (section 3.7.2.1, 3.7.3.1 and 3.11):
/// its element type and the component types allowed, each with whether an integer type must
/// be normalized.
pub(crate) struct Layout {
    /// The use, for messages (`"POSITION"`, `"indices"`, ...).
    pub(crate) what: &'static str,
    pub(crate) dimensions: Dimensions,
    pub(crate) components: &'static [(DataType, bool)],
}

const FLOAT: &[(DataType, bool)] = &[(DataType::F32, false)];

impl Layout {
    /// Vertex positions: floats.
    pub(crate) const POSITION: Layout = Layout {
        what: "POSITION",
        dimensions: Dimensions::Vec3,
        components: FLOAT,
    };
    /// Vertex positions under `KHR_mesh_quantization`: floats or 8- and 16-bit integers,
    /// normalized or not.
    pub(crate) const QUANTIZED_POSITION: Layout = Layout {
        what: "POSITION",
        dimensions: Dimensions::Vec3,
        components: &[
            (DataType::F32, false),
            (DataType::I8, false),
            (DataType::I8, true),
            (DataType::U8, false),
            (DataType::U8, true),
            (DataType::I16, false),
            (DataType::I16, true),
            (DataType::U16, false),
            (DataType::U16, true),
        ],
    };
    /// Triangle indices: unsigned integers, not normalized.
    pub(crate) const INDICES: Layout = Layout {
        what: "indices",
        dimensions: Dimensions::Scalar,
        components: &[
            (DataType::U8, false),
            (DataType::U16, false),
            (DataType::U32, false),
        ],
    };
    /// `JOINTS_n`: 8- or 16-bit unsigned integers.
    pub(crate) const JOINTS: Layout = Layout {
        what: "JOINTS",
        dimensions: Dimensions::Vec4,
        components: &[(DataType::U8, false), (DataType::U16, false)],
    };
    /// `WEIGHTS_n`: floats or normalized unsigned integers.
    pub(crate) const WEIGHTS: Layout = Layout {
        what: "WEIGHTS",
        dimensions: Dimensions::Vec4,
        components: &[
            (DataType::F32, false),
            (DataType::U8, true),
            (DataType::U16, true),
        ],
    };
    /// Inverse bind matrices: float 4x4 matrices.
    pub(crate) const INVERSE_BIND: Layout = Layout {
        what: "inverse bind matrices",
        dimensions: Dimensions::Mat4,
        components: FLOAT,
    };
    /// Keyframe times: floats.
    pub(crate) const TIMES: Layout = Layout {
        what: "keyframe times",
        dimensions: Dimensions::Scalar,
        components: FLOAT,
    };
    /// Translation and scale keyframes: float 3-vectors.
    pub(crate) const VECTOR_KEYS: Layout = Layout {
        what: "keyframe values",
        dimensions: Dimensions::Vec3,
        components: FLOAT,
    };
    /// Rotation keyframes: floats or normalized integers, 4-vectors.
    pub(crate) const ROTATION_KEYS: Layout = Layout {
        what: "keyframe values",
        dimensions: Dimensions::Vec4,
        components: &[
            (DataType::F32, false),
            (DataType::I8, true),
            (DataType::U8, true),
            (DataType::I16, true),
            (DataType::U16, true),
        ],
    };
}

impl Layout {
    /// A typed error unless accessor `a` is stored as this use allows (a position read as
    /// integers, or times as two-vectors, would otherwise be read as garbage).
    pub(crate) fn check(&self, a: &gltf::Accessor, name: &str) -> Result<(), SkinError> {
        let (t, normalized) = (a.data_type(), a.normalized());
        let allowed = self
            .components
            .iter()
            .any(|&(at, an)| at == t && an == normalized);
        if a.dimensions() == self.dimensions && allowed {
            return Ok(());
        }
        Err(SkinError::Data {
            name: name.to_string(),
            message: format!(
                "accessor {} ({}): {:?} of {:?}{}, which glTF does not allow there (expected {:?} of {})",
                a.index(),
                self.what,
                a.dimensions(),
                t,
                if normalized { ", normalized" } else { "" },
                self.dimensions,
                self.components
                    .iter()
                    .map(|(t, n)| format!("{t:?}{}", if *n { " normalized" } else { "" }))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        })
    }
}

impl Buffers {
    /// [`Buffers::read`] of an accessor that must be stored as `layout` says (checked first):
    /// its values and their count per element (`layout`'s).
    pub(crate) fn read_as(
        &self,
        a: &gltf::Accessor,
        name: &str,
        layout: &Layout,
    ) -> Result<(Vec<f64>, usize), SkinError> {
        layout.check(a, name)?;
        self.read(a, name)
    }

    /// The bytes of buffer view `view` (checked against its buffer; decoded, for a
    /// meshopt-compressed view).
    pub(crate) fn view_bytes(&self, view: &gltf::buffer::View) -> Option<&[u8]> {
        if let Some(decoded) = self.views.get(&view.index()) {
            return Some(decoded);
        }
        let buffer = self.data.get(view.buffer().index())?;
        let end = view.offset().checked_add(view.length())?;
        buffer.get(view.offset()..end)
    }
}

/// One little-endian component.
fn component(t: DataType, b: &[u8], normalized: bool) -> f64 {
    match t {
        DataType::I8 => {
            let v = b[0] as i8 as f64;
            if normalized {
                (v / 127.0).max(-1.0)
            } else {
                v
            }
        }
        DataType::U8 => {
            let v = b[0] as f64;
            if normalized {
                v / 255.0
            } else {
                v
            }
        }
        DataType::I16 => {
            let v = i16::from_le_bytes([b[0], b[1]]) as f64;
            if normalized {
                (v / 32767.0).max(-1.0)
            } else {
                v
            }
        }
        DataType::U16 => {
            let v = u16::from_le_bytes([b[0], b[1]]) as f64;
            if normalized {
                v / 65535.0
            } else {
                v
            }
        }
        DataType::U32 => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
        DataType::F32 => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
    }
}

/// What reading a glTF may touch beyond its own bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GltfReadOptions {
    /// Follow buffer URIs that leave the model's folder (`..`, absolute paths, links out of
    /// it). Off by default: a model names files beside it.
    pub allow_external: bool,
    /// The most bytes all buffers together may declare (default 2 GiB).
    pub max_buffer_bytes: usize,
}

impl Default for GltfReadOptions {
    fn default() -> Self {
        GltfReadOptions {
            allow_external: false,
            max_buffer_bytes: 1 << 31,
        }
    }
}

/// `%XX` escapes of a URI decoded (glTF URIs are percent-encoded).
pub(crate) fn percent_decoded(uri: &str) -> String {
    let b = uri.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        if b[i] == b'%' && i + 2 < b.len() {
            if let (Some(h), Some(l)) = (hex(b[i + 1]), hex(b[i + 2])) {
                out.push((h * 16 + l) as u8);
                i += 3;
                continue;
            }
        }
        out.push(b[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Reads the first `length` bytes of the external file `uri` (percent-encoded, as glTF URIs
/// are) beside the model in `base`: never more than declared, and only inside `base` unless
/// `allow_external`.
pub(crate) fn read_external(
    base: &Path,
    uri: &str,
    length: usize,
    allow_external: bool,
) -> Result<Vec<u8>, String> {
    use std::io::Read as _;
    if let Some((scheme, _)) = uri.split_once("://") {
        return Err(format!(
            "{uri:?}: a {scheme}:// URI; only files beside the model are read (nothing is fetched)"
        ));
    }
    let path = base.join(percent_decoded(uri));
    let shown = path.display();
    let real = path.canonicalize().map_err(|e| format!("{shown}: {e}"))?;
    if !allow_external {
        let folder = base
            .canonicalize()
            .map_err(|e| format!("{}: {e}", base.display()))?;
        if !real.starts_with(&folder) {
            return Err(format!(
                "{uri:?} leaves the model's folder {} (allow it with --allow-external)",
                folder.display()
            ));
        }
    }
    let file = std::fs::File::open(&real).map_err(|e| format!("{shown}: {e}"))?;
    let mut bytes = Vec::new();
    file.take(length as u64)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("{shown}: {e}"))?;
    Ok(bytes)
}
