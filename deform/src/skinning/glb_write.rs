//! Rigs out: binary glTF 2.0 (`.glb`) with the mesh, the skin (joints, inverse bind
//! matrices), the node hierarchy and the animations, so any viewer shows and re-animates it.

use super::animation::{Interpolation, Property};
use super::look::VertexAttribute;
use super::morph::{self, parse_target_attribute};
use super::rig::Rig;
use super::SkinError;
use super::Trs;

type Result<T, E = SkinError> = std::result::Result<T, E>;
use crate::mesh::io::{unit_normals, GlbBuilder};
use serde_json::{json, Value};
use std::path::Path;

/// What [`glb_bytes`] writes besides the rig itself.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GlbOptions {
    /// Node transforms to write instead of the rest transforms (a posed or edited rig: see
    /// [`super::RigPose::locals`]); one per node.
    pub node_transforms: Option<Vec<Trs>>,
    /// Leave the animations out.
    pub without_animations: bool,
}

/// Write [`glb_bytes`] to `path` atomically (a temporary file renamed over the target).
///
/// # Errors
/// [`SkinError::Io`]; [`SkinError::InvalidArgument`] as [`glb_bytes`].
pub fn write_glb(rig: &Rig, options: &GlbOptions, path: impl AsRef<Path>) -> Result<()> {
    let path = path.as_ref();
    let bytes = glb_bytes(rig, options)?;
    let tmp = path.with_extension("glb.partial");
    let io = |source: std::io::Error| SkinError::Io {
        path: path.to_path_buf(),
        message: source.to_string(),
    };
    std::fs::write(&tmp, bytes).map_err(io)?;
    std::fs::rename(&tmp, path).map_err(io)
}

/// [`GlbBuilder::floats`] with its error as [`SkinError::InvalidArgument`].
fn floats(
    bin: &mut GlbBuilder,
    v: &[f32],
    dim: usize,
    kind: &str,
    target: Option<u32>,
    bounds: bool,
    what: &str,
) -> Result<usize> {
    bin.floats(v, dim, kind, target, bounds, what)
        .map_err(SkinError::InvalidArgument)
}

/// Per vertex, at most 8 `(joint, weight)` influences: duplicates merged, zero weights
/// dropped, the largest kept and renormalised (glTF viewers read 4 or 8).
fn compact_influences(rig: &Rig) -> (usize, Vec<[u16; 8]>, Vec<[f32; 8]>) {
    let n = rig.mesh.vertex_count();
    let mut rows = Vec::with_capacity(n);
    let mut width = 4;
    for v in 0..n {
        let mut list: Vec<(u32, f64)> = Vec::new();
        for (j, w) in rig.influences.row(v).filter(|&(_, w)| w > 0.0) {
            match list.iter_mut().find(|e| e.0 == j) {
                Some(e) => e.1 += w,
                None => list.push((j, w)),
            }
        }
        list.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.cmp(&b.0)));
        list.truncate(8);
        width = width.max(if list.len() > 4 { 8 } else { 4 });
        rows.push(list);
    }
    let mut joints = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    for list in rows {
        let sum: f64 = list.iter().map(|e| e.1).sum();
        let mut j = [0u16; 8];
        let mut w = [0f32; 8];
        for (k, &(jj, ww)) in list.iter().enumerate() {
            j[k] = jj as u16;
            w[k] = (ww / sum) as f32;
        }
        if list.is_empty() {
            w[0] = 1.0;
        }
        joints.push(j);
        weights.push(w);
    }
    (width, joints, weights)
}

/// The rig as binary glTF: one mesh (every primitive of [`Rig::primitives`]), one skin, the
/// nodes (a new root node instances the skinned mesh), the animations, a scene, and the
/// model's [`super::Look`]: its vertex attributes (its normals where it has them, none for a
/// glTF model without them, which viewers shade flat, else smooth ones), each primitive's
/// material, and the materials, textures, samplers and images (embedded).
/// Positions, smooth normals, matrices and keys are written in single precision, as glTF
/// stores them. Up to 8 influences per vertex are kept (the largest, renormalised).
///
/// # Errors
/// [`SkinError::InvalidArgument`] for a mesh without triangles, more than 65536 joints, a
/// node that is two joints (bound by several skins with different inverse bind matrices) or
/// `node_transforms` of the wrong length.
pub fn glb_bytes(rig: &Rig, options: &GlbOptions) -> Result<Vec<u8>> {
    let locals = check_writable(rig, options)?;
    let look = &rig.look;
    let mut bin = GlbBuilder::default();
    let influences = compact_influences(rig);
    let normals: Vec<[f32; 3]> = match look.attribute("NORMAL").filter(|a| a.width == 3) {
        Some(a) => a
            .values
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect(),
        None => unit_normals(&rig.mesh),
    };
    let primitives = (0..rig.primitives.len())
        .map(|index| write_primitive(rig, index, &influences, &normals, &mut bin))
        .collect::<Result<Vec<_>>>()?;
    let mut mesh = json!({"name": "skin", "primitives": primitives});
    if !look.morph_weights.is_empty() {
        mesh["weights"] = json!(look.morph_weights);
    }
    let ibm: Vec<f32> = rig
        .inverse_bind
        .iter()
        .flat_map(|m| m.as_mat4().to_cols_array())
        .collect();
    let ibm = floats(
        &mut bin,
        &ibm,
        16,
        "MAT4",
        None,
        false,
        "inverse bind matrices",
    )?;
    let (nodes, roots) = node_tree(rig, &locals);
    let animations = if options.without_animations {
        Vec::new()
    } else {
        write_animations(rig, &mut bin)?
    };
    let images = image_views(look, &mut bin);
    let mut doc = json!({
        "asset": {"version": "2.0", "generator": "deform (cga mesh deformers)"},
        "scene": 0,
        "scenes": [{"nodes": roots}],
        "nodes": nodes,
        "meshes": [mesh],
        "skins": [{"joints": rig.joints, "inverseBindMatrices": ibm}],
    });
    if !animations.is_empty() {
        doc["animations"] = json!(animations);
    }
    write_look(look, images, &mut doc);
    bin.finish(doc).map_err(SkinError::InvalidArgument)
}

/// What glTF (and this writer) cannot hold, refused before anything is written: no
/// triangles, more than 2^16 joints, a joint of several skins, node transforms of another
/// count, a look of another size. Returns each node's local transform.
fn check_writable(rig: &Rig, options: &GlbOptions) -> Result<Vec<Trs>> {
    if rig.mesh.triangle_count() == 0 {
        return Err(SkinError::InvalidArgument(
            "the rig's mesh has no triangles: nothing to write".into(),
        ));
    }
    if rig.joints.len() > u16::MAX as usize + 1 {
        return Err(SkinError::InvalidArgument(format!(
            "{} joints: glTF joint indices are 16-bit here",
            rig.joints.len()
        )));
    }
    // One skin is written, and glTF wants its joints unique: a node that several skins of
    // the file bound with different inverse bind matrices cannot be one joint.
    let mut seen = std::collections::HashSet::new();
    if let Some(&node) = rig.joints.iter().find(|&&n| !seen.insert(n)) {
        return Err(SkinError::InvalidArgument(format!(
            "node {node} ({}) is a joint of several skins with different inverse bind \
             matrices: the rig is written with one skin, whose joints must be unique \
             (write OBJ or PLY instead)",
            rig.nodes[node].name
        )));
    }
    let locals: Vec<Trs> = match &options.node_transforms {
        Some(t) if t.len() != rig.nodes.len() => {
            return Err(SkinError::InvalidArgument(format!(
                "{} node transforms for {} nodes",
                t.len(),
                rig.nodes.len()
            )))
        }
        Some(t) => t.clone(),
        None => rig.nodes.iter().map(|n| n.rest).collect(),
    };
    check_look(rig)?;
    Ok(locals)
}

/// Primitive `index` of the rig: its base positions (the rest shape without the morph
/// targets' default weights), indices, normals, the look's other attributes, joint and
/// weight sets, morph targets and material.
fn write_primitive(
    rig: &Rig,
    index: usize,
    (width, joints, weights): &(usize, Vec<[u16; 8]>, Vec<[f32; 8]>),
    normals: &[[f32; 3]],
    bin: &mut GlbBuilder,
) -> Result<Value> {
    let (look, p) = (&rig.look, &rig.primitives[index]);
    let range = p.vertex_offset..p.vertex_offset + p.vertex_count;
    let mut base = rig.mesh.positions[range.clone()].to_vec();
    let targets: Vec<VertexAttribute> = look
        .attributes
        .iter()
        .filter(|a| parse_target_attribute(&a.name).is_some())
        .map(|a| a.rows(range.clone()))
        .collect();
    morph::displace(&mut base, &targets, &look.morph_weights, -1.0);
    let pos: Vec<f32> = base.iter().flat_map(|x| x.as_vec3().to_array()).collect();
    let position = floats(bin, &pos, 3, "VEC3", Some(34962), true, "POSITION")?;
    let idx: Vec<u8> = rig.mesh.triangles[p.triangle_offset..p.triangle_offset + p.triangle_count]
        .iter()
        .flatten()
        .flat_map(|&i| (i - p.vertex_offset as u32).to_le_bytes())
        .collect();
    let indices = bin.push(
        &idx,
        Some(34963),
        json!({"componentType": 5125, "count": 3 * p.triangle_count, "type": "SCALAR"}),
    );
    let mut attributes = json!({ "POSITION": position });
    let vertex_data = |bin: &mut GlbBuilder, values: &[f32], width: usize, name: &str| {
        let kind = ["SCALAR", "VEC2", "VEC3", "VEC4"][width - 1];
        floats(bin, values, width, kind, Some(34962), false, name)
    };
    if !look.flat {
        let nrm: Vec<f32> = normals[range.clone()].iter().flatten().copied().collect();
        attributes["NORMAL"] = json!(vertex_data(bin, &nrm, 3, "NORMAL")?);
    }
    let plain =
        |a: &&VertexAttribute| a.name != "NORMAL" && parse_target_attribute(&a.name).is_none();
    for a in look.attributes.iter().filter(plain) {
        let values = &a.values[range.start * a.width..range.end * a.width];
        attributes[a.name.as_str()] = json!(vertex_data(bin, values, a.width, &a.name)?);
    }
    for set in 0..width / 4 {
        let j: Vec<u8> = joints[range.clone()]
            .iter()
            .flat_map(|r| r[4 * set..4 * set + 4].iter().flat_map(|x| x.to_le_bytes()))
            .collect();
        let w: Vec<f32> = weights[range.clone()]
            .iter()
            .flat_map(|r| r[4 * set..4 * set + 4].to_vec())
            .collect();
        attributes[format!("JOINTS_{set}")] = json!(bin.push(
            &j,
            Some(34962),
            json!({"componentType": 5123, "count": p.vertex_count, "type": "VEC4"})
        ));
        attributes[format!("WEIGHTS_{set}")] = json!(vertex_data(bin, &w, 4, "WEIGHTS")?);
    }
    let mut primitive = json!({"attributes": attributes, "indices": indices, "mode": 4});
    if !look.morph_weights.is_empty() {
        let count = look.morph_weights.len();
        primitive["targets"] = json!(write_targets(bin, &targets, count, !look.flat)?);
    }
    if let Some(m) = look.primitive_materials.get(index).copied().flatten() {
        primitive["material"] = json!(m);
    }
    Ok(primitive)
}

/// The rig's nodes with their local transforms and children, and the skinned mesh's node;
/// and the scene's roots.
fn node_tree(rig: &Rig, locals: &[Trs]) -> (Vec<Value>, Vec<usize>) {
    let mut nodes: Vec<Value> = rig
        .nodes
        .iter()
        .zip(locals)
        .map(|(n, t)| {
            json!({
                "name": n.name,
                "translation": t.translation.as_vec3().to_array(),
                "rotation": t.rotation.normalize().as_quat().to_array(),
                "scale": t.scale.as_vec3().to_array(),
            })
        })
        .collect();
    for (i, n) in rig.nodes.iter().enumerate() {
        if let Some(p) = n.parent {
            let list = nodes[p]
                .as_object_mut()
                .expect("a node object")
                .entry("children")
                .or_insert_with(|| json!([]));
            list.as_array_mut().expect("an array").push(json!(i));
        }
    }
    let mesh_node = nodes.len();
    nodes.push(json!({"name": "skinned mesh", "mesh": 0, "skin": 0}));
    let roots: Vec<usize> = (0..rig.nodes.len())
        .filter(|&i| rig.nodes[i].parent.is_none())
        .chain([mesh_node])
        .collect();
    (nodes, roots)
}

/// Every animation: a sampler (times, values, interpolation) and a channel per animated
/// property.
fn write_animations(rig: &Rig, bin: &mut GlbBuilder) -> Result<Vec<Value>> {
    rig.animations
        .iter()
        .map(|a| {
            let mut samplers = Vec::new();
            let mut channels = Vec::new();
            for c in &a.channels {
                let times: Vec<f32> = c.times.iter().map(|&t| t as f32).collect();
                let input = floats(bin, &times, 1, "SCALAR", None, true, "animation times")?;
                let (dim, kind, path) = match c.property {
                    Property::Translation => (3, "VEC3", "translation"),
                    Property::Rotation => (4, "VEC4", "rotation"),
                    Property::Scale => (3, "VEC3", "scale"),
                };
                let values: Vec<f32> = c
                    .values
                    .iter()
                    .flat_map(|v| v.as_vec4().to_array()[..dim].to_vec())
                    .collect();
                let output = floats(bin, &values, dim, kind, None, false, "animation values")?;
                let interpolation = match c.interpolation {
                    Interpolation::Linear => "LINEAR",
                    Interpolation::Step => "STEP",
                    Interpolation::CubicSpline => "CUBICSPLINE",
                };
                let target = json!({"node": c.node, "path": path});
                channels.push(json!({"sampler": samplers.len(), "target": target}));
                samplers.push(
                    json!({"input": input, "output": output, "interpolation": interpolation}),
                );
            }
            Ok(json!({"name": a.name, "channels": channels, "samplers": samplers}))
        })
        .collect()
}

/// One primitive's morph targets (`count` of them, from its rows of the target attributes):
/// each its `POSITION` offsets (zeros where the rig has none) and, when the primitive has
/// `normals`, its `NORMAL` offsets where the rig has them.
fn write_targets(
    bin: &mut GlbBuilder,
    rows: &[VertexAttribute],
    count: usize,
    normals: bool,
) -> Result<Vec<Value>> {
    let vertices = rows.first().map_or(0, VertexAttribute::vertex_count);
    (0..count)
        .map(|k| {
            let find = |semantic: &str| {
                rows.iter()
                    .find(|a| parse_target_attribute(&a.name) == Some((k, semantic)))
            };
            let zeros = vec![0.0; 3 * vertices];
            let position = find("POSITION").map_or(&zeros[..], |a| &a.values[..]);
            let mut target = json!({"POSITION": floats(bin, position, 3, "VEC3", Some(34962), true, "morph POSITION")?});
            if let Some(n) = find("NORMAL").filter(|_| normals) {
                target["NORMAL"] = json!(floats(bin, &n.values, 3, "VEC3", Some(34962), false, "morph NORMAL")?);
            }
            Ok(target)
        })
        .collect()
}

/// Refuses a look that does not fit the rig: attributes of another length or width, material
/// indices past the materials.
fn check_look(rig: &Rig) -> Result<()> {
    let n = rig.mesh.vertex_count();
    for a in &rig.look.attributes {
        if !(1..=4).contains(&a.width) || a.values.len() != a.width * n {
            return Err(SkinError::InvalidArgument(format!(
                "attribute {}: {} values of width {} for {n} vertices",
                a.name,
                a.values.len(),
                a.width
            )));
        }
    }
    let targets = rig.look.morph_weights.len();
    if let Some(a) = rig.look.attributes.iter().find(|a| {
        parse_target_attribute(&a.name).is_some_and(|(k, _)| k >= targets || a.width != 3)
    }) {
        return Err(SkinError::InvalidArgument(format!(
            "attribute {}: not one of the {targets} morph targets' offsets",
            a.name
        )));
    }
    let materials = rig.look.materials.len();
    if let Some(m) = rig
        .look
        .primitive_materials
        .iter()
        .flatten()
        .find(|&&m| m >= materials)
    {
        return Err(SkinError::InvalidArgument(format!(
            "material {m} past the {materials} materials"
        )));
    }
    Ok(())
}

/// The images' JSON, their bytes stored as buffer views of `bin`.
fn image_views(look: &super::Look, bin: &mut GlbBuilder) -> Vec<Value> {
    look.images
        .iter()
        .map(|image| {
            let mut json = image.json.clone();
            if let Some(bytes) = &image.bytes {
                json["bufferView"] = json!(bin.view(bytes, None));
            }
            json
        })
        .collect()
}

/// The materials, textures, samplers, images and their extensions, into `doc`.
fn write_look(look: &super::Look, images: Vec<Value>, doc: &mut Value) {
    let lists = [
        ("materials", look.materials.clone()),
        ("textures", look.textures.clone()),
        ("samplers", look.samplers.clone()),
        ("images", images),
    ];
    for (key, list) in lists {
        if !list.is_empty() {
            doc[key] = json!(list);
        }
    }
    if !look.extensions_used.is_empty() {
        doc["extensionsUsed"] = json!(look.extensions_used);
    }
    if !look.extensions_required.is_empty() {
        doc["extensionsRequired"] = json!(look.extensions_required);
    }
}
