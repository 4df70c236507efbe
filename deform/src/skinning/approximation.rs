//! What the motor backends change in a rig whose joint transforms are not similarities
//! (non-uniform scale, shear, mirrors): which joints, and how far the mesh moves because each
//! is taken as its nearest similarity, over every frame posed.

use super::pose::RigPose;
use super::rig::Rig;
use std::collections::BTreeMap;

/// The approximated joints and the largest move over the frames counted so far.
#[derive(Clone, Debug, Default)]
pub struct Approximation {
    /// Skin joint -> its largest relative deviation from a similarity.
    joints: BTreeMap<usize, f64>,
    /// The largest move, in the units of the posed mesh (world space).
    shift: f64,
}

impl Approximation {
    /// Count one posed frame.
    pub fn add(&mut self, rig: &Rig, pose: &RigPose) {
        let mut any = false;
        for (j, d) in pose.approximated_joints() {
            let e = self.joints.entry(j).or_insert(0.0);
            *e = e.max(d);
            any = true;
        }
        if !any {
            return;
        }
        let shift = rig.similarity_shift(pose);
        if shift.is_finite() {
            self.shift = self.shift.max(shift);
        }
    }

    /// Each approximated skin joint with its largest relative deviation, in joint order.
    pub fn joints(&self) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.joints.iter().map(|(&j, &d)| (j, d))
    }

    /// The largest move of a vertex, in the posed mesh's units.
    pub fn shift(&self) -> f64 {
        self.shift
    }

    /// What to tell a user, with the move as a percentage of `diagonal` (the model's);
    /// `None` when every joint was a similarity.
    pub fn note(&self, diagonal: f64) -> Option<String> {
        if self.joints.is_empty() {
            return None;
        }
        Some(format!(
            "{} joint transform(s) are not similarities (non-uniform scale, shear or a \
             mirror): this backend takes each as its nearest similarity, which moves the \
             mesh by up to {}% of its diagonal; --backend lbs skins them exactly",
            self.joints.len(),
            crate::mesh::numbers::short_number(100.0 * self.shift / diagonal)
        ))
    }
}
