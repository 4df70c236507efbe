//! Reading a model's [`Look`] from glTF: the per-vertex attributes of its skinned primitives
//! and its materials, textures, samplers and images (embedded, from `data:` URIs or from files
//! beside the model, under the same rules as buffers).

#[cfg(test)]
use super::accessor::percent_decoded;
use super::accessor::{read_external, Buffers, GltfReadOptions};
use super::look::{extensions_in, Look, LookImage, VertexAttribute};
use super::morph::parse_target_attribute;
use super::SkinError;
use base64::Engine;
use serde_json::Value;
use std::path::Path;

/// The attributes of one primitive other than positions, joints and weights (`count`
/// vertices); tangents are left out with a note.
pub(crate) fn primitive_attributes(
    p: &gltf::Primitive,
    count: usize,
    buffers: &Buffers,
    name: &str,
    notes: &mut Vec<String>,
) -> Result<Vec<VertexAttribute>, SkinError> {
    use gltf::Semantic;
    let mut out = Vec::new();
    for (semantic, accessor) in p.attributes() {
        match semantic {
            Semantic::Positions | Semantic::Joints(_) | Semantic::Weights(_) => continue,
            Semantic::Tangents => {
                notes.push(format!(
                    "primitive {}: TANGENT not written (deformation changes it; viewers compute \
                     tangents from normals and UVs)",
                    p.index()
                ));
                continue;
            }
            _ => {}
        }
        let label = semantic.to_string();
        let (v, width) = buffers.read(&accessor, name)?;
        if v.len() != width * count {
            return Err(SkinError::Data {
                name: name.to_string(),
                message: format!(
                    "primitive {}: {label} has {} elements for {count} vertices",
                    p.index(),
                    v.len() / width.max(1)
                ),
            });
        }
        let values: Vec<f32> = v.iter().map(|&x| x as f32).collect();
        if let Some(i) = values.iter().position(|x| !x.is_finite()) {
            return Err(SkinError::Data {
                name: name.to_string(),
                message: format!(
                    "primitive {}: {label} of vertex {} is not finite",
                    p.index(),
                    i / width
                ),
            });
        }
        out.push(VertexAttribute {
            name: label,
            width,
            values,
        });
    }
    Ok(out)
}

/// The attributes every primitive has (same name and width), concatenated in primitive order,
/// and every morph target's offsets (zero on the primitives without the target); the others
/// are left out with a note. Each primitive comes with its vertex count.
pub(crate) fn merge_attributes(
    per_primitive: Vec<(usize, Vec<VertexAttribute>)>,
    notes: &mut Vec<String>,
) -> Vec<VertexAttribute> {
    let everywhere = |a: &VertexAttribute| {
        per_primitive
            .iter()
            .all(|(_, list)| list.iter().any(|b| b.name == a.name && b.width == a.width))
    };
    let mut kept: Vec<(String, usize)> = Vec::new();
    for a in per_primitive.iter().flat_map(|(_, list)| list) {
        let target = parse_target_attribute(&a.name).is_some();
        if (target || everywhere(a)) && !kept.iter().any(|k| k.0 == a.name) {
            kept.push((a.name.clone(), a.width));
        }
    }
    let mut dropped: Vec<&str> = per_primitive
        .iter()
        .flat_map(|(_, list)| list)
        .filter(|a| !kept.iter().any(|k| k.0 == a.name))
        .map(|a| a.name.as_str())
        .collect();
    dropped.sort_unstable();
    dropped.dedup();
    for d in dropped {
        notes.push(format!(
            "{d}: not on every skinned primitive (or of different widths): not written"
        ));
    }
    kept.into_iter()
        .map(|(name, width)| {
            let values = per_primitive
                .iter()
                .flat_map(|(count, list)| {
                    list.iter()
                        .find(|a| a.name == name)
                        .map_or_else(|| vec![0.0; count * width], |a| a.values.clone())
                })
                .collect();
            VertexAttribute {
                name,
                width,
                values,
            }
        })
        .collect()
}

/// The file's JSON as a value (the JSON chunk of a `.glb`).
fn raw_json(bytes: &[u8]) -> Option<Value> {
    if bytes.starts_with(b"glTF") {
        let glb = gltf::binary::Glb::from_slice(bytes).ok()?;
        serde_json::from_slice(&glb.json).ok()
    } else {
        serde_json::from_slice(bytes).ok()
    }
}

/// The array `key` of the document, cloned.
fn array(root: &Value, key: &str) -> Vec<Value> {
    root.get(key)
        .and_then(Value::as_array)
        .cloned()
        .unwrap_or_default()
}

/// The image type of encoded bytes, by their signature.
fn sniff(bytes: &[u8]) -> Option<&'static str> {
    if bytes.starts_with(b"\x89PNG") {
        Some("image/png")
    } else if bytes.starts_with(&[0xFF, 0xD8]) {
        Some("image/jpeg")
    } else if bytes.len() >= 12 && &bytes[..4] == b"RIFF" && &bytes[8..12] == b"WEBP" {
        Some("image/webp")
    } else if bytes.starts_with(b"\xABKTX 20") {
        Some("image/ktx2")
    } else {
        None
    }
}

/// One image's bytes: from its buffer view, its `data:` URI or a file beside the model.
fn image_bytes(
    image: &Value,
    doc: &gltf::Document,
    buffers: &Buffers,
    base: Option<&Path>,
    options: &GltfReadOptions,
) -> Result<Vec<u8>, String> {
    if let Some(v) = image.get("bufferView").and_then(Value::as_u64) {
        let view = doc
            .views()
            .nth(v as usize)
            .ok_or_else(|| format!("buffer view {v} does not exist"))?;
        return buffers
            .view_bytes(&view)
            .map(<[u8]>::to_vec)
            .ok_or_else(|| format!("buffer view {v} reaches past its buffer"));
    }
    let uri = image
        .get("uri")
        .and_then(Value::as_str)
        .ok_or("neither a buffer view nor a URI")?;
    if let Some(rest) = uri.strip_prefix("data:") {
        let (_, payload) = rest
            .split_once(";base64,")
            .ok_or("data URI is not base64")?;
        return base64::engine::general_purpose::STANDARD
            .decode(payload.trim())
            .map_err(|e| format!("bad base64: {e}"));
    }
    let base = base.ok_or("an external file without a base folder")?;
    read_external(base, uri, options.max_buffer_bytes, options.allow_external)
}

/// The materials, textures, samplers and images of the document (the attributes and the
/// primitives' materials are filled in by the caller). An image that cannot be read or whose
/// type is unknown keeps its URI, with a note.
pub(crate) fn read_look(
    bytes: &[u8],
    doc: &gltf::Document,
    buffers: &Buffers,
    base: Option<&Path>,
    options: &GltfReadOptions,
    notes: &mut Vec<String>,
) -> Look {
    let Some(root) = raw_json(bytes) else {
        return Look::default();
    };
    let mut images = Vec::new();
    for (i, image) in array(&root, "images").into_iter().enumerate() {
        let mut json = image.clone();
        let read = image_bytes(&image, doc, buffers, base, options).and_then(|b| {
            let declared = image.get("mimeType").and_then(Value::as_str);
            match declared.or_else(|| sniff(&b)) {
                Some(m) => Ok((b, m.to_string())),
                None => Err("unknown image type".to_string()),
            }
        });
        let obj = json.as_object_mut();
        match (read, obj) {
            (Ok((b, mime)), Some(o)) => {
                o.remove("bufferView");
                o.remove("uri");
                o.insert("mimeType".into(), Value::String(mime));
                images.push(LookImage {
                    json,
                    bytes: Some(b),
                });
            }
            (Err(e), Some(o)) if o.contains_key("uri") => {
                notes.push(format!("image {i}: {e}: kept as a link to its URI"));
                o.remove("bufferView");
                images.push(LookImage { json, bytes: None });
            }
            (Err(e), _) => {
                notes.push(format!("image {i}: {e}: written as a blank 1x1 image"));
                images.push(LookImage {
                    json: serde_json::json!({"mimeType": "image/png"}),
                    bytes: Some(blank_png()),
                });
            }
            (Ok(_), None) => images.push(LookImage { json, bytes: None }),
        }
    }
    let materials = array(&root, "materials");
    let textures = array(&root, "textures");
    let samplers = array(&root, "samplers");
    let mut used = Vec::new();
    for list in [&materials, &textures, &samplers] {
        list.iter().for_each(|v| extensions_in(v, &mut used));
    }
    images
        .iter()
        .for_each(|i| extensions_in(&i.json, &mut used));
    let listed = |key: &str| -> Vec<String> {
        array(&root, key)
            .iter()
            .filter_map(Value::as_str)
            .filter(|e| used.iter().any(|u| u == e))
            .map(str::to_string)
            .collect()
    };
    Look {
        attributes: Vec::new(),
        primitive_materials: Vec::new(),
        extensions_used: listed("extensionsUsed"),
        extensions_required: listed("extensionsRequired"),
        flat: false,
        morph_weights: Vec::new(),
        materials,
        textures,
        samplers,
        images,
    }
}

/// A 1x1 grey PNG, for an image whose bytes are lost (so texture indices stay valid).
fn blank_png() -> Vec<u8> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, 1, 1);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(png::BitDepth::Eight);
    let written = encoder
        .write_header()
        .and_then(|mut w| w.write_image_data(&[180]));
    debug_assert!(written.is_ok(), "encoding a 1x1 PNG in memory");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uris_are_percent_decoded_and_images_sniffed() {
        assert_eq!(percent_decoded("a%20b.png"), "a b.png");
        assert_eq!(percent_decoded("100%"), "100%");
        assert_eq!(sniff(&blank_png()), Some("image/png"));
        assert_eq!(sniff(b"nothing"), None);
    }

    #[test]
    fn the_blank_image_decodes() {
        let bytes = blank_png();
        let decoder = png::Decoder::new(std::io::Cursor::new(&bytes[..]));
        let mut reader = decoder.read_info().expect("a PNG header");
        let mut buf = vec![0; reader.output_buffer_size().expect("a small image")];
        let info = reader.next_frame(&mut buf).expect("a frame");
        assert_eq!((info.width, info.height), (1, 1));
    }
}
