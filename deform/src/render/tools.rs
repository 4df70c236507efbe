//! What previews draw over the meshes (tools, cages, lattices, chains, handles), built from
//! what a deformer has: handle centroids,
//! points moved by their motors, a cage's edges, a lattice's grid lines, a spline's spine,
//! a plane, a cylinder's rims.

use super::Overlay;
use crate::mesh::shapes::grid_edges;
use crate::mesh::Mesh;
use cga::ScaledMotor;
use glam::DVec3;

/// The mean of `positions` at `vertices` (the origin for none).
pub fn centroid(positions: &[DVec3], vertices: &[u32]) -> DVec3 {
    let n = vertices.len().max(1) as f64;
    vertices
        .iter()
        .map(|&v| positions[v as usize])
        .sum::<DVec3>()
        / n
}

/// Each point moved by its motor.
pub fn moved(points: &[DVec3], motors: &[ScaledMotor]) -> Vec<DVec3> {
    points
        .iter()
        .zip(motors)
        .map(|(&p, m)| m.transform_point(p))
        .collect()
}

/// Each pair `[a, b]` of `edges` as a line between `positions[a]` and `positions[b]`.
pub fn edges(o: &mut Overlay, positions: &[DVec3], edges: &[[u32; 2]], color: [u8; 3]) {
    for &[a, b] in edges {
        o.line(positions[a as usize], positions[b as usize], color);
    }
}

/// Every edge of `mesh` once, with its positions replaced by `positions`.
pub fn mesh_edges(o: &mut Overlay, mesh: &Mesh, positions: &[DVec3], color: [u8; 3]) {
    edges(o, positions, &mesh.edges().edges, color);
}

/// The grid lines of a lattice of `dims` points indexed `u + L * (v + M * w)`
/// ([`grid_edges`]), and a dot on each point.
pub fn lattice(o: &mut Overlay, points: &[DVec3], dims: [usize; 3], color: [u8; 3]) {
    edges(o, points, &grid_edges(dims), color);
    for &p in points {
        o.dot(p, 2, color);
    }
}

/// The spine of a mesh along a parameter in `[0, 1]`: the mean position of the vertices in
/// each of `bins` slices of the parameter, empty slices skipped.
pub fn spine(positions: &[DVec3], parameter: &[f64], bins: usize) -> Vec<DVec3> {
    let bins = bins.max(1);
    let mut sum = vec![(DVec3::ZERO, 0usize); bins];
    for (p, &t) in positions.iter().zip(parameter) {
        if t.is_finite() {
            let k = ((t.clamp(0.0, 1.0) * bins as f64) as usize).min(bins - 1);
            sum[k].0 += *p;
            sum[k].1 += 1;
        }
    }
    sum.into_iter()
        .filter(|s| s.1 > 0)
        .map(|(p, n)| p / n as f64)
        .collect()
}

/// Two unit vectors perpendicular to `n` and to each other.
fn basis(n: DVec3) -> (DVec3, DVec3) {
    let n = n.normalize_or(DVec3::Z);
    let u = n.any_orthonormal_vector();
    (u, n.cross(u))
}

/// The plane `n . x = d` as a square of side `size` centred on the point of the plane nearest
/// `center`, with its diagonals.
pub fn plane(o: &mut Overlay, n: DVec3, d: f64, center: DVec3, size: f64, color: [u8; 3]) {
    let n = n.normalize_or(DVec3::Z);
    let c = center - (n.dot(center) - d) * n;
    let (u, v) = basis(n);
    let h = 0.5 * size;
    let corners = [
        c + h * (u + v),
        c + h * (u - v),
        c + h * (-u - v),
        c + h * (v - u),
    ];
    o.polyline(&corners, true, color);
    o.line(corners[0], corners[2], color);
    o.line(corners[1], corners[3], color);
}

/// A circle of `radius` about `center` in the plane perpendicular to `axis`.
pub fn circle(o: &mut Overlay, center: DVec3, axis: DVec3, radius: f64, color: [u8; 3]) {
    let (u, v) = basis(axis);
    let points: Vec<DVec3> = (0..32)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 32.0;
            center + radius * (a.cos() * u + a.sin() * v)
        })
        .collect();
    o.polyline(&points, true, color);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spine_averages_slices_and_skips_empty_ones() {
        let p = [DVec3::ZERO, DVec3::Y, DVec3::X * 10.0, DVec3::NAN];
        let t = [0.0, 0.1, 1.0, f64::NAN];
        assert_eq!(spine(&p, &t, 4), [DVec3::Y * 0.5, DVec3::X * 10.0]);
    }

    #[test]
    fn shapes_have_their_edges() {
        let mut o = Overlay::default();
        let tet = Mesh::new(
            vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
            vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        );
        mesh_edges(&mut o, &tet, &tet.positions, [0; 3]);
        assert_eq!(o.segments.len(), 6);
        let mut o = Overlay::default();
        let pts: Vec<DVec3> = (0..12).map(|k| DVec3::splat(k as f64)).collect();
        lattice(&mut o, &pts, [3, 2, 2], [0; 3]);
        // 2*2*2 along u, 3*1*2 along v, 3*2*1 along w.
        assert_eq!((o.segments.len(), o.dots.len()), (8 + 6 + 6, 12));
        let mut o = Overlay::default();
        plane(&mut o, DVec3::Y * 2.0, 3.0, DVec3::ZERO, 2.0, [0; 3]);
        assert!(o.points().iter().all(|p| (p.y - 3.0).abs() < 1e-12));
        circle(&mut o, DVec3::ZERO, DVec3::Z, 2.0, [0; 3]);
        assert!(o.points()[12..]
            .iter()
            .all(|p| (p.length() - 2.0).abs() < 1e-12));
    }
}
