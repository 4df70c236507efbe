//! Harmonic coordinates (Joshi, Meyer, DeRose, Green and Sanocki 2007): one harmonic function
//! per cage vertex inside the cage, equal on the cage surface to that vertex's piecewise-linear
//! hat function, solved on a voxel grid and looked up trilinearly at the model's vertices.
//!
//! The grid covers the cage's box (plus a margin) with cubic cells, `resolution` nodes along
//! its longest side. Nodes outside the cage (winding number below 1/2) within `sqrt(3)` cells
//! of its surface are boundary nodes, set to the hat functions at their closest point on the
//! cage (so every cell around a point inside the cage has only boundary or interior corners,
//! and every grid edge leaving the inside ends at a boundary node); nodes reached from the
//! grid's border without crossing that band are outside; the rest are interior, where the
//! 7-point Laplace equation is solved for every cage vertex at once with one sparse Cholesky
//! factorisation ([`crate::operators::solve::DirichletSolver`]). The coordinates reproduce the model's vertices to
//! a fraction of a grid spacing (0.28 spacings for the armadillo at 64 nodes). The discrete maximum principle keeps the coordinates in
//! `[0, 1]`; rounding residues are clamped and each row renormalised to sum to one.

use super::CageError;
use crate::deformers::Result;
use crate::mesh::Mesh;
use crate::operators::solve::DirichletSolver;
use crate::operators::solve::SolverOptions;
use glam::DVec3;
use rayon::prelude::*;
use sprs::TriMat;

/// The grid of [`harmonic_cage_coordinates`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HarmonicGrid {
    /// Nodes along the longest side of the cage's box (default 64).
    pub resolution: usize,
}

impl Default for HarmonicGrid {
    fn default() -> Self {
        HarmonicGrid { resolution: 64 }
    }
}

/// Node classes.
const OUTSIDE: u8 = 0;
const INTERIOR: u8 = 1;
const BOUNDARY: u8 = 2;

impl HarmonicGrid {
    /// The resolutions supported: 8 to 512 nodes a side.
    pub const RESOLUTIONS: std::ops::RangeInclusive<usize> = 8..=512;

    /// [`CageError::Grid`] for a resolution outside [`HarmonicGrid::RESOLUTIONS`] (what
    /// [`harmonic_cage_coordinates`] checks first; a program can ask before it sizes anything
    /// by the grid).
    pub fn check(&self) -> std::result::Result<(), CageError> {
        let r = Self::RESOLUTIONS;
        if !r.contains(&self.resolution) {
            return Err(CageError::Grid(format!(
                "resolution {} outside {} ..= {}",
                self.resolution,
                r.start(),
                r.end()
            )));
        }
        Ok(())
    }
}

/// Harmonic coordinates of `points` (inside `cage`, checked closed) on `grid`: vertex-major,
/// `cage.vertex_count()` per point, each in `[0, 1]`, each row summing to one.
///
/// # Errors
/// [`CageError::Grid`] for a resolution below 8 or above 512, or a point outside the grid;
/// solver errors (out of memory).
pub fn harmonic_cage_coordinates(
    cage: &Mesh,
    points: &[DVec3],
    grid: HarmonicGrid,
) -> Result<Vec<f64>> {
    grid.check()?;
    let b = cage
        .bounding_box()
        .ok_or_else(|| CageError::Grid("empty cage".into()))?;
    let h = b.size().max_element() / (grid.resolution - 1) as f64;
    let margin = 3;
    let g = Lattice {
        origin: b.min - DVec3::splat(margin as f64 * h),
        h,
        dims: std::array::from_fn(|a| (b.size()[a] / h).ceil() as usize + 1 + 2 * margin),
    };
    let closest = boundary_band(cage, &g);
    let class = classify(cage, &g, &closest);
    let field = solve_field(cage, &g, &class, &closest)?;
    lookup(points, &g, &field, cage.vertex_count())
}

/// The grid: nodes `origin + h (x, y, z)` for `(x, y, z) < dims`, indexed `x + X (y + Y z)`.
struct Lattice {
    origin: DVec3,
    h: f64,
    dims: [usize; 3],
}

impl Lattice {
    fn total(&self) -> usize {
        self.dims.iter().product()
    }

    fn node(&self, x: usize, y: usize, z: usize) -> usize {
        x + self.dims[0] * (y + self.dims[1] * z)
    }

    fn xyz(&self, i: usize) -> (usize, usize, usize) {
        let d = self.dims;
        (i % d[0], (i / d[0]) % d[1], i / (d[0] * d[1]))
    }

    fn at(&self, i: usize) -> DVec3 {
        let (x, y, z) = self.xyz(i);
        self.origin + self.h * DVec3::new(x as f64, y as f64, z as f64)
    }
}

/// For each node within `sqrt(3) h` of the cage: its distance, the closest face and the
/// barycentric coordinates there (infinite distance elsewhere).
fn boundary_band(cage: &Mesh, g: &Lattice) -> Vec<(f64, u32, DVec3)> {
    let (origin, h, dims) = (g.origin, g.h, g.dims);
    let band = 3f64.sqrt() * h;
    let mut closest: Vec<(f64, u32, DVec3)> = vec![(f64::INFINITY, 0, DVec3::ZERO); g.total()];
    for f in 0..cage.triangle_count() {
        let c = cage.corners(f);
        let lo = c[0].min(c[1]).min(c[2]) - DVec3::splat(band);
        let hi = c[0].max(c[1]).max(c[2]) + DVec3::splat(band);
        let r0: [usize; 3] =
            std::array::from_fn(|a| (((lo[a] - origin[a]) / h).floor().max(0.0)) as usize);
        let r1: [usize; 3] =
            std::array::from_fn(|a| ((((hi[a] - origin[a]) / h).ceil()) as usize).min(dims[a] - 1));
        for z in r0[2]..=r1[2] {
            for y in r0[1]..=r1[1] {
                for x in r0[0]..=r1[0] {
                    let i = g.node(x, y, z);
                    let (q, bary) = closest_on_triangle(g.at(i), c);
                    let d = q.distance(g.at(i));
                    if d <= band && d < closest[i].0 {
                        closest[i] = (d, f as u32, bary);
                    }
                }
            }
        }
    }
    closest
}

/// Each node outside, interior or boundary: band nodes inside the cage are unknowns too (only
/// the outer half of the band is fixed), and the outside is flooded from the grid's corner
/// (the margin is outside the band).
fn classify(cage: &Mesh, g: &Lattice, closest: &[(f64, u32, DVec3)]) -> Vec<u8> {
    let sign = super::orientation(cage);
    let mut class: Vec<u8> = closest
        .par_iter()
        .enumerate()
        .map(|(i, c)| {
            if c.0.is_finite() && sign * super::winding_number(cage, g.at(i)) < super::ENCLOSED {
                BOUNDARY
            } else {
                INTERIOR
            }
        })
        .collect();
    let dims = g.dims;
    let mut stack = vec![0usize];
    class[0] = OUTSIDE;
    while let Some(i) = stack.pop() {
        let (x, y, z) = g.xyz(i);
        let mut visit = |j: usize| {
            if class[j] == INTERIOR {
                class[j] = OUTSIDE;
                stack.push(j);
            }
        };
        if x > 0 {
            visit(i - 1);
        }
        if x + 1 < dims[0] {
            visit(i + 1);
        }
        if y > 0 {
            visit(i - dims[0]);
        }
        if y + 1 < dims[1] {
            visit(i + dims[0]);
        }
        if z > 0 {
            visit(i - dims[0] * dims[1]);
        }
        if z + 1 < dims[2] {
            visit(i + dims[0] * dims[1]);
        }
    }
    class
}

/// The harmonic field of every cage vertex on the active nodes (interior and boundary, in
/// compact order): the grid Laplacian solved with the boundary nodes fixed at the
/// barycentric coordinates of their closest cage point.
struct Field {
    /// Each node's compact index (`u32::MAX` outside).
    compact: Vec<u32>,
    /// Field of cage vertex `j` at active node `k`: `values[j * active + k]`.
    values: Vec<f64>,
    active: usize,
}

fn solve_field(
    cage: &Mesh,
    g: &Lattice,
    class: &[u8],
    closest: &[(f64, u32, DVec3)],
) -> Result<Field> {
    let (m, dims) = (cage.vertex_count(), g.dims);
    let mut compact = vec![u32::MAX; g.total()];
    let mut active = Vec::new();
    for i in 0..g.total() {
        if class[i] != OUTSIDE {
            compact[i] = active.len() as u32;
            active.push(i);
        }
    }
    let n = active.len();
    let mut q = TriMat::new((n, n));
    let mut constrained = Vec::new();
    for (k, &i) in active.iter().enumerate() {
        if class[i] == BOUNDARY {
            constrained.push(k as u32);
            continue;
        }
        let steps = [1, dims[0], dims[0] * dims[1]];
        let mut degree = 0.0;
        for s in steps {
            for j in [i - s, i + s] {
                let c = compact[j];
                if c != u32::MAX {
                    degree += 1.0;
                    q.add_triplet(k, c as usize, -1.0);
                    if class[j] == BOUNDARY {
                        q.add_triplet(c as usize, k, -1.0);
                    }
                }
            }
        }
        q.add_triplet(k, k, degree);
    }
    // Boundary rows: keep Q symmetric (their own diagonal is irrelevant to the free solve).
    for &k in &constrained {
        q.add_triplet(k as usize, k as usize, 1.0);
    }
    let q = q.to_csr::<usize>();
    let solver = DirichletSolver::new(
        &q,
        &constrained,
        SolverOptions {
            check_components: false,
            ..SolverOptions::default()
        },
    )?;
    let nc = constrained.len();
    let mut boundary = vec![0.0; nc * m];
    for (r, &k) in constrained.iter().enumerate() {
        let (_, f, bary) = closest[active[k as usize]];
        let t = cage.triangles[f as usize];
        for c in 0..3 {
            boundary[t[c] as usize * nc + r] += bary[c];
        }
    }
    let values = solver.solve(&boundary, m)?;
    Ok(Field {
        compact,
        values,
        active: n,
    })
}

/// Each point's `m` coordinates by trilinear lookup in `field`, clamped to `[0, 1]` and
/// normalised; a point in a cell with a node outside the cage is an error.
fn lookup(points: &[DVec3], g: &Lattice, field: &Field, m: usize) -> Result<Vec<f64>> {
    let (origin, h, dims, n) = (g.origin, g.h, g.dims, field.active);
    let mut out = vec![0.0; points.len() * m];
    let failed = out
        .par_chunks_mut(m)
        .zip(points.par_iter())
        .enumerate()
        .filter_map(|(i, (row, &p))| {
            let s = (p - origin) / h;
            let c = s.floor();
            if !s.is_finite() || c.min_element() < 0.0 {
                return Some(i);
            }
            let base: [usize; 3] = std::array::from_fn(|a| c[a] as usize);
            if (0..3).any(|a| base[a] + 1 >= dims[a]) {
                return Some(i);
            }
            let f = s - c;
            for corner in 0..8 {
                let o = [corner & 1, (corner >> 1) & 1, corner >> 2];
                let k = field.compact[g.node(base[0] + o[0], base[1] + o[1], base[2] + o[2])];
                if k == u32::MAX {
                    return Some(i);
                }
                let wt = (0..3)
                    .map(|a| if o[a] == 1 { f[a] } else { 1.0 - f[a] })
                    .product::<f64>();
                for (j, r) in row.iter_mut().enumerate() {
                    *r += wt * field.values[j * n + k as usize];
                }
            }
            row.iter_mut().for_each(|x| *x = x.clamp(0.0, 1.0));
            let sum: f64 = row.iter().sum();
            if sum.is_nan() || sum <= 0.0 {
                return Some(i);
            }
            row.iter_mut().for_each(|x| *x /= sum);
            None
        })
        .min();
    match failed {
        Some(i) => Err(CageError::Grid(format!(
            "vertex {i} lies in a grid cell outside the cage's interior"
        ))
        .into()),
        None => Ok(out),
    }
}

/// The closest point on triangle `t` to `p` and its barycentric coordinates (Ericson,
/// Real-Time Collision Detection, 5.1.5).
fn closest_on_triangle(p: DVec3, t: [DVec3; 3]) -> (DVec3, DVec3) {
    let [a, b, c] = t;
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return (a, DVec3::X);
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return (b, DVec3::Y);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return (a + v * ab, DVec3::new(1.0 - v, v, 0.0));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return (c, DVec3::Z);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return (a + w * ac, DVec3::new(1.0 - w, 0.0, w));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return (b + w * (c - b), DVec3::new(0.0, 1.0 - w, w));
    }
    let denom = 1.0 / (va + vb + vc);
    let (v, w) = (vb * denom, vc * denom);
    (a + ab * v + ac * w, DVec3::new(1.0 - v - w, v, w))
}
