//! PNG previews: the rest mesh beside the deformed one, seen by one camera that frames both,
//! the deformed mesh coloured by a per-vertex scalar.

use anyhow::Result;
use deform::render::{render_with_camera, Camera, Coloring, Image, RenderOptions};
use deform::skinning::Rig;
use deform::{Aabb, Mesh};

const BACKGROUND: [u8; 3] = [235, 235, 235];

/// The box holding both meshes.
fn union(a: &Aabb, b: &Aabb) -> Aabb {
    Aabb {
        min: a.min.min(b.min),
        max: a.max.max(b.max),
    }
}

/// One camera for both meshes, looking from `yaw`, `pitch`.
fn camera(rest: &Mesh, posed: &Mesh, yaw: f64, pitch: f64) -> Result<Camera> {
    let (Some(a), Some(b)) = (rest.bounding_box(), posed.bounding_box()) else {
        anyhow::bail!("cannot preview an empty mesh");
    };
    let options = RenderOptions {
        yaw_degrees: yaw,
        pitch_degrees: pitch,
        ..RenderOptions::default()
    };
    Ok(options.camera(&union(&a, &b)))
}

/// The rest mesh (plain) beside the posed mesh coloured by `scalar`.
pub fn before_after(
    rest: &Mesh,
    posed: &Mesh,
    scalar: &[f64],
    yaw: f64,
    pitch: f64,
) -> Result<Image> {
    let cam = camera(rest, posed, yaw, pitch)?;
    let a = render_with_camera(rest, Coloring::default(), &cam, BACKGROUND)?;
    let b = render_with_camera(posed, Coloring::scalar(scalar), &cam, BACKGROUND)?;
    Ok(Image::contact_sheet(&[a, b], 2, BACKGROUND))
}

/// The posed mesh alone, coloured by `scalar`, framed with the rest mesh.
pub fn posed(rest: &Mesh, posed: &Mesh, scalar: &[f64], yaw: f64, pitch: f64) -> Result<Image> {
    let cam = camera(rest, posed, yaw, pitch)?;
    Ok(render_with_camera(
        posed,
        Coloring::scalar(scalar),
        &cam,
        BACKGROUND,
    )?)
}

/// A grid of images.
pub fn sheet(images: &[Image], columns: usize) -> Image {
    Image::contact_sheet(images, columns, BACKGROUND)
}

/// The rest transform of `rig`'s skinned node: it places a mesh of the rig's rest (mesh) space
/// in world space, as a viewer shows the model at rest, so a Z-up glTF model stands upright
/// like the posed meshes the skinning formula gives.
pub fn rest_placement(rig: &Rig) -> Result<glam::DMat4> {
    let rest = rig.pose(None, 0.0, &[])?;
    Ok(rig
        .primitives
        .first()
        .map_or(glam::DMat4::IDENTITY, |p| rest.globals[p.node]))
}

/// `mesh` moved by `place` (see [`rest_placement`]).
pub fn placed(mesh: &Mesh, place: &glam::DMat4) -> Mesh {
    Mesh::new(
        mesh.positions
            .iter()
            .map(|&p| place.transform_point3(p))
            .collect(),
        mesh.triangles.clone(),
    )
}
