//! Morph targets (blend shapes) of glTF primitives. Each target's position and normal offsets
//! are kept as vertex attributes of the rig's [`super::Look`] (`TARGET{k}_POSITION`,
//! `TARGET{k}_NORMAL`), so surgery interpolates them at the vertices it makes, as it does UVs.
//! The default weights (the node's `weights`, else the mesh's) are applied to the rest shape,
//! as three.js applies them before skinning; a written `.glb` stores the base shape again with
//! every target and those weights. Animated morph weights are not played (a note says so).

use super::accessor::Buffers;
use super::look::VertexAttribute;
use super::SkinError;
use glam::DVec3;

/// The attribute name of target `k`'s offsets of `semantic` (`POSITION` or `NORMAL`).
pub(crate) fn target_attribute(k: usize, semantic: &str) -> String {
    format!("TARGET{k}_{semantic}")
}

/// The target index and semantic of a target attribute name; `None` for other attributes.
pub(crate) fn parse_target_attribute(name: &str) -> Option<(usize, &str)> {
    let rest = name.strip_prefix("TARGET")?;
    let (k, semantic) = rest.split_once('_')?;
    Some((k.parse().ok()?, semantic))
}

/// The default weights of a mesh instance: the node's, else the mesh's, else zeros; one per
/// target of the mesh.
pub(crate) fn default_weights(node: &gltf::Node, mesh: &gltf::Mesh, targets: usize) -> Vec<f32> {
    let given = node.weights().or_else(|| mesh.weights()).unwrap_or(&[]);
    (0..targets)
        .map(|k| given.get(k).copied().unwrap_or(0.0))
        .collect()
}

/// The morph targets of primitive `p` (`count` vertices) as attributes numbered from `first`:
/// position offsets, and normal offsets where the target has them.
///
/// # Errors
/// [`SkinError::Data`] for a target accessor of another length or with a non-finite value.
pub(crate) fn primitive_targets(
    p: &gltf::Primitive,
    first: usize,
    count: usize,
    buffers: &Buffers,
    name: &str,
) -> Result<Vec<VertexAttribute>, SkinError> {
    let mut out = Vec::new();
    for (t, target) in p.morph_targets().enumerate() {
        for (semantic, accessor) in [
            ("POSITION", target.positions()),
            ("NORMAL", target.normals()),
        ] {
            let Some(accessor) = accessor else { continue };
            let (v, width) = buffers.read(&accessor, name)?;
            let bad = |what: &str| SkinError::Data {
                name: name.to_string(),
                message: format!(
                    "primitive {} morph target {t}: {semantic} offsets {what}",
                    p.index()
                ),
            };
            if width != 3 || v.len() != 3 * count {
                return Err(bad(&format!(
                    "have {} values of width {width} for {count} vertices",
                    v.len()
                )));
            }
            if v.iter().any(|x| !x.is_finite()) {
                return Err(bad("are not finite"));
            }
            out.push(VertexAttribute {
                name: target_attribute(first + t, semantic),
                width: 3,
                values: v.iter().map(|&x| x as f32).collect(),
            });
        }
    }
    Ok(out)
}

/// The shape the weights give: `positions` (of the vertices the attributes cover) moved by
/// `sign` times the weighted position offsets.
pub(crate) fn displace(
    positions: &mut [DVec3],
    targets: &[VertexAttribute],
    weights: &[f32],
    sign: f64,
) {
    for a in targets {
        let Some((k, "POSITION")) = parse_target_attribute(&a.name) else {
            continue;
        };
        let w = sign * f64::from(weights.get(k).copied().unwrap_or(0.0));
        if w == 0.0 {
            continue;
        }
        for (p, d) in positions.iter_mut().zip(a.values.chunks_exact(3)) {
            *p += w * DVec3::new(f64::from(d[0]), f64::from(d[1]), f64::from(d[2]));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_others_are_not_targets() {
        assert_eq!(
            parse_target_attribute(&target_attribute(12, "NORMAL")),
            Some((12, "NORMAL"))
        );
        assert_eq!(parse_target_attribute("TEXCOORD_0"), None);
        assert_eq!(parse_target_attribute("TARGETx_POSITION"), None);
    }

    #[test]
    fn displacement_is_the_weighted_sum_and_undoes() {
        let a = VertexAttribute {
            name: target_attribute(1, "POSITION"),
            width: 3,
            values: vec![1.0, 0.0, 0.0, 0.0, 2.0, 0.0],
        };
        let n = VertexAttribute {
            name: target_attribute(1, "NORMAL"),
            width: 3,
            values: vec![5.0; 6],
        };
        let mut p = vec![DVec3::ZERO, DVec3::ONE];
        let targets = [a, n];
        displace(&mut p, &targets, &[0.0, 0.5], 1.0);
        assert_eq!(
            p,
            vec![DVec3::new(0.5, 0.0, 0.0), DVec3::new(1.0, 2.0, 1.0)]
        );
        displace(&mut p, &targets, &[0.0, 0.5], -1.0);
        assert_eq!(p, vec![DVec3::ZERO, DVec3::ONE]);
    }
}
