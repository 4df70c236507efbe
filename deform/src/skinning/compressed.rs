//! Compressed glTF geometry, decoded before any accessor is read:
//!
//! * `EXT_meshopt_compression`: buffer views whose bytes are meshoptimizer streams
//!   (`ATTRIBUTES`, `TRIANGLES`, `INDICES` modes; `OCTAHEDRAL`, `QUATERNION`, `EXPONENTIAL`,
//!   `COLOR` filters), decoded by meshoptimizer's own codec (the `meshopt` crate, its C++ built
//!   by `cc`; the pure-Rust port reads only version 0 of the vertex codec, which current
//!   encoders no longer write). The buffers they fall back to may hold no data.
//! * `KHR_draco_mesh_compression`: primitives whose attributes and indices are one Draco
//!   stream, decoded by `draco-oxide-decoder` (pure Rust) into the values of the accessors
//!   the primitive names (which have no buffer view of their own).
//!
//! `KHR_mesh_quantization` needs no decoding: its integer accessors are read like any other.

use gltf::json;
use std::collections::HashMap;

/// The extensions a file may require and still be read: every other required extension is
/// refused by name ([`check_required`]).
pub(crate) const SUPPORTED_REQUIRED: [&str; 3] = [
    "KHR_mesh_quantization",
    "KHR_draco_mesh_compression",
    "EXT_meshopt_compression",
];

/// `Ok` unless the document requires an extension outside [`SUPPORTED_REQUIRED`]; the error
/// names it (and the others) in one line.
pub(crate) fn check_required(root: &json::Root) -> Result<(), String> {
    let missing: Vec<&str> = root
        .extensions_required
        .iter()
        .map(String::as_str)
        .filter(|e| !SUPPORTED_REQUIRED.contains(e))
        .collect();
    if missing.is_empty() {
        return Ok(());
    }
    Err(format!(
        "the file requires the glTF extension{} {}, which this program does not read (it reads {})",
        if missing.len() == 1 { "" } else { "s" },
        missing.join(", "),
        SUPPORTED_REQUIRED.join(", ")
    ))
}

/// An extension object by name from an `extensions` map of the `gltf` crate.
fn extension<'a>(
    others: Option<&'a serde_json::Map<String, serde_json::Value>>,
    name: &str,
) -> Option<&'a serde_json::Value> {
    others?.get(name)
}

/// Whether buffer `b` is a meshopt fallback buffer (it may have no data).
pub(crate) fn is_fallback_buffer(b: &json::Buffer) -> bool {
    extension(
        b.extensions.as_ref().map(|e| &e.others),
        "EXT_meshopt_compression",
    )
    .and_then(|e| e.get("fallback"))
    .and_then(serde_json::Value::as_bool)
    .unwrap_or(false)
}

/// A `usize` field of an extension object.
fn field(v: &serde_json::Value, name: &str) -> Option<usize> {
    v.get(name)?.as_u64().and_then(|x| usize::try_from(x).ok())
}

/// Every meshopt-compressed buffer view, decoded: view index -> its bytes (`byteLength` of
/// them, laid out with the view's stride).
///
/// # Errors
/// A message naming the view: a compressed range past its buffer, a stream that does not
/// decode, an unknown mode or filter.
pub(crate) fn decode_meshopt_views(
    root: &json::Root,
    buffers: &[Vec<u8>],
) -> Result<HashMap<usize, Vec<u8>>, String> {
    let mut out = HashMap::new();
    for (i, view) in root.buffer_views.iter().enumerate() {
        let Some(e) = extension(
            view.extensions.as_ref().map(|e| &e.others),
            "EXT_meshopt_compression",
        ) else {
            continue;
        };
        let bad = |m: String| format!("buffer view {i} (EXT_meshopt_compression): {m}");
        let (Some(buffer), Some(length), Some(stride), Some(count)) = (
            field(e, "buffer"),
            field(e, "byteLength"),
            field(e, "byteStride"),
            field(e, "count"),
        ) else {
            return Err(bad(
                "buffer, byteLength, byteStride and count are required".into()
            ));
        };
        let offset = field(e, "byteOffset").unwrap_or(0);
        let data = buffers
            .get(buffer)
            .and_then(|b| b.get(offset..offset.checked_add(length)?))
            .ok_or_else(|| bad(format!("bytes {offset}+{length} past buffer {buffer}")))?;
        let mode = e.get("mode").and_then(|m| m.as_str()).unwrap_or("");
        let filter = e.get("filter").and_then(|m| m.as_str()).unwrap_or("NONE");
        let size = count
            .checked_mul(stride)
            .filter(|&n| n <= view.byte_length.0 as usize + stride)
            .ok_or_else(|| {
                bad(format!(
                    "{count} elements of {stride} bytes overflow the view"
                ))
            })?;
        let mut bytes = match mode {
            "ATTRIBUTES" => decode_attributes(data, count, stride)?,
            "TRIANGLES" | "INDICES" => decode_indices(data, count, stride, mode == "TRIANGLES")?,
            _ => return Err(bad(format!("unknown mode {mode:?}"))),
        };
        apply_filter(&mut bytes, filter, stride).map_err(bad)?;
        bytes.truncate(size);
        out.insert(i, bytes);
    }
    Ok(out)
}

/// `count` vertices of `stride` bytes (a multiple of 4; at most 128, which glTF vertex
/// attributes and keyframes stay far below).
fn decode_attributes(data: &[u8], count: usize, stride: usize) -> Result<Vec<u8>, String> {
    // Decoded as `[u32; stride / 4]` (the codec copies bytes: each word's bytes in memory
    // order are the stream's).
    macro_rules! strides {
        ($($n:literal)*) => {
            match stride {
                $(s if s == 4 * $n => meshopt::encoding::decode_vertex_buffer::<[u32; $n]>(data, count)
                    .map(|v| v.iter().flatten().flat_map(|w| w.to_ne_bytes()).collect())
                    .map_err(|e| e.to_string()),)*
                _ => Err(format!("byteStride {stride} is not a multiple of 4 up to 128")),
            }
        };
    }
    strides!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32)
}

/// `count` indices of `stride` bytes (2 or 4), a triangle list or an index sequence.
fn decode_indices(
    data: &[u8],
    count: usize,
    stride: usize,
    triangles: bool,
) -> Result<Vec<u8>, String> {
    let err = |e: meshopt::Error| e.to_string();
    match (stride, triangles) {
        (2, true) => meshopt::encoding::decode_index_buffer::<u16>(data, count)
            .map(|v| v.iter().flat_map(|x| x.to_le_bytes()).collect())
            .map_err(err),
        (4, true) => meshopt::encoding::decode_index_buffer::<u32>(data, count)
            .map(|v| v.iter().flat_map(|x| x.to_le_bytes()).collect())
            .map_err(err),
        (2, false) => meshopt::encoding::decode_index_sequence::<u16>(data, count)
            .map(|v| v.iter().flat_map(|x| x.to_le_bytes()).collect())
            .map_err(err),
        (4, false) => meshopt::encoding::decode_index_sequence::<u32>(data, count)
            .map(|v| v.iter().flat_map(|x| x.to_le_bytes()).collect())
            .map_err(err),
        _ => Err(format!("index byteStride {stride} is neither 2 nor 4")),
    }
}

/// Undo the filter of decoded vertices in place.
fn apply_filter(bytes: &mut [u8], filter: &str, stride: usize) -> Result<(), String> {
    use meshopt::encoding as m;
    match (filter, stride) {
        ("NONE", _) => {}
        ("OCTAHEDRAL", 4) => {
            let mut v: Vec<[i8; 4]> = bytes
                .chunks_exact(4)
                .map(|c| [c[0] as i8, c[1] as i8, c[2] as i8, c[3] as i8])
                .collect();
            m::decode_filter_oct(&mut v);
            write(bytes, v.iter().flat_map(|c| c.map(|x| x as u8)));
        }
        ("OCTAHEDRAL", 8) => {
            let mut v: Vec<[i16; 4]> = i16s(bytes);
            m::decode_filter_oct(&mut v);
            write(bytes, v.iter().flatten().flat_map(|x| x.to_le_bytes()));
        }
        ("QUATERNION", 8) => {
            let mut v: Vec<[i16; 4]> = i16s(bytes);
            m::decode_filter_quat(&mut v);
            write(bytes, v.iter().flatten().flat_map(|x| x.to_le_bytes()));
        }
        ("EXPONENTIAL", s) if s % 4 == 0 => {
            let mut v: Vec<[u32; 1]> = bytes
                .chunks_exact(4)
                .map(|c| [u32::from_le_bytes([c[0], c[1], c[2], c[3]])])
                .collect();
            m::decode_filter_exp(&mut v);
            write(bytes, v.iter().flat_map(|x| x[0].to_le_bytes()));
        }
        ("COLOR", 4) => {
            let mut v: Vec<[i8; 4]> = bytes
                .chunks_exact(4)
                .map(|c| [c[0] as i8, c[1] as i8, c[2] as i8, c[3] as i8])
                .collect();
            m::decode_filter_color(&mut v);
            write(bytes, v.iter().flat_map(|c| c.map(|x| x as u8)));
        }
        ("COLOR", 8) => {
            let mut v: Vec<[i16; 4]> = i16s(bytes);
            m::decode_filter_color(&mut v);
            write(bytes, v.iter().flatten().flat_map(|x| x.to_le_bytes()));
        }
        _ => return Err(format!("filter {filter:?} with byteStride {stride}")),
    }
    Ok(())
}

fn i16s(bytes: &[u8]) -> Vec<[i16; 4]> {
    bytes
        .chunks_exact(8)
        .map(|c| {
            let h = |k: usize| i16::from_le_bytes([c[2 * k], c[2 * k + 1]]);
            [h(0), h(1), h(2), h(3)]
        })
        .collect()
}

fn write(bytes: &mut [u8], from: impl Iterator<Item = u8>) {
    for (b, x) in bytes.iter_mut().zip(from) {
        *b = x;
    }
}

/// The values of the accessors of Draco-compressed primitives, decoded: accessor index ->
/// its values as `f64` (normalised as the accessor says) and their count per element.
pub(crate) type DracoValues = HashMap<usize, (Vec<f64>, usize)>;

/// Decode every `KHR_draco_mesh_compression` primitive: its indices accessor gets the
/// stream's faces, each attribute accessor the stream's attribute of the unique id the
/// extension gives for it.
///
/// # Errors
/// A message naming the mesh and primitive: a stream that does not decode, an attribute id
/// the stream does not have, a view past its buffer.
pub(crate) fn decode_draco(
    root: &json::Root,
    view_bytes: &dyn Fn(usize) -> Option<Vec<u8>>,
) -> Result<DracoValues, String> {
    let mut out = DracoValues::new();
    for (mi, mesh) in root.meshes.iter().enumerate() {
        for (pi, prim) in mesh.primitives.iter().enumerate() {
            let Some(e) = extension(
                prim.extensions.as_ref().map(|e| &e.others),
                "KHR_draco_mesh_compression",
            ) else {
                continue;
            };
            let bad = |m: String| format!("mesh {mi} primitive {pi} (Draco): {m}");
            let view = field(e, "bufferView").ok_or_else(|| bad("no bufferView".into()))?;
            let bytes =
                view_bytes(view).ok_or_else(|| bad(format!("buffer view {view} has no data")))?;
            let decoded = draco_oxide_decoder::Decoder::new()
                .decode_mesh(&bytes)
                .map_err(|err| bad(format!("the stream does not decode: {err}")))?;
            if let Some(a) = prim.indices.as_ref() {
                let faces: Vec<f64> = decoded
                    .faces
                    .iter()
                    .flat_map(|f| f.map(|p| usize::from(p) as f64))
                    .collect();
                out.insert(a.value(), (faces, 1));
            }
            let ids = e
                .get("attributes")
                .and_then(|a| a.as_object())
                .ok_or_else(|| bad("no attributes".into()))?;
            for (semantic, id) in ids {
                let id = id
                    .as_u64()
                    .ok_or_else(|| bad(format!("{semantic}: id is not a number")))?;
                let Some(accessor) = prim
                    .attributes
                    .iter()
                    .find(|(k, _)| semantic_name(k) == *semantic)
                    .map(|(_, a)| a.value())
                else {
                    continue;
                };
                let att = decoded
                    .attributes
                    .iter()
                    .find(|a| a.get_id().as_usize() as u64 == id)
                    .ok_or_else(|| {
                        bad(format!("{semantic}: no attribute of id {id} in the stream"))
                    })?;
                let normalized = root.accessors.get(accessor).is_some_and(|a| a.normalized);
                out.insert(accessor, attribute_values(att, normalized));
            }
        }
    }
    Ok(out)
}

/// A semantic as glTF writes it (`POSITION`, `JOINTS_0`, `_CUSTOM`).
fn semantic_name(s: &json::validation::Checked<json::mesh::Semantic>) -> String {
    match s {
        json::validation::Checked::Valid(s) => s.to_string(),
        json::validation::Checked::Invalid => String::new(),
    }
}

/// A decoded attribute's value for every point, as `f64`.
fn attribute_values(
    att: &draco_oxide_core::attribute::Attribute,
    normalized: bool,
) -> (Vec<f64>, usize) {
    use draco_oxide_core::attribute::ComponentDataType as C;
    let n = att.get_num_components();
    let ty = att.get_component_type();
    let size = ty.size();
    let bytes = att.get_data_as_bytes();
    let component = |b: &[u8]| -> f64 {
        let v = match ty {
            C::I8 => b[0] as i8 as f64,
            C::U8 => b[0] as f64,
            C::I16 => i16::from_le_bytes([b[0], b[1]]) as f64,
            C::U16 => u16::from_le_bytes([b[0], b[1]]) as f64,
            C::I32 => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            C::U32 => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            C::F32 => return f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            C::F64 => return f64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]),
            _ => return f64::NAN,
        };
        if !normalized {
            return v;
        }
        match ty {
            C::I8 => (v / 127.0).max(-1.0),
            C::U8 => v / 255.0,
            C::I16 => (v / 32767.0).max(-1.0),
            C::U16 => v / 65535.0,
            _ => v,
        }
    };
    let points = att.len();
    let mut values = Vec::with_capacity(points * n);
    for p in 0..points {
        let v = usize::from(att.get_unique_val_idx(p.into()));
        let at = v * n * size;
        for c in 0..n {
            values.push(
                bytes
                    .get(at + c * size..at + (c + 1) * size)
                    .map_or(f64::NAN, component),
            );
        }
    }
    (values, n)
}
