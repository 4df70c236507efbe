//! Tools in a frame posed by any blend method (`Frame::Blended`): a new vertex goes back to
//! the rest pose through the inverse of its own blend of the keys, so the method that drew the
//! frame poses it where the tool made it. Mapping back by linear blend skinning instead (what
//! `Frame::Posed` does) leaves it off the tool by the difference of the two blends.

use super::{assert_manifold, assert_on_drill, assert_on_incision};
use cga::{Plane, ScaledMotor};
use deform::blend::PreparedKeys;
use deform::skinning::{procedural_arm, Influences, Rig, Skinning};
use deform::surgery::{CutOptions, Drill, DrillOptions, Frame, Scalpel, Surgery, TearOptions};
use deform::surgery::{SurgeryError, VertexOrigin};
use deform::BlendMethod;
use glam::DVec3;

/// The methods whose blend has an affine inverse per vertex.
const METHODS: [BlendMethod; 5] = [
    BlendMethod::MotorLog,
    BlendMethod::MotorLinear,
    BlendMethod::DualQuaternion,
    BlendMethod::Conformal,
    BlendMethod::Matrix,
];

/// The arm at its bent frame: the skin motors, and the positions and prepared keys of
/// `method`'s pose.
fn posed(rig: &Rig, method: BlendMethod) -> (Vec<ScaledMotor>, Vec<DVec3>, PreparedKeys) {
    let pose = rig.pose(Some(0), 2.0, &[]).unwrap();
    let keys = pose.skin_motors().unwrap().to_vec();
    let skin = Skinning::bind(rig, method).unwrap();
    let mut prepared = skin.blend().scratch();
    let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    skin.blend()
        .pose_using(&keys, &mut prepared, &mut out)
        .unwrap();
    (keys, out, prepared)
}

/// A result mesh posed by `method` with `keys`.
fn repose(
    positions: &[DVec3],
    influences: &Influences,
    keys: &[ScaledMotor],
    method: BlendMethod,
) -> Vec<DVec3> {
    let b = Skinning::bind_influences(positions, influences, keys.len(), method).unwrap();
    let mut out = vec![DVec3::ZERO; positions.len()];
    deform::Deformer::pose(&b, keys, &mut out).unwrap();
    out
}

/// Across the forearm in world space, the elbow bent 100 degrees.
fn plane() -> Plane {
    Plane::from_normal_distance(DVec3::new(0.2, 1.0, 0.0), 2.0)
}

#[test]
fn a_cut_in_a_blended_frame_poses_back_onto_the_plane() {
    let rig = procedural_arm(16, 41);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    for method in METHODS {
        let (keys, positions, prepared) = posed(&rig, method);
        let frame = Frame::Blended {
            positions: &positions,
            keys: &prepared,
        };
        let cut = s.cut(&plane(), frame, &CutOptions::default()).unwrap();
        assert!(cut.new_vertices > 0);
        for piece in &cut.pieces {
            assert_manifold(&piece.mesh.mesh);
            let m = &piece.mesh;
            let out = repose(&m.mesh.positions, &m.influences, &keys, method);
            for (v, o) in piece.origin.iter().enumerate() {
                if let VertexOrigin::Edge { .. } = o {
                    let d = plane().signed_distance(out[v]).abs();
                    assert!(d < 1e-9 * diag, "{}: vertex {v} {d} off", method.name());
                }
            }
        }
    }
}

/// The same cut with the frame's positions from dual quaternions but mapped back by LBS
/// (`Frame::Posed`, the skin matrices) lands off the plane when posed by dual quaternions:
/// what `Frame::Blended` is for.
#[test]
fn mapping_a_blended_frame_back_by_lbs_misses_the_plane() {
    let rig = procedural_arm(16, 41);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    let method = BlendMethod::DualQuaternion;
    let (keys, positions, _) = posed(&rig, method);
    let pose = rig.pose(Some(0), 2.0, &[]).unwrap();
    let frame = Frame::Posed {
        positions: &positions,
        skin: &pose.skin_matrices,
    };
    let cut = s.cut(&plane(), frame, &CutOptions::default()).unwrap();
    let mut worst = 0.0f64;
    for piece in &cut.pieces {
        let m = &piece.mesh;
        let out = repose(&m.mesh.positions, &m.influences, &keys, method);
        for (v, o) in piece.origin.iter().enumerate() {
            if let VertexOrigin::Edge { .. } = o {
                worst = worst.max(plane().signed_distance(out[v]).abs());
            }
        }
    }
    assert!(worst > 1e-6 * diag, "LBS inverse of a DQS frame: {worst}");
}

#[test]
fn drills_and_tears_in_a_blended_frame_pose_back_onto_the_tool() {
    let rig = procedural_arm(24, 81);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    for method in [BlendMethod::MotorLog, BlendMethod::DualQuaternion] {
        let (keys, positions, prepared) = posed(&rig, method);
        let frame = Frame::Blended {
            positions: &positions,
            keys: &prepared,
        };
        // Across the forearm (it points up after the bend); refined where the drill needs.
        let d = Drill {
            tip: DVec3::new(2.5, 2.0, -2.0),
            end: DVec3::new(5.5, 2.0, 2.0),
            radius: 0.2,
        };
        let r = s.drill(&d, frame, &DrillOptions::default()).unwrap();
        assert_manifold(&r.mesh.mesh);
        let out = repose(&r.mesh.mesh.positions, &r.mesh.influences, &keys, method);
        assert_on_drill(&out, &r.origin, &d, method.name());
        // A tear along the forearm's +x side: the incision lies on the step planes.
        let blade = |y: f64| Scalpel {
            a: DVec3::new(5.5, y, 0.02),
            b: DVec3::new(4.0, y, 0.02),
        };
        let t = s
            .tear(&[blade(1.5), blade(2.5)], frame, &TearOptions::default())
            .unwrap();
        assert_manifold(&t.mesh.mesh);
        let out = repose(&t.mesh.mesh.positions, &t.mesh.influences, &keys, method);
        assert_on_incision(&out, &t, method.name());
    }
}

/// Keys for fewer joints than the influences name, or conformal-projected keys (no transform
/// per vertex to invert): typed errors, not a panic or an approximate mapping.
#[test]
fn blended_frames_without_an_inverse_are_refused() {
    let rig = procedural_arm(8, 10);
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let (_, positions, _) = posed(&rig, BlendMethod::MotorLog);
    let one = PreparedKeys::new(&[ScaledMotor::IDENTITY], BlendMethod::MotorLog).unwrap();
    let frame = Frame::Blended {
        positions: &positions,
        keys: &one,
    };
    let r = s.cut(&plane(), frame, &CutOptions::default());
    assert!(matches!(r, Err(SurgeryError::BadTool(_))), "{r:?}");
    // Conformal-projected blending has no per-vertex transform to invert: refused.
    let (_, positions, projected) = posed(&rig, BlendMethod::ConformalProjected);
    let frame = Frame::Blended {
        positions: &positions,
        keys: &projected,
    };
    let r = s.cut(&plane(), frame, &CutOptions::default());
    assert!(
        matches!(r, Err(SurgeryError::BadTool(ref m)) if m.contains("conformal-projected")),
        "{r:?}"
    );
}
