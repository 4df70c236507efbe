//! Overlays: lines and dots in world space, projected by a [`Camera`] and drawn on top of a
//! rendered image (no depth test, so a handle or a chain inside the mesh stays visible).
//! Cages, lattices, chains, handle positions, tools and planes are drawn with them.

use glam::DVec3;

use super::{Camera, Image};
use crate::mesh::Aabb;

/// A straight line between two world points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// One end.
    pub a: DVec3,
    /// The other end.
    pub b: DVec3,
    /// Its colour.
    pub color: [u8; 3],
}

/// A filled disc around a world point, with a dark rim so it shows on any colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dot {
    /// Its centre.
    pub p: DVec3,
    /// Its colour.
    pub color: [u8; 3],
    /// Its radius in pixels (0 is a single pixel).
    pub radius: u32,
}

/// Lines and dots to draw over an image, in world space.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overlay {
    /// The lines, drawn first.
    pub segments: Vec<Segment>,
    /// The dots, drawn over the lines.
    pub dots: Vec<Dot>,
    /// Line width in pixels (0 means 1).
    pub line_width: u32,
}

/// The colour of a dot's rim.
const RIM: [u8; 3] = [20, 20, 20];

impl Overlay {
    /// An empty overlay with lines `line_width` pixels wide.
    #[must_use]
    pub fn new(line_width: u32) -> Overlay {
        Overlay {
            line_width,
            ..Overlay::default()
        }
    }

    /// Whether there is nothing to draw.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.segments.is_empty() && self.dots.is_empty()
    }

    /// Adds a line from `a` to `b`.
    pub fn line(&mut self, a: DVec3, b: DVec3, color: [u8; 3]) {
        self.segments.push(Segment { a, b, color });
    }

    /// Adds lines through `points` in order (closed: back to the first).
    pub fn polyline(&mut self, points: &[DVec3], closed: bool, color: [u8; 3]) {
        for w in points.windows(2) {
            self.line(w[0], w[1], color);
        }
        if closed && points.len() > 2 {
            self.line(points[points.len() - 1], points[0], color);
        }
    }

    /// Adds a dot.
    pub fn dot(&mut self, p: DVec3, radius: u32, color: [u8; 3]) {
        self.dots.push(Dot { p, color, radius });
    }

    /// Adds the twelve edges of a box.
    pub fn aabb(&mut self, b: &Aabb, color: [u8; 3]) {
        let corner = |k: usize| {
            DVec3::new(
                if k & 1 == 0 { b.min.x } else { b.max.x },
                if k & 2 == 0 { b.min.y } else { b.max.y },
                if k & 4 == 0 { b.min.z } else { b.max.z },
            )
        };
        for k in 0..8 {
            for bit in [1, 2, 4] {
                if k & bit == 0 {
                    self.line(corner(k), corner(k | bit), color);
                }
            }
        }
    }

    /// Adds everything of `other` (its line width is not taken).
    pub fn extend(&mut self, other: &Overlay) {
        self.segments.extend_from_slice(&other.segments);
        self.dots.extend_from_slice(&other.dots);
    }

    /// This overlay with every point moved by `place` (an affine map).
    #[must_use]
    pub fn placed(&self, place: &glam::DMat4) -> Overlay {
        let mut o = self.clone();
        for s in &mut o.segments {
            s.a = place.transform_point3(s.a);
            s.b = place.transform_point3(s.b);
        }
        for d in &mut o.dots {
            d.p = place.transform_point3(d.p);
        }
        o
    }

    /// Every point of the overlay (segment ends and dot centres), for framing.
    #[must_use]
    pub fn points(&self) -> Vec<DVec3> {
        let ends = self.segments.iter().flat_map(|s| [s.a, s.b]);
        ends.chain(self.dots.iter().map(|d| d.p)).collect()
    }

    /// Draws the overlay over `image` as `camera` sees it. Non-finite points are skipped, as
    /// are the parts of lines behind a perspective camera's near plane.
    pub fn draw(&self, image: &mut Image, camera: &Camera) {
        let width = self.line_width.max(1);
        for s in &self.segments {
            if let Some((a, b)) = clip_near(camera, s.a, s.b) {
                draw_line(image, a, b, width, s.color);
            }
        }
        for d in &self.dots {
            if let Some(p) = visible(camera, d.p) {
                draw_disc(image, p, d.radius + 1, RIM);
                draw_disc(image, p, d.radius, d.color);
            }
        }
    }
}

/// The pixel position of `p`, when it is finite and in front of the camera.
fn visible(camera: &Camera, p: DVec3) -> Option<(f64, f64)> {
    if !p.is_finite() {
        return None;
    }
    let (x, y, depth) = camera.project(p);
    let in_front = camera.near_depth().is_none_or(|n| depth > n);
    (in_front && x.is_finite() && y.is_finite()).then_some((x, y))
}

/// The pixel ends of the part of `a b` in front of the camera.
fn clip_near(camera: &Camera, a: DVec3, b: DVec3) -> Option<((f64, f64), (f64, f64))> {
    if !(a.is_finite() && b.is_finite()) {
        return None;
    }
    let (mut a, mut b) = (a, b);
    if let Some(n) = camera.near_depth() {
        let (da, db) = (camera.to_view(a).z, camera.to_view(b).z);
        if da <= n && db <= n {
            return None;
        }
        let cut = |p: DVec3, q: DVec3, dp: f64, dq: f64| p + (q - p) * ((n - dp) / (dq - dp));
        if da <= n {
            a = cut(a, b, da, db);
        } else if db <= n {
            b = cut(b, a, db, da);
        }
    }
    Some((visible(camera, a)?, visible(camera, b)?))
}

/// A line `width` pixels wide from `a` to `b` (pixel coordinates), clipped to the image.
fn draw_line(image: &mut Image, a: (f64, f64), b: (f64, f64), width: u32, color: [u8; 3]) {
    let (w, h) = (f64::from(image.width), f64::from(image.height));
    let Some((a, b)) = clip_to_rect(a, b, (-2.0, -2.0), (w + 2.0, h + 2.0)) else {
        return;
    };
    // Bresenham between the end pixels: every pixel of the line once, no float gaps.
    let (mut x, mut y) = (a.0.floor() as i64, a.1.floor() as i64);
    let (x1, y1) = (b.0.floor() as i64, b.1.floor() as i64);
    let (dx, dy) = ((x1 - x).abs(), -(y1 - y).abs());
    let (sx, sy) = (if x < x1 { 1 } else { -1 }, if y < y1 { 1 } else { -1 });
    let shift = i64::from(width.saturating_sub(1) / 2);
    let mut err = dx + dy;
    loop {
        image.fill_rect(x - shift, y - shift, width, width, color);
        if x == x1 && y == y1 {
            break;
        }
        let e2 = 2 * err;
        if e2 >= dy {
            err += dy;
            x += sx;
        }
        if e2 <= dx {
            err += dx;
            y += sy;
        }
    }
}

/// A filled disc of `radius` pixels around `c` (pixel coordinates), clipped.
fn draw_disc(image: &mut Image, c: (f64, f64), radius: u32, color: [u8; 3]) {
    let r = i64::from(radius);
    let reach = f64::from(radius) + 1.0;
    let (w, h) = (f64::from(image.width), f64::from(image.height));
    if !(c.0 > -reach && c.1 > -reach && c.0 < w + reach && c.1 < h + reach) {
        return;
    }
    let (cx, cy) = (c.0.floor() as i64, c.1.floor() as i64);
    for dy in -r..=r {
        for dx in -r..=r {
            if dx * dx + dy * dy <= r * r + r {
                image.fill_rect(cx + dx, cy + dy, 1, 1, color);
            }
        }
    }
}

/// Liang-Barsky: the part of the segment `a b` inside the rectangle `lo..hi`.
fn clip_to_rect(
    a: (f64, f64),
    b: (f64, f64),
    lo: (f64, f64),
    hi: (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - lo.0),
        (dx, hi.0 - a.0),
        (-dy, a.1 - lo.1),
        (dy, hi.1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some((
        (a.0 + t0 * dx, a.1 + t0 * dy),
        (a.0 + t1 * dx, a.1 + t1 * dy),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        let cube = Aabb {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        };
        Camera::framing(&cube, 0.0, 0.0, 100, 100)
    }

    fn lit(image: &Image, bg: [u8; 3]) -> usize {
        image.rgb.chunks(3).filter(|c| *c != bg).count()
    }

    #[test]
    fn a_line_and_a_dot_land_where_the_camera_projects_them() {
        let bg = [0, 0, 0];
        let mut image = Image::new(100, 100, bg);
        let mut o = Overlay::new(1);
        o.line(
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            [255, 0, 0],
        );
        o.draw(&mut image, &camera());
        // A horizontal line through the middle, from margin to margin (5 to 95).
        assert_eq!(image.pixel(50, 50), [255, 0, 0]);
        assert_eq!(image.pixel(6, 50), [255, 0, 0]);
        assert_eq!(image.pixel(50, 40), bg);
        assert_eq!(lit(&image, bg), 91);
        o.dot(DVec3::new(0.0, 1.0, 0.0), 2, [0, 255, 0]);
        o.draw(&mut image, &camera());
        assert_eq!(image.pixel(50, 5), [0, 255, 0]);
        assert_eq!(image.pixel(50, 2), RIM);
    }

    #[test]
    fn lines_off_the_image_or_not_finite_draw_nothing_and_never_panic() {
        let bg = [0, 0, 0];
        let mut image = Image::new(50, 40, bg);
        let mut o = Overlay::new(3);
        o.line(
            DVec3::new(-50.0, 9.0, 0.0),
            DVec3::new(50.0, 9.0, 0.0),
            [1, 2, 3],
        );
        o.line(DVec3::NAN, DVec3::ZERO, [1, 2, 3]);
        o.dot(DVec3::new(1e300, 0.0, 0.0), 4, [1, 2, 3]);
        o.dot(DVec3::INFINITY, 4, [1, 2, 3]);
        o.draw(&mut image, &camera());
        assert_eq!(lit(&image, bg), 0);
        // A long line across the image is clipped, not walked pixel by pixel to infinity.
        o.line(
            DVec3::new(-1e12, 0.5, 0.0),
            DVec3::new(1e12, 0.6, 0.0),
            [7, 7, 7],
        );
        o.draw(&mut image, &camera());
        assert!(lit(&image, bg) >= 50);
    }

    #[test]
    fn box_edges_and_points() {
        let mut o = Overlay::default();
        o.aabb(
            &Aabb {
                min: DVec3::ZERO,
                max: DVec3::ONE,
            },
            [0; 3],
        );
        assert_eq!(o.segments.len(), 12);
        o.polyline(&[DVec3::ZERO, DVec3::X, DVec3::Y], true, [0; 3]);
        assert_eq!(o.segments.len(), 15);
        assert_eq!(o.points().len(), 30);
        assert!(!o.is_empty());
    }
}
