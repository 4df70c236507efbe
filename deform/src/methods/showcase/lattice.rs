//! The demo's FFD and cage scenes (first paper, Figs. 7 and 8): a bar twisted half a turn by
//! two lattice layers, motor FFD beside positional FFD with the same lattice points; a bar in
//! a tube-shaped cage bent a quarter turn by motors on the cage vertices that turn each ring
//! about a common axis (motor-valued mean value coordinates).

use super::{displacement, ms, time_pose, PosedScene, Result};
use crate::blend::control::{ControlForm, ControlScratch};
use crate::blend::BlendMethod;
use crate::deformers::cage::{CageDeformer, CageOptions};
use crate::deformers::ffd::{Ffd, FfdOptions};
use crate::deformers::Deformer;
use crate::mesh::shapes::tube;
use crate::mesh::Mesh;
use crate::render::preview::{Look, POSED_INK};
use crate::render::tools::{self, mesh_edges, moved};
use cga::ScaledMotor;
use glam::{DQuat, DVec3};
use std::time::Instant;

fn rotation_about(center: DVec3, q: DQuat) -> ScaledMotor {
    ScaledMotor::from_scale_rotation_translation(1.0, q, center - q * center)
}

fn run(
    name: &'static str,
    method: String,
    rest: &Mesh,
    bind: impl FnOnce() -> Result<Box<dyn Deformer<Scratch = ControlScratch>>>,
    keys: &[ScaledMotor],
    look: Look,
) -> Result<PosedScene> {
    let t = Instant::now();
    let d = bind()?;
    let bind_ms = ms(t);
    let mut posed = vec![DVec3::ZERO; rest.vertex_count()];
    let pose_ms = time_pose(d.as_ref(), keys, &mut posed)?;
    Ok(PosedScene {
        name,
        method,
        scalar: displacement(rest, &posed),
        rest: rest.clone(),
        posed,
        bind_ms,
        pose_ms,
        look,
        rig: None,
    })
}

/// The FFD twists and the cage bend.
pub fn scenes(length: f64) -> Result<Vec<PosedScene>> {
    let mut out = Vec::new();
    // FFD: a 2x2x2 lattice whose u = 0 layer turns -90 degrees and u = 1 layer +90 degrees
    // about the bar's axis.
    let bar = tube(1.0, length, 4, 41);
    let bounds = (DVec3::new(0.0, -1.0, -1.0), DVec3::new(length, 1.0, 1.0));
    let keys: Vec<ScaledMotor> = (0..8)
        .map(|k| {
            let a = if k % 2 == 0 { -90f64 } else { 90.0 };
            rotation_about(DVec3::ZERO, DQuat::from_rotation_x(a.to_radians()))
        })
        .collect();
    for (name, form) in [
        ("ffd-twist-motor", ControlForm::Motor(BlendMethod::MotorLog)),
        ("ffd-twist-points", ControlForm::Positional),
    ] {
        let options = FfdOptions {
            form,
            ..FfdOptions::default()
        };
        out.push(run(
            name,
            format!("FFD 2x2x2 Bernstein / {}", form.name()),
            &bar,
            || Ok(Box::new(Ffd::bind(&bar, [2, 2, 2], Some(bounds), options)?)),
            &keys,
            {
                // The lattice moved by its motors.
                let mut look = Look::new("", "displacement");
                let lattice = crate::deformers::ffd::Lattice::new(
                    [2, 2, 2],
                    bounds.0,
                    bounds.1,
                    crate::deformers::ffd::LatticeBasis::Bernstein,
                )?;
                let points = moved(&lattice.rest_points(), &keys);
                tools::lattice(&mut look.posed, &points, [2, 2, 2], POSED_INK);
                look
            },
        )?);
    }
    // Cage: a square tube cage of 6 rings around a round bar; the vertices at x turn about
    // the axis through (0, r, 0) along z by 90 degrees * x / length (an arc of radius r).
    // The catalogue's bar and cage (the editor's "cage" scene), `length` long.
    let (bar, cage) = (
        crate::methods::scenes::bar(),
        crate::methods::scenes::bar_cage(),
    );
    let theta = std::f64::consts::FRAC_PI_2;
    let center = DVec3::new(0.0, length / theta, 0.0);
    let keys: Vec<ScaledMotor> = cage
        .positions
        .iter()
        .map(|&p| {
            let s = (p.x / length).clamp(0.0, 1.0);
            rotation_about(center, DQuat::from_rotation_z(theta * s))
        })
        .collect();
    out.push(run(
        "cage-bend-motor",
        format!("MVC cage ({} vertices) / motor-log", cage.vertex_count()),
        &bar,
        || {
            Ok(Box::new(CageDeformer::bind(
                &bar,
                &cage,
                CageOptions::default(),
            )?))
        },
        &keys,
        {
            // The cage moved by its motors.
            let mut look = Look::new("", "displacement");
            look.posed.line_width = 1;
            mesh_edges(
                &mut look.posed,
                &cage,
                &moved(&cage.positions, &keys),
                POSED_INK,
            );
            look
        },
    )?);
    Ok(out)
}
