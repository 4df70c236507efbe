//! PNG previews, one convention for the `deform` program's commands, its demo and a library
//! caller: world space (a rig's rest mesh placed by
//! its node, as `skin` draws it), the model's up axis (+Y) up, one camera framing the rest
//! mesh, the result and the overlays; the rest mesh plain beside the result coloured by a
//! per-vertex scalar; a title (command, method, key figures) above and a colour legend
//! below; tools, cages, lattices, chains and handles drawn over both; and where the change
//! is small, a third view zoomed on the vertices it made.

use super::{
    annotate, render_with_camera, Camera, Coloring, Image, Legend, Overlay, RenderOptions,
};
use crate::mesh::{Aabb, Mesh, MeshError, Result};
use glam::DVec3;

const BACKGROUND: [u8; 3] = [235, 235, 235];

/// The view of every preview: yaw and pitch in degrees (see `deform::render::Camera`).
pub const VIEW: (f64, f64) = (30.0, 20.0);

/// The size of one panel of a command's preview.
const PANEL: (u32, u32) = (400, 320);

/// The size of one tile of the demo's contact sheet.
const TILE: (u32, u32) = (320, 240);

/// Colour of what is at rest in overlays (cage, lattice, chain, handles before the motion).
pub const REST_INK: [u8; 3] = [40, 70, 160];
/// Colour of what moved in overlays.
pub const POSED_INK: [u8; 3] = [220, 40, 40];
/// Colour of targets and tools in overlays.
pub const TOOL_INK: [u8; 3] = [230, 0, 200];
/// Colour of the box around the zoomed part.
const FOCUS_INK: [u8; 3] = [255, 140, 0];

/// A part of the result to show zoomed in: vertices of the result mesh, seen along
/// `direction` (default: the preview's view).
pub struct Focus {
    /// The vertices of the result to frame.
    pub vertices: Vec<u32>,
    /// The direction to look along (default: the preview's view).
    pub direction: Option<DVec3>,
}

/// What a preview shows besides the meshes.
pub struct Look {
    /// Command, method and key figures.
    pub title: String,
    /// The name of the per-vertex scalar of the result's colours.
    pub scalar_name: &'static str,
    /// Drawn over the rest mesh.
    pub rest: Overlay,
    /// Drawn over the result.
    pub posed: Overlay,
    /// A part to zoom on.
    pub focus: Option<Focus>,
    /// Yaw and pitch.
    pub view: (f64, f64),
}

impl Look {
    /// A look with a title and a scalar name, no overlays, the common view.
    pub fn new(title: impl Into<String>, scalar_name: &'static str) -> Look {
        Look {
            title: title.into(),
            scalar_name,
            rest: Overlay::new(2),
            posed: Overlay::new(2),
            focus: None,
            view: VIEW,
        }
    }
}

/// "max move 4.1% of diag": the largest vertex displacement from `rest` to `posed` as a
/// percentage of the rest mesh's bounding-box diagonal.
pub fn max_move(rest: &Mesh, posed: &[DVec3]) -> String {
    let diag = rest.bounding_box().map_or(f64::NAN, |b| b.diagonal());
    let moved = posed
        .iter()
        .zip(&rest.positions)
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max);
    format!("max move {:.1}% of diag", 100.0 * moved / diag)
}

/// The box holding `mesh` and the points.
fn bounds(meshes: &[&Mesh], points: &[DVec3]) -> Result<Aabb> {
    let mut all = points.iter().copied().filter(|p| p.is_finite());
    let mut b: Option<Aabb> = None;
    for m in meshes {
        let Some(mb) = m.bounding_box() else {
            return Err(MeshError::InvalidArgument(
                "cannot preview an empty mesh".into(),
            ));
        };
        b = Some(b.map_or(mb, |a| union(&a, &mb)));
    }
    let mut b = b.ok_or_else(|| MeshError::InvalidArgument("cannot preview no mesh".into()))?;
    for p in all.by_ref() {
        b = union(&b, &Aabb { min: p, max: p });
    }
    Ok(b)
}

fn union(a: &Aabb, b: &Aabb) -> Aabb {
    Aabb {
        min: a.min.min(b.min),
        max: a.max.max(b.max),
    }
}

fn camera(b: &Aabb, (yaw, pitch): (f64, f64), (width, height): (u32, u32)) -> Camera {
    let options = RenderOptions {
        width,
        height,
        yaw_degrees: yaw,
        pitch_degrees: pitch,
        ..RenderOptions::default()
    };
    options.camera(b)
}

/// Yaw and pitch of a camera looking along `d` (pitch kept off the poles).
fn view_along(d: DVec3) -> Option<(f64, f64)> {
    let d = d.try_normalize()?;
    let pitch = (-d.y)
        .clamp(-1.0, 1.0)
        .asin()
        .to_degrees()
        .clamp(-80.0, 80.0);
    let yaw = (-d.x).atan2(-d.z).to_degrees();
    Some((yaw, pitch))
}

/// The box around the focus vertices that the zoomed view frames: at least 3% of the
/// diagonal of `whole` across, and half as large again as the vertices' own box.
fn focus_box(mesh: &Mesh, focus: &Focus, whole: &Aabb) -> Option<Aabb> {
    let pts: Vec<DVec3> = focus
        .vertices
        .iter()
        .filter_map(|&v| mesh.positions.get(v as usize).copied())
        .collect();
    let b = Mesh::new(pts, Vec::new()).bounding_box()?;
    let half = (0.75 * b.diagonal()).max(0.03 * whole.diagonal());
    let c = b.center();
    Some(Aabb {
        min: c - DVec3::splat(half),
        max: c + DVec3::splat(half),
    })
}

/// The result seen through `cam`, coloured by `scalar`, with `overlay` on top.
fn panel(mesh: &Mesh, coloring: Coloring, cam: &Camera, overlay: &Overlay) -> Result<Image> {
    let mut image = render_with_camera(mesh, coloring, cam, BACKGROUND)?;
    overlay.draw(&mut image, cam);
    Ok(image)
}

/// The zoomed view of `look.focus` and the box it frames (drawn on the main view).
fn zoom(
    posed: &Mesh,
    scalar: &[f64],
    look: &Look,
    whole: &Aabb,
    size: (u32, u32),
) -> Result<Option<(Image, Aabb)>> {
    let Some(focus) = &look.focus else {
        return Ok(None);
    };
    let Some(b) = focus_box(posed, focus, whole) else {
        return Ok(None);
    };
    let view = focus.direction.and_then(view_along).unwrap_or(look.view);
    let cam = camera(&b, view, size);
    let image = panel(posed, Coloring::scalar(scalar), &cam, &look.posed)?;
    Ok(Some((image, b)))
}

/// The rest mesh (plain) beside the result coloured by `scalar` (and a zoomed view when
/// `look` has a focus), one camera for both, titled, with the legend of `scalar`.
pub fn before_after(rest: &Mesh, posed: &Mesh, scalar: &[f64], look: &Look) -> Result<Image> {
    let mut points = look.rest.points();
    points.extend(look.posed.points());
    let whole = bounds(&[rest, posed], &points)?;
    let cam = camera(&whole, look.view, PANEL);
    let a = panel(rest, Coloring::default(), &cam, &look.rest)?;
    let mut posed_overlay = look.posed.clone();
    let zoomed = zoom(posed, scalar, look, &whole, PANEL)?;
    if let Some((_, b)) = &zoomed {
        posed_overlay.aabb(b, FOCUS_INK);
    }
    let b = panel(posed, Coloring::scalar(scalar), &cam, &posed_overlay)?;
    let mut panels = vec![a, b];
    if let Some((mut z, _)) = zoomed {
        z.outline_rect(0, 0, z.width, z.height, FOCUS_INK);
        panels.push(z);
    }
    let sheet = Image::contact_sheet(&panels, panels.len(), BACKGROUND);
    let legend = Legend::of(look.scalar_name, scalar);
    Ok(annotate(&sheet, &look.title, Some(&legend), BACKGROUND))
}

/// A tile of the demo's contact sheet: the result alone, coloured by `scalar`, framed with
/// the rest mesh, titled, with its legend (and the zoomed view as an inset in a corner).
pub fn tile(rest: &Mesh, posed: &Mesh, scalar: &[f64], look: &Look) -> Result<Image> {
    let mut points = look.rest.points();
    points.extend(look.posed.points());
    let whole = bounds(&[rest, posed], &points)?;
    let cam = camera(&whole, look.view, TILE);
    let inset = (TILE.0 * 2 / 5, TILE.1 * 2 / 5);
    let zoomed = zoom(posed, scalar, look, &whole, inset)?;
    let mut overlay = look.posed.clone();
    if let Some((_, b)) = &zoomed {
        overlay.aabb(b, FOCUS_INK);
    }
    let mut image = panel(posed, Coloring::scalar(scalar), &cam, &overlay)?;
    if let Some((z, _)) = zoomed {
        let x = i64::from(image.width - z.width);
        image.paste(&z, x, 0);
        image.outline_rect(x, 0, z.width, z.height, FOCUS_INK);
    }
    let legend = Legend::of(look.scalar_name, scalar);
    Ok(annotate(&image, &look.title, Some(&legend), BACKGROUND))
}

/// A grid of images.
pub fn sheet(images: &[Image], columns: usize) -> Image {
    Image::contact_sheet(images, columns, BACKGROUND)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_view_along_a_direction_looks_along_it() {
        for d in [DVec3::NEG_Z, DVec3::X, DVec3::new(1.0, -0.5, 2.0)] {
            let (yaw, pitch) = view_along(d).unwrap();
            let b = Aabb {
                min: DVec3::splat(-1.0),
                max: DVec3::ONE,
            };
            let cam = camera(&b, (yaw, pitch), (10, 10));
            assert!(cam.forward().dot(d.normalize()) > 0.999, "{d}");
        }
        assert!(view_along(DVec3::ZERO).is_none());
    }

    #[test]
    fn max_move_is_a_percentage_of_the_diagonal() {
        let rest = Mesh::new(vec![DVec3::ZERO, DVec3::new(3.0, 4.0, 0.0)], Vec::new());
        let posed = [DVec3::ZERO, DVec3::new(3.0, 4.5, 0.0)];
        assert_eq!(max_move(&rest, &posed), "max move 10.0% of diag");
    }
}
