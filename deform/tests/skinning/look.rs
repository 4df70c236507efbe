//! A rig's look (vertex attributes, materials, textures, samplers, images) survives a `.glb`
//! round trip exactly, and a look that does not fit its rig is refused.

use super::{gltf, gltf_out};
use deform::skinning::{glb_bytes, parse_gltf, procedural_arm, GlbOptions, LookImage, Rig};
use deform::skinning::{SkinError, VertexAttribute};
use serde_json::json;

/// Write, read back, and compare every part of the look.
fn round_trip(rig: &Rig, name: &str) -> Rig {
    let bytes = glb_bytes(rig, &GlbOptions::default()).expect("written");
    std::fs::write(gltf_out().join(name), &bytes).unwrap();
    let back = parse_gltf(&bytes, name, None).expect("read back");
    let (a, b) = (&rig.look, &back.look);
    assert_eq!(b.materials, a.materials, "{name}");
    assert_eq!(b.textures, a.textures, "{name}");
    assert_eq!(b.samplers, a.samplers, "{name}");
    assert_eq!(b.images, a.images, "{name}");
    assert_eq!(b.primitive_materials, a.primitive_materials, "{name}");
    assert_eq!(b.extensions_used, a.extensions_used, "{name}");
    let names = |l: &deform::skinning::Look| -> Vec<String> {
        let mut n: Vec<String> = l.attributes.iter().map(|x| x.name.clone()).collect();
        n.sort();
        n
    };
    // NORMAL is written unless the model is flat shaded: the model's own, or smooth ones for
    // a rig that never had a look (procedural, libigl).
    let mut expected = names(a);
    if a.attribute("NORMAL").is_none() && !a.flat {
        expected.push("NORMAL".into());
        expected.sort();
    }
    assert_eq!(names(b), expected, "{name}: attribute names");
    for x in &a.attributes {
        let y = b.attribute(&x.name).unwrap();
        assert_eq!(y.width, x.width, "{name} {}", x.name);
        let worst = x
            .values
            .iter()
            .zip(&y.values)
            .map(|(p, q)| (p - q).abs())
            .fold(0.0f32, f32::max);
        // Normals are renormalised in single precision; everything else is exact.
        let tolerance = if x.name == "NORMAL" { 1e-6 } else { 0.0 };
        assert!(worst <= tolerance, "{name} {}: off by {worst}", x.name);
    }
    back
}

#[test]
fn shared_models_keep_their_look() {
    for name in ["CesiumMan.glb", "Fox.glb"] {
        let Some(rig) = gltf(name) else { continue };
        assert!(
            rig.look.attribute("TEXCOORD_0").is_some(),
            "{name}: UVs read"
        );
        assert!(!rig.look.images[0].bytes.as_ref().unwrap().is_empty());
        // The Fox has no normals: viewers shade it flat, and so does the written file.
        assert_eq!(rig.look.flat, name == "Fox.glb", "{name}");
        round_trip(&rig, &format!("look-{name}"));
    }
}

/// The procedural arm with a made-up look: colours, two UV sets, a material textured through the second.
fn dressed_arm() -> Rig {
    let mut rig = procedural_arm(8, 6);
    let n = rig.mesh.vertex_count();
    let colour = (0..n).flat_map(|v| [v as f32 / n as f32, 0.5, 0.25, 1.0]);
    let uv = (0..n).flat_map(|v| [(v % 7) as f32 / 7.0, (v % 5) as f32 / 5.0]);
    rig.look.attributes = vec![
        VertexAttribute {
            name: "COLOR_0".into(),
            width: 4,
            values: colour.collect(),
        },
        VertexAttribute {
            name: "TEXCOORD_0".into(),
            width: 2,
            values: uv.clone().collect(),
        },
        VertexAttribute {
            name: "TEXCOORD_1".into(),
            width: 2,
            values: uv.map(|x| 1.0 - x).collect(),
        },
    ];
    rig.look.materials = vec![json!({
        "name": "skin",
        "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1}},
        "extensions": {"KHR_materials_unlit": {}}
    })];
    rig.look.textures = vec![json!({"sampler": 0, "source": 0})];
    rig.look.samplers = vec![json!({"magFilter": 9728})];
    let png = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x01\0\0\0\x01\x08\0\0\0\0:~\x9bU\0\0\0\nIDATx\x9cc\xd8\x02\0\0\xb6\0\xb5\x18\xa6%\xe4\0\0\0\0IEND\xaeB`\x82";
    rig.look.images = vec![LookImage {
        json: json!({"name": "one pixel", "mimeType": "image/png"}),
        bytes: Some(png.to_vec()),
    }];
    rig.look.primitive_materials = vec![Some(0)];
    rig.look.extensions_used = vec!["KHR_materials_unlit".into()];
    rig
}

#[test]
fn every_attribute_and_the_material_come_back() {
    round_trip(&dressed_arm(), "look-dressed-arm.glb");
}

#[test]
fn a_look_that_does_not_fit_is_refused() {
    let mut short = dressed_arm();
    short.look.attributes[0].values.pop();
    assert!(matches!(
        glb_bytes(&short, &GlbOptions::default()),
        Err(SkinError::InvalidArgument(m)) if m.contains("COLOR_0")
    ));
    let mut past = dressed_arm();
    past.look.primitive_materials = vec![Some(3)];
    assert!(matches!(
        glb_bytes(&past, &GlbOptions::default()),
        Err(SkinError::InvalidArgument(m)) if m.contains("material 3")
    ));
}
