//! A rig at one time: local transforms, global transforms by walking the hierarchy (as
//! matrices and as motors), and the skin transforms `M_n B_n` of equation (17).

use super::animation::KeyframeBlend;
use super::edit::JointEdit;
use super::rig::Rig;
use super::SkinError;
use super::Trs;
use cga::ScaledMotor;
use glam::{DAffine3, DMat4};

/// The transforms of a rig at one time. Reused from frame to frame by [`Rig::pose_into`].
#[derive(Clone, Debug, Default)]
pub struct RigPose {
    /// Local transform per node.
    pub locals: Vec<Trs>,
    /// Global (world) matrix per node.
    pub globals: Vec<DMat4>,
    /// Global motor per node (identity for nodes no joint depends on).
    pub global_motors: Vec<ScaledMotor>,
    /// Skin matrix per joint: `global(joint) * inverse_bind(joint)`.
    pub skin_matrices: Vec<DAffine3>,
    /// Skin motor per joint, `M_n B_n` (when every transform is a similarity).
    motors: Vec<ScaledMotor>,
    /// Why the motors are missing, if they are.
    motor_error: Option<SkinError>,
}

impl RigPose {
    /// The skin motors `M_n B_n`, one per joint: the keys of [`super::Skinning`].
    ///
    /// # Errors
    /// [`SkinError::NotSimilarity`] when a joint, one of its ancestors or an inverse bind
    /// matrix has a non-uniform scale or shear (motors cannot carry it; the matrices can);
    /// [`SkinError::BadTransform`] for a similarity beyond a scaled motor's range (a scale
    /// past about `1e10` or under `1e-10`).
    pub fn skin_motors(&self) -> Result<&[ScaledMotor], SkinError> {
        match &self.motor_error {
            Some(e) => Err(e.clone()),
            None => Ok(&self.motors),
        }
    }
}

impl Rig {
    /// The rest pose (no animation, no edits).
    ///
    /// # Errors
    /// As [`Rig::pose_into`].
    pub fn rest_pose(&self) -> Result<RigPose, SkinError> {
        self.pose(None, 0.0, &[])
    }

    /// Sample animation `animation` (none: the rest transforms) at time `t` (seconds, clamped
    /// to the animation's keys), apply the joint `edits`, and build every transform.
    ///
    /// # Errors
    /// As [`Rig::pose_into`].
    pub fn pose(
        &self,
        animation: Option<usize>,
        t: f64,
        edits: &[JointEdit],
    ) -> Result<RigPose, SkinError> {
        let mut pose = RigPose::default();
        self.pose_into(animation, t, KeyframeBlend::Gltf, edits, &mut pose)?;
        Ok(pose)
    }

    /// [`Rig::pose`] into reused buffers, with a choice of keyframe blending.
    ///
    /// # Errors
    /// [`SkinError::NoAnimation`] for an index past the animations; [`SkinError::NoJoint`]
    /// for an edit of a joint past the skin; [`SkinError::BadTransform`] when an edit makes a
    /// node transform that is not `T R S`. Motors that cannot be built are reported by
    /// [`RigPose::skin_motors`], not here.
    pub fn pose_into(
        &self,
        animation: Option<usize>,
        t: f64,
        blend: KeyframeBlend,
        edits: &[JointEdit],
        pose: &mut RigPose,
    ) -> Result<(), SkinError> {
        let n = self.nodes.len();
        pose.locals.clear();
        pose.locals.extend(self.nodes.iter().map(|node| node.rest));
        if let Some(a) = animation {
            let anim = self
                .animations
                .get(a)
                .ok_or_else(|| SkinError::NoAnimation(a.to_string()))?;
            anim.apply(t, blend, &mut pose.locals);
        }
        for e in edits {
            let node = *self
                .joints
                .get(e.joint)
                .ok_or_else(|| SkinError::NoJoint(e.joint.to_string()))?;
            let m = pose.locals[node].matrix() * e.motor.to_mat4();
            pose.locals[node] = Trs::from_matrix(&m, &format!("joint {} after its edit", e.joint))?;
        }
        pose.globals.clear();
        pose.globals.resize(n, DMat4::IDENTITY);
        pose.global_motors.clear();
        pose.global_motors.resize(n, ScaledMotor::IDENTITY);
        pose.motor_error = None;
        for &i in &self.order {
            let local = pose.locals[i].matrix();
            let parent = self.nodes[i].parent;
            pose.globals[i] = parent.map_or(local, |p| pose.globals[p] * local);
            if !self.motor_nodes[i] || pose.motor_error.is_some() {
                continue;
            }
            match pose.locals[i].motor(&format!("node {:?}", self.nodes[i].name)) {
                Ok(m) => {
                    pose.global_motors[i] = parent.map_or(m, |p| pose.global_motors[p] * m);
                }
                Err(e) => pose.motor_error = Some(e),
            }
        }
        pose.skin_matrices.clear();
        pose.skin_matrices.extend(
            self.joints
                .iter()
                .zip(&self.inverse_bind)
                .map(|(&j, ibm)| DAffine3::from_mat4(pose.globals[j] * *ibm)),
        );
        pose.motors.clear();
        if pose.motor_error.is_none() {
            for (k, &j) in self.joints.iter().enumerate() {
                match &self.inverse_bind_motors[k] {
                    Ok(b) => pose.motors.push(pose.global_motors[j] * *b),
                    Err(e) => {
                        pose.motor_error = Some(e.clone());
                        break;
                    }
                }
            }
        }
        Ok(())
    }
}
