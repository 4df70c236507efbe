//! A procedural rigged arm (no files needed): for the demo, tests and benches.

use super::animation::{Animation, Channel, Interpolation, Property};
use super::influences::Influences;
use super::rig::{LoadReport, PrimitiveInfo, Rig, RigNode};
use super::Trs;
use crate::mesh::shapes::tube;
use glam::{DMat4, DQuat, DVec3, DVec4};

/// Joint positions along `+x` of the arm: shoulder, elbow, wrist.
const JOINTS_X: [f64; 3] = [0.0, 4.0, 7.0];

/// A tube of length 8 and radius 0.6 along `+x` (`sides` x `rings` vertices) rigged with
/// three joints (shoulder at `x = 0`, elbow at 4, wrist at 7; the elbow and wrist children of
/// the one before), weights blending smoothly over `+-0.8` around each joint, and one
/// 2-second animation `bend` with every sampler kind: the elbow bends 100 degrees about `z`
/// (LINEAR), the wrist twists 90 degrees about `x` (CUBICSPLINE), the shoulder steps up by 0.5
/// at 1 s (STEP).
pub fn procedural_arm(sides: usize, rings: usize) -> Rig {
    let mesh = tube(0.6, 8.0, sides.max(3), rings.max(2));
    let nodes = (0..3)
        .map(|j| RigNode {
            name: ["shoulder", "elbow", "wrist"][j].to_string(),
            parent: j.checked_sub(1),
            rest: Trs {
                translation: DVec3::X * (JOINTS_X[j] - if j > 0 { JOINTS_X[j - 1] } else { 0.0 }),
                ..Trs::IDENTITY
            },
        })
        .collect();
    let inverse_bind = JOINTS_X
        .iter()
        .map(|&x| DMat4::from_translation(-DVec3::X * x))
        .collect();
    let smooth = |x: f64, at: f64| {
        let s = ((x - at + 0.8) / 1.6).clamp(0.0, 1.0);
        s * s * (3.0 - 2.0 * s)
    };
    let mut influences = Influences {
        width: 4,
        ..Influences::default()
    };
    for p in &mesh.positions {
        let (e, w) = (smooth(p.x, JOINTS_X[1]), smooth(p.x, JOINTS_X[2]));
        influences.joints.extend([0, 1, 2, 0]);
        influences
            .weights
            .extend([1.0 - e, e * (1.0 - w), e * w, 0.0]);
    }
    let rot = |axis: DVec3, deg: f64| DVec4::from(DQuat::from_axis_angle(axis, deg.to_radians()));
    let bend = Channel::new(
        1,
        Property::Rotation,
        Interpolation::Linear,
        vec![0.0, 1.0, 2.0],
        vec![
            rot(DVec3::Z, 0.0),
            rot(DVec3::Z, 60.0),
            rot(DVec3::Z, 100.0),
        ],
        "bend elbow",
    );
    let zero = DVec4::ZERO;
    let twist = Channel::new(
        2,
        Property::Rotation,
        Interpolation::CubicSpline,
        vec![0.0, 2.0],
        vec![
            zero,
            rot(DVec3::X, 0.0),
            zero,
            zero,
            rot(DVec3::X, 90.0),
            zero,
        ],
        "twist wrist",
    );
    let lift = Channel::new(
        0,
        Property::Translation,
        Interpolation::Step,
        vec![0.0, 1.0],
        vec![DVec4::ZERO, DVec4::new(0.0, 0.5, 0.0, 0.0)],
        "lift shoulder",
    );
    let channels = [bend, twist, lift]
        .into_iter()
        .map(|c| c.expect("valid procedural keys"))
        .collect();
    let primitives = vec![PrimitiveInfo::whole(&mesh)];
    Rig::new(
        nodes,
        vec![0, 1, 2],
        inverse_bind,
        mesh,
        influences,
        primitives,
        vec![Animation {
            name: "bend".into(),
            channels,
        }],
        LoadReport::default(),
    )
    .expect("a valid procedural rig")
}
