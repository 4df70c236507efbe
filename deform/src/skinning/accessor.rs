//! glTF buffers and accessors, read with every offset checked against the data (a corrupt
//! file is an error, never a panic or an out-of-bounds read).

use super::SkinError;
use base64::Engine;
use gltf::accessor::{DataType, Dimensions};
use gltf::buffer::Source;
use std::path::Path;

/// The bytes of every buffer of a document.
pub(crate) struct Buffers {
    data: Vec<Vec<u8>>,
}

impl Buffers {
    /// Resolve every buffer: the GLB binary chunk, `data:` URIs, or files beside the model.
    pub(crate) fn load(
        doc: &gltf::Document,
        blob: Option<&[u8]>,
        base: Option<&Path>,
        name: &str,
    ) -> Result<Buffers, SkinError> {
        let err = |message: String| SkinError::Data {
            name: name.to_string(),
            message,
        };
        let mut data = Vec::new();
        for b in doc.buffers() {
            let bytes = match b.source() {
                Source::Bin => blob
                    .ok_or_else(|| err(format!("buffer {}: no binary chunk", b.index())))?
                    .to_vec(),
                Source::Uri(uri) if uri.starts_with("data:") => {
                    let payload = uri
                        .split_once(";base64,")
                        .map(|(_, p)| p)
                        .ok_or_else(|| err(format!("buffer {}: data URI is not base64", b.index())))?;
                    base64::engine::general_purpose::STANDARD
                        .decode(payload.trim())
                        .map_err(|e| err(format!("buffer {}: bad base64: {e}", b.index())))?
                }
                Source::Uri(uri) => {
                    let base = base.ok_or_else(|| {
                        err(format!("buffer {}: external file {uri:?} without a base folder", b.index()))
                    })?;
                    let path = base.join(uri);
                    std::fs::read(&path)
                        .map_err(|e| err(format!("buffer {}: {}: {e}", b.index(), path.display())))?
                }
            };
            if bytes.len() < b.length() {
                return Err(err(format!(
                    "buffer {}: {} bytes, the file declares {}",
                    b.index(),
                    bytes.len(),
                    b.length()
                )));
            }
            data.push(bytes);
        }
        Ok(Buffers { data })
    }

    /// The accessor's elements as `f64`, `dimension` components each (normalised integers
    /// mapped to [0, 1] or [-1, 1] as glTF specifies).
    pub(crate) fn read(
        &self,
        a: &gltf::Accessor,
        name: &str,
    ) -> Result<(Vec<f64>, usize), SkinError> {
        let err = |message: String| SkinError::Data {
            name: name.to_string(),
            message: format!("accessor {}: {message}", a.index()),
        };
        if a.sparse().is_some() {
            return Err(SkinError::Unsupported {
                name: name.to_string(),
                message: format!("sparse accessor {}", a.index()),
            });
        }
        let dim = a.dimensions().multiplicity();
        if matches!(a.dimensions(), Dimensions::Mat2 | Dimensions::Mat3)
            && a.data_type().size() < 4
        {
            return Err(SkinError::Unsupported {
                name: name.to_string(),
                message: format!("padded matrix accessor {}", a.index()),
            });
        }
        let count = a.count();
        let Some(view) = a.view() else {
            // No buffer view: all zeros (glTF 2.0, 3.6.2.3).
            return Ok((vec![0.0; count * dim], dim));
        };
        let size = a.data_type().size();
        let elem = size * dim;
        let stride = view.stride().unwrap_or(elem);
        if stride < elem {
            return Err(err(format!("stride {stride} below the element size {elem}")));
        }
        let buffer = self
            .data
            .get(view.buffer().index())
            .ok_or_else(|| err("buffer missing".into()))?;
        let view_end = view
            .offset()
            .checked_add(view.length())
            .filter(|&e| e <= buffer.len())
            .ok_or_else(|| err("buffer view past the end of its buffer".into()))?;
        let start = view.offset() + a.offset();
        if count > 0 {
            let last = (count - 1)
                .checked_mul(stride)
                .and_then(|x| x.checked_add(start))
                .and_then(|x| x.checked_add(elem))
                .ok_or_else(|| err("size overflows".into()))?;
            if last > view_end {
                return Err(err(format!(
                    "{count} elements of {elem} bytes (stride {stride}) reach past the buffer view"
                )));
            }
        }
        let bytes = &buffer[..view_end];
        let normalized = a.normalized();
        let mut out = Vec::with_capacity(count * dim);
        for i in 0..count {
            let at = start + i * stride;
            for c in 0..dim {
                let b = &bytes[at + c * size..at + (c + 1) * size];
                out.push(component(a.data_type(), b, normalized));
            }
        }
        Ok((out, dim))
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
