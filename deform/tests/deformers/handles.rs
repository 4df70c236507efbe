//! Motor handles on harmonic coordinates (first paper, section IV), on the libigl Max Planck
//! bust with its selection file.

use crate::common;
use deform::deformers::DeformError;
use deform::mesh::MeshError;

use cga::ScaledMotor;
use deform::blend::KeyError;
use deform::deformers::handles::HandleOptions;
use deform::mesh::io::{read_dmat, read_mesh};
use deform::{Deformer, MotorHandles};
use glam::{DQuat, DVec3};

#[test]
fn handles_on_max_follow_their_motors_and_coordinates_sum_to_one() {
    let (Some(mesh_path), Some(sel_path)) = (
        common::mesh_path("libigl/decimated-max.obj"),
        common::mesh_path("libigl/decimated-max-selection.dmat"),
    ) else {
        return;
    };
    let mesh = read_mesh(&mesh_path).unwrap();
    let sel = read_dmat(&sel_path).unwrap();
    let groups: Vec<Vec<u32>> = (0..3).map(|g| sel.rows_equal_to(g).unwrap()).collect();
    let sets: Vec<&[u32]> = groups.iter().map(Vec::as_slice).collect();
    let bound = MotorHandles::bind_with(
        &mesh,
        &sets,
        &[ScaledMotor::IDENTITY; 3],
        HandleOptions::default(),
    )
    .unwrap();
    for i in 0..mesh.vertex_count() {
        let sum: f64 = (0..3).map(|j| bound.coordinate(i, j)).sum();
        assert!((sum - 1.0).abs() < 1e-10, "vertex {i}: {sum}");
    }
    let bb = mesh.bounding_box().unwrap();
    let c = bb.center();
    let keys = [
        ScaledMotor::IDENTITY,
        ScaledMotor::from_scale_rotation_translation(
            1.0,
            DQuat::from_rotation_y(0.6),
            DVec3::new(0.0, 0.1, 0.0) * bb.diagonal(),
        ),
        ScaledMotor::from_scale_rotation_translation(
            1.3,
            DQuat::from_rotation_z(-0.4),
            c - 1.3 * (DQuat::from_rotation_z(-0.4) * c),
        ),
    ];
    let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
    bound.pose(&keys, &mut out).unwrap();
    let tol = 1e-12 * bb.diagonal();
    for (j, g) in groups.iter().enumerate() {
        for &v in g {
            let expect = keys[j].transform_point(mesh.positions[v as usize]);
            assert!(
                out[v as usize].distance(expect) < tol,
                "handle {j} vertex {v}"
            );
        }
    }
    assert!(out.iter().all(|p| p.is_finite()));
}

#[test]
fn bad_handle_sets_are_typed_errors() {
    let mesh = deform::mesh::shapes::icosphere(1.0, 1);
    let r = MotorHandles::bind(&mesh, &[&[0, 1], &[]], Default::default());
    assert!(matches!(
        r,
        Err(DeformError::Keys(KeyError::EmptyHandle { set: 1 }))
    ));
    let r = MotorHandles::bind(&mesh, &[&[0, 1], &[1, 2]], Default::default());
    assert!(matches!(
        r,
        Err(DeformError::Mesh(MeshError::OverlappingConstraints { .. }))
    ));
    let r = MotorHandles::bind(&mesh, &[&[0, 1], &[1000]], Default::default());
    assert!(matches!(
        r,
        Err(DeformError::Mesh(MeshError::ConstraintOutOfRange { .. }))
    ));
    let r = MotorHandles::bind(&mesh, &[], Default::default());
    assert!(matches!(
        r,
        Err(DeformError::Keys(KeyError::WrongCount { .. }))
    ));
    let b = MotorHandles::bind(&mesh, &[&[0], &[5]], Default::default()).unwrap();
    let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
    assert!(b.pose(&[ScaledMotor::IDENTITY], &mut out).is_err());
    assert!(b.pose(&[ScaledMotor::IDENTITY; 2], &mut out[1..]).is_err());
    let mut nan = ScaledMotor::IDENTITY;
    nan.e12 = f64::INFINITY;
    assert!(matches!(
        b.pose(&[ScaledMotor::IDENTITY, nan], &mut out),
        Err(DeformError::Keys(KeyError::Invalid { index: 1, .. }))
    ));
}
