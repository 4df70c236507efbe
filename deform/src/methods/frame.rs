//! Which pose of a rig a request means, the same for `skin`, the surgery commands, the editor
//! and a library caller: an animation named alone is its time 0, a time alone is in the first
//! animation (the rest pose for a model without one), neither is the bind pose; and the
//! posed frame a surgery tool is given in.

use super::error::MethodsError;
use crate::blend::BlendMethod;
use crate::mesh::Aabb;
use crate::render::preview::{before_after, Focus, Look};
use crate::render::Image;
use crate::skinning::{Rig, SkinError, Skinning};
use crate::surgery::Frame;

type Result<T> = std::result::Result<T, MethodsError>;
use crate::mesh::Mesh;
use glam::{DAffine3, DVec3};

/// The pose a request names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoseTime {
    /// The animation (`None`: the rest pose, no animation).
    pub animation: Option<usize>,
    /// The time in seconds (0 without one).
    pub time: f64,
    /// Whether a time or an animation was asked for (a posed frame), not the bind pose.
    pub posed: bool,
}

/// The pose meant by an optional animation (by name or index) and an optional time.
///
/// ```
/// use deform::methods::frame::pose_time;
/// let rig = deform::skinning::procedural_arm(8, 9);
/// assert_eq!(pose_time(&rig, None, Some(0.5)).unwrap().animation, Some(0));
/// assert_eq!(pose_time(&rig, Some("0"), None).unwrap().time, 0.0);
/// assert!(!pose_time(&rig, None, None).unwrap().posed);
/// assert!(pose_time(&rig, Some("no such"), None).is_err());
/// ```
///
/// # Errors
/// [`SkinError::NoAnimation`] for an animation the rig does not have.
pub fn pose_time(
    rig: &Rig,
    animation: Option<&str>,
    time: Option<f64>,
) -> std::result::Result<PoseTime, SkinError> {
    let animation = match animation {
        Some(name) => Some(rig.animation_index(name)?),
        None if time.is_some() && !rig.animations.is_empty() => Some(0),
        None => None,
    };
    Ok(PoseTime {
        posed: time.is_some() || animation.is_some(),
        animation,
        time: time.unwrap_or(0.0),
    })
}

/// Where a surgery tool's coordinates are given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToolSpace {
    /// The rest mesh's own coordinates.
    Mesh,
    /// The scene's world space at the bind pose (the default).
    BindPose,
    /// The posed world space at a time of an animation.
    Posed,
}

/// The posed positions and skin matrices of the frame a tool is given in (linear blend
/// skinning by the skin matrices, as glTF viewers pose).
pub struct ToolFrame {
    /// The posed positions, one per vertex.
    pub positions: Vec<DVec3>,
    /// The skin matrix of each joint.
    pub skin: Vec<DAffine3>,
    /// The bind pose or a posed frame.
    pub space: ToolSpace,
}

impl ToolFrame {
    /// The frame of `pose` ([`pose_time`]'s: the bind pose when not posed).
    pub fn new(rig: &Rig, pose: PoseTime) -> Result<ToolFrame> {
        let p = rig.pose(pose.animation, pose.time, &[])?;
        let lbs = Skinning::bind(rig, BlendMethod::Matrix)?;
        let mut positions = vec![DVec3::ZERO; rig.mesh.vertex_count()];
        lbs.pose_rig(&p, &mut lbs.blend().scratch(), &mut positions)?;
        let space = if pose.posed {
            ToolSpace::Posed
        } else {
            ToolSpace::BindPose
        };
        Ok(ToolFrame {
            positions,
            skin: p.skin_matrices.clone(),
            space,
        })
    }

    /// The surgery's frame of `frame` (`None`: the rest mesh's own space).
    pub fn surgery_frame(frame: &Option<ToolFrame>) -> Frame<'_> {
        match frame {
            None => Frame::Rest,
            Some(p) => Frame::Posed {
                positions: &p.positions,
                skin: &p.skin,
            },
        }
    }

    /// The space of `frame`.
    pub fn space(frame: &Option<ToolFrame>) -> ToolSpace {
        frame.as_ref().map_or(ToolSpace::Mesh, |p| p.space)
    }

    /// The model's box in the tool's space (to size what is drawn of a tool).
    pub fn bounds(frame: &Option<ToolFrame>, rig: &Rig) -> Option<Aabb> {
        match frame {
            None => rig.mesh.bounding_box(),
            Some(p) => Mesh::new(p.positions.clone(), Vec::new()).bounding_box(),
        }
    }
}

/// How [`parts_preview`] shows a rig's parts: the space the tool was given in, the vertices a
/// tool made (`marks`, one value per vertex of the parts in order, else each vertex coloured
/// by its part), the direction to zoom on them along, and the view.
pub struct PartsView {
    /// Where the tool (and the overlays) were given.
    pub space: ToolSpace,
    /// A value per vertex of the parts (the vertices a tool made), or `None`.
    pub marks: Option<Vec<f64>>,
    /// The direction to look at the marked vertices along, zoomed.
    pub focus: Option<DVec3>,
    /// The preview's yaw and pitch.
    pub view: (f64, f64),
}

/// The preview of `rig` made into `result` (its vertices traced back to the parts' by
/// `trace`, as [`Rig::with_parts_traced`] gives): the rest in the scene's world space at the
/// bind pose beside each part skinned at the rest pose and pulled apart by `away(part)`,
/// coloured by part or by the marks; `look`'s overlays, given in the tool's space, are drawn
/// in world space.
pub fn parts_preview(
    rig: &Rig,
    result: &Rig,
    trace: &[usize],
    away: &dyn Fn(usize) -> DVec3,
    shown: PartsView,
    look: Look,
) -> Result<Image> {
    // Tools given in the rest mesh's space are placed as the mesh node places the mesh;
    // tools in the bind pose's world space are drawn as given.
    let place = match shown.space {
        ToolSpace::Mesh => rig.rest_placement()?,
        ToolSpace::BindPose | ToolSpace::Posed => glam::DMat4::IDENTITY,
    };
    let rest_world = rig.bind_pose_positions()?;
    let mut parts = Mesh::new(result.bind_pose_positions()?, result.mesh.triangles.clone());
    let mut part_of = vec![0.0; parts.vertex_count()];
    for p in &result.primitives {
        // The part a primitive belongs to (a part with several materials has several).
        let k = p.primitive;
        let shift = place.transform_vector3(away(k));
        let r = p.vertex_offset..p.vertex_offset + p.vertex_count;
        parts.positions[r.clone()]
            .iter_mut()
            .for_each(|x| *x += shift);
        part_of[r].iter_mut().for_each(|x| *x = k as f64);
    }
    // The marks follow the vertices into the rig's order (regrouped by primitive).
    let marks = shown
        .marks
        .map(|m| trace.iter().map(|&v| m[v]).collect::<Vec<f64>>());
    let mut look = look;
    if let (Some(m), Some(direction)) = (&marks, shown.focus) {
        let vertices: Vec<u32> = (0..m.len() as u32)
            .filter(|&v| m[v as usize] > 0.0)
            .collect();
        if !vertices.is_empty() {
            look.focus = Some(Focus {
                vertices,
                direction: Some(direction),
            });
        }
    }
    let scalar = marks.unwrap_or(part_of);
    let look = Look {
        rest: look.rest.placed(&place),
        posed: look.posed.placed(&place),
        focus: look.focus.map(|f| Focus {
            direction: f.direction.map(|d| place.transform_vector3(d)),
            ..f
        }),
        view: shown.view,
        ..look
    };
    let rest = Mesh::new(rest_world, rig.mesh.triangles.clone());
    Ok(before_after(&rest, &parts, &scalar, &look)?)
}
