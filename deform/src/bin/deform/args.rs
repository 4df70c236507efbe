//! Command-line arguments (clap). Every subcommand shares the motor JSON format, the
//! selection format, `-o`, `--png`, `--json` and `--quiet`.

use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// Mesh deformation with conformal geometric algebra motors.
#[derive(Parser, Debug)]
#[command(name = "deform", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// The work budget: the most elements (f64s of a buffer, grid nodes, vertices times frames
    /// or iterations) any size asked for may come to; larger requests are refused up front.
    #[arg(long, global = true, default_value_t = crate::budget::DEFAULT_MAX_WORK)]
    pub max_work: u64,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Bend, twist and stretch procedural meshes with every scheme, fit a spline to a FABRIK
    /// chain, move motor handles; write OBJ files, PNG previews and a contact sheet, and
    /// print a table of bind and pose times.
    Demo(DemoArgs),
    /// Spline-aligned deformation: group 0 of the selection is H_1 (lambda = 0), the highest
    /// group H_n (lambda = 1); keys are posed relative to the rest pose (rest keys are the
    /// identity unless --rest-keys is given).
    Spline(SplineArgs),
    /// Motor handles: one harmonic field per selection group, one motor per group.
    Handles(HandlesArgs),
    /// Inverse kinematics driving a spline: a chain of joints (JSON array of [x, y, z],
    /// root first; default: a straight chain of --joints joints from the centroid of group 0
    /// to the centroid of the highest group) is solved by FABRIK for its end effector to reach
    /// --target; its joint frames are fitted by a cubic B-spline of --controls motors, which
    /// deforms the mesh (the first paper's Fig. 5). An unreachable target stretches the chain
    /// towards it and says so.
    Fabrik(FabrikArgs),
    /// Free-form deformation: a lattice of L x M x N control points over the mesh's box (or
    /// --box), one motor per control point (index u + L*(v + M*w), "*" the rest); motor FFD
    /// (the paper's equations (7)-(8)) or classic positional FFD (--positional).
    Ffd(FfdArgs),
    /// Cage deformation: mean value or harmonic coordinates of the mesh in a closed cage, one
    /// motor per cage vertex ("*" the rest); motor-valued or positional (--positional). A cage
    /// that does not enclose the mesh is an error (exit code 2).
    Cage(CageArgs),
    /// As-rigid-as-possible deformation (the paper's rotors): selection groups with a motor
    /// in --motors are handles moved rigidly by it, the other groups stay fixed; iterates
    /// from the rest pose and prints the energy after each iteration.
    Arap(crate::arap_cmd::ArapArgs),
    /// Skinning: pose a rigged model (glTF, or a mesh with --skeleton TGF and --weights DMAT)
    /// at --time of --animation, with joint edits, by any --backend; write OBJ (world space by
    /// the glTF skinning formula, one vertex per glTF vertex, primitives concatenated in
    /// document order), an OBJ sequence (--range, --in-betweens) or the whole rig as .glb.
    Skin(crate::skin_cmd::SkinArgs),
    /// Cut a rigged model by the plane n.x = d (the second paper's Algorithm 1): both pieces
    /// stay skinned and animatable; .glb keeps the rig (one primitive per piece), OBJ writes
    /// the rest mesh. Coordinates are rest-pose mesh space unless --time is given.
    Cut(crate::surgery_cmds::CutArgs),
    /// Drill a hole with a finite cylinder from --tip to --end of --radius (Algorithm 3);
    /// the result stays skinned and animatable.
    Drill(crate::surgery_cmds::DrillArgs),
    /// Tear the skin with a scalpel given at successive time steps (Algorithm 2): the
    /// incision opens (--open pulls its lips apart); the result stays skinned and animatable.
    Tear(crate::surgery_cmds::TearArgs),
}

/// Options every command that writes files shares.
#[derive(Args, Debug, Clone)]
pub struct OutputArgs {
    /// The deformed mesh (OBJ; the input's vertex order and count are kept).
    #[arg(short = 'o', long = "output")]
    pub output: PathBuf,
    /// A PNG preview: the rest mesh beside the deformed one.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Print timings and counts as one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum SchemeArg {
    Linear,
    Quadratic,
    Bezier,
    Bspline,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum LaplacianArg {
    MeanValue,
    Cotangent,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum BlendArg {
    MotorLog,
    MotorLinear,
    DualQuaternion,
    Matrix,
    MatrixF32,
    Conformal,
    ConformalProjected,
}

/// The mesh and its handle groups, read by every subcommand.
#[derive(Args, Debug)]
pub struct MeshInput {
    /// The mesh (OBJ, OFF or MEDIT).
    pub mesh: PathBuf,
    /// Handle groups: a libigl DMAT (-1 free, k >= 0 group) or JSON {"k": [vertices]}.
    #[arg(long)]
    pub select: PathBuf,
}

/// How weights are computed and motors blended.
#[derive(Args, Debug)]
pub struct BlendingArgs {
    /// The Laplacian of the harmonic fields.
    #[arg(long, value_enum, default_value = "mean-value")]
    pub laplacian: LaplacianArg,
    /// How the key motors are blended.
    #[arg(long, value_enum, default_value = "motor-log")]
    pub blend: BlendArg,
}

#[derive(Args, Debug)]
pub struct DemoArgs {
    /// Where the OBJ files and PNG previews go.
    #[arg(long, default_value = "deform-demo")]
    pub out: PathBuf,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
    /// Print the table as JSON.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args, Debug)]
pub struct SplineArgs {
    #[command(flatten)]
    pub input: MeshInput,
    /// The key motors: a JSON array of motors.
    #[arg(long)]
    pub keys: PathBuf,
    /// The rest key motors (default: the identity for every key).
    #[arg(long)]
    pub rest_keys: Option<PathBuf>,
    /// The basis functions.
    #[arg(long, value_enum, default_value = "bspline")]
    pub scheme: SchemeArg,
    #[command(flatten)]
    pub blending: BlendingArgs,
    #[command(flatten)]
    pub out: OutputArgs,
}

#[derive(Args, Debug)]
pub struct HandlesArgs {
    #[command(flatten)]
    pub input: MeshInput,
    /// Per-group motors: JSON {"k": motor, "*": motor for the rest}.
    #[arg(long)]
    pub motors: PathBuf,
    #[command(flatten)]
    pub blending: BlendingArgs,
    #[command(flatten)]
    pub out: OutputArgs,
}

#[derive(Args, Debug)]
pub struct FabrikArgs {
    /// (Group 0 of the selection is the chain's root end, lambda = 0; the highest group its
    /// tip end, lambda = 1.)
    #[command(flatten)]
    pub input: MeshInput,
    /// Where the end effector should go: X,Y,Z.
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true)]
    pub target: [f64; 3],
    /// The chain's rest joints: a JSON array of [x, y, z], root first.
    #[arg(long)]
    pub chain: Option<PathBuf>,
    /// Joints of the default straight chain.
    #[arg(long, default_value_t = 6)]
    pub joints: usize,
    /// Control motors of the fitted B-spline (at most the number of joints).
    #[arg(long, default_value_t = 4)]
    pub controls: usize,
    /// FABRIK tolerance (distance of the end effector to the target).
    #[arg(long, default_value_t = 1e-6, value_parser = crate::numbers::positive)]
    pub tolerance: f64,
    /// FABRIK iteration cap.
    #[arg(long, default_value_t = 100)]
    pub iterations: usize,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// `X,Y,Z` as three finite numbers.
fn parse_vec3(s: &str) -> Result<[f64; 3], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>().map_err(|e| format!("{x:?}: {e}")))
        .collect::<Result<_, _>>()?;
    match v.as_slice() {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok([*x, *y, *z]),
        _ => Err(format!("expected three finite numbers X,Y,Z, got {s:?}")),
    }
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum CoordsArg {
    Mvc,
    Harmonic,
}

/// Positional or motor-valued posing of control points.
#[derive(Args, Debug)]
pub struct FormArgs {
    /// Classic positional form: each control point moves by its motor, vertices follow the
    /// weighted sum of the points.
    #[arg(long)]
    pub positional: bool,
    /// How the motors are blended in the motor form.
    #[arg(long, value_enum, default_value = "motor-log")]
    pub blend: BlendArg,
}

#[derive(Args, Debug)]
pub struct FfdArgs {
    /// The mesh (OBJ, OFF or MEDIT).
    pub mesh: PathBuf,
    /// Control points per axis: LxMxN (each at least 2).
    #[arg(long, value_parser = parse_dims)]
    pub lattice: [usize; 3],
    /// Clamped uniform B-spline basis of this degree (1 to 3) instead of Bernstein
    /// polynomials of degree L-1, M-1, N-1.
    #[arg(long)]
    pub degree: Option<usize>,
    /// The lattice box MINX,MINY,MINZ,MAXX,MAXY,MAXZ (default: the mesh's bounding box).
    #[arg(long = "box", value_parser = parse_box, allow_hyphen_values = true)]
    pub bounds: Option<[f64; 6]>,
    /// Per-control-point motors: JSON {"index": motor, "*": motor for the rest}.
    #[arg(long)]
    pub motors: PathBuf,
    #[command(flatten)]
    pub form: FormArgs,
    #[command(flatten)]
    pub out: OutputArgs,
}

#[derive(Args, Debug)]
pub struct CageArgs {
    /// The mesh (OBJ, OFF or MEDIT).
    pub mesh: PathBuf,
    /// The closed triangle cage around it.
    #[arg(long)]
    pub cage: PathBuf,
    /// Mean value or harmonic coordinates.
    #[arg(long, value_enum, default_value = "mvc")]
    pub coords: CoordsArg,
    /// Grid nodes along the cage's longest side (harmonic coordinates).
    #[arg(long, default_value_t = 64)]
    pub grid: usize,
    /// Accept a cage whose faces cross each other (refused by default).
    #[arg(long)]
    pub allow_self_intersecting: bool,
    /// Per-cage-vertex motors: JSON {"index": motor, "*": motor for the rest}.
    #[arg(long)]
    pub motors: PathBuf,
    #[command(flatten)]
    pub form: FormArgs,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// `LxMxN` as three counts.
fn parse_dims(s: &str) -> Result<[usize; 3], String> {
    let v: Vec<usize> = s
        .split(['x', 'X'])
        .map(|x| x.trim().parse::<usize>().map_err(|e| format!("{x:?}: {e}")))
        .collect::<Result<_, _>>()?;
    match v.as_slice() {
        [l, m, n] => Ok([*l, *m, *n]),
        _ => Err(format!("expected LxMxN, got {s:?}")),
    }
}

/// Six finite numbers, the minimum corner before the maximum.
fn parse_box(s: &str) -> Result<[f64; 6], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>().map_err(|e| format!("{x:?}: {e}")))
        .collect::<Result<_, _>>()?;
    match <[f64; 6]>::try_from(v.as_slice()) {
        Ok(b) if b.iter().all(|c| c.is_finite()) => Ok(b),
        _ => Err(format!(
            "expected six finite numbers MINX,MINY,MINZ,MAXX,MAXY,MAXZ, got {s:?}"
        )),
    }
}
