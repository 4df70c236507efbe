//! Encoded geometry: meshopt and Draco compression, quantised and sparse accessors, and a
//! required extension that is not supported.

use super::{bar, skin_rig, two_joint_bar, Bar};
use crate::gltf_out;
use deform::skinning::{glb_bytes, parse_gltf, GlbOptions, SkinError};
use deform::BlendMethod;
use glam::{DMat4, DQuat, DVec3};
use serde_json::{json, Value};

/// Meshopt-compressed views (`EXT_meshopt_compression`, encoded by meshoptimizer here) read
/// as the same rig as the plain file.
#[test]
fn meshopt_compressed_views() {
    let plain = two_joint_bar(Bar::default());
    let mut f = two_joint_bar(Bar::default());
    // Compress the POSITION view (accessor 0, stride 12) and the indices (accessor 1).
    let mut bin = std::mem::take(&mut f.bin);
    let views = f.json["bufferViews"].clone();
    let view_of =
        |a: usize| views[f.json["accessors"][a]["bufferView"].as_u64().unwrap() as usize].clone();
    let (pv, iv) = (view_of(0), view_of(1));
    let slice = |v: &Value| {
        let o = v["byteOffset"].as_u64().unwrap() as usize;
        bin[o..o + v["byteLength"].as_u64().unwrap() as usize].to_vec()
    };
    let positions: Vec<[u8; 12]> = slice(&pv)
        .chunks_exact(12)
        .map(|c| c.try_into().unwrap())
        .collect();
    let indices: Vec<u32> = slice(&iv)
        .chunks_exact(2)
        .map(|c| u16::from_le_bytes([c[0], c[1]]) as u32)
        .collect();
    let pe = meshopt::encoding::encode_vertex_buffer(&positions).unwrap();
    let ie = meshopt::encoding::encode_index_buffer(&indices, positions.len()).unwrap();
    // The compressed streams go into buffer 1 (the GLB chunk); buffer 0 becomes the
    // fallback without data... kept simple: both in the one chunk, views marked.
    let mut put = |bytes: &[u8]| {
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let o = bin.len();
        bin.extend_from_slice(bytes);
        o
    };
    let (po, io) = (put(&pe), put(&ie));
    let pvi = f.json["accessors"][0]["bufferView"].as_u64().unwrap() as usize;
    let ivi = f.json["accessors"][1]["bufferView"].as_u64().unwrap() as usize;
    f.json["bufferViews"][pvi]["byteStride"] = json!(12);
    f.json["bufferViews"][pvi]["extensions"] = json!({"EXT_meshopt_compression": {
        "buffer": 0, "byteOffset": po, "byteLength": pe.len(), "byteStride": 12,
        "count": positions.len(), "mode": "ATTRIBUTES"}});
    f.json["bufferViews"][ivi]["extensions"] = json!({"EXT_meshopt_compression": {
        "buffer": 0, "byteOffset": io, "byteLength": ie.len(), "byteStride": 2,
        "count": indices.len(), "mode": "TRIANGLES"}});
    f.json["extensionsUsed"] = json!(["EXT_meshopt_compression"]);
    f.json["extensionsRequired"] = json!(["EXT_meshopt_compression"]);
    // The uncompressed bytes are overwritten: only the decoder can give them back.
    for v in [&pv, &iv] {
        let o = v["byteOffset"].as_u64().unwrap() as usize;
        let n = v["byteLength"].as_u64().unwrap() as usize;
        bin[o..o + n].fill(0xAB);
    }
    f.bin = bin;
    let a = parse_gltf(&f.glb(), "meshopt", None).unwrap();
    let b = parse_gltf(&plain.glb(), "plain", None).unwrap();
    assert_eq!(a.mesh.positions, b.mesh.positions);
    // The index codec may rotate a triangle's corners (same triangle, same orientation).
    let canonical = |t: &[u32; 3]| {
        let k = (0..3).min_by_key(|&k| t[k]).unwrap();
        [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
    };
    let ta: Vec<_> = a.mesh.triangles.iter().map(canonical).collect();
    let tb: Vec<_> = b.mesh.triangles.iter().map(canonical).collect();
    assert_eq!(ta, tb);
    let out = glb_bytes(&a, &GlbOptions::default()).unwrap();
    std::fs::write(gltf_out().join("wild-meshopt-decoded.glb"), &out).unwrap();
}

/// A Draco mesh stream (bitstream 2.2) in the plainest form the specification has: the
/// sequential method, indices stored directly, every attribute's values raw (the generic
/// decoder: no quantisation, no prediction). `attributes`: (Draco attribute type, Draco data
/// type, components, little-endian values); attribute `k` gets unique id `k`.
fn draco_stream(triangles: &[u16], points: usize, attributes: &[(u8, u8, u8, Vec<u8>)]) -> Vec<u8> {
    fn leb128(s: &mut Vec<u8>, mut v: usize) {
        loop {
            let byte = (v & 0x7f) as u8;
            v >>= 7;
            if v == 0 {
                s.push(byte);
                return;
            }
            s.push(byte | 0x80);
        }
    }
    let mut s = b"DRACO".to_vec();
    // Version 2.2, a triangular mesh, the sequential method, no flags.
    s.extend_from_slice(&[2, 2, 1, 0, 0, 0]);
    leb128(&mut s, triangles.len() / 3);
    leb128(&mut s, points);
    s.push(1); // indices stored directly, in the narrowest width
    for &i in triangles {
        if points < 256 {
            s.push(i as u8);
        } else {
            s.extend_from_slice(&i.to_le_bytes());
        }
    }
    s.push(1); // one attributes decoder
    leb128(&mut s, attributes.len());
    for (uid, (kind, data, n, _)) in attributes.iter().enumerate() {
        s.extend_from_slice(&[*kind, *data, *n, 0]);
        leb128(&mut s, uid);
    }
    s.extend(attributes.iter().map(|_| 0u8)); // the generic decoder for each
    for (_, _, _, values) in attributes {
        s.extend_from_slice(values);
    }
    s
}

/// A Draco-compressed primitive (`KHR_draco_mesh_compression`: its accessors without buffer
/// views, the stream in one view) reads as the same rig as the plain file; a corrupt stream is
/// one typed error that names the primitive.
#[test]
fn draco_compressed_primitive() {
    let plain = two_joint_bar(Bar::default());
    let mut f = two_joint_bar(Bar::default());
    let (pos, tri) = bar(9);
    let n = pos.len() / 3;
    let (joints, weights) = super::bar_influences(&pos);
    let le = |v: &[f32]| -> Vec<u8> { v.iter().flat_map(|x| x.to_le_bytes()).collect() };
    // POSITION f32 x3, JOINTS_0 u8 x4 and WEIGHTS_0 f32 x4 as generic attributes.
    let stream = draco_stream(
        &tri,
        n,
        &[
            (0, 9, 3, le(&pos)),
            (4, 2, 4, joints),
            (4, 9, 4, le(&weights)),
        ],
    );
    let view = f.view(&stream, None);
    for a in 0..4 {
        f.json["accessors"][a]
            .as_object_mut()
            .unwrap()
            .remove("bufferView");
    }
    let ext = json!({"bufferView": view,
        "attributes": {"POSITION": 0, "JOINTS_0": 1, "WEIGHTS_0": 2}});
    f.json["meshes"][0]["primitives"][0]["extensions"] = json!({"KHR_draco_mesh_compression": ext});
    f.json["extensionsUsed"] = json!(["KHR_draco_mesh_compression"]);
    f.json["extensionsRequired"] = json!(["KHR_draco_mesh_compression"]);
    let a = parse_gltf(&f.glb(), "draco", None).unwrap();
    let b = parse_gltf(&plain.glb(), "plain", None).unwrap();
    assert_eq!(a.mesh.positions, b.mesh.positions);
    assert_eq!(a.mesh.triangles, b.mesh.triangles);
    assert_eq!(a.influences, b.influences);
    assert_eq!(
        skin_rig(&a, BlendMethod::Matrix, Some(1.0)),
        skin_rig(&b, BlendMethod::Matrix, Some(1.0))
    );
    let out = glb_bytes(&a, &GlbOptions::default()).unwrap();
    std::fs::write(gltf_out().join("wild-draco-decoded.glb"), &out).unwrap();

    // The stream cut short: a typed error naming the primitive, in one line.
    let o = f.json["bufferViews"][view]["byteOffset"].as_u64().unwrap() as usize;
    f.bin[o + stream.len() / 2..o + stream.len()].fill(0xFF);
    f.json["bufferViews"][view]["byteLength"] = json!(stream.len() / 2);
    let e = parse_gltf(&f.glb(), "draco", None).unwrap_err().to_string();
    assert!(e.contains("Draco") && !e.contains('\n'), "{e}");
}

/// Quantised positions (`KHR_mesh_quantization`: normalised u16) and a sparse accessor
/// moving one vertex: read as the reference reads them.
#[test]
fn quantised_and_sparse_positions() {
    let mut f = two_joint_bar(Bar::default());
    // Positions as u16 normalised over [-1, 3] per axis -> [0, 65535], dequantised by the
    // inverse bind matrices (as gltfpack does for skinned meshes).
    let (pos, _) = bar(9);
    let q: Vec<u16> = pos
        .iter()
        .map(|&x| (((x as f64 + 1.0) / 4.0) * 65535.0).round() as u16)
        .collect();
    let mut padded = Vec::new();
    for c in q.chunks_exact(3) {
        padded.extend_from_slice(&[c[0], c[1], c[2], 0]);
    }
    let bytes: Vec<u8> = padded.iter().flat_map(|x| x.to_le_bytes()).collect();
    let view = f.view(&bytes, Some(8));
    f.json["accessors"][0] = json!({"bufferView": view, "componentType": 5123,
        "normalized": true, "type": "VEC3", "count": pos.len() / 3,
        "min": [0, 0, 0], "max": [65535, 65535, 65535]});
    f.json["extensionsUsed"] = json!(["KHR_mesh_quantization"]);
    f.json["extensionsRequired"] = json!(["KHR_mesh_quantization"]);
    // Dequantise: p = 4 q - 1, folded into every inverse bind matrix.
    let dequantise = DMat4::from_scale_rotation_translation(
        DVec3::splat(4.0),
        DQuat::IDENTITY,
        DVec3::splat(-1.0),
    );
    let ib = f.json["skins"][0]["inverseBindMatrices"].as_u64().unwrap() as usize;
    let vi = f.json["accessors"][ib]["bufferView"].as_u64().unwrap() as usize;
    let o = f.json["bufferViews"][vi]["byteOffset"].as_u64().unwrap() as usize;
    for k in 0..2 {
        let at = o + 64 * k;
        let m: Vec<f64> = f.bin[at..at + 64]
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
            .collect();
        let m = DMat4::from_cols_slice(&m) * dequantise;
        let bytes: Vec<u8> = m
            .to_cols_array()
            .iter()
            .flat_map(|x| (*x as f32).to_le_bytes())
            .collect();
        f.bin[at..at + 64].copy_from_slice(&bytes);
    }
    let rig = parse_gltf(&f.glb(), "quantised", None).unwrap();
    let want: Vec<DVec3> = pos
        .chunks_exact(3)
        .map(|p| DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64))
        .collect();
    let got = skin_rig(&rig, BlendMethod::Matrix, None);
    let err = got
        .iter()
        .zip(&want)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(err < 1e-4, "dequantised at rest: {err}");
    let out = glb_bytes(&rig, &GlbOptions::default()).unwrap();
    std::fs::write(gltf_out().join("wild-quantised.glb"), &out).unwrap();

    // Sparse: vertex 5 of the positions replaced.
    let mut f = two_joint_bar(Bar::default());
    let idx = f.view(&5u16.to_le_bytes(), None);
    let val: Vec<u8> = [9.0f32, 8.0, 7.0]
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let vals = f.view(&val, None);
    f.json["accessors"][0]["sparse"] = json!({"count": 1,
        "indices": {"bufferView": idx, "componentType": 5123},
        "values": {"bufferView": vals}});
    f.json["accessors"][0]["max"] = json!([9.0, 8.0, 7.0]);
    let rig = parse_gltf(&f.glb(), "sparse", None).unwrap();
    assert_eq!(rig.mesh.positions[5], DVec3::new(9.0, 8.0, 7.0));
    assert_eq!(
        rig.mesh.positions[4],
        DVec3::new(0.2f32 as f64, 0.25, 0.2f32 as f64)
    );
}

/// A required extension the reader does not support is refused in one line, by name.
#[test]
fn unsupported_required_extension() {
    let mut f = two_joint_bar(Bar::default());
    f.json["extensionsUsed"] = json!(["KHR_texture_basisu"]);
    f.json["extensionsRequired"] = json!(["KHR_texture_basisu"]);
    let e = parse_gltf(&f.glb(), "basisu", None).unwrap_err();
    assert!(matches!(e, SkinError::Unsupported { .. }), "{e}");
    let text = e.to_string();
    assert!(
        text.contains("KHR_texture_basisu") && !text.contains('\n'),
        "{text}"
    );
}
