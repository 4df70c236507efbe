//! `deform spline`: spline-aligned deformation of a mesh between its first and last
//! selection groups by key motors: read, bind, pose, write, report.

use crate::finish::finish;
use crate::input_files::{read_mesh_input, read_text};
use crate::progress::with_progress;
use crate::report::Report;
use crate::shared_args::{BlendingArgs, MeshInput, OutputArgs};
use crate::timing::ms;
use anyhow::{bail, Context, Result};
use clap::{Args, ValueEnum};
use deform::deformers::spline::{SplineOptions, WeightScheme};
use deform::input::parse_key_list;
use deform::render::preview::{Look, POSED_INK, REST_INK};
use deform::render::tools::{centroid, spine};
use deform::{Poser, SplineDeformer};
use glam::DVec3;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum SchemeArg {
    Linear,
    Quadratic,
    Bezier,
    Bspline,
}

impl SchemeArg {
    fn scheme(self) -> WeightScheme {
        match self {
            SchemeArg::Linear => WeightScheme::Linear,
            SchemeArg::Quadratic => WeightScheme::Quadratic,
            SchemeArg::Bezier => WeightScheme::Bezier,
            SchemeArg::Bspline => WeightScheme::BSpline,
        }
    }
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

pub fn run(a: &SplineArgs) -> Result<()> {
    let mut extra = vec![a.keys.as_path()];
    if let Some(r) = &a.rest_keys {
        extra.push(r.as_path());
    }
    let (mesh, sel) = read_mesh_input(&a.input, &extra, &a.out)?;
    let (first, last) = sel.ends(&a.input.select.display().to_string())?;
    let (first, last) = (first.to_vec(), last.to_vec());
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
        scheme: a.scheme.scheme(),
        harmonic: a.blending.harmonic(),
        method: a.blending.blend,
    };
    crate::budget::get().spline_keys("--keys", keys.len(), options.scheme, mesh.vertex_count())?;
    let t = Instant::now();
    let d = with_progress(
        "binding (harmonic field)",
        mesh.vertex_count(),
        a.out.quiet,
        || SplineDeformer::bind(&mesh, &first, &last, &rest, options),
    )
    .with_context(|| format!("{}: cannot bind", a.input.mesh.display()))?;
    let bind_ms = ms(t);
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    let pose_ms = Poser::new(&d)
        .best_time_ms(&keys, &mut posed, 5)
        .with_context(|| format!("{name}: cannot pose"))?;
    let mut report = Report::new("spline", &mesh);
    report.add("scheme", options.scheme.name());
    report.add("blend", options.method.name());
    report.add("keys", keys.len());
    report.add("bind_ms", bind_ms);
    report.add("pose_ms", pose_ms);
    let lambda = d.lambda().to_vec();
    let title = format!(
        "spline  {}  {}  {} keys",
        options.scheme.name(),
        options.method.name(),
        keys.len()
    );
    let mut look = Look::new(title, "lambda");
    // The spine (mean position along lambda) and the end groups, before and after.
    let rest_spine = spine(&mesh.positions, &lambda, 24);
    look.rest.polyline(&rest_spine, false, REST_INK);
    look.posed
        .polyline(&spine(&posed, &lambda, 24), false, POSED_INK);
    for g in [&first, &last] {
        look.rest.dot(centroid(&mesh.positions, g), 4, REST_INK);
        look.posed.dot(centroid(&posed, g), 4, POSED_INK);
    }
    finish(&mesh, posed, &lambda, look, &a.out, &mut report)
}
