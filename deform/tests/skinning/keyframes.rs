//! Keyframes: glTF's samplers against their closed forms, and logarithmic (motor) keyframe
//! blending.

use cga::ScaledMotor;
use deform::skinning::procedural_arm;
use glam::{DQuat, DVec3};

/// STEP holds, CUBICSPLINE follows the Hermite form with tangents scaled by the interval,
/// LINEAR rotations take the shortest path; times clamp to the keys.
#[test]
fn samplers_closed_forms() {
    use deform::skinning::{Channel, Interpolation, Property};
    use glam::DVec4;
    let step = Channel::new(
        0,
        Property::Translation,
        Interpolation::Step,
        vec![1.0, 2.0],
        vec![DVec4::X, DVec4::Y],
        "s",
    )
    .unwrap();
    assert_eq!(step.sample(0.0), DVec4::X);
    assert_eq!(step.sample(1.99), DVec4::X);
    assert_eq!(step.sample(2.0), DVec4::Y);
    assert_eq!(step.sample(9.0), DVec4::Y);
    // p(s) = 2s^3 - 3s^2 + 1 for value 1 -> 0 with out-tangent 0 and in-tangent 0, plus the
    // tangent terms: out-tangent m0 = 1 per second over an interval of 2 s.
    let cubic = Channel::new(
        0,
        Property::Translation,
        Interpolation::CubicSpline,
        vec![0.0, 2.0],
        vec![
            DVec4::ZERO,
            DVec4::X,
            DVec4::X,
            DVec4::ZERO,
            DVec4::ZERO,
            DVec4::ZERO,
        ],
        "c",
    )
    .unwrap();
    for s in [0.0, 0.25, 0.5, 0.9] {
        let want = (2.0 * s * s * s - 3.0 * s * s + 1.0) + 2.0 * (s * s * s - 2.0 * s * s + s);
        assert!((cubic.sample(2.0 * s).x - want).abs() < 1e-14, "s = {s}");
    }
    // Shortest path: keys q and -q' (nearly the same rotation) interpolate without a flip.
    let a = DQuat::from_rotation_z(0.1);
    let b = -DQuat::from_rotation_z(0.3);
    let lin = Channel::new(
        0,
        Property::Rotation,
        Interpolation::Linear,
        vec![0.0, 1.0],
        vec![DVec4::from(a), DVec4::from(b)],
        "r",
    )
    .unwrap();
    let mid = DQuat::from_vec4(lin.sample(0.5));
    assert!(mid.angle_between(DQuat::from_rotation_z(0.2)) < 1e-12);
}

/// Logarithmic keyframe blending: at the keys it is the keys; between keys of a rotation
/// about a fixed pivot it is the slerp (a motor geodesic of rotations is a rotation); with a
/// simultaneous translation it is a screw motion, not glTF's separate lerp and slerp.
#[test]
fn motor_log_keyframes() {
    use deform::skinning::{Animation, Channel, Interpolation, KeyframeBlend, Property, RigPose};
    use glam::DVec4;
    let mut rig = procedural_arm(8, 10);
    let rot = |deg: f64| DVec4::from(DQuat::from_rotation_z(deg.to_radians()));
    let spin = Channel::new(
        1,
        Property::Rotation,
        Interpolation::Linear,
        vec![0.0, 1.0],
        vec![rot(0.0), rot(90.0)],
        "spin",
    )
    .unwrap();
    let slide = Channel::new(
        1,
        Property::Translation,
        Interpolation::Linear,
        vec![0.0, 1.0],
        vec![
            DVec4::new(4.0, 0.0, 0.0, 0.0),
            DVec4::new(4.0, 2.0, 0.0, 0.0),
        ],
        "slide",
    )
    .unwrap();
    rig.animations = vec![
        Animation {
            name: "spin".into(),
            channels: vec![spin.clone()],
        },
        Animation {
            name: "screw".into(),
            channels: vec![spin, slide],
        },
    ];
    let (mut a, mut b) = (RigPose::default(), RigPose::default());
    for t in [0.0, 0.3, 0.5, 1.0] {
        rig.pose_into(Some(0), t, KeyframeBlend::Gltf, &[], &mut a)
            .unwrap();
        rig.pose_into(Some(0), t, KeyframeBlend::MotorLog, &[], &mut b)
            .unwrap();
        let d = (a.globals[2] - b.globals[2])
            .abs()
            .to_cols_array()
            .into_iter()
            .fold(0.0, f64::max);
        assert!(d < 1e-12, "rotation only, t = {t}: {d}");
        rig.pose_into(Some(1), t, KeyframeBlend::Gltf, &[], &mut a)
            .unwrap();
        rig.pose_into(Some(1), t, KeyframeBlend::MotorLog, &[], &mut b)
            .unwrap();
        let d = (a.globals[2] - b.globals[2])
            .abs()
            .to_cols_array()
            .into_iter()
            .fold(0.0, f64::max);
        if t == 0.0 || t == 1.0 {
            assert!(d < 1e-12, "screw at a key, t = {t}: {d}");
        } else {
            assert!(
                d > 1e-3,
                "a screw motion differs from lerp + slerp between keys, t = {t}"
            );
        }
        // The screw: the elbow's local motor at t is exp(t log(M0^-1 M1)) from M0.
        let m0 = ScaledMotor::from_scale_rotation_translation(
            1.0,
            DQuat::IDENTITY,
            DVec3::new(4.0, 0.0, 0.0),
        );
        let m1 = ScaledMotor::from_scale_rotation_translation(
            1.0,
            DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2),
            DVec3::new(4.0, 2.0, 0.0),
        );
        let want = ScaledMotor::interpolate(m0, m1, t);
        let got = b.locals[1];
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert!((want.transform_point(p) - got.matrix().transform_point3(p)).length() < 1e-12);
    }
}
