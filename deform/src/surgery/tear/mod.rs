//! Tearing (second paper, Algorithm 2): a scalpel at successive time steps opens an incision.
//!
//! For each step the point `S_i` where the blade `A_i B_i` enters the skin is found with the
//! face index (the first hit from `A_i`) and inserted as a vertex (snapped onto a corner or an
//! edge within [`TearOptions::snap`] of it; `entry.rs`). Between two points the incision is
//! the curve where the surface meets the swept blade: the plane through `S_i` and the next
//! blade `A_{i+1} B_{i+1}` (through `S_i` and `S_{i+1}` along that blade when `S_{i+1}` was
//! snapped). That curve is traced from `S_i` both ways, across as many faces as it crosses,
//! and the arc that joins `S_{i+1}` while staying nearest the swept blade is taken (`walk.rs`);
//! each edge it crosses is split at the crossing (both its faces), corners within the snap
//! fraction are taken instead, so the incision becomes a chain of mesh edges. Steps are as
//! long as the model allows: only a blade that misses the surface, or two points the curve
//! does not join (say a blade that enters another limb), are refused, saying where. A sequence
//! of steps makes one longer incision. Every incision point but the two ends is then split in
//! two lips: the faces on one side of the incision keep it, those on the other side get a
//! copy, so the surface opens (`open.rs`); [`TearOptions::open`] moves the two lips apart
//! along the planes' normals (tapered to zero at the tips). A scalpel that goes back along
//! its incision splits and moves each point once: the slit opens as if traced once. New vertices get interpolated
//! weights (4 largest, renormalised).
//!
//! glTF models split vertices along UV seams. The tear sees through them (`seams.rs`): the
//! curve is followed from one side of a seam to the other, a seam edge it crosses is split on
//! both sides at coincident copies of one new vertex, an incision point on a seam opens on
//! every copy, and the boundary loops are counted over the welded surface, as a cut and a
//! drill count them.

mod entry;
mod open;
mod seams;
mod walk;

use super::nearest::nearest_to_segment;
use super::soup::Soup;
use super::split::{local_loops, FaceFate};
use super::{check_snap, FaceBvh, Frame, SkinnedMesh, Surgery, SurgeryError, VertexOrigin};
use crate::mesh::numbers::short_point;
use crate::mesh::Mesh;
use entry::{first_hit, insert_point};
use glam::DVec3;
use seams::Seams;
use walk::Step;

/// The blade at one time step: the segment from `a` to `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scalpel {
    /// One end of the blade (the handle side).
    pub a: DVec3,
    /// The other end.
    pub b: DVec3,
}

/// The snap fraction a tear uses at least, [`TearOptions::snap`] `0` included: a scalpel point
/// or a crossing within this fraction of an edge of a corner is that corner. It is rounding,
/// not geometry (a point 1e-17 from an edge made sliver faces that the next step's curve could
/// not follow).
pub const ROUNDING_SNAP: f64 = 1e-9;

/// Options of [`Surgery::tear`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TearOptions {
    /// Corners closer to the incision than this fraction of an edge are taken as incision
    /// vertices instead of splitting the edge (no slivers). In `[0, 0.5)`; default 0.02; at
    /// least [`ROUNDING_SNAP`] is used.
    pub snap: f64,
    /// How far the two lips are pulled apart at the incision's middle (0: a closed slit).
    pub open: f64,
}

impl Default for TearOptions {
    fn default() -> Self {
        TearOptions {
            snap: 0.02,
            open: 0.0,
        }
    }
}

/// The torn mesh and what changed.
#[derive(Clone, Debug, PartialEq)]
pub struct TearResult {
    /// The torn mesh: the input vertices in input order, then the new ones.
    pub mesh: SkinnedMesh,
    /// Where each vertex comes from.
    pub origin: Vec<VertexOrigin>,
    /// The incision: its vertices from the first scalpel point to the last (the left lip).
    /// Consecutive vertices share an edge of the welded surface (where the incision crosses
    /// a UV seam, a vertex may stand for its coincident copy). A scalpel that goes back along
    /// the incision lists its points again.
    pub incision: Vec<u32>,
    /// Each step's plane, as `(unit normal, point on it)`. A step whose scalpel stays at one
    /// point of the surface (a position repeated, as a drag sampled twice gives) cuts nothing
    /// and takes the plane of the step before it (of the one after it for the first).
    pub planes: Vec<(DVec3, DVec3)>,
    /// Vertices added (incision points, their copies across UV seams, and the lips' copies).
    pub new_vertices: usize,
    /// Inner incision points split into two lips (each once, however often the scalpel passed).
    pub duplicated: usize,
    /// Input faces re-triangulated.
    pub changed_faces: usize,
    /// Boundary loops of the result, over the welded surface when the input has coincident
    /// vertices (UV seams): a slit through a closed surface is one loop.
    pub boundary_loops: usize,
}

impl TearResult {
    /// How many vertices the incision has: those of [`TearResult::incision`], each counted
    /// once (a scalpel that goes back along its incision lists points twice).
    pub fn incision_vertex_count(&self) -> usize {
        let mut v = self.incision.clone();
        v.sort_unstable();
        v.dedup();
        v.len()
    }
}

/// The largest opening of a tear, in bounding-box diagonals of the model.
pub const MAX_OPEN_PER_DIAGONAL: f64 = 100.0;

impl Surgery {
    /// Tear along the scalpel positions (at least two); see the module documentation.
    ///
    /// # Errors
    /// [`SurgeryError::BadTool`] for fewer than two positions, positions that all enter the
    /// surface at one point (nothing to tear), a non-finite or zero-length blade, a blade that does not touch the surface (with how far it passes and the nearest
    /// surface point), a plane that is not defined (the blade moved along itself between two different entry
    /// points; a position repeated is a step that cuts nothing), two
    /// scalpel points that the plane's curve over the surface does not join (with where the
    /// curve goes and how near it comes), an opening over [`MAX_OPEN_PER_DIAGONAL`]
    /// bounding-box diagonals, posed positions of the wrong length;
    /// [`SurgeryError::BadMesh`] when a new vertex cannot be mapped back to the rest pose (a
    /// singular blended skin transform); [`SurgeryError::Broken`] when the mesh bookkeeping
    /// breaks an invariant (a bug).
    pub fn tear(
        &self,
        scalpel: &[Scalpel],
        frame: Frame,
        options: &TearOptions,
    ) -> Result<TearResult, SurgeryError> {
        let snap = self.check_tear(scalpel, options)?;
        let src = &self.mesh;
        let n0 = src.mesh.vertex_count();
        let resolved = self.resolve(frame)?;
        let (positions, skin, bvh) = (resolved.positions, resolved.skin, &*resolved.bvh);
        // Where each blade enters the skin, on the input mesh.
        let hits = blade_hits(scalpel, bvh, &src.mesh.triangles, positions)?;
        let mut soup = Soup::new(
            &src.mesh.triangles,
            &self.topology.neighbors,
            &self.topology.vertex_face,
            &src.mesh.positions,
            positions,
            &src.influences,
            &src.sources,
            skin,
        );
        let canon = self.weld.as_ref().map(|w| &w.canon[..]);
        let mut seams = Seams::new(canon, n0, &src.mesh.triangles);
        // A blade that enters where an earlier one did (a position given again) lands on the
        // point that one inserted, within the snap (at least ROUNDING_SNAP): the same vertex.
        let points: Vec<u32> = hits
            .iter()
            .map(|&(f, p)| insert_point(&mut soup, &mut seams, f, p, snap))
            .collect::<Result<_, _>>()?;
        // Every blade entered at one point: there is no incision to open (it would only add
        // that point as a vertex).
        if points
            .iter()
            .all(|&p| seams.label(p) == seams.label(points[0]))
        {
            return Err(SurgeryError::BadTool(format!(
                "the {} scalpel positions all enter the surface at one point, {}: the scalpel \
                 has to move across the surface to tear it",
                scalpel.len(),
                short_point(soup.at(points[0]))
            )));
        }
        // A step whose scalpel stays at one point of the surface (a position held for a
        // sample, as a drag gives) cuts nothing; its plane is only needed where it is defined.
        let still = |i: usize| seams.label(points[i]) == seams.label(points[i + 1]);
        let own: Vec<Option<(DVec3, DVec3)>> = (0..points.len() - 1)
            .map(|i| {
                if still(i) {
                    return Ok(None);
                }
                let ends = [points[i], points[i + 1]].map(|v| soup.at(v));
                step_plane(i, ends, &scalpel[i + 1]).map(Some)
            })
            .collect::<Result<_, _>>()?;
        let planes = fill_still_planes(&own)?;
        // Follow each step's plane from one scalpel point to the next.
        let mut incision = vec![points[0]];
        for i in 0..points.len() - 1 {
            if seams.label(points[i]) == seams.label(points[i + 1]) {
                continue;
            }
            let step = Step {
                index: i,
                from: points[i],
                to: points[i + 1],
                normal: planes[i].0,
                point: planes[i].1,
                blades: [scalpel[i], scalpel[i + 1]],
                snap,
                diagonal: self.diagonal,
            };
            let path = walk::follow(&mut soup, &mut seams, &step)?;
            incision.extend_from_slice(&path[1..]);
        }
        // Open: the faces on one side of the incision get copies of its inner vertices.
        let duplicated =
            open::open_incision(&mut soup, &mut seams, &mut incision, &planes, options.open)?;
        let new_vertices = soup.rest.len() - n0;
        let changed: Vec<u32> = (0..src.mesh.triangle_count() as u32)
            .filter(|&f| soup.touched[f as usize])
            .collect();
        let boundary_loops = self.welded_loops(&soup, &seams, &changed);
        Ok(TearResult {
            mesh: SkinnedMesh {
                mesh: Mesh::new(soup.rest, soup.tris),
                influences: soup.influences,
                sources: soup.sources,
            },
            origin: soup.origin,
            incision,
            planes,
            new_vertices,
            duplicated,
            changed_faces: changed.len(),
            boundary_loops,
        })
    }
}

impl Surgery {
    /// The tools of a tear, checked: at least two finite, non-empty scalpel positions, a snap
    /// fraction in range, a finite opening within the model's scale. Returns the snap used
    /// (at least [`ROUNDING_SNAP`]: a point within rounding of a corner or an edge is on it).
    fn check_tear(&self, scalpel: &[Scalpel], options: &TearOptions) -> Result<f64, SurgeryError> {
        if scalpel.len() < 2 {
            return Err(SurgeryError::BadTool(
                "a tear needs at least two scalpel positions".into(),
            ));
        }
        if let Some(i) = scalpel
            .iter()
            .position(|s| !(s.a.is_finite() && s.b.is_finite()) || s.a == s.b)
        {
            return Err(SurgeryError::BadTool(format!(
                "scalpel {i} is not a finite, non-empty segment"
            )));
        }
        check_snap(options.snap)?;
        if !options.open.is_finite() {
            return Err(SurgeryError::BadTool("the opening is not finite".into()));
        }
        // An opening far beyond the model's size would only push the lips out of range (and
        // past what f64 and the f32 of a .glb hold); the model's scale bounds it.
        if options.open.abs() > MAX_OPEN_PER_DIAGONAL * self.diagonal {
            return Err(SurgeryError::BadTool(format!(
                "the opening {:.3e} is over {MAX_OPEN_PER_DIAGONAL} times the model's size \
                 (bounding-box diagonal {:.3e})",
                options.open, self.diagonal
            )));
        }
        Ok(options.snap.max(ROUNDING_SNAP))
    }
}

/// Where each blade first enters the surface (face and point), or which blade misses and
/// where it passes.
fn blade_hits(
    scalpel: &[Scalpel],
    bvh: &FaceBvh,
    triangles: &[[u32; 3]],
    positions: &[DVec3],
) -> Result<Vec<(u32, DVec3)>, SurgeryError> {
    let mut hits = Vec::with_capacity(scalpel.len());
    for (i, s) in scalpel.iter().enumerate() {
        let Some(hit) = first_hit(bvh, triangles, positions, s.a, s.b) else {
            let whereabouts = nearest_to_segment(triangles, positions, s.a, s.b)
                .map_or(String::new(), |n| format!(": {}", n.describe()));
            return Err(SurgeryError::BadTool(format!(
                "scalpel {i}, the blade from {} to {}, does not touch the surface{whereabouts}",
                short_point(s.a),
                short_point(s.b)
            )));
        };
        hits.push(hit);
    }
    Ok(hits)
}

impl Surgery {
    /// The boundary loops of the torn soup around its `changed` input faces, over the welded
    /// surface when coincident vertices were welded (seam copies are one vertex, the lips of
    /// the incision two), as a cut and a drill count them.
    fn welded_loops(&self, soup: &Soup, seams: &Seams, changed: &[u32]) -> usize {
        let label = seams.labels();
        let produced: Vec<([u32; 3], u8)> = (0..soup.tris.len() as u32)
            .filter(|&f| soup.touched[soup.root(f) as usize])
            .map(|f| (soup.tris[f as usize].map(|v| label[v as usize]), 0u8))
            .collect();
        let fate = |f: u32| {
            if soup.touched[f as usize] {
                FaceFate::Changed
            } else {
                FaceFate::Kept(0)
            }
        };
        let (topology, triangles) = match &self.weld {
            Some(w) => (&w.topology, &w.triangles[..]),
            None => (&self.topology, &self.mesh.mesh.triangles[..]),
        };
        local_loops(topology, triangles, fate, changed, &[], &produced, 0).len()
    }
}

/// Every step's plane: its own for a step that moves, else (a step that stays at one point)
/// the previous step's, else the first moving step's. Some step moves (the caller refused
/// scalpels that all enter at one point) and has its plane (or the tear was refused).
fn fill_still_planes(own: &[Option<(DVec3, DVec3)>]) -> Result<Vec<(DVec3, DVec3)>, SurgeryError> {
    let mut last = own.iter().flatten().next().copied();
    own.iter()
        .map(|p| {
            last = p.or(last);
            last.ok_or_else(|| SurgeryError::Broken("a tear with no moving step".into()))
        })
        .collect()
}

/// The plane of step `i` (Algorithm 2, step 5), as `(unit normal, first point)`: through its
/// two scalpel points `ends` and along the next blade `next`. Where the second point is where
/// blade `next` enters, this is the paper's plane through the first point and the next
/// blade's ends; where it was snapped onto a corner or an edge, the plane still holds both
/// points (and so the whole incision of the step). Two points that coincide take the paper's
/// plane.
fn step_plane(i: usize, ends: [DVec3; 2], next: &Scalpel) -> Result<(DVec3, DVec3), SurgeryError> {
    let [s, t] = ends;
    let (normal, scale) = if s == t {
        let n = (next.a - s).cross(next.b - s);
        (n, (next.a - s).length() * (next.b - s).length())
    } else {
        let d = next.b - next.a;
        ((t - s).cross(d), (t - s).length() * d.length())
    };
    let len = normal.length();
    if len.is_nan() || len <= 1e-12 * scale {
        return Err(SurgeryError::BadTool(format!(
            "step {i}: the scalpel points and the next blade are collinear: no plane"
        )));
    }
    Ok((normal / len, s))
}
