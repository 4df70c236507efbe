//! Triangle clipping and z-buffered scan conversion with a top-left fill rule.
//!
//! Vertices are snapped to a fixed-point grid of [`SUBPIXELS`] steps per pixel and edge
//! functions are evaluated exactly in integers, so two triangles sharing an edge agree on
//! every pixel centre along it: the top-left rule gives each such pixel to exactly one of them
//! (no cracks, no double coverage). Clipping computes each new vertex from the edge's
//! endpoints in a canonical order, so a clipped shared edge is cut at bit-identical points in
//! both triangles.

use std::cmp::Ordering;

use glam::DVec3;

use super::camera::{Camera, Plane};

/// Fixed-point steps per pixel.
const SUBPIXELS: i64 = 256;

/// A clipped polygon has at most 3 + (number of planes) vertices.
const MAX_POLYGON: usize = 3 + 5;

/// A vertex in view coordinates with the scalar attribute it carries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Vertex {
    pub(crate) view: DVec3,
    pub(crate) scalar: f64,
}

impl Vertex {
    /// A total order on vertices, used to make clipping independent of edge direction.
    fn canonical_cmp(&self, other: &Vertex) -> Ordering {
        let (a, b) = (self.view, other.view);
        a.x.total_cmp(&b.x)
            .then(a.y.total_cmp(&b.y))
            .then(a.z.total_cmp(&b.z))
            .then(self.scalar.total_cmp(&other.scalar))
    }
}

/// How a triangle's pixels get their colour.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Paint {
    /// One colour for the whole triangle.
    Flat([u8; 3]),
    /// The interpolated scalar through `color(scalar)`, times `intensity`.
    Scalar { intensity: f64 },
}

/// Colour and depth buffers being drawn into.
pub(crate) struct Target<'a> {
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) rgb: &'a mut [u8],
    /// Depth keys, smaller is nearer; `+inf` where nothing is drawn.
    pub(crate) depth: Vec<f64>,
    /// Perspective-correct interpolation (depth key `-1/z`, attributes over `z`).
    pub(crate) perspective: bool,
}

/// Per-vertex quantities that are affine in screen space.
#[derive(Debug, Clone, Copy)]
struct Screen {
    x: i64,
    y: i64,
    /// Depth key.
    key: f64,
    /// Interpolation weight: 1 (orthographic) or `1/z` (perspective).
    weight: f64,
    /// Scalar times weight.
    scalar: f64,
}

/// Clips a triangle against `planes` and rasterises what is left.
pub(crate) fn draw_triangle(
    target: &mut Target,
    camera: &Camera,
    planes: &[Plane],
    tri: [Vertex; 3],
    paint: Paint,
    color: &dyn Fn(f64) -> [f64; 3],
) {
    let mut poly = [tri[0]; MAX_POLYGON];
    poly[..3].copy_from_slice(&tri);
    let mut len = 3;
    for plane in planes {
        let d = tri.map(|v| plane.distance(v.view));
        if d.iter().all(|&d| d < 0.0) || d.iter().any(|d| d.is_nan()) {
            return;
        }
    }
    for plane in planes {
        len = clip(&mut poly, len, plane);
        if len < 3 {
            return;
        }
    }
    let mut screen = [Screen {
        x: 0,
        y: 0,
        key: 0.0,
        weight: 0.0,
        scalar: 0.0,
    }; MAX_POLYGON];
    for (s, v) in screen.iter_mut().zip(&poly[..len]) {
        match to_screen(camera, v, target.perspective) {
            Some(p) => *s = p,
            None => return,
        }
    }
    for k in 1..len - 1 {
        fill(target, [screen[0], screen[k], screen[k + 1]], paint, color);
    }
}

/// Sutherland-Hodgman against one plane, in place; returns the new length.
fn clip(poly: &mut [Vertex; MAX_POLYGON], len: usize, plane: &Plane) -> usize {
    let d: [f64; MAX_POLYGON] = std::array::from_fn(|i| {
        if i < len {
            plane.distance(poly[i].view)
        } else {
            0.0
        }
    });
    if d[..len].iter().all(|&d| d >= 0.0) {
        return len;
    }
    let src = *poly;
    let mut n = 0;
    for i in 0..len {
        let j = (i + 1) % len;
        let (a, b) = (src[i], src[j]);
        if d[i] >= 0.0 && n < MAX_POLYGON {
            poly[n] = a;
            n += 1;
        }
        if (d[i] >= 0.0) != (d[j] >= 0.0) && n < MAX_POLYGON {
            poly[n] = intersect(a, d[i], b, d[j]);
            n += 1;
        }
    }
    n
}

/// The point where the edge `a b` crosses the plane, computed from the endpoints in
/// canonical order so that the result does not depend on the edge's direction.
fn intersect(a: Vertex, da: f64, b: Vertex, db: f64) -> Vertex {
    let ((p, dp), (q, dq)) = if a.canonical_cmp(&b) == Ordering::Greater {
        ((b, db), (a, da))
    } else {
        ((a, da), (b, db))
    };
    let t = dp / (dp - dq);
    Vertex {
        view: p.view + t * (q.view - p.view),
        scalar: p.scalar + t * (q.scalar - p.scalar),
    }
}

/// Snaps a view-space vertex to the fixed-point pixel grid; `None` when it is not finite or
/// too far out for exact integer edge functions.
fn to_screen(camera: &Camera, v: &Vertex, perspective: bool) -> Option<Screen> {
    // Clipping keeps vertices within a guard band of the image, far below this bound; it
    // keeps edge-function products below 2^62.
    const LIMIT: f64 = (1i64 << 29) as f64;
    let (x, y) = camera.view_to_pixel(v.view);
    let (sx, sy) = (
        (x * SUBPIXELS as f64).round(),
        (y * SUBPIXELS as f64).round(),
    );
    if !(sx.abs() < LIMIT && sy.abs() < LIMIT) {
        return None;
    }
    let (key, weight) = if perspective {
        (-1.0 / v.view.z, 1.0 / v.view.z)
    } else {
        (v.view.z, 1.0)
    };
    Some(Screen {
        x: sx as i64,
        y: sy as i64,
        key,
        weight,
        scalar: v.scalar * weight,
    })
}

/// Twice the signed area of `a b p` in fixed point (positive when clockwise on screen, since
/// y points down).
#[inline]
fn edge(a: &Screen, b: &Screen, px: i64, py: i64) -> i64 {
    (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x)
}

/// Whether the edge `a -> b` of a positive-area triangle is a top or a left edge.
#[inline]
fn is_top_left(a: &Screen, b: &Screen) -> bool {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    dy < 0 || (dy == 0 && dx > 0)
}

/// Scan-converts one screen triangle (either orientation) with depth test.
fn fill(target: &mut Target, tri: [Screen; 3], paint: Paint, color: &dyn Fn(f64) -> [f64; 3]) {
    let [a, mut b, mut c] = tri;
    let mut area = edge(&a, &b, c.x, c.y);
    if area == 0 {
        return;
    }
    if area < 0 {
        std::mem::swap(&mut b, &mut c);
        area = -area;
    }
    const HALF: i64 = SUBPIXELS / 2;
    let (w, h) = (i64::from(target.width), i64::from(target.height));
    // Pixel (i, j) has its centre at (i * S + S/2, j * S + S/2).
    let first = |m: i64| -(-(m - HALF)).div_euclid(SUBPIXELS);
    let last = |m: i64| (m - HALF).div_euclid(SUBPIXELS);
    let x0 = first(a.x.min(b.x).min(c.x)).max(0);
    let x1 = last(a.x.max(b.x).max(c.x)).min(w - 1);
    let y0 = first(a.y.min(b.y).min(c.y)).max(0);
    let y1 = last(a.y.max(b.y).max(c.y)).min(h - 1);
    if x0 > x1 || y0 > y1 {
        return;
    }
    // Edge k is opposite vertex k; its value is vertex k's barycentric weight times `area`.
    let edges = [(&b, &c), (&c, &a), (&a, &b)];
    let bias = edges.map(|(p, q)| if is_top_left(p, q) { 0 } else { -1 });
    let step_x = edges.map(|(p, q)| -(q.y - p.y) * SUBPIXELS);
    let step_y = edges.map(|(p, q)| (q.x - p.x) * SUBPIXELS);
    let (px0, py0) = (x0 * SUBPIXELS + HALF, y0 * SUBPIXELS + HALF);
    let mut row = edges.map(|(p, q)| edge(p, q, px0, py0));
    let inv = 1.0 / area as f64;
    let verts = [a, b, c];
    let lerp = |e: &[i64; 3], f: fn(&Screen) -> f64| -> f64 {
        (e[0] as f64 * f(&verts[0]) + e[1] as f64 * f(&verts[1]) + e[2] as f64 * f(&verts[2])) * inv
    };
    for y in y0..=y1 {
        let mut e = row;
        for x in x0..=x1 {
            if e[0] + bias[0] >= 0 && e[1] + bias[1] >= 0 && e[2] + bias[2] >= 0 {
                let i = (y * w + x) as usize;
                let key = lerp(&e, |s| s.key);
                if key < target.depth[i] {
                    target.depth[i] = key;
                    let rgb = match paint {
                        Paint::Flat(rgb) => rgb,
                        Paint::Scalar { intensity } => {
                            let s = lerp(&e, |s| s.scalar) / lerp(&e, |s| s.weight);
                            color(s).map(|c| (c * intensity).round().clamp(0.0, 255.0) as u8)
                        }
                    };
                    target.rgb[3 * i..3 * i + 3].copy_from_slice(&rgb);
                }
            }
            for k in 0..3 {
                e[k] += step_x[k];
            }
        }
        for k in 0..3 {
            row[k] += step_y[k];
        }
    }
}
