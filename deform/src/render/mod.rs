//! A small deterministic software renderer for PNG previews of meshes.
//!
//! **May use**: the mesh foundation. **Must not use**: any other layer or the crate-level
//! `Error`; it reports [`MeshError`] (bad meshes, sizes and files).
//!
//! * [`Camera`]: looks at a box from a yaw and a pitch, orthographic or perspective
//!   ([`Projection`]), and frames it so that it fills the image with a margin;
//! * [`render`] / [`render_with_camera`]: z-buffered, flat-shaded triangles (Lambert with a
//!   headlight plus ambient, two-sided, so open and inconsistently oriented meshes look
//!   right), coloured uniformly or by a per-vertex scalar through a viridis-like colormap
//!   ([`Coloring`], [`viridis`]);
//! * [`Image`]: RGB8 pixels, PNG encoding ([`Image::write_png_to`]) and contact sheets of
//!   several views ([`Image::contact_sheet`], [`render_views`]);
//! * [`Overlay`]: lines and dots in world space (cages, lattices, chains, handles, tools)
//!   projected by the same camera and drawn on top;
//! * [`font`]: a 5x8 bitmap font of printable ASCII ([`Image::draw_text`]), and [`annotate`]:
//!   a title band above an image and a colour [`Legend`] below it.
//!
//! Rasterisation is exact on a fixed-point grid with a top-left fill rule, so triangles that
//! share an edge leave no cracks and cover no pixel twice; everything runs in plain sequential
//! loops, so the same input gives the same bytes on every run. Bad input (an empty mesh,
//! non-finite or huge coordinates, out-of-range indices, a scalar slice of the wrong length,
//! an image side of 0 or above [`MAX_IMAGE_SIDE`]) is an error, never a panic.
//!
//! ```
//! use deform::render::{render, render_views, Coloring, Image, RenderOptions};
//! use deform::Mesh;
//! use glam::DVec3;
//! let tet = Mesh::new(
//!     vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
//!     vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
//! );
//! let options = RenderOptions { width: 64, height: 48, ..Default::default() };
//! let image = render(&tet, Coloring::Uniform([200, 120, 80]), &options).unwrap();
//! assert_eq!((image.width, image.height), (64, 48));
//! assert_ne!(image.pixel(32, 24), options.background);
//!
//! // Colour by height, four views on a sheet of two columns, as PNG.
//! let height: Vec<f64> = tet.positions.iter().map(|p| p.y).collect();
//! let views = [(0.0, 0.0), (90.0, 0.0), (30.0, 20.0), (0.0, 90.0)];
//! let sheet = render_views(&tet, Coloring::scalar(&height), &options, &views, 2).unwrap();
//! assert_eq!(sheet.width, 2 * 64 + deform::render::CONTACT_SHEET_GAP);
//! let mut png = Vec::new();
//! sheet.write_png_to(&mut png).unwrap();
//! assert_eq!(&png[1..4], b"PNG");
//! ```

mod annotate;
mod camera;
mod colormap;
pub mod font;
mod image;
mod overlay;
pub mod preview;
mod raster;
pub mod tools;

pub use crate::mesh::numbers::short_number;
pub use annotate::{annotate, text_scale, wrap, Legend, TEXT_COLOR};
pub use camera::{Camera, Projection, FRAME_MARGIN};
pub use colormap::viridis;
pub use image::{Image, CONTACT_SHEET_GAP, MAX_IMAGE_SIDE};
pub use overlay::{Dot, Overlay, Segment};

use glam::DVec3;

use crate::mesh::validate::MAX_COORDINATE;
use crate::mesh::IndexList;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::mesh::Result;
use raster::{Paint, Target, Vertex};

/// The light that reaches faces seen edge-on; faces facing the camera get 1.
pub const AMBIENT: f64 = 0.3;

/// The colour of [`Coloring::default`].
pub const DEFAULT_MESH_COLOR: [u8; 3] = [200, 190, 170];

/// How the triangles are coloured before shading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Coloring<'a> {
    /// One colour for the whole mesh.
    Uniform([u8; 3]),
    /// One value per vertex, interpolated across triangles (perspective-correct) and mapped
    /// through [`viridis`]: `min` (and below) is dark purple, `max` (and above) yellow. The
    /// values must be finite and `min <= max`; `min == max` maps everything to the middle.
    Scalar {
        /// One value per vertex.
        values: &'a [f64],
        /// Value shown as the colormap's start.
        min: f64,
        /// Value shown as the colormap's end.
        max: f64,
    },
}

impl Default for Coloring<'_> {
    fn default() -> Self {
        Coloring::Uniform(DEFAULT_MESH_COLOR)
    }
}

impl<'a> Coloring<'a> {
    /// [`Coloring::Scalar`] over the range of the finite `values` (0 to 1 when there are
    /// none).
    #[must_use]
    pub fn scalar(values: &'a [f64]) -> Coloring<'a> {
        let finite = values.iter().copied().filter(|v| v.is_finite());
        let min = finite.clone().fold(f64::INFINITY, f64::min);
        let max = finite.fold(f64::NEG_INFINITY, f64::max);
        let (min, max) = if min <= max { (min, max) } else { (0.0, 1.0) };
        Coloring::Scalar { values, min, max }
    }
}

/// Image size, view direction, projection and background of [`render`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RenderOptions {
    /// Image width in pixels (`1..=MAX_IMAGE_SIDE`).
    pub width: u32,
    /// Image height in pixels (`1..=MAX_IMAGE_SIDE`).
    pub height: u32,
    /// Turn of the eye about the `Y` axis, degrees (0 looks along `-Z`).
    pub yaw_degrees: f64,
    /// Elevation of the eye above the `XZ` plane, degrees.
    pub pitch_degrees: f64,
    /// Colour where no triangle is drawn.
    pub background: [u8; 3],
    /// Orthographic (default) or perspective.
    pub projection: Projection,
}

impl Default for RenderOptions {
    /// 320x240, yaw 30, pitch 20, light grey background, orthographic.
    fn default() -> Self {
        RenderOptions {
            width: 320,
            height: 240,
            yaw_degrees: 30.0,
            pitch_degrees: 20.0,
            background: [235, 235, 235],
            projection: Projection::Orthographic,
        }
    }
}

impl RenderOptions {
    /// The camera these options give for a box (see [`Camera::framing_with`]).
    #[must_use]
    pub fn camera(&self, bounds: &crate::mesh::Aabb) -> Camera {
        Camera::framing_with(
            bounds,
            self.yaw_degrees,
            self.pitch_degrees,
            self.width,
            self.height,
            self.projection,
        )
    }
}

/// Renders `mesh` with a camera framing the mesh itself (its bounding box).
///
/// # Errors
/// See [`render_with_camera`].
pub fn render(mesh: &Mesh, coloring: Coloring, options: &RenderOptions) -> Result<Image> {
    Image::check_size(options.width, options.height)?;
    check_mesh(mesh)?;
    let bounds = mesh.bounding_box().ok_or(MeshError::EmptyMesh {
        vertices: 0,
        triangles: mesh.triangles.len(),
    })?;
    render_with_camera(mesh, coloring, &options.camera(&bounds), options.background)
}

/// Renders `mesh` with a given camera (so a rest mesh and its posed copies share one view).
/// Parts of the mesh outside the camera's view are simply not drawn.
///
/// # Errors
/// * [`MeshError::InvalidArgument`]: an image side of 0 or above [`MAX_IMAGE_SIDE`], a camera with
///   non-finite numbers, a non-finite scalar value or range, or `min > max`;
/// * [`MeshError::EmptyMesh`]: no vertices or no triangles;
/// * [`MeshError::NonFinite`]: vertices with NaN or infinite coordinates;
/// * [`MeshError::CoordinateRange`]: coordinates beyond [`MAX_COORDINATE`] in magnitude;
/// * [`MeshError::FaceIndexOutOfRange`]: triangles referring to missing vertices;
/// * [`MeshError::DimensionMismatch`]: scalar values not one per vertex.
pub fn render_with_camera(
    mesh: &Mesh,
    coloring: Coloring,
    camera: &Camera,
    background: [u8; 3],
) -> Result<Image> {
    let (width, height) = (camera.width(), camera.height());
    Image::check_size(width, height)?;
    check_mesh(mesh)?;
    check_coloring(mesh, &coloring)?;
    if !camera.is_finite() {
        return Err(MeshError::InvalidArgument(
            "the camera has non-finite parameters (did it frame a non-finite box?)".into(),
        ));
    }
    let mut image = Image::new(width, height, background);
    let perspective = matches!(camera.projection(), Projection::Perspective { .. });
    let mut target = Target {
        width,
        height,
        rgb: &mut image.rgb,
        depth: vec![f64::INFINITY; width as usize * height as usize],
        perspective,
    };
    let planes = camera.clip_planes(f64::from(width.max(height)));
    let view: Vec<DVec3> = mesh.positions.iter().map(|&p| camera.to_view(p)).collect();
    let (values, min, max) = match coloring {
        Coloring::Uniform(_) => (None, 0.0, 1.0),
        Coloring::Scalar { values, min, max } => (Some(values), min, max),
    };
    let color = move |s: f64| viridis(colormap::normalize(s, min, max));
    for t in &mesh.triangles {
        let tri = t.map(|v| Vertex {
            view: view[v as usize],
            scalar: values.map_or(0.0, |s| s[v as usize]),
        });
        let Some(intensity) = intensity(&tri) else {
            continue;
        };
        let paint = match coloring {
            Coloring::Uniform(rgb) => Paint::Flat(rgb.map(|c| shade(f64::from(c), intensity))),
            Coloring::Scalar { .. } => Paint::Scalar { intensity },
        };
        raster::draw_triangle(&mut target, camera, &planes, tri, paint, &color);
    }
    Ok(image)
}

/// Renders one image per `(yaw, pitch)` view (degrees; other settings from `options`, each
/// view framing the mesh) and lays them out with [`Image::contact_sheet`] in `columns`
/// columns on `options.background`.
///
/// # Errors
/// As [`render`].
pub fn render_views(
    mesh: &Mesh,
    coloring: Coloring,
    options: &RenderOptions,
    views: &[(f64, f64)],
    columns: usize,
) -> Result<Image> {
    let images = views
        .iter()
        .map(|&(yaw_degrees, pitch_degrees)| {
            let o = RenderOptions {
                yaw_degrees,
                pitch_degrees,
                ..*options
            };
            render(mesh, coloring, &o)
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Image::contact_sheet(&images, columns, options.background))
}

/// Lambert term with a headlight along the view direction (so coplanar triangles get one
/// shade, also in perspective), two-sided, plus ambient; `None` for a triangle without a
/// normal (zero area or non-finite).
fn intensity(tri: &[Vertex; 3]) -> Option<f64> {
    let (e1, e2) = (tri[1].view - tri[0].view, tri[2].view - tri[0].view);
    // Scaled so that the cross product cannot overflow.
    let m = e1.abs().max_element().max(e2.abs().max_element());
    if !(m > 0.0 && m.is_finite()) {
        return None;
    }
    let n = (e1 / m).cross(e2 / m).normalize_or_zero();
    if n == DVec3::ZERO {
        return None;
    }
    Some(AMBIENT + (1.0 - AMBIENT) * n.z.abs())
}

/// A colour channel times an intensity, rounded to 8 bits.
#[inline]
fn shade(c: f64, intensity: f64) -> u8 {
    (c * intensity).round().clamp(0.0, 255.0) as u8
}

/// Empty mesh, non-finite or huge coordinates, out-of-range indices.
fn check_mesh(mesh: &Mesh) -> Result<()> {
    if mesh.is_empty() {
        return Err(MeshError::EmptyMesh {
            vertices: mesh.positions.len(),
            triangles: mesh.triangles.len(),
        });
    }
    let (mut non_finite, mut huge) = (Vec::new(), Vec::new());
    for (v, p) in mesh.positions.iter().enumerate() {
        if !p.is_finite() {
            non_finite.push(v as u32);
        } else if p.abs().max_element() > MAX_COORDINATE {
            huge.push(v as u32);
        }
    }
    if !non_finite.is_empty() {
        return Err(MeshError::NonFinite {
            vertices: IndexList(non_finite),
        });
    }
    if !huge.is_empty() {
        return Err(MeshError::CoordinateRange {
            vertices: IndexList(huge),
            limit: MAX_COORDINATE,
        });
    }
    let n = mesh.positions.len();
    let bad: Vec<u32> = (0..mesh.triangles.len() as u32)
        .filter(|&f| mesh.triangles[f as usize].iter().any(|&v| v as usize >= n))
        .collect();
    if !bad.is_empty() {
        return Err(MeshError::FaceIndexOutOfRange {
            faces: IndexList(bad),
            vertex_count: n,
        });
    }
    Ok(())
}

/// One finite value per vertex and a finite range with `min <= max`.
fn check_coloring(mesh: &Mesh, coloring: &Coloring) -> Result<()> {
    let Coloring::Scalar { values, min, max } = *coloring else {
        return Ok(());
    };
    if values.len() != mesh.positions.len() {
        return Err(MeshError::DimensionMismatch {
            what: "scalar values (one per vertex)",
            expected: mesh.positions.len(),
            got: values.len(),
        });
    }
    if let Some(v) = values.iter().position(|s| !s.is_finite()) {
        return Err(MeshError::InvalidArgument(format!(
            "scalar value {} at vertex {v} is not finite",
            values[v]
        )));
    }
    if !(min.is_finite() && max.is_finite() && min <= max) {
        return Err(MeshError::InvalidArgument(format!(
            "scalar range [{min}, {max}] must be finite with min <= max"
        )));
    }
    Ok(())
}
