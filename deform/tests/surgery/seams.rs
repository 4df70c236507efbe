//! Cuts of a glTF model whose vertices are split along UV seams (CesiumMan: 3,273 vertices at
//! 2,338 positions). Vertex by vertex the model is a set of open patches; the cut finds its
//! loops and caps over coincident vertices welded, so both pieces close.

use crate::common;

use cga::Plane;
use deform::skinning::read_gltf;
use deform::surgery::{CutOptions, CutResult, Frame, Surgery, VertexOrigin};
use deform::Mesh;
use glam::DVec3;
use std::collections::HashMap;

/// The triangles with every vertex replaced by the first vertex at its position (an
/// independent weld: exact positions, no tolerance).
pub(crate) fn welded(m: &Mesh) -> Vec<[u32; 3]> {
    let mut first = HashMap::new();
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
    m.triangles
        .iter()
        .map(|t| t.map(|v| canon[v as usize]))
        .collect()
}

fn welded_loops(m: &Mesh) -> usize {
    deform::mesh::adjacency::boundary_loops(&welded(m), m.vertex_count()).len()
}

/// Welded, the piece is an edge-manifold, consistently oriented surface.
fn assert_welded_manifold(m: &Mesh) {
    common::assert_oriented_manifold(&welded(m), m.vertex_count());
}

/// Areas add up (caps aside), new vertices lie on the plane, loops agree with a welded count.
fn check(mesh: &Mesh, cut: &CutResult, plane: &Plane) {
    let diag = mesh.bounding_box().unwrap().diagonal();
    let mut area = 0.0;
    for p in &cut.pieces {
        let m = &p.mesh.mesh;
        assert_welded_manifold(m);
        assert_eq!(p.boundary_loops, welded_loops(m), "boundary loops");
        area += p
            .face_origin
            .iter()
            .zip(m.face_areas())
            .filter(|(o, _)| **o != u32::MAX)
            .map(|(_, a)| a)
            .sum::<f64>();
        for (v, o) in p.origin.iter().enumerate() {
            if let VertexOrigin::Edge { .. } = o {
                let d = plane.signed_distance(m.positions[v]).abs();
                assert!(d <= 1e-9 * diag, "new vertex {v} is {d} off the plane");
            }
        }
    }
    let a0 = mesh.area();
    assert!((area - a0).abs() <= 1e-9 * a0, "areas {area} vs {a0}");
}

#[test]
fn cesium_man_cuts_close_over_uv_seams() {
    let Some(dir) = common::data_dir() else {
        return;
    };
    let rig = read_gltf(dir.join("gltf/CesiumMan.glb")).unwrap();
    let mesh = &rig.mesh;
    let raw_loops = deform::mesh::adjacency::boundary_loops(&mesh.triangles, mesh.vertex_count());
    assert!(raw_loops.len() > 100, "{} seam loops", raw_loops.len());
    assert_eq!(welded_loops(mesh), 0, "CesiumMan is closed once welded");
    let s = Surgery::new(mesh, &rig.influences).unwrap();
    let bb = mesh.bounding_box().unwrap();
    let centre = 0.5 * (bb.min + bb.max);
    let v0 = mesh.volume();
    for normal in [DVec3::Z, DVec3::X, DVec3::new(1.0, 0.3, 0.5).normalize()] {
        let plane = Plane::from_normal_distance(normal, normal.dot(centre) + 0.01);
        let open = s.cut(&plane, Frame::Rest, &CutOptions::default()).unwrap();
        check(mesh, &open, &plane);
        assert!(open.pieces.iter().all(|p| p.boundary_loops >= 1));
        // Capped: both pieces close. With snapping off every cap vertex lies on the plane, so
        // the caps are planar and the volumes add up exactly (a snapped vertex is treated as
        // on the plane without being moved, and a non-planar cap's volume depends on its
        // triangulation).
        for snap in [CutOptions::default().snap, 0.0] {
            let capped = CutOptions { cap: true, snap };
            let closed = s.cut(&plane, Frame::Rest, &capped).unwrap();
            check(mesh, &closed, &plane);
            for p in &closed.pieces {
                assert_eq!(p.boundary_loops, 0, "normal {normal}");
                assert!(p.cap_triangles > 0);
            }
            if snap == 0.0 {
                assert_eq!(closed.snapped_vertices, 0);
                let v: f64 = closed.pieces.iter().map(|p| p.mesh.mesh.volume()).sum();
                assert!((v - v0).abs() < 1e-9 * v0.abs(), "{v} vs {v0}");
            }
        }
    }
}

/// Linear blend skinning by the skin matrices themselves (what `Frame::Posed` is given).
fn lbs(rest: &[DVec3], inf: &deform::skinning::Influences, skin: &[glam::DAffine3]) -> Vec<DVec3> {
    rest.iter()
        .enumerate()
        .map(|(v, &p)| {
            inf.row(v)
                .map(|(j, w)| w * skin[j as usize].transform_point3(p))
                .sum()
        })
        .collect()
}

/// A posed cut of CesiumMan mid-walk closes too, and the pieces pose back onto the plane.
#[test]
fn cesium_man_posed_cut_closes() {
    let Some(dir) = common::data_dir() else {
        return;
    };
    let rig = read_gltf(dir.join("gltf/CesiumMan.glb")).unwrap();
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let (t0, t1) = rig.animations[0].range();
    let pose = rig.pose(Some(0), 0.5 * (t0 + t1), &[]).unwrap();
    let skin = &pose.skin_matrices;
    let posed = lbs(&rig.mesh.positions, &rig.influences, skin);
    let posed_mesh = Mesh::new(posed.clone(), rig.mesh.triangles.clone());
    let bb = posed_mesh.bounding_box().unwrap();
    let centre = 0.5 * (bb.min + bb.max);
    // Across the body's longest extent, through the middle.
    let e = bb.max - bb.min;
    let axis = if e.x >= e.y && e.x >= e.z {
        DVec3::X
    } else if e.y >= e.z {
        DVec3::Y
    } else {
        DVec3::Z
    };
    let plane = Plane::from_normal_distance(axis, axis.dot(centre));
    let frame = Frame::Posed {
        positions: &posed,
        skin,
    };
    let options = CutOptions {
        cap: true,
        ..CutOptions::default()
    };
    let cut = s.cut(&plane, frame, &options).unwrap();
    let diag = bb.diagonal();
    for p in &cut.pieces {
        assert_eq!(p.boundary_loops, 0);
        assert!(p.cap_triangles > 0);
        assert_welded_manifold(&p.mesh.mesh);
        let out = lbs(&p.mesh.mesh.positions, &p.mesh.influences, skin);
        for (v, o) in p.origin.iter().enumerate() {
            if let VertexOrigin::Edge { .. } = o {
                let d = plane.signed_distance(out[v]).abs();
                assert!(d < 1e-9 * diag, "posed new vertex {v} is {d} off the plane");
            }
        }
        // Posed, the piece is closed over welded vertices too: copies pose alike.
        assert_eq!(
            welded_loops(&Mesh::new(out, p.mesh.mesh.triangles.clone())),
            0
        );
    }
}
