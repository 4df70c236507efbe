//! Planar cuts of skinned meshes (second paper, Algorithm 1): areas and volumes add up, new
//! vertices lie on the plane, pieces are edge-manifold with the expected boundary loops,
//! triangles keep a quality bound, weights stay partitions of unity, and the pieces animate
//! exactly as the uncut mesh did.

mod common;

use cga::{Plane, ScaledMotor};
use deform::skinning::{procedural_arm, Rig, Skinning};
use deform::surgery::{
    CutOptions, CutPiece, CutResult, Frame, Surgery, SurgeryError, VertexOrigin,
};
use deform::{BlendMethod, Deformer, Mesh};
use glam::{DQuat, DVec3};

fn assert_manifold(m: &Mesh) {
    common::assert_oriented_manifold(&m.triangles, m.vertex_count());
}

/// Every check that holds for any cut of `rig` by `plane` on the rest pose.
fn check_cut(rig: &Rig, cut: &CutResult, plane: &Plane, options: &CutOptions) {
    let area: f64 = cut.pieces.iter().map(|p| p.mesh.mesh.area()).sum();
    let cap_area: f64 = cut
        .pieces
        .iter()
        .map(|p| {
            p.face_origin
                .iter()
                .zip(p.mesh.mesh.face_areas())
                .filter(|(o, _)| **o == u32::MAX)
                .map(|(_, a)| a)
                .sum::<f64>()
        })
        .sum();
    let a0 = rig.mesh.area();
    assert!(
        ((area - cap_area) - a0).abs() <= 1e-9 * a0,
        "areas {area} - caps {cap_area} vs {a0}"
    );
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    let src_areas = rig.mesh.face_areas();
    for piece in &cut.pieces {
        let m = &piece.mesh.mesh;
        assert_manifold(m);
        // The loop count found locally agrees with a count over the whole piece.
        let all = deform::adjacency::boundary_loops(&m.triangles, m.vertex_count()).len();
        assert_eq!(piece.boundary_loops, all, "boundary loops");
        assert_eq!(piece.origin.len(), m.vertex_count());
        for (v, o) in piece.origin.iter().enumerate() {
            match *o {
                VertexOrigin::Edge { .. } => {
                    let d = plane.signed_distance(m.positions[v]).abs();
                    assert!(d <= 1e-9 * diag, "new vertex {v} is {d} off the plane");
                    // Weights: a partition of unity with at most 4 influences.
                    let row: Vec<(u32, f64)> = piece.mesh.influences.row(v).collect();
                    let sum: f64 = row.iter().map(|r| r.1).sum();
                    assert!((sum - 1.0).abs() < 1e-12);
                    assert!(row.iter().filter(|r| r.1 != 0.0).count() <= 4);
                    assert!(row.iter().all(|r| r.1 >= 0.0));
                }
                VertexOrigin::Original(i) => {
                    assert_eq!(m.positions[v], rig.mesh.positions[i as usize]);
                }
                other => panic!("a cut makes no {other:?} vertex"),
            }
        }
        // Quality: a triangle cut from a face keeps at least snap^2 of its area.
        for (f, &src) in piece.face_origin.iter().enumerate() {
            if src == u32::MAX {
                continue;
            }
            let [a, b, c] = m.corners(f);
            let area = 0.5 * (b - a).cross(c - a).length();
            let bound = options.snap * options.snap * src_areas[src as usize];
            assert!(
                area >= bound * (1.0 - 1e-9),
                "triangle {f}: {area} < {bound}"
            );
        }
    }
}

/// Posing the pieces with the same skin motors moves every unchanged vertex exactly as before.
fn check_animates(rig: &Rig, piece: &CutPiece, keys: &[ScaledMotor], method: BlendMethod) {
    let whole = Skinning::bind(rig, method).unwrap();
    let mut before = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    whole.pose(keys, &mut before).unwrap();
    let part = Skinning::bind_influences(
        &piece.mesh.mesh.positions,
        &piece.mesh.influences,
        rig.joints.len(),
        method,
    )
    .unwrap();
    let mut after = vec![DVec3::ZERO; piece.mesh.mesh.vertex_count()];
    part.pose(keys, &mut after).unwrap();
    for (v, o) in piece.origin.iter().enumerate() {
        if let VertexOrigin::Original(i) = o {
            assert_eq!(
                after[v],
                before[*i as usize],
                "vertex {v} ({}) moved differently",
                method.name()
            );
        }
    }
}

#[test]
fn cut_the_arm_across() {
    let rig = procedural_arm(16, 41);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let options = CutOptions::default();
    let plane = Plane::from_normal_distance(DVec3::new(1.0, 0.2, 0.1), 4.13);
    let cut = s.cut(&plane, Frame::Rest, &options).unwrap();
    check_cut(&rig, &cut, &plane, &options);
    assert_eq!(cut.pieces[0].boundary_loops, 1);
    assert_eq!(cut.pieces[1].boundary_loops, 1);
    eprintln!(
        "cut: {} new vertices, {} split faces, {} snapped, {} examined, pieces {} + {} vertices",
        cut.new_vertices,
        cut.split_faces,
        cut.snapped_vertices,
        cut.faces_examined,
        cut.pieces[0].mesh.mesh.vertex_count(),
        cut.pieces[1].mesh.mesh.vertex_count()
    );
    assert!(cut.new_vertices >= 16 && cut.split_faces >= 32);
    assert!(
        cut.faces_examined < rig.mesh.triangle_count() / 4,
        "the index narrows the search"
    );
    let pose = rig.pose(Some(0), 1.5, &[]).unwrap();
    for method in BlendMethod::ALL {
        for piece in &cut.pieces {
            check_animates(&rig, piece, pose.skin_motors().unwrap(), method);
        }
    }
    // Capped: both pieces are closed and their volumes add up to the tube's.
    let capped = s
        .cut(
            &plane,
            Frame::Rest,
            &CutOptions {
                cap: true,
                ..options
            },
        )
        .unwrap();
    check_cut(&rig, &capped, &plane, &options);
    for p in &capped.pieces {
        assert_eq!(p.boundary_loops, 0);
        assert!(p.cap_triangles > 0);
        assert_manifold(&p.mesh.mesh);
    }
    let v: f64 = capped.pieces.iter().map(|p| p.mesh.mesh.volume()).sum();
    assert!(
        (v - rig.mesh.volume()).abs() < 1e-9 * rig.mesh.volume(),
        "{v} vs {}",
        rig.mesh.volume()
    );
}

#[test]
fn degenerate_cuts() {
    let rig = procedural_arm(16, 41);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let options = CutOptions::default();
    let ring_x = 8.0 * 20.0 / 40.0;
    for (what, plane, loops) in [
        // Exactly through a ring of vertices.
        (
            "through a vertex ring",
            Plane::from_normal_distance(DVec3::X, ring_x),
            [1, 1],
        ),
        // Containing the tube's axis: the plane holds vertices and whole edges (y = 0).
        (
            "along edges",
            Plane::from_normal_distance(DVec3::Y, 0.0),
            [1, 1],
        ),
        // Through a face and exactly one ring vertex (a tilted plane through vertex 20*16).
        (
            "through a face at a vertex",
            Plane::from_point_normal(rig.mesh.positions[20 * 16], DVec3::new(1.0, 0.0, 0.3)),
            [1, 1],
        ),
        // A hair away from a ring: snapped, no slivers.
        (
            "a hair from a ring",
            Plane::from_normal_distance(DVec3::X, ring_x + 1e-9),
            [1, 1],
        ),
    ] {
        let cut = s
            .cut(&plane, Frame::Rest, &options)
            .unwrap_or_else(|e| panic!("{what}: {e}"));
        check_cut(&rig, &cut, &plane, &options);
        assert_eq!(
            [cut.pieces[0].boundary_loops, cut.pieces[1].boundary_loops],
            loops,
            "{what}"
        );
        if what == "through a vertex ring" {
            assert_eq!(cut.new_vertices, 0, "the ring's vertices are the cut");
        }
        if what == "a hair from a ring" {
            assert!(
                cut.snapped_vertices >= 16,
                "{what}: {} snapped",
                cut.snapped_vertices
            );
        }
    }
}

#[test]
fn cut_a_posed_frame() {
    let rig = procedural_arm(16, 41);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let pose = rig.pose(Some(0), 2.0, &[]).unwrap();
    let keys = pose.skin_motors().unwrap();
    let lbs = Skinning::bind(&rig, BlendMethod::Matrix).unwrap();
    let mut posed = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    lbs.pose(keys, &mut posed).unwrap();
    // The elbow is bent 100 degrees: cut across the forearm in world space.
    let plane = Plane::from_normal_distance(DVec3::new(0.2, 1.0, 0.0), 2.0);
    let frame = Frame::Posed {
        positions: &posed,
        skin: &pose.skin_matrices,
    };
    let cut = s.cut(&plane, frame, &CutOptions::default()).unwrap();
    assert!(cut.new_vertices > 0);
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    for piece in &cut.pieces {
        assert_manifold(&piece.mesh.mesh);
        // Posed again by LBS at the same frame, the new vertices lie on the plane.
        let b = Skinning::bind_influences(
            &piece.mesh.mesh.positions,
            &piece.mesh.influences,
            3,
            BlendMethod::Matrix,
        )
        .unwrap();
        let mut out = vec![DVec3::ZERO; piece.mesh.mesh.vertex_count()];
        b.pose(keys, &mut out).unwrap();
        for (v, o) in piece.origin.iter().enumerate() {
            match o {
                VertexOrigin::Edge { .. } => {
                    assert!(plane.signed_distance(out[v]).abs() < 1e-9 * diag)
                }
                VertexOrigin::Original(i) => assert_eq!(out[v], posed[*i as usize]),
                other => panic!("a cut makes no {other:?} vertex"),
            }
        }
        check_animates(&rig, piece, keys, BlendMethod::DualQuaternion);
    }
}

#[test]
fn cut_real_meshes() {
    let Some(rig) = common::libigl_rig("arm") else {
        return;
    };
    let loops0 =
        deform::adjacency::boundary_loops(&rig.mesh.triangles, rig.mesh.vertex_count()).len();
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let b = rig.mesh.bounding_box().unwrap();
    let c = b.center();
    let options = CutOptions::default();
    // Across the arm's long axis, through its middle.
    let size = b.size();
    let axis = if size.x >= size.y && size.x >= size.z {
        DVec3::X
    } else if size.y >= size.z {
        DVec3::Y
    } else {
        DVec3::Z
    };
    let plane = Plane::from_point_normal(c, axis + 0.1 * axis.any_orthonormal_vector());
    let cut = s.cut(&plane, Frame::Rest, &options).unwrap();
    check_cut(&rig, &cut, &plane, &options);
    let loops: usize = cut.pieces.iter().map(|p| p.boundary_loops).sum();
    assert!(loops >= loops0 + 2, "{loops} loops after, {loops0} before");
    let keys: Vec<ScaledMotor> = (0..rig.joints.len())
        .map(|j| {
            ScaledMotor::from_scale_rotation_translation(
                1.0,
                DQuat::from_rotation_z(0.2 * j as f64),
                c - DQuat::from_rotation_z(0.2 * j as f64) * c,
            )
        })
        .collect();
    for piece in &cut.pieces {
        check_animates(&rig, piece, &keys, BlendMethod::Conformal);
    }
}

#[test]
fn bad_cuts_are_typed_errors() {
    let rig = procedural_arm(8, 10);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let o = CutOptions::default();
    let miss = Plane::from_normal_distance(DVec3::X, 100.0);
    assert!(matches!(
        s.cut(&miss, Frame::Rest, &o),
        Err(SurgeryError::Misses { .. })
    ));
    let nan = Plane::from_normal_distance(DVec3::new(f64::NAN, 0.0, 1.0), 0.0);
    assert!(matches!(
        s.cut(&nan, Frame::Rest, &o),
        Err(SurgeryError::BadTool(_))
    ));
    let ok = Plane::from_normal_distance(DVec3::X, 3.0);
    assert!(matches!(
        s.cut(&ok, Frame::Rest, &CutOptions { snap: 0.7, ..o }),
        Err(SurgeryError::BadTool(_))
    ));
    let short = [DVec3::ZERO; 3];
    let frame = Frame::Posed {
        positions: &short,
        skin: &[],
    };
    assert!(matches!(
        s.cut(&ok, frame, &o),
        Err(SurgeryError::BadTool(_))
    ));
    // A non-manifold mesh: a fin glued onto one edge of the tube.
    let mut m = rig.mesh.clone();
    let [a, b, _] = m.triangles[0];
    m.positions.push(DVec3::new(0.0, 5.0, 5.0));
    let fin = (m.positions.len() - 1) as u32;
    m.triangles.push([a, b, fin]);
    let mut inf = rig.influences.clone();
    inf.joints.extend([0, 0, 0, 0]);
    inf.weights.extend([1.0, 0.0, 0.0, 0.0]);
    assert!(matches!(
        Surgery::new(&m, &inf),
        Err(SurgeryError::NonManifold { .. })
    ));
    assert!(matches!(
        Surgery::new(&rig.mesh, &inf),
        Err(SurgeryError::BadMesh(_))
    ));
}

/// Drill checks: manifold result, intersection points on the cylinder (side or end discs),
/// weights partitions of unity with at most 4 influences, input vertices unchanged.
fn check_drill(rig: &Rig, r: &deform::surgery::DrillResult, d: &deform::surgery::Drill) {
    let m = &r.mesh.mesh;
    assert_manifold(m);
    let all = deform::adjacency::boundary_loops(&m.triangles, m.vertex_count()).len();
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
    let axis = (d.end - d.tip).normalize();
    for (v, o) in r.origin.iter().enumerate() {
        if let VertexOrigin::Edge { .. } = o {
            let x = out[v] - d.tip;
            let radial = (x - x.dot(axis) * axis).length();
            assert!(
                (radial - d.radius).abs() < 1e-9 || x.dot(axis).abs() < 1e-9,
                "{radial}"
            );
        }
    }
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

/// Tear checks: manifold, area kept (a slit re-triangulates the same surface), incision points
/// on their step's plane, weights partitions of unity, input vertices unchanged.
fn check_tear(rig: &Rig, r: &deform::surgery::TearResult, opened: bool) {
    let m = &r.mesh.mesh;
    assert_manifold(m);
    let all = deform::adjacency::boundary_loops(&m.triangles, m.vertex_count()).len();
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
    for (v, o) in r.origin.iter().enumerate() {
        if matches!(o, VertexOrigin::Incision) {
            let d = r
                .planes
                .iter()
                .map(|(n, p)| n.dot(out[v] - *p).abs())
                .fold(f64::INFINITY, f64::min);
            assert!(d < 1e-9, "{d}");
        }
    }
    let Some(arm) = common::libigl_rig("arm") else {
        return;
    };
    let s = Surgery::new(&arm.mesh, &arm.influences).unwrap();
    let loops0 =
        deform::adjacency::boundary_loops(&arm.mesh.triangles, arm.mesh.vertex_count()).len();
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

/// The CLI: cut, tear and drill a rig into `.glb` files that keep the skin and animations
/// (checked by the Khronos validator in CI, read back and animated here); exit code 2 on bad
/// input.
#[test]
fn surgery_cli() {
    use std::process::Command;
    let out = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gltf-out");
    std::fs::create_dir_all(&out).unwrap();
    let exe = env!("CARGO_BIN_EXE_deform");
    let run = |args: &[&str]| Command::new(exe).args(args).output().unwrap();
    let rig_path = out.join("arm-rig.glb");
    let rig = procedural_arm(24, 81);
    deform::skinning::write_glb(&rig, &Default::default(), &rig_path).unwrap();
    let model = rig_path.to_str().unwrap();
    let cases: [(&str, Vec<&str>); 4] = [
        (
            "arm-cut.glb",
            vec!["cut", model, "--plane", "1,0.2,0,3.1", "--cap"],
        ),
        (
            "arm-tear.glb",
            vec![
                "tear",
                model,
                "--scalpel",
                "2,0.05,1.2:2,0.05,0.2",
                "--scalpel",
                "3,0.1,1.2:3,0.1,0.2",
                "--open",
                "0.2",
            ],
        ),
        (
            "arm-drill.glb",
            vec![
                "drill",
                model,
                "--tip=1.5,0.1,-2",
                "--end",
                "1.5,0.1,2",
                "--radius",
                "0.3",
            ],
        ),
        (
            "arm-cut-posed.glb",
            vec!["cut", model, "--plane", "0,1,0,2", "--time", "2"],
        ),
    ];
    for (file, mut args) in cases {
        let o = out.join(file);
        let path = o.to_str().unwrap().to_string();
        args.extend(["-o", &path, "--json"]);
        let r = run(&args);
        assert!(
            r.status.success(),
            "{file}: {}",
            String::from_utf8_lossy(&r.stderr)
        );
        let back = deform::skinning::read_gltf(&o).unwrap();
        assert_eq!(back.animations.len(), 1, "{file}: the animation is kept");
        assert_eq!(back.joints.len(), 3);
        let pose = back.pose(Some(0), 1.0, &[]).unwrap();
        let b = Skinning::bind(&back, BlendMethod::Conformal).unwrap();
        let mut p = vec![DVec3::ZERO; back.mesh.vertex_count()];
        b.pose(pose.skin_motors().unwrap(), &mut p).unwrap();
        assert!(p.iter().all(|x| x.is_finite()), "{file} re-animates");
    }
    for args in [
        vec!["cut", model, "--plane", "1,0,0,100", "-o", "/tmp/never.glb"],
        vec!["cut", model, "--plane", "0,0,0,1", "-o", "/tmp/never.glb"],
        vec![
            "drill",
            model,
            "--tip=0,9,0",
            "--end",
            "1,9,0",
            "--radius",
            "0.1",
            "-o",
            "/tmp/never.glb",
        ],
        vec![
            "tear",
            model,
            "--scalpel",
            "2,0,1.2:2,0,0.2",
            "-o",
            "/tmp/never.glb",
        ],
        vec!["cut", model, "--plane", "1,0,0,3", "-o", model],
    ] {
        let r = run(&args);
        assert_eq!(r.status.code(), Some(2), "{args:?}");
        assert!(!r.stderr.is_empty());
    }
}
