//! Mesh geometry, adjacency, validation and cleaning.

use crate::common;
use deform::operators::SolveError;

use common::grid;
use deform::mesh::validate::clean;
use deform::mesh::validate::validate;
use deform::Mesh;
use glam::DVec3;

fn tetrahedron() -> Mesh {
    Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z],
        vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
}

#[test]
fn geometry_of_a_tetrahedron() {
    let t = tetrahedron();
    let bb = t.bounding_box().expect("box");
    assert_eq!((bb.min, bb.max), (DVec3::ZERO, DVec3::ONE));
    assert!((t.volume() - 1.0 / 6.0).abs() < 1e-15);
    assert!((t.area() - (1.5 + 3f64.sqrt() / 2.0)).abs() < 1e-15);
    assert_eq!(t.face_normals()[0], DVec3::NEG_Z);
    let n0 = t.vertex_normals()[0];
    assert!((n0 - DVec3::splat(-1.0 / 3f64.sqrt())).length() < 1e-15);
    assert!(Mesh::default().bounding_box().is_none());
}

#[test]
fn edges_rings_and_components() {
    let t = tetrahedron();
    let e = t.edges();
    assert_eq!(
        e.edges,
        vec![[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]
    );
    assert!(e.face_count.iter().all(|&c| c == 2));
    // Edge opposite corner 0 of triangle [0, 2, 1] is 2-1.
    assert_eq!(e.edges[e.face_edges[0][0] as usize], [1, 2]);
    let rings = t.one_rings();
    assert_eq!(rings.row(2), &[0, 1, 3]);
    assert_eq!(t.vertex_faces().row(3), &[1, 2, 3]);
    assert!(t.boundary_loops().is_empty());
    let mut two = t.clone();
    two.positions.extend([
        DVec3::splat(5.0),
        DVec3::splat(6.0),
        DVec3::new(5.0, 6.0, 5.0),
    ]);
    two.triangles.push([4, 5, 6]);
    let c = two.components();
    assert_eq!(c.count, 2);
    assert_eq!(c.members()[1], vec![4, 5, 6]);
}

#[test]
fn grid_boundary_loop_follows_orientation() {
    let m = grid(4, 3, false);
    let loops = m.boundary_loops();
    assert_eq!(loops.len(), 1);
    let l = &loops[0];
    assert_eq!(l.len(), 10);
    // Counter-clockwise triangles: the boundary runs counter-clockwise, 0 -> 1 -> 2 ...
    let at0 = l.iter().position(|&v| v == 0).expect("corner");
    assert_eq!(l[(at0 + 1) % l.len()], 1);
    assert_eq!(m.edges().boundary().count(), 10);
}

/// A pinwheel of separate triangles around one vertex: every boundary edge is in exactly one
/// loop, each loop a triangle through the centre. 60,000 blades: the centre's 60,000 outgoing
/// boundary edges were scanned from the first at each of its visits (quadratic: 0.7 s here).
#[test]
fn boundary_loops_at_a_vertex_on_many_boundary_edges() {
    let blades = 60_000u32;
    let mut positions = vec![DVec3::ZERO];
    let mut triangles = Vec::new();
    for i in 0..blades {
        let a = std::f64::consts::TAU * f64::from(i) / f64::from(blades);
        positions.push(DVec3::new(a.cos(), a.sin(), 0.0));
        positions.push(DVec3::new((a + 1e-5).cos(), (a + 1e-5).sin(), 0.0));
        triangles.push([0, 2 * i + 1, 2 * i + 2]);
    }
    let m = Mesh::new(positions, triangles);
    let loops = m.boundary_loops();
    assert_eq!(loops.len(), blades as usize);
    let mut seen = std::collections::HashSet::new();
    for l in &loops {
        assert_eq!(l.len(), 3, "{l:?}");
        assert!(l.contains(&0));
        for k in 0..3 {
            assert!(seen.insert((l[k], l[(k + 1) % 3])), "edge used twice");
        }
    }
    assert_eq!(seen.len(), 3 * blades as usize);
}

#[test]
fn midpoint_subdivision() {
    let t = tetrahedron();
    let s = t.subdivide_midpoint();
    assert_eq!((s.vertex_count(), s.triangle_count()), (10, 16));
    assert!((s.area() - t.area()).abs() < 1e-15);
    assert!((s.volume() - t.volume()).abs() < 1e-15);
    assert!(validate(&s).is_clean());
    assert!(s.edges().face_count.iter().all(|&c| c == 2));
}

#[test]
fn validation_reports_every_problem_with_indices() {
    let mut m = grid(3, 3, false); // 9 vertices, 8 triangles
    m.positions.push(DVec3::splat(9.0)); // 9: unreferenced
    m.positions.push(DVec3::new(f64::INFINITY, 0.0, 0.0)); // 10: non-finite (unreferenced)
    m.triangles.push([0, 1, 99]); // 8: out of range
    m.triangles.push([4, 4, 5]); // 9: repeated index
    m.triangles.push(m.triangles[0]); // 10: duplicate of 0 (and makes its edges non-manifold)
    m.positions.push(DVec3::new(0.5, 0.0, 0.0)); // 11
    m.triangles.push([0, 11, 1]); // 11: zero area
    let r = validate(&m);
    assert_eq!(r.out_of_range_faces, vec![8]);
    assert_eq!(r.degenerate_faces, vec![9, 11]);
    assert_eq!(r.duplicate_faces, vec![[10, 0]]);
    assert_eq!(r.unreferenced_vertices, vec![9, 10]);
    assert_eq!(r.non_finite_vertices, vec![10]);
    assert!(r.non_manifold_edges.contains(&[0, 1]));
    assert!(!r.is_clean());
    assert!(r.check_solvable().is_err());
    let c = clean(&m);
    assert_eq!(c.removed_faces, vec![8, 9, 10, 11]);
    assert_eq!(c.mesh.vertex_count(), 9);
    assert!(validate(&c.mesh).is_clean());
    assert!(c.remap(&[9]).is_err());
    assert!(c.remap(&[1000]).is_err());
    assert_eq!(c.remap(&[8, 0]).expect("kept"), vec![8, 0]);
}

#[test]
fn bow_tie_and_components_are_reported() {
    let bow = Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::X,
            DVec3::Y,
            DVec3::NEG_X,
            DVec3::NEG_Y,
            DVec3::splat(3.0),
            DVec3::splat(4.0),
            DVec3::new(3.0, 4.0, 3.0),
        ],
        vec![[0, 1, 2], [0, 3, 4], [5, 6, 7]],
    );
    let r = validate(&bow);
    assert_eq!(r.non_manifold_vertices, vec![0]);
    assert!(r.non_manifold_edges.is_empty());
    assert_eq!(r.components, vec![0, 5]);
    assert_eq!(r.boundary_edges, 9);
}

#[test]
fn raw_stanford_bunny_is_cleaned() {
    let Some(p) = common::mesh_path("common-3d-test-models/stanford-bunny.obj") else {
        return;
    };
    let m = deform::mesh::io::read_mesh(p).expect("bunny");
    let r = validate(&m);
    assert_eq!(r.unreferenced_vertices.len(), 1113);
    assert_eq!(r.boundary_edges, 223);
    assert!(r.check_solvable().is_ok());
    let c = clean(&m);
    assert_eq!(c.mesh.vertex_count(), 35947 - 1113);
    let rc = validate(&c.mesh);
    assert!(rc.unreferenced_vertices.is_empty() && rc.degenerate_faces.is_empty());
    // Harmonic field between the lowest and highest vertices on the cleaned mesh.
    let ys: Vec<f64> = c.mesh.positions.iter().map(|p| p.y).collect();
    let lo = (0..ys.len())
        .min_by(|&a, &b| ys[a].total_cmp(&ys[b]))
        .expect("lo") as u32;
    let hi = (0..ys.len())
        .max_by(|&a, &b| ys[a].total_cmp(&ys[b]))
        .expect("hi") as u32;
    assert_eq!(rc.components.len(), 1);
    let x = deform::operators::harmonic::harmonic_field(&c.mesh, &[lo], &[hi], Default::default())
        .expect("field");
    assert!(x.iter().all(|v| v.is_finite()));
    assert_eq!((x[lo as usize], x[hi as usize]), (0.0, 1.0));
    // On the raw scan the unreferenced vertices make the system singular, named as such.
    match deform::operators::harmonic::harmonic_field(
        &m,
        &[c.new_to_old[lo as usize]],
        &[c.new_to_old[hi as usize]],
        Default::default(),
    ) {
        Err(SolveError::Unconstrained {
            components,
            isolated,
            vertices,
        }) => {
            assert_eq!(components, 1113);
            assert_eq!(
                isolated, 1113,
                "every unreferenced vertex is a single vertex"
            );
            assert_eq!(vertices.0, r.unreferenced_vertices);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn slab_handles_match_the_readme_timing_convention() {
    let Some(p) = common::mesh_path("large/cactus-5k.off") else {
        return;
    };
    let m = deform::mesh::io::read_mesh(p).expect("cactus");
    let fixed = m.vertices_in_slab(1, 0.0, 0.05);
    let moved = m.vertices_in_slab(1, 0.95, 1.0);
    // The README's table lists 422 handles for cactus-5k.
    assert_eq!((fixed.len(), moved.len()), (256, 166));
}
