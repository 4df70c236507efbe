//! Free-form deformation: identity, partition of unity, rigid motions, the 180-degree twist
//! (motor vs positional), bad input.

use cga::ScaledMotor;
use deform::blend::control::ControlForm;
use deform::blend::KeyError;
use deform::deformers::ffd::{Ffd, FfdError, FfdOptions, Lattice, LatticeBasis};
use deform::deformers::DeformError;
use deform::mesh::shapes;
use deform::{BlendMethod, Deformer, Mesh};
use glam::{DQuat, DVec3};

fn bar() -> Mesh {
    shapes::tube(1.0, 10.0, 24, 41)
}

fn options(basis: LatticeBasis, form: ControlForm) -> FfdOptions {
    FfdOptions { basis, form }
}

const BASES: [LatticeBasis; 3] = [
    LatticeBasis::Bernstein,
    LatticeBasis::BSpline(2),
    LatticeBasis::BSpline(3),
];
const FORMS: [ControlForm; 3] = [
    ControlForm::Positional,
    ControlForm::Motor(BlendMethod::MotorLog),
    ControlForm::Motor(BlendMethod::DualQuaternion),
];

#[test]
fn identity_motors_leave_the_mesh_unchanged() {
    let mesh = bar();
    for basis in BASES {
        for form in FORMS {
            let d = Ffd::bind(&mesh, [4, 3, 5], None, options(basis, form)).unwrap();
            let keys = vec![ScaledMotor::IDENTITY; d.key_count()];
            let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
            d.pose(&keys, &mut out).unwrap();
            for (a, b) in out.iter().zip(&mesh.positions) {
                assert!(a.distance(*b) < 1e-12, "{basis:?} {form:?}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn weights_are_a_partition_of_unity_and_non_negative() {
    let mesh = bar();
    for basis in BASES {
        let lattice = Lattice::new(
            [5, 4, 3],
            DVec3::splat(-1.5),
            DVec3::new(11.0, 1.5, 1.5),
            basis,
        )
        .unwrap();
        let w = lattice.weights(&mesh.positions).unwrap();
        for i in 0..mesh.vertex_count() {
            let row = w.row(i);
            let sum: f64 = row.weights.iter().sum();
            assert!((sum - 1.0).abs() < 1e-12, "{basis:?} vertex {i}: {sum}");
            assert!(row.weights.iter().all(|&x| x >= 0.0));
        }
    }
}

#[test]
fn a_rigid_motion_of_the_whole_lattice_moves_the_mesh_rigidly() {
    let mesh = bar();
    let r = ScaledMotor::from_scale_rotation_translation(
        1.0,
        DQuat::from_axis_angle(DVec3::new(1.0, 2.0, -0.5).normalize(), 2.1),
        DVec3::new(0.3, -4.0, 7.0),
    );
    for basis in BASES {
        for form in FORMS {
            let d = Ffd::bind(&mesh, [3, 3, 3], None, options(basis, form)).unwrap();
            let keys = vec![r; d.key_count()];
            let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
            d.pose(&keys, &mut out).unwrap();
            for (a, b) in out.iter().zip(&mesh.positions) {
                let e = r.transform_point(*b);
                assert!(a.distance(e) < 1e-10, "{basis:?} {form:?}: {a} vs {e}");
            }
        }
    }
}

/// The area of the polygon of ring `r` (projected onto the y-z plane after removing x).
fn ring_area(p: &[DVec3], sides: usize, r: usize) -> f64 {
    let ring = &p[r * sides..(r + 1) * sides];
    let c = ring.iter().copied().sum::<DVec3>() / sides as f64;
    (0..sides)
        .map(|k| {
            let a = ring[k] - c;
            let b = ring[(k + 1) % sides] - c;
            0.5 * a.cross(b).x
        })
        .sum::<f64>()
        .abs()
}

#[test]
fn a_180_degree_twist_keeps_the_cross_section_with_motors_and_collapses_it_with_points() {
    let (sides, rings) = (24, 41);
    let mesh = shapes::tube(1.0, 10.0, sides, rings);
    let lo = DVec3::new(0.0, -1.0, -1.0);
    let hi = DVec3::new(10.0, 1.0, 1.0);
    let rest_area = ring_area(&mesh.positions, sides, rings / 2);
    let mut areas = Vec::new();
    for form in [
        ControlForm::Motor(BlendMethod::MotorLog),
        ControlForm::Positional,
    ] {
        let d = Ffd::bind(
            &mesh,
            [2, 2, 2],
            Some((lo, hi)),
            options(LatticeBasis::Bernstein, form),
        )
        .unwrap();
        // Two lattice layers (u = 0 and u = 1), rotated -90 and +90 degrees about the bar's axis.
        let keys: Vec<ScaledMotor> = (0..8)
            .map(|k| {
                let angle = if k % 2 == 0 { -90f64 } else { 90.0 };
                ScaledMotor::from_scale_rotation_translation(
                    1.0,
                    DQuat::from_axis_angle(DVec3::X, angle.to_radians()),
                    DVec3::ZERO,
                )
            })
            .collect();
        let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
        d.pose(&keys, &mut out).unwrap();
        // The two end layers of the lattice point are where the motors put them, in both forms.
        let area = ring_area(&out, sides, rings / 2);
        areas.push(area / rest_area);
    }
    eprintln!(
        "mid cross-section area ratio: motor {:.4}, positional {:.4}",
        areas[0], areas[1]
    );
    assert!((areas[0] - 1.0).abs() < 0.02, "motor FFD: {}", areas[0]);
    assert!(areas[1] < 0.5, "positional FFD: {}", areas[1]);
}

#[test]
fn bad_lattices_and_keys_are_typed_errors() {
    let mesh = bar();
    let flat = Ffd::bind(
        &mesh,
        [2, 2, 2],
        Some((DVec3::ZERO, DVec3::new(10.0, 0.0, 1.0))),
        FfdOptions::default(),
    );
    assert!(matches!(
        flat,
        Err(DeformError::Ffd(FfdError::ZeroExtent { axis: 1, .. }))
    ));
    let small = Ffd::bind(
        &mesh,
        [2, 2, 2],
        Some((DVec3::splat(-1.0), DVec3::new(5.0, 1.0, 1.0))),
        FfdOptions::default(),
    );
    match small {
        Err(DeformError::Ffd(FfdError::Outside { vertex, .. })) => {
            assert!(mesh.positions[vertex].x > 5.0)
        }
        other => panic!("expected Outside, got {other:?}"),
    }
    let dims = Ffd::bind(&mesh, [1, 2, 2], None, FfdOptions::default());
    assert!(matches!(dims, Err(DeformError::Ffd(FfdError::Dims { .. }))));
    let degree = Ffd::bind(
        &mesh,
        [5, 5, 5],
        None,
        options(LatticeBasis::BSpline(7), ControlForm::Positional),
    );
    assert!(matches!(degree, Err(DeformError::Ffd(FfdError::Degree(7)))));
    let nan = Ffd::bind(
        &mesh,
        [2, 2, 2],
        Some((DVec3::splat(f64::NAN), DVec3::ONE)),
        FfdOptions::default(),
    );
    assert!(matches!(
        nan,
        Err(DeformError::Ffd(FfdError::ZeroExtent { .. }))
    ));
    for form in FORMS {
        let d = Ffd::bind(
            &mesh,
            [2, 2, 2],
            None,
            options(LatticeBasis::Bernstein, form),
        )
        .unwrap();
        let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
        let wrong = d.pose(&[ScaledMotor::IDENTITY; 7], &mut out);
        assert!(matches!(
            wrong,
            Err(DeformError::Keys(KeyError::WrongCount { got: 7, .. }))
        ));
        assert!(out.iter().all(|p| *p == DVec3::ZERO), "untouched on error");
    }
}

#[test]
fn positional_ffd_by_points_matches_the_lattice_moved_by_motors() {
    let mesh = bar();
    let d = Ffd::bind(
        &mesh,
        [3, 2, 2],
        None,
        options(LatticeBasis::Bernstein, ControlForm::Positional),
    )
    .unwrap();
    let shift = ScaledMotor::from_scale_rotation_translation(1.0, DQuat::IDENTITY, DVec3::Y);
    let mut keys = vec![ScaledMotor::IDENTITY; 12];
    keys[1] = shift; // the middle of the bottom-front row
    let mut a = vec![DVec3::ZERO; mesh.vertex_count()];
    d.pose(&keys, &mut a).unwrap();
    let mut points = d.binding().rest_points().to_vec();
    points[1] += DVec3::Y;
    let mut b = vec![DVec3::ZERO; mesh.vertex_count()];
    d.binding().pose_points(&points, &mut b).unwrap();
    assert_eq!(a, b);
    assert!(a
        .iter()
        .zip(&mesh.positions)
        .any(|(p, q)| p.distance(*q) > 0.1));
}

#[test]
fn a_vertex_that_is_not_finite_is_a_typed_error() {
    let mut mesh = bar();
    mesh.positions[3].y = f64::INFINITY;
    let box_ = Some((DVec3::splat(-2.0), DVec3::splat(12.0)));
    match Ffd::bind(&mesh, [2, 2, 2], box_, FfdOptions::default()) {
        Err(DeformError::Ffd(FfdError::Outside { vertex: 3, .. })) => {}
        other => panic!("expected Outside at vertex 3, got {other:?}"),
    }
}
