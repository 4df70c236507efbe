//! The PNG preview renderer: determinism, silhouettes against projected bounds, fill rule,
//! z-buffer, colormap, contact sheets, PNG round trip and bad input.

use std::f64::consts::PI;
use std::io::Cursor;

use deform::render::{
    render, render_views, render_with_camera, viridis, Camera, Coloring, Image, Projection,
    RenderOptions, CONTACT_SHEET_GAP, MAX_IMAGE_SIDE,
};
use deform::{Error, Mesh};
use glam::DVec3;

const BG: [u8; 3] = [235, 235, 235];
const RED: [u8; 3] = [220, 60, 40];

/// An icosphere of radius `r` centred at `c` (the library's, moved).
fn icosphere(level: u32, r: f64, c: DVec3) -> Mesh {
    let mut m = deform::shapes::icosphere(r, level as usize);
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

#[test]
fn scalar_colour_follows_the_scalar_monotonically() {
    let mesh = grid(40, 4, (0.0, 4.0), (0.0, 1.0), 0.0, 0.0);
    let x: Vec<f64> = mesh.positions.iter().map(|p| p.x).collect();
    let image = render(&mesh, Coloring::scalar(&x), &options(300, 100, 0.0, 0.0)).unwrap();
    let row: Vec<[u8; 3]> = (0..image.width)
        .map(|i| image.pixel(i, image.height / 2))
        .filter(|&c| c != BG)
        .collect();
    assert!(row.len() > 250);
    for w in row.windows(2) {
        assert!(w[1][1] >= w[0][1], "green falls: {:?} -> {:?}", w[0], w[1]);
        assert!(
            luminance(w[1]) + 1.0 >= luminance(w[0]),
            "{:?} -> {:?}",
            w[0],
            w[1]
        );
    }
    let (first, last) = (row[0], row[row.len() - 1]);
    assert!(
        first[1] < 20 && first[2] > first[1],
        "start is dark purple: {first:?}"
    );
    assert!(
        last[0] > 230 && last[1] > 220 && last[2] < 60,
        "end is yellow: {last:?}"
    );
    // An explicit range clamps: everything above `max` is the end colour.
    let clamped = Coloring::Scalar {
        values: &x,
        min: 0.0,
        max: 1.0,
    };
    let image = render(&mesh, clamped, &options(300, 100, 0.0, 0.0)).unwrap();
    assert_eq!(image.pixel(250, 50), viridis(1.0).map(|c| c as u8));
}

#[test]
fn contact_sheet_dimensions_and_placement() {
    let imgs = [
        Image::new(10, 20, [255, 0, 0]),
        Image::new(30, 5, [0, 255, 0]),
        Image::new(7, 7, [0, 0, 255]),
    ];
    let sheet = Image::contact_sheet(&imgs, 2, BG);
    let gap = CONTACT_SHEET_GAP;
    assert_eq!((sheet.width, sheet.height), (2 * 30 + gap, 2 * 20 + gap));
    assert_eq!(sheet.rgb.len(), 3 * (sheet.width * sheet.height) as usize);
    // Centred in 30x20 cells.
    assert_eq!(sheet.pixel(10, 0), [255, 0, 0]);
    assert_eq!(sheet.pixel(9, 0), BG);
    assert_eq!(sheet.pixel(30 + gap, 6), BG);
    assert_eq!(sheet.pixel(30 + gap, 7), [0, 255, 0]);
    assert_eq!(sheet.pixel(11, 20 + gap + 6), [0, 0, 255]);
    assert_eq!(sheet.pixel(30 + gap + 15, 20 + gap + 10), BG);
    // Column counts are clamped to 1..=len.
    let one = Image::contact_sheet(&imgs, 0, BG);
    assert_eq!((one.width, one.height), (30, 3 * 20 + 2 * gap));
    let wide = Image::contact_sheet(&imgs, 10, BG);
    assert_eq!((wide.width, wide.height), (3 * 30 + 2 * gap, 20));
    let none = Image::contact_sheet(&[], 3, BG);
    assert_eq!((none.width, none.height, none.rgb.len()), (0, 0, 0));
    // Rendered views on a sheet.
    let mesh = icosphere(2, 1.0, DVec3::ZERO);
    let views = [
        (0.0, 0.0),
        (90.0, 0.0),
        (30.0, 20.0),
        (0.0, 90.0),
        (45.0, -30.0),
    ];
    let sheet = render_views(
        &mesh,
        Coloring::default(),
        &options(64, 48, 0.0, 0.0),
        &views,
        3,
    )
    .unwrap();
    assert_eq!(
        (sheet.width, sheet.height),
        (3 * 64 + 2 * gap, 2 * 48 + gap)
    );
}

#[test]
fn png_bytes_decode_to_the_same_pixels() {
    let mesh = icosphere(3, 1.0, DVec3::ZERO);
    let h: Vec<f64> = mesh.positions.iter().map(|p| p.y).collect();
    let image = render(&mesh, Coloring::scalar(&h), &options(123, 77, 40.0, 25.0)).unwrap();
    let mut bytes = Vec::new();
    image.write_png_to(&mut bytes).unwrap();
    let mut reader = png::Decoder::new(Cursor::new(&bytes)).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (123, 77));
    assert_eq!(info.color_type, png::ColorType::Rgb);
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    assert_eq!(&buf[..info.buffer_size()], &image.rgb[..]);
}

#[test]
fn perspective_clips_geometry_behind_the_camera() {
    // A floor reaching far behind the eye, framed by a camera for the unit cube.
    let floor = grid(4, 4, (-100.0, 100.0), (-100.0, 100.0), 0.0, 0.0);
    let mut floor = floor;
    for p in &mut floor.positions {
        *p = DVec3::new(p.x, -1.0, p.y);
    }
    let bounds = cube().bounding_box().unwrap();
    let persp = Projection::Perspective {
        fov_y_degrees: 60.0,
    };
    let camera = Camera::framing_with(&bounds, 0.0, 0.0, 160, 120, persp);
    let image = render_with_camera(&floor, Coloring::Uniform(RED), &camera, BG).unwrap();
    // The floor is below the horizon (the image's middle row) only.
    assert!((0..160).all(|x| image.pixel(x, 0) == BG && image.pixel(x, 119) != BG));
    assert_eq!(
        image,
        render_with_camera(&floor, Coloring::Uniform(RED), &camera, BG).unwrap()
    );
    // A triangle wholly behind the eye draws nothing; one through the eye does not panic.
    let eye = camera.eye();
    let behind = Mesh::new(
        vec![
            eye + DVec3::new(-1.0, -1.0, 1.0),
            eye + DVec3::new(1.0, -1.0, 1.0),
            eye + DVec3::Z,
        ],
        vec![[0, 1, 2]],
    );
    let image = render_with_camera(&behind, Coloring::Uniform(RED), &camera, BG).unwrap();
    assert!(drawn(&image).is_empty());
    let through = Mesh::new(
        vec![
            eye + DVec3::new(-1.0, 0.0, 1.0),
            eye + DVec3::new(1.0, 0.0, 1.0),
            eye - 5.0 * DVec3::Z,
        ],
        vec![[0, 1, 2]],
    );
    render_with_camera(&through, Coloring::Uniform(RED), &camera, BG).unwrap();
}

#[test]
fn huge_triangles_are_clipped_to_the_image() {
    // Orthographic: a triangle a million times larger than the framed box covers everything.
    let tri = Mesh::new(
        vec![
            DVec3::new(-1e6, -1e6, 0.0),
            DVec3::new(1e6, -1e6, 0.0),
            DVec3::new(0.0, 1e6, 0.0),
        ],
        vec![[0, 1, 2]],
    );
    let camera = Camera::framing(&cube().bounding_box().unwrap(), 0.0, 0.0, 90, 70);
    let image = render_with_camera(&tri, Coloring::Uniform(RED), &camera, BG).unwrap();
    assert_eq!(drawn(&image).len(), 90 * 70);
}

#[test]
fn fifty_thousand_triangles_render() {
    // Speed is measured by the criterion bench, not here; this checks a dense mesh draws.
    let mesh = uv_sphere(125, 200);
    assert_eq!(mesh.triangles.len(), 50_000);
    let o = RenderOptions::default();
    let image = render(&mesh, Coloring::default(), &o).unwrap();
    assert!(!drawn(&image).is_empty());
}

#[test]
fn bad_inputs_are_errors() {
    let good = cube();
    let o = options(32, 32, 30.0, 20.0);
    let uni = Coloring::Uniform(RED);
    let empty = Mesh::new(vec![], vec![]);
    assert!(matches!(
        render(&empty, uni, &o),
        Err(Error::EmptyMesh { .. })
    ));
    let no_tris = Mesh::new(vec![DVec3::ZERO], vec![]);
    assert!(matches!(
        render(&no_tris, uni, &o),
        Err(Error::EmptyMesh { .. })
    ));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let mut m = good.clone();
        m.positions[3].y = bad;
        let e = render(&m, uni, &o).unwrap_err();
        assert!(
            matches!(&e, Error::NonFinite { vertices } if vertices.0 == vec![3]),
            "{e}"
        );
    }
    let mut huge = good.clone();
    huge.positions[0].x = 1e301;
    assert!(matches!(
        render(&huge, uni, &o),
        Err(Error::CoordinateRange { .. })
    ));
    let mut out = good.clone();
    out.triangles[5][1] = 8;
    let e = render(&out, uni, &o).unwrap_err();
    assert!(
        matches!(&e, Error::FaceIndexOutOfRange { faces, vertex_count: 8 } if faces.0 == vec![5])
    );
    let short = [0.0; 7];
    assert!(matches!(
        render(&good, Coloring::scalar(&short), &o),
        Err(Error::DimensionMismatch {
            expected: 8,
            got: 7,
            ..
        })
    ));
    let mut nan = [0.5; 8];
    nan[2] = f64::NAN;
    assert!(matches!(
        render(&good, Coloring::scalar(&nan), &o),
        Err(Error::InvalidArgument(_))
    ));
    let ok = [0.5; 8];
    for (min, max) in [(1.0, 0.0), (f64::NAN, 1.0), (0.0, f64::INFINITY)] {
        let c = Coloring::Scalar {
            values: &ok,
            min,
            max,
        };
        assert!(matches!(
            render(&good, c, &o),
            Err(Error::InvalidArgument(_))
        ));
    }
    for (w, h) in [(0, 10), (10, 0), (MAX_IMAGE_SIDE + 1, 10), (10, u32::MAX)] {
        let o = options(w, h, 0.0, 0.0);
        assert!(
            matches!(render(&good, uni, &o), Err(Error::InvalidArgument(_))),
            "{w}x{h}"
        );
    }
    // A camera that framed a non-finite box.
    let mut nan_box = good.bounding_box().unwrap();
    nan_box.max.x = f64::NAN;
    let camera = Camera::framing(&nan_box, 0.0, 0.0, 32, 32);
    assert!(matches!(
        render_with_camera(&good, uni, &camera, BG),
        Err(Error::InvalidArgument(_))
    ));
    // A zero-sized image cannot be a PNG: an error, not a panic.
    assert!(Image::new(0, 0, BG).to_png_bytes().is_err());
    // Degenerate but valid: all vertices at one point, zero-area triangles.
    let point = Mesh::new(vec![DVec3::splat(2.0); 3], vec![[0, 1, 2]]);
    let image = render(&point, uni, &o).unwrap();
    assert!(drawn(&image).is_empty());
}
