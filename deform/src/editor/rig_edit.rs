//! A rig in the editor: animation and joint edits posed by a chosen backend, the per-vertex
//! difference to dual-quaternion skinning, and cuts, tears and drills with undo and redo.

use crate::blend::BlendMethod;
use crate::blend::PreparedKeys;
use crate::editor::error::{bail, refused, Result};
use crate::editor::ms;
use crate::editor::protocol::{AnimationInfo, EditSpec, Reply, RigInfo};
use crate::mesh::Mesh;
use crate::skinning::{
    bake_edits, glb_bytes, GlbOptions, JointEdit, KeyframeBlend, Rig, RigPart, RigPose, Skinning,
};
use crate::surgery::{
    CutOptions, Drill, DrillOptions, Frame, Scalpel, Surgery, TearOptions, VertexOrigin,
};
use glam::DVec3;
use std::time::Instant;

/// The skinning backends the page offers.
pub const BACKENDS: [BlendMethod; 5] = [
    BlendMethod::MotorLog,
    BlendMethod::MotorLinear,
    BlendMethod::DualQuaternion,
    BlendMethod::Matrix,
    BlendMethod::Conformal,
];

/// One version of the rig: after opening, or after a cut.
struct Version {
    rig: Rig,
    /// 1 for vertices a cut made, 0 for the input's.
    made: Vec<f64>,
}

/// The rig being edited.
pub struct RigEdit {
    history: Vec<Version>,
    redo: Vec<Version>,
    backend: BlendMethod,
    skin: Skinning,
    prepared: PreparedKeys,
    dqs: Skinning,
    dqs_prepared: PreparedKeys,
    pose: RigPose,
    /// The dual-quaternion pose of the last frame, when asked for.
    dqs_posed: Vec<DVec3>,
    /// Pose the dual-quaternion comparison with every frame.
    pub compare: bool,
    edits: Vec<(usize, crate::input::MotorSpec)>,
    /// What the page has not been told yet: that this backend approximates joints.
    note: Option<String>,
    /// The approximation was told for the current backend.
    told: bool,
    pub bind_ms: f64,
    pub pose_ms: f64,
}

impl RigEdit {
    pub fn new(rig: Rig) -> Result<RigEdit> {
        let made = vec![0.0; rig.mesh.vertex_count()];
        let t = Instant::now();
        let skin = Skinning::bind(&rig, BlendMethod::MotorLog)?;
        let dqs = Skinning::bind(&rig, BlendMethod::DualQuaternion)?;
        Ok(RigEdit {
            prepared: skin.blend().scratch(),
            dqs_prepared: dqs.blend().scratch(),
            skin,
            dqs,
            backend: BlendMethod::MotorLog,
            pose: RigPose::default(),
            dqs_posed: rig.mesh.positions.clone(),
            compare: false,
            edits: Vec::new(),
            note: None,
            told: false,
            bind_ms: ms(t),
            pose_ms: 0.0,
            history: vec![Version { rig, made }],
            redo: Vec::new(),
        })
    }

    /// The current rig.
    pub fn rig(&self) -> &Rig {
        &self.history.last().expect("a rig version").rig
    }

    /// Bind the current rig for `backend` (and dual quaternions).
    fn rebind(&mut self, backend: BlendMethod) -> Result<()> {
        let t = Instant::now();
        let skin = Skinning::bind(self.rig(), backend)?;
        let dqs = Skinning::bind(self.rig(), BlendMethod::DualQuaternion)?;
        self.prepared = skin.blend().scratch();
        self.dqs_prepared = dqs.blend().scratch();
        self.skin = skin;
        self.dqs = dqs;
        self.backend = backend;
        self.told = false;
        self.dqs_posed = self.rig().mesh.positions.clone();
        self.bind_ms = ms(t);
        Ok(())
    }

    /// Pose at `time` of `animation` with `edits` into `posed` (resized to the rig's vertices).
    pub fn pose(
        &mut self,
        seq: u32,
        animation: Option<usize>,
        time: f64,
        backend: &str,
        edits: &[EditSpec],
        posed: &mut Vec<DVec3>,
    ) -> Result<Reply> {
        let backend = <BlendMethod as crate::methods::named::Named>::from_name(backend)?;
        if !BACKENDS.contains(&backend) {
            bail!("backend {} is not offered here", backend.name());
        }
        if !time.is_finite() {
            bail!("time {time} is not finite");
        }
        let joints = self.rig().joints.len();
        let mut joint_edits = Vec::with_capacity(edits.len());
        for e in edits {
            if e.joint >= joints {
                bail!("joint {} does not exist (the rig has {joints})", e.joint);
            }
            let motor = e
                .motor
                .to_motor()
                .map_err(|m| refused!("joint {}: {m}", e.joint))?;
            joint_edits.push(JointEdit {
                joint: e.joint,
                motor,
            });
        }
        if backend != self.backend {
            self.rebind(backend)?;
        }
        let t = Instant::now();
        let rig = &self.history.last().expect("a rig version").rig;
        rig.pose_into(
            animation,
            time,
            KeyframeBlend::Gltf,
            &joint_edits,
            &mut self.pose,
        )?;
        // `lbs` blends the exact skin matrices, the motor backends their nearest similarities.
        posed.resize(rig.mesh.vertex_count(), DVec3::ZERO);
        self.skin.pose_rig(&self.pose, &mut self.prepared, posed)?;
        self.pose_ms = ms(t);
        if self.compare {
            self.dqs
                .pose_rig(&self.pose, &mut self.dqs_prepared, &mut self.dqs_posed)?;
        }
        if !self.told && !self.skin.blends_matrices() && self.pose.approximated_joints().count() > 0
        {
            self.told = true;
            let joints: Vec<String> = self
                .pose
                .approximated_joints()
                .map(|(j, _)| rig.nodes[rig.joints[j]].name.clone())
                .collect();
            let world = rig.bind_pose_positions()?;
            let diagonal = Mesh::new(world, Vec::new())
                .bounding_box()
                .map_or(f64::NAN, |b| b.diagonal());
            let percent = 100.0 * rig.similarity_shift(&self.pose) / diagonal;
            self.note = Some(format!(
                "{} takes joint(s) {} as their nearest similarities (non-uniform scale, shear \
                 or a mirror): the mesh moves by {}% of its diagonal because of it; lbs skins \
                 them exactly",
                backend.name(),
                joints.join(", "),
                crate::render::short_number(percent)
            ));
        }
        self.edits = edits.iter().map(|e| (e.joint, e.motor.clone())).collect();
        let frames = rig
            .joints
            .iter()
            .map(|&node| {
                let (_, q, t) = self.pose.globals[node].to_scale_rotation_translation();
                [t.x, t.y, t.z, q.x, q.y, q.z, q.w]
            })
            .collect();
        Ok(Reply::Posed {
            seq,
            pose_ms: self.pose_ms,
            energy: None,
            joints: Some(frames),
        })
    }

    /// A note for the page, once per backend: the joints it approximates and the move.
    pub fn take_note(&mut self) -> Option<String> {
        self.note.take()
    }

    /// A rig field: `dqs-difference`, `piece`, `made` (`None` for another name).
    pub fn field(&self, name: &str, posed: &[DVec3]) -> Option<Vec<f64>> {
        let v = self.history.last().expect("a rig version");
        match name {
            "dqs-difference" => Some(
                posed
                    .iter()
                    .zip(&self.dqs_posed)
                    .map(|(a, b)| (*a - *b).length())
                    .collect(),
            ),
            "piece" => Some(
                v.rig
                    .primitives
                    .iter()
                    .flat_map(|p| std::iter::repeat_n(p.primitive as f64, p.vertex_count))
                    .collect(),
            ),
            "made" => Some(v.made.clone()),
            _ => None,
        }
    }

    /// The posed frame of the last pose, with the keys its backend blended (so a tool's new
    /// vertices go back to the rest pose through the inverse of the blend that drew them);
    /// the rest frame before any pose.
    fn frame<'a>(&'a self, posed: &'a [DVec3]) -> Frame<'a> {
        if posed.len() == self.rig().mesh.vertex_count()
            && self.prepared.key_count() == self.rig().joints.len()
        {
            Frame::Blended {
                positions: posed,
                keys: &self.prepared,
            }
        } else {
            Frame::Rest
        }
    }

    /// A tool's result as the new version of the rig (undoable).
    fn push(&mut self, parts: &[RigPart], origin: &[VertexOrigin]) -> Result<()> {
        let (rig, trace) = self.rig().with_parts_traced(parts)?;
        // The origins are per vertex of the parts, in order; the rig regroups them.
        let made = trace
            .iter()
            .map(|&v| if origin[v].is_input() { 0.0 } else { 1.0 })
            .collect();
        self.history.push(Version { rig, made });
        self.redo.clear();
        self.rebind(self.backend)
    }

    fn surgery(&self) -> Result<Surgery> {
        let rig = self.rig();
        Ok(Surgery::new(&rig.mesh, &rig.influences)?)
    }

    /// Cut by the plane through `point` with normal `normal`, in the frame of `posed` (the
    /// last pose), and re-rig the pieces.
    pub fn cut(&mut self, point: DVec3, normal: DVec3, cap: bool, posed: &[DVec3]) -> Result<()> {
        let plane = cga::Plane::try_from_point_normal(point, normal).map_err(|e| {
            refused!("cut: the plane needs a finite point and a non-zero normal ({e})")
        })?;
        let options = CutOptions {
            cap,
            ..CutOptions::default()
        };
        let cut = self.surgery()?.cut(&plane, self.frame(posed), &options)?;
        let parts: Vec<_> = cut.pieces.iter().map(|p| p.mesh.part()).collect();
        let origin: Vec<VertexOrigin> = cut.pieces.iter().flat_map(|p| p.origin.clone()).collect();
        self.push(&parts, &origin)
    }

    /// Tear with the scalpel at successive positions, in the frame of `posed`.
    pub fn tear(&mut self, blades: &[Scalpel], open: f64, posed: &[DVec3]) -> Result<()> {
        let options = TearOptions {
            open,
            ..TearOptions::default()
        };
        let tear = self.surgery()?.tear(blades, self.frame(posed), &options)?;
        self.push(&[tear.mesh.part()], &tear.origin)
    }

    /// Drill a hole, in the frame of `posed`.
    pub fn drill(&mut self, drill: &Drill, posed: &[DVec3]) -> Result<()> {
        let result = self
            .surgery()?
            .drill(drill, self.frame(posed), &DrillOptions::default())?;
        self.push(&[result.mesh.part()], &result.origin)
    }

    pub fn undo(&mut self) -> Result<()> {
        if self.history.len() < 2 {
            bail!("nothing to undo");
        }
        let v = self.history.pop().expect("two versions");
        self.redo.push(v);
        self.rebind(self.backend)
    }

    pub fn redo(&mut self) -> Result<()> {
        let v = self.redo.pop().ok_or_else(|| refused!("nothing to redo"))?;
        self.history.push(v);
        self.rebind(self.backend)
    }

    /// The page's view of the rig.
    pub fn info(&self) -> RigInfo {
        let rig = self.rig();
        RigInfo {
            animations: rig
                .animations
                .iter()
                .map(|a| {
                    let (start, end) = a.range();
                    AnimationInfo {
                        name: a.name.clone(),
                        start,
                        end,
                    }
                })
                .collect(),
            joints: rig
                .joints
                .iter()
                .map(|&n| rig.nodes[n].name.clone())
                .collect(),
            parents: rig
                .joints
                .iter()
                .map(|&n| {
                    let mut p = rig.nodes[n].parent;
                    while let Some(q) = p {
                        if let Some(j) = rig.joints.iter().position(|&x| x == q) {
                            return j as i64;
                        }
                        p = rig.nodes[q].parent;
                    }
                    -1
                })
                .collect(),
            backends: BACKENDS.map(BlendMethod::name).to_vec(),
            undo: self.history.len() - 1,
            redo: self.redo.len(),
        }
    }

    /// The joint edits as `{"joint name": motor}` (each motor is a file for
    /// `deform skin --edit JOINT=FILE`).
    pub fn edits_json(&self) -> Result<String> {
        let rig = self.rig();
        let map: serde_json::Map<String, serde_json::Value> = self
            .edits
            .iter()
            .map(|(j, m)| {
                let name = rig.nodes[rig.joints[*j]].name.clone();
                Ok((name, serde_json::to_value(m)?))
            })
            .collect::<Result<_>>()?;
        Ok(serde_json::to_string_pretty(&map)?)
    }

    /// The rig with the joint edits baked into its rest pose and animations, as `.glb` bytes.
    pub fn glb(&self) -> Result<Vec<u8>> {
        let edits: Vec<JointEdit> = self
            .edits
            .iter()
            .map(|(j, m)| {
                Ok(JointEdit {
                    joint: *j,
                    motor: m.to_motor().map_err(|e| refused!("{e}"))?,
                })
            })
            .collect::<Result<_>>()?;
        let baked = bake_edits(self.rig(), &edits)?;
        Ok(glb_bytes(&baked, &GlbOptions::default())?)
    }
}
