//! `deform fabrik`: inverse kinematics driving a spline. A chain of joints is solved by
//! FABRIK for its end effector to reach a target, its joint frames are fitted by a cubic
//! B-spline of control motors, which deforms the mesh: read, bind, pose, write, report.

use crate::finish::finish;
use crate::input_files::{read_mesh_input, read_text};
use crate::progress::with_progress;
use crate::report::Report;
use crate::shared_args::{MeshInput, OutputArgs};
use crate::timing::ms;
use anyhow::{bail, Context, Result};
use clap::Args;
use deform::deformers::fabrik::straight_chain;
use deform::deformers::fabrik::FabrikOptions;
use deform::deformers::spline::SplineOptions;
use deform::render::preview::{Look, POSED_INK, REST_INK, TOOL_INK};
use deform::ChainDeformer;
use glam::DVec3;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(Args, Debug)]
pub struct FabrikArgs {
    /// (Group 0 of the selection is the chain's root end, lambda = 0; the highest group its
    /// tip end, lambda = 1.)
    #[command(flatten)]
    pub input: MeshInput,
    /// Where the end effector should go: X,Y,Z.
    #[arg(long, value_parser = crate::numbers::xyz, allow_hyphen_values = true)]
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

pub fn run(a: &FabrikArgs) -> Result<()> {
    let extra: Vec<&Path> = a.chain.iter().map(|p| p.as_path()).collect();
    let (mesh, sel) = read_mesh_input(&a.input, &extra, &a.out)?;
    let (first, last) = sel.ends(&a.input.select.display().to_string())?;
    let (first, last) = (first.to_vec(), last.to_vec());
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
            crate::budget::get().check("--joints", &what, &[a.joints as u64, 64])?;
            straight_chain(&mesh, &first, &last, a.joints)
        }
    };
    let what = format!(
        "{} FABRIK iterations over {} joints",
        a.iterations,
        joints.len()
    );
    crate::budget::get().check(
        "--iterations",
        &what,
        &[a.iterations as u64, joints.len() as u64],
    )?;
    // Each pose fits the controls to the joints by dense least squares: joints x controls^2.
    let what = format!(
        "a fit of {} control motors to {} joints",
        a.controls,
        joints.len()
    );
    crate::budget::get().check(
        "--controls",
        &what,
        &[joints.len() as u64, a.controls as u64, a.controls as u64],
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
    let bind_ms = ms(t);
    let options = FabrikOptions {
        tolerance: a.tolerance,
        max_iterations: a.iterations,
    };
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    let t = Instant::now();
    let result = d.pose_to_target(DVec3::from_array(a.target), &options, &mut posed)?;
    let pose_ms = ms(t);
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
    if result.solution.status == deform::deformers::fabrik::FabrikStatus::Unreachable
        && !a.out.quiet
        && !a.out.json
    {
        eprintln!(
            "note: the target is out of reach; the chain is stretched towards it ({} short)",
            deform::render::short_number(result.solution.distance)
        );
    }
    let lambda = d.spline().lambda().to_vec();
    let title = format!(
        "fabrik  {} joints  {} controls  {} in {} iter",
        joints.len(),
        a.controls,
        format!("{:?}", result.solution.status).to_lowercase(),
        result.solution.iterations
    );
    let mut look = Look::new(title, "lambda");
    // The chain at rest and solved, and the target.
    let target = DVec3::from_array(a.target);
    look.rest.polyline(&joints, false, REST_INK);
    look.posed
        .polyline(&result.solution.joints, false, POSED_INK);
    for &j in &joints {
        look.rest.dot(j, 3, REST_INK);
    }
    for &j in &result.solution.joints {
        look.posed.dot(j, 3, POSED_INK);
    }
    look.rest.dot(target, 5, TOOL_INK);
    look.posed.dot(target, 5, TOOL_INK);
    finish(&mesh, posed, &lambda, look, &a.out, &mut report)
}
