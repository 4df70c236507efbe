//! A rig at one time: local transforms, global transforms by walking the hierarchy (as
//! matrices and as motors), and the skin transforms `M_n B_n` of equation (17).

use super::animation::KeyframeBlend;
use super::edit::JointEdit;
use super::rig::Rig;
use super::similarity::{nearest_similarity, SIMILARITY_NOISE};
use super::SkinError;
use super::Trs;
use cga::ScaledMotor;
use glam::{DAffine3, DMat4, DVec3};
use rayon::prelude::*;

/// The transforms of a rig at one time. Reused from frame to frame by [`Rig::pose_into`].
#[derive(Clone, Debug, Default)]
pub struct RigPose {
    /// Local transform per node (for an edited node whose product with its edit is not
    /// `T R S`, the nearest decomposition; the matrices below carry the product exactly).
    pub locals: Vec<Trs>,
    /// Global (world) matrix per node: the product of the local matrices from the root.
    pub globals: Vec<DMat4>,
    /// Skin matrix per joint: `global(joint) * inverse_bind(joint)`, exactly as glTF defines
    /// it (any affine map): what matrix skinning blends.
    pub skin_matrices: Vec<DAffine3>,
    /// The local matrices (edits applied), for the walk.
    local_matrices: Vec<DMat4>,
    /// Skin motor per joint: the similarity nearest to its skin matrix, `M_n B_n`.
    motors: Vec<ScaledMotor>,
    /// The nearest similarities as affine maps (for measuring what they change).
    similarities: Vec<DAffine3>,
    /// Per joint, the relative deviation of its skin matrix from its motor.
    deviations: Vec<f64>,
    /// Why the motors are missing, if they are.
    motor_error: Option<SkinError>,
}

impl RigPose {
    /// The skin motors `M_n B_n`, one per joint: the keys of [`super::Skinning`]. Each is the
    /// similarity nearest to the joint's skin matrix ([`nearest_similarity`]): the matrix
    /// itself when it is a similarity, up to rounding; otherwise (non-uniform scale, shear,
    /// a mirror) an approximation that [`RigPose::approximated_joints`] names and
    /// [`Rig::similarity_shift`] measures.
    ///
    /// # Errors
    /// [`SkinError::BadTransform`] naming the joint when its skin matrix is singular or not
    /// finite, or a similarity beyond a scaled motor's range (a scale past about `1e10` or
    /// under `1e-10`).
    pub fn skin_motors(&self) -> Result<&[ScaledMotor], SkinError> {
        match &self.motor_error {
            Some(e) => Err(e.clone()),
            None => Ok(&self.motors),
        }
    }

    /// Per joint, the relative deviation `||A - s R||_2 / s` of its skin matrix from the
    /// similarity its motor holds (0 for an exact similarity, about 1e-7 for one rounded to
    /// single precision; empty when [`RigPose::skin_motors`] fails).
    pub fn similarity_deviations(&self) -> &[f64] {
        &self.deviations
    }

    /// The joints whose skin matrix is further than [`SIMILARITY_NOISE`] from a similarity,
    /// with their deviation: the motor backends approximate these.
    pub fn approximated_joints(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.deviations
            .iter()
            .copied()
            .enumerate()
            .filter(|&(_, d)| d > SIMILARITY_NOISE)
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
    /// node transform singular or not finite. Motors that cannot be built are reported by
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
        pose.local_matrices.clear();
        pose.local_matrices
            .extend(pose.locals.iter().map(Trs::matrix));
        for e in edits {
            let node = *self
                .joints
                .get(e.joint)
                .ok_or_else(|| SkinError::NoJoint(e.joint.to_string()))?;
            let m = pose.local_matrices[node] * e.motor.to_mat4();
            let what = format!("joint {} after its edit", e.joint);
            pose.locals[node] = Trs::decompose(&m, &what)?.0;
            pose.local_matrices[node] = m;
        }
        pose.globals.clear();
        pose.globals.resize(n, DMat4::IDENTITY);
        for &i in &self.order {
            let local = pose.local_matrices[i];
            pose.globals[i] = self.nodes[i]
                .parent
                .map_or(local, |p| pose.globals[p] * local);
        }
        pose.skin_matrices.clear();
        pose.skin_matrices.extend(
            self.joints
                .iter()
                .zip(&self.inverse_bind)
                .map(|(&j, ibm)| DAffine3::from_mat4(pose.globals[j] * *ibm)),
        );
        self.skin_motors_into(pose);
        Ok(())
    }

    /// The motors of `pose.skin_matrices`: per joint its nearest similarity.
    fn skin_motors_into(&self, pose: &mut RigPose) {
        pose.motors.clear();
        pose.similarities.clear();
        pose.deviations.clear();
        pose.motor_error = None;
        for (k, m) in pose.skin_matrices.iter().enumerate() {
            let name = &self.nodes[self.joints[k]].name;
            let bad = |message: String| SkinError::BadTransform {
                what: format!("joint {k} ({name})"),
                message,
            };
            let Some(near) = nearest_similarity(m) else {
                pose.motor_error = Some(bad(
                    "its skin matrix (global * inverse bind) is singular or not finite".into(),
                ));
                break;
            };
            match ScaledMotor::try_from_scale_rotation_translation(
                near.scale,
                near.rotation,
                near.translation,
            ) {
                Ok(motor) => pose.motors.push(motor),
                Err(e) => {
                    pose.motor_error = Some(bad(format!(
                        "a similarity of scale {:e} that a scaled motor cannot hold: {e}",
                        near.scale
                    )));
                    break;
                }
            }
            pose.similarities.push(near.affine());
            pose.deviations.push(near.deviation);
        }
        if pose.motor_error.is_some() {
            pose.motors.clear();
            pose.similarities.clear();
            pose.deviations.clear();
        }
    }

    /// How far the mesh moves, at `pose`, because the motor backends take each joint's nearest
    /// similarity for its skin matrix: the largest `|sum_n w_n (S_n - M_n) p|` over the
    /// vertices (matrix skinning with the exact matrices against matrix skinning with the
    /// similarities), counting only joints past [`SIMILARITY_NOISE`]; 0 when there are none,
    /// NaN when the motors could not be built.
    pub fn similarity_shift(&self, pose: &RigPose) -> f64 {
        if pose.motor_error.is_some() || pose.deviations.len() != self.joints.len() {
            return f64::NAN;
        }
        let far: Vec<bool> = pose
            .deviations
            .iter()
            .map(|&d| d > SIMILARITY_NOISE)
            .collect();
        if !far.contains(&true) {
            return 0.0;
        }
        let inf = &self.influences;
        let width = inf.width.max(1);
        (0..self.mesh.vertex_count())
            .into_par_iter()
            .map(|v| {
                let p = self.mesh.positions[v];
                let mut shift = DVec3::ZERO;
                for k in v * width..(v + 1) * width {
                    let (j, w) = (inf.joints[k] as usize, inf.weights[k]);
                    if w != 0.0 && far[j] {
                        shift += w
                            * (pose.skin_matrices[j].transform_point3(p)
                                - pose.similarities[j].transform_point3(p));
                    }
                }
                shift.length()
            })
            .reduce(|| 0.0, f64::max)
    }
}
