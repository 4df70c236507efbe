//! The GPU blends (`deform::gpu`, the `gpu` feature) against the CPU's f64 ones: every method
//! with a GPU form, on the shared rigs (libigl's armadillo with its dense weights and its arm,
//! CesiumMan and the Fox mid-animation) and on keys that scale, within 1e-5 of the rest mesh's
//! bounding-box diagonal. CI runs them on Mesa's software Vulkan driver (lavapipe); without any
//! adapter they are skipped, except under `CI=true`, where that is a failure.

#[path = "../benches/support/skin_scenes.rs"]
mod skin_scenes;

use cga::ScaledMotor;
use deform::blend::BoundBlend;
use deform::gpu::{GpuBlend, GpuContext, GpuError};
use deform::skinning::Skinning;
use deform::BlendMethod;
use glam::{DQuat, DVec3};
use skin_scenes::SkinScene;

fn context() -> Option<GpuContext> {
    match GpuContext::new() {
        Ok(c) => {
            eprintln!("GPU adapter: {}", c.adapter());
            Some(c)
        }
        Err(e) if std::env::var_os("CI").is_some() => panic!("CI=true and {e}"),
        Err(e) => {
            eprintln!("skipped: {e}");
            None
        }
    }
}

fn diagonal(p: &[DVec3]) -> f64 {
    let (lo, hi) = p
        .iter()
        .fold((DVec3::MAX, DVec3::MIN), |(a, b), x| (a.min(*x), b.max(*x)));
    (hi - lo).length()
}

/// Every GPU method against the CPU on one scene; returns the largest relative error.
fn compare(ctx: &GpuContext, s: &SkinScene) -> f64 {
    let diag = diagonal(&s.positions);
    let mut worst: f64 = 0.0;
    for method in BlendMethod::ALL {
        let cpu =
            Skinning::bind_influences(&s.positions, &s.influences, s.joints, method).expect("bind");
        let blend: &BoundBlend = cpu.blend();
        let mut want = vec![DVec3::ZERO; s.positions.len()];
        blend.pose(&s.keys, &mut want).expect("cpu pose");
        let mut gpu = match GpuBlend::bind(ctx, blend) {
            Ok(g) => g,
            Err(GpuError::Unsupported(m)) => {
                assert_eq!(method, BlendMethod::MotorLog, "{m} should have a GPU form");
                continue;
            }
            Err(e) => panic!("{}: {e}", method.name()),
        };
        let mut got = vec![DVec3::splat(f64::NAN); s.positions.len()];
        gpu.pose(ctx, &s.keys, &mut got).expect("gpu pose");
        let err = got
            .iter()
            .zip(&want)
            .map(|(a, b)| (*a - *b).length())
            .fold(0.0, f64::max)
            / diag;
        assert!(
            err <= 1e-5,
            "{} {}: GPU differs from the CPU by {err:e} of the diagonal",
            s.name,
            method.name()
        );
        eprintln!("{} {}: {err:.2e}", s.name, method.name());
        worst = worst.max(err);
        // A second pose reuses the buffers: the keys of the identity give the rest mesh.
        let rest = vec![ScaledMotor::IDENTITY; s.keys.len()];
        gpu.pose(ctx, &rest, &mut got).expect("gpu pose");
        let back = got
            .iter()
            .zip(&s.positions)
            .map(|(a, b)| (*a - *b).length())
            .fold(0.0, f64::max)
            / diag;
        assert!(
            back <= 1e-5,
            "{} {}: rest pose {back:e}",
            s.name,
            method.name()
        );
    }
    worst
}

#[test]
fn gpu_blends_agree_with_the_cpu_on_the_shared_rigs() {
    let Some(ctx) = context() else { return };
    let mut scenes = skin_scenes::all();
    if let Some(path) = devkit::shared::data_file("gltf/Fox.glb") {
        let rig = deform::skinning::read_gltf(path).expect("Fox loads");
        let (t0, t1) = rig.animations[0].range();
        let pose = rig.pose(Some(0), 0.4 * (t0 + t1), &[]).expect("pose");
        scenes.push(SkinScene {
            name: "Fox",
            keys: pose.skin_motors().expect("similarity rig").to_vec(),
            joints: rig.joints.len(),
            influences: rig.influences.clone(),
            positions: rig.mesh.positions.clone(),
        });
    }
    assert!(!scenes.is_empty() || std::env::var_os("CI").is_none());
    for s in &scenes {
        let worst = compare(&ctx, s);
        assert!(worst.is_finite());
    }
}

#[test]
fn gpu_blends_scale_like_the_cpu() {
    let Some(ctx) = context() else { return };
    // A procedural bar of 2,001 points, two keys: a scale by 1.5 and a turn with a scale by 0.8,
    // weights blending along the bar (the log-scale path of motor and dual-quaternion blending).
    let positions: Vec<DVec3> = (0..2001)
        .map(|i| {
            let t = i as f64 / 2000.0;
            DVec3::new(4.0 * t - 2.0, (7.0 * t).sin() * 0.3, (5.0 * t).cos() * 0.2)
        })
        .collect();
    let influences = deform::skinning::Influences {
        width: 2,
        joints: (0..2001).flat_map(|_| [0u32, 1]).collect(),
        weights: (0..2001)
            .flat_map(|i| {
                let t = i as f64 / 2000.0;
                [1.0 - t, t]
            })
            .collect(),
    };
    let q = DQuat::from_axis_angle(DVec3::new(0.2, 1.0, 0.3).normalize(), 1.1);
    let keys = vec![
        ScaledMotor::from_scale_rotation_translation(
            1.5,
            DQuat::IDENTITY,
            DVec3::new(0.1, 0.2, 0.0),
        ),
        ScaledMotor::from_scale_rotation_translation(0.8, q, DVec3::new(-0.4, 0.0, 0.3)),
    ];
    let s = SkinScene {
        name: "scaled bar",
        positions,
        influences,
        joints: 2,
        keys,
    };
    compare(&ctx, &s);
}

#[test]
fn bad_poses_are_refused_and_leave_out_untouched() {
    let Some(ctx) = context() else { return };
    let positions = vec![DVec3::X, DVec3::Y, DVec3::Z];
    let influences = deform::skinning::Influences {
        width: 1,
        joints: vec![0, 0, 0],
        weights: vec![1.0, 1.0, 1.0],
    };
    let cpu = Skinning::bind_influences(&positions, &influences, 1, BlendMethod::MotorLinear)
        .expect("bind");
    let mut gpu = GpuBlend::bind(&ctx, cpu.blend()).expect("gpu bind");
    let mut out = vec![DVec3::splat(7.0); 3];
    // Wrong key count, a NaN key, the wrong output length: typed errors, `out` untouched.
    assert!(gpu.pose(&ctx, &[], &mut out).is_err());
    let mut nan = ScaledMotor::IDENTITY;
    nan.s = f64::NAN;
    assert!(gpu.pose(&ctx, &[nan], &mut out).is_err());
    assert!(gpu
        .pose(&ctx, &[ScaledMotor::IDENTITY], &mut out[..2])
        .is_err());
    assert!(out.iter().all(|p| *p == DVec3::splat(7.0)));
    // Log blending has no GPU form: said so at bind.
    let log =
        Skinning::bind_influences(&positions, &influences, 1, BlendMethod::MotorLog).expect("bind");
    assert!(matches!(
        GpuBlend::bind(&ctx, log.blend()),
        Err(GpuError::Unsupported("motor-log"))
    ));
}
