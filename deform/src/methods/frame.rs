//! Which pose of a rig a request means, the same for `skin`, the surgery commands, the editor
//! and a library caller: an animation named alone is its time 0, a time alone is in the first
//! animation (the rest pose for a model without one), neither is the bind pose; and the
//! posed frame a surgery tool is given in.

use super::error::MethodsError;
use crate::blend::BlendMethod;
use crate::mesh::Aabb;
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
