//! The skinning deformer: a rig's rest mesh and influences bound once, posed by the skin
//! motors of any frame with any backend.

use super::{Influences, Rig, RigPose, SkinError};
use crate::blend::{BlendMethod, BoundBlend, KeyError, KeyWeights, PreparedKeys};
use crate::deformers::deformer::deformer_via_blend;
use crate::deformers::Result;
use cga::ScaledMotor;
use glam::DVec3;

/// A skinned mesh bound to its joints: `pose(skin_motors, out)` gives
/// `p_m = blend_n(w_mn, M_n B_n)(c_m)` with the blend of the chosen [`BlendMethod`]:
///
/// | backend | method |
/// |---|---|
/// | matrix LBS, f64 / f32 (glam) | [`BlendMethod::Matrix`] / [`BlendMethod::MatrixF32`] |
/// | dual-quaternion skinning (Kavan; hemisphere of the first influence) | [`BlendMethod::DualQuaternion`] |
/// | equation (17), add then down-project | [`BlendMethod::Conformal`] |
/// | equation (17), down-project each term then add | [`BlendMethod::ConformalProjected`] |
/// | motor blending (normalised weighted motor sum, scale blended geometrically) | [`BlendMethod::MotorLinear`] |
/// | log blending `exp(sum w log M)` | [`BlendMethod::MotorLog`] |
///
/// The keys are the skin motors of a [`super::RigPose`] ([`super::RigPose::skin_motors`]),
/// one per joint, in the order of [`Rig::joints`]. Influence rows keep the file's order, so
/// the dual-quaternion hemisphere reference is each vertex's first influence.
#[derive(Clone, Debug)]
pub struct Skinning {
    blend: BoundBlend,
}

impl Skinning {
    /// Bind the rig's rest mesh and influences.
    ///
    /// # Errors
    /// As [`Skinning::bind_influences`].
    pub fn bind(rig: &Rig, method: BlendMethod) -> Result<Self> {
        Self::bind_influences(
            &rig.mesh.positions,
            &rig.influences,
            rig.joints.len(),
            method,
        )
    }

    /// Bind rest positions with per-vertex influences over `joint_count` joints.
    ///
    /// # Errors
    /// [`MeshError::DimensionMismatch`](crate::mesh::MeshError::DimensionMismatch) when the influences do not match the positions,
    /// [`MeshError::InvalidArgument`](crate::mesh::MeshError::InvalidArgument) for a joint index past `joint_count` or a non-finite
    /// weight, [`crate::blend::KeyError::TooMany`] for too many joints.
    pub fn bind_influences(
        positions: &[DVec3],
        influences: &Influences,
        joint_count: usize,
        method: BlendMethod,
    ) -> Result<Self> {
        KeyError::check_count("joints", joint_count)?;
        let weights = KeyWeights::gathered(
            joint_count,
            influences.width,
            influences.joints.clone(),
            influences.weights.clone(),
        )?;
        let rest = vec![ScaledMotor::IDENTITY; joint_count];
        Ok(Skinning {
            blend: BoundBlend::bind(positions, weights, &rest, method)?,
        })
    }

    /// The bound blend (weights, method).
    pub fn blend(&self) -> &BoundBlend {
        &self.blend
    }

    /// Whether this backend blends the skin matrices themselves (matrix LBS, f64 or f32),
    /// so that any affine joint transform is skinned exactly; the others blend the skin
    /// motors, each joint's nearest similarity.
    pub fn blends_matrices(&self) -> bool {
        matches!(
            self.blend.method(),
            BlendMethod::Matrix | BlendMethod::MatrixF32
        )
    }

    /// Skin a posed rig: the matrix backends by the skin matrices exactly as glTF defines them
    /// (any affine map), the others by the skin motors ([`RigPose::skin_motors`]: each
    /// joint's nearest similarity). The scratch is the caller's, as for
    /// [`crate::Deformer::pose_using`].
    ///
    /// # Errors
    /// The motors' error ([`RigPose::skin_motors`]) for a motor backend;
    /// [`SkinError::Pose`] with the blend's (a pose of another rig, a position leaving the
    /// `f64` range).
    pub fn pose_rig(
        &self,
        pose: &RigPose,
        scratch: &mut PreparedKeys,
        out: &mut [DVec3],
    ) -> std::result::Result<(), SkinError> {
        let posed = if self.blends_matrices() {
            self.blend
                .pose_affine_using(&pose.skin_matrices, scratch, out)
        } else {
            self.blend.pose_using(pose.skin_motors()?, scratch, out)
        };
        posed.map_err(|e| SkinError::Pose(e.to_string()))
    }

    /// The best of `runs` [`Skinning::pose_rig`]s (at least one) in milliseconds, with one
    /// scratch, as [`crate::deformers::Poser::best_time_ms`] times a pose.
    ///
    /// # Errors
    /// As [`Skinning::pose_rig`].
    pub fn best_rig_time_ms(
        &self,
        pose: &RigPose,
        out: &mut [DVec3],
        runs: usize,
    ) -> std::result::Result<f64, SkinError> {
        let mut scratch = self.blend.scratch();
        let mut best = f64::INFINITY;
        for _ in 0..runs.max(1) {
            let t = std::time::Instant::now();
            self.pose_rig(pose, &mut scratch, out)?;
            best = best.min(t.elapsed().as_secs_f64() * 1e3);
        }
        Ok(best)
    }
}

deformer_via_blend!(Skinning, blend, crate::blend::PreparedKeys);

impl Rig {
    /// The rest mesh in the scene's world space at the bind pose, as viewers show the model
    /// before any animation: matrix skinning of the rest pose with the skin matrices exactly
    /// (armature transforms, unit scale and up axis applied; a Mixamo rig's centimetres and
    /// Z-up turned into the scene's metres and Y-up).
    ///
    /// # Errors
    /// As [`Rig::pose`], and [`SkinError::Pose`] for positions leaving the `f64` range.
    pub fn bind_pose_positions(&self) -> Result<Vec<DVec3>, SkinError> {
        let pose = self.rest_pose()?;
        let skin = Skinning::bind(self, crate::blend::BlendMethod::Matrix)
            .map_err(|e| SkinError::Pose(e.to_string()))?;
        let mut out = vec![DVec3::ZERO; self.mesh.vertex_count()];
        skin.pose_rig(&pose, &mut skin.blend().scratch(), &mut out)?;
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::blend::MAX_KEYS;

    #[test]
    fn too_many_joints_are_named_as_joints() {
        let influences = Influences {
            width: 4,
            joints: vec![0, 1, 2, 3],
            weights: vec![1.0, 0.0, 0.0, 0.0],
        };
        let e = Skinning::bind_influences(
            &[DVec3::ZERO],
            &influences,
            MAX_KEYS + 2,
            BlendMethod::MotorLinear,
        )
        .expect_err("too many joints");
        assert_eq!(
            e.to_string(),
            format!("{} joints: at most {MAX_KEYS} are supported", MAX_KEYS + 2)
        );
    }
}
