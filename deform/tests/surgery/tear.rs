//! Tearing a skinned mesh: manifold results, area kept, incision points on their planes,
//! weights, bad tears, real and posed meshes.

use crate::{assert_manifold, check_animates, common};
use deform::skinning::{procedural_arm, Rig, Skinning};
use deform::surgery::{CutPiece, Frame, Surgery, SurgeryError, VertexOrigin};
use deform::{BlendMethod, Deformer};
use glam::DVec3;

/// Tear checks: manifold, area kept (a slit re-triangulates the same surface), incision points
/// on their step's plane, weights partitions of unity, input vertices unchanged.
fn check_tear(rig: &Rig, r: &deform::surgery::TearResult, opened: bool) {
    let m = &r.mesh.mesh;
    assert_manifold(m);
    let all = deform::mesh::adjacency::boundary_loops(&m.triangles, m.vertex_count()).len();
    assert_eq!(r.boundary_loops, all, "boundary loops");
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    if !opened {
        assert!((m.area() - rig.mesh.area()).abs() < 1e-9 * rig.mesh.area());
    }
    for (v, o) in r.origin.iter().enumerate() {
        match *o {
            VertexOrigin::Incision if !opened => {
                let d = r
                    .planes
                    .iter()
                    .map(|(n, p)| n.dot(m.positions[v] - *p).abs())
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    d < 1e-9 * diag,
                    "incision vertex {v} is {d} off every step plane"
                );
            }
            VertexOrigin::Original(i) if !opened || !r.incision.contains(&(v as u32)) => {
                assert_eq!(m.positions[v], rig.mesh.positions[i as usize]);
            }
            _ => {}
        }
        let row: Vec<(u32, f64)> = r.mesh.influences.row(v).collect();
        assert!((row.iter().map(|x| x.1).sum::<f64>() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn tear_the_arm() {
    use deform::surgery::{Scalpel, TearOptions};
    let rig = procedural_arm(24, 81);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let blade = |x: f64, z: f64| Scalpel {
        a: DVec3::new(x, 1.2, z),
        b: DVec3::new(x, 0.2, z),
    };
    let two = [blade(2.03, 0.05), blade(3.01, 0.08)];
    let r = s.tear(&two, Frame::Rest, &TearOptions::default()).unwrap();
    check_tear(&rig, &r, false);
    assert_eq!(r.boundary_loops, 1, "the slit is one loop");
    assert!(r.duplicated >= 3, "{} duplicated", r.duplicated);
    assert!(r.incision.len() >= 5);
    let pose = rig.pose(Some(0), 1.3, &[]).unwrap();
    let piece = CutPiece {
        mesh: r.mesh.clone(),
        origin: r.origin.clone(),
        face_origin: vec![],
        boundary_loops: r.boundary_loops,
        cap_triangles: 0,
    };
    for method in [
        BlendMethod::Matrix,
        BlendMethod::DualQuaternion,
        BlendMethod::Conformal,
    ] {
        check_animates(&rig, &piece, pose.skin_motors().unwrap(), method);
    }
    // A sequence of steps is one longer incision.
    let four = [
        blade(2.03, 0.05),
        blade(2.6, 0.1),
        blade(3.3, 0.12),
        blade(4.1, 0.0),
    ];
    let r = s.tear(&four, Frame::Rest, &TearOptions::default()).unwrap();
    check_tear(&rig, &r, false);
    assert_eq!(r.boundary_loops, 1);
    // Opened: the lips part in the middle, the ends stay.
    let r = s
        .tear(
            &four,
            Frame::Rest,
            &TearOptions {
                open: 0.1,
                ..TearOptions::default()
            },
        )
        .unwrap();
    check_tear(&rig, &r, true);
    let m = &r.mesh.mesh;
    let widest = r
        .origin
        .iter()
        .enumerate()
        .filter_map(|(c, o)| match o {
            VertexOrigin::Copy(v) => Some(m.positions[c].distance(m.positions[*v as usize])),
            _ => None,
        })
        .fold(0.0, f64::max);
    assert!(
        widest > 0.05 && widest <= 0.1 + 1e-12,
        "widest gap {widest}"
    );
}

#[test]
fn bad_tears() {
    use deform::surgery::{Scalpel, TearOptions};
    let rig = procedural_arm(12, 21);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let o = TearOptions::default();
    let one = [Scalpel {
        a: DVec3::new(2.0, 1.0, 0.0),
        b: DVec3::new(2.0, 0.0, 0.0),
    }];
    assert!(matches!(
        s.tear(&one, Frame::Rest, &o),
        Err(SurgeryError::BadTool(_))
    ));
    let air = [
        Scalpel {
            a: DVec3::new(2.0, 3.0, 0.0),
            b: DVec3::new(2.0, 2.0, 0.0),
        },
        Scalpel {
            a: DVec3::new(3.0, 3.0, 0.0),
            b: DVec3::new(3.0, 2.0, 0.0),
        },
    ];
    assert!(matches!(
        s.tear(&air, Frame::Rest, &o),
        Err(SurgeryError::BadTool(_))
    ));
    // The same position twice (or blades entering at one point): nothing to tear.
    let still = [one[0], one[0], one[0]];
    match s.tear(&still, Frame::Rest, &o) {
        Err(SurgeryError::BadTool(text)) => assert!(text.contains("at one point"), "{text}"),
        other => panic!("a scalpel that does not move: {other:?}"),
    }
    let nan = [
        Scalpel {
            a: DVec3::NAN,
            b: DVec3::ZERO,
        },
        Scalpel {
            a: DVec3::ONE,
            b: DVec3::ZERO,
        },
    ];
    assert!(matches!(
        s.tear(&nan, Frame::Rest, &o),
        Err(SurgeryError::BadTool(_))
    ));
}

#[test]
fn tear_real_and_posed() {
    use deform::surgery::{Scalpel, TearOptions};
    let rig = procedural_arm(24, 81);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let pose = rig.pose(Some(0), 2.0, &[]).unwrap();
    let keys = pose.skin_motors().unwrap();
    let lbs = Skinning::bind(&rig, BlendMethod::Matrix).unwrap();
    let mut posed = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    lbs.pose(keys, &mut posed).unwrap();
    // The forearm points up after the bend: tear along it on its +x side.
    let blade = |y: f64| Scalpel {
        a: DVec3::new(5.5, y, 0.02),
        b: DVec3::new(4.0, y, 0.02),
    };
    let frame = Frame::Posed {
        positions: &posed,
        skin: &pose.skin_matrices,
    };
    let r = s
        .tear(&[blade(1.5), blade(2.5)], frame, &TearOptions::default())
        .unwrap();
    assert_manifold(&r.mesh.mesh);
    assert_eq!(r.boundary_loops, 1);
    // Posed again by LBS, the incision lies on the step plane.
    let b = Skinning::bind_influences(
        &r.mesh.mesh.positions,
        &r.mesh.influences,
        3,
        BlendMethod::Matrix,
    )
    .unwrap();
    let mut out = vec![DVec3::ZERO; r.mesh.mesh.vertex_count()];
    b.pose(keys, &mut out).unwrap();
    super::assert_on_incision(&out, &r, "posed by LBS");
    let Some(arm) = common::libigl_rig("arm") else {
        return;
    };
    let s = Surgery::new(&arm.mesh, &arm.influences).unwrap();
    let loops0 =
        deform::mesh::adjacency::boundary_loops(&arm.mesh.triangles, arm.mesh.vertex_count()).len();
    // Two blades pointing into the skin along the normals of two nearby vertices.
    let normals = arm.mesh.vertex_normals();
    let c = arm.mesh.bounding_box().unwrap().center();
    let v0 = (0..arm.mesh.vertex_count())
        .min_by(|&i, &j| {
            arm.mesh.positions[i]
                .distance(c)
                .total_cmp(&arm.mesh.positions[j].distance(c))
        })
        .unwrap();
    let p0 = arm.mesh.positions[v0];
    let along = normals[v0].any_orthonormal_vector();
    let at = |p: DVec3| Scalpel {
        a: p + normals[v0] * 0.05,
        b: p - normals[v0] * 0.05,
    };
    let r = s
        .tear(
            &[at(p0 + along * 0.013), at(p0 + along * 0.06)],
            Frame::Rest,
            &TearOptions::default(),
        )
        .unwrap();
    check_tear(&arm, &r, false);
    assert_eq!(r.boundary_loops, loops0 + 1);
}

/// A scalpel that misses says where its blade is, how far from the surface, and the nearest
/// surface point (issue 21).
#[test]
fn a_scalpel_that_misses_says_where_the_surface_is() {
    use deform::surgery::{Scalpel, TearOptions};
    let rig = procedural_arm(12, 21);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let top = rig
        .mesh
        .positions
        .iter()
        .map(|p| p.y)
        .fold(f64::MIN, f64::max);
    let high = [
        Scalpel {
            a: DVec3::new(2.0, 3.0, 0.0),
            b: DVec3::new(2.0, 4.0, 0.0),
        },
        Scalpel {
            a: DVec3::new(3.0, 3.0, 0.0),
            b: DVec3::new(3.0, 4.0, 0.0),
        },
    ];
    match s.tear(&high, Frame::Rest, &TearOptions::default()) {
        Err(SurgeryError::BadTool(text)) => {
            assert!(
                text.contains("scalpel 0, the blade from (2, 3, 0)"),
                "{text}"
            );
            let gap = format!(
                "it passes {} from the surface",
                deform::render::short_number(3.0 - top)
            );
            assert!(text.contains(&gap), "{text} (expected {gap:?})");
        }
        other => panic!("expected a refusal, got {:?}", other.map(|_| ())),
    }
}

/// A blade through `(x, y)` down across the procedural arm (from z = 1.2 to 0.2).
fn across_the_arm(x: f64, y: f64) -> deform::surgery::Scalpel {
    deform::surgery::Scalpel {
        a: DVec3::new(x, y, 1.2),
        b: DVec3::new(x, y, 0.2),
    }
}

/// A scalpel that goes back along its incision (there and back, and twice over) tears and
/// opens the same slit as one pass: the same triangles and positions, each point split once.
/// Before, the points passed twice were split twice in the count and their lips pulled apart
/// twice, by a taper that peaked at the slit's tip.
#[test]
fn a_scalpel_that_retraces_its_incision_opens_the_slit_once() {
    let rig = procedural_arm(24, 81);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let at = across_the_arm;
    let (a, b) = (at(4.6, 0.05), at(6.3, 0.0));
    for snap in [deform::surgery::TearOptions::default().snap, 0.0] {
        retrace_with_snap(&rig, &s, a, b, snap);
    }
}

fn retrace_with_snap(
    rig: &Rig,
    s: &Surgery,
    a: deform::surgery::Scalpel,
    b: deform::surgery::Scalpel,
    snap: f64,
) {
    let options = deform::surgery::TearOptions { open: 0.25, snap };
    let once = s.tear(&[a, b], Frame::Rest, &options).unwrap();
    check_tear(rig, &once, true);
    assert!(once.duplicated > 10, "{}", once.duplicated);
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    for blades in [vec![a, b, a], vec![a, b, a, b]] {
        let again = s.tear(&blades, Frame::Rest, &options).unwrap();
        check_tear(rig, &again, true);
        assert!(again.incision.len() > once.incision.len());
        assert_eq!(again.incision_vertex_count(), once.incision_vertex_count());
        assert_eq!(again.duplicated, once.duplicated, "points split");
        assert_eq!(again.new_vertices, once.new_vertices);
        assert_eq!(again.boundary_loops, once.boundary_loops);
        assert_eq!(again.mesh.mesh.triangles, once.mesh.mesh.triangles);
        let worst = again
            .mesh
            .mesh
            .positions
            .iter()
            .zip(&once.mesh.mesh.positions)
            .map(|(p, q)| p.distance(*q))
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-12 * diag,
            "snap {snap}, {} steps: lips {worst:e} apart",
            blades.len()
        );
    }
}

/// A scalpel position given twice in a row (a drag sampled while the hand rests) cuts nothing
/// more: the tear is the one without the repeat. Before, the repeated step had no plane (the
/// next blade enters at its own point) and the whole tear was refused.
#[test]
fn a_scalpel_position_held_for_a_sample_tears_as_without_it() {
    let rig = procedural_arm(24, 81);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let at = across_the_arm;
    let (a, b, c) = (at(4.6, 0.05), at(5.4, 0.1), at(6.3, 0.0));
    // With the default snap and with none (where a repeated hit lands exactly on the vertex
    // the first one inserted, and must be that vertex, not a second one beside it).
    for snap in [deform::surgery::TearOptions::default().snap, 0.0] {
        let options = deform::surgery::TearOptions { open: 0.25, snap };
        let plain = s.tear(&[a, b, c], Frame::Rest, &options).unwrap();
        check_tear(&rig, &plain, true);
        let held_cases = [
            (vec![a, a, b, c], vec![0, 0, 1]),
            (vec![a, b, b, c], vec![0, 0, 1]),
            (vec![a, b, c, c], vec![0, 1, 1]),
            (vec![a, b, b, b, c], vec![0, 0, 0, 1]),
        ];
        for (blades, plane_of_step) in held_cases {
            let held = s.tear(&blades, Frame::Rest, &options).unwrap();
            check_tear(&rig, &held, true);
            let want: Vec<_> = plane_of_step.iter().map(|&i| plain.planes[i]).collect();
            assert_eq!(
                held.planes, want,
                "snap {snap}: a held step takes its neighbour's plane"
            );
            assert_eq!(
                held.incision,
                plain.incision,
                "snap {snap}, {} positions",
                blades.len()
            );
            assert_eq!(held.duplicated, plain.duplicated);
            assert_eq!(held.mesh.mesh.triangles, plain.mesh.mesh.triangles);
            assert_eq!(held.mesh.mesh.positions, plain.mesh.mesh.positions);
        }
    }
}
