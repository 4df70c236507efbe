//! Spline-aligned deformation, B-spline fitting, FABRIK and the blend baselines (first paper,
//! sections III and IV) against closed forms and invariants.

use cga::{Motor, ScaledMotor};
use deform::blend::KeyError;
use deform::deformers::bspline::{bspline_motor, fit_bspline, FitSolver};
use deform::deformers::spline::{SplineOptions, WeightScheme};
use deform::deformers::DeformError;
use deform::mesh::shapes::{tube, tube_ring};
use deform::mesh::MeshError;
use deform::operators::SolveError;
use deform::{BlendMethod, Deformer, SplineDeformer};
use glam::{DQuat, DVec3};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

pub(crate) const SIDES: usize = 24;
pub(crate) const RINGS: usize = 41;
const LENGTH: f64 = 10.0;

pub(crate) fn bar() -> deform::Mesh {
    tube(1.0, LENGTH, SIDES, RINGS)
}

fn keys_of(motors: &[Motor]) -> Vec<ScaledMotor> {
    motors.iter().map(|&m| ScaledMotor::from(m)).collect()
}

fn rotation_about(axis: DVec3, angle: f64, center: DVec3) -> ScaledMotor {
    let q = DQuat::from_axis_angle(axis, angle);
    ScaledMotor::from_scale_rotation_translation(1.0, q, center - q * center)
}

/// `lambda = x / L` (the exact parameter along the bar).
fn lambda_along(mesh: &deform::Mesh) -> Vec<f64> {
    mesh.positions.iter().map(|p| p.x / LENGTH).collect()
}

fn bind_bar(keys: usize, scheme: WeightScheme, method: BlendMethod) -> SplineDeformer {
    let mesh = bar();
    SplineDeformer::bind(
        &mesh,
        &tube_ring(SIDES, 0),
        &tube_ring(SIDES, RINGS - 1),
        &vec![ScaledMotor::IDENTITY; keys],
        SplineOptions {
            scheme,
            method,
            ..SplineOptions::default()
        },
    )
    .unwrap()
}

fn key_count(scheme: WeightScheme) -> usize {
    match scheme {
        WeightScheme::Linear => 2,
        WeightScheme::Quadratic => 3,
        WeightScheme::Bezier | WeightScheme::BSpline => 4,
    }
}

#[test]
fn identity_keys_leave_the_mesh_unchanged() {
    let mesh = bar();
    for scheme in WeightScheme::ALL {
        for method in BlendMethod::ALL {
            let n = key_count(scheme);
            let d = bind_bar(n, scheme, method);
            let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
            d.pose(&vec![ScaledMotor::IDENTITY; n], &mut out).unwrap();
            let err = out
                .iter()
                .zip(&mesh.positions)
                .map(|(a, b)| a.distance(*b))
                .fold(0.0, f64::max);
            let tol = if method == BlendMethod::MatrixF32 {
                1e-5
            } else {
                1e-12
            };
            assert!(err < tol, "{scheme:?} {method:?}: {err}");
        }
    }
}

#[test]
fn lambda_is_harmonic_and_clamped_on_the_handles() {
    let d = bind_bar(4, WeightScheme::BSpline, BlendMethod::MotorLog);
    let l = d.lambda();
    assert!(tube_ring(SIDES, 0).iter().all(|&v| l[v as usize] == 0.0));
    assert!(tube_ring(SIDES, RINGS - 1)
        .iter()
        .all(|&v| l[v as usize] == 1.0));
    assert!(l.iter().all(|x| (0.0..=1.0).contains(x)));
    // Symmetric bar: the middle ring is at one half.
    for v in tube_ring(SIDES, RINGS / 2) {
        assert!((l[v as usize] - 0.5).abs() < 1e-9, "{}", l[v as usize]);
    }
}

#[test]
fn a_translation_key_moves_the_last_handle_rigidly() {
    let mesh = bar();
    let t = DVec3::new(0.5, 2.0, -1.0);
    for scheme in WeightScheme::ALL {
        let n = key_count(scheme);
        let d = bind_bar(n, scheme, BlendMethod::MotorLog);
        let mut keys = vec![ScaledMotor::IDENTITY; n];
        keys[n - 1] = ScaledMotor::from(Motor::from_translation(t));
        let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
        d.pose(&keys, &mut out).unwrap();
        for v in tube_ring(SIDES, RINGS - 1) {
            let v = v as usize;
            assert!(
                (out[v] - (mesh.positions[v] + t)).length() < 1e-12,
                "{scheme:?}"
            );
        }
        for v in tube_ring(SIDES, 0) {
            let v = v as usize;
            assert!((out[v] - mesh.positions[v]).length() < 1e-12, "{scheme:?}");
        }
    }
}

#[test]
fn a_scaled_key_grows_the_last_handle() {
    let mesh = bar();
    let d = bind_bar(4, WeightScheme::BSpline, BlendMethod::MotorLog);
    let end = DVec3::new(LENGTH, 0.0, 0.0);
    let grow = ScaledMotor::from_scale_rotation_translation(2.0, DQuat::IDENTITY, end - 2.0 * end);
    let mut keys = vec![ScaledMotor::IDENTITY; 4];
    keys[3] = grow;
    let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
    d.pose(&keys, &mut out).unwrap();
    for v in tube_ring(SIDES, RINGS - 1) {
        let p = mesh.positions[v as usize];
        let expect = end + 2.0 * (p - end);
        assert!((out[v as usize] - expect).length() < 1e-12);
    }
}

/// The linear scheme bends a bar into a circular arc: with rest keys `[1, T(L x)]` each
/// cross-section is bound in the frame of the point `lambda L` of the axis, and a pose key
/// that rotates by `theta` about the line through `(0, r, 0)` along `z` sweeps it along the
/// circle of radius `r` about that line. A vertex at height `y` ends at distance `r - y` from
/// the line, at angle `lambda theta`; with `r = L / theta` the axis keeps its length.
#[test]
fn the_linear_scheme_bends_a_bar_into_a_circular_arc() {
    let mesh = bar();
    let theta = FRAC_PI_2;
    let r = LENGTH / theta;
    let center = DVec3::new(0.0, r, 0.0);
    let rest = keys_of(&[Motor::IDENTITY, Motor::from_translation(DVec3::X * LENGTH)]);
    let d = SplineDeformer::bind_with_lambda(
        &mesh.positions,
        lambda_along(&mesh),
        &rest,
        WeightScheme::Linear,
        BlendMethod::MotorLog,
    )
    .unwrap();
    let pose = [
        ScaledMotor::IDENTITY,
        rotation_about(DVec3::Z, theta, center),
    ];
    let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
    d.pose(&pose, &mut out).unwrap();
    for (p, q) in mesh.positions.iter().zip(&out) {
        let phi = theta * p.x / LENGTH;
        let rel = *q - center;
        assert!((q.z - p.z).abs() < 1e-12);
        assert!(((rel.x * rel.x + rel.y * rel.y).sqrt() - (r - p.y)).abs() < 1e-12);
        let angle = rel.x.atan2(-rel.y);
        assert!((angle - phi).abs() < 1e-12, "{angle} vs {phi}");
    }
}

fn ring_area(points: &[DVec3], ring: &[u32]) -> f64 {
    let c: DVec3 = ring.iter().map(|&v| points[v as usize]).sum::<DVec3>() / ring.len() as f64;
    let mut a = DVec3::ZERO;
    for k in 0..ring.len() {
        let p = points[ring[k] as usize] - c;
        let q = points[ring[(k + 1) % ring.len()] as usize] - c;
        a += p.cross(q);
    }
    0.5 * a.length()
}

#[test]
fn a_half_turn_twist_keeps_the_section_with_motors_and_collapses_it_with_matrices() {
    let mesh = bar();
    let middle = tube_ring(SIDES, RINGS / 2);
    let rest_area = ring_area(&mesh.positions, &middle);
    let twist = keys_of(&[Motor::IDENTITY, Motor::from_axis_angle(DVec3::X, PI)]);
    let mut areas = Vec::new();
    for method in BlendMethod::ALL {
        let d = bind_bar(2, WeightScheme::Linear, method);
        let mut out = vec![DVec3::ZERO; mesh.vertex_count()];
        d.pose(&twist, &mut out).unwrap();
        areas.push((method, ring_area(&out, &middle) / rest_area));
    }
    for (method, ratio) in areas {
        match method {
            // Matrices, and equation (17) which is their blend for rigid keys, collapse.
            BlendMethod::Matrix
            | BlendMethod::MatrixF32
            | BlendMethod::Conformal
            | BlendMethod::ConformalProjected => assert!(ratio < 0.5, "{method:?}: {ratio}"),
            _ => assert!((ratio - 1.0).abs() < 0.02, "{method:?}: {ratio}"),
        }
    }
}

#[test]
fn weights_are_partitions_of_unity_and_clamped() {
    let mut w = vec![0.0; 8];
    for scheme in WeightScheme::ALL {
        for n in [2, 3, 4, 5, 8] {
            if scheme.check_key_count(n).is_err() {
                continue;
            }
            for k in 0..=100 {
                let l = k as f64 / 100.0;
                let width = scheme.width(n);
                let first = scheme.weights(n, l, &mut w);
                assert!(first + width <= n);
                let sum: f64 = w[..width].iter().sum();
                assert!((sum - 1.0).abs() < 1e-14, "{scheme:?} {n} {l}: {sum}");
            }
            let first = scheme.weights(n, 0.0, &mut w);
            assert_eq!((first, w[0]), (0, 1.0), "{scheme:?} {n} at 0");
            let first = scheme.weights(n, 1.0, &mut w);
            let width = scheme.width(n);
            assert_eq!(first + width, n);
            assert!((w[width - 1] - 1.0).abs() < 1e-15, "{scheme:?} {n} at 1");
        }
    }
    // The paper's quadratic Lagrange weights.
    WeightScheme::Quadratic.weights(3, 0.25, &mut w);
    assert_eq!(&w[..3], &[0.375, 0.75, -0.125]);
}

#[test]
fn bad_keys_and_parameters_are_typed_errors() {
    let mesh = bar();
    let (a, b) = (tube_ring(SIDES, 0), tube_ring(SIDES, RINGS - 1));
    let opts = |scheme| SplineOptions {
        scheme,
        ..SplineOptions::default()
    };
    let e = SplineDeformer::bind(
        &mesh,
        &a,
        &b,
        &[ScaledMotor::IDENTITY; 4],
        opts(WeightScheme::Quadratic),
    );
    assert!(
        matches!(e, Err(DeformError::Keys(KeyError::WrongCount { .. }))),
        "{e:?}"
    );
    let e = SplineDeformer::bind(
        &mesh,
        &a,
        &b,
        &[ScaledMotor::IDENTITY; 1],
        opts(WeightScheme::BSpline),
    );
    assert!(matches!(
        e,
        Err(DeformError::Keys(KeyError::WrongCount { .. }))
    ));
    let e = SplineDeformer::bind(
        &mesh,
        &[],
        &b,
        &[ScaledMotor::IDENTITY; 2],
        opts(WeightScheme::Linear),
    );
    assert!(matches!(
        e,
        Err(DeformError::Keys(KeyError::EmptyHandle { set: 0 }))
    ));
    let e = SplineDeformer::bind(
        &mesh,
        &a,
        &a,
        &[ScaledMotor::IDENTITY; 2],
        opts(WeightScheme::Linear),
    );
    assert!(matches!(
        e,
        Err(DeformError::Mesh(MeshError::OverlappingConstraints { .. }))
    ));
    let e = SplineDeformer::bind(
        &mesh,
        &a,
        &[9999],
        &[ScaledMotor::IDENTITY; 2],
        opts(WeightScheme::Linear),
    );
    assert!(matches!(
        e,
        Err(DeformError::Mesh(MeshError::ConstraintOutOfRange { .. }))
    ));
    let mut lambda = lambda_along(&mesh);
    lambda[7] = 1.5;
    let e = SplineDeformer::bind_with_lambda(
        &mesh.positions,
        lambda,
        &[ScaledMotor::IDENTITY; 2],
        WeightScheme::Linear,
        BlendMethod::MotorLog,
    );
    assert!(matches!(
        e,
        Err(DeformError::Keys(KeyError::ParameterOutOfRange {
            index: 7,
            ..
        }))
    ));

    let d = bind_bar(4, WeightScheme::BSpline, BlendMethod::MotorLog);
    let mut out = mesh.positions.clone();
    let before = out.clone();
    let mut bad = [ScaledMotor::IDENTITY; 4];
    bad[2].s = f64::NAN;
    let e = d.pose(&bad, &mut out);
    assert!(
        matches!(
            e,
            Err(DeformError::Keys(KeyError::Invalid { index: 2, .. }))
        ),
        "{e:?}"
    );
    bad[2] = ScaledMotor::IDENTITY;
    bad[1].e123i = 0.7; // not a versor
    let e = d.pose(&bad, &mut out);
    assert!(
        matches!(
            e,
            Err(DeformError::Keys(KeyError::Invalid { index: 1, .. }))
        ),
        "{e:?}"
    );
    let e = d.pose(&[ScaledMotor::IDENTITY; 3], &mut out);
    assert!(matches!(
        e,
        Err(DeformError::Keys(KeyError::WrongCount { .. }))
    ));
    let e = d.pose(&[ScaledMotor::IDENTITY; 4], &mut out[1..]);
    assert!(matches!(
        e,
        Err(DeformError::Mesh(MeshError::DimensionMismatch { .. }))
    ));
    assert_eq!(out, before, "positions untouched on error");
}

#[test]
fn fitted_splines_reproduce_keys_they_can_represent() {
    let controls: Vec<ScaledMotor> = (0..5)
        .map(|j| {
            let q = DQuat::from_axis_angle(DVec3::new(1.0, 0.3, -0.2).normalize(), 0.4 * j as f64);
            ScaledMotor::from_scale_rotation_translation(
                1.0 + 0.1 * j as f64,
                q,
                DVec3::new(j as f64, 0.5, 0.0),
            )
        })
        .collect();
    let lambda: Vec<f64> = (0..=20).map(|i| i as f64 / 20.0).collect();
    let keys: Vec<ScaledMotor> = lambda
        .iter()
        .map(|&l| bspline_motor(&controls, l).unwrap())
        .collect();
    let fit = fit_bspline(&keys, &lambda, 5).unwrap();
    assert_eq!(fit.solver, FitSolver::Cholesky);
    assert!(fit.max_residual < 1e-10, "{}", fit.max_residual);
    for (c, f) in controls.iter().zip(&fit.controls) {
        assert!(c.to_mat4().abs_diff_eq(f.to_mat4(), 1e-9));
    }
    // Parameters that miss a control point make A^T A singular: SVD takes over.
    let crowded: Vec<f64> = (0..=20).map(|i| 0.2 * i as f64 / 20.0).collect();
    let keys: Vec<ScaledMotor> = crowded
        .iter()
        .map(|&l| bspline_motor(&controls, l).unwrap())
        .collect();
    let fit = fit_bspline(&keys, &crowded, 5).unwrap();
    assert_eq!(fit.solver, FitSolver::Svd);
    assert!(fit.max_residual < 1e-9);
    assert!(fit_bspline(&keys, &crowded, 1).is_err());
    assert!(fit_bspline(&keys, &crowded[1..], 4).is_err());
}

proptest! {
    #[test]
    fn the_log_blend_of_a_key_with_itself_is_the_key(angle in -3.0..3.0f64, t in -5.0..5.0f64, s in 0.5..2.0f64, l in 0.0..1.0f64) {
        let k = ScaledMotor::from_scale_rotation_translation(s, DQuat::from_rotation_y(angle), DVec3::new(t, 1.0, -t));
        for scheme in [WeightScheme::Linear, WeightScheme::Bezier, WeightScheme::BSpline] {
            let mesh = deform::Mesh::new(vec![DVec3::new(1.0, 2.0, 3.0)], vec![]);
            let d = SplineDeformer::bind_with_lambda(&mesh.positions, vec![l], &[ScaledMotor::IDENTITY; 4], scheme, BlendMethod::MotorLog).unwrap();
            let mut out = [DVec3::ZERO];
            d.pose(&[k; 4], &mut out).unwrap();
            prop_assert!((out[0] - k.transform_point(mesh.positions[0])).length() < 1e-10);
        }
    }
}

#[test]
fn a_component_without_handles_is_a_typed_error() {
    // Two separate bars; the handles are both on the first one.
    let a = bar();
    let mut b = bar();
    let n = a.vertex_count() as u32;
    let mut positions = a.positions.clone();
    positions.extend(b.positions.iter().map(|p| *p + DVec3::new(0.0, 5.0, 0.0)));
    let mut triangles = a.triangles.clone();
    triangles.extend(b.triangles.drain(..).map(|t| t.map(|v| v + n)));
    let two = deform::Mesh::new(positions, triangles);
    let e = SplineDeformer::bind(
        &two,
        &tube_ring(SIDES, 0),
        &tube_ring(SIDES, RINGS - 1),
        &[ScaledMotor::IDENTITY; 2],
        SplineOptions::default(),
    );
    assert!(
        matches!(e, Err(DeformError::Solve(SolveError::Unconstrained { .. }))),
        "{e:?}"
    );
}
