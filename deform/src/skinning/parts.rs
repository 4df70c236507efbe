//! A rig made from another by surgery: the same nodes, skin and animations over new mesh parts,
//! each split by the material its vertices come from, with the look's attributes interpolated
//! from each vertex's sources and caps given planar texture coordinates.

use super::influences::Influences;
use super::look::{planar_uvs, Look, VertexAttribute};
use super::rig::{PrimitiveInfo, Rig};
use super::SkinError;
use crate::mesh::Mesh;
use glam::DVec3;

/// One part of a rig made by [`Rig::with_parts`]: a cut piece, a torn or drilled mesh, or a
/// cap.
#[derive(Clone, Copy, Debug)]
pub struct RigPart<'a> {
    /// The rest mesh.
    pub mesh: &'a Mesh,
    /// Its influences, one row per vertex.
    pub influences: &'a Influences,
    /// Where each vertex comes from: rows of `(vertex of the original rig's mesh,
    /// coefficient)` ([`crate::surgery::SkinnedMesh::sources`]). `None`: the look's vertex
    /// attributes cannot follow and are left out of the new rig.
    pub sources: Option<&'a Influences>,
    /// `Some(normal)` for a flat cap closing a cut (its plane's unit normal): its texture
    /// coordinates are a planar projection covering the UVs of its rim ([`planar_uvs`]), its
    /// normals the cap's own.
    pub cap: Option<DVec3>,
}

impl<'a> RigPart<'a> {
    /// A part with its sources.
    pub fn new(mesh: &'a Mesh, influences: &'a Influences, sources: &'a Influences) -> Self {
        RigPart {
            mesh,
            influences,
            sources: Some(sources),
            cap: None,
        }
    }
}

impl Rig {
    /// The original primitive holding vertex `v` of [`Rig::mesh`].
    fn primitive_of(&self, v: usize) -> usize {
        self.primitives
            .iter()
            .position(|p| (p.vertex_offset..p.vertex_offset + p.vertex_count).contains(&v))
            .unwrap_or(0)
    }

    /// The same rig (nodes, skin, animations) with its mesh replaced by `parts`, in order: how
    /// a cut, torn or drilled mesh stays animatable. A part whose triangles come from several
    /// original primitives becomes one primitive per original primitive, with its material;
    /// [`PrimitiveInfo::primitive`] of each new primitive is the index of its part. The look's
    /// vertex attributes follow each vertex's sources (all parts must have them).
    ///
    /// # Errors
    /// As [`Rig::new`] (influences of another length, joint indices past the skin), and
    /// [`SkinError::InvalidArgument`] for sources of another length or past the mesh.
    pub fn with_parts(&self, parts: &[RigPart]) -> Result<Rig, SkinError> {
        self.with_parts_traced(parts).map(|(rig, _)| rig)
    }

    /// [`Rig::with_parts`], and for each vertex of the new rig the vertex of the parts it is
    /// (an index into the parts' vertices, concatenated in order): a part split by primitive
    /// has its vertices regrouped (and a vertex on two primitives' border repeated), so
    /// per-vertex values of the parts (a surgery's [`crate::surgery::VertexOrigin`]) map to
    /// the new rig through it.
    ///
    /// # Errors
    /// As [`Rig::with_parts`].
    pub fn with_parts_traced(&self, parts: &[RigPart]) -> Result<(Rig, Vec<usize>), SkinError> {
        let mut trace = Vec::new();
        let mut part_start = 0;
        let width = parts.iter().map(|p| p.influences.width).max().unwrap_or(4);
        let mut mesh = Mesh::new(Vec::new(), Vec::new());
        let mut influences = Influences {
            width,
            ..Influences::default()
        };
        let keep_attributes = parts.iter().all(|p| p.sources.is_some());
        let mut attributes: Vec<VertexAttribute> = if keep_attributes {
            self.look
                .attributes
                .iter()
                .map(|a| VertexAttribute {
                    values: Vec::new(),
                    ..a.clone()
                })
                .collect()
        } else {
            Vec::new()
        };
        let node = self.primitives.first().map_or(0, |p| p.node);
        let mut primitives = Vec::new();
        let mut materials = Vec::new();
        for (k, part) in parts.iter().enumerate() {
            let m = part.mesh;
            if part.influences.vertex_count() != m.vertex_count() {
                return Err(SkinError::NoSkin(format!(
                    "part {k}: {} influence rows for {} vertices",
                    part.influences.vertex_count(),
                    m.vertex_count()
                )));
            }
            let looks = match part.sources {
                Some(s) if keep_attributes => self.part_attributes(k, part, s)?,
                _ => Vec::new(),
            };
            // Triangles by the original primitive their first corner comes from.
            let group_of = |t: &[u32; 3]| match part.sources {
                Some(s) => s
                    .row(t[0] as usize)
                    .max_by(|a, b| a.1.total_cmp(&b.1))
                    .map_or(0, |(v, _)| self.primitive_of(v as usize)),
                None => 0,
            };
            let groups: Vec<usize> = m.triangles.iter().map(group_of).collect();
            let mut order = groups.clone();
            order.sort_unstable();
            order.dedup();
            let order_len = order.len();
            for g in order {
                let tris: Vec<[u32; 3]> = m
                    .triangles
                    .iter()
                    .zip(&groups)
                    .filter(|(_, &h)| h == g)
                    .map(|(t, _)| *t)
                    .collect();
                // One group keeps every vertex in order; several take the vertices they use.
                let (local, used): (Vec<u32>, Vec<usize>) = if order_len == 1 {
                    (
                        (0..m.vertex_count() as u32).collect(),
                        (0..m.vertex_count()).collect(),
                    )
                } else {
                    let mut local = vec![u32::MAX; m.vertex_count()];
                    let mut used = Vec::new();
                    for &v in tris.iter().flatten() {
                        if local[v as usize] == u32::MAX {
                            local[v as usize] = used.len() as u32;
                            used.push(v as usize);
                        }
                    }
                    (local, used)
                };
                let offset = mesh.positions.len();
                primitives.push(PrimitiveInfo {
                    node,
                    mesh: 0,
                    primitive: k,
                    vertex_offset: offset,
                    vertex_count: used.len(),
                    triangle_offset: mesh.triangles.len(),
                    triangle_count: tris.len(),
                });
                materials.push(self.look.primitive_materials.get(g).copied().flatten());
                mesh.positions.extend(used.iter().map(|&v| m.positions[v]));
                trace.extend(used.iter().map(|&v| part_start + v));
                mesh.triangles.extend(
                    tris.iter()
                        .map(|t| t.map(|v| local[v as usize] + offset as u32)),
                );
                for &v in &used {
                    let row: Vec<(u32, f64)> = part.influences.row(v).collect();
                    for c in 0..width {
                        let (j, w) = row.get(c).copied().unwrap_or((0, 0.0));
                        influences.joints.push(j);
                        influences.weights.push(w);
                    }
                }
                for (out, a) in attributes.iter_mut().zip(&looks) {
                    for &v in &used {
                        out.values.extend_from_slice(a.row(v));
                    }
                }
            }
            part_start += m.vertex_count();
        }
        let mut rig = Rig::new(
            self.nodes.clone(),
            self.joints.clone(),
            self.inverse_bind.clone(),
            mesh,
            influences,
            primitives,
            self.animations.clone(),
            self.report.clone(),
        )?;
        rig.look = Look {
            attributes,
            primitive_materials: materials,
            ..self.look.clone()
        };
        Ok((rig, trace))
    }

    /// The look's attributes over part `k`'s vertices: interpolated from `sources`, and on a
    /// cap planar UVs and the cap's own normals.
    fn part_attributes(
        &self,
        k: usize,
        part: &RigPart,
        sources: &Influences,
    ) -> Result<Vec<VertexAttribute>, SkinError> {
        let n = self.mesh.vertex_count();
        if sources.vertex_count() != part.mesh.vertex_count() {
            return Err(SkinError::InvalidArgument(format!(
                "part {k}: {} source rows for {} vertices",
                sources.vertex_count(),
                part.mesh.vertex_count()
            )));
        }
        if let Some(&v) = sources.joints.iter().find(|&&v| v as usize >= n) {
            return Err(SkinError::InvalidArgument(format!(
                "part {k}: source vertex {v} is past the rig's {n} vertices"
            )));
        }
        let mut out: Vec<VertexAttribute> = self
            .look
            .attributes
            .iter()
            .map(|a| a.interpolated(sources))
            .collect();
        if let Some(normal) = part.cap {
            for a in &mut out {
                if a.name.starts_with("TEXCOORD_") && a.width == 2 {
                    let rim: Vec<[f32; 2]> =
                        a.values.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
                    let uv = planar_uvs(&part.mesh.positions, normal, &rim);
                    a.values = uv.into_iter().flatten().collect();
                } else if a.name == "NORMAL" && a.width == 3 {
                    let own = part.mesh.vertex_normals();
                    a.values = own
                        .iter()
                        .flat_map(|n| {
                            let n = if n.length_squared() > 0.0 { *n } else { normal };
                            n.as_vec3().to_array()
                        })
                        .collect();
                }
            }
        }
        Ok(out)
    }
}
