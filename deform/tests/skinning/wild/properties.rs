//! Properties of rigs as exporters write them: f32 noise, odd joint scales, armature units,
//! many primitives, shared skins, no animation, morph targets.

use super::{bar, check, diagonal, reference_skinning, skin_rig, two_joint_bar, Bar};
use deform::skinning::{glb_bytes, parse_gltf, GlbOptions};
use deform::BlendMethod;
use glam::{DMat4, DQuat, DVec3};
use serde_json::json;

/// The Blender 1.8-era inverse bind matrix (singular values 1.0000194, 1.0000005, 1) is f32
/// noise: every backend takes it without a word; the shield's non-uniform joint scale is not:
/// `lbs` skins it exactly, the motors name the joint and measure the move.
#[test]
fn noisy_inverse_binds_and_non_uniform_joints() {
    let noise = DMat4::from_scale(DVec3::new(1.0000194, 1.0000005, 1.0));
    let f = two_joint_bar(Bar {
        ibm_factor: noise,
        ..Bar::default()
    });
    let rig = check("noisy-inverse-bind", &f);
    let pose = rig.pose(Some(0), 1.0, &[]).unwrap();
    assert_eq!(pose.approximated_joints().count(), 0);
    assert!(pose.skin_motors().is_ok());
    assert_eq!(rig.similarity_shift(&pose), 0.0);

    // Bound at scale 1 (the inverse bind lacks the scale), posed with the shield's scale.
    let f = two_joint_bar(Bar {
        joint_scale: [1.24, 1.0008, 1.24],
        joint_turn: DQuat::from_rotation_y(0.3),
        ibm_factor: DMat4::from_scale(DVec3::new(1.24, 1.0008, 1.24)),
        ..Bar::default()
    });
    let rig = check("non-uniform-joint", &f);
    let pose = rig.pose(Some(0), 1.0, &[]).unwrap();
    let far: Vec<_> = pose.approximated_joints().collect();
    assert_eq!(far.len(), 1, "{far:?}");
    assert!(far[0].1 > 0.05, "{far:?}");
    let shift = rig.similarity_shift(&pose);
    // The motor backends move the mesh by that much, and no more, against lbs.
    let lbs = skin_rig(&rig, BlendMethod::Matrix, Some(1.0));
    let cga = skin_rig(&rig, BlendMethod::ConformalProjected, Some(1.0));
    let moved = lbs
        .iter()
        .zip(&cga)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(
        shift > 0.0 && (moved - shift).abs() <= 1e-9 * diagonal(&lbs),
        "{moved} {shift}"
    );
}

/// A mirrored joint (its inverse bind mirrored too, as exporters write a mirrored rig): the
/// skin matrices are proper, matrices and motors both take it.
#[test]
fn mirrored_joint() {
    let f = two_joint_bar(Bar {
        joint_scale: [-1.0, 1.0, 1.0],
        ..Bar::default()
    });
    let rig = check("mirrored-joint", &f);
    let pose = rig.pose(Some(0), 1.0, &[]).unwrap();
    assert_eq!(pose.approximated_joints().count(), 0);
}

/// A Mixamo-style armature: centimetres (scale 0.01) and Z-up turned to Y-up. The bind pose
/// in world space is the bar standing 0.02 units tall along y; the rest mesh stays as stored.
#[test]
fn centimetre_z_up_armature() {
    let turn = DQuat::from_rotation_x(-std::f64::consts::FRAC_PI_2);
    let f = two_joint_bar(Bar {
        armature: (0.01, turn),
        ..Bar::default()
    });
    let rig = check("centimetre-armature", &f);
    let world = rig.bind_pose_positions().unwrap();
    let want = reference_skinning(&f, None);
    let err = world
        .iter()
        .zip(&want)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(err < 1e-9, "{err}");
    let height = world.iter().map(|p| p.z).fold(f64::NEG_INFINITY, f64::max)
        - world.iter().map(|p| p.z).fold(f64::INFINITY, f64::min);
    assert!((diagonal(&world) / diagonal(&rig.mesh.positions) - 0.01).abs() < 1e-6);
    assert!(
        height.abs() > 0.019,
        "stood up along the turned axis: {height}"
    );
}

/// A thousand primitives of one mesh, and a second node sharing the skin: every instance is
/// read, in order of mesh, primitive, node.
#[test]
fn many_primitives_and_a_shared_skin() {
    let f = two_joint_bar(Bar {
        primitives: 1000,
        ..Bar::default()
    });
    let rig = check("thousand-primitives", &f);
    assert_eq!(rig.primitives.len(), 1000);
    let f = two_joint_bar(Bar {
        shared: true,
        ..Bar::default()
    });
    let rig = check("shared-skin", &f);
    assert_eq!(rig.primitives.len(), 2);
    assert_eq!(rig.joints.len(), 2, "one skin, its joints once");
}

/// No animation: asking for one says so; the rest pose works.
#[test]
fn no_animation() {
    let f = two_joint_bar(Bar {
        animated: false,
        ..Bar::default()
    });
    let rig = check("no-animation", &f);
    let e = rig.animation_index("0").unwrap_err().to_string();
    assert!(e.contains("this model has no animations"), "{e}");
}

/// Morph targets at default weights (the node's overriding the mesh's, as glTF says): the rest
/// shape has them applied before skinning; the targets and weights are kept through writing
/// and a cut (the cut's new vertices get interpolated offsets).
#[test]
fn morph_targets_at_default_weights() {
    let mut f = two_joint_bar(Bar::default());
    let (pos, _) = bar(9);
    let n = pos.len() / 3;
    // Target 0 pushes the top ring along x, target 1 moves everything along z (with normals).
    let top: Vec<f32> = pos
        .chunks_exact(3)
        .flat_map(|p| {
            if p[1] > 1.99 {
                [0.3, 0.0, 0.0]
            } else {
                [0.0; 3]
            }
        })
        .collect();
    let t0 = f.floats(&top, "VEC3", n);
    let t1 = f.floats(&[0.0, 0.0, 0.1].repeat(n), "VEC3", n);
    let t1n = f.floats(&[0.0, 0.0, 0.0].repeat(n), "VEC3", n);
    // Base normals (radial), so the normal offsets have a base to apply to.
    let radial: Vec<f32> = pos
        .chunks_exact(3)
        .flat_map(|p| {
            DVec3::new(p[0] as f64, 0.0, p[2] as f64)
                .normalize()
                .as_vec3()
                .to_array()
        })
        .collect();
    let normals = f.floats(&radial, "VEC3", n);
    f.json["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = json!(normals);
    f.json["meshes"][0]["primitives"][0]["targets"] =
        json!([{"POSITION": t0}, {"POSITION": t1, "NORMAL": t1n}]);
    f.json["meshes"][0]["weights"] = json!([0.0, 0.0]);
    f.json["nodes"][3]["weights"] = json!([0.5, 1.0]);
    let rig = check("morph-targets", &f);
    assert_eq!(rig.look.morph_weights, vec![0.5, 1.0]);
    // The top ring's first vertex: (0.2, 2, 0.2) + 0.5 (0.3, 0, 0) + (0, 0, 0.1).
    let v = rig.mesh.positions[n - 4];
    assert!(v.distance(DVec3::new(0.35, 2.0, 0.3)) < 1e-6, "{v}");
    // Written and read back: the same rest shape, the same targets.
    let bytes = glb_bytes(&rig, &GlbOptions::default()).unwrap();
    let back = parse_gltf(&bytes, "morph back", None).unwrap();
    assert_eq!(back.look.morph_weights, rig.look.morph_weights);
    let far = back
        .mesh
        .positions
        .iter()
        .zip(&rig.mesh.positions)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(far < 1e-6, "{far}");
    let names: Vec<&str> = back
        .look
        .attributes
        .iter()
        .map(|a| a.name.as_str())
        .collect();
    for want in ["TARGET0_POSITION", "TARGET1_POSITION", "TARGET1_NORMAL"] {
        assert!(names.contains(&want), "{names:?}");
    }
}
