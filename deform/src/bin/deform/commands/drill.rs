//! `deform drill`: drill a hole with a finite cylinder (the second paper's Algorithm 3); the
//! result stays skinned and animatable, written as `.glb` or OBJ.

use crate::report::Report;
use crate::shared_args::{OutputArgs, RigInput, ToolFrame};
use crate::surgery_io::{prepare, report_dropped, tool_overlay, write_one, Posed, Prepared};
use crate::timing::ms;
use anyhow::Result;
use clap::Args;
use deform::render::preview::{Look, TOOL_INK};
use deform::render::short_number;
use deform::render::tools::circle;
use glam::DVec3;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct DrillArgs {
    #[command(flatten)]
    pub rig: RigInput,
    /// The drill's tip A as X,Y,Z.
    #[arg(long, value_parser = crate::numbers::point, allow_hyphen_values = true)]
    pub tip: DVec3,
    /// The drill's end B as X,Y,Z.
    #[arg(long, value_parser = crate::numbers::point, allow_hyphen_values = true)]
    pub end: DVec3,
    /// The drill's radius.
    #[arg(long, value_parser = crate::numbers::positive)]
    pub radius: f64,
    #[command(flatten)]
    pub frame: ToolFrame,
    #[command(flatten)]
    pub out: OutputArgs,
}

pub fn run(a: &DrillArgs) -> Result<()> {
    use deform::surgery::{Drill, DrillOptions};
    let Prepared {
        rig,
        posed,
        surgery,
        index_ms,
    } = prepare(&a.rig, &a.frame, &a.out)?;
    let d = Drill {
        tip: a.tip,
        end: a.end,
        radius: a.radius,
    };
    let t = Instant::now();
    let r = surgery.drill(&d, Posed::surgery_frame(&posed), &DrillOptions::default())?;
    let drill_ms = ms(t);
    let mut report = Report::new("drill", &rig.mesh);
    report.add("index_ms", index_ms);
    report_dropped(&surgery, &mut report);
    report.add("drill_ms", drill_ms);
    report.add("new_vertices", r.new_vertices);
    report.add("removed_faces", r.removed_faces);
    report.add("refined_faces", r.refined_faces);
    report.add("holes", r.holes);
    report.add("boundary_loops", r.boundary_loops);
    let title = format!(
        "drill  radius {}  {} holes  {} new vertices",
        short_number(a.radius),
        r.holes,
        r.new_vertices
    );
    let mut look = Look::new(title, "new vertex");
    // The drill's axis and its rims at tip and end.
    look.rest = tool_overlay(&posed, |o| {
        let axis = d.end - d.tip;
        o.line(d.tip, d.end, TOOL_INK);
        circle(o, d.tip, axis, d.radius, TOOL_INK);
        circle(o, d.end, axis, d.radius, TOOL_INK);
    });
    write_one(
        &rig,
        Posed::space(&posed),
        &r.mesh,
        &r.origin,
        &a.out,
        look,
        d.end - d.tip,
        &mut report,
    )
}
