//! Cutting skinned meshes so that they stay animatable (second paper, section 4.2).
//!
//! [`Surgery::new`] binds a skinned mesh once: it checks that the mesh is an edge-manifold
//! triangle mesh with finite positions and influences for every vertex, and builds a
//! [`FaceBvh`] over its triangles. [`Surgery::cut`] then cuts it by a `cga` plane
//! (Algorithm 1): vertices are classified by the CGA point-plane predicate `X . pi`, vertices
//! closer to the plane than a fraction [`CutOptions::snap`] of a crossing edge are snapped onto
//! it (treated as on the plane, not moved, as Blender's bisect does with its threshold), so no
//! slivers appear; crossing edges get one new vertex each, shared by both sides; cut faces are
//! re-triangulated; each side becomes its own [`SkinnedMesh`], optionally capped; new vertices
//! get their edge's interpolated weights (4 largest, renormalised: section 4.3).
//!
//! glTF models split vertices along UV seams, so vertex by vertex they are open patches.
//! [`Surgery::new`] welds vertices at bit-identical positions for the cut's topology: boundary
//! loops and caps are found over the welded surface (a cut of CesiumMan closes with two caps
//! instead of meeting hundreds of seam loops), while each piece keeps every input vertex; the
//! copies of a new vertex on a seam get identical rest positions and weights. Drills count their
//! loops the same way (unless they refine the mesh), and so do tears, whose incision also
//! crosses seams as if they were not there.
//!
//! The cut can be made on the rest mesh or on a posed frame ([`Frame::Posed`]): the plane then
//! classifies the posed positions, and each new vertex is mapped back to the rest pose through
//! the inverse of its own blended skin transform, so posing the pieces at that frame gives
//! exactly the cut that was seen.
//!
//! **May use**: mesh, skinning. **Must not use**: operators, blend, deformers, render, input,
//! or the crate-level `Error`; its error is [`SurgeryError`].
//!
//! ```
//! use deform::skinning::procedural_arm;
//! use deform::surgery::{CutOptions, Frame, Surgery};
//! let rig = procedural_arm(12, 20);
//! let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
//! let plane = cga::Plane::from_normal_distance(glam::DVec3::X, 4.1);
//! let cut = s.cut(&plane, Frame::Rest, &CutOptions::default()).unwrap();
//! let (a, b) = (&cut.pieces[0], &cut.pieces[1]);
//! assert!((a.mesh.mesh.area() + b.mesh.mesh.area() - rig.mesh.area()).abs() < 1e-9 * rig.mesh.area());
//! assert_eq!((a.boundary_loops, b.boundary_loops), (1, 1));
//! ```

mod bvh;
mod cap;
mod cut;
mod drill;
mod nearest;
mod ray;
mod refine;
mod soup;
mod split;
mod tear;
mod weights;
mod weld;

pub use bvh::FaceBvh;
pub use cut::{CutOptions, CutPiece, CutResult};
pub use drill::{Drill, DrillOptions, DrillResult};
pub use ray::RayHit;
pub use split::VertexOrigin;
pub use tear::{Scalpel, TearOptions, TearResult, MAX_OPEN_PER_DIAGONAL, ROUNDING_SNAP};
pub use weights::{identity_sources, push_interpolated, NEW_VERTEX_INFLUENCES};

use crate::blend::{PreparedKeys, Row};
use crate::mesh::Mesh;
use crate::skinning::Influences;
use glam::{DAffine3, DVec3};

/// What is wrong with a surgery's input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SurgeryError {
    /// Edges shared by more than two triangles (the first few listed).
    #[error("non-manifold mesh: {count} edges have more than two triangles, e.g. {example:?}")]
    NonManifold {
        /// How many.
        count: usize,
        /// One of them.
        example: [u32; 2],
    },
    /// A mesh that cannot be cut (empty, non-finite, indices out of range, influences of
    /// another length).
    #[error("{0}")]
    BadMesh(String),
    /// A plane, blade or cylinder that is not finite or degenerate.
    #[error("{0}")]
    BadTool(String),
    /// The surgery's own bookkeeping broke an invariant (a bug in this crate, reported as an
    /// error instead of a panic; please report it with the input).
    #[error("internal error in the surgery's mesh bookkeeping: {0}")]
    Broken(String),
    /// The tool does not reach the mesh: a plane with every vertex on one side (or on it), a
    /// drill with no vertex inside and no edge through it, a scalpel that does not touch the
    /// surface.
    #[error("the tool does not reach the mesh ({vertices} vertices): nothing to cut{where_}")]
    Misses {
        /// The mesh's vertex count.
        vertices: usize,
        /// Where the tool is: how far from the surface and the nearest surface point (empty
        /// when not known), as `"; ..."`.
        where_: String,
    },
}

/// A triangle mesh with per-vertex skin influences, and where each vertex comes from.
#[derive(Clone, Debug, PartialEq)]
pub struct SkinnedMesh {
    /// The rest mesh.
    pub mesh: Mesh,
    /// Influences, one row per vertex.
    pub influences: Influences,
    /// Sources, one row per vertex: the vertices of the mesh given to [`Surgery::new`] that
    /// this vertex is interpolated from, with their coefficients (in the `joints` and
    /// `weights` of each row), exactly as its influences were (section 4.3: the 4 largest,
    /// renormalised). An input vertex has `(v, 1)`. Interpolate any other per-vertex
    /// attribute (UVs, colours, normals) with them:
    /// [`crate::skinning::VertexAttribute::interpolated`].
    pub sources: Influences,
}

impl SkinnedMesh {
    /// The triangles `keep` accepts, over the vertices they use (in their order here), with
    /// their influences and sources.
    pub fn with_triangles(&self, keep: impl Fn(usize) -> bool) -> SkinnedMesh {
        let n = self.mesh.vertex_count();
        let tris: Vec<[u32; 3]> = (0..self.mesh.triangle_count())
            .filter(|&f| keep(f))
            .map(|f| self.mesh.triangles[f])
            .collect();
        let mut local = vec![u32::MAX; n];
        tris.iter().flatten().for_each(|&v| local[v as usize] = 0);
        let mut positions = Vec::new();
        let rows = |i: &Influences| Influences {
            width: i.width,
            ..Influences::default()
        };
        let (mut influences, mut sources) = (rows(&self.influences), rows(&self.sources));
        for (v, slot) in local.iter_mut().enumerate().filter(|(_, s)| **s == 0) {
            *slot = positions.len() as u32;
            positions.push(self.mesh.positions[v]);
            weights::push_copy(&self.influences, v as u32, &mut influences);
            weights::push_copy(&self.sources, v as u32, &mut sources);
        }
        let triangles = tris.iter().map(|t| t.map(|v| local[v as usize])).collect();
        SkinnedMesh {
            mesh: Mesh::new(positions, triangles),
            influences,
            sources,
        }
    }

    /// This mesh as a part of a rig made by [`crate::skinning::Rig::with_parts`].
    pub fn part(&self) -> crate::skinning::RigPart<'_> {
        crate::skinning::RigPart::new(&self.mesh, &self.influences, &self.sources)
    }
}

/// The frame a tool is given in.
#[derive(Clone, Copy, Debug)]
pub enum Frame<'a> {
    /// The rest (bind) pose.
    Rest,
    /// A posed frame: the posed position of every vertex, and the skin matrix of every joint
    /// (`global * inverse bind`, [`crate::skinning::RigPose::skin_matrices`]) that posed them
    /// (by linear blend skinning).
    Posed {
        /// Posed positions, one per vertex.
        positions: &'a [DVec3],
        /// Skin matrix per joint.
        skin: &'a [DAffine3],
    },
    /// A frame posed by a blend method (any but `conformal-projected`, which blends points,
    /// not transforms): the posed position of every vertex, and the joints'
    /// skin motors prepared for the method that posed them (the [`PreparedKeys`] of
    /// [`crate::blend::BoundBlend::pose_using`], or `PreparedKeys::new(pose.skin_motors()?, method)`).
    /// A new vertex is mapped back by the inverse of its own blend of those keys, so the
    /// same method poses it where the tool made it.
    Blended {
        /// Posed positions, one per vertex.
        positions: &'a [DVec3],
        /// The joints' keys as the posing method prepared them.
        keys: &'a PreparedKeys,
    },
}

impl<'a> Frame<'a> {
    /// How the frame was posed, if it was.
    pub(crate) fn posing(&self) -> Option<Posing<'a>> {
        match *self {
            Frame::Rest => None,
            Frame::Posed { skin, .. } => Some(Posing::Lbs(skin)),
            Frame::Blended { keys, .. } => Some(Posing::Keys(keys)),
        }
    }

    /// The same posing with other posed positions.
    pub(crate) fn with_positions(&self, positions: &'a [DVec3]) -> Frame<'a> {
        match *self {
            Frame::Rest => Frame::Rest,
            Frame::Posed { skin, .. } => Frame::Posed { positions, skin },
            Frame::Blended { keys, .. } => Frame::Blended { positions, keys },
        }
    }
}

/// How a posed frame was posed: what maps a posed point back to the rest pose.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Posing<'a> {
    /// Linear blend skinning by these skin matrices, one per joint.
    Lbs(&'a [DAffine3]),
    /// The blend of these keys, one per joint, by their method.
    Keys(&'a PreparedKeys),
}

/// A skinned mesh bound for cutting: checked once, with its face index.
#[derive(Clone, Debug)]
pub struct Surgery {
    mesh: SkinnedMesh,
    bvh: FaceBvh,
    topology: split::Topology,
    /// Coincident vertices welded, for the loops and caps of a cut (`None`: none coincide).
    weld: Option<weld::Weld>,
    diagonal: f64,
    /// Input triangles with a repeated corner, left out.
    dropped: usize,
}

impl Surgery {
    /// Check the mesh and build its face index. Triangles with a repeated corner (no surface:
    /// exporters leave them, viewers draw nothing) are left out of the mesh the tools work on
    /// and return ([`Surgery::dropped_triangles`] counts them).
    ///
    /// # Errors
    /// [`SurgeryError::BadMesh`] for an empty mesh, the errors of
    /// [`crate::mesh::validate::check_elements`] (indices out of range, non-finite or huge coordinates),
    /// or influences that [`Influences::check`] refuses (another length, joints and weights of
    /// different lengths, a weight that is not finite); [`SurgeryError::NonManifold`].
    pub fn new(mesh: &Mesh, influences: &Influences) -> Result<Surgery, SurgeryError> {
        let n = mesh.vertex_count();
        if mesh.triangle_count() == 0 {
            return Err(SurgeryError::BadMesh("the mesh has no triangles".into()));
        }
        influences.check(n).map_err(SurgeryError::BadMesh)?;
        crate::mesh::validate::check_elements(mesh)
            .map_err(|e| SurgeryError::BadMesh(e.to_string()))?;
        let kept: Vec<[u32; 3]> = mesh
            .triangles
            .iter()
            .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
            .copied()
            .collect();
        let dropped = mesh.triangle_count() - kept.len();
        if kept.is_empty() {
            return Err(SurgeryError::BadMesh(
                "every triangle has a repeated corner".into(),
            ));
        }
        let mesh = &Mesh::new(mesh.positions.clone(), kept);
        let edges = crate::mesh::adjacency::edges(&mesh.triangles, n);
        let bad: Vec<usize> = edges.non_manifold().collect();
        if let Some(&e) = bad.first() {
            return Err(SurgeryError::NonManifold {
                count: bad.len(),
                example: edges.edges[e],
            });
        }
        let diagonal = mesh.bounding_box().map_or(0.0, |b| b.diagonal());
        Ok(Surgery {
            topology: split::Topology::new(&mesh.triangles, n),
            weld: weld::Weld::new(mesh),
            bvh: FaceBvh::new(mesh),
            mesh: SkinnedMesh {
                mesh: mesh.clone(),
                influences: influences.clone(),
                sources: weights::identity_sources(n),
            },
            diagonal,
            dropped,
        })
    }

    /// How many triangles of the input had a repeated corner and were left out.
    pub fn dropped_triangles(&self) -> usize {
        self.dropped
    }

    /// The bound mesh.
    pub fn mesh(&self) -> &SkinnedMesh {
        &self.mesh
    }

    /// The face index.
    pub fn bvh(&self) -> &FaceBvh {
        &self.bvh
    }
}

/// The rest position of a point posed at `p` by the influences `joints`, `weights`
/// (interpolated for a new vertex): the inverse of its blended transform (the LBS blend of
/// the skin matrices, or the blend of the prepared keys by their method) applied to `p`.
/// `None` for a joint out of range or a singular blend.
pub(crate) fn unskin(p: DVec3, joints: &[u32], weights: &[f64], posing: Posing) -> Option<DVec3> {
    let m = match posing {
        Posing::Lbs(skin) => {
            let mut m = DAffine3::ZERO;
            for (&j, &w) in joints.iter().zip(weights) {
                let a = skin.get(j as usize)?;
                m.matrix3 += a.matrix3 * w;
                m.translation += a.translation * w;
            }
            m
        }
        Posing::Keys(keys) => {
            if joints.len() != weights.len()
                || joints.iter().any(|&j| j as usize >= keys.key_count())
            {
                return None;
            }
            keys.affine(Row::gathered(joints, weights))
        }
    };
    let r = m.inverse().transform_point3(p);
    r.is_finite().then_some(r)
}

/// A tool's frame, resolved: the positions it sees, the skin matrices of a posed frame, and
/// the face index over those positions (the bound index on the rest pose, a refitted copy on a
/// posed frame).
pub(crate) struct Resolved<'a> {
    pub positions: &'a [DVec3],
    pub skin: Option<Posing<'a>>,
    pub bvh: std::borrow::Cow<'a, FaceBvh>,
}

impl Surgery {
    /// Resolve `frame`, checking posed positions.
    pub(crate) fn resolve<'a>(&'a self, frame: Frame<'a>) -> Result<Resolved<'a>, SurgeryError> {
        let src = &self.mesh.mesh;
        let n = src.vertex_count();
        Ok(match frame {
            Frame::Rest => Resolved {
                positions: &src.positions,
                skin: None,
                bvh: std::borrow::Cow::Borrowed(&self.bvh),
            },
            Frame::Posed { positions, .. } | Frame::Blended { positions, .. } => {
                if positions.len() != n || positions.iter().any(|p| !p.is_finite()) {
                    return Err(SurgeryError::BadTool(format!(
                        "{} posed positions for {n} vertices (or not finite)",
                        positions.len()
                    )));
                }
                // Equation (17) projecting each term first blends points, not transforms: no
                // per-vertex transform to invert. Every joint the influences name needs its
                // transform.
                let posing = frame.posing();
                let transforms = match posing {
                    Some(Posing::Keys(keys))
                        if keys.method() == crate::blend::BlendMethod::ConformalProjected =>
                    {
                        return Err(SurgeryError::BadTool(
                            "a frame posed by conformal-projected blending has no per-vertex \
                             transform to map new vertices back by (pose the frame by another \
                             method)"
                                .into(),
                        ));
                    }
                    Some(Posing::Lbs(skin)) => skin.len(),
                    Some(Posing::Keys(keys)) => keys.key_count(),
                    None => 0,
                };
                let used = self
                    .mesh
                    .influences
                    .joints
                    .iter()
                    .max()
                    .map_or(0, |&j| j as usize + 1);
                if transforms < used {
                    return Err(SurgeryError::BadTool(format!(
                        "the posed frame has {transforms} joint transforms; the influences name {used}"
                    )));
                }
                let mut bvh = self.bvh.clone();
                bvh.refit(&Mesh::new(positions.to_vec(), src.triangles.clone()));
                Resolved {
                    positions,
                    skin: posing,
                    bvh: std::borrow::Cow::Owned(bvh),
                }
            }
        })
    }
}

/// Check a snap fraction.
pub(crate) fn check_snap(snap: f64) -> Result<(), SurgeryError> {
    if (0.0..0.5).contains(&snap) {
        Ok(())
    } else {
        Err(SurgeryError::BadTool(format!(
            "snap fraction {snap} outside [0, 0.5)"
        )))
    }
}
