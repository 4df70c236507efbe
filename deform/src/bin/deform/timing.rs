//! Timings the commands report, in milliseconds.

use anyhow::Result;
use deform::{Deformer, Poser};
use glam::DVec3;
use std::time::Instant;

/// Milliseconds since `t`.
pub fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// The best of a few poses with one scratch (the first pose fills the scratch and warms the
/// caches), in milliseconds.
pub fn time_pose<D: Deformer + ?Sized>(
    d: &D,
    keys: &[cga::ScaledMotor],
    out: &mut [DVec3],
) -> Result<f64> {
    Ok(Poser::new(d).best_time_ms(keys, out, 5)?)
}

/// [`time_pose`] of a posed rig ([`deform::skinning::Skinning::pose_rig`]: the skin matrices
/// for the matrix backends, the skin motors for the others).
pub fn time_rig_pose(
    skin: &deform::skinning::Skinning,
    pose: &deform::skinning::RigPose,
    out: &mut [DVec3],
) -> Result<f64> {
    let mut scratch = skin.blend().scratch();
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        skin.pose_rig(pose, &mut scratch, out)?;
        best = best.min(ms(t));
    }
    Ok(best)
}
