//! `deform arap`: as-rigid-as-possible deformation (first paper, section VII). Selection
//! groups with a motor in the motors file are handles moved rigidly by it; every other
//! selected group stays fixed; iterations start from the rest pose and the energy is printed
//! after each one.

use crate::finish::{displacement, finish};
use crate::input_files::{read_mesh_input, read_text};
use crate::progress::with_progress;
use crate::report::Report;
use crate::shared_args::{named, MeshInput, OutputArgs};
use crate::timing::ms;
use anyhow::{bail, Context, Result};
use clap::Args;
use deform::deformers::arap::{Arap, ArapEnergy, ArapOptions, LocalStep, Stop, Targets};
use deform::input::parse_group_motors;
use deform::methods::kinds::arap::{ENERGY, ITERATIONS, LOCAL_STEP};
use deform::render::preview::{Look, POSED_INK, REST_INK, TOOL_INK};
use deform::render::tools::centroid;
use std::path::PathBuf;
use std::time::Instant;

/// Iteration cap of `--tolerance`.
const MAX_ITERATIONS: usize = 1000;

#[derive(Args, Debug)]
pub struct ArapArgs {
    /// (Selection groups: libigl convention, -1 free, k = group k.)
    #[command(flatten)]
    pub input: MeshInput,
    /// Per-group motors: JSON {"k": motor, "*": motor for every group not listed}. Groups
    /// with a motor are handles moved rigidly by it; the other groups stay fixed.
    #[arg(long)]
    pub motors: PathBuf,
    #[arg(long = ENERGY.name, help = ENERGY.help,
          value_parser = named::<ArapEnergy>(), default_value = "spokes-and-rims")]
    pub energy: ArapEnergy,
    /// Iterations from the rest pose (10 unless --tolerance is given).
    #[arg(long = ITERATIONS.name, conflicts_with = "tolerance")]
    pub iterations: Option<usize>,
    /// Iterate until the energy's relative change is at most this (at most 1000 iterations).
    #[arg(long, value_parser = crate::numbers::non_negative)]
    pub tolerance: Option<f64>,
    #[arg(long = LOCAL_STEP.name, help = LOCAL_STEP.help,
          value_parser = named::<LocalStep>(), default_value = "rotor")]
    pub local_step: LocalStep,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The groups the motors file names (all of them when it has `"*"`).
fn moved_groups(text: &str, name: &str, groups: usize) -> Result<Vec<bool>> {
    let object: serde_json::Map<String, serde_json::Value> = serde_json::from_str(text)
        .with_context(|| format!("{name}: expected an object from group numbers to motors"))?;
    if object.contains_key("*") {
        return Ok(vec![true; groups]);
    }
    let mut moved = vec![false; groups];
    for key in object.keys() {
        // parse_group_motors has checked every key.
        if let Ok(g) = key.parse::<usize>() {
            if g < groups {
                moved[g] = true;
            }
        }
    }
    Ok(moved)
}

pub fn run(a: &ArapArgs) -> Result<()> {
    let (mesh, sel) = read_mesh_input(&a.input, &[a.motors.as_path()], &a.out)?;
    let name = a.motors.display().to_string();
    let text = read_text(&a.motors)?;
    let motors = parse_group_motors(&text, &name, sel.groups.len())?;
    let moved = moved_groups(&text, &name, sel.groups.len())?;
    let stop = match (a.iterations, a.tolerance) {
        (_, Some(t)) if !(t.is_finite() && t >= 0.0) => {
            bail!("--tolerance must be a finite number >= 0, got {t}")
        }
        (_, Some(t)) => Stop::RelativeChange {
            tolerance: t,
            max_iterations: MAX_ITERATIONS,
        },
        (Some(0), None) => bail!("--iterations must be at least 1"),
        (Some(n), None) => {
            crate::budget::get().iterations("--iterations", n, mesh.vertex_count())?;
            Stop::Iterations(n)
        }
        (None, None) => Stop::Iterations(10),
    };
    let mut fixed = Vec::new();
    let mut handles: Vec<&[u32]> = Vec::new();
    let mut keys = Vec::new();
    for (g, vertices) in sel.groups.iter().enumerate() {
        if moved[g] {
            handles.push(vertices);
            keys.push(motors[g]);
        } else {
            fixed.extend_from_slice(vertices);
        }
    }
    let options = ArapOptions {
        energy: a.energy,
        local_step: a.local_step,
        ..ArapOptions::default()
    };
    let t = Instant::now();
    let arap = with_progress(
        "binding (ARAP system)",
        mesh.vertex_count(),
        a.out.quiet,
        || Arap::bind(&mesh, &fixed, &handles, options),
    )
    .with_context(|| format!("{}: cannot bind", a.input.mesh.display()))?;
    let bind_ms = ms(t);
    let mut posed = mesh.positions.clone();
    let chatty = !a.out.quiet && !a.out.json;
    let mut energies = Vec::new();
    let mut scratch = arap
        .scratch()
        .with_context(|| format!("{name}: cannot pose"))?;
    let t = Instant::now();
    let converged = arap
        .pose_using(
            &Targets::Motors(&keys),
            stop,
            &mut scratch,
            &mut posed,
            |k, e| {
                if chatty {
                    println!("iteration {k:>4}: energy {e:.9e}");
                }
                energies.push(e);
            },
        )
        .with_context(|| format!("{name}: cannot pose"))?;
    if let Some((k, e)) = energies.iter().enumerate().find(|(_, e)| !e.is_finite()) {
        bail!(
            "{name}: the energy of iteration {} is {e}: the motors move the handles too far for \
             double precision (nothing written)",
            k + 1
        );
    }
    let pose_ms = ms(t);
    let mut report = Report::new("arap", &mesh);
    report.add("energy_kind", options.energy.name());
    report.add("local_step", options.local_step.name());
    report.add("fixed", fixed.len());
    report.add("handles", handles.len());
    report.add("iterations", energies.len());
    if let Stop::RelativeChange { .. } = stop {
        report.add("converged", converged);
    }
    if let Some(e) = energies.last() {
        report.add("energy", *e);
    }
    if a.out.json {
        report.add("energies", energies.clone());
    }
    report.add("bind_ms", bind_ms);
    report.add("pose_ms", pose_ms);
    let title = format!(
        "arap  {}  {}  {} iter",
        options.energy.name(),
        options.local_step.name(),
        energies.len()
    );
    let mut look = Look::new(title, "displacement");
    // Fixed groups stay; handle groups move by their motors.
    for (g, vertices) in sel.groups.iter().enumerate() {
        let c = centroid(&mesh.positions, vertices);
        if moved[g] {
            look.rest.dot(c, 4, POSED_INK);
            let m = motors[g].transform_point(c);
            look.posed.line(c, m, TOOL_INK);
            look.posed.dot(m, 4, POSED_INK);
        } else {
            look.rest.dot(c, 4, REST_INK);
            look.posed.dot(c, 4, REST_INK);
        }
    }
    let shift = displacement(&mesh, &posed);
    finish(&mesh, posed, &shift, look, &a.out, &mut report)
}
