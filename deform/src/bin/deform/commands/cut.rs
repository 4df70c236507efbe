//! `deform cut`: cut a rigged model by a plane (the second paper's Algorithm 1); both pieces
//! stay skinned and animatable, written as `.glb` (the rig, one primitive per piece) or OBJ
//! (the rest mesh).

use crate::report::Report;
use crate::shared_args::{OutputArgs, RigInput, ToolFrame};
use crate::surgery_io::{prepare, report_dropped, tool_overlay, write_result, Posed, Prepared};
use crate::timing::ms;
use anyhow::{Context, Result};
use clap::Args;
use deform::render::preview::{Look, TOOL_INK};
use deform::render::tools as overlays;
use deform::skinning::RigPart;
use deform::surgery::CutOptions;
use glam::DVec3;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct CutArgs {
    #[command(flatten)]
    pub rig: RigInput,
    /// The plane n.x = d as NX,NY,NZ,D (the normal need not be unit).
    #[arg(long, value_parser = crate::numbers::plane, allow_hyphen_values = true)]
    pub plane: [f64; 4],
    /// Close both pieces with triangulated caps.
    #[arg(long)]
    pub cap: bool,
    /// Snap fraction: vertices closer to the plane than this fraction of a crossing edge are
    /// treated as on it.
    #[arg(long, default_value_t = 0.02, value_parser = crate::numbers::non_negative)]
    pub snap: f64,
    #[command(flatten)]
    pub frame: ToolFrame,
    #[command(flatten)]
    pub out: OutputArgs,
}

pub fn run(a: &CutArgs) -> Result<()> {
    let [nx, ny, nz, d] = a.plane;
    let plane = cga::Plane::try_from_equation(DVec3::new(nx, ny, nz), d).context("--plane")?;
    let plane_d = plane.distance();
    let Prepared {
        rig,
        posed,
        surgery,
        index_ms,
    } = prepare(&a.rig, &a.frame, &a.out)?;
    let t = Instant::now();
    let options = CutOptions {
        snap: a.snap,
        cap: a.cap,
    };
    let cut = surgery.cut(&plane, Posed::surgery_frame(&posed), &options)?;
    let cut_ms = ms(t);
    let mut report = Report::new("cut", &rig.mesh);
    report.add("index_ms", index_ms);
    report_dropped(&surgery, &mut report);
    report.add("cut_ms", cut_ms);
    report.add("new_vertices", cut.new_vertices);
    report.add("split_faces", cut.split_faces);
    report.add("snapped_vertices", cut.snapped_vertices);
    for (k, p) in cut.pieces.iter().enumerate() {
        report.add(
            if k == 0 {
                "piece_positive"
            } else {
                "piece_negative"
            },
            serde_json::json!({
                "vertices": p.mesh.mesh.vertex_count(),
                "triangles": p.mesh.mesh.triangle_count(),
                "boundary_loops": p.boundary_loops,
                "cap_triangles": p.cap_triangles,
            }),
        );
    }
    let bounds = Posed::bounds(&posed, &rig);
    let spread = 0.04 * bounds.map_or(1.0, |b| b.diagonal());
    let n = plane.normal();
    // Each piece's surface, then its caps (their own vertices: planar UVs, flat normals).
    let split: Vec<_> = cut.pieces.iter().map(|p| p.surface_and_caps()).collect();
    let mut parts = Vec::new();
    let mut piece_of = Vec::new();
    for (k, (surface, caps)) in split.iter().enumerate() {
        parts.push(surface.part());
        piece_of.push(k);
        if let Some(c) = caps {
            parts.push(RigPart {
                cap: Some(n),
                ..c.part()
            });
            piece_of.push(k);
        }
    }
    let title = format!(
        "cut{}  {} new vertices  {} pieces  (pieces pulled apart)",
        if a.cap { "  capped" } else { "" },
        cut.new_vertices,
        cut.pieces.len()
    );
    let mut look = Look::new(title, "piece");
    // The plane, on the model's centre, in both views.
    let tool = tool_overlay(&posed, |o| {
        let b = bounds;
        let (c, size) = b.map_or((DVec3::ZERO, 1.0), |b| (b.center(), 0.8 * b.diagonal()));
        overlays::plane(o, n, plane_d, c, size, TOOL_INK);
    });
    look.rest = tool.clone();
    look.posed = tool;
    write_result(
        &rig,
        &parts,
        Posed::space(&posed),
        &a.out,
        |k| {
            if piece_of[k] == 0 {
                n * spread
            } else {
                -n * spread
            }
        },
        None,
        None,
        look,
        &mut report,
    )
}
