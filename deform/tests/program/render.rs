//! The PNG preview renderer: determinism, silhouettes against projected bounds, fill rule,
//! z-buffer, colormap, contact sheets, PNG round trip and bad input.

use std::f64::consts::PI;

use deform::render::{render, viridis, Camera, Coloring, Image, Projection, RenderOptions};
use deform::Mesh;
use glam::DVec3;

mod output;

const BG: [u8; 3] = [235, 235, 235];
const RED: [u8; 3] = [220, 60, 40];

/// An icosphere of radius `r` centred at `c` (the library's, moved).
fn icosphere(level: u32, r: f64, c: DVec3) -> Mesh {
    let mut m = deform::mesh::shapes::icosphere(r, level as usize);
    for p in &mut m.positions {
        *p += c;
    }
    m
}

/// A UV sphere with `stacks * slices * 2` triangles (less the poles' degenerate ones).
fn uv_sphere(stacks: u32, slices: u32) -> Mesh {
    let mut p = Vec::new();
    for i in 0..=stacks {
        let th = PI * f64::from(i) / f64::from(stacks);
        for j in 0..slices {
            let ph = 2.0 * PI * f64::from(j) / f64::from(slices);
            p.push(DVec3::new(
                th.sin() * ph.cos(),
                th.cos(),
                th.sin() * ph.sin(),
            ));
        }
    }
    let mut t = Vec::new();
    for i in 0..stacks {
        for j in 0..slices {
            let (a, b) = (i * slices + j, i * slices + (j + 1) % slices);
            let (c, d) = (a + slices, b + slices);
            t.push([a, c, b]);
            t.push([b, c, d]);
        }
    }
    Mesh::new(p, t)
}

/// The cube `[-1, 1]^3`, 12 triangles.
fn cube() -> Mesh {
    let p = (0..8)
        .map(|k| {
            let s = |b: i32| if k & b == 0 { -1.0 } else { 1.0 };
            DVec3::new(s(1), s(2), s(4))
        })
        .collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let t = quads
        .iter()
        .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
        .collect();
    Mesh::new(p, t)
}

/// A grid in the plane `z = z0` over `[x0, x1] x [y0, y1]` with `nx x ny` cells; interior
/// vertices jittered in-plane by up to `jitter` of a cell (deterministically).
fn grid(
    nx: u32,
    ny: u32,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    z0: f64,
    jitter: f64,
) -> Mesh {
    let mut p = Vec::new();
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut rand = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let (dx, dy) = ((x1 - x0) / f64::from(nx), (y1 - y0) / f64::from(ny));
    for j in 0..=ny {
        for i in 0..=nx {
            let interior = i > 0 && i < nx && j > 0 && j < ny;
            let (jx, jy) = if interior {
                (rand() * jitter, rand() * jitter)
            } else {
                (0.0, 0.0)
            };
            p.push(DVec3::new(
                x0 + (f64::from(i) + jx) * dx,
                y0 + (f64::from(j) + jy) * dy,
                z0,
            ));
        }
    }
    let mut t = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let a = j * (nx + 1) + i;
            let (b, c, d) = (a + 1, a + nx + 1, a + nx + 2);
            // Alternate the diagonal and the winding to exercise both orientations.
            if (i + j) % 2 == 0 {
                t.push([a, b, d]);
                t.push([a, d, c]);
            } else {
                t.push([a, c, b]);
                t.push([b, c, d]);
            }
        }
    }
    Mesh::new(p, t)
}

/// Pixels that differ from the background.
fn drawn(image: &Image) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for y in 0..image.height {
        for x in 0..image.width {
            if image.pixel(x, y) != BG {
                out.push((x, y));
            }
        }
    }
    out
}

/// `(xmin, xmax, ymin, ymax)` of pixel centres.
fn pixel_bounds(pixels: &[(u32, u32)]) -> (f64, f64, f64, f64) {
    let xs = pixels.iter().map(|p| f64::from(p.0) + 0.5);
    let ys = pixels.iter().map(|p| f64::from(p.1) + 0.5);
    (
        xs.clone().fold(f64::INFINITY, f64::min),
        xs.fold(f64::NEG_INFINITY, f64::max),
        ys.clone().fold(f64::INFINITY, f64::min),
        ys.fold(f64::NEG_INFINITY, f64::max),
    )
}

/// `(xmin, xmax, ymin, ymax)` of the projected vertices.
fn projected_bounds(mesh: &Mesh, camera: &Camera) -> (f64, f64, f64, f64) {
    let mut b = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &p in &mesh.positions {
        let (x, y, _) = camera.project(p);
        b = (b.0.min(x), b.1.max(x), b.2.min(y), b.3.max(y));
    }
    b
}

fn options(width: u32, height: u32, yaw: f64, pitch: f64) -> RenderOptions {
    RenderOptions {
        width,
        height,
        yaw_degrees: yaw,
        pitch_degrees: pitch,
        background: BG,
        projection: Projection::Orthographic,
    }
}

fn luminance(c: [u8; 3]) -> f64 {
    0.2126 * f64::from(c[0]) + 0.7152 * f64::from(c[1]) + 0.0722 * f64::from(c[2])
}

#[test]
fn rendering_is_deterministic() {
    let mesh = icosphere(3, 1.3, DVec3::new(0.2, -0.1, 0.5));
    let lambda: Vec<f64> = mesh.positions.iter().map(|p| p.x * p.y + p.z).collect();
    for projection in [
        Projection::Orthographic,
        Projection::Perspective {
            fov_y_degrees: 40.0,
        },
    ] {
        let o = RenderOptions {
            projection,
            ..options(200, 150, 30.0, 20.0)
        };
        let a = render(&mesh, Coloring::scalar(&lambda), &o).unwrap();
        let b = render(&mesh, Coloring::scalar(&lambda), &o).unwrap();
        assert_eq!(a, b);
        assert_eq!(a.to_png_bytes().unwrap(), b.to_png_bytes().unwrap());
    }
}

#[test]
fn sphere_silhouette_matches_its_projection() {
    let (r, c) = (1.5, DVec3::new(3.0, -2.0, 1.0));
    let mesh = icosphere(4, r, c);
    for (yaw, pitch) in [(30.0, 20.0), (0.0, 0.0), (-75.0, 60.0), (180.0, -90.0)] {
        let o = options(320, 240, yaw, pitch);
        let image = render(&mesh, Coloring::Uniform(RED), &o).unwrap();
        let camera = o.camera(&mesh.bounding_box().unwrap());
        let pixels = drawn(&image);
        // Coverage against pi r^2 of the projected sphere.
        let rp = r * camera.scale();
        let disc = PI * rp * rp;
        let coverage = pixels.len() as f64;
        assert!(
            (coverage / disc - 1.0).abs() < 0.05,
            "view ({yaw}, {pitch}): {coverage} pixels, disc {disc}"
        );
        // Centre of the silhouette at the projected centre.
        let (cx, cy, _) = camera.project(c);
        let (pb, vb) = (pixel_bounds(&pixels), projected_bounds(&mesh, &camera));
        assert!(((pb.0 + pb.1) / 2.0 - cx).abs() < 1.0 && ((pb.2 + pb.3) / 2.0 - cy).abs() < 1.0);
        // Drawn bounding box against the projected vertices.
        for (d, p) in [(pb.0, vb.0), (pb.1, vb.1), (pb.2, vb.2), (pb.3, vb.3)] {
            assert!(
                (d - p).abs() <= 2.0,
                "view ({yaw}, {pitch}): drawn {pb:?} projected {vb:?}"
            );
        }
        // No cracks: every row of the convex silhouette is one run of drawn pixels.
        for y in 0..image.height {
            let row: Vec<u32> = pixels.iter().filter(|p| p.1 == y).map(|p| p.0).collect();
            if let (Some(first), Some(last)) = (row.first(), row.last()) {
                assert_eq!(row.len() as u32, last - first + 1, "gap in row {y}");
            }
        }
    }
}

#[test]
fn perspective_silhouette_matches_projected_vertices() {
    let mesh = icosphere(4, 1.0, DVec3::ZERO);
    let o = RenderOptions {
        projection: Projection::Perspective {
            fov_y_degrees: 50.0,
        },
        ..options(240, 240, 10.0, 15.0)
    };
    let image = render(&mesh, Coloring::Uniform(RED), &o).unwrap();
    let camera = o.camera(&mesh.bounding_box().unwrap());
    let (pb, vb) = (
        pixel_bounds(&drawn(&image)),
        projected_bounds(&mesh, &camera),
    );
    for (d, p) in [(pb.0, vb.0), (pb.1, vb.1), (pb.2, vb.2), (pb.3, vb.3)] {
        assert!((d - p).abs() <= 2.0, "drawn {pb:?} projected {vb:?}");
    }
}

#[test]
fn cube_head_on_covers_a_square() {
    // 200x200, margin 10: the front face spans pixels 10..190 in both directions.
    let image = render(
        &cube(),
        Coloring::Uniform(RED),
        &options(200, 200, 0.0, 0.0),
    )
    .unwrap();
    let pixels = drawn(&image);
    assert_eq!(pixels.len(), 180 * 180);
    assert!(pixels
        .iter()
        .all(|&(x, y)| (10..190).contains(&x) && (10..190).contains(&y)));
    // The face looks straight at the headlight: full intensity, one colour.
    assert!(pixels.iter().all(|&(x, y)| image.pixel(x, y) == RED));
}

#[test]
fn shared_edges_leave_no_cracks() {
    // A jittered grid with both windings and both diagonals, seen head-on: every pixel of its
    // square is drawn, by triangles of the same colour.
    let mesh = grid(37, 23, (-1.0, 1.0), (-1.0, 1.0), 0.0, 0.6);
    let image = render(&mesh, Coloring::Uniform(RED), &options(257, 193, 0.0, 0.0)).unwrap();
    let pixels = drawn(&image);
    let (x0, x1, y0, y1) = pixel_bounds(&pixels);
    let side = (x1 - x0 + 1.0) * (y1 - y0 + 1.0);
    assert_eq!(pixels.len() as f64, side);
    assert!(pixels.iter().all(|&(x, y)| image.pixel(x, y) == RED));
}

#[test]
fn the_nearer_surface_wins_whatever_the_order() {
    let near = grid(2, 2, (-1.0, 0.5), (-1.0, 0.5), 1.0, 0.0);
    let far = grid(2, 2, (-0.5, 1.0), (-0.5, 1.0), 0.0, 0.0);
    let join = |a: &Mesh, b: &Mesh| {
        let n = a.positions.len() as u32;
        let mut m = a.clone();
        m.positions.extend(&b.positions);
        m.triangles
            .extend(b.triangles.iter().map(|t| t.map(|v| v + n)));
        m
    };
    let values_for = |m: &Mesh| m.positions.iter().map(|p| p.z).collect::<Vec<_>>();
    let o = options(100, 100, 0.0, 0.0);
    for mesh in [join(&near, &far), join(&far, &near)] {
        let z = values_for(&mesh);
        let image = render(
            &mesh,
            Coloring::Scalar {
                values: &z,
                min: 0.0,
                max: 1.0,
            },
            &o,
        )
        .unwrap();
        // The overlap (around the origin, the image centre) shows the near (yellow) sheet.
        let camera = o.camera(&mesh.bounding_box().unwrap());
        let (x, y, _) = camera.project(DVec3::ZERO);
        assert_eq!(
            image.pixel(x as u32, y as u32),
            viridis(1.0).map(|c| c as u8)
        );
    }
}

#[test]
fn lighting_is_two_sided() {
    let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(0.3, 1.0, 0.2)];
    let o = options(64, 64, 20.0, 10.0);
    let a = render(
        &Mesh::new(p.clone(), vec![[0, 1, 2]]),
        Coloring::Uniform(RED),
        &o,
    )
    .unwrap();
    let b = render(&Mesh::new(p, vec![[0, 2, 1]]), Coloring::Uniform(RED), &o).unwrap();
    assert_eq!(a, b);
    assert!(!drawn(&a).is_empty());
}
