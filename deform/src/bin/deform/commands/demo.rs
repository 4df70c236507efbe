//! `deform demo`: every method on procedural meshes (no files needed). Writes one OBJ and one
//! PNG per scene and a contact sheet of them all, and prints a table of bind and pose times.

mod lattice;
mod scene;
use scene::DemoScene;
mod surgery;

use crate::finish::displacement;
use crate::output_files::{write_mesh, write_png};
use crate::spline_ends::straight_chain;
use crate::timing::{ms, time_pose};
use anyhow::{Context, Result};
use cga::{Motor, ScaledMotor};
use clap::Args;
use deform::deformers::arap::{Arap, ArapOptions, Stop, Targets};
use deform::deformers::fabrik::FabrikOptions;
use deform::deformers::handles::HandleOptions;
use deform::deformers::spline::{SplineOptions, WeightScheme};
use deform::mesh::shapes::{tube, tube_ring};
use deform::methods::scenes::{beam_with_ends, sphere_with_caps};
use deform::render::preview::{self, Look, POSED_INK, REST_INK, TOOL_INK};
use deform::render::tools::{centroid, spine};
use deform::{BlendMethod, ChainDeformer, Mesh, MotorHandles, SplineDeformer};
use glam::{DQuat, DVec3};
use std::f64::consts::PI;
use std::path::PathBuf;
use std::time::Instant;

const LENGTH: f64 = 10.0;
const SIDES: usize = 4;
const RINGS: usize = 81;

#[derive(Args, Debug)]
pub struct DemoArgs {
    /// Where the OBJ files and PNG previews go.
    #[arg(long, default_value = "deform-demo")]
    pub out: PathBuf,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
    /// Print the table as JSON.
    #[arg(long)]
    pub json: bool,
}

/// One scene's result.
#[derive(Clone)]
struct Row {
    name: &'static str,
    method: String,
    vertices: usize,
    bind_ms: f64,
    pose_ms: f64,
}

fn rigid(q: DQuat, t: DVec3) -> ScaledMotor {
    ScaledMotor::from(Motor::from_rotation_translation(q, t))
}

/// The motor `x -> c + s R (x - c) + t`.
fn about(center: DVec3, s: f64, q: DQuat, t: DVec3) -> ScaledMotor {
    ScaledMotor::from_scale_rotation_translation(s, q, center - s * (q * center) + t)
}

/// A spline scene on the square bar.
struct SplineScene {
    name: &'static str,
    scheme: WeightScheme,
    method: BlendMethod,
    rest: Vec<ScaledMotor>,
    keys: Vec<ScaledMotor>,
}

fn spline_keys() -> Vec<SplineScene> {
    let theta = PI / 2.0;
    let r = LENGTH / theta;
    let bend = about(
        DVec3::new(0.0, r, 0.0),
        1.0,
        DQuat::from_rotation_z(theta),
        DVec3::ZERO,
    );
    let half_turn = rigid(DQuat::from_rotation_x(PI), DVec3::ZERO);
    let end = DVec3::new(LENGTH, 0.0, 0.0);
    let along = |f: f64| rigid(DQuat::IDENTITY, end * f);
    let up = |y: f64| rigid(DQuat::IDENTITY, DVec3::new(0.0, y, 0.0));
    vec![
        SplineScene {
            name: "bend-linear",
            scheme: WeightScheme::Linear,
            method: BlendMethod::MotorLog,
            rest: vec![ScaledMotor::IDENTITY, along(1.0)],
            keys: vec![ScaledMotor::IDENTITY, bend],
        },
        SplineScene {
            name: "twist-motor",
            scheme: WeightScheme::Linear,
            method: BlendMethod::MotorLog,
            rest: vec![ScaledMotor::IDENTITY; 2],
            keys: vec![ScaledMotor::IDENTITY, half_turn],
        },
        SplineScene {
            name: "twist-matrix",
            scheme: WeightScheme::Linear,
            method: BlendMethod::Matrix,
            rest: vec![ScaledMotor::IDENTITY; 2],
            keys: vec![ScaledMotor::IDENTITY, half_turn],
        },
        SplineScene {
            name: "stretch-quadratic",
            scheme: WeightScheme::Quadratic,
            method: BlendMethod::MotorLog,
            rest: vec![ScaledMotor::IDENTITY; 3],
            keys: vec![
                ScaledMotor::IDENTITY,
                up(2.0),
                about(
                    end,
                    1.8,
                    DQuat::from_rotation_z(-0.5),
                    DVec3::new(4.0, 0.0, 0.0),
                ),
            ],
        },
        SplineScene {
            name: "wave-bezier",
            scheme: WeightScheme::Bezier,
            method: BlendMethod::MotorLog,
            rest: vec![ScaledMotor::IDENTITY; 4],
            keys: vec![
                ScaledMotor::IDENTITY,
                up(5.0),
                up(-5.0),
                rigid(DQuat::from_rotation_x(PI / 2.0), DVec3::ZERO),
            ],
        },
        SplineScene {
            name: "snake-bspline",
            scheme: WeightScheme::BSpline,
            method: BlendMethod::MotorLog,
            rest: (0..6).map(|j| along(j as f64 / 5.0)).collect(),
            keys: (0..6)
                .map(|j| {
                    let a = if j % 2 == 0 { 0.6 } else { -0.6 };
                    let p = end * (j as f64 / 5.0);
                    about(p, 1.0, DQuat::from_rotation_z(a), DVec3::ZERO) * along(j as f64 / 5.0)
                })
                .collect(),
        },
    ]
}

pub fn run(a: &DemoArgs) -> Result<()> {
    std::fs::create_dir_all(&a.out)
        .with_context(|| format!("{}: cannot create", a.out.display()))?;
    let mut scenes = spline_scenes()?;
    scenes.push(fabrik_scene()?);
    // FFD twists (motor vs positional lattice) and a bar bent by motors on its cage's
    // vertices (demo/lattice.rs).
    scenes.extend(lattice::scenes(LENGTH)?);
    scenes.push(handles_scene()?);
    scenes.push(arap_scene()?);
    // Skinning, then cutting, tearing and drilling the rigged arm, re-animated after each
    // (demo/surgery.rs); every rig is also written as .glb.
    scenes.extend(surgery::scenes(&a.out)?);
    let mut rows = Vec::new();
    let mut images = Vec::new();
    for scene in scenes {
        rows.push(Row {
            name: scene.name,
            method: scene.method.clone(),
            vertices: scene.rest.vertex_count(),
            bind_ms: scene.bind_ms,
            pose_ms: scene.pose_ms,
        });
        images.push(save(a, scene)?);
    }
    let sheet = preview::sheet(&images, 4);
    let sheet_path = a.out.join("contact-sheet.png");
    write_png(&sheet_path, &sheet)?;
    print_table(&rows, a, &sheet_path);
    Ok(())
}

/// One OBJ and one before-and-after PNG of `s`, titled with the scene, its method and how far
/// it moved; returns its tile of the contact sheet.
fn save(a: &DemoArgs, s: DemoScene) -> Result<deform::render::Image> {
    let posed = Mesh::new(s.posed.clone(), s.rest.triangles.clone());
    let name = s.name;
    write_mesh(&a.out.join(format!("{name}.obj")), &posed)?;
    let moved = preview::max_move(&s.rest, &posed.positions);
    let look = Look {
        title: format!("{name}  {}  {moved}", s.method),
        ..s.look
    };
    let (rest, scalar) = (&s.rest, &s.scalar);
    let image = preview::before_after(rest, &posed, scalar, &look)?;
    write_png(&a.out.join(format!("{name}.png")), &image)?;
    Ok(preview::tile(rest, &posed, scalar, &look)?)
}

/// The spline scenes on the square bar.
fn spline_scenes() -> Result<Vec<DemoScene>> {
    let bar = tube(1.0, LENGTH, SIDES, RINGS);
    let (h1, hn) = (tube_ring(SIDES, 0), tube_ring(SIDES, RINGS - 1));
    let mut scenes = Vec::new();
    for s in spline_keys() {
        let options = SplineOptions {
            scheme: s.scheme,
            method: s.method,
            ..SplineOptions::default()
        };
        let t = Instant::now();
        let d = SplineDeformer::bind(&bar, &h1, &hn, &s.rest, options)?;
        let bind_ms = ms(t);
        let mut out = vec![DVec3::ZERO; bar.vertex_count()];
        let pose_ms = time_pose(&d, &s.keys, &mut out)?;
        let mut look = Look::new("", "lambda");
        look.posed
            .polyline(&spine(&out, d.lambda(), 24), false, POSED_INK);
        scenes.push(DemoScene {
            name: s.name,
            method: format!("{} / {}", s.scheme.name(), s.method.name()),
            rest: bar.clone(),
            posed: out,
            scalar: d.lambda().to_vec(),
            bind_ms,
            pose_ms,
            look,
        });
    }
    Ok(scenes)
}

/// FABRIK: a round bar follows a chain whose end effector is pulled up and back.
fn fabrik_scene() -> Result<DemoScene> {
    let rod = tube(1.0, LENGTH, 24, RINGS);
    let (r1, rn) = (tube_ring(24, 0), tube_ring(24, RINGS - 1));
    let joints = straight_chain(&rod, &r1, &rn, 6);
    let t = Instant::now();
    let chain = ChainDeformer::bind(&rod, &r1, &rn, &joints, 4, SplineOptions::default())?;
    let bind_ms = ms(t);
    let mut out = vec![DVec3::ZERO; rod.vertex_count()];
    let t = Instant::now();
    let target = DVec3::new(5.0, 6.0, 2.0);
    let r = chain.pose_to_target(target, &FabrikOptions::default(), &mut out)?;
    let pose_ms = ms(t);
    let mut look = Look::new("", "lambda");
    look.posed.polyline(&r.solution.joints, false, POSED_INK);
    for &j in &r.solution.joints {
        look.posed.dot(j, 3, POSED_INK);
    }
    look.posed.dot(target, 5, TOOL_INK);
    let passes = r.solution.iterations;
    Ok(DemoScene {
        name: "fabrik-chain",
        method: format!("FABRIK ({passes} passes) + B-spline fit / motor-log"),
        scalar: chain.spline().lambda().to_vec(),
        rest: rod,
        posed: out,
        bind_ms,
        pose_ms,
        look,
    })
}

/// Motor handles on the catalogue's sphere: the bottom cap stays, the top cap lifts and
/// grows, a side cap turns.
fn handles_scene() -> Result<DemoScene> {
    let (ball, sets) = sphere_with_caps();
    let slices: Vec<&[u32]> = sets.iter().map(Vec::as_slice).collect();
    let t = Instant::now();
    let rest = [ScaledMotor::IDENTITY; 3];
    let handles = MotorHandles::bind_with(&ball, &slices, &rest, HandleOptions::default())?;
    let bind_ms = ms(t);
    let keys = [
        ScaledMotor::IDENTITY,
        about(DVec3::Y, 1.4, DQuat::IDENTITY, DVec3::new(0.0, 0.8, 0.0)),
        about(
            DVec3::X,
            1.0,
            DQuat::from_rotation_x(PI / 2.0),
            DVec3::new(0.5, 0.0, 0.0),
        ),
    ];
    let mut out = vec![DVec3::ZERO; ball.vertex_count()];
    let pose_ms = time_pose(&handles, &keys, &mut out)?;
    let mut look = Look::new("", "displacement");
    for (set, key) in sets.iter().zip(&keys) {
        let centre = key.transform_point(centroid(&ball.positions, set));
        look.posed.dot(centre, 4, POSED_INK);
    }
    Ok(DemoScene {
        name: "handles-sphere",
        method: "3 harmonic handles / motor-log".into(),
        scalar: displacement(&ball, &out),
        rest: ball,
        posed: out,
        bind_ms,
        pose_ms,
        look,
    })
}

/// ARAP with rotors on the catalogue's beam: its left end fixed, its right end lifted and
/// turned by a motor; a few iterations of the spokes-and-rims energy from the rest pose.
fn arap_scene() -> Result<DemoScene> {
    let (beam, ends) = beam_with_ends();
    let (fixed, end) = (&ends[0], &ends[1]);
    let t = Instant::now();
    let arap = Arap::bind(&beam, fixed, &[end], ArapOptions::default())?;
    let bind_ms = ms(t);
    let tip = DVec3::new(LENGTH, 0.0, 0.0);
    let turn = DQuat::from_rotation_z(PI / 2.0) * DQuat::from_rotation_x(PI / 3.0);
    let key = about(tip, 1.0, turn, DVec3::new(-4.0, 5.0, 0.0));
    let iterations = 8;
    let mut out = beam.positions.clone();
    let t = Instant::now();
    let targets = Targets::Motors(&[key]);
    let report = arap.pose(&targets, Stop::Iterations(iterations), &mut out)?;
    let pose_ms = ms(t);
    let mut look = Look::new("", "displacement");
    look.posed
        .dot(centroid(&beam.positions, fixed), 4, REST_INK);
    let end_centre = key.transform_point(centroid(&beam.positions, end));
    look.posed.dot(end_centre, 4, POSED_INK);
    let energy = report.energies.last().copied().unwrap_or(f64::NAN);
    Ok(DemoScene {
        name: "arap-beam",
        method: format!(
            "ARAP {} / rotor, {iterations} iterations (E {energy:.3})",
            arap.options().energy.name(),
        ),
        scalar: displacement(&beam, &out),
        rest: beam,
        posed: out,
        bind_ms,
        pose_ms,
        look,
    })
}

fn print_table(rows: &[Row], a: &DemoArgs, sheet: &std::path::Path) {
    if a.json {
        let v: Vec<serde_json::Value> = rows
            .iter()
            .map(|r| {
                serde_json::json!({
                    "scene": r.name, "method": r.method, "vertices": r.vertices,
                    "bind_ms": r.bind_ms, "pose_ms": r.pose_ms,
                })
            })
            .collect();
        println!(
            "{}",
            serde_json::json!({ "out": a.out.display().to_string(), "scenes": v })
        );
        return;
    }
    if a.quiet {
        return;
    }
    // Columns as wide as their longest entry.
    let scene = rows.iter().map(|r| r.name.len()).max().unwrap_or(0).max(5);
    let method = rows
        .iter()
        .map(|r| r.method.len())
        .max()
        .unwrap_or(0)
        .max(6);
    println!(
        "{:<scene$} {:<method$} {:>8} {:>9} {:>9}",
        "scene", "method", "vertices", "bind ms", "pose ms"
    );
    for r in rows {
        println!(
            "{:<scene$} {:<method$} {:>8} {:>9.2} {:>9.3}",
            r.name, r.method, r.vertices, r.bind_ms, r.pose_ms
        );
    }
    println!(
        "wrote {} OBJ files and PNG previews to {}, contact sheet {}",
        rows.len(),
        a.out.display(),
        sheet.display()
    );
}
