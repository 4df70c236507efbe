//! Planar cuts of skinned meshes (second paper, Algorithm 1): areas and volumes add up, new
//! vertices lie on the plane, pieces are edge-manifold with the expected boundary loops,
//! triangles keep a quality bound, weights stay partitions of unity, and the pieces animate
//! exactly as the uncut mesh did.

#[path = "../common/mod.rs"]
mod common;

mod blended;
#[cfg(feature = "cli")]
mod cli;
mod drill;
mod look;
mod seams;
mod tear;
mod tear_steps;

use cga::{Plane, ScaledMotor};
use deform::skinning::{procedural_arm, Rig, Skinning};
use deform::surgery::{
    CutOptions, CutPiece, CutResult, Frame, Surgery, SurgeryError, VertexOrigin,
};
use deform::{BlendMethod, Deformer, Mesh};
use glam::{DQuat, DVec3};

pub(crate) fn assert_manifold(m: &Mesh) {
    common::assert_oriented_manifold(&m.triangles, m.vertex_count());
}

/// Every vertex a drill made, at its posed position `out`, lies on the drill's cylinder (or
/// on a cap plane through its tip).
pub(crate) fn assert_on_drill(
    out: &[DVec3],
    origin: &[VertexOrigin],
    d: &deform::surgery::Drill,
    what: &str,
) {
    let axis = (d.end - d.tip).normalize();
    for (v, o) in origin.iter().enumerate() {
        if let VertexOrigin::Edge { .. } = o {
            let x = out[v] - d.tip;
            let radial = (x - x.dot(axis) * axis).length();
            assert!(
                (radial - d.radius).abs() < 1e-9 || x.dot(axis).abs() < 1e-9,
                "{what}: vertex {v} at {radial} from the axis"
            );
        }
    }
}

/// Every incision vertex of a tear, at its posed position `out`, lies on one of the steps'
/// planes.
pub(crate) fn assert_on_incision(out: &[DVec3], t: &deform::surgery::TearResult, what: &str) {
    for (v, o) in t.origin.iter().enumerate() {
        if matches!(o, VertexOrigin::Incision) {
            let d = t
                .planes
                .iter()
                .map(|(n, p)| n.dot(out[v] - *p).abs())
                .fold(f64::INFINITY, f64::min);
            assert!(d < 1e-9, "{what}: incision vertex {v} is {d} off");
        }
    }
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
        let all = deform::mesh::adjacency::boundary_loops(&m.triangles, m.vertex_count()).len();
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
        deform::mesh::adjacency::boundary_loops(&rig.mesh.triangles, rig.mesh.vertex_count()).len();
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
    // Influences whose joints and weights differ in length (a cut then panicked), a weight
    // that is not finite (a cut gave pieces of NaN weights), a coordinate beyond 1e300.
    let mut short = rig.influences.clone();
    short.joints.truncate(short.joints.len() - 9);
    let mut nan = rig.influences.clone();
    nan.weights[5] = f64::NAN;
    let mut far = rig.mesh.clone();
    far.positions[3].z = 1e301;
    for (mesh, inf, words) in [
        (&rig.mesh, &short, "influence joints for"),
        (
            &rig.mesh,
            &nan,
            "vertex 1: influence weight NaN is not finite",
        ),
        (
            &far,
            &rig.influences,
            "vertices [3] have coordinates beyond",
        ),
    ] {
        match Surgery::new(mesh, inf) {
            Err(SurgeryError::BadMesh(m)) => assert!(m.contains(words), "{m}"),
            other => panic!("{words}: {:?}", other.map(|_| ())),
        }
    }
}
