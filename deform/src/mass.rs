//! Lumped (diagonal) mass matrices.

use crate::mesh::is_degenerate_triangle;
use crate::Mesh;
use sprs::CsMat;

/// How a triangle's area is shared among its corners.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MassKind {
    /// A third of the area to each corner.
    Barycentric,
    /// Mixed Voronoi areas (Meyer et al. 2003), libigl's default for triangles: the Voronoi
    /// area of each corner for a non-obtuse triangle; for an obtuse one, half the area to the
    /// obtuse corner and a quarter to each other corner.
    #[default]
    Voronoi,
}

/// The lumped mass of every vertex (sum over incident triangles). Zero-area triangles add
/// nothing; unreferenced vertices get zero. Triangle indices must be in range.
///
/// ```
/// use deform::{mass_diagonal, MassKind, Mesh};
/// use glam::DVec3;
/// let m = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
/// let v = mass_diagonal(&m, MassKind::Voronoi);
/// // Right triangle: the right-angle corner gets half, the others a quarter of the area 1/2.
/// assert_eq!(v, vec![0.25, 0.125, 0.125]);
/// ```
pub fn mass_diagonal(mesh: &Mesh, kind: MassKind) -> Vec<f64> {
    let mut m = vec![0.0; mesh.positions.len()];
    for t in &mesh.triangles {
        let p = t.map(|v| mesh.positions[v as usize]);
        if is_degenerate_triangle(p[0], p[1], p[2]) {
            continue;
        }
        let area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length();
        let share = match kind {
            MassKind::Barycentric => [area / 3.0; 3],
            MassKind::Voronoi => voronoi_shares(p, area),
        };
        for k in 0..3 {
            m[t[k] as usize] += share[k];
        }
    }
    m
}

/// Mixed Voronoi area of each corner of a non-degenerate triangle.
fn voronoi_shares(p: [glam::DVec3; 3], area: f64) -> [f64; 3] {
    // Dot products at each corner tell obtuse (< 0) angles.
    let dots: [f64; 3] =
        std::array::from_fn(|k| (p[(k + 1) % 3] - p[k]).dot(p[(k + 2) % 3] - p[k]));
    if let Some(o) = (0..3).find(|&k| dots[k] < 0.0) {
        let mut s = [area / 4.0; 3];
        s[o] = area / 2.0;
        return s;
    }
    // cot of the angle at each corner = dot / (2 area).
    let cot: [f64; 3] = std::array::from_fn(|k| dots[k] / (2.0 * area));
    std::array::from_fn(|k| {
        let (j, l) = ((k + 1) % 3, (k + 2) % 3);
        // Edge k-j is opposite corner l; edge k-l is opposite corner j.
        ((p[j] - p[k]).length_squared() * cot[l] + (p[l] - p[k]).length_squared() * cot[j]) / 8.0
    })
}

/// The diagonal mass matrix `M` (CSR).
pub fn mass_matrix(mesh: &Mesh, kind: MassKind) -> CsMat<f64> {
    let d = mass_diagonal(mesh, kind);
    let n = d.len();
    CsMat::new((n, n), (0..=n).collect(), (0..n).collect(), d)
}
