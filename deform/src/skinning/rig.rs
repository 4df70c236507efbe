//! The rig: node hierarchy, skin, rest mesh with influences, animations.

use super::{Animation, Influences, Look, SkinError, Trs};
use crate::mesh::Mesh;
use glam::DMat4;

/// Weights down to this (negative) value are rounding noise of a weight solver and read as 0.
pub(crate) const NEGATIVE_WEIGHT_TOLERANCE: f64 = -1e-6;

/// One node of the hierarchy.
#[derive(Clone, Debug, PartialEq)]
pub struct RigNode {
    /// Its name (`node N` when the file gives none).
    pub name: String,
    /// Its parent.
    pub parent: Option<usize>,
    /// Its rest (unanimated) local transform.
    pub rest: Trs,
}

/// Where a glTF primitive's vertices sit in the rig's concatenated mesh.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PrimitiveInfo {
    /// The node instancing the mesh.
    pub node: usize,
    /// The glTF mesh.
    pub mesh: usize,
    /// The primitive within the mesh.
    pub primitive: usize,
    /// First vertex in [`Rig::mesh`].
    pub vertex_offset: usize,
    /// Number of vertices.
    pub vertex_count: usize,
    /// First triangle in [`Rig::mesh`].
    pub triangle_offset: usize,
    /// Number of triangles.
    pub triangle_count: usize,
}

impl PrimitiveInfo {
    /// One primitive holding all of `mesh` (a rig built from one mesh, under node 0).
    pub fn whole(mesh: &Mesh) -> PrimitiveInfo {
        PrimitiveInfo {
            node: 0,
            mesh: 0,
            primitive: 0,
            vertex_offset: 0,
            vertex_count: mesh.vertex_count(),
            triangle_offset: 0,
            triangle_count: mesh.triangle_count(),
        }
    }
}

/// What the loader changed or ignored.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct LoadReport {
    /// Vertices whose weights did not sum to 1 (within 1e-5) and were normalised.
    pub renormalised_vertices: usize,
    /// Things read but not used (morph targets, unskinned meshes, other skins...).
    pub notes: Vec<String>,
}

/// A skinned, animated model.
#[derive(Clone, Debug, PartialEq)]
pub struct Rig {
    /// Every node (joints and their ancestors included).
    pub nodes: Vec<RigNode>,
    /// Nodes ordered parents first.
    pub(crate) order: Vec<usize>,
    /// The skin's joints, as node indices; influences index this list.
    pub joints: Vec<usize>,
    /// One inverse bind matrix per joint (identity where the file gives none).
    pub inverse_bind: Vec<DMat4>,
    /// The rest (bind-space) mesh: every skinned primitive, concatenated.
    pub mesh: Mesh,
    /// Per-vertex influences.
    pub influences: Influences,
    /// The glTF primitives behind [`Rig::mesh`] (one entry for libigl rigs).
    pub primitives: Vec<PrimitiveInfo>,
    /// Animations.
    pub animations: Vec<Animation>,
    /// What the loader changed or ignored.
    pub report: LoadReport,
    /// What the model looks like (UVs, colours, materials, textures), kept for writing.
    pub look: Look,
}

impl Rig {
    /// Assemble a rig, checking the hierarchy (no cycles, parents in range), the joint
    /// indices of the influences and every transform; normalises the weights.
    ///
    /// # Errors
    /// [`SkinError`] naming the offending node, joint or vertex.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        nodes: Vec<RigNode>,
        joints: Vec<usize>,
        inverse_bind: Vec<DMat4>,
        mesh: Mesh,
        mut influences: Influences,
        primitives: Vec<PrimitiveInfo>,
        animations: Vec<Animation>,
        mut report: LoadReport,
    ) -> Result<Rig, SkinError> {
        let order = hierarchy_order(&nodes)?;
        if joints.is_empty() {
            return Err(SkinError::NoSkin("the skin has no joints".into()));
        }
        if let Some(&j) = joints.iter().find(|&&j| j >= nodes.len()) {
            return Err(SkinError::NoJoint(format!("node {j} (past the last node)")));
        }
        if inverse_bind.len() != joints.len() {
            return Err(SkinError::BadTransform {
                what: "inverse bind matrices".into(),
                message: format!("{} for {} joints", inverse_bind.len(), joints.len()),
            });
        }
        if let Some(j) = inverse_bind.iter().position(|m| !m.is_finite()) {
            return Err(SkinError::BadTransform {
                what: format!("inverse bind matrix of joint {j}"),
                message: "not finite".into(),
            });
        }
        if influences.vertex_count() != mesh.vertex_count() {
            return Err(SkinError::NoSkin(format!(
                "{} vertices but influences for {}",
                mesh.vertex_count(),
                influences.vertex_count()
            )));
        }
        for (k, (&j, w)) in influences
            .joints
            .iter()
            .zip(&mut influences.weights)
            .enumerate()
        {
            let vertex = k / influences.width.max(1);
            if *w < 0.0 && *w >= NEGATIVE_WEIGHT_TOLERANCE {
                *w = 0.0;
            }
            let w = *w;
            if !(w.is_finite() && w >= 0.0) {
                return Err(SkinError::BadWeight { vertex, weight: w });
            }
            if j as usize >= joints.len() {
                return Err(SkinError::JointOutOfRange {
                    vertex,
                    joint: j,
                    joints: joints.len(),
                });
            }
        }
        report.renormalised_vertices += influences.normalise();
        for a in &animations {
            if let Some(c) = a.channels.iter().find(|c| c.node >= nodes.len()) {
                return Err(SkinError::BadTransform {
                    what: format!("animation {:?}", a.name),
                    message: format!("a channel targets node {}, past the last node", c.node),
                });
            }
        }
        Ok(Rig {
            nodes,
            order,
            joints,
            inverse_bind,
            mesh,
            influences,
            primitives,
            animations,
            report,
            look: Look::default(),
        })
    }

    /// The rest transform of the skinned node: it places a mesh of the rest (mesh) space in
    /// world space, as a viewer shows the model at rest, so a Z-up glTF model stands upright
    /// like the posed meshes the skinning formula gives.
    pub fn rest_placement(&self) -> Result<glam::DMat4, SkinError> {
        let rest = self.pose(None, 0.0, &[])?;
        Ok(self
            .primitives
            .first()
            .map_or(glam::DMat4::IDENTITY, |p| rest.globals[p.node]))
    }

    /// The index of an animation given by name or by index.
    ///
    /// # Errors
    /// [`SkinError::NoAnimation`].
    pub fn animation_index(&self, name_or_index: &str) -> Result<usize, SkinError> {
        if self.animations.is_empty() {
            return Err(SkinError::NoAnimation(format!(
                "{name_or_index:?}: this model has no animations (pose it at rest: no \
                 --animation or --time)"
            )));
        }
        if let Some(i) = self.animations.iter().position(|a| a.name == name_or_index) {
            return Ok(i);
        }
        match name_or_index.parse::<usize>() {
            Ok(i) if i < self.animations.len() => Ok(i),
            _ => Err(SkinError::NoAnimation(format!(
                "{name_or_index:?} (have: {})",
                self.animations
                    .iter()
                    .enumerate()
                    .map(|(i, a)| format!("{i} {:?}", a.name))
                    .collect::<Vec<_>>()
                    .join(", ")
            ))),
        }
    }

    /// The skin joint (index into [`Rig::joints`]) given by node name or joint index.
    ///
    /// # Errors
    /// [`SkinError::NoJoint`].
    pub fn joint_index(&self, name_or_index: &str) -> Result<usize, SkinError> {
        if let Some(j) = self
            .joints
            .iter()
            .position(|&n| self.nodes[n].name == name_or_index)
        {
            return Ok(j);
        }
        match name_or_index.parse::<usize>() {
            Ok(j) if j < self.joints.len() => Ok(j),
            _ => Err(SkinError::NoJoint(format!("{name_or_index:?}"))),
        }
    }
}

/// Nodes ordered parents first.
fn hierarchy_order(nodes: &[RigNode]) -> Result<Vec<usize>, SkinError> {
    let n = nodes.len();
    let mut children = vec![Vec::new(); n];
    let mut roots = Vec::new();
    for (i, node) in nodes.iter().enumerate() {
        match node.parent {
            Some(p) if p >= n => {
                return Err(SkinError::BadTransform {
                    what: format!("node {i}"),
                    message: format!("parent {p} past the last node"),
                })
            }
            Some(p) => children[p].push(i),
            None => roots.push(i),
        }
    }
    let mut order = Vec::with_capacity(n);
    let mut stack = roots;
    while let Some(i) = stack.pop() {
        order.push(i);
        stack.extend(children[i].iter().rev());
    }
    if order.len() != n {
        return Err(SkinError::BadTransform {
            what: "node hierarchy".into(),
            message: "has a cycle".into(),
        });
    }
    Ok(order)
}
