//! One editing session (one browser connection): the scene, the handle groups, the bound
//! method and the latest pose. Requests in, replies out; no I/O here, so the server and the
//! tests drive it the same way.

use super::protocol::{Frame, GroupInfo, Reply, Request, StateInfo};
use super::rig_edit::RigEdit;
use super::scenes::{Content, Method, Scene};
use crate::timing::ms;
use anyhow::{anyhow, bail, Context, Result};
use cga::ScaledMotor;
use deform::arap::{Arap, ArapOptions, ArapScratch, Stop, Targets};
use deform::input::{parse_group_motors, parse_selection_json, MotorSpec};
use deform::surgery::FaceBvh;
use deform::{
    BlendMethod, BoundBlend, Deformer, HandleOptions, Mesh, MotorHandles, PoseScratch,
    PreparedKeys, SplineDeformer, SplineOptions,
};
use glam::DVec3;
use std::time::Instant;

/// What the server sends back: a text frame or a binary one.
pub enum Out {
    Text(Reply),
    Binary(Frame),
}

/// No group.
const NONE: u32 = u32::MAX;

/// The bound method of a mesh scene.
enum Bound {
    /// Too few groups (or a failed bind): the rest pose.
    None,
    Handles {
        handles: Box<MotorHandles>,
        blend: Box<BoundBlend>,
        scratch: PreparedKeys,
    },
    Arap {
        arap: Box<Arap>,
        scratch: Box<ArapScratch>,
    },
    Spline {
        spline: Box<SplineDeformer>,
        rest: Vec<ScaledMotor>,
        scratch: PoseScratch,
    },
}

/// The field the mesh is coloured by.
#[derive(Clone, Debug, PartialEq)]
struct FieldChoice {
    name: String,
    group: usize,
}

/// The state of one connection.
pub struct Session {
    scenes: Vec<Scene>,
    scene: usize,
    mesh: Mesh,
    bvh: FaceBvh,
    posed: Vec<DVec3>,
    owner: Vec<u32>,
    groups: Vec<Vec<u32>>,
    stale: bool,
    method: Method,
    blend: BlendMethod,
    iterations: usize,
    bound: Bound,
    bind_ms: f64,
    specs: Vec<MotorSpec>,
    rig: Option<RigEdit>,
    field: FieldChoice,
}

fn v3(a: [f64; 3]) -> DVec3 {
    DVec3::from_array(a)
}

impl Session {
    /// A session on `scenes[0]`, with its opening frames.
    pub fn new(scenes: Vec<Scene>) -> Result<(Session, Vec<Out>)> {
        if scenes.is_empty() {
            bail!("no scene to open");
        }
        let mesh = Mesh::new(Vec::new(), Vec::new());
        let mut s = Session {
            bvh: FaceBvh::new(&mesh),
            mesh,
            scenes,
            scene: 0,
            posed: Vec::new(),
            owner: Vec::new(),
            groups: Vec::new(),
            stale: false,
            method: Method::Handles,
            blend: BlendMethod::MotorLog,
            iterations: 2,
            bound: Bound::None,
            bind_ms: 0.0,
            specs: Vec::new(),
            rig: None,
            field: FieldChoice {
                name: "displacement".into(),
                group: 0,
            },
        };
        let out = s.open(0)?;
        Ok((s, out))
    }

    /// Answer one request. `Err` is a refused request (the page shows it; the session is
    /// unchanged where the error says so).
    pub fn handle(&mut self, request: Request) -> Result<Vec<Out>> {
        match request {
            Request::Scene { name } => {
                let i = self
                    .scenes
                    .iter()
                    .position(|s| s.name == name)
                    .ok_or_else(|| anyhow!("no scene {name:?}"))?;
                self.open(i)
            }
            Request::Paint {
                origin,
                direction,
                radius,
                group,
                erase,
            } => self.paint(v3(origin), v3(direction), radius, group, erase),
            Request::ClearGroups => {
                self.mesh_only("clear groups")?;
                self.set_groups(Vec::new());
                Ok(vec![Out::Binary(Frame::groups(&self.owner)), self.state()])
            }
            Request::Bind => {
                self.mesh_only("bind")?;
                self.bind()
            }
            Request::Method {
                method,
                blend,
                iterations,
            } => {
                self.mesh_only("a method")?;
                let m = Method::parse(&method).ok_or_else(|| anyhow!("no method {method:?}"))?;
                let b: BlendMethod = blend.parse()?;
                let k = iterations.unwrap_or(self.iterations);
                if !(1..=50).contains(&k) {
                    bail!("iterations per frame: {k} is not in 1..=50");
                }
                let rebind = m != self.method || k != self.iterations && m == Method::Arap;
                self.iterations = k;
                if !rebind && b != self.blend {
                    return self.reblend(b);
                }
                self.method = m;
                self.blend = b;
                self.bind()
            }
            Request::Motors { seq, motors } => self.pose_motors(seq, motors),
            Request::Rig {
                seq,
                animation,
                time,
                backend,
                edits,
            } => {
                let rig = self
                    .rig
                    .as_mut()
                    .ok_or_else(|| anyhow!("this scene has no rig"))?;
                rig.compare = self.field.name == "dqs-difference";
                let reply = rig.pose(seq, animation, time, &backend, &edits, &mut self.posed)?;
                let mut out = vec![Out::Text(reply)];
                out.push(Out::Binary(Frame::positions(seq, rig.pose_ms, &self.posed)));
                out.extend(self.field_frame());
                Ok(out)
            }
            Request::Field { name, group } => {
                let choice = FieldChoice { name, group };
                if !self.fields().contains(&choice.name.as_str()) {
                    bail!("no field {:?} in this scene", choice.name);
                }
                self.field = choice;
                Ok(self.field_frame().into_iter().collect())
            }
            Request::Cut { point, normal, cap } => {
                let rig = self
                    .rig
                    .as_mut()
                    .ok_or_else(|| anyhow!("this scene has no rig to cut"))?;
                rig.cut(v3(point), v3(normal), cap, &self.posed)?;
                self.load_rig_mesh()
            }
            Request::Undo | Request::Redo => {
                let rig = self
                    .rig
                    .as_mut()
                    .ok_or_else(|| anyhow!("nothing to undo: this scene has no rig"))?;
                if matches!(request, Request::Undo) {
                    rig.undo()?;
                } else {
                    rig.redo()?;
                }
                self.load_rig_mesh()
            }
            Request::Export { what } => self.export(&what),
            Request::Load { what, text } => self.load(&what, &text),
        }
    }

    fn mesh_only(&self, what: &str) -> Result<()> {
        if self.rig.is_some() {
            bail!("{what}: this scene is a rig (joints and surgery, not handle groups)");
        }
        Ok(())
    }

    /// Open scene `i`: its mesh, groups and method, bound.
    fn open(&mut self, i: usize) -> Result<Vec<Out>> {
        let scene = self.scenes[i].clone();
        self.scene = i;
        self.field = FieldChoice {
            name: "displacement".into(),
            group: 0,
        };
        match &*scene.content {
            Content::Mesh {
                mesh,
                groups,
                method,
            } => {
                self.rig = None;
                self.mesh = mesh.clone();
                self.method = *method;
                self.blend = BlendMethod::MotorLog;
                self.set_groups(groups.clone());
                self.bvh = FaceBvh::new(&self.mesh);
                let mut out = vec![Out::Binary(Frame::mesh(
                    &self.mesh.positions,
                    &self.mesh.triangles,
                ))];
                out.extend(self.bind()?);
                Ok(out)
            }
            Content::Rig(rig) => {
                self.rig = Some(RigEdit::new((**rig).clone())?);
                self.set_groups(Vec::new());
                self.stale = false;
                self.load_rig_mesh()
            }
        }
    }

    /// After a rig changed (opened, cut, undone): its mesh, rest pose and state.
    fn load_rig_mesh(&mut self) -> Result<Vec<Out>> {
        let rig = self.rig.as_ref().expect("a rig scene");
        self.mesh = rig.rig().mesh.clone();
        self.bind_ms = rig.bind_ms;
        self.owner = vec![NONE; self.mesh.vertex_count()];
        self.bvh = FaceBvh::new(&self.mesh);
        self.posed = self.mesh.positions.clone();
        let mut out = vec![
            Out::Binary(Frame::mesh(&self.mesh.positions, &self.mesh.triangles)),
            self.state(),
        ];
        out.extend(self.field_frame());
        Ok(out)
    }

    fn set_groups(&mut self, groups: Vec<Vec<u32>>) {
        self.owner = vec![NONE; self.mesh.vertex_count()];
        for (g, vs) in groups.iter().enumerate() {
            for &v in vs {
                self.owner[v as usize] = g as u32;
            }
        }
        self.specs = vec![MotorSpec::default(); groups.len()];
        self.groups = groups;
        self.posed = self.mesh.positions.clone();
        self.stale = true;
    }

    /// Paint or erase around where the ray meets the posed surface.
    fn paint(
        &mut self,
        origin: DVec3,
        direction: DVec3,
        radius: f64,
        group: usize,
        erase: bool,
    ) -> Result<Vec<Out>> {
        self.mesh_only("paint")?;
        if !(radius.is_finite() && radius >= 0.0) {
            bail!("paint radius {radius} is not a finite length");
        }
        if group > self.groups.len() || group >= 250 {
            bail!(
                "group {group}: paint an existing group (0..{}) or the next new one",
                self.groups.len()
            );
        }
        let posed = Mesh::new(self.posed.clone(), self.mesh.triangles.clone());
        self.bvh.refit(&posed);
        let Some(hit) = self.bvh.ray_hit(&posed, origin, direction) else {
            return Ok(Vec::new());
        };
        let r2 = radius * radius;
        let mut changed = false;
        for (v, p) in self.posed.iter().enumerate() {
            if (*p - hit.point).length_squared() > r2 {
                continue;
            }
            let want = if erase {
                if self.owner[v] == group as u32 {
                    NONE
                } else {
                    self.owner[v]
                }
            } else {
                group as u32
            };
            changed |= want != self.owner[v];
            self.owner[v] = want;
        }
        if !changed {
            return Ok(Vec::new());
        }
        // Groups from owners, renumbered without gaps (an emptied group disappears).
        let mut groups: Vec<Vec<u32>> = vec![Vec::new(); self.groups.len() + 1];
        for (v, &g) in self.owner.iter().enumerate() {
            if g != NONE {
                groups[g as usize].push(v as u32);
            }
        }
        let mut specs = std::mem::take(&mut self.specs);
        specs.push(MotorSpec::default());
        let (groups, specs): (Vec<_>, Vec<_>) = groups
            .into_iter()
            .zip(specs)
            .filter(|(g, _)| !g.is_empty())
            .unzip();
        let posed = std::mem::take(&mut self.posed);
        self.set_groups(groups);
        self.specs = specs;
        self.posed = posed;
        Ok(vec![Out::Binary(Frame::groups(&self.owner)), self.state()])
    }

    /// Bind the method to the groups; with too few groups the rest pose (and a note).
    fn bind(&mut self) -> Result<Vec<Out>> {
        self.stale = false;
        self.bound = Bound::None;
        self.posed = self.mesh.positions.clone();
        let need = if self.method == Method::Spline { 2 } else { 1 };
        let mut out = Vec::new();
        if self.groups.len() >= need {
            let t = Instant::now();
            self.bound = self.bind_method().with_context(|| {
                format!(
                    "cannot bind {} to {} groups",
                    self.method.name(),
                    self.groups.len()
                )
            })?;
            self.bind_ms = ms(t);
        } else {
            out.push(Out::Text(Reply::Note {
                message: format!(
                    "{} needs {need} handle group(s) or more: paint them on the surface",
                    self.method.name()
                ),
            }));
        }
        out.push(Out::Binary(Frame::groups(&self.owner)));
        out.push(self.state());
        let specs = self.specs.clone();
        out.extend(self.pose_motors(0, specs).unwrap_or_default());
        Ok(out)
    }

    fn bind_method(&self) -> Result<Bound> {
        let sets: Vec<&[u32]> = self.groups.iter().map(Vec::as_slice).collect();
        Ok(match self.method {
            Method::Handles => {
                let rest = vec![ScaledMotor::IDENTITY; sets.len()];
                let options = HandleOptions {
                    method: self.blend,
                    ..HandleOptions::default()
                };
                let handles = MotorHandles::bind_with(&self.mesh, &sets, &rest, options)?;
                let blend = Box::new(handles.blend().clone());
                let scratch = blend.scratch();
                Bound::Handles {
                    handles: Box::new(handles),
                    blend,
                    scratch,
                }
            }
            Method::Arap => {
                let arap = Arap::bind(&self.mesh, &[], &sets, ArapOptions::default())?;
                let scratch = arap.scratch()?;
                Bound::Arap {
                    arap: Box::new(arap),
                    scratch: Box::new(scratch),
                }
            }
            Method::Spline => {
                let rest = self.rest_keys();
                let options = SplineOptions {
                    method: self.blend,
                    ..SplineOptions::default()
                };
                let first = sets[0];
                let last = sets[sets.len() - 1];
                let spline = SplineDeformer::bind(&self.mesh, first, last, &rest, options)?;
                let scratch = spline.scratch();
                Bound::Spline {
                    spline: Box::new(spline),
                    rest,
                    scratch,
                }
            }
        })
    }

    /// The spline's rest keys: a translation to each group's centre.
    fn rest_keys(&self) -> Vec<ScaledMotor> {
        self.centres()
            .into_iter()
            .map(|c| ScaledMotor::from_motor(cga::Motor::from_translation(c)))
            .collect()
    }

    fn centres(&self) -> Vec<DVec3> {
        self.groups
            .iter()
            .map(|g| {
                g.iter()
                    .map(|&v| self.mesh.positions[v as usize])
                    .sum::<DVec3>()
                    / g.len() as f64
            })
            .collect()
    }

    /// A new blend method for handles or spline without solving again: the same weights.
    fn reblend(&mut self, b: BlendMethod) -> Result<Vec<Out>> {
        self.blend = b;
        let t = Instant::now();
        match &mut self.bound {
            Bound::Handles { blend, scratch, .. } => {
                let rest = vec![ScaledMotor::IDENTITY; blend.key_count()];
                **blend =
                    BoundBlend::bind(&self.mesh.positions, blend.weights().clone(), &rest, b)?;
                *scratch = blend.scratch();
            }
            Bound::Spline { .. } | Bound::Arap { .. } | Bound::None => return self.bind(),
        }
        self.bind_ms = ms(t);
        let mut out = vec![self.state()];
        let specs = self.specs.clone();
        out.extend(self.pose_motors(0, specs)?);
        Ok(out)
    }

    /// Pose the groups by `specs` (one per group).
    fn pose_motors(&mut self, seq: u32, specs: Vec<MotorSpec>) -> Result<Vec<Out>> {
        self.mesh_only("motors")?;
        if specs.len() != self.groups.len() {
            bail!(
                "{} motors for {} groups (send one per group)",
                specs.len(),
                self.groups.len()
            );
        }
        let motors = specs
            .iter()
            .enumerate()
            .map(|(g, s)| s.to_motor().map_err(|e| anyhow!("group {g}: {e}")))
            .collect::<Result<Vec<_>>>()?;
        let t = Instant::now();
        let mut energy = None;
        match &mut self.bound {
            // Painted since the last bind: the bound keys do not match the groups yet.
            _ if self.stale => {}
            Bound::None => self.posed.copy_from_slice(&self.mesh.positions),
            Bound::Handles { blend, scratch, .. } => {
                blend.pose_using(&motors, scratch, &mut self.posed)?
            }
            Bound::Arap { arap, scratch } => {
                let mut last = f64::NAN;
                arap.pose_using(
                    &Targets::Motors(&motors),
                    Stop::Iterations(self.iterations),
                    scratch,
                    &mut self.posed,
                    |_, e| last = e,
                )?;
                energy = Some(last);
            }
            Bound::Spline {
                spline,
                rest,
                scratch,
            } => {
                let keys: Vec<ScaledMotor> =
                    rest.iter().zip(&motors).map(|(r, m)| r.then(*m)).collect();
                spline.pose_using(&keys, scratch, &mut self.posed)?
            }
        }
        let pose_ms = ms(t);
        self.specs = specs;
        let mut out = vec![
            Out::Text(Reply::Posed {
                seq,
                pose_ms,
                energy,
                joints: None,
            }),
            Out::Binary(Frame::positions(seq, pose_ms, &self.posed)),
        ];
        out.extend(self.field_frame());
        Ok(out)
    }

    /// The fields this scene can be coloured by.
    fn fields(&self) -> Vec<&'static str> {
        if self.rig.is_some() {
            return vec!["displacement", "dqs-difference", "piece", "made"];
        }
        let mut f = vec!["displacement", "group"];
        match self.bound {
            Bound::Handles { .. } => f.push("harmonic"),
            Bound::Spline { .. } => f.push("lambda"),
            _ => {}
        }
        f
    }

    /// The current field's values, as a frame.
    fn field_frame(&self) -> Option<Out> {
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
            ("harmonic", Bound::Handles { handles, .. }, _) => {
                let j = self.field.group.min(self.groups.len().saturating_sub(1));
                (0..n).map(|i| handles.coordinate(i, j)).collect()
            }
            ("lambda", Bound::Spline { spline, .. }, _) => spline.lambda().to_vec(),
            (name, _, Some(rig)) => rig.field(name, &self.posed)?,
            _ => displacement(),
        };
        Some(Out::Binary(Frame::field(&values)))
    }

    /// The whole state, for the page's panels.
    fn state(&self) -> Out {
        let centres = self.centres();
        Out::Text(Reply::State(Box::new(StateInfo {
            scene: self.scenes[self.scene].name.clone(),
            scenes: self.scenes.iter().map(|s| s.name.clone()).collect(),
            kind: if self.rig.is_some() { "rig" } else { "mesh" },
            method: self.method.name().into(),
            methods: Method::ALL.map(Method::name).to_vec(),
            blend: self.blend.name().into(),
            blends: [
                BlendMethod::MotorLog,
                BlendMethod::MotorLinear,
                BlendMethod::DualQuaternion,
                BlendMethod::Matrix,
            ]
            .map(BlendMethod::name)
            .to_vec(),
            iterations: self.iterations,
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
        })))
    }

    /// A file of the current state.
    fn export(&self, what: &str) -> Result<Vec<Out>> {
        let scene = &self.scenes[self.scene].name;
        let (name, text) = match what {
            "obj" => {
                let posed = Mesh::new(self.posed.clone(), self.mesh.triangles.clone());
                let mut bytes = Vec::new();
                deform::io::write_obj_to(&posed, &mut bytes)?;
                (format!("{scene}-posed.obj"), String::from_utf8(bytes)?)
            }
            "motors" => {
                self.mesh_only("motors")?;
                let map: serde_json::Map<String, serde_json::Value> = self
                    .specs
                    .iter()
                    .enumerate()
                    .map(|(g, s)| Ok((g.to_string(), serde_json::to_value(s)?)))
                    .collect::<Result<_>>()?;
                (
                    format!("{scene}-motors.json"),
                    serde_json::to_string_pretty(&map)?,
                )
            }
            "selection" => {
                self.mesh_only("selection")?;
                let map: serde_json::Map<String, serde_json::Value> = self
                    .groups
                    .iter()
                    .enumerate()
                    .map(|(g, vs)| (g.to_string(), serde_json::json!(vs)))
                    .collect();
                (
                    format!("{scene}-selection.json"),
                    serde_json::to_string(&map)?,
                )
            }
            "glb" => {
                use base64::Engine;
                let rig = self
                    .rig
                    .as_ref()
                    .ok_or_else(|| anyhow!("glb: this scene has no rig (export obj)"))?;
                let bytes = rig.glb()?;
                (
                    format!("{scene}-edited.glb"),
                    base64::engine::general_purpose::STANDARD.encode(bytes),
                )
            }
            "edits" => {
                let rig = self
                    .rig
                    .as_ref()
                    .ok_or_else(|| anyhow!("edits: this scene has no rig"))?;
                (format!("{scene}-edits.json"), rig.edits_json()?)
            }
            _ => bail!("cannot export {what:?} (obj, glb, motors, selection, edits)"),
        };
        let base64 = what == "glb";
        Ok(vec![Out::Text(Reply::File { name, text, base64 })])
    }

    /// Load a selection or motors the page read from a file, through the CLI's parsers.
    fn load(&mut self, what: &str, text: &str) -> Result<Vec<Out>> {
        self.mesh_only("load")?;
        match what {
            "selection" => {
                let sel = parse_selection_json(text, self.mesh.vertex_count(), "selection")?;
                self.set_groups(sel.groups);
                let mut out = vec![Out::Binary(Frame::groups(&self.owner))];
                out.extend(self.bind()?);
                Ok(out)
            }
            "motors" => {
                let motors = parse_group_motors(text, "motors", self.groups.len())?;
                // The gizmo keeps scale, rotation and translation about each group's centre.
                let centres = self.centres();
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
