//! `deform handles`: motor handles, one harmonic field and one motor per selection group:
//! read, bind, pose, write, report.

use crate::finish::pose_and_finish;
use crate::input_files::{read_mesh_input, read_text};
use crate::progress::with_progress;
use crate::report::Report;
use crate::shared_args::{BlendingArgs, MeshInput, OutputArgs};
use crate::timing::ms;
use anyhow::{Context, Result};
use clap::Args;
use deform::deformers::handles::HandleOptions;
use deform::input::parse_group_motors;
use deform::render::preview::{Look, POSED_INK, REST_INK, TOOL_INK};
use deform::render::tools::{centroid, moved};
use deform::MotorHandles;
use glam::DVec3;
use std::path::PathBuf;
use std::time::Instant;

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

pub fn run(a: &HandlesArgs) -> Result<()> {
    let (mesh, sel) = read_mesh_input(&a.input, &[a.motors.as_path()], &a.out)?;
    let name = a.motors.display().to_string();
    let motors = parse_group_motors(&read_text(&a.motors)?, &name, sel.groups.len())?;
    crate::budget::get().handle_groups("--select", sel.groups.len(), mesh.vertex_count())?;
    let options = HandleOptions {
        harmonic: a.blending.harmonic(),
        method: a.blending.blend,
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
    let bind_ms = ms(t);
    let mut report = Report::new("handles", &mesh);
    report.add("handles", sel.groups.len());
    report.add("blend", options.method.name());
    report.add("bind_ms", bind_ms);
    let title = format!(
        "handles  {}  {} groups",
        options.method.name(),
        sel.groups.len()
    );
    let mut look = Look::new(title, "displacement");
    // Each group's centre at rest, and where its motor takes it.
    let centres: Vec<DVec3> = sel
        .groups
        .iter()
        .map(|g| centroid(&mesh.positions, g))
        .collect();
    for (c, m) in centres.iter().zip(moved(&centres, &motors)) {
        look.rest.dot(*c, 4, REST_INK);
        look.posed.line(*c, m, TOOL_INK);
        look.posed.dot(m, 4, POSED_INK);
    }
    pose_and_finish(&d, &mesh, &motors, look, &a.out, report)
}
