//! A camera that frames a box: view basis from yaw and pitch, projection, pixel mapping.

use glam::DVec3;

use crate::mesh::Aabb;

/// Fraction of the image's shorter side left free on each side by [`Camera::framing`].
pub const FRAME_MARGIN: f64 = 0.05;

/// How view space maps to the image plane.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Projection {
    /// Parallel projection along the view direction: sizes do not shrink with distance, and
    /// there is no near plane (everything on a line of sight is seen, nearest first).
    #[default]
    Orthographic,
    /// Pinhole projection with a vertical field of view in degrees (clamped to `1..=170`; NaN
    /// means 45). Geometry closer than a near plane (a thousandth of the framing distance) is
    /// clipped away, so points behind the camera are never drawn.
    Perspective {
        /// Vertical field of view in degrees.
        fov_y_degrees: f64,
    },
}

/// A half-space `a . v + b >= 0` in view coordinates.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Plane {
    pub(crate) a: DVec3,
    pub(crate) b: f64,
}

impl Plane {
    #[inline]
    pub(crate) fn distance(&self, v: DVec3) -> f64 {
        self.a.dot(v) + self.b
    }
}

/// A camera looking at a box from a direction given by yaw and pitch (degrees), orthographic
/// or perspective, framing the box so that it fills the image with a margin.
///
/// View coordinates are `x` along [`Camera::right`], `y` along [`Camera::up`] and `z` (depth)
/// along [`Camera::forward`], measured from [`Camera::eye`]. Yaw 0 and pitch 0 look along
/// `-Z` with `+X` to the right and `+Y` up; positive yaw turns the eye towards `+X` about the
/// `Y` axis and positive pitch raises it towards `+Y`.
///
/// ```
/// use deform::render::Camera;
/// use deform::mesh::Aabb;
/// use glam::DVec3;
/// let cube = Aabb { min: DVec3::splat(-1.0), max: DVec3::splat(1.0) };
/// let cam = Camera::framing(&cube, 0.0, 0.0, 200, 100);
/// let (x, y, _) = cam.project(DVec3::ZERO);
/// assert!((x - 100.0).abs() < 1e-9 && (y - 50.0).abs() < 1e-9);
/// // The square's projection fills the height less the margins: 100 - 2 * 5 pixels.
/// let (_, top, _) = cam.project(DVec3::new(0.0, 1.0, 0.0));
/// assert!((top - 5.0).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    eye: DVec3,
    right: DVec3,
    up: DVec3,
    forward: DVec3,
    projection: Projection,
    /// Pixels per unit of the raw projection.
    scale: f64,
    /// Pixel position of the raw projection's origin.
    offset: (f64, f64),
    /// Perspective near-plane depth (unused for orthographic cameras).
    near: f64,
    width: u32,
    height: u32,
}

impl Camera {
    /// An orthographic camera looking at `bounds` from yaw and pitch (degrees), scaled and
    /// centred so that the projection of the box's eight corners fills a `width x height`
    /// image less a margin of [`FRAME_MARGIN`] of the shorter side on every side.
    #[must_use]
    pub fn framing(
        bounds: &Aabb,
        yaw_degrees: f64,
        pitch_degrees: f64,
        width: u32,
        height: u32,
    ) -> Camera {
        Camera::framing_with(
            bounds,
            yaw_degrees,
            pitch_degrees,
            width,
            height,
            Projection::Orthographic,
        )
    }

    /// [`Camera::framing`] with a choice of projection. A perspective camera stands far enough
    /// away that the box's bounding sphere lies inside its field of view, then the image is
    /// scaled and centred on the projected corners as for an orthographic one.
    #[must_use]
    pub fn framing_with(
        bounds: &Aabb,
        yaw_degrees: f64,
        pitch_degrees: f64,
        width: u32,
        height: u32,
        projection: Projection,
    ) -> Camera {
        let (yaw, pitch) = (yaw_degrees.to_radians(), pitch_degrees.to_radians());
        let to_eye = DVec3::new(
            pitch.cos() * yaw.sin(),
            pitch.sin(),
            pitch.cos() * yaw.cos(),
        );
        let forward = -to_eye;
        let right = DVec3::new(yaw.cos(), 0.0, -yaw.sin());
        let up = right.cross(forward);
        let center = bounds.center();
        let mut radius = half_diagonal(bounds);
        if radius.is_nan() || radius <= 0.0 {
            radius = (center.abs().max_element() * 1e-6).max(1.0);
        }
        let (projection, distance) = match projection {
            Projection::Orthographic => (projection, 2.0 * radius),
            Projection::Perspective { fov_y_degrees } => {
                let fov = if fov_y_degrees.is_nan() {
                    45.0
                } else {
                    fov_y_degrees.clamp(1.0, 170.0)
                };
                let half_y = 0.5 * fov.to_radians();
                let aspect = f64::from(width.max(1)) / f64::from(height.max(1));
                let half_x = (half_y.tan() * aspect).atan();
                (
                    Projection::Perspective { fov_y_degrees: fov },
                    radius / half_y.min(half_x).sin(),
                )
            }
        };
        let mut camera = Camera {
            eye: center + distance * to_eye,
            right,
            up,
            forward,
            projection,
            scale: 1.0,
            offset: (0.0, 0.0),
            near: 1e-3 * distance,
            width,
            height,
        };
        camera.fit(bounds, radius, distance);
        camera
    }

    /// Chooses scale and offset so that the projected corners of `bounds` fill the image less
    /// the margins, centred.
    fn fit(&mut self, bounds: &Aabb, radius: f64, distance: f64) {
        let (mut lo, mut hi) = (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for k in 0..8 {
            let c = DVec3::new(
                if k & 1 == 0 {
                    bounds.min.x
                } else {
                    bounds.max.x
                },
                if k & 2 == 0 {
                    bounds.min.y
                } else {
                    bounds.max.y
                },
                if k & 4 == 0 {
                    bounds.min.z
                } else {
                    bounds.max.z
                },
            );
            let (x, y) = self.raw(self.to_view(c));
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
        }
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let margin = FRAME_MARGIN * w.min(h);
        let (aw, ah) = (w - 2.0 * margin, h - 2.0 * margin);
        let fit = |avail: f64, extent: f64| {
            if extent > 0.0 {
                avail / extent
            } else {
                f64::INFINITY
            }
        };
        let mut scale = fit(aw, hi.0 - lo.0).min(fit(ah, hi.1 - lo.1));
        if scale == f64::INFINITY {
            // A box seen as a point: frame its bounding sphere instead.
            let extent = match self.projection {
                Projection::Orthographic => 2.0 * radius,
                Projection::Perspective { .. } => 2.0 * radius / distance,
            };
            scale = aw.min(ah) / extent;
        }
        if !(scale.is_finite() && scale > 0.0) {
            scale = 1.0;
        }
        self.scale = scale;
        self.offset = (
            0.5 * w - scale * (0.5 * lo.0 + 0.5 * hi.0),
            0.5 * h - scale * (0.5 * lo.1 + 0.5 * hi.1),
        );
    }

    /// Pixel coordinates (x right, y down, pixel centres at half-integers) and depth (distance
    /// along [`Camera::forward`] from the eye) of a world point. For a perspective camera a
    /// depth at or below zero means the point is behind the eye, and its x and y are
    /// meaningless.
    #[inline]
    #[must_use]
    pub fn project(&self, p: DVec3) -> (f64, f64, f64) {
        let v = self.to_view(p);
        let (x, y) = self.view_to_pixel(v);
        (x, y, v.z)
    }

    /// View coordinates of a world point: `(right, up, forward)` components of `p - eye`.
    #[inline]
    #[must_use]
    pub fn to_view(&self, p: DVec3) -> DVec3 {
        let d = p - self.eye;
        DVec3::new(d.dot(self.right), d.dot(self.up), d.dot(self.forward))
    }

    /// Pixel coordinates of a point in view coordinates.
    #[inline]
    #[must_use]
    pub fn view_to_pixel(&self, v: DVec3) -> (f64, f64) {
        let (x, y) = self.raw(v);
        (
            self.offset.0 + self.scale * x,
            self.offset.1 + self.scale * y,
        )
    }

    /// The projection before scaling: `(x, -y)` or `(x / z, -y / z)`.
    #[inline]
    fn raw(&self, v: DVec3) -> (f64, f64) {
        match self.projection {
            Projection::Orthographic => (v.x, -v.y),
            Projection::Perspective { .. } => (v.x / v.z, -v.y / v.z),
        }
    }

    /// The eye position (for an orthographic camera: a point on the central line of sight,
    /// in front of the framed box).
    #[must_use]
    pub fn eye(&self) -> DVec3 {
        self.eye
    }

    /// Unit vector pointing right in the image.
    #[must_use]
    pub fn right(&self) -> DVec3 {
        self.right
    }

    /// Unit vector pointing up in the image.
    #[must_use]
    pub fn up(&self) -> DVec3 {
        self.up
    }

    /// Unit viewing direction.
    #[must_use]
    pub fn forward(&self) -> DVec3 {
        self.forward
    }

    /// The projection (a perspective field of view as clamped by the constructor).
    #[must_use]
    pub fn projection(&self) -> Projection {
        self.projection
    }

    /// Image width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Image height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Pixels per world unit (orthographic), or per unit of `x / z` (perspective).
    #[must_use]
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// True when every number of the camera is finite (false when it framed a box with NaN or
    /// infinite coordinates).
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.eye.is_finite()
            && self.right.is_finite()
            && self.up.is_finite()
            && self.forward.is_finite()
            && self.scale.is_finite()
            && self.offset.0.is_finite()
            && self.offset.1.is_finite()
            && self.near.is_finite()
    }

    /// The perspective near plane's depth (`None` for an orthographic camera).
    pub(crate) fn near_depth(&self) -> Option<f64> {
        match self.projection {
            Projection::Orthographic => None,
            Projection::Perspective { .. } => Some(self.near),
        }
    }

    /// Half-spaces in view coordinates that keep geometry in front of the near plane
    /// (perspective only) and within `guard` pixels of the image on every side.
    pub(crate) fn clip_planes(&self, guard: f64) -> Vec<Plane> {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let (s, (ox, oy)) = (self.scale, self.offset);
        let (left, right) = (ox + guard, w + guard - ox);
        let (top, bottom) = (oy + guard, h + guard - oy);
        match self.projection {
            Projection::Orthographic => vec![
                Plane {
                    a: DVec3::new(s, 0.0, 0.0),
                    b: left,
                },
                Plane {
                    a: DVec3::new(-s, 0.0, 0.0),
                    b: right,
                },
                Plane {
                    a: DVec3::new(0.0, -s, 0.0),
                    b: top,
                },
                Plane {
                    a: DVec3::new(0.0, s, 0.0),
                    b: bottom,
                },
            ],
            Projection::Perspective { .. } => vec![
                Plane {
                    a: DVec3::Z,
                    b: -self.near,
                },
                Plane {
                    a: DVec3::new(s, 0.0, left),
                    b: 0.0,
                },
                Plane {
                    a: DVec3::new(-s, 0.0, right),
                    b: 0.0,
                },
                Plane {
                    a: DVec3::new(0.0, -s, top),
                    b: 0.0,
                },
                Plane {
                    a: DVec3::new(0.0, s, bottom),
                    b: 0.0,
                },
            ],
        }
    }
}

/// Half the box's diagonal, computed without overflow for any finite box.
fn half_diagonal(bounds: &Aabb) -> f64 {
    let size = 0.5 * bounds.max - 0.5 * bounds.min;
    let m = size.abs().max_element();
    if m > 0.0 && m.is_finite() {
        m * (size / m).length()
    } else {
        m
    }
}
