//! criterion benches of the cage and lattice deformers (issue 13): mean value coordinates
//! bound for `meshes/cages/armadillo-dense.obj` (3,990 vertices) in its 77-vertex cage,
//! positional vs motor-valued posing on those coordinates, harmonic coordinates on a 64^3 grid,
//! and a 4x4x4 FFD lattice (positional vs motor). Targets: MVC bind < 50 ms; pose < 0.5 ms
//! positional and < 2 ms motor; harmonic coordinates < 5 s.
//!
//! `cargo bench -p deform --bench cage`

use cga::ScaledMotor;
use criterion::{criterion_group, criterion_main, Criterion};
use deform::blend::control::ControlForm;
use deform::deformers::cage::{
    harmonic_cage_coordinates, mean_value_coordinates, CageDeformer, CageOptions, HarmonicGrid,
};
use deform::deformers::ffd::{Ffd, FfdOptions};
use deform::{BlendMethod, Deformer, Mesh};
use glam::{DQuat, DVec3};
use std::hint::black_box;
use std::time::Duration;

mod support;

use support::scenes;

/// A mesh of the data set (see `scenes::mesh`).
fn read(rel: &str) -> Option<Mesh> {
    scenes::mesh(&format!("cages/{rel}"))
}

/// One motor per key: rotations of up to 30 degrees about the box centre and a small lift,
/// varying with the key's rest position.
fn keys(points: &[DVec3]) -> Vec<ScaledMotor> {
    let c = points.iter().copied().sum::<DVec3>() / points.len() as f64;
    points
        .iter()
        .map(|&p| {
            let a = 0.5 * ((p - c).y * 0.1).sin();
            let q = DQuat::from_axis_angle(DVec3::Z, a);
            ScaledMotor::from_scale_rotation_translation(1.0, q, c - q * c + 0.01 * DVec3::Y)
        })
        .collect()
}

fn benches(c: &mut Criterion) {
    let (Some(model), Some(cage)) = (
        read("armadillo-dense.obj"),
        read("armadillo-cage-robust-6.obj"),
    ) else {
        return;
    };
    let n = model.vertex_count();
    let mut g = c.benchmark_group("cage-armadillo-dense");
    g.sample_size(20).measurement_time(Duration::from_secs(4));
    g.bench_function("bind_mvc_coordinates", |b| {
        b.iter(|| mean_value_coordinates(black_box(&cage), &model.positions).expect("mvc"))
    });
    g.bench_function("bind_mvc_deformer_motor", |b| {
        b.iter(|| {
            CageDeformer::bind(black_box(&model), &cage, CageOptions::default()).expect("bind")
        })
    });
    let k = keys(&cage.positions);
    let mut out = vec![DVec3::ZERO; n];
    for form in [
        ControlForm::Positional,
        ControlForm::Motor(BlendMethod::MotorLog),
        ControlForm::Motor(BlendMethod::DualQuaternion),
    ] {
        let d = CageDeformer::bind(
            &model,
            &cage,
            CageOptions {
                form,
                ..CageOptions::default()
            },
        )
        .expect("bind");
        let mut poser = d.poser();
        g.bench_function(format!("pose_mvc_{}", form.name()), |b| {
            b.iter(|| poser.pose(black_box(&k), &mut out).expect("pose"))
        });
    }
    g.sample_size(10).measurement_time(Duration::from_secs(20));
    g.bench_function("harmonic_coordinates_64", |b| {
        b.iter(|| {
            harmonic_cage_coordinates(&cage, &model.positions, HarmonicGrid { resolution: 64 })
                .expect("harmonic")
        })
    });
    g.finish();

    let mut g = c.benchmark_group("ffd-armadillo-dense");
    g.sample_size(20).measurement_time(Duration::from_secs(3));
    for form in [
        ControlForm::Positional,
        ControlForm::Motor(BlendMethod::MotorLog),
    ] {
        let options = FfdOptions {
            form,
            ..FfdOptions::default()
        };
        g.bench_function(format!("bind_4x4x4_{}", form.name()), |b| {
            b.iter(|| Ffd::bind(black_box(&model), [4, 4, 4], None, options).expect("bind"))
        });
        let d = Ffd::bind(&model, [4, 4, 4], None, options).expect("bind");
        let k = keys(d.binding().rest_points());
        let mut poser = d.poser();
        g.bench_function(format!("pose_4x4x4_{}", form.name()), |b| {
            b.iter(|| poser.pose(black_box(&k), &mut out).expect("pose"))
        });
    }
    g.finish();
}

criterion_group!(cage_benches, benches);
criterion_main!(cage_benches);
