//! FABRIK and the chain deformer (first paper, section IV): inverse kinematics that drives a
//! spline-aligned deformation.

use super::spline::{bar, RINGS, SIDES};
use deform::deformers::fabrik::fabrik;
use deform::deformers::fabrik::{chain_key_motors, FabrikOptions, FabrikStatus};
use deform::deformers::spline::SplineOptions;
use deform::mesh::shapes::tube_ring;
use deform::ChainDeformer;
use glam::DVec3;

fn chain(n: usize) -> Vec<DVec3> {
    (0..n)
        .map(|i| DVec3::new(i as f64 * 2.5, 0.0, 0.0))
        .collect()
}

#[test]
fn fabrik_reaches_reachable_targets_and_stretches_towards_the_others() {
    let rest = chain(5); // length 10
    let opts = FabrikOptions {
        tolerance: 1e-8,
        max_iterations: 500,
    };
    for target in [
        DVec3::new(5.0, 5.0, 0.0),
        DVec3::new(0.0, 0.0, 7.0),
        DVec3::new(-3.0, 2.0, 1.0),
    ] {
        let s = fabrik(&rest, target, &opts).unwrap();
        assert_eq!(s.status, FabrikStatus::Reached, "{target}");
        assert!(s.distance <= 1e-8 && s.joints[4].distance(target) <= 1e-8);
        assert_eq!(s.joints[0], rest[0]);
        for w in s.joints.windows(2) {
            assert!((w[0].distance(w[1]) - 2.5).abs() < 1e-9);
        }
    }
    let far = DVec3::new(0.0, 30.0, 0.0);
    let s = fabrik(&rest, far, &opts).unwrap();
    assert_eq!(s.status, FabrikStatus::Unreachable);
    assert!((s.distance - 20.0).abs() < 1e-9);
    assert!(s.joints.iter().all(|p| p.x.abs() < 1e-12 && p.y >= 0.0));
    assert!(fabrik(&rest[..1], far, &opts).is_err());
    assert!(fabrik(&[DVec3::ZERO, DVec3::ZERO], far, &opts).is_err());
    assert!(fabrik(&rest, DVec3::NAN, &opts).is_err());
}

#[test]
fn chain_keys_map_rest_joints_onto_posed_joints() {
    let rest = chain(5);
    let s = fabrik(&rest, DVec3::new(4.0, 6.0, 1.0), &FabrikOptions::default()).unwrap();
    let keys = chain_key_motors(&rest, &s.joints).unwrap();
    for (i, k) in keys.iter().enumerate() {
        assert!((k.transform_point(rest[i]) - s.joints[i]).length() < 1e-9);
    }
}

#[test]
fn a_chain_bends_a_bar_through_ik_in_one_call() {
    let mesh = bar();
    let joints = chain(5);
    let d = ChainDeformer::bind(
        &mesh,
        &tube_ring(SIDES, 0),
        &tube_ring(SIDES, RINGS - 1),
        &joints,
        5,
        SplineOptions::default(),
    )
    .unwrap();
    let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
    // The rest target leaves the mesh in place.
    let r = d
        .pose_to_target(joints[4], &FabrikOptions::default(), &mut out)
        .unwrap();
    assert_eq!(r.solution.status, FabrikStatus::Reached);
    let err = out
        .iter()
        .zip(&mesh.positions)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(err < 1e-9, "{err}");
    // A raised target bends the bar upwards. With as many controls as joints the fit
    // interpolates, so the end rings turn about the root joint and sit on the end effector.
    let target = DVec3::new(7.0, 5.0, 0.0);
    let r = d
        .pose_to_target(target, &FabrikOptions::default(), &mut out)
        .unwrap();
    assert_eq!(r.solution.status, FabrikStatus::Reached);
    assert!(r.fit.max_residual < 1e-9);
    let centre = |ring: usize| -> DVec3 {
        tube_ring(SIDES, ring)
            .iter()
            .map(|&v| out[v as usize])
            .sum::<DVec3>()
            / SIDES as f64
    };
    assert!(centre(0).length() < 1e-9, "{}", centre(0));
    assert!(
        centre(RINGS - 1).distance(target) < 1e-6,
        "{}",
        centre(RINGS - 1)
    );
    assert!(out.iter().all(|p| p.is_finite()));
}
