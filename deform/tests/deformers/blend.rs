//! Key weights over contiguous runs and over gathered key lists pose the same.

use cga::ScaledMotor;
use deform::blend::{BoundBlend, KeyWeights};
use deform::{BlendMethod, Deformer, MotorHandles};
use glam::{DQuat, DVec3};

#[test]
fn gathered_rows_pose_like_contiguous_rows() {
    let positions: Vec<DVec3> = (0..20)
        .map(|i| DVec3::new(i as f64 * 0.3, (i % 3) as f64, 1.0))
        .collect();
    let n = positions.len();
    // Keys 1..4 contiguous, versus the same keys listed backwards (weights reversed too).
    let mut w = Vec::new();
    for i in 0..n {
        let t = i as f64 / (n - 1) as f64;
        w.extend([(1.0 - t) * 0.5, 0.5, t * 0.5]);
    }
    let contiguous = KeyWeights::new(5, 3, vec![1; n], w.clone()).unwrap();
    let mut keys = Vec::new();
    let mut rw = Vec::new();
    for row in w.chunks(3) {
        keys.extend([3u32, 2, 1]);
        rw.extend([row[2], row[1], row[0]]);
    }
    let gathered = KeyWeights::gathered(5, 3, keys, rw).unwrap();
    for i in 0..n {
        for j in 0..5 {
            assert_eq!(contiguous.weight(i, j), gathered.weight(i, j));
        }
    }
    let motors: Vec<ScaledMotor> = (0..5)
        .map(|j| {
            ScaledMotor::from_scale_rotation_translation(
                1.0 + 0.1 * j as f64,
                DQuat::from_rotation_z(0.3 * j as f64),
                DVec3::X * j as f64,
            )
        })
        .collect();
    for method in BlendMethod::ALL {
        let rest = [ScaledMotor::IDENTITY; 5];
        let a = BoundBlend::bind(&positions, contiguous.clone(), &rest, method).unwrap();
        let b = BoundBlend::bind(&positions, gathered.clone(), &rest, method).unwrap();
        let (mut pa, mut pb) = (vec![DVec3::ZERO; n], vec![DVec3::ZERO; n]);
        a.pose(&motors, &mut pa).unwrap();
        b.pose(&motors, &mut pb).unwrap();
        // Single precision sums in another order: its rounding, about 1e-7 relative.
        let tol = if method == BlendMethod::MatrixF32 {
            1e-5
        } else {
            1e-12
        };
        for (x, y) in pa.iter().zip(&pb) {
            assert!(x.distance(*y) < tol, "{method:?}");
        }
        // Posing twice reuses the prepared keys: same result.
        a.pose(&motors, &mut pb).unwrap();
        assert_eq!(pa, pb);
    }
    assert!(KeyWeights::gathered(5, 3, vec![5, 0, 0], vec![1.0, 0.0, 0.0]).is_err());
    assert!(KeyWeights::gathered(5, 3, vec![0, 0], vec![1.0, 0.0, 0.0]).is_err());
    assert!(KeyWeights::new(5, 3, vec![3], vec![1.0, 0.0, 0.0]).is_err());
    assert!(KeyWeights::new(5, 3, vec![0], vec![f64::NAN, 0.0, 0.0]).is_err());
}

#[test]
fn a_cloned_deformer_poses_the_same() {
    let mesh = deform::mesh::shapes::icosphere(1.0, 2);
    let h = MotorHandles::bind(&mesh, &[&[0], &[3]], Default::default()).unwrap();
    let c = h.clone();
    let keys = [
        ScaledMotor::IDENTITY,
        ScaledMotor::from_scale_rotation_translation(1.2, DQuat::IDENTITY, DVec3::Y),
    ];
    let (mut a, mut b) = (
        vec![DVec3::ZERO; mesh.vertex_count()],
        vec![DVec3::ZERO; mesh.vertex_count()],
    );
    h.pose(&keys, &mut a).unwrap();
    c.pose(&keys, &mut b).unwrap();
    assert_eq!(a, b);
}

/// Keys spread over all of rotation space (some past a half-turn, so hemisphere signs flip),
/// scaled or rigid, some negated (the same motion with the other sign).
fn spread_keys(count: usize, scaled: bool) -> Vec<ScaledMotor> {
    (0..count)
        .map(|j| {
            let a = DVec3::new(1.0, (j % 5) as f64 - 2.0, 0.3 * j as f64).normalize();
            let q = DQuat::from_axis_angle(a, 0.9 * j as f64 - 2.0);
            let s = if scaled {
                (0.15 * (j % 4) as f64).exp()
            } else {
                1.0
            };
            let m = ScaledMotor::from_scale_rotation_translation(
                s,
                q,
                DVec3::new(j as f64 * 0.2, 1.0, -0.5),
            );
            if j % 3 == 1 {
                ScaledMotor::from_array(m.to_array().map(|c| -c))
            } else {
                m
            }
        })
        .collect()
}

/// The batch pose loop (four vertices at a time, weight rows laid out for streaming, keys in
/// the generated wide twins, AVX2 where the CPU has it) gives, for every method, what the
/// per-vertex blend gives: with few keys (the hemisphere-aligned table) and many (signs per
/// term), rigid and scaled keys, and a vertex count that leaves a partial last batch.
#[test]
fn the_batch_loop_poses_as_the_per_vertex_blend() {
    for (key_count, width, n) in [(5, 4, 4103), (70, 3, 2051), (3, 2, 7)] {
        let positions: Vec<DVec3> = (0..n)
            .map(|i| {
                let t = i as f64 * 0.37;
                DVec3::new(t.sin() * 2.0, t.cos(), (i % 17) as f64 * 0.1)
            })
            .collect();
        let mut keys = Vec::new();
        let mut weights = Vec::new();
        for i in 0..n {
            let raw: Vec<f64> = (0..width)
                .map(|j| 1.0 + ((i * 7 + j * 3) % 5) as f64)
                .collect();
            let sum: f64 = raw.iter().sum();
            weights.extend(raw.iter().map(|w| w / sum));
            keys.extend((0..width).map(|j| ((i * 13 + j * 29) % key_count) as u32));
        }
        let rows = KeyWeights::gathered(key_count, width, keys, weights).unwrap();
        let rest = vec![ScaledMotor::IDENTITY; key_count];
        for scaled in [false, true] {
            let posed = spread_keys(key_count, scaled);
            for method in BlendMethod::ALL {
                let bound = BoundBlend::bind(&positions, rows.clone(), &rest, method).unwrap();
                let mut out = vec![DVec3::ZERO; n];
                bound.pose(&posed, &mut out).unwrap();
                let prepared = deform::blend::PreparedKeys::new(&posed, method).unwrap();
                let mut worst = 0.0f64;
                for (i, (o, &p)) in out.iter().zip(bound.local()).enumerate() {
                    let want = prepared.transform(rows.row(i), p);
                    worst = worst.max((*o - want).abs().max_element() / want.length().max(1.0));
                }
                let tol = if method == BlendMethod::MatrixF32 {
                    0.0
                } else {
                    1e-13
                };
                assert!(
                    worst <= tol,
                    "{} keys, {} {}: batch differs from the per-vertex blend by {worst:e}",
                    key_count,
                    method.name(),
                    if scaled { "scaled" } else { "rigid" }
                );
            }
        }
    }
}

/// The positional form of lattices and cages runs the batch loop too: `sum w P` gives the
/// bits of the per-vertex sum, with a partial last batch and more keys than lanes.
#[test]
fn the_positional_batch_loop_sums_as_the_per_vertex_loop() {
    use deform::blend::control::{ControlBinding, ControlForm};
    for (key_count, width, n) in [(64, 8, 4103), (3, 2, 7)] {
        let positions: Vec<DVec3> = (0..n)
            .map(|i| DVec3::new(i as f64 * 0.01, (i % 13) as f64, 0.5))
            .collect();
        let mut keys = Vec::new();
        let mut weights = Vec::new();
        for i in 0..n {
            let raw: Vec<f64> = (0..width)
                .map(|j| 0.3 + ((i * 11 + j * 5) % 7) as f64)
                .collect();
            let sum: f64 = raw.iter().sum();
            weights.extend(raw.iter().map(|w| w / sum));
            keys.extend((0..width).map(|j| ((i * 17 + j * 31) % key_count) as u32));
        }
        let rows = KeyWeights::gathered(key_count, width, keys, weights).unwrap();
        let rest: Vec<DVec3> = (0..key_count)
            .map(|j| DVec3::new(j as f64, (j * j % 7) as f64, -(j as f64) * 0.5))
            .collect();
        let bound = ControlBinding::bind(
            &positions,
            rest.clone(),
            rows.clone(),
            ControlForm::Positional,
        )
        .unwrap();
        let control: Vec<DVec3> = rest
            .iter()
            .map(|p| *p * 1.3 + DVec3::new(0.1, -0.2, 0.7))
            .collect();
        let mut out = vec![DVec3::ZERO; n];
        bound.pose_points(&control, &mut out).unwrap();
        for (i, o) in out.iter().enumerate() {
            let want = rows.row(i).fold(DVec3::ZERO, |a, k, w| a + w * control[k]);
            assert_eq!(*o, want, "vertex {i} of {n}");
        }
    }
}

/// A pose whose blend leaves the `f64` range is an error naming the vertex, with every
/// method and on both the batch and the vertex-by-vertex paths (it was `Ok` with NaN or
/// infinite positions).
#[test]
fn poses_beyond_the_f64_range_are_errors() {
    let huge_key = ScaledMotor::from_scale_rotation_translation(1e10, DQuat::IDENTITY, DVec3::ZERO);
    // 4100 vertices: enough for the parallel batch loop; the last one is out of range.
    let mut rest = vec![DVec3::ONE; 4100];
    rest[4099] = DVec3::splat(1e300);
    let n = rest.len();
    let weights = KeyWeights::new(1, 1, vec![0; n], vec![1.0; n]).unwrap();
    for method in BlendMethod::ALL {
        let b = BoundBlend::bind(&rest, weights.clone(), &[ScaledMotor::IDENTITY], method).unwrap();
        let mut out = vec![DVec3::ZERO; n];
        let mut prepared = Default::default();
        for result in [
            b.pose(&[huge_key], &mut out),
            b.pose_vertex_by_vertex(&[huge_key], &mut prepared, &mut out),
        ] {
            let e = result.expect_err(method.name()).to_string();
            assert!(
                e.contains("posed vertex") && e.contains("index 4099"),
                "{method:?}: {e}"
            );
        }
        // The identity poses (not in single precision, which cannot hold 1e300).
        if method != BlendMethod::MatrixF32 {
            b.pose(&[ScaledMotor::IDENTITY], &mut out).unwrap();
        }
    }
    // Weights that extrapolate far past their keys: a scale of 2^1100 in log blending.
    let twice = ScaledMotor::from_scale_rotation_translation(2.0, DQuat::IDENTITY, DVec3::ZERO);
    let w = KeyWeights::new(2, 2, vec![0], vec![1100.0, -1099.0]).unwrap();
    for method in [
        BlendMethod::MotorLog,
        BlendMethod::MotorLinear,
        BlendMethod::DualQuaternion,
    ] {
        let b = BoundBlend::bind(
            &[DVec3::ONE],
            w.clone(),
            &[ScaledMotor::IDENTITY; 2],
            method,
        )
        .unwrap();
        let mut out = [DVec3::ZERO];
        let r = b.pose(&[twice, ScaledMotor::IDENTITY], &mut out);
        assert!(r.is_err(), "{method:?}: {out:?}");
    }
}

/// Equation (17) keeps the precision of the other methods at large scales: its `eo` weight
/// came from the expanded point matrix, which loses `eps * d^2` for a scale `d` (a point
/// scaled by 1e7 was 0.6% off, by 1e9 98%).
#[test]
fn equation_17_is_as_precise_as_the_matrix_at_large_scales() {
    let rest = [DVec3::new(1.0, -0.5, 0.25)];
    let w = KeyWeights::new(1, 1, vec![0], vec![1.0]).unwrap();
    let turn = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 2.0).normalize(), 0.7);
    for d in [1e-9, 1e-6, 1e-3, 10.0, 1e3, 1e5, 1e7, 1e9] {
        let key = ScaledMotor::from_scale_rotation_translation(d, turn, DVec3::new(0.3, 0.1, -2.0));
        let want = d * (turn * rest[0]) + DVec3::new(0.3, 0.1, -2.0);
        for method in [
            BlendMethod::Conformal,
            BlendMethod::ConformalProjected,
            BlendMethod::Matrix,
        ] {
            let b = BoundBlend::bind(&rest, w.clone(), &[ScaledMotor::IDENTITY], method).unwrap();
            let mut out = [DVec3::ZERO];
            b.pose(&[key], &mut out).unwrap();
            let err = (out[0] - want).length() / want.length();
            // The scale's own representation holds about eps * max(d, 1/d).
            assert!(
                err < 1e-14 * d.max(1.0 / d).max(10.0),
                "{method:?}, scale {d:e}: {err:e}"
            );
        }
    }
}

/// A key given as a multiple of a scaled motor (the same motion) poses the same with every
/// method: equation (17) read the point matrix of the multiple, whose formulas hold for unit
/// versors only (0.2 times a key moved a point by 40 units).
#[test]
fn multiples_of_a_key_pose_the_same_with_every_method() {
    let rest = [DVec3::new(1.0, -0.5, 0.25)];
    let w = KeyWeights::new(1, 1, vec![0], vec![1.0]).unwrap();
    let turn = DQuat::from_rotation_z(0.4);
    let key = ScaledMotor::from_scale_rotation_translation(1.5, turn, DVec3::new(0.3, 0.1, -2.0));
    let want = 1.5 * (turn * rest[0]) + DVec3::new(0.3, 0.1, -2.0);
    for k in [1.0, 0.2, 3.0, -1.0] {
        for method in BlendMethod::ALL {
            let b = BoundBlend::bind(&rest, w.clone(), &[ScaledMotor::IDENTITY], method).unwrap();
            let mut out = [DVec3::ZERO];
            b.pose(&[key * k], &mut out).unwrap();
            let tol = if method == BlendMethod::MatrixF32 {
                1e-6
            } else {
                1e-13
            };
            assert!(
                (out[0] - want).length() < tol,
                "{method:?}, {k} times the key: {}",
                out[0]
            );
        }
    }
}
