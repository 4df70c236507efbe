//! Drilling (second paper, Algorithm 3): a finite cylinder removes the surface inside it.
//!
//! A point is inside the drill when its projection on the axis falls between the tip `A` and
//! the end `B` and its distance from the axis is below the radius. Edges with one end inside
//! are cut where they leave the cylinder: through its side at the root of the quadratic of
//! equations (18)-(20) (the projected edge against the circle of radius `r`), or through an
//! end disc. The faces the drill reaches come from the face index; faces that it pierces
//! without containing an intersection point (a drill thinner than the triangles), edges that
//! pass through it with both ends outside (the two-root case), and drills that make fewer than
//! [`DrillOptions::min_points`] intersection points are refined 1-to-4 around the drill (red-
//! green, no T-junctions) and drilled again, up to [`DrillOptions::max_refinements`] times.
//! An edge tangent to the cylinder (a double root) removes nothing.

use super::nearest::nearest_to_segment;
use super::refine::Work;
use super::split::{assemble, local_loops, new_vertex_data, FaceFate, Splitter};
use super::weld::{canonical_ids, share_copies};
use super::{check_snap, Frame, SkinnedMesh, Surgery, SurgeryError, VertexOrigin};
use crate::mesh::numbers::{short_number, short_point};
use crate::mesh::Mesh;
use crate::skinning::Influences;
use glam::DVec3;

/// A drill: a cylinder from its `tip` to its `end`, of `radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drill {
    /// The tip `A`.
    pub tip: DVec3,
    /// The end `B`.
    pub end: DVec3,
    /// The radius `r`.
    pub radius: f64,
}

/// Options of [`Surgery::drill`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrillOptions {
    /// As [`super::CutOptions::snap`]: vertices closer to the cylinder than this fraction of a
    /// crossing edge are treated as on it.
    pub snap: f64,
    /// Refine when the drill makes fewer intersection points than this.
    pub min_points: usize,
    /// Refinement rounds at most.
    pub max_refinements: usize,
}

impl Default for DrillOptions {
    fn default() -> Self {
        DrillOptions {
            snap: 0.02,
            min_points: 6,
            max_refinements: 6,
        }
    }
}

/// The drilled mesh and what changed.
#[derive(Clone, Debug, PartialEq)]
pub struct DrillResult {
    /// The drilled mesh (input vertices that remain, in input order, then refinement
    /// midpoints and intersection points).
    pub mesh: SkinnedMesh,
    /// Where each vertex comes from: [`VertexOrigin::Edge`] for intersection points (the edge
    /// of the refined mesh when [`DrillResult::refined_faces`] is not 0, whose extra vertices
    /// are [`VertexOrigin::Refined`]).
    pub origin: Vec<VertexOrigin>,
    /// Intersection points made (new vertices on the cylinder).
    pub new_vertices: usize,
    /// Faces removed or re-triangulated.
    pub removed_faces: usize,
    /// Faces replaced by refinement.
    pub refined_faces: usize,
    /// Boundary loops of the result (the holes, and any the input had).
    pub boundary_loops: usize,
    /// Boundary loops the drill added.
    pub holes: usize,
}

/// The cylinder in a convenient form.
struct Cylinder {
    a: DVec3,
    n: DVec3,
    len: f64,
    r: f64,
}

impl Cylinder {
    fn axial(&self, x: DVec3) -> f64 {
        (x - self.a).dot(self.n)
    }

    fn radial(&self, x: DVec3) -> DVec3 {
        let d = x - self.a;
        d - d.dot(self.n) * self.n
    }

    fn inside(&self, x: DVec3) -> bool {
        let a = self.axial(x);
        a > 0.0 && a < self.len && self.radial(x).length_squared() < self.r * self.r
    }

    /// The parameter interval of `p + t (q - p)`, `t` in `[0, 1]`, inside the closed cylinder
    /// (the side by the quadratic `K t^2 + L t + N <= 0` of equations (18)-(20)).
    fn clip(&self, p: DVec3, q: DVec3) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        let (ap, aq) = (self.axial(p), self.axial(q));
        let da = aq - ap;
        if da.abs() < 1e-300 {
            if ap < 0.0 || ap > self.len {
                return None;
            }
        } else {
            let (t0, t1) = ((0.0 - ap) / da, (self.len - ap) / da);
            lo = lo.max(t0.min(t1));
            hi = hi.min(t0.max(t1));
        }
        let (rp, rq) = (self.radial(p), self.radial(q));
        let dr = rq - rp;
        let k = dr.length_squared();
        let l = 2.0 * rp.dot(dr);
        let n = rp.length_squared() - self.r * self.r;
        if k <= 1e-300 {
            if n > 0.0 {
                return None;
            }
        } else {
            let disc = l * l - 4.0 * k * n;
            if disc < 0.0 {
                return None;
            }
            let s = disc.sqrt();
            // Stable roots.
            let qq = -0.5 * (l + l.signum() * s);
            let (mut t0, mut t1) = if qq != 0.0 {
                (qq / k, n / qq)
            } else {
                (0.0, 0.0)
            };
            if t0 > t1 {
                std::mem::swap(&mut t0, &mut t1);
            }
            lo = lo.max(t0);
            hi = hi.min(t1);
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// Whether the axis segment pierces the triangle.
    fn pierces(&self, [a, b, c]: [DVec3; 3]) -> bool {
        let d = self.n * self.len;
        let (e1, e2) = (b - a, c - a);
        let h = d.cross(e2);
        let det = e1.dot(h);
        if det.abs() < 1e-300 {
            return false;
        }
        let s = self.a - a;
        let u = s.dot(h) / det;
        let q = s.cross(e1);
        let v = d.dot(q) / det;
        let t = e2.dot(q) / det;
        (0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && (0.0..=1.0).contains(&t)
    }
}

impl Surgery {
    /// Drill `drill` through the mesh (Algorithm 3); see the module documentation.
    ///
    /// # Errors
    /// [`SurgeryError::BadTool`] for a non-finite drill, a zero radius or length, a snap
    /// fraction outside `[0, 0.5)`, posed positions of the wrong length, a drill that would
    /// remove the whole mesh, a drill that meets the surface but is too thin to remove a
    /// vertex after refinement;
    /// [`SurgeryError::Misses`] when the drill reaches no part of the surface (even after
    /// refinement); [`SurgeryError::BadMesh`] when a new vertex cannot be mapped back to the
    /// rest pose.
    pub fn drill(
        &self,
        drill: &Drill,
        frame: Frame,
        options: &DrillOptions,
    ) -> Result<DrillResult, SurgeryError> {
        let axis = drill.end - drill.tip;
        let len = axis.length();
        if !(drill.tip.is_finite() && drill.end.is_finite() && drill.radius.is_finite()) {
            return Err(SurgeryError::BadTool("the drill is not finite".into()));
        }
        if !(drill.radius > 0.0 && len > 0.0) {
            return Err(SurgeryError::BadTool(format!(
                "a drill needs a positive radius and length (radius {}, length {len})",
                drill.radius
            )));
        }
        check_snap(options.snap)?;
        let cyl = Cylinder {
            a: drill.tip,
            n: axis / len,
            len,
            r: drill.radius,
        };
        let src = &self.mesh;
        let resolved = self.resolve(frame)?;
        let (frame_positions, skin) = (resolved.positions, resolved.skin);
        let mut work: Option<Work> = None;
        let mut refined_faces = 0;
        for round in 0..=options.max_refinements {
            let (rest, fpos, inf, tris) = match &work {
                None => (
                    &src.mesh.positions[..],
                    frame_positions,
                    &src.influences,
                    &src.mesh.triangles[..],
                ),
                Some(w) => (&w.rest[..], &w.frame[..], &w.influences, &w.triangles[..]),
            };
            let index = work.is_none().then_some(&*resolved.bvh);
            let near = faces_near_cylinder(&cyl, tris, fpos, index);
            let plan = plan(&cyl, tris, fpos, &near, options.snap);
            // Every vertex inside: nothing would remain, whatever refinement did (refining
            // first took tens of seconds and gigabytes on a drill wider than the model).
            if work.is_none() && plan.sign.iter().all(|&s| s < 0) {
                return Err(SurgeryError::BadTool(
                    "the drill removes the whole mesh".into(),
                ));
            }
            let points = plan.crossings + plan.snapped;
            let needs = !plan.pierced.is_empty()
                || !plan.two_root.is_empty()
                || points < options.min_points;
            if needs && round < options.max_refinements && !near.is_empty() {
                let mut red: Vec<u32> = plan.pierced.clone();
                red.extend(&plan.two_root);
                if points < options.min_points {
                    red.extend(&plan.touched);
                }
                red.sort_unstable();
                red.dedup();
                if !red.is_empty() {
                    let w = work.get_or_insert_with(|| Work {
                        rest: src.mesh.positions.clone(),
                        frame: frame_positions.to_vec(),
                        influences: src.influences.clone(),
                        sources: src.sources.clone(),
                        triangles: src.mesh.triangles.clone(),
                        skin,
                    });
                    refined_faces += w.refine(&red)?;
                    continue;
                }
            }
            if plan.removed == 0 {
                return Err(self.removes_nothing(drill, tris, fpos, options));
            }
            let sources = work.as_ref().map(|w| &w.sources);
            let round = Round {
                rest,
                fpos,
                influences: inf,
                tris,
                sources,
            };
            let mut r = self.drill_out(&cyl, &plan, &near, &round, frame)?;
            r.refined_faces = refined_faces;
            return Ok(r);
        }
        unreachable!("the last round always returns")
    }

    /// Why a drill that removes no vertex is refused: an axis through the surface means a
    /// drill too thin for the mesh there; else it misses, saying where its axis passes.
    fn removes_nothing(
        &self,
        drill: &Drill,
        tris: &[[u32; 3]],
        fpos: &[DVec3],
        options: &DrillOptions,
    ) -> SurgeryError {
        let axis = nearest_to_segment(tris, fpos, drill.tip, drill.end);
        // An axis through the surface (not one that grazes it): the drill is too thin.
        if let Some(n) = axis.filter(|n| n.distance < 0.5 * drill.radius) {
            return SurgeryError::BadTool(format!(
                "the drill (radius {}) meets the surface near {} but removes no vertex, \
                 even after {} rounds of refinement around it: it is too thin for the \
                 mesh there; widen it (`DrillOptions::max_refinements` allows more \
                 refinement)",
                short_number(drill.radius),
                short_point(n.surface),
                options.max_refinements,
            ));
        }
        // The model's own vertex count: `rest` may hold the vertices refinement added.
        SurgeryError::Misses {
            vertices: self.mesh.mesh.vertex_count(),
            where_: axis.map_or(String::new(), |n| {
                format!(
                    "; the drill's axis (radius {}): {}",
                    short_number(drill.radius),
                    n.describe()
                )
            }),
        }
    }

    /// Split the faces the drill changes and keep the outside: the new mesh, where each
    /// vertex comes from, and the boundary loops it made (over the welded surface when
    /// coincident vertices exist and the input's topology applies, as the cut counts).
    fn drill_out(
        &self,
        cyl: &Cylinder,
        plan: &Plan,
        near: &[u32],
        round: &Round,
        frame: Frame,
    ) -> Result<DrillResult, SurgeryError> {
        let (fpos, tris) = (round.fpos, round.tris);
        let n0 = self.mesh.mesh.vertex_count();
        let owned;
        let sub = match round.sources {
            None => &self.mesh,
            Some(sources) => {
                owned = SkinnedMesh {
                    mesh: Mesh::new(round.rest.to_vec(), Vec::new()),
                    influences: round.influences.clone(),
                    sources: sources.clone(),
                };
                &owned
            }
        };
        let NearSplit {
            splitter,
            changed,
            produced,
        } = split_near(cyl, plan, near, fpos, tris);
        let kept = keep_unchanged(tris, &changed, &produced);
        let fate = |f: u32| {
            if changed.binary_search(&f).is_ok() {
                FaceFate::Changed
            } else {
                FaceFate::Kept(0)
            }
        };
        if kept.is_empty() {
            return Err(SurgeryError::BadTool(
                "the drill removes the whole mesh".into(),
            ));
        }
        let posed_frame = frame.with_positions(fpos);
        // glTF's seam copies are one vertex, and the new vertices on the copies of a seam
        // edge coincide exactly.
        let unrefined = round.sources.is_none();
        let weld = self.weld.as_ref().filter(|_| unrefined);
        let canon = weld.map(|w| canonical_ids(&w.canon, &splitter.new_edges));
        let mut new = new_vertex_data(sub, &splitter.new_edges, posed_frame, fpos)?;
        if let Some(c) = &canon {
            share_copies(&c[n0..], n0, &mut new.influences, &mut new.mesh.positions);
        }
        let a = assemble(sub, kept, &splitter, &new);
        let origin = a
            .origin
            .iter()
            .map(|o| match *o {
                VertexOrigin::Original(i) if i as usize >= n0 => VertexOrigin::Refined,
                other => other,
            })
            .collect();
        // The input's loops over the same vertices: welded when the result's are.
        let loops_before = weld.map_or(self.topology.loops, |w| w.topology.loops);
        let boundary_loops = match (weld, &canon) {
            (Some(w), Some(c)) => {
                let produced: Vec<([u32; 3], u8)> = produced
                    .iter()
                    .map(|(t, k)| (t.map(|v| c[v as usize]), *k))
                    .collect();
                local_loops(&w.topology, &w.triangles, fate, &changed, &[], &produced, 0).len()
            }
            _ if unrefined => {
                local_loops(&self.topology, tris, fate, &changed, &[], &produced, 0).len()
            }
            // Refined: the input's topology does not apply.
            _ => crate::mesh::adjacency::boundary_loops(
                &a.mesh.mesh.triangles,
                a.mesh.mesh.vertex_count(),
            )
            .len(),
        };
        Ok(DrillResult {
            mesh: a.mesh,
            origin,
            new_vertices: splitter.new_edges.len(),
            removed_faces: changed.len(),
            refined_faces: 0,
            boundary_loops,
            holes: boundary_loops.saturating_sub(loops_before),
        })
    }
}

/// What [`split_near`] gives: the splitter with its new edges, the faces it changed (sorted)
/// and the outside triangles it produced (each with its side, 0).
struct NearSplit<'a> {
    splitter: Splitter<'a>,
    changed: Vec<u32>,
    produced: Vec<([u32; 3], u8)>,
}

/// The faces of `near` with a vertex inside the drill, split along `cyl`.
fn split_near<'a>(
    cyl: &Cylinder,
    plan: &Plan,
    near: &[u32],
    fpos: &'a [DVec3],
    tris: &[[u32; 3]],
) -> NearSplit<'a> {
    let mut splitter = Splitter::new(fpos);
    let root = |a: u32, b: u32| {
        let (pa, pb) = (fpos[a as usize], fpos[b as usize]);
        let (lo, hi) = cyl.clip(pa, pb).unwrap_or((0.0, 1.0));
        if plan.sign[a as usize] < 0 {
            hi
        } else {
            lo
        }
    };
    // Only faces near the drill can change (a face with a vertex inside meets its box).
    let mut changed: Vec<u32> = near
        .iter()
        .copied()
        .filter(|&f| tris[f as usize].iter().any(|&v| plan.sign[v as usize] < 0))
        .collect();
    changed.sort_unstable();
    let mut produced = Vec::new();
    for &f in &changed {
        let t = tris[f as usize];
        let g = t.map(|v| plan.sign[v as usize]);
        if g.contains(&1) {
            splitter.split(t, g, &root, |side, tri| {
                if side == 0 {
                    produced.push((tri, 0u8));
                }
            });
        }
    }
    NearSplit {
        splitter,
        changed,
        produced,
    }
}

/// The triangles not in `changed` (sorted), in order, then the `produced` ones.
fn keep_unchanged(
    tris: &[[u32; 3]],
    changed: &[u32],
    produced: &[([u32; 3], u8)],
) -> Vec<[u32; 3]> {
    let mut kept = Vec::with_capacity(tris.len() + produced.len());
    let mut next = changed.iter().peekable();
    for (fi, t) in tris.iter().enumerate() {
        if next.peek() == Some(&&(fi as u32)) {
            next.next();
        } else {
            kept.push(*t);
        }
    }
    kept.extend(produced.iter().map(|p| p.0));
    kept
}

/// The working mesh of one round: rest and frame positions, influences, triangles, and the
/// sources of its vertices once refinement made its own copy (`None`: the surgery's mesh).
struct Round<'a> {
    rest: &'a [DVec3],
    fpos: &'a [DVec3],
    influences: &'a Influences,
    tris: &'a [[u32; 3]],
    sources: Option<&'a Influences>,
}

/// Faces whose boxes meet the drill's box: from the face index when there is one for these
/// positions, else (after refinement) by a scan of the working mesh.
fn faces_near_cylinder(
    cyl: &Cylinder,
    tris: &[[u32; 3]],
    pos: &[DVec3],
    index: Option<&super::FaceBvh>,
) -> Vec<u32> {
    let r = DVec3::splat(cyl.r);
    let b = cyl.a + cyl.n * cyl.len;
    let (lo, hi) = (cyl.a.min(b) - r, cyl.a.max(b) + r);
    let overlaps = |min: DVec3, max: DVec3| min.cmple(hi).all() && max.cmpge(lo).all();
    if let Some(bvh) = index {
        let mut out = Vec::new();
        bvh.query(|bx| overlaps(bx.min, bx.max), |f| out.push(f));
        return out;
    }
    (0..tris.len() as u32)
        .filter(|&f| {
            let t = tris[f as usize];
            let (p, q, s) = (pos[t[0] as usize], pos[t[1] as usize], pos[t[2] as usize]);
            overlaps(p.min(q).min(s), p.max(q).max(s))
        })
        .collect()
}

/// The signs of the vertices (-1 inside, 0 snapped, 1 outside) and what needs refinement.
struct Plan {
    sign: Vec<i8>,
    crossings: usize,
    snapped: usize,
    removed: usize,
    /// Faces the axis pierces with no corner inside.
    pierced: Vec<u32>,
    /// Faces with an edge passing through the drill with both ends outside.
    two_root: Vec<u32>,
    /// Faces the drill reaches.
    touched: Vec<u32>,
}

fn plan(cyl: &Cylinder, tris: &[[u32; 3]], pos: &[DVec3], near: &[u32], snap: f64) -> Plan {
    let mut sign = vec![1i8; pos.len()];
    for &f in near {
        for &v in &tris[f as usize] {
            if cyl.inside(pos[v as usize]) {
                sign[v as usize] = -1;
            }
        }
    }
    let mut snapped_list = Vec::new();
    let (mut pierced, mut two_root, mut touched) = (Vec::new(), Vec::new(), Vec::new());
    let mut crossings = 0;
    for &f in near {
        let t = tris[f as usize];
        let mut touches = false;
        let mut two = false;
        for k in 0..3 {
            let (i, j) = (t[k], t[(k + 1) % 3]);
            let (pi, pj) = (pos[i as usize], pos[j as usize]);
            let (si, sj) = (sign[i as usize], sign[j as usize]);
            if si != sj {
                touches = true;
                crossings += 1;
                if let Some((lo, hi)) = cyl.clip(pi, pj) {
                    let at = if si < 0 { hi } else { lo };
                    if at < snap {
                        snapped_list.push(i);
                    }
                    if 1.0 - at < snap {
                        snapped_list.push(j);
                    }
                }
            } else if si > 0 {
                if let Some((lo, hi)) = cyl.clip(pi, pj) {
                    if hi - lo > 1e-9 {
                        two = true;
                        touches = true;
                    }
                }
            } else {
                touches = true;
            }
        }
        let corners = t.map(|v| pos[v as usize]);
        if !touches && cyl.pierces(corners) {
            pierced.push(f);
        }
        if two {
            two_root.push(f);
        }
        if touches || cyl.pierces(corners) {
            touched.push(f);
        }
    }
    snapped_list.sort_unstable();
    snapped_list.dedup();
    for &v in &snapped_list {
        sign[v as usize] = 0;
    }
    let removed = near
        .iter()
        .filter(|&&f| tris[f as usize].iter().any(|&v| sign[v as usize] < 0))
        .count();
    Plan {
        sign,
        // Each crossing edge was counted from both of its faces.
        crossings: crossings / 2,
        snapped: snapped_list.len(),
        removed,
        pierced,
        two_root,
        touched,
    }
}
