//! The demo's skinning and surgery scenes (second paper): a procedural rigged arm animated
//! and its elbow dilated by equation (17); then cut (capped), torn (three scalpel steps,
//! opened) and drilled, each result re-animated at the end of the arm's animation. Every rig
//! is kept with its scene (the demo writes it as `.glb`: mesh, skin, animations).

use super::{displacement, ms, time_pose, PosedScene, Result};
use crate::blend::BlendMethod;
use crate::mesh::Mesh;
use crate::render::preview::{Focus, Look};
use crate::skinning::{procedural_arm, JointEdit, Rig, Skinning};
use crate::surgery::{
    CutOptions, Drill, DrillOptions, Frame, Scalpel, Surgery, TearOptions, VertexOrigin,
};
use cga::ScaledMotor;
use glam::{DQuat, DVec3};
use std::time::Instant;

/// Pose `rig` at `t` of its animation (with `edits`) by equation (17).
fn animate(rig: &Rig, t: f64, edits: &[JointEdit]) -> Result<(Vec<DVec3>, f64)> {
    let skin = Skinning::bind(rig, BlendMethod::Conformal)?;
    let pose = rig.pose(Some(0), t, edits)?;
    let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    let pose_ms = time_pose(&skin, pose.skin_motors()?, &mut out)?;
    Ok((out, pose_ms))
}

/// 1 for vertices a tool made, 0 for input vertices.
fn made(origin: &[VertexOrigin]) -> Vec<f64> {
    origin
        .iter()
        .map(|o| if o.is_input() { 0.0 } else { 1.0 })
        .collect()
}

/// A look zoomed on the vertices a tool made, seen along `direction`.
fn zoomed(origin: &[VertexOrigin], direction: DVec3) -> Look {
    let mut look = Look::new("", "new vertex");
    let vertices: Vec<u32> = (0..origin.len() as u32)
        .filter(|&v| !origin[v as usize].is_input())
        .collect();
    if !vertices.is_empty() {
        look.focus = Some(Focus {
            vertices,
            direction: Some(direction),
        });
    }
    look
}

/// The skin and surgery scenes.
pub fn scenes() -> Result<Vec<PosedScene>> {
    let rig = procedural_arm(24, 81);
    let surgery = Surgery::new(&rig.mesh, &rig.influences)?;
    Ok(vec![
        skin_scene(&rig)?,
        cut_scene(&rig, &surgery)?,
        tear_scene(&rig, &surgery)?,
        drill_scene(&rig, &surgery)?,
    ])
}

/// The arm at `t = 2` of its animation with its elbow dilated by 1.3.
fn skin_scene(rig: &Rig) -> Result<PosedScene> {
    let edit = [JointEdit {
        joint: 1,
        motor: ScaledMotor::from_scale_rotation_translation(1.3, DQuat::IDENTITY, DVec3::ZERO),
    }];
    let t = Instant::now();
    let (posed, pose_ms) = animate(rig, 2.0, &edit)?;
    let moved = displacement(&rig.mesh, &posed);
    Ok(PosedScene {
        name: "skin-arm",
        method: "3-joint rig, animation + dilated elbow / equation (17)".into(),
        rest: rig.mesh.clone(),
        posed,
        scalar: moved,
        bind_ms: ms(t) - pose_ms,
        pose_ms,
        look: Look::new("", "displacement"),
        rig: Some(rig.clone()),
    })
}

/// A cut across the upper arm, capped: the two pieces stay on the skeleton.
fn cut_scene(rig: &Rig, surgery: &Surgery) -> Result<PosedScene> {
    let t = Instant::now();
    let plane = cga::Plane::from_normal_distance(DVec3::new(1.0, 0.3, 0.0).normalize(), 2.6);
    let cut = surgery.cut(
        &plane,
        Frame::Rest,
        &CutOptions {
            cap: true,
            ..CutOptions::default()
        },
    )?;
    let cut_ms = ms(t);
    let parts: Vec<_> = cut.pieces.iter().map(|p| p.mesh.part()).collect();
    let cut_rig = rig.with_parts(&parts)?;
    let (posed, pose_ms) = animate(&cut_rig, 2.0, &[])?;
    let side: Vec<f64> = cut_rig
        .primitives
        .iter()
        .flat_map(|p| std::iter::repeat_n(p.primitive as f64, p.vertex_count))
        .collect();
    Ok(PosedScene {
        name: "cut-arm",
        method: format!(
            "cut + caps ({} new vertices) / re-animated",
            cut.new_vertices
        ),
        rest: cut_rig.mesh.clone(),
        posed,
        scalar: side,
        bind_ms: cut_ms,
        pose_ms,
        look: Look::new("", "piece"),
        rig: Some(cut_rig),
    })
}

/// A tear along the forearm's front (+z, towards the camera) in three scalpel steps, opened.
fn tear_scene(rig: &Rig, surgery: &Surgery) -> Result<PosedScene> {
    let blade = |x: f64, y: f64| Scalpel {
        a: DVec3::new(x, y, 1.2),
        b: DVec3::new(x, y, 0.2),
    };
    let t = Instant::now();
    let tear = surgery.tear(
        &[blade(4.6, 0.05), blade(5.4, 0.1), blade(6.3, 0.0)],
        Frame::Rest,
        &TearOptions {
            open: 0.25,
            ..TearOptions::default()
        },
    )?;
    let tear_ms = ms(t);
    let torn = rig.with_parts(&[tear.mesh.part()])?;
    let (posed, pose_ms) = animate(&torn, 2.0, &[])?;
    Ok(PosedScene {
        name: "tear-arm",
        method: format!(
            "tear, 2 steps, opened ({} incision vertices) / re-animated",
            tear.incision_vertex_count()
        ),
        rest: torn.mesh.clone(),
        posed,
        scalar: made(&tear.origin),
        bind_ms: tear_ms,
        pose_ms,
        look: zoomed(&tear.origin, DVec3::NEG_Z),
        rig: Some(torn),
    })
}

/// A drill through the upper arm.
fn drill_scene(rig: &Rig, surgery: &Surgery) -> Result<PosedScene> {
    let t = Instant::now();
    let drill = surgery.drill(
        &Drill {
            tip: DVec3::new(1.5, 0.1, -2.0),
            end: DVec3::new(1.5, 0.1, 2.0),
            radius: 0.3,
        },
        Frame::Rest,
        &DrillOptions::default(),
    )?;
    let drill_ms = ms(t);
    let drilled = rig.with_parts(&[drill.mesh.part()])?;
    let (posed, pose_ms) = animate(&drilled, 2.0, &[])?;
    Ok(PosedScene {
        name: "drill-arm",
        method: format!("drill, {} holes / re-animated", drill.holes),
        rest: Mesh::new(
            drilled.mesh.positions.clone(),
            drilled.mesh.triangles.clone(),
        ),
        posed,
        scalar: made(&drill.origin),
        bind_ms: drill_ms,
        pose_ms,
        look: zoomed(&drill.origin, DVec3::Z),
        rig: Some(drilled),
    })
}
