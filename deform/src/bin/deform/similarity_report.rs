//! What the motor backends change in a rig whose joint transforms are not similarities
//! (non-uniform scale, shear, mirrors): which joints, and how far the mesh moves because each
//! is taken as its nearest similarity, over every frame a command poses.

use crate::report::Report;
use deform::skinning::{Rig, RigPose};
use std::collections::BTreeMap;

/// The approximated joints and the largest move over the frames posed so far.
#[derive(Default)]
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

    /// Add the joints and the move (relative to `diagonal`, the world-space diagonal of the
    /// model) to the closing lines (and `--json`), when there are any.
    pub fn report(&self, rig: &Rig, diagonal: f64, report: &mut Report) {
        if self.joints.is_empty() {
            return;
        }
        let joints: Vec<serde_json::Value> = self
            .joints
            .iter()
            .map(|(&j, &d)| {
                serde_json::json!({
                    "joint": j,
                    "name": rig.nodes[rig.joints[j]].name,
                    "deviation": d,
                })
            })
            .collect();
        let percent = 100.0 * self.shift / diagonal;
        report.add("approximated_joints", joints);
        report.add("approximation_move_percent_of_diagonal", percent);
        report.add(
            "note",
            format!(
                "{} joint transform(s) are not similarities (non-uniform scale, shear or a \
                 mirror): this backend takes each as its nearest similarity, which moves the \
                 mesh by up to {}% of its diagonal; --backend lbs skins them exactly",
                self.joints.len(),
                deform::render::short_number(percent)
            ),
        );
    }
}
