//! The editor's wire format. The page sends JSON text frames (one [`Request`] each); the
//! server answers with JSON text frames ([`Reply`]) and binary frames for the bulk data
//! (a little-endian `u32` kind, then its payload, every array 4-byte aligned):
//!
//! | kind | payload |
//! |---|---|
//! | 1 mesh | `u32 n, u32 m, u32 0, f64 rest[3n], u32 triangles[3m]` |
//! | 2 positions | `u32 seq, f32 pose_ms, u32 0, f64 posed[3n]` |
//! | 3 field | `f32 min, f32 max, f32 value[n]` |
//! | 4 groups | `u32 n, u8 group_plus_one[n]` (0: in no group; padded to 4 bytes) |
//! | 5 positions in f32 | `u32 seq, f32 pose_ms, u32 0, f32 posed[3n]` |
//!
//! Positions travel in f64 by default, exactly as the library computed them (a client can
//! compare them with its own pose bit for bit); the page, which draws in f32, asks for kind 5
//! ([`Request::Precision`]): half the bytes per pose (1.2 MB -> 0.6 MB on a 50k mesh).

use crate::input::MotorSpec;
use crate::methods::option::{OptionKind, OptionSpec, OptionValue};
use glam::DVec3;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Frame kinds of the binary frames.
pub const MESH: u32 = 1;
/// Kind 2: posed positions in f64.
pub const POSITIONS: u32 = 2;
/// Kind 3: a scalar per vertex.
pub const FIELD: u32 = 3;
/// Kind 4: each vertex's group.
pub const GROUPS: u32 = 4;
/// Kind 5: posed positions in f32.
pub const POSITIONS_F32: u32 = 5;

/// The precision of the positions frames.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Precision {
    /// Kind 2: the library's f64 (the default).
    #[default]
    F64,
    /// Kind 5: rounded to f32, as the page draws them.
    F32,
}

/// One joint edit of a rig: `motor` in the joint's own frame.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EditSpec {
    /// The joint (index into the rig's joints).
    pub joint: usize,
    /// The motor, in the joint's own frame.
    pub motor: MotorSpec,
}

/// What the page asks for.
#[derive(Clone, Debug, Deserialize)]
#[serde(tag = "op", rename_all = "kebab-case", deny_unknown_fields)]
pub enum Request {
    /// Open a scene by name (one of [`Reply::State`]'s `scenes`).
    Scene {
        /// The scene's name.
        name: String,
    },
    /// Paint: the vertices within `radius` of where the ray first meets the posed surface join
    /// group `group` (`group == groups` starts a new one), or leave their group (`erase`).
    Paint {
        /// The ray's origin (world space).
        origin: [f64; 3],
        /// The ray's direction.
        direction: [f64; 3],
        /// The brush radius (world units).
        radius: f64,
        /// The group painted.
        group: usize,
        /// Take the vertices out of their group instead.
        #[serde(default)]
        erase: bool,
        /// The first dab of a stroke: the selection before it is what an undo returns to.
        #[serde(default)]
        begin: bool,
    },
    /// Lasso: the vertices seen from `eye` whose projection by `view_proj` (column-major 4x4)
    /// falls inside `polygon` (normalised device coordinates) join `group` (or leave it).
    Lasso {
        /// The camera's position (world space).
        eye: [f64; 3],
        /// The view-projection matrix, column-major.
        view_proj: [f64; 16],
        /// The lasso, in normalised device coordinates.
        polygon: Vec<[f64; 2]>,
        /// The group the vertices join.
        group: usize,
        /// Take the vertices out of their group instead.
        #[serde(default)]
        erase: bool,
    },
    /// Forget every group.
    ClearGroups,
    /// Bind the method to the current groups (after a paint stroke).
    Bind,
    /// Choose the method (any of the state's `methods`), its blend and its options; rebinds
    /// when the weights change.
    Method {
        /// The method by the library's name.
        method: String,
        /// The blend method by name, or `positional` for lattices and cages.
        blend: String,
        /// Options by name (the state's `option_specs`): a name, a number, `[l, m, n]` for
        /// points per axis; what is given changes, all checked together.
        #[serde(default)]
        options: BTreeMap<String, serde_json::Value>,
    },
    /// Pose the handle groups: one motor per group (the CLI's motor JSON).
    Motors {
        /// The pose's sequence number (echoed in the reply).
        seq: u32,
        /// One motor per key.
        motors: Vec<MotorSpec>,
    },
    /// Pose the rig at `time` of `animation` (none: rest) with joint edits, by `backend`.
    Rig {
        /// The pose's sequence number (echoed in the reply).
        seq: u32,
        /// The animation (none: the rest pose).
        animation: Option<usize>,
        /// The time in seconds.
        time: f64,
        /// The skinning backend by blend method name.
        backend: String,
        /// Joint edits.
        #[serde(default)]
        edits: Vec<EditSpec>,
    },
    /// Colour by a field (one of the state's `fields`); `group` for per-group fields.
    Field {
        /// The field's name.
        name: String,
        /// The group of a per-group field.
        #[serde(default)]
        group: usize,
    },
    /// Cut the rig by the plane through `point` with normal `normal`, in the posed frame.
    Cut {
        /// A point on the plane (posed frame).
        point: [f64; 3],
        /// The plane's normal.
        normal: [f64; 3],
        /// Close the pieces with caps (default).
        #[serde(default = "yes")]
        cap: bool,
    },
    /// Tear the rig's skin along the surface under a stroke: one ray (origin, direction) per
    /// sample, in the posed frame; `open` pulls the lips apart.
    Tear {
        /// One ray (origin, direction) per sample of the stroke.
        rays: Vec<[[f64; 3]; 2]>,
        /// How far the lips are pulled apart.
        #[serde(default)]
        open: f64,
    },
    /// Drill where the ray meets the posed surface: `radius` and `depth` are fractions of the
    /// mesh's size.
    Drill {
        /// The ray's origin (world space).
        origin: [f64; 3],
        /// The ray's direction.
        direction: [f64; 3],
        /// The drill's radius, a fraction of the mesh's size.
        radius: f64,
        /// The drill's depth, a fraction of the mesh's size.
        depth: f64,
    },
    /// Undo or redo the last surgery (a rig) or selection change (a mesh scene: a paint
    /// stroke, a lasso, clearing or loading the groups).
    Undo,
    /// Redo what [`Request::Undo`] undid.
    Redo,
    /// A file of the current state: `obj`, `motors`, `selection`, `edits`.
    Export {
        /// What to export.
        what: String,
    },
    /// Load a selection (`selection`, the CLI's JSON) or motors (`motors`).
    Load {
        /// What the text is: `selection` or `motors`.
        what: String,
        /// The file's text.
        text: String,
    },
    /// Open a model the page read from a file (OBJ, OFF, MEDIT, `.glb`, `.gltf` with its
    /// buffers embedded), as the CLI reads one: `name` chooses the format, `base64` holds
    /// its bytes.
    Upload {
        /// The file's name (its extension chooses the format).
        name: String,
        /// The file's bytes, base64.
        base64: String,
    },
    /// Send the positions of every later pose in this precision (no reply).
    Precision {
        /// The precision.
        positions: Precision,
    },
}

impl Request {
    /// What a request that may take a while (a bind, a cut) is doing, for the page to show.
    pub fn slow(&self) -> Option<&'static str> {
        match self {
            Request::Scene { .. } | Request::Upload { .. } => Some("opening the scene"),
            Request::Bind | Request::Method { .. } | Request::Load { .. } => Some("binding"),
            Request::Cut { .. } => Some("cutting"),
            Request::Tear { .. } => Some("tearing"),
            Request::Drill { .. } => Some("drilling"),
            Request::Undo | Request::Redo => Some("rebinding"),
            _ => None,
        }
    }
}

fn yes() -> bool {
    true
}

/// One handle group as the page draws it.
#[derive(Clone, Debug, Serialize)]
pub struct GroupInfo {
    /// Its vertex count.
    pub vertices: usize,
    /// Its centroid at rest.
    pub center: [f64; 3],
}

/// One option of the current method, for the page's panel.
#[derive(Clone, Debug, Serialize)]
pub struct OptionSpecInfo {
    /// Its name (the request's and the state's key, the program's flag).
    pub name: &'static str,
    /// One line of help.
    pub help: &'static str,
    /// `choice`, `number`, `dims` (points per axis) or `switch`.
    pub kind: &'static str,
    /// The names a choice takes.
    pub values: Option<Vec<&'static str>>,
    /// The least number (of each axis).
    pub min: Option<usize>,
    /// The greatest number (of each axis).
    pub max: Option<usize>,
}

impl OptionSpecInfo {
    /// The page's description of `spec`.
    pub fn of(spec: &OptionSpec) -> OptionSpecInfo {
        let kind = match spec.kind {
            OptionKind::Choice { .. } => "choice",
            OptionKind::Number(_) => "number",
            OptionKind::Dims(_) => "dims",
            OptionKind::Switch => "switch",
        };
        OptionSpecInfo {
            name: spec.name,
            help: spec.help,
            kind,
            values: spec.values(),
            min: spec.range().map(|r| *r.start()),
            max: spec.range().map(|r| *r.end()),
        }
    }
}

/// A lattice's or cage's control points at rest and the lines between them.
#[derive(Clone, Debug, Serialize)]
pub struct ControlsInfo {
    /// The control points at rest.
    pub points: Vec<[f64; 3]>,
    /// Pairs of points joined by a line.
    pub edges: Vec<[u32; 2]>,
}

/// An animation of the rig.
#[derive(Clone, Debug, Serialize)]
pub struct AnimationInfo {
    /// Its name.
    pub name: String,
    /// Its first key time, seconds.
    pub start: f64,
    /// Its last key time, seconds.
    pub end: f64,
}

/// What the page needs of a rig.
#[derive(Clone, Debug, Serialize)]
pub struct RigInfo {
    /// The animations.
    pub animations: Vec<AnimationInfo>,
    /// The joints' names.
    pub joints: Vec<String>,
    /// Each joint's nearest ancestor that is a joint (-1: none), for drawing the skeleton.
    pub parents: Vec<i64>,
    /// The skinning backends by name.
    pub backends: Vec<&'static str>,
    /// Surgeries that can be undone.
    pub undo: usize,
    /// Surgeries that can be redone.
    pub redo: usize,
}

/// The whole editing state, as [`Reply::State`] sends it.
#[derive(Clone, Debug, Serialize)]
pub struct StateInfo {
    /// The open scene.
    pub scene: String,
    /// Every scene's name.
    pub scenes: Vec<String>,
    /// `mesh` (handles, ARAP, spline) or `rig`.
    pub kind: &'static str,
    /// The method by name.
    pub method: String,
    /// The methods this scene offers.
    pub methods: Vec<&'static str>,
    /// The blend by name (`positional` for the positional form).
    pub blend: String,
    /// The blends this method offers.
    pub blends: Vec<&'static str>,
    /// Every method's options by name, with their values (a name, a number, `[l, m, n]`).
    pub options: BTreeMap<&'static str, OptionValue>,
    /// The current method's options, for the page's panel.
    pub option_specs: Vec<OptionSpecInfo>,
    /// What the current method's command reads besides the mesh (`selection`, `motors`,
    /// `keys`, `rest-keys`, `cage`): the page's exports for its replay.
    pub inputs: Vec<&'static str>,
    /// The handle groups.
    pub groups: Vec<GroupInfo>,
    /// The fields the mesh can be coloured by.
    pub fields: Vec<&'static str>,
    /// The control points when the method is a lattice or a cage (then the motors are theirs).
    pub controls: Option<ControlsInfo>,
    /// The rig, for a rig scene.
    pub rig: Option<RigInfo>,
    /// The last bind's time.
    pub bind_ms: f64,
    /// The mesh's vertex count.
    pub vertices: usize,
    /// The mesh's triangle count.
    pub triangles: usize,
    /// Whether the groups changed since the last bind.
    pub stale: bool,
    /// Selection changes that can be undone and redone (mesh scenes).
    pub selection_undo: usize,
    /// Selection changes that can be redone.
    pub selection_redo: usize,
    /// The `deform ...` command that replays the pose from the exported files.
    pub replay: String,
}

/// What the server says in text frames.
#[derive(Clone, Debug, Serialize)]
#[serde(tag = "type", rename_all = "kebab-case")]
pub enum Reply {
    /// The whole editing state (after a scene, a bind, a method change or a surgery).
    State(Box<StateInfo>),
    /// A bind started (it may take a while); the page shows it, with the time it has taken,
    /// until [`Reply::Idle`]: against `expect_ms` where known, the time the last request of
    /// the same kind took on the same scene with the same method (an estimate, so the page
    /// can draw a fraction).
    Binding {
        /// What is being done.
        what: String,
        /// How long the last such request took.
        #[serde(skip_serializing_if = "Option::is_none")]
        expect_ms: Option<f64>,
    },
    /// The slow request announced by [`Reply::Binding`] is done (its results were sent).
    Idle,
    /// A pose was not made, or a request was refused, and why.
    Error {
        /// Why.
        message: String,
    },
    /// Something the page should say that is not an error (what to do next).
    Note {
        /// What to say.
        message: String,
    },
    /// Per-pose figures beside the positions frame.
    Posed {
        /// The request's sequence number.
        seq: u32,
        /// The pose's time.
        pose_ms: f64,
        /// ARAP's energy after the frame's iterations.
        energy: Option<f64>,
        /// The rig's joint positions (world) and frames (unit quaternions `x y z w`).
        joints: Option<Vec<[f64; 7]>>,
    },
    /// A file for the page to save (`.glb` as base64).
    File {
        /// The file's name.
        name: String,
        /// Its content (base64 when `base64`).
        text: String,
        /// Whether `text` is base64.
        base64: bool,
    },
    /// Motors loaded from a file, as scale, rotation (`x y z w`) and translation about each
    /// group's rest centre.
    Motors {
        /// Per key: scale, rotation and translation.
        motors: Vec<[f64; 8]>,
    },
}

/// A binary frame: kind, then the payload words.
pub struct Frame(
    /// The frame's bytes.
    pub Vec<u8>,
);

impl Frame {
    fn new(kind: u32, capacity: usize) -> Frame {
        let mut v = Vec::with_capacity(4 + capacity);
        v.extend_from_slice(&kind.to_le_bytes());
        Frame(v)
    }
    fn u32(&mut self, x: u32) -> &mut Self {
        self.0.extend_from_slice(&x.to_le_bytes());
        self
    }
    fn f32(&mut self, x: f64) -> &mut Self {
        self.0.extend_from_slice(&(x as f32).to_le_bytes());
        self
    }
    fn points(&mut self, p: &[DVec3]) -> &mut Self {
        for q in p {
            for x in q.to_array() {
                self.0.extend_from_slice(&x.to_le_bytes());
            }
        }
        self
    }

    /// Kind 1: rest positions and triangles.
    pub fn mesh(rest: &[DVec3], triangles: &[[u32; 3]]) -> Frame {
        let mut f = Frame::new(MESH, 12 + 24 * rest.len() + 12 * triangles.len());
        f.u32(rest.len() as u32).u32(triangles.len() as u32).u32(0);
        f.points(rest);
        for t in triangles {
            f.u32(t[0]).u32(t[1]).u32(t[2]);
        }
        f
    }

    /// Kind 2: posed positions.
    pub fn positions(seq: u32, pose_ms: f64, posed: &[DVec3]) -> Frame {
        let mut f = Frame::new(POSITIONS, 12 + 24 * posed.len());
        f.u32(seq).f32(pose_ms).u32(0).points(posed);
        f
    }

    /// Kind 5: [`Frame::positions`] rounded to f32.
    pub fn positions_f32(seq: u32, pose_ms: f64, posed: &[DVec3]) -> Frame {
        let mut f = Frame::new(POSITIONS_F32, 12 + 12 * posed.len());
        f.u32(seq).f32(pose_ms).u32(0);
        for q in posed {
            for x in q.to_array() {
                f.f32(x);
            }
        }
        f
    }

    /// Kind 3: a scalar per vertex and its range (non-finite values drawn as the minimum).
    pub fn field(values: &[f64]) -> Frame {
        let finite = values.iter().copied().filter(|x| x.is_finite());
        let min = finite.clone().fold(f64::INFINITY, f64::min);
        let max = finite.fold(f64::NEG_INFINITY, f64::max);
        let (min, max) = if min <= max { (min, max) } else { (0.0, 0.0) };
        let mut f = Frame::new(FIELD, 8 + 4 * values.len());
        f.f32(min).f32(max);
        for &x in values {
            f.f32(if x.is_finite() { x } else { min });
        }
        f
    }

    /// Kind 4: each vertex's group plus one (0: none; groups past 254 shown as 255).
    pub fn groups(owner: &[u32]) -> Frame {
        let mut f = Frame::new(GROUPS, 4 + owner.len() + 3);
        f.u32(owner.len() as u32);
        f.0.extend(owner.iter().map(|&g| {
            if g == u32::MAX {
                0
            } else {
                (g + 1).min(255) as u8
            }
        }));
        while !f.0.len().is_multiple_of(4) {
            f.0.push(0);
        }
        f
    }
}
