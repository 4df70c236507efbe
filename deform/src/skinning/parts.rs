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
        let width = parts.iter().map(|p| p.influences.width).max().unwrap_or(4);
        let keep_attributes = parts.iter().all(|p| p.sources.is_some());
        let node = self.primitives.first().map_or(0, |p| p.node);
        let mut joined = JoinedParts::new(&self.look, node, width, keep_attributes);
        let mut part_start = 0;
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
            let groups = self.triangle_primitives(part);
            let mut order = groups.clone();
            order.sort_unstable();
            order.dedup();
            for &g in &order {
                let tris: Vec<[u32; 3]> = m
                    .triangles
                    .iter()
                    .zip(&groups)
                    .filter(|(_, &h)| h == g)
                    .map(|(t, _)| *t)
                    .collect();
                // One group keeps every vertex in order; several take the vertices they use.
                let (local, used) = if order.len() == 1 {
                    every_vertex(m.vertex_count())
                } else {
                    used_vertices(m.vertex_count(), &tris)
                };
                let material = self.look.primitive_materials.get(g).copied().flatten();
                joined.push_primitive(k, part, &tris, (&local, &used), &looks, material);
                joined.trace.extend(used.iter().map(|&v| part_start + v));
            }
            part_start += part.mesh.vertex_count();
        }
        let mut rig = Rig::new(
            self.nodes.clone(),
            self.joints.clone(),
            self.inverse_bind.clone(),
            joined.mesh,
            joined.influences,
            joined.primitives,
            self.animations.clone(),
            self.report.clone(),
        )?;
        rig.look = Look {
            attributes: joined.attributes,
            primitive_materials: joined.materials,
            ..self.look.clone()
        };
        Ok((rig, joined.trace))
    }

    /// For each triangle of `part`, the original primitive its first corner comes from (0
    /// without sources).
    fn triangle_primitives(&self, part: &RigPart) -> Vec<usize> {
        let group_of = |t: &[u32; 3]| match part.sources {
            Some(s) => s
                .row(t[0] as usize)
                .max_by(|a, b| a.1.total_cmp(&b.1))
                .map_or(0, |(v, _)| self.primitive_of(v as usize)),
            None => 0,
        };
        part.mesh.triangles.iter().map(group_of).collect()
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

/// Every vertex of a part of `n`, in order: (part vertex -> primitive vertex, primitive
/// vertex -> part vertex).
fn every_vertex(n: usize) -> (Vec<u32>, Vec<usize>) {
    ((0..n as u32).collect(), (0..n).collect())
}

/// The vertices of a part of `n` that `tris` use, in order of first use: (part vertex ->
/// primitive vertex or `u32::MAX`, primitive vertex -> part vertex).
fn used_vertices(n: usize, tris: &[[u32; 3]]) -> (Vec<u32>, Vec<usize>) {
    let mut local = vec![u32::MAX; n];
    let mut used = Vec::new();
    for &v in tris.iter().flatten() {
        if local[v as usize] == u32::MAX {
            local[v as usize] = used.len() as u32;
            used.push(v as usize);
        }
    }
    (local, used)
}

/// The new rig's mesh, influences, look and primitives as [`Rig::with_parts_traced`] joins the
/// parts' primitives, and the trace of each new vertex to the parts' vertices.
struct JoinedParts {
    /// The node every new primitive is on (the first original primitive's).
    node: usize,
    mesh: Mesh,
    influences: Influences,
    attributes: Vec<VertexAttribute>,
    primitives: Vec<PrimitiveInfo>,
    materials: Vec<Option<usize>>,
    trace: Vec<usize>,
}

impl JoinedParts {
    /// Nothing joined yet: primitives on `node`, influences `width` wide, the look's
    /// attributes (without values) where `keep_attributes`.
    fn new(look: &Look, node: usize, width: usize, keep_attributes: bool) -> JoinedParts {
        let attributes = if keep_attributes {
            look.attributes
                .iter()
                .map(|a| VertexAttribute {
                    values: Vec::new(),
                    ..a.clone()
                })
                .collect()
        } else {
            Vec::new()
        };
        JoinedParts {
            node,
            mesh: Mesh::new(Vec::new(), Vec::new()),
            influences: Influences {
                width,
                ..Influences::default()
            },
            attributes,
            primitives: Vec::new(),
            materials: Vec::new(),
            trace: Vec::new(),
        }
    }

    /// Appends one primitive of part `k`: its triangles `tris`, the part's vertices `used`
    /// (`local` maps them back), their influences and attributes (`looks`), its material.
    fn push_primitive(
        &mut self,
        k: usize,
        part: &RigPart,
        tris: &[[u32; 3]],
        (local, used): (&[u32], &[usize]),
        looks: &[VertexAttribute],
        material: Option<usize>,
    ) {
        let offset = self.mesh.positions.len();
        self.primitives.push(PrimitiveInfo {
            node: self.node,
            mesh: 0,
            primitive: k,
            vertex_offset: offset,
            vertex_count: used.len(),
            triangle_offset: self.mesh.triangles.len(),
            triangle_count: tris.len(),
        });
        self.materials.push(material);
        let m = part.mesh;
        self.mesh
            .positions
            .extend(used.iter().map(|&v| m.positions[v]));
        self.mesh.triangles.extend(
            tris.iter()
                .map(|t| t.map(|v| local[v as usize] + offset as u32)),
        );
        let width = self.influences.width;
        for &v in used {
            let row: Vec<(u32, f64)> = part.influences.row(v).collect();
            for c in 0..width {
                let (j, w) = row.get(c).copied().unwrap_or((0, 0.0));
                self.influences.joints.push(j);
                self.influences.weights.push(w);
            }
        }
        for (out, a) in self.attributes.iter_mut().zip(looks) {
            for &v in used {
                out.values.extend_from_slice(a.row(v));
            }
        }
    }
}
