//! `deform cut`, `deform tear`, `deform drill`: surgery on a rigged model that stays
//! animatable; the result is written as `.glb` (the rig with the new mesh, its skin and
//! animations) or OBJ (the rest mesh).

use crate::args::OutputArgs;
use crate::commands::Report;
use crate::output::{check_outputs, write_obj, write_png};
use crate::preview;
use crate::skin_cmd::RigInput;
use anyhow::{bail, Context, Result};
use clap::Args;
use deform::skinning::{GlbOptions, Rig, Skinning};
use deform::surgery::{CutOptions, Frame, Surgery};
use deform::{BlendMethod, Deformer, Mesh};
use glam::{DAffine3, DVec3};
use std::time::Instant;

/// Where the tool's coordinates are given.
#[derive(Args, Debug)]
pub struct ToolFrame {
    /// Give the tool in the posed world space at this time (of --animation, default the
    /// first) instead of the rest-pose mesh space.
    #[arg(long, value_parser = crate::numbers::finite, allow_hyphen_values = true)]
    pub time: Option<f64>,
    /// The animation for --time, by name or index.
    #[arg(long, requires = "time")]
    pub animation: Option<String>,
}

#[derive(Args, Debug)]
pub struct CutArgs {
    #[command(flatten)]
    pub rig: RigInput,
    /// The plane n.x = d as NX,NY,NZ,D (the normal need not be unit).
    #[arg(long, value_parser = parse_plane, allow_hyphen_values = true)]
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

/// `X,Y,Z` as a vector.
pub fn parse_vec3(s: &str) -> Result<DVec3, String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("{s:?}: expected X,Y,Z"))?;
    match v[..] {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok(DVec3::new(x, y, z)),
        _ => Err(format!("{s:?}: expected three finite numbers X,Y,Z")),
    }
}

fn parse_plane(s: &str) -> Result<[f64; 4], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("{s:?}: expected NX,NY,NZ,D"))?;
    match v[..] {
        [a, b, c, d] if v.iter().all(|x| x.is_finite()) => Ok([a, b, c, d]),
        _ => Err(format!("{s:?}: expected four finite numbers NX,NY,NZ,D")),
    }
}

/// The posed positions and skin matrices of the frame the tool is given in (none: rest).
pub struct Posed {
    pub positions: Vec<DVec3>,
    pub skin: Vec<DAffine3>,
}

impl Posed {
    pub fn read(rig: &Rig, f: &ToolFrame) -> Result<Option<Posed>> {
        let Some(t) = f.time else { return Ok(None) };
        let animation = match &f.animation {
            Some(a) => Some(rig.animation_index(a)?),
            None => (!rig.animations.is_empty()).then_some(0),
        };
        let pose = rig.pose(animation, t, &[])?;
        let lbs = Skinning::bind(rig, BlendMethod::Matrix)?;
        let mut positions = vec![DVec3::ZERO; rig.mesh.vertex_count()];
        lbs.pose(pose.skin_motors()?, &mut positions)?;
        Ok(Some(Posed {
            positions,
            skin: pose.skin_matrices.clone(),
        }))
    }

    pub fn frame(p: &Option<Posed>) -> Frame<'_> {
        match p {
            None => Frame::Rest,
            Some(p) => Frame::Posed {
                positions: &p.positions,
                skin: &p.skin,
            },
        }
    }
}

/// Write the new rig (`.glb`) or its rest mesh (OBJ), and a preview of the parts moved by
/// `away(part)`, coloured by part, or by `marks` (one value per vertex of a single part).
pub fn write_result(
    rig: &Rig,
    parts: &[(&Mesh, &deform::skinning::Influences)],
    out: &OutputArgs,
    away: impl Fn(usize) -> DVec3,
    marks: Option<Vec<f64>>,
    report: &mut Report,
) -> Result<()> {
    let result = rig
        .with_parts(parts)
        .context("the result is not a valid rig")?;
    let glb = out
        .output
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("glb"));
    if glb {
        crate::output::write_glb(&out.output, &result, &GlbOptions::default())?;
    } else {
        write_obj(&out.output, &result.mesh)?;
    }
    report.add("output", out.output.display().to_string());
    if let Some(png) = &out.png {
        let mut shown = result.mesh.clone();
        let mut part_of = vec![0.0; shown.vertex_count()];
        for (k, p) in result.primitives.iter().enumerate() {
            let shift = away(k);
            let r = p.vertex_offset..p.vertex_offset + p.vertex_count;
            shown.positions[r.clone()]
                .iter_mut()
                .for_each(|x| *x += shift);
            part_of[r].iter_mut().for_each(|x| *x = k as f64);
        }
        let scalar = marks.unwrap_or(part_of);
        let image = preview::before_after(&rig.mesh, &shown, &scalar, 30.0, 50.0)?;
        write_png(png, &image)?;
        report.add("png", png.display().to_string());
    }
    report.print(out);
    Ok(())
}

/// What every surgery command reads first: the rig (refusing outputs that are inputs), the
/// posed frame of --time, the bound surgery and the time its index took.
struct Prepared {
    rig: Rig,
    posed: Option<Posed>,
    surgery: Surgery,
    index_ms: f64,
}

fn prepare(rig: &RigInput, frame: &ToolFrame, out: &OutputArgs) -> Result<Prepared> {
    let mut outputs = vec![out.output.as_path()];
    outputs.extend(out.png.as_deref());
    check_outputs(&rig.paths(), &outputs)?;
    crate::output::check_formats(out, &["obj", "glb"])?;
    let rig = rig.read()?;
    let posed = Posed::read(&rig, frame)?;
    let t = Instant::now();
    let surgery = Surgery::new(&rig.mesh, &rig.influences)?;
    let index_ms = t.elapsed().as_secs_f64() * 1e3;
    Ok(Prepared {
        rig,
        posed,
        surgery,
        index_ms,
    })
}

/// [`write_result`] for a tool with one result mesh, its new vertices marked in the preview.
fn write_one(
    rig: &Rig,
    mesh: &deform::surgery::SkinnedMesh,
    origin: &[deform::surgery::VertexOrigin],
    out: &OutputArgs,
    report: &mut Report,
) -> Result<()> {
    let marks = origin
        .iter()
        .map(|o| if o.is_input() { 0.0 } else { 1.0 })
        .collect();
    write_result(
        rig,
        &[(&mesh.mesh, &mesh.influences)],
        out,
        |_| DVec3::ZERO,
        Some(marks),
        report,
    )
}

pub fn cut(a: &CutArgs) -> Result<()> {
    let [nx, ny, nz, d] = a.plane;
    let normal = DVec3::new(nx, ny, nz);
    let len = normal.length();
    if len.is_nan() || len <= 0.0 {
        bail!("--plane: the normal is zero");
    }
    let plane = cga::Plane::from_normal_distance(normal / len, d / len);
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
    let cut = surgery.cut(&plane, Posed::frame(&posed), &options)?;
    let cut_ms = t.elapsed().as_secs_f64() * 1e3;
    let mut report = Report::new("cut", &rig.mesh);
    report.add("index_ms", index_ms);
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
    let spread = 0.04 * rig.mesh.bounding_box().map_or(1.0, |b| b.diagonal());
    let n = plane.normal();
    let parts: Vec<_> = cut
        .pieces
        .iter()
        .map(|p| (&p.mesh.mesh, &p.mesh.influences))
        .collect();
    write_result(
        &rig,
        &parts,
        &a.out,
        |k| if k == 0 { n * spread } else { -n * spread },
        None,
        &mut report,
    )
}

#[derive(Args, Debug)]
pub struct DrillArgs {
    #[command(flatten)]
    pub rig: RigInput,
    /// The drill's tip A as X,Y,Z.
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true)]
    pub tip: DVec3,
    /// The drill's end B as X,Y,Z.
    #[arg(long, value_parser = parse_vec3, allow_hyphen_values = true)]
    pub end: DVec3,
    /// The drill's radius.
    #[arg(long, value_parser = crate::numbers::positive)]
    pub radius: f64,
    #[command(flatten)]
    pub frame: ToolFrame,
    #[command(flatten)]
    pub out: OutputArgs,
}

pub fn drill(a: &DrillArgs) -> Result<()> {
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
    let r = surgery.drill(&d, Posed::frame(&posed), &DrillOptions::default())?;
    let drill_ms = t.elapsed().as_secs_f64() * 1e3;
    let mut report = Report::new("drill", &rig.mesh);
    report.add("index_ms", index_ms);
    report.add("drill_ms", drill_ms);
    report.add("new_vertices", r.new_vertices);
    report.add("removed_faces", r.removed_faces);
    report.add("refined_faces", r.refined_faces);
    report.add("holes", r.holes);
    report.add("boundary_loops", r.boundary_loops);
    write_one(&rig, &r.mesh, &r.origin, &a.out, &mut report)
}

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
    Ok((parse_vec3(a)?, parse_vec3(b)?))
}

pub fn tear(a: &TearArgs) -> Result<()> {
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
    let r = surgery.tear(&blades, Posed::frame(&posed), &options)?;
    let tear_ms = t.elapsed().as_secs_f64() * 1e3;
    let mut report = Report::new("tear", &rig.mesh);
    report.add("index_ms", index_ms);
    report.add("tear_ms", tear_ms);
    report.add("steps", blades.len() - 1);
    report.add("incision_vertices", r.incision.len());
    report.add("new_vertices", r.new_vertices);
    report.add("duplicated", r.duplicated);
    report.add("changed_faces", r.changed_faces);
    report.add("boundary_loops", r.boundary_loops);
    write_one(&rig, &r.mesh, &r.origin, &a.out, &mut report)
}
