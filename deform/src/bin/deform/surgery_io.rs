//! What `cut`, `drill` and `tear` share: reading the rig for surgery (refusing outputs that
//! are inputs), posing it in the frame the tool is given in, and writing what it becomes:
//! the new rig as `.glb` (its mesh, skin and animations) or its rest mesh as OBJ or PLY, and a
//! preview.

use crate::input_files::read_rig;
use crate::output_files::{
    check_formats, check_outputs, write_glb, write_png, write_rig_mesh, MESH_FORMATS,
};
use crate::report::Report;
use crate::shared_args::{OutputArgs, RigInput, ToolFrame as ToolFrameArgs};
use crate::timing::ms;
use anyhow::{Context, Result};
pub use deform::methods::frame::{
    parts_preview, pose_time, PartsView, ToolFrame as Posed, ToolSpace,
};
use deform::render::preview::Look;
use deform::render::Overlay;
use deform::skinning::{GlbOptions, Rig, RigPart};
use deform::surgery::Surgery;
use glam::DVec3;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The frame a tool is given in, by the library's convention
/// ([`deform::methods::frame::pose_time`]); `None` for `--mesh-space`.
pub fn tool_frame(rig: &Rig, f: &ToolFrameArgs) -> Result<Option<Posed>> {
    if f.mesh_space {
        return Ok(None);
    }
    // --animation alone is its time 0 (a posed frame), as for `skin`.
    let time = f.time.or(f.animation.as_ref().map(|_| 0.0));
    let pose = pose_time(rig, f.animation.as_deref(), time)?;
    Ok(Some(Posed::new(rig, pose)?))
}

/// Write the new rig (`.glb`) or its rest mesh (OBJ or PLY), and a preview of the parts moved
/// by `away(part)`, coloured by part, or by `marks` (one value per vertex of the parts, in
/// order: the new vertices), the marked vertices in focus along `direction` when given, with
/// `look`'s title and overlays (given in the rig's mesh space, drawn in world space).
#[allow(clippy::too_many_arguments)]
pub fn write_result(
    rig: &Rig,
    parts: &[RigPart],
    space: ToolSpace,
    out: &OutputArgs,
    away: impl Fn(usize) -> DVec3,
    marks: Option<Vec<f64>>,
    focus: Option<DVec3>,
    look: Look,
    report: &mut Report,
) -> Result<()> {
    let (result, trace) = rig
        .with_parts_traced(parts)
        .context("the result is not a valid rig")?;
    let glb = out
        .output
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("glb"));
    if glb {
        write_glb(&out.output, &result, &GlbOptions::default())?;
    } else {
        write_rig_mesh(&out.output, &result.mesh, &result.look)?;
    }
    report.add("output", out.output.display().to_string());
    if let Some(png) = &out.png {
        let shown = PartsView {
            space,
            marks,
            focus,
            view: out.view(),
        };
        write_png(
            png,
            &parts_preview(rig, &result, &trace, &away, shown, look)?,
        )?;
        report.add("png", png.display().to_string());
    }
    report.print(out);
    Ok(())
}

/// A note for the triangles the surgery left out (a repeated corner: no surface).
pub fn report_dropped(surgery: &Surgery, report: &mut Report) {
    let n = surgery.dropped_triangles();
    if n > 0 {
        report.add(
            "note",
            format!("{n} triangle(s) with a repeated corner (no surface) left out"),
        );
    }
}

/// What every surgery command reads first: the rig (refusing outputs that are inputs), the
/// posed frame of --time, the bound surgery and the time its index took.
pub struct Prepared {
    pub rig: Rig,
    pub posed: Option<Posed>,
    pub surgery: Surgery,
    pub index_ms: f64,
}

pub fn prepare(rig: &RigInput, frame: &ToolFrameArgs, out: &OutputArgs) -> Result<Prepared> {
    let inputs = rig.paths();
    let inputs: Vec<&Path> = inputs.iter().map(PathBuf::as_path).collect();
    check_outputs(&inputs, &out.paths())?;
    check_formats(out, &MESH_FORMATS)?;
    let rig = read_rig(rig)?;
    let posed = tool_frame(&rig, frame)?;
    let t = Instant::now();
    let surgery = Surgery::new(&rig.mesh, &rig.influences)?;
    let index_ms = ms(t);
    Ok(Prepared {
        rig,
        posed,
        surgery,
        index_ms,
    })
}

/// [`write_result`] for a tool with one result mesh, its new vertices marked in the preview
/// and shown zoomed in, seen along `direction` (mesh space).
#[allow(clippy::too_many_arguments)]
pub fn write_one(
    rig: &Rig,
    space: ToolSpace,
    mesh: &deform::surgery::SkinnedMesh,
    origin: &[deform::surgery::VertexOrigin],
    out: &OutputArgs,
    look: Look,
    direction: DVec3,
    report: &mut Report,
) -> Result<()> {
    let marks: Vec<f64> = origin
        .iter()
        .map(|o| if o.is_input() { 0.0 } else { 1.0 })
        .collect();
    write_result(
        rig,
        &[mesh.part()],
        space,
        out,
        |_| DVec3::ZERO,
        Some(marks),
        Some(direction),
        look,
        report,
    )
}

/// The tool's overlay: drawn when it is given at the bind pose (in the world space the
/// preview shows, or in the rest mesh's space, placed), left out when it is given in a
/// posed frame.
pub fn tool_overlay(posed: &Option<Posed>, draw: impl FnOnce(&mut Overlay)) -> Overlay {
    let mut o = Overlay::new(2);
    if Posed::space(posed) != ToolSpace::Posed {
        draw(&mut o);
    }
    o
}
