//! One editing session (one browser connection): the scene, the handle groups, the bound
//! method and the latest pose. Requests in, replies out; no I/O here, so the server and the
//! tests drive it the same way. `report` says what the page shows (state, fields), `keep` what
//! it saves and loads, `replay` the CLI command that poses those files again, `select` the painting and lasso, `surgery` the tear and the drill.

mod analysis;
mod keep;
mod method;
pub use keep::MAX_UPLOAD;
mod replay;
mod report;
mod select;
mod surgery;

use super::controls::{self, Controls};
use super::protocol::{Frame, Precision, Reply, Request};
use super::rig_edit::RigEdit;
use super::scenes::{Content, Method, Scene};
use crate::timing::ms;
use anyhow::{anyhow, bail, Context, Result};
use cga::ScaledMotor;
use deform::blend::control::ControlForm;
use deform::blend::control::ControlScratch;
use deform::blend::{BoundBlend, PreparedKeys};
use deform::deformers::arap::{Arap, ArapOptions, ArapScratch, Stop, Targets};
use deform::deformers::handles::HandleOptions;
use deform::deformers::spline::SplineOptions;
use deform::input::MotorSpec;
use deform::surgery::{FaceBvh, RayHit};
use deform::{BlendMethod, Deformer, Mesh, MotorHandles, SplineDeformer};
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
        scratch: PreparedKeys,
    },
    /// An FFD lattice or a cage: one motor per control point.
    Control {
        controls: Box<Controls>,
        scratch: ControlScratch,
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
    /// ARAP's energy and local step.
    arap: ArapOptions,
    bound: Bound,
    /// The scene's cage, if it has one.
    cage: Option<Mesh>,
    /// Lattices and cages: the positional form (else the motor form with `blend`).
    positional: bool,
    /// The lattice's size and basis, the cage's coordinates.
    control: controls::ControlChoice,
    bind_ms: f64,
    specs: Vec<MotorSpec>,
    rig: Option<RigEdit>,
    field: FieldChoice,
    /// The mesh's harmonic system, analysed once for every handle selection.
    analysed: analysis::Analysed,
    /// Undo and redo of selection changes.
    history: select::SelectionHistory,
    /// The precision of the positions frames the client asked for.
    precision: Precision,
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
            arap: ArapOptions::default(),
            bound: Bound::None,
            cage: None,
            positional: false,
            control: controls::ControlChoice::default(),
            bind_ms: 0.0,
            specs: Vec::new(),
            rig: None,
            field: FieldChoice {
                name: "displacement".into(),
                group: 0,
            },
            analysed: analysis::Analysed::default(),
            history: Default::default(),
            precision: Precision::F64,
        };
        let out = s.open(0)?;
        Ok((s, out))
    }

    /// What the last duration of a slow request `what` is kept under: the kind, the scene and
    /// the method it binds (the one it asks for, or the current one).
    pub fn slow_key(&self, request: &Request, what: &str) -> String {
        let method = match request {
            Request::Method { method, .. } => method.as_str(),
            Request::Scene { name } => name.as_str(),
            Request::Upload { name, .. } => name.as_str(),
            _ => self.method.name(),
        };
        format!("{what} / {} / {method}", self.scene)
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
                begin,
            } => {
                if begin {
                    self.begin_change();
                }
                self.paint(v3(origin), v3(direction), radius, group, erase)
            }
            Request::Lasso {
                eye,
                view_proj,
                polygon,
                group,
                erase,
            } => self.lasso(v3(eye), view_proj, &polygon, group, erase),
            Request::ClearGroups => {
                self.mesh_only("clear groups")?;
                self.begin_change();
                if !self.groups.is_empty() {
                    self.changed();
                }
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
                energy,
                local_step,
                controls,
            } => {
                self.mesh_only("a method")?;
                let (energy, local_step) = (energy.as_deref(), local_step.as_deref());
                let options = (energy, local_step, controls.as_ref());
                self.set_method(&method, &blend, iterations, options)
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
                if let Some(message) = rig.take_note() {
                    out.push(Out::Text(Reply::Note { message }));
                }
                let ms = rig.pose_ms;
                out.push(self.positions_frame(seq, ms));
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
            Request::Tear { .. } | Request::Drill { .. } => self.tool(request),
            Request::Undo | Request::Redo => self.undo_redo(matches!(request, Request::Undo)),
            Request::Export { what } => self.export(&what),
            Request::Load { what, text } => self.load(&what, &text),
            Request::Upload { name, base64 } => self.upload(&name, &base64),
            Request::Precision { positions } => {
                self.precision = positions;
                Ok(Vec::new())
            }
        }
    }

    /// The posed positions as the client asked for them.
    fn positions_frame(&self, seq: u32, pose_ms: f64) -> Out {
        Out::Binary(match self.precision {
            Precision::F64 => Frame::positions(seq, pose_ms, &self.posed),
            Precision::F32 => Frame::positions_f32(seq, pose_ms, &self.posed),
        })
    }

    pub(super) fn mesh_only(&self, what: &str) -> Result<()> {
        if self.rig.is_some() {
            bail!("{what}: this scene is a rig (joints and surgery, not handle groups)");
        }
        Ok(())
    }

    /// Open scene `i`: its mesh, groups and method, bound.
    pub(super) fn open(&mut self, i: usize) -> Result<Vec<Out>> {
        let scene = self.scenes[i].clone();
        self.scene = i;
        self.history = Default::default();
        self.field = FieldChoice {
            name: "displacement".into(),
            group: 0,
        };
        match &*scene.content {
            Content::Mesh {
                mesh,
                groups,
                method,
                cage,
            } => {
                self.rig = None;
                self.cage = cage.clone();
                self.positional = false;
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
    pub(super) fn load_rig_mesh(&mut self) -> Result<Vec<Out>> {
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

    pub(super) fn set_groups(&mut self, groups: Vec<Vec<u32>>) {
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

    /// Where the ray first meets the posed surface.
    pub(super) fn hit(&mut self, origin: DVec3, direction: DVec3) -> Option<RayHit> {
        let posed = Mesh::new(self.posed.clone(), self.mesh.triangles.clone());
        self.bvh.refit(&posed);
        self.bvh.ray_hit(&posed, origin, direction)
    }

    /// Bind the method to the groups; with too few groups the rest pose (and a note).
    pub(super) fn bind(&mut self) -> Result<Vec<Out>> {
        self.stale = false;
        self.bound = Bound::None;
        self.posed = self.mesh.positions.clone();
        let need = match self.method {
            Method::Spline => 2,
            Method::Ffd | Method::Cage => 0,
            Method::Handles | Method::Arap => 1,
        };
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
            let k = self.key_count();
            if self.specs.len() != k {
                self.specs = vec![MotorSpec::default(); k];
            }
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

    fn bind_method(&mut self) -> Result<Bound> {
        let sets: Vec<&[u32]> = self.groups.iter().map(Vec::as_slice).collect();
        if self.method == Method::Handles {
            // A weight per vertex and group: a loaded selection may have thousands of groups.
            // (The spline's B-spline keys weigh a vertex by at most four of them.)
            crate::budget::get().handle_groups(
                "the selection",
                sets.len(),
                self.mesh.vertex_count(),
            )?;
        }
        Ok(match self.method {
            Method::Handles => {
                let rest = vec![ScaledMotor::IDENTITY; sets.len()];
                let options = HandleOptions {
                    method: self.blend,
                    ..HandleOptions::default()
                };
                let analysis = self.analysed.of(&self.mesh, &options.harmonic)?;
                let handles =
                    MotorHandles::bind_with_analysis(&self.mesh, analysis, &sets, &rest, options)?;
                let blend = Box::new(handles.blend().clone());
                let scratch = blend.scratch();
                Bound::Handles {
                    handles: Box::new(handles),
                    blend,
                    scratch,
                }
            }
            Method::Arap => {
                let arap = Arap::bind(&self.mesh, &[], &sets, self.arap)?;
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
            Method::Ffd | Method::Cage => {
                let form = if self.positional {
                    ControlForm::Positional
                } else {
                    ControlForm::Motor(self.blend)
                };
                let controls = match &self.cage {
                    Some(cage) if self.method == Method::Cage => {
                        controls::cage(&self.mesh, cage, form, &self.control)?
                    }
                    _ => controls::lattice(&self.mesh, form, &self.control)?,
                };
                let scratch = controls.deformer.scratch();
                Bound::Control {
                    controls: Box::new(controls),
                    scratch,
                }
            }
        })
    }

    /// The number of motors a pose takes: one per control point of a lattice or cage, else
    /// one per group.
    fn key_count(&self) -> usize {
        match &self.bound {
            Bound::Control { controls, .. } => controls.points.len(),
            _ => self.groups.len(),
        }
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
            Bound::Spline { .. } | Bound::Arap { .. } | Bound::Control { .. } | Bound::None => {
                return self.bind()
            }
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
        let k = self.key_count();
        if specs.len() != k {
            let what = if self.method.controls() && !matches!(self.bound, Bound::None) {
                "control points"
            } else {
                "groups"
            };
            bail!("{} motors for {k} {what} (send one per key)", specs.len());
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
            Bound::Control { controls, scratch } => {
                controls
                    .deformer
                    .pose_using(&motors, scratch, &mut self.posed)?
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
            self.positions_frame(seq, pose_ms),
        ];
        out.extend(self.field_frame());
        Ok(out)
    }
}
