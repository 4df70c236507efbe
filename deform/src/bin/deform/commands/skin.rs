//! `deform skin`: pose a rigged model (glTF, or OBJ + TGF + DMAT weights) at a time of one of
//! its animations, with joint edits, by any skinning backend; write OBJ (one file, or a
//! sequence for a time range or generated in-betweens) or the whole rig as `.glb`.

mod frames;

use crate::finish::displacement;
use crate::input_files::{read_rig, read_text};
use crate::output_files::{check_formats, check_outputs, write_glb, write_png, MESH_FORMATS};
use crate::report::Report;
use crate::shared_args::{OutputArgs, RigInput};
use crate::timing::ms;
use anyhow::{bail, Context, Result};
use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use clap::{Args, ValueEnum};
use deform::input::parse_motor;
use deform::methods::frame::pose_time;
use deform::render::preview;
use deform::skinning::{bake_edits, in_betweens, GlbOptions, JointEdit, KeyframeBlend, Skinning};
use deform::{BlendMethod, Mesh};
use glam::DVec3;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The skinning backends by their usual names: the name, the blend method it selects and
/// its help (the one table from `--backend` names to [`BlendMethod`]s).
const BACKENDS: [(&str, BlendMethod, &str); 7] = [
    (
        "lbs",
        BlendMethod::Matrix,
        "Matrix linear blend skinning (f64)",
    ),
    (
        "lbs-f32",
        BlendMethod::MatrixF32,
        "Matrix linear blend skinning in single precision (glam SIMD)",
    ),
    (
        "dqs",
        BlendMethod::DualQuaternion,
        "Dual-quaternion skinning (Kavan)",
    ),
    (
        "cga",
        BlendMethod::Conformal,
        "The paper's equation (17), adding conformal points then down-projecting",
    ),
    (
        "cga-projected",
        BlendMethod::ConformalProjected,
        "Equation (17), down-projecting each term then adding",
    ),
    (
        "motor",
        BlendMethod::MotorLinear,
        "Motor blending: the normalised weighted motor sum, scale blended geometrically",
    ),
    (
        "motor-log",
        BlendMethod::MotorLog,
        "Log blending of the skin motors, exp(sum w log M)",
    ),
];

/// A skinning backend: its name as given and the blend method it selects.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Backend {
    pub name: &'static str,
    pub method: BlendMethod,
}

/// A backend by one of the [`BACKENDS`] names (clap's possible values, with their help).
fn backend() -> impl TypedValueParser<Value = Backend> {
    let names = BACKENDS.map(|(name, _, help)| PossibleValue::new(name).help(help));
    PossibleValuesParser::new(names).try_map(|given: String| {
        BACKENDS
            .iter()
            .find(|(name, _, _)| *name == given)
            .map(|&(name, method, _)| Backend { name, method })
            .ok_or_else(|| format!("unknown backend {given:?}"))
    })
}

/// Keyframe blending.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum Keyframes {
    /// Each property by its sampler (LINEAR, STEP, CUBICSPLINE), as glTF specifies.
    Gltf,
    /// `M_1 exp(a log(M_1^-1 M_2))` between a node's neighbouring keyframes.
    MotorLog,
}

#[derive(Args, Debug)]
pub struct SkinArgs {
    #[command(flatten)]
    pub rig: RigInput,
    /// The animation, by name or index (default: the first when --time or --range is given,
    /// as for cut, tear and drill; without either, the rest pose).
    #[arg(long)]
    pub animation: Option<String>,
    /// Time in seconds (clamped to the animation's keys; default 0); with --dmat-animation a
    /// frame index.
    #[arg(long, value_parser = crate::numbers::finite, allow_hyphen_values = true)]
    pub time: Option<f64>,
    /// A time range T0:T1:N: N frames written as OUT_0000.obj, OUT_0001.obj, ...
    #[arg(long, value_parser = parse_range, conflicts_with = "time")]
    pub range: Option<(f64, f64, usize)>,
    /// A libigl animation (DMAT: per frame, per bone, the 4x3 block `igl::lbs_matrix` takes)
    /// for a mesh model; --time is then the frame index.
    #[arg(long, requires = "skeleton")]
    pub dmat_animation: Option<PathBuf>,
    /// How keyframes are blended: glTF's samplers, or logarithmic blending of neighbouring
    /// keyframes as motors (the paper's choice for existing keyframes).
    #[arg(long, value_enum, default_value_t = Keyframes::Gltf)]
    pub keyframes: Keyframes,
    /// The skinning backend.
    #[arg(long, value_parser = backend(), default_value = "cga")]
    pub backend: Backend,
    /// Pose on the GPU (wgpu; every backend), in f32: needs a program built
    /// with `--features gpu`, and a GPU or Mesa's lavapipe (otherwise exit code 2);
    /// `--gpu=auto` poses on the CPU instead, with a note, where there is none.
    #[arg(long, value_enum, num_args = 0..=1, require_equals = true, default_value = "off",
          default_missing_value = "on", value_name = "WHEN")]
    pub gpu: crate::shared_args::GpuChoice,
    /// A joint edit JOINT=MOTOR.json (joint name or skin joint index; the motor acts in the
    /// joint's own frame: rotate or dilate about its pivot, translate along its axes).
    #[arg(long = "edit", value_parser = parse_edit)]
    pub edits: Vec<(String, PathBuf)>,
    /// Also skin with this backend and report the l-infinity distance between the two, as a
    /// percentage of the bounding-box diagonal (the paper's Fig. 2: `--backend cga --compare
    /// dqs` with a slight edit of the neck).
    #[arg(long, value_parser = backend())]
    pub compare: Option<Backend>,
    /// Generate N in-between frames from the unedited pose to the edited one (linear
    /// blending), written as an OBJ sequence.
    #[arg(long)]
    pub in_betweens: Option<usize>,
    #[command(flatten)]
    pub out: OutputArgs,
}

fn parse_range(s: &str) -> Result<(f64, f64, usize), String> {
    let p: Vec<&str> = s.split(':').collect();
    let bad = || format!("{s:?}: expected T0:T1:N");
    if p.len() != 3 {
        return Err(bad());
    }
    let t0: f64 = p[0].parse().map_err(|_| bad())?;
    let t1: f64 = p[1].parse().map_err(|_| bad())?;
    let n: usize = p[2].parse().map_err(|_| bad())?;
    if !(t0.is_finite() && t1.is_finite()) || n == 0 || n > 100_000 {
        return Err(format!("{s:?}: times must be finite and N in 1..=100000"));
    }
    Ok((t0, t1, n))
}

fn parse_edit(s: &str) -> Result<(String, PathBuf), String> {
    let (j, m) = s
        .split_once('=')
        .ok_or_else(|| format!("{s:?}: expected JOINT=MOTOR.json"))?;
    Ok((j.to_string(), PathBuf::from(m)))
}

/// `OUT.obj` -> `OUT_0003.obj` (`.ply` stays `.ply`).
fn numbered(path: &Path, k: usize) -> PathBuf {
    let stem = path
        .file_stem()
        .map_or("frame".into(), |s| s.to_string_lossy().to_string());
    let ext = path
        .extension()
        .filter(|e| e.eq_ignore_ascii_case("ply"))
        .map_or("obj".into(), |e| e.to_string_lossy().to_string());
    path.with_file_name(format!("{stem}_{k:04}.{ext}"))
}

pub fn run(a: &SkinArgs) -> Result<()> {
    let rig_files = a.rig.paths();
    let mut inputs: Vec<&Path> = rig_files.iter().map(PathBuf::as_path).collect();
    inputs.extend(a.dmat_animation.as_deref());
    inputs.extend(a.edits.iter().map(|(_, p)| p.as_path()));
    check_outputs(&inputs, &a.out.paths())?;
    check_formats(&a.out, &MESH_FORMATS)?;
    let glb = a
        .out
        .output
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("glb"));
    let t = Instant::now();
    let rig = read_rig(&a.rig)?;
    let load_ms = ms(t);
    // The library's convention, as for cut, tear and drill: a time (or a range) without a
    // named animation is in the first one. A DMAT animation is the frames given instead.
    let timed = a.time.or(a.range.map(|r| r.0));
    let timed = timed.filter(|_| a.dmat_animation.is_none() || a.animation.is_some());
    let animation = pose_time(&rig, a.animation.as_deref(), timed)?.animation;
    let time = a.time.unwrap_or(0.0);
    let mut edits = Vec::new();
    for (joint, path) in &a.edits {
        let j = rig.joint_index(joint)?;
        let motor = parse_motor(&read_text(path)?, &path.display().to_string())?;
        edits.push(JointEdit { joint: j, motor });
    }
    // The written rig carries the edits in its rest transforms and its animations, so a
    // viewer playing it shows them; refused here, before any work, when that is impossible.
    let baked = if glb {
        Some(bake_edits(&rig, &edits)?)
    } else {
        None
    };
    let method = a.backend.method;
    let t = Instant::now();
    let bound = Skinning::bind(&rig, method)?;
    let bind_ms = ms(t);
    let mut report = Report::new("skin", &rig.mesh);
    // The name given on the command line, and the blend method it selects.
    report.add("backend", a.backend.name);
    report.add("blend_method", method.name());
    report.add("joints", rig.joints.len());
    report.add("animations", rig.animations.len());
    if let Some(k) = animation {
        report.add("animation", rig.animations[k].name.as_str());
    }
    report.add("renormalised_vertices", rig.report.renormalised_vertices);
    for note in &rig.report.notes {
        report.add("note", note.as_str());
    }
    let gpu = crate::gpu_pose::GpuPoser::choose(a.gpu, &mut report, a.out.quiet, || {
        crate::gpu_pose::GpuPoser::open(bound.blend())
    })?;
    report.add("load_ms", load_ms);
    report.add("bind_ms", bind_ms);
    let dmat = read_dmat_animation(a, &rig, &edits, &mut report)?;
    let frames = frame_list(a, &edits, time, rig.mesh.vertex_count())?;
    let sequence = frames.len() > 1;
    if glb && sequence {
        bail!("a frame sequence is written as OBJ files, not .glb");
    }
    if sequence {
        // The generated names, as a set, before anything is written: none may name an input.
        let names: Vec<PathBuf> = (0..frames.len())
            .map(|k| numbered(&a.out.output, k))
            .collect();
        let mut outputs: Vec<&Path> = names.iter().map(PathBuf::as_path).collect();
        outputs.extend(a.out.png.as_deref());
        check_outputs(&inputs, &outputs)?;
    }
    let mut posing = frames::Posing {
        rig: &rig,
        bound: &bound,
        other: a
            .compare
            .map(|b| Skinning::bind(&rig, b.method))
            .transpose()?,
        gpu,
        dmat: dmat.as_ref(),
        animation,
        keyframes: match a.keyframes {
            Keyframes::Gltf => KeyframeBlend::Gltf,
            Keyframes::MotorLog => KeyframeBlend::MotorLog,
        },
    };
    let posed = posing.pose_frames(a, &frames, !glb)?;
    if !glb {
        frames::write_frames(&posed.finished, sequence, &rig)?;
    }
    report.add("frames", frames.len());
    if let Some(b) = a.compare {
        let diag = diagonal(&posed.last);
        // The --compare name as given, in the --backend vocabulary.
        report.add("compared_with", b.name);
        report.add(
            "linf_difference_percent_of_diagonal",
            100.0 * posed.linf / diag,
        );
    }
    report.add("pose_ms", posed.pose_ms / frames.len() as f64);
    let world_diagonal = diagonal(&posed.last);
    crate::similarity_report::report(&posed.approximation, &rig, world_diagonal, &mut report);
    if let Some(baked) = &baked {
        write_glb(&a.out.output, baked, &GlbOptions::default())?;
    }
    report.add("output", a.out.output.display().to_string());
    if let Some(png) = &a.out.png {
        let t = frames.last().map_or(time, |f| f.0);
        write_preview(a, &rig, &posed, t, edits.len(), png)?;
        report.add("png", png.display().to_string());
    }
    report.print(&a.out);
    Ok(())
}

/// The bounding-box diagonal of `positions`.
fn diagonal(positions: &[DVec3]) -> f64 {
    Mesh::new(positions.to_vec(), Vec::new())
        .bounding_box()
        .map_or(f64::NAN, |b| b.diagonal())
}

/// `--dmat-animation`: libigl's bone transforms per frame (no edits or glTF animation with
/// them).
fn read_dmat_animation(
    a: &SkinArgs,
    rig: &deform::Rig,
    edits: &[JointEdit],
    report: &mut Report,
) -> Result<Option<deform::skinning::LibiglAnimation>> {
    let Some(path) = &a.dmat_animation else {
        return Ok(None);
    };
    if !edits.is_empty() || a.animation.is_some() {
        bail!("--dmat-animation poses the bones directly: no --edit or --animation with it");
    }
    let m = deform::mesh::io::read_dmat(path)?;
    let anim = deform::skinning::read_libigl_animation(&m, rig.joints.len())
        .with_context(|| format!("{}: not an animation of this rig", path.display()))?;
    report.add("frames_in_animation", anim.frames.len());
    Ok(Some(anim))
}

/// The frames to pose, (time, edits) each: one, a `--range` of times, or `--in-betweens` of
/// the edits. Each frame is a file written: a tiny rig cannot ask for a million of them.
fn frame_list(
    a: &SkinArgs,
    edits: &[JointEdit],
    time: f64,
    vertices: usize,
) -> Result<Vec<(f64, Vec<JointEdit>)>> {
    if let Some((_, _, n)) = a.range {
        crate::budget::get().frames_written("--range", n, vertices)?;
    }
    if let Some(n) = a.in_betweens {
        crate::budget::get().frames_written("--in-betweens", n, vertices)?;
    }
    Ok(match (a.range, a.in_betweens) {
        (Some(_), Some(_)) => bail!("--range and --in-betweens cannot be combined"),
        (Some((t0, t1, n)), None) => (0..n)
            .map(|k| {
                let s = if n == 1 {
                    0.0
                } else {
                    k as f64 / (n - 1) as f64
                };
                (t0 + (t1 - t0) * s, edits.to_vec())
            })
            .collect(),
        (None, Some(n)) => {
            let steps: Vec<Vec<JointEdit>> = edits
                .iter()
                .map(|e| {
                    in_betweens(e.motor, n.max(1))
                        .into_iter()
                        .map(|m| JointEdit {
                            joint: e.joint,
                            motor: m,
                        })
                        .collect()
                })
                .collect();
            (0..n.max(1))
                .map(|k| (time, steps.iter().map(|s| s[k]).collect()))
                .collect()
        }
        (None, None) => vec![(time, edits.to_vec())],
    })
}

/// The preview: the rest in the scene's world space at the bind pose (armature transforms,
/// unit scale and up axis applied), where the posed mesh is, beside the last frame.
fn write_preview(
    a: &SkinArgs,
    rig: &deform::Rig,
    posed: &frames::Posed,
    time: f64,
    edits: usize,
    png: &Path,
) -> Result<()> {
    let rest_mesh = Mesh::new(rig.bind_pose_positions()?, rig.mesh.triangles.clone());
    let moved = displacement(&rest_mesh, &posed.last);
    let mut title = format!(
        "skin  {}  t {}  {edits} edit(s)  {}",
        a.backend.name,
        deform::render::short_number(time),
        preview::max_move(&rest_mesh, &posed.last)
    );
    if let Some(b) = a.compare {
        let diag = rest_mesh.bounding_box().map_or(f64::NAN, |b| b.diagonal());
        let percent = deform::render::short_number(100.0 * posed.linf / diag);
        title.push_str(&format!("  vs {}: {percent}% of diag", b.name));
    }
    let mut look = preview::Look::new(title, "displacement");
    look.view = a.out.view();
    let posed_mesh = Mesh::new(posed.last.clone(), rig.mesh.triangles.clone());
    let image = preview::before_after(&rest_mesh, &posed_mesh, &moved, &look)?;
    write_png(png, &image)
}
