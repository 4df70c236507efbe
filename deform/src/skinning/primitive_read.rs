//! One glTF primitive read into the rig's mesh: its positions, triangles and skin influences
//! (up to two JOINTS/WEIGHTS sets, or a rigid binding to its node's joint).

use super::accessor::{Buffers, Layout};
use super::influences::Influences;
use super::rig::PrimitiveInfo;
use super::SkinError;
use crate::mesh::Mesh;
use glam::DVec3;

/// Append one primitive's positions and triangles to `mesh`; its influences, their joint
/// indices mapped to the rig's by `remap` (a rigid primitive's one joint: weight 1 on
/// `remap[0]`). `quantized`: the document uses `KHR_mesh_quantization`, so positions may be
/// integers.
pub(super) fn read_primitive(
    p: &gltf::Primitive,
    buffers: &Buffers,
    name: &str,
    quantized: bool,
    remap: &[u32],
    mesh: &mut Mesh,
) -> Result<(PrimitiveInfo, Influences), SkinError> {
    let data = |message: String| SkinError::Data {
        name: name.to_string(),
        message,
    };
    let pos = p
        .get(&gltf::Semantic::Positions)
        .ok_or_else(|| data(format!("primitive {}: no POSITION", p.index())))?;
    let layout = if quantized {
        &Layout::QUANTIZED_POSITION
    } else {
        &Layout::POSITION
    };
    let (v, _) = buffers.read_as(&pos, name, layout)?;
    let offset = mesh.positions.len();
    let count = v.len() / 3;
    let positions: Vec<DVec3> = v.chunks_exact(3).map(DVec3::from_slice).collect();
    if let Some(i) = positions.iter().position(|x| !x.is_finite()) {
        return Err(data(format!(
            "vertex {}: position is not finite",
            offset + i
        )));
    }
    let indices: Vec<u32> = match p.indices() {
        Some(a) => buffers
            .read_as(&a, name, &Layout::INDICES)?
            .0
            .iter()
            .map(|&x| x as u32)
            .collect(),
        None => (0..count as u32).collect(),
    };
    if !indices.len().is_multiple_of(3) {
        return Err(data(format!(
            "{} indices: not whole triangles",
            indices.len()
        )));
    }
    if let Some(&i) = indices.iter().find(|&&i| i as usize >= count) {
        return Err(data(format!(
            "index {i} past the primitive's {count} vertices"
        )));
    }
    let triangle_offset = mesh.triangles.len();
    mesh.positions.extend(positions);
    mesh.triangles.extend(indices.chunks_exact(3).map(|t| {
        [
            t[0] + offset as u32,
            t[1] + offset as u32,
            t[2] + offset as u32,
        ]
    }));
    let info = PrimitiveInfo {
        node: 0,
        mesh: 0,
        primitive: 0,
        vertex_offset: offset,
        vertex_count: count,
        triangle_offset,
        triangle_count: indices.len() / 3,
    };
    let influences = read_influences(p, buffers, name, remap, offset, count)?;
    Ok((info, influences))
}

/// The primitive's skin influences (its `count` vertices from `offset` in the rig): up to
/// two JOINTS/WEIGHTS sets, joints remapped to the rig's list; a primitive without joints on
/// a node of one joint is bound rigidly to it.
fn read_influences(
    p: &gltf::Primitive,
    buffers: &Buffers,
    name: &str,
    remap: &[u32],
    offset: usize,
    count: usize,
) -> Result<Influences, SkinError> {
    let data = |message: String| SkinError::Data {
        name: name.to_string(),
        message,
    };
    let rigid = p.get(&gltf::Semantic::Joints(0)).is_none() && remap.len() == 1;
    if rigid {
        let influences = Influences {
            width: 1,
            joints: vec![remap[0]; count],
            weights: vec![1.0; count],
        };
        return Ok(influences);
    }
    let sets: Vec<(Vec<f64>, Vec<f64>)> = (0..2)
        .map_while(|s| {
            let j = p.get(&gltf::Semantic::Joints(s))?;
            let w = p.get(&gltf::Semantic::Weights(s))?;
            Some((j, w))
        })
        .map(|(j, w)| {
            Ok((
                buffers.read_as(&j, name, &Layout::JOINTS)?.0,
                buffers.read_as(&w, name, &Layout::WEIGHTS)?.0,
            ))
        })
        .collect::<Result<_, SkinError>>()?;
    if sets.is_empty() {
        return Err(SkinError::NoSkin(format!(
            "{name}: primitive {} has no JOINTS_0/WEIGHTS_0",
            p.index()
        )));
    }
    for (j, w) in &sets {
        if j.len() != 4 * count || w.len() != 4 * count {
            return Err(data("JOINTS/WEIGHTS are not VEC4 per vertex".into()));
        }
    }
    let width = 4 * sets.len();
    let mut influences = Influences {
        width,
        joints: Vec::with_capacity(width * count),
        weights: Vec::with_capacity(width * count),
    };
    for v in 0..count {
        for (j, w) in &sets {
            for k in 0..4 {
                let (joint, weight) = (j[4 * v + k], w[4 * v + k]);
                // A zero weight's joint does not matter: keep it in range.
                let joint = if weight == 0.0 {
                    remap[0]
                } else {
                    *remap
                        .get(joint as usize)
                        .ok_or(SkinError::JointOutOfRange {
                            vertex: offset + v,
                            joint: joint as u32,
                            joints: remap.len(),
                        })?
                };
                influences.joints.push(joint);
                influences.weights.push(weight);
            }
        }
    }
    Ok(influences)
}
