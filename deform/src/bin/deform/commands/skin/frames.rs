//! Posing `skin`'s frames (each timed; compared with a second backend; the motor
//! approximation measured) and writing them once every frame is posed.

use super::{numbered, SkinArgs};
use crate::gpu_pose::GpuPoser;
use crate::output_files::write_rig_mesh;
use anyhow::{bail, Result};
use deform::skinning::Approximation;
use deform::skinning::{JointEdit, KeyframeBlend, LibiglAnimation, RigPose, Skinning};
use deform::{Deformer, Mesh, Poser, Rig};
use glam::DVec3;
use std::path::PathBuf;

/// What poses every frame.
pub struct Posing<'a> {
    pub rig: &'a Rig,
    pub bound: &'a Skinning,
    /// `--compare`'s backend.
    pub other: Option<Skinning>,
    pub gpu: Option<GpuPoser>,
    /// `--dmat-animation`'s frames.
    pub dmat: Option<&'a LibiglAnimation>,
    pub animation: Option<usize>,
    pub keyframes: KeyframeBlend,
}

/// The posed frames.
pub struct Posed {
    /// Each frame's path and positions (when written as meshes).
    pub finished: Vec<(PathBuf, Vec<DVec3>)>,
    /// The last frame's positions.
    pub last: Vec<DVec3>,
    /// The total posing time.
    pub pose_ms: f64,
    /// The largest difference to `--compare`'s backend.
    pub linf: f64,
    /// How far the joints' nearest similarities move the mesh.
    pub approximation: Approximation,
}

impl Posing<'_> {
    /// Pose each of `frames`, keeping each result (with its path) when `keep`.
    pub fn pose_frames(
        &mut self,
        a: &SkinArgs,
        frames: &[(f64, Vec<JointEdit>)],
        keep: bool,
    ) -> Result<Posed> {
        let n = self.rig.mesh.vertex_count();
        let sequence = frames.len() > 1;
        let mut out = Posed {
            finished: Vec::with_capacity(frames.len()),
            last: vec![DVec3::ZERO; n],
            pose_ms: 0.0,
            linf: 0.0,
            approximation: Approximation::default(),
        };
        let mut other_posed = vec![DVec3::ZERO; n];
        let mut pose = RigPose::default();
        let progress = crate::progress::frames(frames.len(), sequence && !a.out.quiet);
        for (k, (time, frame_edits)) in frames.iter().enumerate() {
            if let Some(bar) = &progress {
                bar.set_position(k as u64);
            }
            let frame_motors;
            let (motors, matrices) = match self.dmat {
                Some(anim) => {
                    frame_motors = anim.skin_motors(dmat_frame(a, anim, *time)?)?;
                    (&frame_motors[..], None)
                }
                None => {
                    let rig = self.rig;
                    rig.pose_into(
                        self.animation,
                        *time,
                        self.keyframes,
                        frame_edits,
                        &mut pose,
                    )?;
                    // The motor backends (and the GPU, which takes motors) take each joint's
                    // nearest similarity: how far that moves the mesh is measured and reported.
                    let motors_used = !self.bound.blends_matrices()
                        || self.gpu.is_some()
                        || self.other.as_ref().is_some_and(|o| !o.blends_matrices());
                    if motors_used {
                        out.approximation.add(rig, &pose);
                    }
                    (pose.skin_motors()?, Some(&pose))
                }
            };
            let posed = &mut out.last;
            out.pose_ms += match (&mut self.gpu, matrices) {
                (Some(g), _) => g.pose(motors, posed)?,
                (None, Some(p)) => self.bound.best_rig_time_ms(p, posed, 5)?,
                (None, None) => Poser::new(self.bound).best_time_ms(motors, posed, 5)?,
            };
            if let Some(o) = &self.other {
                match matrices {
                    Some(p) => o.pose_rig(p, &mut o.blend().scratch(), &mut other_posed)?,
                    None => o.pose(motors, &mut other_posed)?,
                }
                out.linf = posed
                    .iter()
                    .zip(&other_posed)
                    .map(|(p, q)| (*p - *q).abs().max_element())
                    .fold(out.linf, f64::max);
            }
            if let Some(i) = posed.iter().position(|p| !p.is_finite()) {
                bail!("vertex {i}: skinning produced a non-finite position");
            }
            if keep {
                let path = if sequence {
                    numbered(&a.out.output, k)
                } else {
                    a.out.output.clone()
                };
                out.finished.push((path, posed.clone()));
            }
        }
        if let Some(bar) = progress {
            bar.finish_and_clear();
        }
        Ok(out)
    }
}

/// The frame index a time names in a DMAT animation (times are frame indices there).
fn dmat_frame(a: &SkinArgs, anim: &LibiglAnimation, time: f64) -> Result<usize> {
    let flag = if a.range.is_some() {
        "--range"
    } else {
        "--time"
    };
    let count = anim.frames.len();
    if !(time >= 0.0 && time.fract() == 0.0 && time < count as f64) {
        bail!(
            "{flag}: frame {}: with --dmat-animation times are frame indices, \
             0 to {} for this animation of {count} frame{}",
            deform::render::short_number(time),
            count.saturating_sub(1),
            if count == 1 { "" } else { "s" }
        );
    }
    Ok(time as usize)
}

/// Write the frames, only once every frame is posed (a failing frame leaves no partial
/// sequence); a failed write, or an interrupt, removes the frames this run wrote before it.
pub fn write_frames(finished: &[(PathBuf, Vec<DVec3>)], sequence: bool, rig: &Rig) -> Result<()> {
    let mut unfinished = crate::interrupt::pending(&[]);
    for (k, (path, positions)) in finished.iter().enumerate() {
        let mesh = Mesh::new(positions.clone(), rig.mesh.triangles.clone());
        if sequence {
            unfinished.add(path);
        }
        if let Err(e) = write_rig_mesh(path, &mesh, &rig.look) {
            for (written, _) in &finished[..k] {
                let _ = std::fs::remove_file(written);
            }
            return Err(e);
        }
    }
    drop(unfinished); // the sequence is complete
    Ok(())
}
