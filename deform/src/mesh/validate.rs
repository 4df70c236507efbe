//! Mesh validation (with the offending indices) and cleaning of raw scans.

use crate::mesh::adjacency;
use crate::mesh::is_degenerate_triangle;
use crate::mesh::IndexList;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::mesh::Result;

/// The largest coordinate magnitude [`ValidationReport::check_solvable`] accepts: below it
/// every edge vector (a difference of two positions) is finite. Angles are computed
/// scale-invariantly, so any scale below it gives the same Laplacian; quantities with units
/// (masses, mean-value weights) are checked after they are computed.
pub const MAX_COORDINATE: f64 = 1e300;

/// What [`validate()`] found. Every list holds indices into the input mesh.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ValidationReport {
    /// Number of vertices.
    pub vertex_count: usize,
    /// Number of triangles.
    pub triangle_count: usize,
    /// Triangles with an index `>= vertex_count`.
    pub out_of_range_faces: Vec<u32>,
    /// Triangles with (numerically) zero area or a repeated vertex index.
    pub degenerate_faces: Vec<u32>,
    /// `[face, earlier]`: `face` uses the same three vertices as `earlier`.
    pub duplicate_faces: Vec<[u32; 2]>,
    /// Edges `[a, b]` (`a < b`) shared by more than two triangles.
    pub non_manifold_edges: Vec<[u32; 2]>,
    /// Vertices whose incident triangles form more than one edge-connected fan (bow-ties).
    pub non_manifold_vertices: Vec<u32>,
    /// Vertices used by no triangle.
    pub unreferenced_vertices: Vec<u32>,
    /// Vertices with a NaN or infinite coordinate.
    pub non_finite_vertices: Vec<u32>,
    /// Vertices with a finite coordinate beyond [`MAX_COORDINATE`] in magnitude.
    pub huge_vertices: Vec<u32>,
    /// Number of boundary edges (one incident triangle).
    pub boundary_edges: usize,
    /// The smallest vertex of each connected component of referenced vertices.
    pub components: Vec<u32>,
}

impl ValidationReport {
    /// True when nothing at all was found: no bad, degenerate, duplicate, non-manifold,
    /// unreferenced or non-finite element, and exactly one component (boundaries are fine).
    pub fn is_clean(&self) -> bool {
        self.out_of_range_faces.is_empty()
            && self.degenerate_faces.is_empty()
            && self.duplicate_faces.is_empty()
            && self.non_manifold_edges.is_empty()
            && self.non_manifold_vertices.is_empty()
            && self.unreferenced_vertices.is_empty()
            && self.non_finite_vertices.is_empty()
            && self.huge_vertices.is_empty()
            && self.components.len() == 1
    }

    /// The first hard error for Laplacian-based solves: empty mesh, out-of-range indices,
    /// non-finite coordinates, coordinates beyond [`MAX_COORDINATE`], non-manifold edges or
    /// vertices. Degenerate triangles,
    /// unreferenced vertices and several components are not errors here (the Laplacians skip
    /// degenerate triangles; unconstrained parts are caught by the solver).
    pub fn check_solvable(&self) -> Result<()> {
        if self.vertex_count == 0 || self.triangle_count == 0 {
            return Err(MeshError::EmptyMesh {
                vertices: self.vertex_count,
                triangles: self.triangle_count,
            });
        }
        self.check_elements()?;
        if !self.non_manifold_edges.is_empty() || !self.non_manifold_vertices.is_empty() {
            let mut ev: Vec<u32> = self.non_manifold_edges.iter().flatten().copied().collect();
            ev.sort_unstable();
            ev.dedup();
            return Err(MeshError::NonManifold {
                vertices: IndexList(self.non_manifold_vertices.clone()),
                edge_vertices: IndexList(ev),
            });
        }
        Ok(())
    }
}

impl ValidationReport {
    /// The errors of [`check_elements`]: out-of-range indices, non-finite coordinates,
    /// coordinates beyond [`MAX_COORDINATE`].
    fn check_elements(&self) -> Result<()> {
        if !self.out_of_range_faces.is_empty() {
            return Err(MeshError::FaceIndexOutOfRange {
                faces: IndexList(self.out_of_range_faces.clone()),
                vertex_count: self.vertex_count,
            });
        }
        if !self.non_finite_vertices.is_empty() {
            return Err(MeshError::NonFinite {
                vertices: IndexList(self.non_finite_vertices.clone()),
            });
        }
        if !self.huge_vertices.is_empty() {
            return Err(MeshError::CoordinateRange {
                vertices: IndexList(self.huge_vertices.clone()),
                limit: MAX_COORDINATE,
            });
        }
        Ok(())
    }
}

/// The checks every function that reads a mesh's triangles makes first (the Laplacians, the
/// mass matrices, mean-value coordinates): each triangle index in range, each coordinate
/// finite and within [`MAX_COORDINATE`]. Linear and allocation-free on a good mesh; empty,
/// degenerate and non-manifold meshes pass (see [`check_solvable`] for those).
///
/// ```
/// use deform::mesh::validate::check_elements;
/// use deform::Mesh;
/// use glam::DVec3;
/// let m = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 7]]);
/// assert!(check_elements(&m).is_err());
/// ```
pub fn check_elements(mesh: &Mesh) -> Result<()> {
    let n = mesh.positions.len();
    let mut r = positions_report(mesh);
    r.out_of_range_faces = (0..mesh.triangles.len() as u32)
        .filter(|&f| mesh.triangles[f as usize].iter().any(|&v| v as usize >= n))
        .collect();
    r.check_elements()
}

/// A report of `mesh`'s counts and of its vertices that are not finite or beyond
/// [`MAX_COORDINATE`], the rest to be filled in.
fn positions_report(mesh: &Mesh) -> ValidationReport {
    let mut r = ValidationReport {
        vertex_count: mesh.positions.len(),
        triangle_count: mesh.triangles.len(),
        ..Default::default()
    };
    for (v, p) in mesh.positions.iter().enumerate() {
        if !p.is_finite() {
            r.non_finite_vertices.push(v as u32);
        } else if p.abs().max_element() > MAX_COORDINATE {
            r.huge_vertices.push(v as u32);
        }
    }
    r
}

/// Checks a mesh and reports every problem with its indices. Never panics.
///
/// ```
/// use deform::mesh::validate::validate;
/// use deform::Mesh;
/// use glam::DVec3;
/// let m = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z], vec![[0, 1, 2], [0, 1, 7]]);
/// let r = validate(&m);
/// assert_eq!(r.out_of_range_faces, vec![1]);
/// assert_eq!(r.unreferenced_vertices, vec![3]);
/// assert!(r.check_solvable().is_err());
/// ```
pub fn validate(mesh: &Mesh) -> ValidationReport {
    inspect(mesh, true)
}

/// The checks of [`ValidationReport::check_solvable`] only (empty mesh, out-of-range indices,
/// non-finite or huge coordinates, non-manifold edges and vertices), skipping the duplicate-face and
/// component analyses: the fast path used before building Laplacian systems.
pub fn check_solvable(mesh: &Mesh) -> Result<()> {
    inspect(mesh, false).check_solvable()
}

/// Validation; `full = false` skips duplicates and components. Linear in the mesh size
/// (plus sorting), whatever the valences.
fn inspect(mesh: &Mesh, full: bool) -> ValidationReport {
    Scan::new(mesh, full).finish(full)
}

/// The first half of a validation: the positions, the triangles usable for topology and
/// their edge table, kept so that the Laplacian's pattern can be laid out from the same
/// edges ([`crate::operators::harmonic::Harmonic::new`] orders that pattern while the second half runs).
pub(crate) struct Scan {
    report: ValidationReport,
    /// Triangles in range with three distinct indices.
    good: Vec<[u32; 3]>,
    /// The edges of `good`.
    pub(crate) edges: adjacency::Edges,
}

impl Scan {
    /// Positions, triangles and edges; `full` also looks for zero-area and duplicate
    /// triangles.
    pub(crate) fn new(mesh: &Mesh, full: bool) -> Scan {
        let n = mesh.positions.len();
        let mut r = positions_report(mesh);
        // Triangles usable for topology: in range and with three distinct indices.
        let mut good = Vec::with_capacity(mesh.triangles.len());
        let mut good_ids = Vec::with_capacity(mesh.triangles.len());
        for (f, t) in mesh.triangles.iter().enumerate() {
            if t.iter().any(|&v| v as usize >= n) {
                r.out_of_range_faces.push(f as u32);
                continue;
            }
            let repeated = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
            // Zero area matters to the full report only (the solvable checks do not fail on it).
            let flat = || {
                let [a, b, c] = t.map(|v| mesh.positions[v as usize]);
                is_degenerate_triangle(a, b, c)
            };
            if repeated || (full && flat()) {
                r.degenerate_faces.push(f as u32);
            }
            if !repeated {
                good.push(*t);
                good_ids.push(f as u32);
            }
        }
        if full {
            r.duplicate_faces = duplicates(&good, &good_ids);
        }
        let edges = adjacency::edges(&good, n);
        r.boundary_edges = edges.boundary().count();
        r.non_manifold_edges = edges.non_manifold().map(|e| edges.edges[e]).collect();
        Scan {
            report: r,
            good,
            edges,
        }
    }

    /// Whether every triangle of the mesh is usable, so that `edges` are the edges of all of
    /// them.
    pub(crate) fn covers_all(&self) -> bool {
        self.good.len() == self.report.triangle_count
    }

    /// [`ValidationReport::check_solvable`] of the finished report.
    pub(crate) fn check_solvable(&self) -> Result<()> {
        self.finish(false).check_solvable()
    }

    /// The second half: fans (manifold vertices, unreferenced ones) and, if `full`, the
    /// components.
    fn finish(&self, full: bool) -> ValidationReport {
        let (n, good) = (self.report.vertex_count, &self.good);
        let mut r = self.report.clone();
        // A vertex is manifold when its triangles form one edge-connected fan.
        let fans = adjacency::fan_counts(good, n, &self.edges);
        for (v, &k) in fans.iter().enumerate() {
            match k {
                0 => r.unreferenced_vertices.push(v as u32),
                1 => {}
                _ => r.non_manifold_vertices.push(v as u32),
            }
        }
        if full {
            // Components among referenced vertices.
            let comps = adjacency::components(good, n);
            let mut seen = vec![false; comps.count];
            for (v, &k) in fans.iter().enumerate() {
                let c = comps.labels[v] as usize;
                if k > 0 && !seen[c] {
                    seen[c] = true;
                    r.components.push(v as u32);
                }
            }
        }
        r
    }
}

/// `[face, earlier]` pairs of triangles with the same vertex set (any order), sorted.
fn duplicates(triangles: &[[u32; 3]], ids: &[u32]) -> Vec<[u32; 2]> {
    let mut keys: Vec<([u32; 3], u32)> = triangles
        .iter()
        .zip(ids)
        .map(|(t, &f)| {
            let mut k = *t;
            k.sort_unstable();
            (k, f)
        })
        .collect();
    keys.sort_unstable();
    let mut out = Vec::new();
    let mut first = 0;
    for i in 1..keys.len() {
        if keys[i].0 != keys[first].0 {
            first = i;
        } else {
            // Sorted by face within equal keys: report against the first occurrence.
            out.push([keys[i].1, keys[first].1]);
        }
    }
    out.sort_unstable();
    out
}

/// The result of [`clean()`]: the cleaned mesh and the vertex maps.
#[derive(Debug, Clone, PartialEq)]
pub struct Cleaned {
    /// The cleaned mesh.
    pub mesh: Mesh,
    /// For each input vertex, its index in the cleaned mesh (`None` when removed).
    pub old_to_new: Vec<Option<u32>>,
    /// For each cleaned vertex, its input index.
    pub new_to_old: Vec<u32>,
    /// Input triangles that were dropped.
    pub removed_faces: Vec<u32>,
}

impl Cleaned {
    /// Maps input vertex indices (e.g. handles) to cleaned indices; an error names indices
    /// that are out of range or were removed.
    pub fn remap(&self, vertices: &[u32]) -> Result<Vec<u32>> {
        let bad: Vec<u32> = vertices
            .iter()
            .copied()
            .filter(|&v| v as usize >= self.old_to_new.len())
            .collect();
        if !bad.is_empty() {
            return Err(MeshError::ConstraintOutOfRange {
                vertices: IndexList(bad),
                vertex_count: self.old_to_new.len(),
            });
        }
        let removed: Vec<u32> = vertices
            .iter()
            .copied()
            .filter(|&v| self.old_to_new[v as usize].is_none())
            .collect();
        if !removed.is_empty() {
            return Err(MeshError::RemovedVertices {
                vertices: IndexList(removed),
            });
        }
        Ok(vertices
            .iter()
            .filter_map(|&v| self.old_to_new[v as usize])
            .collect())
    }
}

/// Drops triangles that are out of range, degenerate (zero area, repeated or non-finite
/// corners) or duplicates of an earlier triangle, then vertices no remaining triangle uses;
/// the remaining vertices keep their relative order.
///
/// ```
/// use deform::mesh::validate::clean;
/// use deform::Mesh;
/// use glam::DVec3;
/// let m = Mesh::new(
///     vec![DVec3::ZERO, DVec3::ONE, DVec3::X, DVec3::Y],
///     vec![[0, 2, 3], [0, 0, 2]],
/// );
/// let c = clean(&m);
/// assert_eq!(c.mesh.triangles, vec![[0, 1, 2]]);
/// assert_eq!(c.remap(&[3]).unwrap(), vec![2]);
/// assert!(c.remap(&[1]).is_err());
/// ```
pub fn clean(mesh: &Mesh) -> Cleaned {
    let report = validate(mesh);
    let mut drop = vec![false; mesh.triangles.len()];
    for &f in report
        .out_of_range_faces
        .iter()
        .chain(&report.degenerate_faces)
        .chain(report.duplicate_faces.iter().map(|d| &d[0]))
    {
        drop[f as usize] = true;
    }
    let n = mesh.positions.len();
    let mut used = vec![false; n];
    let mut removed_faces = Vec::new();
    for (f, t) in mesh.triangles.iter().enumerate() {
        if drop[f] {
            removed_faces.push(f as u32);
        } else {
            t.iter().for_each(|&v| used[v as usize] = true);
        }
    }
    let mut old_to_new = vec![None; n];
    let mut new_to_old = Vec::new();
    for v in 0..n {
        if used[v] {
            old_to_new[v] = Some(new_to_old.len() as u32);
            new_to_old.push(v as u32);
        }
    }
    let triangles = mesh
        .triangles
        .iter()
        .enumerate()
        .filter(|(f, _)| !drop[*f])
        .map(|(_, t)| t.map(|v| old_to_new[v as usize].unwrap_or(u32::MAX)))
        .collect();
    let positions = new_to_old
        .iter()
        .map(|&v| mesh.positions[v as usize])
        .collect();
    Cleaned {
        mesh: Mesh {
            positions,
            triangles,
        },
        old_to_new,
        new_to_old,
        removed_faces,
    }
}
