//! Procedural meshes for demos, tests and benches (no files needed): a capped tube (a round
//! bar) and a subdivided sphere.

use crate::mesh::Mesh;
use glam::DVec3;
use std::f64::consts::TAU;

/// A tube along `+x` from `x = 0` to `x = length`, of `radius`, with `rings` rings of
/// `sides` vertices (ring-major: vertex `r * sides + k` is ring `r`, angle `k`), closed by a
/// fan at each end whose centres are the last two vertices (`x = 0`, then `x = length`).
/// Outward-facing, watertight. Needs `sides >= 3`, `rings >= 2`.
///
/// ```
/// let bar = deform::mesh::shapes::tube(1.0, 10.0, 16, 21);
/// assert_eq!(bar.vertex_count(), 16 * 21 + 2);
/// // The volume of a prism over the inscribed 16-gon: outward-facing and closed.
/// let area = 8.0 * (std::f64::consts::TAU / 16.0).sin();
/// assert!((bar.volume() - 10.0 * area).abs() < 1e-9);
/// ```
///
/// # Panics
/// When the tube would have more vertices than 32-bit indices hold.
pub fn tube(radius: f64, length: f64, sides: usize, rings: usize) -> Mesh {
    let (sides, rings) = (sides.max(3), rings.max(2));
    assert!(
        sides
            .checked_mul(rings)
            .and_then(|v| v.checked_add(2))
            .is_some_and(|v| v <= u32::MAX as usize),
        "a tube of {sides} sides and {rings} rings has more vertices than 32-bit indices hold"
    );
    let mut positions = Vec::with_capacity(sides * rings + 2);
    for r in 0..rings {
        let x = length * r as f64 / (rings - 1) as f64;
        for k in 0..sides {
            let a = TAU * k as f64 / sides as f64;
            positions.push(DVec3::new(x, radius * a.cos(), radius * a.sin()));
        }
    }
    let start = positions.len() as u32;
    positions.push(DVec3::ZERO);
    positions.push(DVec3::new(length, 0.0, 0.0));
    let v = |r: usize, k: usize| (r * sides + k % sides) as u32;
    let mut triangles = Vec::with_capacity(2 * sides * rings);
    for r in 0..rings - 1 {
        for k in 0..sides {
            triangles.push([v(r, k), v(r + 1, k + 1), v(r + 1, k)]);
            triangles.push([v(r, k), v(r, k + 1), v(r + 1, k + 1)]);
        }
    }
    for k in 0..sides {
        triangles.push([start, v(0, k + 1), v(0, k)]);
        triangles.push([start + 1, v(rings - 1, k), v(rings - 1, k + 1)]);
    }
    Mesh::new(positions, triangles)
}

/// The vertices of ring `r` of a [`tube`] with `sides` sides.
///
/// # Panics
/// When ring `r` lies past the 32-bit indices (no [`tube`] has it).
pub fn tube_ring(sides: usize, r: usize) -> Vec<u32> {
    assert!(
        (r + 1)
            .checked_mul(sides)
            .is_some_and(|e| e <= u32::MAX as usize),
        "ring {r} of {sides} sides lies past the 32-bit indices"
    );
    (r * sides..(r + 1) * sides).map(|i| i as u32).collect()
}

/// A sphere of `radius` about the origin: an icosahedron subdivided `levels` times (each
/// level splits every triangle in four), vertices projected onto the sphere.
///
/// ```
/// let s = deform::mesh::shapes::icosphere(1.0, 2);
/// assert_eq!((s.vertex_count(), s.triangle_count()), (162, 320));
/// ```
///
/// # Panics
/// For more than 14 levels (`10 * 4^levels + 2` vertices pass the 32-bit indices there).
pub fn icosphere(radius: f64, levels: usize) -> Mesh {
    assert!(
        levels <= 14,
        "an icosphere of {levels} levels has more vertices than 32-bit indices hold (at most 14)"
    );
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let positions = [
        (-1.0, t, 0.0),
        (1.0, t, 0.0),
        (-1.0, -t, 0.0),
        (1.0, -t, 0.0),
        (0.0, -1.0, t),
        (0.0, 1.0, t),
        (0.0, -1.0, -t),
        (0.0, 1.0, -t),
        (t, 0.0, -1.0),
        (t, 0.0, 1.0),
        (-t, 0.0, -1.0),
        (-t, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| DVec3::new(x, y, z))
    .collect();
    let triangles = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    let mut mesh = Mesh::new(positions, triangles);
    for _ in 0..levels {
        mesh = mesh.subdivide_midpoint();
    }
    for p in &mut mesh.positions {
        *p = radius * p.normalize();
    }
    mesh
}

/// The grid lines of an `L x M x N` grid of points indexed `u + L * (v + M * w)`: each pair of
/// neighbours `[i, j]` along u, v and w.
///
/// ```
/// let e = deform::mesh::shapes::grid_edges([3, 2, 2]);
/// assert_eq!(e.len(), 2 * 2 * 2 + 3 * 1 * 2 + 3 * 2 * 1);
/// assert!(e.contains(&[0, 1]) && e.contains(&[0, 3]) && e.contains(&[0, 6]));
/// ```
pub fn grid_edges(dims: [usize; 3]) -> Vec<[u32; 2]> {
    let [a, b, c] = dims;
    let index = |u: usize, v: usize, w: usize| (u + a * (v + b * w)) as u32;
    let mut edges = Vec::new();
    for w in 0..c {
        for v in 0..b {
            for u in 0..a {
                for (du, dv, dw) in [(1, 0, 0), (0, 1, 0), (0, 0, 1)] {
                    if u + du < a && v + dv < b && w + dw < c {
                        edges.push([index(u, v, w), index(u + du, v + dv, w + dw)]);
                    }
                }
            }
        }
    }
    edges
}
