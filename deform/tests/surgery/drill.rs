//! Drilling a skinned mesh: manifold results, points on the cylinder, weights, degenerate and
//! bad drills, posed frames and the real arm.

use crate::{assert_manifold, check_animates, common};
use deform::skinning::{procedural_arm, Rig, Skinning};
use deform::surgery::{CutPiece, Frame, Surgery, SurgeryError, VertexOrigin};
use deform::{BlendMethod, Deformer};
use glam::DVec3;

/// Drill checks: manifold result, intersection points on the cylinder (side or end discs),
/// weights partitions of unity with at most 4 influences, input vertices unchanged.
fn check_drill(rig: &Rig, r: &deform::surgery::DrillResult, d: &deform::surgery::Drill) {
    let m = &r.mesh.mesh;
    assert_manifold(m);
    let all = deform::mesh::adjacency::boundary_loops(&m.triangles, m.vertex_count()).len();
    assert_eq!(r.boundary_loops, all, "boundary loops");
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    let axis = (d.end - d.tip).normalize();
    let len = (d.end - d.tip).length();
    for (v, o) in r.origin.iter().enumerate() {
        match *o {
            VertexOrigin::Edge { .. } => {
                let x = m.positions[v] - d.tip;
                let a = x.dot(axis);
                let radial = (x - a * axis).length();
                let on_side = (radial - d.radius).abs() <= 1e-9 * diag
                    && a >= -1e-9 * diag
                    && a <= len + 1e-9 * diag;
                let on_disc = radial <= d.radius * (1.0 + 1e-9)
                    && (a.abs() <= 1e-9 * diag || (a - len).abs() <= 1e-9 * diag);
                assert!(on_side || on_disc, "vertex {v}: radial {radial}, axial {a}");
                let row: Vec<(u32, f64)> = r.mesh.influences.row(v).collect();
                assert!((row.iter().map(|x| x.1).sum::<f64>() - 1.0).abs() < 1e-12);
                assert!(row.iter().filter(|x| x.1 != 0.0).count() <= 4);
            }
            VertexOrigin::Original(i) => assert_eq!(m.positions[v], rig.mesh.positions[i as usize]),
            VertexOrigin::Refined => {}
            other => panic!("a drill makes no {other:?} vertex"),
        }
    }
}

#[test]
fn drill_through_the_arm() {
    use deform::surgery::{Drill, DrillOptions};
    let rig = procedural_arm(24, 81);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let o = DrillOptions::default();
    // Through both walls of the tube, across it.
    let through = Drill {
        tip: DVec3::new(2.05, 0.03, -2.0),
        end: DVec3::new(2.05, 0.03, 2.0),
        radius: 0.25,
    };
    let r = s.drill(&through, Frame::Rest, &o).unwrap();
    check_drill(&rig, &r, &through);
    assert_eq!(r.holes, 2, "two walls, two holes");
    assert!(r.new_vertices >= 12);
    let pose = rig.pose(Some(0), 1.2, &[]).unwrap();
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
        BlendMethod::MotorLinear,
        BlendMethod::Conformal,
    ] {
        check_animates(&rig, &piece, pose.skin_motors().unwrap(), method);
    }
    // Into one wall only: the tip stops inside the tube.
    let one = Drill {
        tip: DVec3::new(5.0, 0.02, 0.0),
        end: DVec3::new(5.0, 0.02, 3.0),
        radius: 0.2,
    };
    let r = s.drill(&one, Frame::Rest, &o).unwrap();
    check_drill(&rig, &r, &one);
    assert_eq!(r.holes, 1);
    // Thinner than the triangles: refined first, then drilled.
    let thin = Drill {
        tip: DVec3::new(3.03, 0.011, -1.0),
        end: DVec3::new(3.03, 0.011, 1.0),
        radius: 0.02,
    };
    let r = s.drill(&thin, Frame::Rest, &o).unwrap();
    check_drill(&rig, &r, &thin);
    assert!(r.refined_faces > 0);
    assert_eq!(r.holes, 2);
    assert!(r.new_vertices >= 2 * o.min_points.min(6) / 2);
}

#[test]
fn degenerate_and_bad_drills() {
    use deform::surgery::{Drill, DrillOptions};
    let rig = procedural_arm(16, 41);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let o = DrillOptions::default();
    // Tangent to the tube along a line of vertices (a ring vertex at y = 0.6): removes nothing.
    let r = 0.1;
    let tangent = Drill {
        tip: DVec3::new(4.0, 0.6 + r, -1.0),
        end: DVec3::new(4.0, 0.6 + r, 1.0),
        radius: r,
    };
    assert!(matches!(
        s.drill(&tangent, Frame::Rest, &o),
        Err(SurgeryError::Misses { .. })
    ));
    // Through the tube's wall but far thinner than its faces: it meets the surface and
    // removes nothing even after refinement, and says so (not "does not reach").
    let thin = Drill {
        tip: DVec3::new(4.03, 2.0, 0.01),
        end: DVec3::new(4.03, -2.0, 0.01),
        radius: 1e-9,
    };
    match s.drill(&thin, Frame::Rest, &o) {
        Err(SurgeryError::BadTool(m)) => assert!(m.contains("too thin"), "{m}"),
        other => panic!("a thin drill: {:?}", other.map(|_| ())),
    }
    let outside = Drill {
        tip: DVec3::new(0.0, 5.0, 0.0),
        end: DVec3::new(1.0, 5.0, 0.0),
        radius: 0.3,
    };
    assert!(matches!(
        s.drill(&outside, Frame::Rest, &o),
        Err(SurgeryError::Misses { .. })
    ));
    let nan = Drill {
        tip: DVec3::NAN,
        end: DVec3::ONE,
        radius: 0.3,
    };
    assert!(matches!(
        s.drill(&nan, Frame::Rest, &o),
        Err(SurgeryError::BadTool(_))
    ));
    let flat = Drill {
        tip: DVec3::ONE,
        end: DVec3::ONE,
        radius: 0.3,
    };
    assert!(matches!(
        s.drill(&flat, Frame::Rest, &o),
        Err(SurgeryError::BadTool(_))
    ));
    let zero = Drill {
        tip: DVec3::ZERO,
        end: DVec3::Z,
        radius: 0.0,
    };
    assert!(matches!(
        s.drill(&zero, Frame::Rest, &o),
        Err(SurgeryError::BadTool(_))
    ));
}

#[test]
fn drill_a_posed_frame_and_real_arm() {
    use deform::surgery::{Drill, DrillOptions};
    let rig = procedural_arm(24, 81);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let pose = rig.pose(Some(0), 2.0, &[]).unwrap();
    let keys = pose.skin_motors().unwrap();
    let lbs = Skinning::bind(&rig, BlendMethod::Matrix).unwrap();
    let mut posed = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    lbs.pose(keys, &mut posed).unwrap();
    // The forearm points up (+y) after the 100-degree bend: drill across it.
    let d = Drill {
        tip: DVec3::new(2.5, 2.0, -2.0),
        end: DVec3::new(5.5, 2.0, 2.0),
        radius: 0.2,
    };
    let frame = Frame::Posed {
        positions: &posed,
        skin: &pose.skin_matrices,
    };
    let r = s.drill(&d, frame, &DrillOptions::default()).unwrap();
    assert_manifold(&r.mesh.mesh);
    assert!(r.holes >= 1);
    // Posed again at the same frame, the intersection points lie on the drill.
    let b = Skinning::bind_influences(
        &r.mesh.mesh.positions,
        &r.mesh.influences,
        3,
        BlendMethod::Matrix,
    )
    .unwrap();
    let mut out = vec![DVec3::ZERO; r.mesh.mesh.vertex_count()];
    b.pose(keys, &mut out).unwrap();
    super::assert_on_drill(&out, &r.origin, &d, "posed by LBS");
    let Some(arm) = common::libigl_rig("arm") else {
        return;
    };
    let s = Surgery::new(&arm.mesh, &arm.influences).unwrap();
    let b = arm.mesh.bounding_box().unwrap();
    let span = b.diagonal();
    // Along the normal of the vertex nearest the box's centre, through it.
    let c = b.center();
    let v = (0..arm.mesh.vertex_count())
        .min_by(|&i, &j| {
            arm.mesh.positions[i]
                .distance(c)
                .total_cmp(&arm.mesh.positions[j].distance(c))
        })
        .unwrap();
    let (p, nrm) = (arm.mesh.positions[v], arm.mesh.vertex_normals()[v]);
    let d = Drill {
        tip: p - nrm * 0.5 * span,
        end: p + nrm * 0.05 * span,
        radius: 0.01 * span,
    };
    let r = s.drill(&d, Frame::Rest, &DrillOptions::default()).unwrap();
    check_drill(&arm, &r, &d);
    assert!(r.holes >= 1, "{} holes", r.holes);
}

/// A drill or a cut that misses says how far the tool is and where the nearest surface point
/// is (issue 21).
#[test]
fn tools_that_miss_say_where_the_surface_is() {
    use deform::surgery::{CutOptions, Drill, DrillOptions};
    let rig = procedural_arm(16, 41);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let top = rig
        .mesh
        .positions
        .iter()
        .map(|p| p.y)
        .fold(f64::MIN, f64::max);
    let outside = Drill {
        tip: DVec3::new(3.0, 5.0, 0.0),
        end: DVec3::new(5.0, 5.0, 0.0),
        radius: 0.3,
    };
    match s.drill(&outside, Frame::Rest, &DrillOptions::default()) {
        Err(e @ SurgeryError::Misses { .. }) => {
            let text = e.to_string();
            let gap = format!(
                "it passes {} from the surface",
                deform::render::short_number(5.0 - top)
            );
            assert!(text.contains(&gap), "{text} (expected {gap:?})");
            assert!(text.contains("radius 0.3)"), "{text}");
        }
        other => panic!("expected a miss, got {:?}", other.map(|_| ())),
    }
    let plane = cga::Plane::from_normal_distance(DVec3::X, -2.0);
    match s.cut(&plane, Frame::Rest, &CutOptions::default()) {
        Err(e @ SurgeryError::Misses { .. }) => {
            let text = e.to_string();
            assert!(text.contains("the nearest off it 2 away at ("), "{text}");
        }
        other => panic!("expected a miss, got {:?}", other.map(|_| ())),
    }
}

/// On a glTF model split along UV seams, a drill counts loops over the welded surface, as a
/// cut does (issue 21): a drill through CesiumMan's torso makes two holes and reports two
/// loops, not the seams' hundreds; the copies of each new vertex on a seam coincide.
#[test]
fn a_drill_counts_holes_over_the_welded_surface() {
    use deform::surgery::{Drill, DrillOptions};
    let Some(dir) = common::data_dir() else {
        return;
    };
    let rig = deform::skinning::read_gltf(dir.join("gltf/CesiumMan.glb")).unwrap();
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let through = Drill {
        tip: DVec3::new(0.0, -0.5, 1.0),
        end: DVec3::new(0.0, 0.5, 1.0),
        radius: 0.05,
    };
    let r = s
        .drill(&through, Frame::Rest, &DrillOptions::default())
        .unwrap();
    assert_eq!((r.boundary_loops, r.holes), (2, 2));
    assert_eq!(r.refined_faces, 0);
    // The truth: the result welded by bit-identical positions (the seam copies of a new
    // vertex must coincide exactly) has exactly those loops, and the input none.
    let welded_loops = |m: &deform::Mesh| {
        let mut first = std::collections::HashMap::new();
        let canon: Vec<u32> = m
            .positions
            .iter()
            .enumerate()
            .map(|(i, p)| {
                *first
                    .entry(p.to_array().map(f64::to_bits))
                    .or_insert(i as u32)
            })
            .collect();
        let tris: Vec<[u32; 3]> = m
            .triangles
            .iter()
            .map(|t| t.map(|v| canon[v as usize]))
            .collect();
        deform::mesh::adjacency::boundary_loops(&tris, m.vertex_count()).len()
    };
    assert_eq!(welded_loops(&rig.mesh), 0);
    assert_eq!(welded_loops(&r.mesh.mesh), 2);
    assert_manifold(&r.mesh.mesh);
}
