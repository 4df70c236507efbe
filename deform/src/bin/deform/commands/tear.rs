//! `deform tear`: tear the skin with a scalpel given at successive time steps (the second
//! paper's Algorithm 2), the incision opened; the result stays skinned and animatable,
//! written as `.glb` or OBJ.

use crate::numbers::point;
use crate::report::Report;
use crate::shared_args::{OutputArgs, RigInput, ToolFrame};
use crate::surgery_io::{prepare, report_dropped, tool_overlay, write_one, Posed, Prepared};
use crate::timing::ms;
use anyhow::Result;
use clap::Args;
use deform::render::preview::{Look, TOOL_INK};
use deform::render::short_number;
use glam::DVec3;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct TearArgs {
    #[command(flatten)]
    pub rig: RigInput,
    /// The blade at one time step, AX,AY,AZ:BX,BY,BZ (from A into the skin towards B); at
    /// least two, in time order.
    #[arg(long = "scalpel", value_parser = parse_blade, allow_hyphen_values = true, required = true)]
    pub scalpel: Vec<(DVec3, DVec3)>,
    /// Pull the incision's lips apart by this much at its middle.
    #[arg(long, default_value_t = 0.0, value_parser = crate::numbers::non_negative)]
    pub open: f64,
    #[command(flatten)]
    pub frame: ToolFrame,
    #[command(flatten)]
    pub out: OutputArgs,
}

fn parse_blade(s: &str) -> Result<(DVec3, DVec3), String> {
    let (a, b) = s
        .split_once(':')
        .ok_or_else(|| format!("{s:?}: expected AX,AY,AZ:BX,BY,BZ"))?;
    Ok((point(a)?, point(b)?))
}

pub fn run(a: &TearArgs) -> Result<()> {
    use deform::surgery::{Scalpel, TearOptions};
    let Prepared {
        rig,
        posed,
        surgery,
        index_ms,
    } = prepare(&a.rig, &a.frame, &a.out)?;
    let blades: Vec<Scalpel> = a.scalpel.iter().map(|&(a, b)| Scalpel { a, b }).collect();
    let t = Instant::now();
    let options = TearOptions {
        open: a.open,
        ..TearOptions::default()
    };
    let r = surgery.tear(&blades, Posed::surgery_frame(&posed), &options)?;
    let tear_ms = ms(t);
    let mut report = Report::new("tear", &rig.mesh);
    report.add("index_ms", index_ms);
    report_dropped(&surgery, &mut report);
    report.add("tear_ms", tear_ms);
    report.add("steps", blades.len() - 1);
    report.add("incision_vertices", r.incision_vertex_count());
    report.add("new_vertices", r.new_vertices);
    report.add("duplicated", r.duplicated);
    report.add("changed_faces", r.changed_faces);
    report.add("boundary_loops", r.boundary_loops);
    let title = format!(
        "tear  {} steps  open {}  {} new vertices",
        blades.len() - 1,
        short_number(a.open),
        r.new_vertices
    );
    let mut look = Look::new(title, "new vertex");
    // The blade at each step, and its path.
    look.rest = tool_overlay(&posed, |o| {
        for s in &blades {
            o.line(s.a, s.b, TOOL_INK);
            o.dot(s.b, 3, TOOL_INK);
        }
        let tips: Vec<DVec3> = blades.iter().map(|s| s.b).collect();
        o.polyline(&tips, false, TOOL_INK);
    });
    let direction = blades[0].b - blades[0].a;
    write_one(
        &rig,
        Posed::space(&posed),
        &r.mesh,
        &r.origin,
        &a.out,
        look,
        direction,
        &mut report,
    )
}
