//! The command that replays a mesh scene's pose with the CLI, from the files the page exports
//! (rest mesh, selection, motors, spline keys, cage), and those files' names.

use super::Session;
use crate::editor::error::{bail, Result};
use crate::input::{MotorSpec, RotateSpec};
use crate::methods::bound::BoundMethod;
use glam::DVec3;

/// The file each export writes for scene `scene`.
pub(super) fn file_name(scene: &str, what: &str) -> Result<String> {
    Ok(match what {
        "obj" => format!("{scene}-posed.obj"),
        "rest" => format!("{scene}-rest.obj"),
        "cage" => format!("{scene}-cage.obj"),
        "motors" | "selection" | "keys" | "rest-keys" | "edits" => {
            format!("{scene}-{what}.json")
        }
        "glb" => glb_name(scene, false),
        _ => bail!("cannot export {what:?} (obj, rest, glb, motors, selection, keys, rest-keys, cage, edits)"),
    })
}

/// The `.glb` export's name: a rig's keeps its edits and cuts, a mesh scene's is its pose.
pub(super) fn glb_name(scene: &str, rig: bool) -> String {
    if rig {
        format!("{scene}-edited.glb")
    } else {
        format!("{scene}-posed.glb")
    }
}

impl Session {
    /// The `deform ...` command that poses the exported rest mesh as the page shows it, written
    /// to `{scene}-replayed.obj`. The method's flags come from
    /// the library's [`crate::methods::MethodSettings::args`] (ARAP: many iterations from the
    /// rest pose, where the page iterates from its last frame).
    pub(super) fn replay(&self) -> String {
        let scene = &self.scenes[self.scene].name;
        if self.rig.is_some() {
            return format!(
                "the .glb export keeps the cuts and joint edits baked in: deform skin {} ...",
                glb_name(scene, true)
            );
        }
        if self.stale {
            return "none yet: the groups changed since the last bind".into();
        }
        let f = |what: &str| file_name(scene, what).unwrap_or_default();
        let method = self.settings.method;
        let mut words = vec![format!("deform {}", method.command().join(" ")), f("rest")];
        for (flag, what) in method.inputs() {
            words.push(format!("--{flag} {}", f(what)));
        }
        words.extend(self.settings.args());
        words.push(format!("-o {scene}-replayed.obj"));
        words.join(" ")
    }

    /// The spline's keys as the CLI's `--keys` takes them: each group's motor after the
    /// translation to its centre (the rest key), as one motor.
    pub(super) fn spline_keys(&self) -> Result<(Vec<MotorSpec>, Vec<MotorSpec>)> {
        let bound = matches!(self.bound, BoundMethod::Bound(_));
        if !self.settings.method.reads("keys") || !bound {
            bail!("keys: the method is not one with keys (or it has too few groups to bind)");
        }
        if self.stale || self.specs.len() != self.groups.len() {
            bail!("keys: the groups changed since the last bind (bind first)");
        }
        let centres = self.centres();
        let keys = self
            .specs
            .iter()
            .zip(&centres)
            .map(|(s, &c)| after_translation(s, c))
            .collect();
        let rest = centres
            .iter()
            .map(|c| MotorSpec {
                translate: Some(c.to_array()),
                ..MotorSpec::default()
            })
            .collect();
        Ok((keys, rest))
    }
}

/// `x -> m(x + c)` for the motor `m` of `spec` (`x -> k + s R (x - k) + t`, `k` its centre):
/// the same rotation and scale about `k - c`, then the translation `t + c`.
fn after_translation(spec: &MotorSpec, c: DVec3) -> MotorSpec {
    let k = spec
        .rotate
        .as_ref()
        .and_then(|r| r.center)
        .or(spec.center)
        .map(DVec3::from_array)
        .unwrap_or(DVec3::ZERO);
    let centre = (k - c).to_array();
    let t = spec.translate.map(DVec3::from_array).unwrap_or(DVec3::ZERO) + c;
    MotorSpec {
        rotate: spec.rotate.as_ref().map(|r| RotateSpec {
            center: Some(centre),
            ..r.clone()
        }),
        center: spec.rotate.is_none().then_some(centre),
        translate: Some(t.to_array()),
        scale: spec.scale,
    }
}
