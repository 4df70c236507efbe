//! One editing session (one browser connection): the scene, the handle groups, the bound
//! method and the latest pose. Requests in, replies out; no I/O here, so the server and the
//! tests drive it the same way. `report` says what the page shows (state, fields), `keep` what
//! it saves and loads, `replay` the CLI command that poses those files again, `select` the painting and lasso, `surgery` the tear and the drill.

mod keep;
mod method;
mod replay;
mod report;
mod select;
mod surgery;

use crate::blend::BlendMethod;
use crate::editor::error::{bail, refused, Context, Result};
use crate::editor::ms;
use crate::editor::protocol::{Frame, Precision, Reply, Request};
use crate::editor::rig_edit::RigEdit;
use crate::input::MotorSpec;
use crate::mesh::Mesh;
use crate::methods::bound::BoundMethod;
use crate::methods::budget::WorkBudget;
use crate::methods::harmonic_cache::{group_centres, HarmonicCache};
use crate::methods::scenes::{Content, Scene};
use crate::methods::MethodSettings;
use crate::surgery::{FaceBvh, RayHit};
use glam::DVec3;
use std::time::Instant;

/// What the server sends back: a text frame or a binary one.
pub enum Out {
    /// A JSON text frame.
    Text(Reply),
    /// A binary frame.
    Binary(Frame),
}

/// No group.
const NONE: u32 = u32::MAX;

/// The most bytes an uploaded model may have (the page checks first; the socket's message
/// limit bounds what reaches the server).
pub const MAX_UPLOAD: usize = 16 << 20;

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
    /// The method and its options.
    settings: MethodSettings,
    bound: BoundMethod,
    /// The scene's cage, if it has one.
    cage: Option<Mesh>,
    bind_ms: f64,
    specs: Vec<MotorSpec>,
    rig: Option<RigEdit>,
    field: FieldChoice,
    /// The mesh's harmonic system, analysed once for every handle selection.
    analysed: HarmonicCache,
    /// Undo and redo of selection changes.
    history: select::SelectionHistory,
    /// The precision of the positions frames the client asked for.
    precision: Precision,
    /// What a bind may come to.
    budget: WorkBudget,
}

fn v3(a: [f64; 3]) -> DVec3 {
    DVec3::from_array(a)
}

impl Session {
    /// A session on `scenes[0]`, with its opening frames; every bind is checked against
    /// `budget`.
    pub fn new(scenes: Vec<Scene>, budget: WorkBudget) -> Result<(Session, Vec<Out>)> {
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
            settings: MethodSettings::default(),
            bound: BoundMethod::Rest { groups: 0 },
            cage: None,
            bind_ms: 0.0,
            specs: Vec::new(),
            rig: None,
            field: FieldChoice {
                name: "displacement".into(),
                group: 0,
            },
            analysed: HarmonicCache::default(),
            history: Default::default(),
            precision: Precision::F64,
            budget,
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
            _ => crate::methods::named::Named::name(self.settings.method),
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
                    .ok_or_else(|| refused!("no scene {name:?}"))?;
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
                options,
            } => {
                self.mesh_only("a method")?;
                self.set_method(&method, &blend, &options)
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
                    .ok_or_else(|| refused!("this scene has no rig"))?;
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
                    .ok_or_else(|| refused!("this scene has no rig to cut"))?;
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
                self.mesh = mesh.clone();
                self.settings.set_method(*method);
                self.settings.blend = BlendMethod::MotorLog;
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
        let groups = self.groups.len();
        self.bound = BoundMethod::Rest { groups };
        self.posed = self.mesh.positions.clone();
        let method = self.settings.method;
        let need = method.groups_needed();
        let mut out = Vec::new();
        if groups >= need {
            let t = Instant::now();
            self.bound = BoundMethod::bind(
                &self.mesh,
                &self.groups,
                self.cage.as_ref(),
                &self.settings,
                &self.budget,
                &mut self.analysed,
            )
            .with_context(|| format!("cannot bind {} to {groups} groups", self.method_name()))?;
            self.bind_ms = ms(t);
            let k = self.bound.key_count();
            if self.specs.len() != k {
                self.specs = vec![MotorSpec::default(); k];
            }
        } else {
            out.push(Out::Text(Reply::Note {
                message: format!(
                    "{} needs {need} handle group(s) or more: paint them on the surface",
                    self.method_name()
                ),
            }));
        }
        out.push(Out::Binary(Frame::groups(&self.owner)));
        out.push(self.state());
        let specs = self.specs.clone();
        out.extend(self.pose_motors(0, specs).unwrap_or_default());
        Ok(out)
    }

    /// The method's name.
    fn method_name(&self) -> &'static str {
        crate::methods::named::Named::name(self.settings.method)
    }

    /// The centre of each group at rest.
    fn centres(&self) -> Vec<DVec3> {
        group_centres(&self.mesh, &self.groups)
    }

    /// A new blend method without solving again where the method keeps its weights apart
    /// (handles); else a rebind.
    fn reblend(&mut self, b: BlendMethod) -> Result<Vec<Out>> {
        self.settings.blend = b;
        let t = Instant::now();
        if !self.bound.reblend(&self.mesh.positions, b)? {
            return self.bind();
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
        let motors = specs
            .iter()
            .enumerate()
            .map(|(g, s)| s.to_motor().map_err(|e| refused!("group {g}: {e}")))
            .collect::<Result<Vec<_>>>()?;
        let t = Instant::now();
        let energy = if self.stale {
            // Painted since the last bind: the bound keys do not match the groups yet.
            let k = self.bound.key_count();
            if motors.len() != k {
                bail!("{} motors for {k} groups (send one per key)", motors.len());
            }
            None
        } else {
            self.bound
                .pose(&motors, &self.mesh.positions, &mut self.posed)?
        };
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
