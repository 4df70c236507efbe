//! The motor backends' approximation of joints that are not similarities
//! (`deform::skinning::Approximation`), in the report: the joints, the move, and a note.

use crate::report::Report;
use deform::skinning::{Approximation, Rig};

/// Add the joints and the move (relative to `diagonal`, the world-space diagonal of the
/// model) to the closing lines (and `--json`), when there are any.
pub fn report(a: &Approximation, rig: &Rig, diagonal: f64, report: &mut Report) {
    let Some(note) = a.note(diagonal) else {
        return;
    };
    let joints: Vec<serde_json::Value> = a
        .joints()
        .map(|(j, d)| {
            let name = &rig.nodes[rig.joints[j]].name;
            serde_json::json!({"joint": j, "name": name, "deviation": d})
        })
        .collect();
    report.add("approximated_joints", joints);
    report.add(
        "approximation_move_percent_of_diagonal",
        100.0 * a.shift() / diagonal,
    );
    report.add("note", note);
}
