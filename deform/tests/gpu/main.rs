//! The GPU blends (`deform::gpu`, the `gpu` feature) against the CPU's f64 ones: every method
//! (log blending through the generated WGSL `exp`), on the shared rigs (libigl's armadillo with its dense weights and its arm,
//! CesiumMan and the Fox mid-animation) and on keys that scale, within 1e-5 of the rest mesh's
//! bounding-box diagonal. CI runs them on Mesa's software Vulkan driver (lavapipe); without any
//! adapter they are skipped, except under `CI=true`, where that is a failure.

#[path = "../../benches/support/skin_scenes.rs"]
mod skin_scenes;
mod wgsl;

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

/// The largest distance between corresponding points of `got` and `want`, over `diag`.
fn worst_error(got: &[DVec3], want: &[DVec3], diag: f64) -> f64 {
    assert_eq!(got.len(), want.len());
    got.iter()
        .zip(want)
        .map(|(a, b)| (*a - *b).length())
        .fold(0.0, f64::max)
        / diag
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
        let mut gpu =
            GpuBlend::bind(ctx, blend).unwrap_or_else(|e| panic!("{}: {e}", method.name()));
        let mut got = vec![DVec3::splat(f64::NAN); s.positions.len()];
        gpu.pose(ctx, &s.keys, &mut got).expect("gpu pose");
        let err = worst_error(&got, &want, diag);
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
        let back = worst_error(&got, &s.positions, diag);
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
    assert!(matches!(
        gpu.pose(&ctx, &[], &mut out),
        Err(GpuError::Blend(_))
    ));
}

/// A spline-aligned deformer's blend (contiguous key runs, rest keys that are not the
/// identity, so the bound points are in the frame of their blended rest transform) posed on
/// the GPU like on the CPU, for every method, the paper's log blending (its default) too.
#[test]
fn spline_blend_on_the_gpu() {
    use deform::deformers::spline::{SplineDeformer, WeightScheme};
    let Some(ctx) = context() else { return };
    let positions: Vec<DVec3> = (0..3000)
        .map(|i| {
            let t = i as f64 / 2999.0;
            DVec3::new(3.0 * t, 0.2 * (31.0 * t).sin(), 0.2 * (17.0 * t).cos())
        })
        .collect();
    let lambda: Vec<f64> = (0..3000).map(|i| i as f64 / 2999.0).collect();
    let key = |angle: f64, x: f64, s: f64| {
        let q = DQuat::from_axis_angle(DVec3::Z, angle);
        ScaledMotor::from_scale_rotation_translation(s, q, DVec3::new(x, 0.0, 0.0))
    };
    let rest: Vec<ScaledMotor> = (0..5)
        .map(|j| key(0.1 * j as f64, 0.75 * j as f64, 1.0))
        .collect();
    let pose: Vec<ScaledMotor> = (0..5)
        .map(|j| key(0.5 * j as f64, 0.6 * j as f64, 1.0 + 0.1 * j as f64))
        .collect();
    let diag = diagonal(&positions);
    for method in BlendMethod::ALL {
        let d = SplineDeformer::bind_with_lambda(
            &positions,
            lambda.clone(),
            &rest,
            WeightScheme::BSpline,
            method,
        )
        .expect("bind");
        let mut want = vec![DVec3::ZERO; positions.len()];
        d.blend().pose(&pose, &mut want).expect("cpu pose");
        let mut gpu = GpuBlend::bind(&ctx, d.blend()).expect("gpu bind");
        let mut got = vec![DVec3::ZERO; positions.len()];
        gpu.pose(&ctx, &pose, &mut got).expect("gpu pose");
        let err = worst_error(&got, &want, diag);
        assert!(err <= 1e-5, "spline {}: {err:e}", method.name());
    }
}

/// An FFD lattice in the motor form (`ControlBinding::motor_blend`: explicit key lists, the
/// lattice block of each vertex) posed on the GPU like on the CPU, for every method.
#[test]
fn ffd_motor_form_on_the_gpu() {
    use deform::blend::control::ControlForm;
    use deform::deformers::ffd::{Ffd, FfdOptions};
    let Some(ctx) = context() else { return };
    let mesh = deform::mesh::shapes::tube(1.0, 10.0, 16, 21);
    let diag = diagonal(&mesh.positions);
    for method in BlendMethod::ALL {
        let options = FfdOptions {
            form: ControlForm::Motor(method),
            ..FfdOptions::default()
        };
        let ffd = Ffd::bind(&mesh, [2, 3, 2], None, options).expect("bind");
        let blend = ffd.binding().motor_blend().expect("motor form");
        let keys: Vec<ScaledMotor> = (0..blend.key_count())
            .map(|j| {
                let f = j as f64 / blend.key_count() as f64;
                let q = DQuat::from_axis_angle(DVec3::new(1.0, f, 0.3).normalize(), 0.8 * f);
                ScaledMotor::from_scale_rotation_translation(1.0 + 0.2 * f, q, DVec3::splat(f))
            })
            .collect();
        let mut want = vec![DVec3::ZERO; mesh.positions.len()];
        blend.pose(&keys, &mut want).expect("cpu pose");
        let mut gpu = GpuBlend::bind(&ctx, blend).expect("gpu bind");
        let mut got = vec![DVec3::ZERO; mesh.positions.len()];
        gpu.pose(&ctx, &keys, &mut got).expect("gpu pose");
        let err = worst_error(&got, &want, diag);
        assert!(err <= 1e-5, "ffd {}: {err:e}", method.name());
    }
}

/// Positional lattices and cages on the GPU (`GpuBlend::bind_control`): control points moved
/// by their motors, and control points given directly, as `ControlBinding` poses them on the
/// CPU; bad inputs are the same typed errors.
#[test]
fn positional_lattices_and_cages_on_the_gpu() {
    use deform::blend::control::{ControlBinding, ControlForm};
    use deform::deformers::cage::{CageDeformer, CageOptions};
    use deform::deformers::ffd::{Ffd, FfdOptions, LatticeBasis};
    let Some(ctx) = context() else { return };
    let mesh = deform::mesh::shapes::tube(1.0, 10.0, 16, 21);
    let diag = diagonal(&mesh.positions);
    let mut cage = deform::mesh::shapes::tube(1.6, 12.0, 4, 6);
    cage.positions.iter_mut().for_each(|p| p.x -= 1.0);
    let bernstein = FfdOptions {
        form: ControlForm::Positional,
        ..FfdOptions::default()
    };
    let bspline = FfdOptions {
        basis: LatticeBasis::BSpline(3),
        ..bernstein
    };
    let positional_cage = CageOptions {
        form: ControlForm::Positional,
        ..CageOptions::default()
    };
    let bindings: Vec<(&str, ControlBinding)> = vec![
        (
            "bernstein 4x3x3",
            Ffd::bind(&mesh, [4, 3, 3], None, bernstein)
                .unwrap()
                .binding()
                .clone(),
        ),
        (
            "b-spline 7x3x3",
            Ffd::bind(&mesh, [7, 3, 3], None, bspline)
                .unwrap()
                .binding()
                .clone(),
        ),
        (
            "mean value cage",
            CageDeformer::bind(&mesh, &cage, positional_cage)
                .unwrap()
                .binding()
                .clone(),
        ),
    ];
    for (what, binding) in &bindings {
        let n = binding.rest_points().len();
        let keys: Vec<ScaledMotor> = (0..n)
            .map(|j| {
                let f = j as f64 / n as f64;
                let q = DQuat::from_axis_angle(DVec3::new(1.0, f, 0.3).normalize(), 0.8 * f);
                ScaledMotor::from_scale_rotation_translation(1.0 + 0.2 * f, q, DVec3::splat(f))
            })
            .collect();
        let mut want = vec![DVec3::ZERO; mesh.positions.len()];
        let mut scratch = binding.scratch();
        binding.pose_using(&keys, &mut scratch, &mut want).unwrap();
        let mut gpu = GpuBlend::bind_control(&ctx, binding).expect("gpu bind");
        assert_eq!(gpu.form(), ControlForm::Positional);
        let mut got = vec![DVec3::ZERO; mesh.positions.len()];
        gpu.pose(&ctx, &keys, &mut got).expect("gpu pose");
        let err = worst_error(&got, &want, diag);
        assert!(err <= 1e-5, "{what}, motors: {err:e}");
        assert!(
            worst_error(&got, &mesh.positions, diag) > 1e-2,
            "{what}: it moved"
        );
        // Control points given directly.
        let points: Vec<DVec3> = binding
            .rest_points()
            .iter()
            .enumerate()
            .map(|(j, p)| *p * 1.2 + DVec3::new(0.0, (j % 3) as f64 * 0.1, 0.3))
            .collect();
        binding.pose_points(&points, &mut want).unwrap();
        gpu.pose_points(&ctx, &points, &mut got)
            .expect("gpu pose points");
        let err = worst_error(&got, &want, diag);
        assert!(err <= 1e-5, "{what}, points: {err:e}");
        // Bad input: a key too few, a point that is not finite; `out` untouched.
        let before = got.clone();
        assert!(matches!(
            gpu.pose(&ctx, &keys[1..], &mut got),
            Err(GpuError::Blend(_))
        ));
        let mut nan = points.clone();
        nan[0].y = f64::NAN;
        assert!(matches!(
            gpu.pose_points(&ctx, &nan, &mut got),
            Err(GpuError::Blend(_))
        ));
        assert_eq!(got, before);
        // Points beyond single precision: the read-back names the vertex (it was `Ok` with
        // infinite positions).
        let far: Vec<DVec3> = points.iter().map(|p| *p * 1e39).collect();
        match gpu.pose_points(&ctx, &far, &mut got) {
            Err(GpuError::Blend(e)) => assert!(e.to_string().contains("posed vertex"), "{e}"),
            other => panic!("{what}: {other:?}"),
        }
    }
    // Control points to a motor form: refused.
    let motor = Ffd::bind(&mesh, [2, 2, 2], None, FfdOptions::default()).unwrap();
    let mut gpu = GpuBlend::bind_control(&ctx, motor.binding()).unwrap();
    let mut out = vec![DVec3::ZERO; mesh.positions.len()];
    assert!(matches!(
        gpu.pose_points(&ctx, &motor.lattice().rest_points(), &mut out),
        Err(GpuError::Blend(_))
    ));
}

/// A timed pass poses as the untimed one, and where the device writes timestamps its time is
/// positive and below the wall-clock time of the whole pose.
#[test]
fn a_timed_pass_poses_the_same_and_reports_its_device_time() {
    use deform::blend::control::ControlForm;
    use deform::deformers::ffd::{Ffd, FfdOptions};
    let Some(ctx) = context() else { return };
    let mesh = deform::mesh::shapes::tube(1.0, 10.0, 32, 201);
    for form in [
        ControlForm::Motor(BlendMethod::DualQuaternion),
        ControlForm::Positional,
    ] {
        let options = FfdOptions {
            form,
            ..FfdOptions::default()
        };
        let ffd = Ffd::bind(&mesh, [3, 2, 2], None, options).expect("bind");
        let keys: Vec<ScaledMotor> = (0..12)
            .map(|j| {
                let q = DQuat::from_axis_angle(DVec3::X, 0.1 * j as f64);
                ScaledMotor::from_scale_rotation_translation(1.0, q, DVec3::splat(0.05 * j as f64))
            })
            .collect();
        let mut gpu = GpuBlend::bind_control(&ctx, ffd.binding()).expect("gpu bind");
        let (mut a, mut b) = (
            vec![DVec3::ZERO; mesh.vertex_count()],
            vec![DVec3::ZERO; mesh.vertex_count()],
        );
        gpu.run(&ctx, &keys).expect("run");
        gpu.read_back(&ctx, &mut a).expect("read");
        let t = std::time::Instant::now();
        let ms = gpu.run_timed(&ctx, &keys).expect("timed run");
        let wall = t.elapsed().as_secs_f64() * 1e3;
        gpu.read_back(&ctx, &mut b).expect("read");
        assert_eq!(a, b, "{}", form.name());
        assert_eq!(ms.is_some(), ctx.has_timestamps());
        if let Some(ms) = ms {
            assert!(
                ms > 0.0 && ms <= wall,
                "{}: pass {ms} ms, pose {wall} ms",
                form.name()
            );
        }
    }
}
