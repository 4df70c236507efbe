//! The `spline`, `handles` and `fabrik` subcommands: read, bind, pose, write, report.

use crate::args::{
    BlendArg, FabrikArgs, HandlesArgs, LaplacianArg, MeshInput, OutputArgs, SchemeArg, SplineArgs,
};
use crate::output::{check_outputs, read_mesh, read_selection, read_text, write_obj, write_png};
use crate::preview;
use anyhow::{bail, Context, Result};
use deform::input::{parse_group_motors, parse_key_list, Selection};
use deform::{
    BlendMethod, ChainDeformer, Deformer, FabrikOptions, HandleOptions, HarmonicOptions,
    LaplacianKind, Mesh, MotorHandles, SplineDeformer, SplineOptions, WeightScheme,
};
use glam::DVec3;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::Path;
use std::time::{Duration, Instant};

pub fn scheme(s: SchemeArg) -> WeightScheme {
    match s {
        SchemeArg::Linear => WeightScheme::Linear,
        SchemeArg::Quadratic => WeightScheme::Quadratic,
        SchemeArg::Bezier => WeightScheme::Bezier,
        SchemeArg::Bspline => WeightScheme::BSpline,
    }
}

pub fn harmonic(l: LaplacianArg) -> HarmonicOptions {
    HarmonicOptions {
        laplacian: match l {
            LaplacianArg::MeanValue => LaplacianKind::MeanValue,
            LaplacianArg::Cotangent => LaplacianKind::Default,
        },
        ..HarmonicOptions::default()
    }
}

pub fn blend(b: BlendArg) -> BlendMethod {
    match b {
        BlendArg::MotorLog => BlendMethod::MotorLog,
        BlendArg::MotorLinear => BlendMethod::MotorLinear,
        BlendArg::DualQuaternion => BlendMethod::DualQuaternion,
        BlendArg::Matrix => BlendMethod::Matrix,
        BlendArg::MatrixF32 => BlendMethod::MatrixF32,
        BlendArg::Conformal => BlendMethod::Conformal,
        BlendArg::ConformalProjected => BlendMethod::ConformalProjected,
    }
}

/// Run `f` under a spinner when it may take a while (large meshes, an interactive terminal,
/// not `--quiet`).
pub fn with_progress<T>(message: &str, vertices: usize, quiet: bool, f: impl FnOnce() -> T) -> T {
    let bar = (!quiet && vertices >= 20_000).then(|| {
        let b = ProgressBar::new_spinner();
        b.set_style(
            ProgressStyle::with_template("{spinner} {msg} {elapsed}")
                .unwrap_or_else(|_| ProgressStyle::default_spinner()),
        );
        b.set_message(message.to_string());
        b.enable_steady_tick(Duration::from_millis(100));
        b
    });
    let out = f();
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    out
}

/// The best of a few poses (the first one warms the caches), in milliseconds.
pub fn time_pose(d: &dyn Deformer, keys: &[cga::ScaledMotor], out: &mut [DVec3]) -> Result<f64> {
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        d.pose(keys, out)?;
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
    }
    Ok(best)
}

/// Counts and timings, printed as lines or one JSON object.
pub struct Report {
    pub fields: Vec<(&'static str, serde_json::Value)>,
}

impl Report {
    pub fn new(command: &str, mesh: &Mesh) -> Report {
        Report {
            fields: vec![
                ("command", command.into()),
                ("vertices", mesh.vertex_count().into()),
                ("triangles", mesh.triangle_count().into()),
            ],
        }
    }
    pub fn add(&mut self, key: &'static str, value: impl Into<serde_json::Value>) {
        self.fields.push((key, value.into()));
    }
    pub fn print(&self, out: &OutputArgs) {
        if out.json {
            let map: serde_json::Map<String, serde_json::Value> = self
                .fields
                .iter()
                .map(|(k, v)| (k.to_string(), v.clone()))
                .collect();
            println!("{}", serde_json::Value::Object(map));
        } else if !out.quiet {
            for (k, v) in &self.fields {
                println!("{k:>12}: {v}");
            }
        }
    }
}

/// Write the posed mesh and its preview.
pub(crate) fn finish(
    mesh: &Mesh,
    posed: Vec<DVec3>,
    scalar: &[f64],
    out: &OutputArgs,
    report: &mut Report,
) -> Result<()> {
    if let Some(i) = posed.iter().position(|p| !p.is_finite()) {
        bail!("vertex {i}: the deformation produced a non-finite position");
    }
    let posed = Mesh::new(posed, mesh.triangles.clone());
    write_obj(&out.output, &posed)?;
    report.add("output", out.output.display().to_string());
    if let Some(png) = &out.png {
        let image = preview::before_after(mesh, &posed, scalar, 30.0, 20.0)?;
        write_png(png, &image)?;
        report.add("png", png.display().to_string());
    }
    report.print(out);
    Ok(())
}

/// Read the mesh and selection, refusing outputs that are inputs.
pub(crate) fn read_inputs(
    input: &MeshInput,
    extra: &[&Path],
    out: &OutputArgs,
) -> Result<(Mesh, Selection)> {
    let (mesh, select) = (input.mesh.as_path(), input.select.as_path());
    let mut inputs = vec![mesh, select];
    inputs.extend_from_slice(extra);
    let mut outputs = vec![out.output.as_path()];
    if let Some(p) = &out.png {
        outputs.push(p.as_path());
    }
    check_outputs(&inputs, &outputs)?;
    crate::output::check_formats(out, &["obj"])?;
    let m = read_mesh(mesh)?;
    let sel = read_selection(select, m.vertex_count())?;
    Ok((m, sel))
}

/// The first and last groups of a selection, for the spline deformers.
fn ends(sel: &Selection, name: &Path) -> Result<(Vec<u32>, Vec<u32>)> {
    if sel.groups.len() < 2 {
        bail!(
            "{}: a spline needs at least two groups (0 = H_1, highest = H_n), found {}",
            name.display(),
            sel.groups.len()
        );
    }
    Ok((
        sel.groups[0].clone(),
        sel.groups[sel.groups.len() - 1].clone(),
    ))
}

pub fn spline(a: &SplineArgs) -> Result<()> {
    let mut extra = vec![a.keys.as_path()];
    if let Some(r) = &a.rest_keys {
        extra.push(r.as_path());
    }
    let (mesh, sel) = read_inputs(&a.input, &extra, &a.out)?;
    let (first, last) = ends(&sel, &a.input.select)?;
    let name = a.keys.display().to_string();
    let keys = parse_key_list(&read_text(&a.keys)?, &name)?;
    let rest = match &a.rest_keys {
        Some(r) => parse_key_list(&read_text(r)?, &r.display().to_string())?,
        None => vec![cga::ScaledMotor::IDENTITY; keys.len()],
    };
    if rest.len() != keys.len() {
        bail!("{} rest keys but {} keys", rest.len(), keys.len());
    }
    let options = SplineOptions {
        scheme: scheme(a.scheme),
        harmonic: harmonic(a.blending.laplacian),
        method: blend(a.blending.blend),
    };
    let t = Instant::now();
    let d = with_progress(
        "binding (harmonic field)",
        mesh.vertex_count(),
        a.out.quiet,
        || SplineDeformer::bind(&mesh, &first, &last, &rest, options),
    )
    .with_context(|| format!("{}: cannot bind", a.input.mesh.display()))?;
    let bind_ms = t.elapsed().as_secs_f64() * 1e3;
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    let pose_ms =
        time_pose(&d, &keys, &mut posed).with_context(|| format!("{name}: cannot pose"))?;
    let mut report = Report::new("spline", &mesh);
    report.add("scheme", options.scheme.name());
    report.add("blend", options.method.name());
    report.add("keys", keys.len());
    report.add("bind_ms", bind_ms);
    report.add("pose_ms", pose_ms);
    let lambda = d.lambda().to_vec();
    finish(&mesh, posed, &lambda, &a.out, &mut report)
}

pub fn handles(a: &HandlesArgs) -> Result<()> {
    let (mesh, sel) = read_inputs(&a.input, &[a.motors.as_path()], &a.out)?;
    let name = a.motors.display().to_string();
    let motors = parse_group_motors(&read_text(&a.motors)?, &name, sel.groups.len())?;
    let options = HandleOptions {
        harmonic: harmonic(a.blending.laplacian),
        method: blend(a.blending.blend),
    };
    let rest = vec![cga::ScaledMotor::IDENTITY; sel.groups.len()];
    let t = Instant::now();
    let d = with_progress(
        "binding (harmonic fields)",
        mesh.vertex_count(),
        a.out.quiet,
        || MotorHandles::bind_with(&mesh, &sel.sets(), &rest, options),
    )
    .with_context(|| format!("{}: cannot bind", a.input.mesh.display()))?;
    let bind_ms = t.elapsed().as_secs_f64() * 1e3;
    let mut report = Report::new("handles", &mesh);
    report.add("handles", sel.groups.len());
    report.add("blend", options.method.name());
    report.add("bind_ms", bind_ms);
    pose_and_finish(&d, &mesh, &motors, &a.out, report)
}

/// Pose, time, report and write, the preview coloured by displacement.
pub(crate) fn pose_and_finish(
    d: &dyn Deformer,
    mesh: &Mesh,
    motors: &[cga::ScaledMotor],
    out: &OutputArgs,
    mut report: Report,
) -> Result<()> {
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    let pose_ms = time_pose(d, motors, &mut posed).context("cannot pose")?;
    report.add("pose_ms", pose_ms);
    let moved: Vec<f64> = posed
        .iter()
        .zip(&mesh.positions)
        .map(|(a, b)| a.distance(*b))
        .collect();
    finish(mesh, posed, &moved, out, &mut report)
}

/// A straight chain of `n` joints from the centroid of `a` to the centroid of `b`.
pub fn straight_chain(mesh: &Mesh, a: &[u32], b: &[u32], n: usize) -> Vec<DVec3> {
    let centroid =
        |s: &[u32]| s.iter().map(|&v| mesh.positions[v as usize]).sum::<DVec3>() / s.len() as f64;
    let (p, q) = (centroid(a), centroid(b));
    (0..n)
        .map(|i| p.lerp(q, i as f64 / (n - 1) as f64))
        .collect()
}

pub fn fabrik(a: &FabrikArgs) -> Result<()> {
    let extra: Vec<&Path> = a.chain.iter().map(|p| p.as_path()).collect();
    let (mesh, sel) = read_inputs(&a.input, &extra, &a.out)?;
    let (first, last) = ends(&sel, &a.input.select)?;
    let joints: Vec<DVec3> = match &a.chain {
        Some(path) => {
            let text = read_text(path)?;
            let j: Vec<[f64; 3]> = serde_json::from_str(&text).with_context(|| {
                format!(
                    "{}: expected a JSON array of [x, y, z] joints",
                    path.display()
                )
            })?;
            j.into_iter().map(DVec3::from_array).collect()
        }
        None => {
            if a.joints < 2 {
                bail!("--joints must be at least 2");
            }
            let what = format!("a chain of {} joints", a.joints);
            crate::budget::check("--joints", &what, &[a.joints as u64, 64])?;
            straight_chain(&mesh, &first, &last, a.joints)
        }
    };
    let what = format!(
        "{} FABRIK iterations over {} joints",
        a.iterations,
        joints.len()
    );
    crate::budget::check(
        "--iterations",
        &what,
        &[a.iterations as u64, joints.len() as u64],
    )?;
    let t = Instant::now();
    let d = with_progress(
        "binding (harmonic field)",
        mesh.vertex_count(),
        a.out.quiet,
        || {
            ChainDeformer::bind(
                &mesh,
                &first,
                &last,
                &joints,
                a.controls,
                SplineOptions::default(),
            )
        },
    )
    .with_context(|| format!("{}: cannot bind", a.input.mesh.display()))?;
    let bind_ms = t.elapsed().as_secs_f64() * 1e3;
    let options = FabrikOptions {
        tolerance: a.tolerance,
        max_iterations: a.iterations,
    };
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    let t = Instant::now();
    let result = d.pose_to_target(DVec3::from_array(a.target), &options, &mut posed)?;
    let pose_ms = t.elapsed().as_secs_f64() * 1e3;
    let mut report = Report::new("fabrik", &mesh);
    report.add("joints", joints.len());
    report.add("controls", a.controls);
    report.add(
        "status",
        format!("{:?}", result.solution.status).to_lowercase(),
    );
    report.add("iterations", result.solution.iterations);
    report.add("distance", result.solution.distance);
    report.add("fit_residual", result.fit.max_residual);
    report.add("bind_ms", bind_ms);
    report.add("pose_ms", pose_ms);
    if result.solution.status == deform::FabrikStatus::Unreachable && !a.out.quiet && !a.out.json {
        eprintln!(
            "note: the target is out of reach; the chain is stretched towards it ({:.4} short)",
            result.solution.distance
        );
    }
    let lambda = d.spline().lambda().to_vec();
    finish(&mesh, posed, &lambda, &a.out, &mut report)
}
