//! ARAP (first paper, section VII): agreement with libigl's `arap_solve`, rigid motions,
//! monotone energy, rotor and SVD local steps, handle motors, bad input.

use crate::common;

use cga::ScaledMotor;
use common::{reference, reference_mesh, u32s};
use deform::deformers::arap::{Arap, ArapEnergy, ArapOptions, LocalStep, Stop, Targets};
use deform::mesh::shapes::{tube, tube_ring};
use deform::Mesh;
use glam::{DMat3, DQuat, DVec3};

mod input;

fn vec3s(v: &serde_json::Value) -> Vec<DVec3> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|p| {
            let c = common::f64s(p);
            DVec3::new(c[0], c[1], c[2])
        })
        .collect()
}

fn options(energy: ArapEnergy, local_step: LocalStep) -> ArapOptions {
    ArapOptions {
        energy,
        local_step,
        ..ArapOptions::default()
    }
}

/// The largest distance between two position lists over the bounding-box diagonal.
fn relative_error(mesh: &Mesh, a: &[DVec3], b: &[DVec3]) -> f64 {
    let d = mesh.bounding_box().expect("box").diagonal();
    a.iter()
        .zip(b)
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max)
        / d
}

fn check_libigl(name: &str) {
    let Some(r) = reference(name) else { return };
    let mesh = reference_mesh(&r);
    let fixed = u32s(&r["spec"]["fixed"]);
    let handles = u32s(&r["spec"]["handles"]);
    let mut targets: Vec<DVec3> = fixed.iter().map(|&v| mesh.positions[v as usize]).collect();
    targets.extend(vec3s(&r["spec"]["handle_targets"]));
    for (energy, key) in [
        (ArapEnergy::Spokes, "spokes"),
        (ArapEnergy::SpokesAndRims, "spokes_and_rims"),
    ] {
        for step in [LocalStep::Rotor, LocalStep::Svd] {
            let arap = Arap::bind(&mesh, &fixed, &[&handles], options(energy, step)).expect("bind");
            for iterations in [1, 10] {
                let want = vec3s(&r[format!("arap_{key}_it{iterations}")]);
                let mut p = mesh.positions.clone();
                let report = arap
                    .pose(
                        &Targets::Positions(&targets),
                        Stop::Iterations(iterations),
                        &mut p,
                    )
                    .expect("pose");
                assert_eq!(report.iterations(), iterations);
                let err = relative_error(&mesh, &p, &want);
                println!(
                    "{name} {key} {step:?} {iterations} iterations: {err:.2e} of the diagonal"
                );
                // libigl fits rotations with an approximate single-precision 3x3 SVD
                // (McAdams et al., a fixed number of Jacobi sweeps): on the decimated knight,
                // whose obtuse triangles give negative weights and slow convergence, that
                // noise (median 4e-7 of the diagonal after one iteration, also with an f32
                // SVD of our own) grows to 4.9e-5 after ten spokes iterations.
                let tolerance = if name.contains("knight") && key == "spokes" && iterations == 10 {
                    1e-4
                } else {
                    1e-5
                };
                assert!(err < tolerance, "{name} {key} {iterations}: {err:e}");
            }
        }
    }
}

#[test]
fn agrees_with_libigl_on_the_knight() {
    check_libigl("libigl_knight.json");
}

#[test]
fn agrees_with_libigl_on_the_tube() {
    check_libigl("libigl_tube_41x24.json");
}

/// A bar along x and three of its rings: the left end, the middle and the right end.
fn bar() -> (Mesh, Vec<u32>, Vec<u32>, Vec<u32>) {
    let mesh = tube(1.0, 8.0, 12, 17);
    (mesh, tube_ring(12, 0), tube_ring(12, 8), tube_ring(12, 16))
}

fn motor(q: DQuat, t: DVec3) -> ScaledMotor {
    ScaledMotor::from_scale_rotation_translation(1.0, q, t)
}

#[test]
fn rigid_motion_of_every_handle_moves_the_mesh_rigidly() {
    let (mesh, _, mid, right) = bar();
    let left = tube_ring(12, 0);
    let m = motor(
        DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 0.5).normalize(), 1.1),
        DVec3::new(0.3, -2.0, 4.0),
    );
    for energy in [ArapEnergy::Spokes, ArapEnergy::SpokesAndRims] {
        let arap = Arap::bind(
            &mesh,
            &[],
            &[&left, &mid, &right],
            options(energy, LocalStep::Rotor),
        )
        .expect("bind");
        let mut p = mesh.positions.clone();
        let report = arap
            .pose(
                &Targets::Motors(&[m; 3]),
                // ARAP converges linearly; the energy, quadratic in the error, stops
                // resolving progress long before the positions do, so run a fixed count.
                Stop::Iterations(300),
                &mut p,
            )
            .expect("pose");
        println!(
            "{energy:?}: {} iterations, energy {:e}",
            report.iterations(),
            report.energies.last().expect("energies")
        );
        let want: Vec<DVec3> = mesh
            .positions
            .iter()
            .map(|&x| m.transform_point(x))
            .collect();
        let err = relative_error(&mesh, &p, &want);
        assert!(err < 1e-9, "{energy:?}: {err:e}");
        let last = *report.energies.last().expect("energies");
        assert!(last.abs() < 1e-9, "{energy:?}: energy {last:e}");
    }
}

#[test]
fn energy_never_increases_and_the_knight_converges() {
    let Some(r) = reference("libigl_knight.json") else {
        return;
    };
    let mesh = reference_mesh(&r);
    let fixed = u32s(&r["spec"]["fixed"]);
    let handles = u32s(&r["spec"]["handles"]);
    let mut targets: Vec<DVec3> = fixed.iter().map(|&v| mesh.positions[v as usize]).collect();
    targets.extend(vec3s(&r["spec"]["handle_targets"]));
    for energy in [ArapEnergy::Spokes, ArapEnergy::SpokesAndRims] {
        let arap = Arap::bind(
            &mesh,
            &fixed,
            &[&handles],
            options(energy, LocalStep::Rotor),
        )
        .expect("bind");
        let mut p = mesh.positions.clone();
        let report = arap
            .pose(
                &Targets::Positions(&targets),
                Stop::RelativeChange {
                    tolerance: 1e-9,
                    max_iterations: 2000,
                },
                &mut p,
            )
            .expect("pose");
        let e = &report.energies;
        let scale = e[0].abs();
        for k in 1..e.len() {
            assert!(
                e[k] <= e[k - 1] + 1e-12 * scale,
                "{energy:?}: iteration {}: {} > {}",
                k + 1,
                e[k],
                e[k - 1]
            );
        }
        assert!(report.converged, "{energy:?}: {} iterations", e.len());
        println!(
            "knight {energy:?}: converged in {} iterations, energy {:.6e} -> {:.6e}",
            e.len(),
            e[0],
            e[e.len() - 1]
        );
        // A warm start from the converged pose stays there.
        let before = p.clone();
        let again = arap
            .pose(&Targets::Positions(&targets), Stop::Iterations(1), &mut p)
            .expect("pose");
        assert!((again.energies[0] - e[e.len() - 1]).abs() <= 1e-6 * scale);
        assert!(relative_error(&mesh, &p, &before) < 1e-4);
    }
}

#[test]
fn rotor_and_svd_local_steps_agree_on_real_meshes() {
    for name in ["libigl_knight.json", "libigl_tube_41x24.json"] {
        let Some(r) = reference(name) else { return };
        let mesh = reference_mesh(&r);
        let fixed = u32s(&r["spec"]["fixed"]);
        let handles = u32s(&r["spec"]["handles"]);
        let mut targets: Vec<DVec3> = fixed.iter().map(|&v| mesh.positions[v as usize]).collect();
        targets.extend(vec3s(&r["spec"]["handle_targets"]));
        for energy in [ArapEnergy::Spokes, ArapEnergy::SpokesAndRims] {
            let run = |step| {
                let arap =
                    Arap::bind(&mesh, &fixed, &[&handles], options(energy, step)).expect("bind");
                let mut p = mesh.positions.clone();
                // Three iterations: the rotations of the third are fitted to a deformed pose.
                let mut scratch = arap.scratch().expect("scratch");
                let targets = Targets::Positions(&targets);
                arap.pose_using(
                    &targets,
                    Stop::Iterations(3),
                    &mut scratch,
                    &mut p,
                    |_, _| {},
                )
                .expect("pose");
                (p, scratch.rotation_matrices().to_vec())
            };
            let (pr, rr) = run(LocalStep::Rotor);
            let (ps, rs) = run(LocalStep::Svd);
            let worst = rr
                .iter()
                .zip(&rs)
                .map(|(a, b)| {
                    (*a - *b)
                        .to_cols_array()
                        .iter()
                        .fold(0.0f64, |m, x| m.max(x.abs()))
                })
                .fold(0.0, f64::max);
            println!("{name} {energy:?}: rotor vs SVD rotations differ by {worst:.2e}");
            assert!(worst < 1e-9, "{name} {energy:?}: {worst:e}");
            assert!(relative_error(&mesh, &pr, &ps) < 1e-9);
            for r in &rr {
                assert!((r.determinant() - 1.0).abs() < 1e-12);
                assert!((*r * r.transpose()).abs_diff_eq(DMat3::IDENTITY, 1e-12));
            }
        }
    }
}
