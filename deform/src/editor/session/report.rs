//! What the page is shown of a session: the whole state and the colour fields.

use super::{Out, Session, NONE};
use crate::blend::BlendMethod;
use crate::editor::protocol::{ControlsInfo, Frame, GroupInfo, OptionSpecInfo, Reply, StateInfo};
use crate::editor::rig_edit::RigEdit;
use crate::methods::named::Named;
use crate::methods::Method;

impl Session {
    /// The fields this scene can be coloured by.
    pub(super) fn fields(&self) -> Vec<&'static str> {
        if self.rig.is_some() {
            return vec!["displacement", "dqs-difference", "piece", "made"];
        }
        let mut f = vec!["displacement", "group"];
        f.extend(self.bound.fields());
        f
    }

    /// The current field's values, as a frame.
    pub(super) fn field_frame(&self) -> Option<Out> {
        let n = self.mesh.vertex_count();
        let displacement = || -> Vec<f64> {
            (0..n)
                .map(|v| (self.posed[v] - self.mesh.positions[v]).length())
                .collect()
        };
        let values: Vec<f64> = match (self.field.name.as_str(), &self.bound, &self.rig) {
            ("displacement", ..) => displacement(),
            ("group", ..) => self
                .owner
                .iter()
                .map(|&g| if g == NONE { -1.0 } else { g as f64 })
                .collect(),
            (name, _, Some(rig)) => rig.field(name, &self.posed)?,
            (name, bound, None) => match bound.field(name, self.field.group) {
                Some(values) => values,
                None => displacement(),
            },
        };
        Some(Out::Binary(Frame::field(&values)))
    }

    /// The whole state, for the page's panels.
    pub(super) fn state(&self) -> Out {
        let centres = self.centres();
        Out::Text(Reply::State(Box::new(StateInfo {
            scene: self.scenes[self.scene].name.clone(),
            scenes: self.scenes.iter().map(|s| s.name.clone()).collect(),
            kind: if self.rig.is_some() { "rig" } else { "mesh" },
            method: self.method_name().into(),
            methods: Method::ALL
                .iter()
                .filter(|m| !m.reads("cage") || self.cage.is_some())
                .map(|m| m.name())
                .collect(),
            blend: if self.settings.positional {
                "positional".into()
            } else {
                self.settings.blend.name().into()
            },
            blends: [
                BlendMethod::MotorLog,
                BlendMethod::MotorLinear,
                BlendMethod::DualQuaternion,
                BlendMethod::Matrix,
            ]
            .map(BlendMethod::name)
            .into_iter()
            .chain(self.settings.method.controls().then_some("positional"))
            .collect(),
            controls: self.bound.controls().map(|c| ControlsInfo {
                points: c.points.iter().map(|p| p.to_array()).collect(),
                edges: c.edges.clone(),
            }),
            options: self.settings.values().into_iter().collect(),
            option_specs: (self.settings.method.options().iter())
                .map(OptionSpecInfo::of)
                .collect(),
            inputs: self.settings.method.inputs().iter().map(|i| i.1).collect(),
            groups: self
                .groups
                .iter()
                .zip(centres)
                .map(|(g, c)| GroupInfo {
                    vertices: g.len(),
                    center: c.to_array(),
                })
                .collect(),
            fields: self.fields(),
            rig: self.rig.as_ref().map(RigEdit::info),
            bind_ms: self.bind_ms,
            vertices: self.mesh.vertex_count(),
            triangles: self.mesh.triangle_count(),
            stale: self.stale,
            selection_undo: self.history.undo_count(),
            selection_redo: self.history.redo_count(),
            replay: self.replay(),
        })))
    }
}
