//! Files of a session: export the pose, selection, motors, edits or the rig; load a selection
//! or motors through the CLI's parsers; open an uploaded model as the CLI opens one.

use super::replay::{file_name, glb_name};
use super::{Out, Session, MAX_UPLOAD};
use crate::editor::error::{bail, refused, Context, Result};
use crate::editor::protocol::{Frame, Reply};
use crate::input::{parse_group_motors, parse_selection_json, MotorSpec};
use crate::mesh::Mesh;
use crate::methods::scenes::Scene;

impl Session {
    /// A file of the current state.
    pub(super) fn export(&self, what: &str) -> Result<Vec<Out>> {
        let name = file_name(&self.scenes[self.scene].name, what)?;
        let obj = |mesh: &Mesh| -> Result<String> {
            let mut bytes = Vec::new();
            crate::mesh::io::write_obj_to(mesh, &mut bytes)?;
            Ok(String::from_utf8(bytes)?)
        };
        let json_list = |specs: &[MotorSpec]| serde_json::to_string_pretty(specs);
        let (name, text) = match what {
            "obj" => (
                name,
                obj(&Mesh::new(self.posed.clone(), self.mesh.triangles.clone()))?,
            ),
            "rest" => (name, obj(&self.mesh)?),
            "cage" => match &self.cage {
                Some(cage) if self.settings.method.reads("cage") => (name, obj(cage)?),
                _ => bail!("cage: the method is not a cage"),
            },
            "motors" => {
                self.mesh_only("motors")?;
                let map: serde_json::Map<String, serde_json::Value> = self
                    .specs
                    .iter()
                    .enumerate()
                    .map(|(g, s)| Ok((g.to_string(), serde_json::to_value(s)?)))
                    .collect::<Result<_>>()?;
                (name, serde_json::to_string_pretty(&map)?)
            }
            "keys" => (name, json_list(&self.spline_keys()?.0)?),
            "rest-keys" => (name, json_list(&self.spline_keys()?.1)?),
            "selection" => {
                self.mesh_only("selection")?;
                let map: serde_json::Map<String, serde_json::Value> = self
                    .groups
                    .iter()
                    .enumerate()
                    .map(|(g, vs)| (g.to_string(), serde_json::json!(vs)))
                    .collect();
                (name, serde_json::to_string(&map)?)
            }
            "glb" => {
                use base64::Engine;
                let scene = &self.scenes[self.scene].name;
                // A rig keeps its skin, edits and animations; a mesh scene its posed surface.
                let bytes = match &self.rig {
                    Some(rig) => rig.glb()?,
                    None => {
                        let posed = Mesh::new(self.posed.clone(), self.mesh.triangles.clone());
                        crate::mesh::io::glb_bytes(&posed)?
                    }
                };
                let name = glb_name(scene, self.rig.is_some());
                (
                    name,
                    base64::engine::general_purpose::STANDARD.encode(bytes),
                )
            }
            "edits" => {
                let rig = self
                    .rig
                    .as_ref()
                    .ok_or_else(|| refused!("edits: this scene has no rig"))?;
                (name, rig.edits_json()?)
            }
            _ => bail!("cannot export {what:?}"),
        };
        let base64 = what == "glb";
        Ok(vec![Out::Text(Reply::File { name, text, base64 })])
    }

    /// Load a selection or motors the page read from a file, through the CLI's parsers.
    pub(super) fn load(&mut self, what: &str, text: &str) -> Result<Vec<Out>> {
        self.mesh_only("load")?;
        match what {
            "selection" => {
                let sel = parse_selection_json(text, self.mesh.vertex_count(), "selection")?;
                self.begin_change();
                self.changed();
                self.set_groups(sel.groups);
                let mut out = vec![Out::Binary(Frame::groups(&self.owner))];
                out.extend(self.bind()?);
                Ok(out)
            }
            "motors" => {
                let motors = parse_group_motors(text, "motors", self.bound.key_count())?;
                // The gizmo keeps scale, rotation and translation about each key's centre.
                let centres = match self.bound.controls() {
                    Some(c) => c.points.clone(),
                    None => self.centres(),
                };
                let motors = motors
                    .iter()
                    .zip(centres)
                    .map(|(m, c)| {
                        let (s, q, _) = m.to_scale_rotation_translation();
                        let t = m.transform_point(c) - c;
                        [s, q.x, q.y, q.z, q.w, t.x, t.y, t.z]
                    })
                    .collect();
                Ok(vec![Out::Text(Reply::Motors { motors })])
            }
            _ => bail!("cannot load {what:?} (selection, motors)"),
        }
    }
}

impl Session {
    /// Open a model the page uploaded: its bytes go through the CLI's readers and checks
    /// (a mesh must be solvable; a glTF may not name files outside itself). It joins this
    /// session's scenes, replacing an earlier upload of the same name.
    pub(super) fn upload(&mut self, name: &str, base64: &str) -> Result<Vec<Out>> {
        use base64::Engine;
        // Only the file's own name: it names the scene and the format, never a path here.
        let name = std::path::Path::new(name)
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .filter(|n| !n.is_empty())
            .ok_or_else(|| refused!("an upload needs a file name"))?;
        if base64.len() > MAX_UPLOAD.div_ceil(3) * 4 {
            bail!("{name}: larger than {} MiB", MAX_UPLOAD >> 20);
        }
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(base64)
            .map_err(|e| refused!("{name}: not base64 ({e})"))?;
        let lower = name.to_ascii_lowercase();
        let scene = if lower.ends_with(".glb") || lower.ends_with(".gltf") {
            let rig = crate::skinning::parse_gltf(&bytes, &name, None)?;
            Scene::new(&name, crate::methods::scenes::Content::Rig(Box::new(rig)))
        } else {
            let mesh = crate::mesh::io::parse_mesh(&bytes, &name)?;
            crate::mesh::validate::check_solvable(&mesh)
                .with_context(|| format!("{name}: not a usable mesh"))?;
            Scene::mesh(&name, mesh)
        };
        let i = match self.scenes.iter().position(|s| s.name == scene.name) {
            Some(i) => {
                self.scenes[i] = scene;
                i
            }
            None => {
                self.scenes.push(scene);
                self.scenes.len() - 1
            }
        };
        self.open(i)
    }
}
