//! The indices of a glTF document checked before anything follows them: the `gltf` crate's
//! own checks miss some (an animation targeting a missing node), and its accessors then panic.

use gltf::json::validation::Checked;
use gltf::json::Root;

/// `Err` naming `what` unless index `i` is below `n`.
fn index_in(what: String, i: usize, n: usize) -> Result<(), String> {
    if i < n {
        Ok(())
    } else {
        Err(format!(
            "{what} refers to index {i}, past the {n} there are"
        ))
    }
}

/// Check every index this crate follows (nodes, meshes, skins, accessors, views, buffers,
/// animation samplers and targets) and every enum it reads.
pub(crate) fn check_indices(root: &Root) -> Result<(), String> {
    check_data(root)?;
    check_nodes_and_skins(root)?;
    check_meshes(root)?;
    check_animations(root)
}

/// Buffer views' buffers, accessors' views (sparse ones included).
fn check_data(root: &Root) -> Result<(), String> {
    let (views, buffers) = (root.buffer_views.len(), root.buffers.len());
    for (i, v) in root.buffer_views.iter().enumerate() {
        index_in(
            format!("bufferViews[{i}].buffer"),
            v.buffer.value(),
            buffers,
        )?;
    }
    for (i, a) in root.accessors.iter().enumerate() {
        if let Some(v) = a.buffer_view {
            index_in(format!("accessors[{i}].bufferView"), v.value(), views)?;
        }
        if let Some(s) = &a.sparse {
            index_in(
                format!("accessors[{i}].sparse.indices.bufferView"),
                s.indices.buffer_view.value(),
                views,
            )?;
            index_in(
                format!("accessors[{i}].sparse.values.bufferView"),
                s.values.buffer_view.value(),
                views,
            )?;
        }
    }
    Ok(())
}

/// Nodes' children, meshes and skins; skins' joints and inverse bind matrices.
fn check_nodes_and_skins(root: &Root) -> Result<(), String> {
    let (nodes, meshes, skins) = (root.nodes.len(), root.meshes.len(), root.skins.len());
    for (i, n) in root.nodes.iter().enumerate() {
        for c in n.children.iter().flatten() {
            index_in(format!("nodes[{i}].children"), c.value(), nodes)?;
        }
        if let Some(m) = n.mesh {
            index_in(format!("nodes[{i}].mesh"), m.value(), meshes)?;
        }
        if let Some(s) = n.skin {
            index_in(format!("nodes[{i}].skin"), s.value(), skins)?;
        }
    }
    for (i, s) in root.skins.iter().enumerate() {
        for j in &s.joints {
            index_in(format!("skins[{i}].joints"), j.value(), nodes)?;
        }
        if let Some(a) = s.inverse_bind_matrices {
            index_in(
                format!("skins[{i}].inverseBindMatrices"),
                a.value(),
                root.accessors.len(),
            )?;
        }
    }
    Ok(())
}

/// Primitives' attributes, indices and morph targets; their modes.
fn check_meshes(root: &Root) -> Result<(), String> {
    let accessors = root.accessors.len();
    for (i, m) in root.meshes.iter().enumerate() {
        for (k, p) in m.primitives.iter().enumerate() {
            for a in p.attributes.values().chain(p.indices.as_ref()) {
                index_in(format!("meshes[{i}].primitives[{k}]"), a.value(), accessors)?;
            }
            for (t, target) in p.targets.iter().flatten().enumerate() {
                let attributes = [&target.positions, &target.normals, &target.tangents];
                for a in attributes.into_iter().flatten() {
                    let what = format!("meshes[{i}].primitives[{k}].targets[{t}]");
                    index_in(what, a.value(), accessors)?;
                }
            }
            if matches!(p.mode, Checked::Invalid) {
                return Err(format!("meshes[{i}].primitives[{k}].mode is invalid"));
            }
        }
    }
    Ok(())
}

/// Animation samplers' accessors and interpolations; channels' samplers, nodes and paths.
fn check_animations(root: &Root) -> Result<(), String> {
    let (nodes, accessors) = (root.nodes.len(), root.accessors.len());
    for (i, a) in root.animations.iter().enumerate() {
        for (k, s) in a.samplers.iter().enumerate() {
            index_in(
                format!("animations[{i}].samplers[{k}].input"),
                s.input.value(),
                accessors,
            )?;
            index_in(
                format!("animations[{i}].samplers[{k}].output"),
                s.output.value(),
                accessors,
            )?;
            if matches!(s.interpolation, Checked::Invalid) {
                return Err(format!(
                    "animations[{i}].samplers[{k}].interpolation is invalid"
                ));
            }
        }
        for (k, c) in a.channels.iter().enumerate() {
            index_in(
                format!("animations[{i}].channels[{k}].sampler"),
                c.sampler.value(),
                a.samplers.len(),
            )?;
            index_in(
                format!("animations[{i}].channels[{k}].target.node"),
                c.target.node.value(),
                nodes,
            )?;
            if matches!(c.target.path, Checked::Invalid) {
                return Err(format!(
                    "animations[{i}].channels[{k}].target.path is invalid"
                ));
            }
        }
    }
    Ok(())
}
