//! Joint edits baked into the written rig (issue 21): the edit plays with the animation.

use crate::{gltf, max_dist};
use cga::ScaledMotor;
use deform::skinning::{
    bake_edits, glb_bytes, parse_gltf, procedural_arm, GlbOptions, JointEdit, KeyframeBlend, Rig,
    RigPose, SkinError,
};
use glam::{DQuat, DVec3};

/// The posed mesh of `rig` at `t` with `edits` (matrix skinning, exact).
fn posed(
    rig: &Rig,
    animation: usize,
    t: f64,
    blend: KeyframeBlend,
    edits: &[JointEdit],
) -> Vec<DVec3> {
    let mut pose = RigPose::default();
    rig.pose_into(Some(animation), t, blend, edits, &mut pose)
        .expect("pose");
    rig.mesh
        .positions
        .iter()
        .enumerate()
        .map(|(v, &p)| {
            rig.influences
                .row(v)
                .map(|(j, w)| w * pose.skin_matrices[j as usize].transform_point3(p))
                .sum()
        })
        .collect()
}

fn diagonal(rig: &Rig) -> f64 {
    rig.mesh.bounding_box().expect("a mesh").diagonal()
}

/// Rotation and dilation about the joint: exact at every time, between keys too, for the
/// arm's LINEAR (elbow), CUBICSPLINE (wrist) and STEP (shoulder) channels, with both keyframe
/// blends, and through a written and re-read `.glb`.
#[test]
fn a_baked_edit_poses_like_the_edit_at_every_time() {
    let rig = procedural_arm(12, 24);
    let tilt = ScaledMotor::from_scale_rotation_translation(
        1.15,
        DQuat::from_axis_angle(DVec3::new(0.3, 0.2, 1.0).normalize(), 0.4),
        DVec3::ZERO,
    );
    for joint in 0..rig.joints.len() {
        let edits = [JointEdit { joint, motor: tilt }];
        let baked = bake_edits(&rig, &edits).expect("bake");
        let written = parse_gltf(
            &glb_bytes(&baked, &GlbOptions::default()).expect("glb"),
            "arm",
            None,
        )
        .expect("read back");
        let d = diagonal(&rig);
        for t in [0.0, 0.137, 0.5, 0.999, 1.0, 1.31, 2.0, 2.5] {
            for blend in [KeyframeBlend::Gltf, KeyframeBlend::MotorLog] {
                let want = posed(&rig, 0, t, blend, &edits);
                let got = posed(&baked, 0, t, blend, &[]);
                let e = max_dist(&want, &got) / d;
                assert!(
                    e < 1e-12,
                    "joint {joint}, t {t}, {blend:?}: {e:e} of the diagonal"
                );
            }
            // Single precision in the file.
            let e = max_dist(
                &posed(&rig, 0, t, KeyframeBlend::Gltf, &edits),
                &posed(&written, 0, t, KeyframeBlend::Gltf, &[]),
            ) / d;
            assert!(
                e < 1e-6,
                "joint {joint}, t {t}, written: {e:e} of the diagonal"
            );
        }
        // The edit shows: the baked rig differs from the unedited one.
        let e = max_dist(
            &posed(&rig, 0, 0.5, KeyframeBlend::Gltf, &[]),
            &posed(&baked, 0, 0.5, KeyframeBlend::Gltf, &[]),
        );
        assert!(
            e > 1e-3 * diagonal(&rig),
            "joint {joint}: the edit changed nothing"
        );
    }
}

/// A translation bakes exactly into a joint whose rotation and scale are not animated (the
/// arm's shoulder: only its translation is keyed), and is refused for one whose rotation is.
#[test]
fn a_translating_edit_bakes_only_where_it_can_be_exact() {
    let rig = procedural_arm(12, 24);
    let shift = ScaledMotor::from_scale_rotation_translation(
        1.0,
        DQuat::from_rotation_z(0.3),
        DVec3::new(0.2, -0.1, 0.05),
    );
    let shoulder = [JointEdit {
        joint: 0,
        motor: shift,
    }];
    let baked = bake_edits(&rig, &shoulder).expect("bake");
    for t in [0.0, 0.7, 1.0, 1.6] {
        let e = max_dist(
            &posed(&rig, 0, t, KeyframeBlend::Gltf, &shoulder),
            &posed(&baked, 0, t, KeyframeBlend::Gltf, &[]),
        );
        assert!(e < 1e-12 * diagonal(&rig), "t {t}: {e:e}");
    }
    let elbow = [JointEdit {
        joint: 1,
        motor: shift,
    }];
    match bake_edits(&rig, &elbow) {
        Err(SkinError::BadTransform { what, message }) => {
            assert!(what.contains("joint 1"), "{what}");
            assert!(message.contains("translates"), "{message}");
        }
        other => panic!("expected a refusal, got {:?}", other.map(|_| ())),
    }
    assert!(matches!(
        bake_edits(
            &rig,
            &[JointEdit {
                joint: 99,
                motor: shift
            }]
        ),
        Err(SkinError::NoJoint(_))
    ));
}

/// CesiumMan's neck (the example): the edit plays through the walk.
#[test]
fn cesium_man_neck_edit_plays() {
    let Some(rig) = gltf("CesiumMan.glb") else {
        return;
    };
    let joint = rig.joint_index("Skeleton_neck_joint_1").expect("neck");
    let edits = [JointEdit {
        joint,
        motor: ScaledMotor::from_scale_rotation_translation(
            1.1,
            DQuat::from_rotation_x(20f64.to_radians()),
            DVec3::ZERO,
        ),
    }];
    let baked = bake_edits(&rig, &edits).expect("bake");
    let written = parse_gltf(
        &glb_bytes(&baked, &GlbOptions::default()).expect("glb"),
        "man",
        None,
    )
    .expect("read back");
    let d = diagonal(&rig);
    for t in [0.0, 0.5, 1.1, 1.9] {
        let want = posed(&rig, 0, t, KeyframeBlend::Gltf, &edits);
        let e = max_dist(&want, &posed(&written, 0, t, KeyframeBlend::Gltf, &[])) / d;
        assert!(e < 1e-6, "t {t}: {e:e} of the diagonal");
        let unedited = posed(&rig, 0, t, KeyframeBlend::Gltf, &[]);
        assert!(
            max_dist(&want, &unedited) > 1e-3 * d,
            "t {t}: the edit does not show"
        );
    }
}
