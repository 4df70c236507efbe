//! What comes out: colour along a scalar, contact sheets and PNG bytes; clipping behind the
//! camera and at the image's edges, a large mesh, and bad input.

use super::{cube, drawn, grid, icosphere, luminance, options, uv_sphere, BG, RED};
use deform::mesh::MeshError;
use std::io::Cursor;

use deform::render::{
    render, render_views, render_with_camera, viridis, Camera, Coloring, Image, Projection,
    RenderOptions, CONTACT_SHEET_GAP, MAX_IMAGE_SIDE,
};
use deform::Mesh;
use glam::DVec3;

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
        Err(MeshError::EmptyMesh { .. })
    ));
    let no_tris = Mesh::new(vec![DVec3::ZERO], vec![]);
    assert!(matches!(
        render(&no_tris, uni, &o),
        Err(MeshError::EmptyMesh { .. })
    ));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let mut m = good.clone();
        m.positions[3].y = bad;
        let e = render(&m, uni, &o).unwrap_err();
        assert!(
            matches!(&e, MeshError::NonFinite { vertices } if vertices.0 == vec![3]),
            "{e}"
        );
    }
    let mut huge = good.clone();
    huge.positions[0].x = 1e301;
    assert!(matches!(
        render(&huge, uni, &o),
        Err(MeshError::CoordinateRange { .. })
    ));
    let mut out = good.clone();
    out.triangles[5][1] = 8;
    let e = render(&out, uni, &o).unwrap_err();
    assert!(
        matches!(&e, MeshError::FaceIndexOutOfRange { faces, vertex_count: 8 } if faces.0 == vec![5])
    );
    let short = [0.0; 7];
    assert!(matches!(
        render(&good, Coloring::scalar(&short), &o),
        Err(MeshError::DimensionMismatch {
            expected: 8,
            got: 7,
            ..
        })
    ));
    let mut nan = [0.5; 8];
    nan[2] = f64::NAN;
    assert!(matches!(
        render(&good, Coloring::scalar(&nan), &o),
        Err(MeshError::InvalidArgument(_))
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
            Err(MeshError::InvalidArgument(_))
        ));
    }
    for (w, h) in [(0, 10), (10, 0), (MAX_IMAGE_SIDE + 1, 10), (10, u32::MAX)] {
        let o = options(w, h, 0.0, 0.0);
        assert!(
            matches!(render(&good, uni, &o), Err(MeshError::InvalidArgument(_))),
            "{w}x{h}"
        );
    }
    // A camera that framed a non-finite box.
    let mut nan_box = good.bounding_box().unwrap();
    nan_box.max.x = f64::NAN;
    let camera = Camera::framing(&nan_box, 0.0, 0.0, 32, 32);
    assert!(matches!(
        render_with_camera(&good, uni, &camera, BG),
        Err(MeshError::InvalidArgument(_))
    ));
    // A zero-sized image cannot be a PNG: an error, not a panic.
    assert!(Image::new(0, 0, BG).to_png_bytes().is_err());
    // Degenerate but valid: all vertices at one point, zero-area triangles.
    let point = Mesh::new(vec![DVec3::splat(2.0); 3], vec![[0, 1, 2]]);
    let image = render(&point, uni, &o).unwrap();
    assert!(drawn(&image).is_empty());
}
