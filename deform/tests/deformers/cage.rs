//! Cage coordinates: identity, partition of unity, linear precision of MVC, harmonic
//! coordinates in [0, 1], rigid motions, the shared model/cage pairs, bad cages.

use crate::common;
use deform::deformers::DeformError;

use cga::ScaledMotor;
use deform::blend::control::ControlForm;
use deform::blend::KeyError;
use deform::deformers::cage::{
    check_cage, check_encloses, harmonic_cage_coordinates, mean_value_coordinates, CageCoordinates,
    CageDeformer, CageError, CageOptions, HarmonicGrid,
};
use deform::mesh::{io, shapes};
use deform::{BlendMethod, Deformer, Mesh};
use glam::{DMat3, DQuat, DVec3};

/// An axis-aligned box cage of 8 corners and 12 outward faces.
fn box_cage(lo: DVec3, hi: DVec3) -> Mesh {
    let p = (0..8)
        .map(|i| {
            DVec3::new(
                if i & 1 == 0 { lo.x } else { hi.x },
                if i & 2 == 0 { lo.y } else { hi.y },
                if i & 4 == 0 { lo.z } else { hi.z },
            )
        })
        .collect();
    let t = vec![
        [0, 2, 3],
        [0, 3, 1],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [0, 4, 6],
        [0, 6, 2],
        [1, 3, 7],
        [1, 7, 5],
    ];
    Mesh::new(p, t)
}

/// A non-convex cage: an icosphere with some vertices pulled in.
fn dented_cage() -> Mesh {
    let mut c = shapes::icosphere(2.0, 1);
    for (i, p) in c.positions.iter_mut().enumerate() {
        if i % 5 == 0 {
            *p *= 0.8;
        }
    }
    c
}

fn model() -> Mesh {
    shapes::icosphere(1.2, 2)
}

const FORMS: [ControlForm; 2] = [
    ControlForm::Positional,
    ControlForm::Motor(BlendMethod::MotorLog),
];

#[test]
fn identity_motors_leave_the_model_unchanged() {
    let m = model();
    for cage in [
        dented_cage(),
        box_cage(DVec3::splat(-2.0), DVec3::splat(2.0)),
    ] {
        for form in FORMS {
            let d = CageDeformer::bind(
                &m,
                &cage,
                CageOptions {
                    form,
                    ..CageOptions::default()
                },
            )
            .unwrap();
            let keys = vec![ScaledMotor::IDENTITY; cage.vertex_count()];
            let mut out = vec![DVec3::ZERO; m.vertex_count()];
            d.pose(&keys, &mut out).unwrap();
            for (a, b) in out.iter().zip(&m.positions) {
                assert!(a.distance(*b) < 1e-12, "{form:?}: {a} vs {b}");
            }
        }
    }
}

/// Mean value coordinates read the cage's faces only after checking them: an index past the
/// cage panicked, an empty cage gave `Ok` with no weights.
#[test]
fn mvc_of_a_cage_that_cannot_be_read_are_refused() {
    let points = [DVec3::splat(0.1)];
    let mut past = dented_cage();
    past.triangles[0] = [0, 2, 99];
    let mut nan = dented_cage();
    nan.positions[1].x = f64::NAN;
    let empty = deform::Mesh::new(Vec::new(), Vec::new());
    for (cage, what) in [
        (past, "faces [0] have out-of-range"),
        (nan, "[1]"),
        (empty, "0 vertices"),
    ] {
        let e = mean_value_coordinates(&cage, &points)
            .expect_err(what)
            .to_string();
        assert!(e.contains(what), "{e}");
    }
}

#[test]
fn mvc_are_a_partition_of_unity_with_linear_precision() {
    let cage = dented_cage();
    let mut points = model().positions;
    // Special cases: a cage vertex, a face centroid, an edge midpoint, near a face.
    let t = cage.triangles[3];
    let [a, b, c] = cage.corners(3);
    points.extend([
        a,
        (a + b + c) / 3.0,
        0.5 * (a + b),
        (a + b + c) / 3.0 * (1.0 - 1e-6),
    ]);
    let _ = t;
    let w = mean_value_coordinates(&cage, &points).unwrap();
    let m = cage.vertex_count();
    let affine = |p: DVec3| {
        DMat3::from_cols_array(&[1.2, -0.3, 0.5, 0.7, 0.9, -1.1, 0.2, 0.4, 2.0]) * p
            + DVec3::new(3.0, -1.0, 0.5)
    };
    let moved: Vec<DVec3> = cage.positions.iter().map(|&p| affine(p)).collect();
    for (i, &p) in points.iter().enumerate() {
        let row = &w[i * m..(i + 1) * m];
        assert!(row.iter().all(|x| x.is_finite()));
        assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-12, "point {i}");
        let rebuilt: DVec3 = row.iter().zip(&cage.positions).map(|(w, q)| *w * *q).sum();
        assert!(rebuilt.distance(p) < 1e-10, "point {i}: {rebuilt} vs {p}");
        let mapped: DVec3 = row.iter().zip(&moved).map(|(w, q)| *w * *q).sum();
        assert!(mapped.distance(affine(p)) < 1e-10, "point {i}: affine");
    }
    let first = points.len() - 4;
    assert!(
        (w[first * m + t[0] as usize] - 1.0).abs() < 1e-15,
        "at a cage vertex"
    );
}

#[test]
fn harmonic_coordinates_are_in_unit_interval_and_sum_to_one() {
    let cage = dented_cage();
    let points = model().positions;
    let w = harmonic_cage_coordinates(&cage, &points, HarmonicGrid { resolution: 32 }).unwrap();
    let m = cage.vertex_count();
    for i in 0..points.len() {
        let row = &w[i * m..(i + 1) * m];
        assert!(row.iter().all(|&x| (0.0..=1.0).contains(&x)), "point {i}");
        assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        // Linear precision only up to a fraction of the grid spacing (4 / 31 here).
        let rebuilt: DVec3 = row.iter().zip(&cage.positions).map(|(w, q)| *w * *q).sum();
        assert!(
            rebuilt.distance(points[i]) < 0.5 * 4.0 / 31.0,
            "point {i}: {rebuilt}"
        );
    }
}

#[test]
fn a_rigid_motion_of_the_whole_cage_moves_the_model_rigidly() {
    let m = model();
    let cage = dented_cage();
    let r = ScaledMotor::from_scale_rotation_translation(
        1.0,
        DQuat::from_axis_angle(DVec3::new(0.2, -1.0, 0.4).normalize(), 2.5),
        DVec3::new(-2.0, 1.0, 4.0),
    );
    let coordinates = [
        CageCoordinates::MeanValue,
        CageCoordinates::Harmonic(HarmonicGrid { resolution: 24 }),
    ];
    for coordinates in coordinates {
        for form in FORMS {
            let d = CageDeformer::bind(
                &m,
                &cage,
                CageOptions {
                    coordinates,
                    form,
                    ..CageOptions::default()
                },
            )
            .unwrap();
            // The rest reconstruction: the model itself, except for positional harmonic
            // coordinates, whose linear precision is that of the grid.
            let mut rest = vec![DVec3::ZERO; m.vertex_count()];
            d.pose(&vec![ScaledMotor::IDENTITY; cage.vertex_count()], &mut rest)
                .unwrap();
            let mut out = vec![DVec3::ZERO; m.vertex_count()];
            d.pose(&vec![r; cage.vertex_count()], &mut out).unwrap();
            for (a, b) in out.iter().zip(&rest) {
                let e = r.transform_point(*b);
                assert!(
                    a.distance(e) < 1e-10,
                    "{coordinates:?} {form:?}: {a} vs {e}"
                );
            }
        }
    }
}

#[test]
fn the_shared_model_cage_pairs_bind_and_the_partial_cage_is_refused() {
    let Some(dir) = common::mesh_path("cages") else {
        return;
    };
    let read = |f: &str| io::read_mesh(dir.join(f)).unwrap();
    for (model, cage) in [
        ("armadillo-dense.obj", "armadillo-cage-robust-6.obj"),
        ("bar.OBJ", "bar_cage.OBJ"),
        ("cactus-dense.obj", "cactus_cage.obj"),
        ("hand_bones.obj", "hand_bones_cage_coarse.obj"),
    ] {
        let (model, cage) = (read(model), read(cage));
        let options = CageOptions {
            // The cactus cage's faces cross (37 pairs, for example faces 11 and 95): refused unless
            // allowed.
            allow_self_intersecting: true,
            ..CageOptions::default()
        };
        let d = CageDeformer::bind(&model, &cage, options).unwrap();
        let mut out = vec![DVec3::ZERO; model.vertex_count()];
        d.pose(&vec![ScaledMotor::IDENTITY; cage.vertex_count()], &mut out)
            .unwrap();
        assert!(out
            .iter()
            .zip(&model.positions)
            .all(|(a, b)| a.distance(*b) < 1e-9));
    }
    match check_cage(&read("cactus_cage.obj")) {
        Err(DeformError::Cage(CageError::SelfIntersecting { pairs, first })) => {
            assert_eq!((pairs, first), (37, [11, 90]))
        }
        other => panic!("expected SelfIntersecting, got {other:?}"),
    }
    let partial = read("bar_cage_partial.OBJ");
    check_cage(&partial).unwrap();
    match check_encloses(&partial, &read("bar.OBJ").positions) {
        Err(DeformError::Cage(CageError::NotEnclosing { count, .. })) => assert!(count > 0),
        other => panic!("expected NotEnclosing, got {other:?}"),
    }
}

#[test]
fn bad_cages_and_keys_are_typed_errors() {
    let m = model();
    let cage = dented_cage();
    let mut open = cage.clone();
    open.triangles.pop();
    assert!(matches!(
        check_cage(&open),
        Err(DeformError::Cage(CageError::Open { .. }))
    ));
    let mut shared = cage.clone();
    let t = shared.triangles[0];
    shared.triangles.push(t);
    assert!(matches!(
        check_cage(&shared),
        Err(DeformError::Cage(CageError::NonManifold { .. }))
    ));
    let mut flat = box_cage(DVec3::splat(-2.0), DVec3::splat(2.0));
    flat.positions[7] = flat.positions[3]; // corner 7 collapses onto corner 3
    assert!(matches!(
        check_cage(&flat),
        Err(DeformError::Cage(CageError::Degenerate { .. }))
    ));
    let mut nan = cage.clone();
    nan.positions[2].x = f64::NAN;
    assert!(matches!(
        check_cage(&nan),
        Err(DeformError::Cage(CageError::NonFinite { .. }))
    ));
    let small = shapes::icosphere(0.5, 1);
    match CageDeformer::bind(&m, &small, CageOptions::default()) {
        Err(DeformError::Cage(CageError::NotEnclosing { count, .. })) => {
            assert_eq!(count, m.vertex_count())
        }
        other => panic!("expected NotEnclosing, got {other:?}"),
    }
    let grid = harmonic_cage_coordinates(&cage, &m.positions, HarmonicGrid { resolution: 2 });
    assert!(matches!(grid, Err(DeformError::Cage(CageError::Grid(_)))));
    for form in FORMS {
        let d = CageDeformer::bind(
            &m,
            &cage,
            CageOptions {
                form,
                ..CageOptions::default()
            },
        )
        .unwrap();
        let mut out = vec![DVec3::ZERO; m.vertex_count()];
        let wrong = d.pose(&[ScaledMotor::IDENTITY; 3], &mut out);
        assert!(matches!(
            wrong,
            Err(DeformError::Keys(KeyError::WrongCount { got: 3, .. }))
        ));
    }
}

#[test]
fn winding_numbers_from_the_coordinates_match_the_direct_ones() {
    let cage = dented_cage();
    let mut points = model().positions;
    points.extend([DVec3::splat(5.0), DVec3::new(0.0, 0.0, -3.0)]);
    let (_, w) = deform::deformers::cage::coordinates_and_winding(&cage, &points).unwrap();
    for (i, &p) in points.iter().enumerate() {
        let direct = deform::deformers::cage::winding_number(&cage, p);
        assert!(
            (w[i] - direct).abs() < 1e-9,
            "point {i}: {} vs {direct}",
            w[i]
        );
        let inside = i < points.len() - 2;
        assert!((direct - if inside { 1.0 } else { 0.0 }).abs() < 1e-9);
    }
}

#[test]
fn a_self_intersecting_cage_is_refused() {
    // Push one vertex of a box cage through the opposite face.
    let mut cage = box_cage(DVec3::splat(-2.0), DVec3::splat(2.0));
    cage.positions[7] = DVec3::new(-3.0, -1.0, -1.5);
    match check_cage(&cage) {
        Err(DeformError::Cage(CageError::SelfIntersecting { pairs, .. })) => assert!(pairs > 0),
        other => panic!("expected SelfIntersecting, got {other:?}"),
    }
    assert!(deform::deformers::cage::intersect::self_intersections(&dented_cage(), 10).is_empty());
}

#[test]
fn a_model_vertex_that_is_not_finite_is_a_typed_error() {
    let mut m = model();
    m.positions[5] = DVec3::new(f64::NAN, 0.0, 0.0);
    let cage = dented_cage();
    for coordinates in [
        CageCoordinates::MeanValue,
        CageCoordinates::Harmonic(HarmonicGrid { resolution: 16 }),
    ] {
        let options = CageOptions {
            coordinates,
            ..CageOptions::default()
        };
        match CageDeformer::bind(&m, &cage, options) {
            Err(DeformError::Cage(CageError::NotEnclosing { vertices, .. })) => {
                assert_eq!(vertices.0, vec![5])
            }
            other => panic!("{coordinates:?}: expected NotEnclosing, got {other:?}"),
        }
    }
}
