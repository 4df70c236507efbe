//! Every method of both papers on the procedural meshes of the scene catalogue, bound and
//! posed with fixed keys: the spline schemes bending, twisting and stretching a bar, a FABRIK
//! chain, FFD lattices and a cage, motor handles, ARAP, and the rigged arm animated, cut, torn
//! and drilled (`surgery.rs`). What `deform demo` writes and a library caller can reproduce:
//! each scene with its rest and posed meshes, the scalar its preview is coloured by, its
//! overlays, and its bind and pose times.

mod lattice;
mod surgery;

use super::error::MethodsError;
use super::scenes::{beam_with_ends, sphere_with_caps};
use crate::blend::BlendMethod;
use crate::deformers::arap::{Arap, ArapOptions, Stop, Targets};
use crate::deformers::fabrik::{straight_chain, ChainDeformer, FabrikOptions};
use crate::deformers::handles::{HandleOptions, MotorHandles};
use crate::deformers::spline::{SplineDeformer, SplineOptions, WeightScheme};
use crate::deformers::{Deformer, Poser};
use crate::mesh::shapes::{tube, tube_ring};
use crate::mesh::Mesh;
use crate::render::preview::{Look, POSED_INK, REST_INK, TOOL_INK};
use crate::render::tools::{centroid, spine};
use crate::skinning::Rig;
use cga::{Motor, ScaledMotor};
use glam::{DQuat, DVec3};
use std::f64::consts::PI;
use std::time::Instant;

type Result<T> = std::result::Result<T, MethodsError>;

const LENGTH: f64 = 10.0;
const SIDES: usize = 4;
const RINGS: usize = 81;

/// One scene: its meshes, the scalar of its preview, its overlays and its times.
pub struct PosedScene {
    /// Its name (the demo's file names).
    pub name: &'static str,
    /// The method and its figures, for titles and tables.
    pub method: String,
    /// The rest mesh.
    pub rest: Mesh,
    /// The posed positions.
    pub posed: Vec<DVec3>,
    /// The value per vertex the preview is coloured by.
    pub scalar: Vec<f64>,
    /// The bind's (or the tool's) time.
    pub bind_ms: f64,
    /// The best pose time of a few.
    pub pose_ms: f64,
    /// The preview's scalar name and overlays (its title is the caller's).
    pub look: Look,
    /// The rig, for the skinning and surgery scenes (written as `.glb` by the demo).
    pub rig: Option<Rig>,
}

/// Every scene, in the demo's order.
pub fn showcase() -> Result<Vec<PosedScene>> {
    let mut scenes = spline_scenes()?;
    scenes.push(fabrik_scene()?);
    // FFD twists (motor vs positional lattice) and a bar bent by motors on its cage's
    // vertices (lattice.rs).
    scenes.extend(lattice::scenes(LENGTH)?);
    scenes.push(handles_scene()?);
    scenes.push(arap_scene()?);
    // Skinning, then cutting, tearing and drilling the rigged arm, re-animated after each
    // (surgery.rs).
    scenes.extend(surgery::scenes()?);
    Ok(scenes)
}

/// Milliseconds since `t`.
fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// The best of five poses with one scratch, in milliseconds.
fn time_pose<D: Deformer + ?Sized>(d: &D, keys: &[ScaledMotor], out: &mut [DVec3]) -> Result<f64> {
    Ok(Poser::new(d).best_time_ms(keys, out, 5)?)
}

/// How far each vertex moved from `rest` to `posed`.
fn displacement(rest: &Mesh, posed: &[DVec3]) -> Vec<f64> {
    posed
        .iter()
        .zip(&rest.positions)
        .map(|(p, q)| p.distance(*q))
        .collect()
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

/// The spline scenes on the square bar.
fn spline_scenes() -> Result<Vec<PosedScene>> {
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
        scenes.push(PosedScene {
            name: s.name,
            method: format!("{} / {}", s.scheme.name(), s.method.name()),
            rest: bar.clone(),
            posed: out,
            scalar: d.lambda().to_vec(),
            bind_ms,
            pose_ms,
            look,
            rig: None,
        });
    }
    Ok(scenes)
}

/// FABRIK: a round bar follows a chain whose end effector is pulled up and back.
fn fabrik_scene() -> Result<PosedScene> {
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
    Ok(PosedScene {
        name: "fabrik-chain",
        method: format!("FABRIK ({passes} passes) + B-spline fit / motor-log"),
        scalar: chain.spline().lambda().to_vec(),
        rest: rod,
        posed: out,
        bind_ms,
        pose_ms,
        look,
        rig: None,
    })
}

/// Motor handles on the catalogue's sphere: the bottom cap stays, the top cap lifts and
/// grows, a side cap turns.
fn handles_scene() -> Result<PosedScene> {
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
    Ok(PosedScene {
        name: "handles-sphere",
        method: "3 harmonic handles / motor-log".into(),
        scalar: displacement(&ball, &out),
        rest: ball,
        posed: out,
        bind_ms,
        pose_ms,
        look,
        rig: None,
    })
}

/// ARAP with rotors on the catalogue's beam: its left end fixed, its right end lifted and
/// turned by a motor; a few iterations of the spokes-and-rims energy from the rest pose.
fn arap_scene() -> Result<PosedScene> {
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
    Ok(PosedScene {
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
        rig: None,
    })
}
