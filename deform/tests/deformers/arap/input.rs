//! ARAP's handles and input: handle regions end where their motors put them, clamped weights,
//! bad and degenerate input, and `deform arap` end to end.

use super::{bar, motor};
use cga::ScaledMotor;
use deform::blend::KeyError;
use deform::deformers::arap::{Arap, ArapEnergy, ArapError, ArapOptions, Stop, Targets};
use deform::deformers::DeformError;
use deform::mesh::shapes::tube;
use deform::mesh::MeshError;
use deform::operators::laplacian::CotangentOptions;
use deform::operators::SolveError;
use deform::Deformer;
use glam::{DQuat, DVec3};

#[test]
fn handle_regions_end_where_their_motors_put_them() {
    let (mesh, left, mid, right) = bar();
    let arap = Arap::bind(&mesh, &left, &[&mid, &right], ArapOptions::default()).expect("bind");
    let keys = [
        motor(DQuat::IDENTITY, DVec3::new(0.0, 1.5, 0.0)),
        motor(DQuat::from_rotation_x(1.2), DVec3::new(-1.0, 3.0, 0.0)),
    ];
    let mut p = mesh.positions.clone();
    arap.pose(&Targets::Motors(&keys), Stop::Iterations(4), &mut p)
        .expect("pose");
    for &v in &left {
        assert_eq!(p[v as usize], mesh.positions[v as usize]);
    }
    for (g, key) in keys.iter().enumerate() {
        for &v in arap.handle(g).unwrap() {
            let want = key.transform_point(mesh.positions[v as usize]);
            assert!(
                (p[v as usize] - want).length() < 1e-12,
                "group {g} vertex {v}"
            );
        }
    }
    // The Deformer form (from the rest pose, the bound stop rule) gives the same handles.
    let mut q = vec![DVec3::ZERO; mesh.vertex_count()];
    Deformer::pose(&arap, &keys, &mut q).expect("deformer pose");
    assert_eq!(arap.key_count(), 2);
    for &v in arap.handle(1).unwrap() {
        assert!(
            (q[v as usize] - keys[1].transform_point(mesh.positions[v as usize])).length() < 1e-12
        );
    }
}

#[test]
fn clamped_weights_and_spokes_give_a_finite_smooth_result() {
    let (mesh, left, _, right) = bar();
    let o = ArapOptions {
        energy: ArapEnergy::Spokes,
        cotangent: CotangentOptions {
            clamp_negative: true,
            ..CotangentOptions::default()
        },
        ..ArapOptions::default()
    };
    let arap = Arap::bind(&mesh, &left, &[&right], o).expect("bind");
    let mut p = mesh.positions.clone();
    let key = motor(DQuat::from_rotation_z(0.8), DVec3::new(-1.0, 2.0, 0.0));
    let report = arap
        .pose(&Targets::Motors(&[key]), Stop::Iterations(8), &mut p)
        .expect("pose");
    assert!(p.iter().all(|x| x.is_finite()));
    assert!(report
        .energies
        .windows(2)
        .all(|e| e[1] <= e[0] * (1.0 + 1e-12)));
}

#[test]
fn bad_input_is_a_typed_error() {
    let (mesh, left, mid, right) = bar();
    let o = ArapOptions::default();
    // No constraints at all.
    assert!(matches!(
        Arap::bind(&mesh, &[], &[], o),
        Err(DeformError::Arap(ArapError::NoConstraints))
    ));
    // A fixed vertex that is also a handle vertex.
    match Arap::bind(&mesh, &left, &[&[left[3], 100]], o) {
        Err(DeformError::Mesh(MeshError::OverlappingConstraints { vertices })) => {
            assert_eq!(vertices.0, vec![left[3]])
        }
        other => panic!("{other:?}"),
    }
    // Out of range, empty handle.
    assert!(matches!(
        Arap::bind(&mesh, &[10_000], &[], o),
        Err(DeformError::Mesh(MeshError::ConstraintOutOfRange { .. }))
    ));
    assert!(matches!(
        Arap::bind(&mesh, &left, &[&[]], o),
        Err(DeformError::Keys(KeyError::EmptyHandle { set: 0 }))
    ));
    // Two bars, the second without constraints.
    let other = tube(1.0, 2.0, 6, 3);
    let offset = mesh.vertex_count() as u32;
    let mut both = mesh.clone();
    both.positions.extend(
        other
            .positions
            .iter()
            .map(|p| *p + DVec3::new(0.0, 10.0, 0.0)),
    );
    both.triangles
        .extend(other.triangles.iter().map(|t| t.map(|v| v + offset)));
    match Arap::bind(&both, &left, &[&right], o) {
        Err(DeformError::Solve(SolveError::Unconstrained {
            components,
            vertices,
            ..
        })) => {
            assert_eq!(components, 1);
            assert_eq!(vertices.0[0], offset);
        }
        other => panic!("{other:?}"),
    }
    // A handle covering the whole second component.
    let whole: Vec<u32> = (offset..both.vertex_count() as u32).collect();
    match Arap::bind(&both, &left, &[&whole], o) {
        Err(DeformError::Arap(ArapError::NothingToDeform { vertices })) => {
            assert_eq!(vertices.0, whole)
        }
        other => panic!("{other:?}"),
    }
    // Non-finite targets, wrong counts, bad stop rules; positions stay as they were.
    let arap = Arap::bind(&mesh, &left, &[&mid], o).expect("bind");
    let mut p = mesh.positions.clone();
    let mut t: Vec<DVec3> = arap
        .constrained()
        .iter()
        .map(|&v| mesh.positions[v as usize])
        .collect();
    t[14] = DVec3::new(f64::NAN, 0.0, 0.0);
    match arap.pose(&Targets::Positions(&t), Stop::Iterations(2), &mut p) {
        Err(DeformError::Mesh(MeshError::NonFinite { vertices })) => {
            assert_eq!(vertices.0, vec![arap.constrained()[14]])
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        arap.pose(&Targets::Positions(&t[..3]), Stop::Iterations(2), &mut p),
        Err(DeformError::Mesh(MeshError::DimensionMismatch { .. }))
    ));
    let mut nan = ScaledMotor::IDENTITY;
    nan.s = f64::NAN;
    assert!(matches!(
        arap.pose(&Targets::Motors(&[nan]), Stop::Iterations(2), &mut p),
        Err(DeformError::Keys(KeyError::Invalid { index: 0, .. }))
    ));
    assert!(matches!(
        arap.pose(&Targets::Motors(&[]), Stop::Iterations(2), &mut p),
        Err(DeformError::Keys(KeyError::WrongCount { .. }))
    ));
    assert!(matches!(
        arap.pose(
            &Targets::Motors(&[ScaledMotor::IDENTITY]),
            Stop::Iterations(0),
            &mut p
        ),
        Err(DeformError::Mesh(MeshError::InvalidArgument(_)))
    ));
    assert!(matches!(
        arap.pose(
            &Targets::Motors(&[ScaledMotor::IDENTITY]),
            Stop::RelativeChange {
                tolerance: f64::NAN,
                max_iterations: 3
            },
            &mut p
        ),
        Err(DeformError::Mesh(MeshError::InvalidArgument(_)))
    ));
    assert_eq!(p, mesh.positions);
    p[5].y = f64::INFINITY;
    match arap.pose(
        &Targets::Motors(&[ScaledMotor::IDENTITY]),
        Stop::Iterations(1),
        &mut p,
    ) {
        Err(DeformError::Mesh(MeshError::NonFinite { vertices })) => {
            assert_eq!(vertices.0, vec![5])
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn degenerate_triangles_follow_the_foundation_policy() {
    let (mut mesh, left, _, right) = bar();
    // Collapse one triangle of the middle onto a line: its weights are skipped.
    let t = mesh.triangles[100];
    mesh.positions[t[2] as usize] =
        0.5 * (mesh.positions[t[0] as usize] + mesh.positions[t[1] as usize]);
    let arap = Arap::bind(&mesh, &left, &[&right], ArapOptions::default()).expect("bind");
    let mut p = mesh.positions.clone();
    arap.pose(
        &Targets::Motors(&[motor(DQuat::IDENTITY, DVec3::Y)]),
        Stop::Iterations(3),
        &mut p,
    )
    .expect("pose");
    assert!(p.iter().all(|x| x.is_finite()));
    let strict = ArapOptions {
        cotangent: CotangentOptions {
            degenerate: deform::operators::laplacian::DegeneratePolicy::Error,
            ..CotangentOptions::default()
        },
        ..ArapOptions::default()
    };
    assert!(matches!(
        Arap::bind(&mesh, &left, &[&right], strict),
        Err(DeformError::Mesh(MeshError::DegenerateTriangles { .. }))
    ));
}

/// `deform arap` end to end on a bar: group 0 fixed (no motor), group 1 moved by its motor;
/// energies printed per iteration; bad input exits with code 2.
#[cfg(feature = "cli")]
#[test]
fn the_arap_command_moves_the_motor_groups_and_fixes_the_others() {
    let dir = std::env::temp_dir().join(format!("deform-arap-cli-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("dir");
    let (mesh, left, _, right) = bar();
    deform::mesh::io::write_obj(&mesh, dir.join("bar.obj")).expect("obj");
    std::fs::write(
        dir.join("sel.json"),
        format!("{{\"0\": {left:?}, \"1\": {right:?}}}"),
    )
    .expect("sel");
    std::fs::write(
        dir.join("motors.json"),
        r#"{"1": {"rotate": {"axis": [0, 0, 1], "degrees": 40, "center": [8, 0, 0]}, "translate": [0, 1, 0]}}"#,
    )
    .expect("motors");
    let p = |f: &str| dir.join(f).display().to_string();
    let run = |extra: &[&str]| {
        let mut args = vec![
            "arap".to_string(),
            p("bar.obj"),
            "--select".into(),
            p("sel.json"),
            "--motors".into(),
            p("motors.json"),
        ];
        args.extend(extra.iter().map(|s| s.to_string()));
        std::process::Command::new(env!("CARGO_BIN_EXE_deform"))
            .args(&args)
            .output()
            .expect("run deform")
    };
    let out = p("out.obj");
    let o = run(&["--iterations", "4", "-o", &out, "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    assert_eq!(v["energies"].as_array().expect("energies").len(), 4);
    assert_eq!(
        (v["fixed"].as_u64(), v["handles"].as_u64()),
        (Some(12), Some(1))
    );
    let posed = deform::mesh::io::read_mesh(std::path::Path::new(&out)).expect("output");
    assert_eq!(posed.vertex_count(), mesh.vertex_count());
    for &v in &left {
        assert!(posed.positions[v as usize].distance(mesh.positions[v as usize]) < 1e-9);
    }
    let key = ScaledMotor::from_scale_rotation_translation(
        1.0,
        DQuat::from_rotation_z(40f64.to_radians()),
        DVec3::new(8.0, 0.0, 0.0)
            - DQuat::from_rotation_z(40f64.to_radians()) * DVec3::new(8.0, 0.0, 0.0)
            + DVec3::Y,
    );
    for &v in &right {
        let want = key.transform_point(mesh.positions[v as usize]);
        assert!(posed.positions[v as usize].distance(want) < 1e-6);
    }
    // Plain output prints one energy line per iteration.
    let o = run(&[
        "--tolerance",
        "1e-4",
        "--energy",
        "spokes",
        "--local-step",
        "svd",
        "-o",
        &out,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("iteration    2: energy"));
    // Bad input: both stop rules, a motor for a group that does not exist, zero iterations.
    for bad in [
        vec!["--iterations", "3", "--tolerance", "1e-3", "-o", &out],
        vec!["--iterations", "0", "-o", &out],
        vec!["--tolerance", "-1", "-o", &out],
    ] {
        let o = run(&bad);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
    }
    std::fs::write(dir.join("motors.json"), r#"{"7": {}}"#).expect("motors");
    let o = run(&["-o", &out]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("group"));
    let _ = std::fs::remove_dir_all(&dir);
}
