//! Lumped (diagonal) mass matrices.

use crate::mesh::triangle::Frame;
use crate::mesh::validate::check_elements;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::operators::Result;
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
/// nothing; unreferenced vertices get zero. Out-of-range indices and non-finite or huge
/// coordinates are the errors of [`check_elements`].
///
/// Shares are computed in each triangle's normalised frame (see
/// [`crate::mesh::is_degenerate_triangle`]) and scaled back to real units; masses are areas,
/// so coordinates beyond about `1e150` (or below `1e-160`) can leave the `f64` range: that
/// is [`MeshError::Overflow`] (a non-degenerate triangle whose area overflows or underflows to
/// zero, or a vertex whose sum overflows), never an infinite or zero mass.
///
/// ```
/// use deform::operators::mass::{mass_diagonal, MassKind};
/// use deform::Mesh;
/// use glam::DVec3;
/// let m = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
/// let v = mass_diagonal(&m, MassKind::Voronoi).unwrap();
/// // Right triangle: the right-angle corner gets half, the others a quarter of the area 1/2.
/// assert_eq!(v, vec![0.25, 0.125, 0.125]);
/// ```
pub fn mass_diagonal(mesh: &Mesh, kind: MassKind) -> Result<Vec<f64>> {
    check_elements(mesh)?;
    let mut m = vec![0.0; mesh.positions.len()];
    for (f, t) in mesh.triangles.iter().enumerate() {
        let Some(frame) = Frame::new(t.map(|v| mesh.positions[v as usize])) else {
            continue;
        };
        let area = 0.5 * frame.double_area();
        let share = match kind {
            MassKind::Barycentric => [area / 3.0; 3],
            MassKind::Voronoi => frame.voronoi_shares(),
        };
        for k in 0..3 {
            let s = frame.unscale(share[k], 2);
            if !s.is_finite() || s <= 0.0 {
                return Err(MeshError::Overflow {
                    what: "triangle area",
                    index: f,
                }
                .into());
            }
            m[t[k] as usize] += s;
        }
    }
    if let Some(index) = m.iter().position(|x| !x.is_finite()) {
        return Err(MeshError::Overflow {
            what: "vertex mass",
            index,
        }
        .into());
    }
    Ok(m)
}

/// The diagonal mass matrix `M` (CSR); see [`mass_diagonal`].
pub fn mass_matrix(mesh: &Mesh, kind: MassKind) -> Result<CsMat<f64>> {
    let d = mass_diagonal(mesh, kind)?;
    let n = d.len();
    Ok(CsMat::new((n, n), (0..=n).collect(), (0..n).collect(), d))
}
