//! Tears with long scalpel steps (issue 21): between two positions the incision follows the
//! swept blade's plane across as many faces and UV seams as it crosses, the arc between the
//! two entry points that stays by the swept blade; loops are counted over the welded surface,
//! alike on the rest pose and on a posed frame.

use crate::seams::welded;
use crate::{assert_manifold, common};
use deform::skinning::{procedural_arm, read_gltf, Influences, Rig, Skinning};
use deform::surgery::{
    Frame, Scalpel, Surgery, SurgeryError, TearOptions, TearResult, VertexOrigin,
};
use deform::{BlendMethod, Deformer, Mesh};
use glam::{DAffine3, DQuat, DVec3};
use std::collections::HashSet;

/// Loops of the mesh welded by bit-identical positions (an independent count).
fn welded_loops(m: &Mesh) -> usize {
    deform::mesh::adjacency::boundary_loops(&welded(m), m.vertex_count()).len()
}

/// A blade from `a` to `b`.
fn blade(a: DVec3, b: DVec3) -> Scalpel {
    Scalpel { a, b }
}

/// Every check of a tear of `mesh` by `blades`, its lips pulled apart by `open`:
/// edge-manifold over its own and over welded vertices, loops counted as a weld by positions
/// counts them, area kept, new points on their step planes, originals in place, weights
/// partitions of unity, the incision a chain of edges that stays by the swept blades, and
/// every inner incision point split into two lips.
fn check(mesh: &Mesh, blades: &[Scalpel], r: &TearResult, open: f64) {
    let m = &r.mesh.mesh;
    let diag = mesh.bounding_box().unwrap().diagonal();
    assert_manifold(m);
    common::assert_oriented_manifold(&welded(m), m.vertex_count());
    if open == 0.0 {
        // A closed slit welded by position is the input's surface again: no T-junction where
        // the incision crossed a seam (both copies of a seam edge were split alike).
        assert_eq!(welded_loops(m), welded_loops(mesh), "closed slit, welded");
        let a0 = mesh.area();
        assert!(
            (m.area() - a0).abs() < 1e-9 * a0,
            "area {} vs {a0}",
            m.area()
        );
    } else {
        assert_eq!(
            r.boundary_loops,
            welded_loops(m),
            "loops over welded vertices"
        );
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
            widest > 0.5 * open && widest <= open * (1.0 + 1e-9),
            "widest gap {widest}"
        );
    }
    // Input positions of the incision (each stands for its seam copies too): only those move.
    let on_incision: HashSet<[u64; 3]> = r
        .incision
        .iter()
        .filter_map(|&v| match r.origin[v as usize] {
            VertexOrigin::Original(i) => {
                Some(mesh.positions[i as usize].to_array().map(f64::to_bits))
            }
            _ => None,
        })
        .collect();
    for (v, o) in r.origin.iter().enumerate() {
        match *o {
            VertexOrigin::Incision if open == 0.0 => {
                let d = r
                    .planes
                    .iter()
                    .map(|(n, p)| n.dot(m.positions[v] - *p).abs())
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    d < 1e-9 * diag,
                    "incision vertex {v} is {d} off every plane"
                );
            }
            VertexOrigin::Original(i)
                if open == 0.0
                    || !on_incision
                        .contains(&mesh.positions[i as usize].to_array().map(f64::to_bits)) =>
            {
                assert_eq!(m.positions[v], mesh.positions[i as usize]);
            }
            _ => {}
        }
        let row: Vec<(u32, f64)> = r.mesh.influences.row(v).collect();
        assert!((row.iter().map(|x| x.1).sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(row.iter().all(|x| x.1 >= 0.0));
        if !o.is_input() {
            assert!(row.iter().filter(|x| x.1 != 0.0).count() <= 4);
        }
    }
    // The incision: a chain of edges of the welded surface, from blade to blade, staying in
    // the box of some step's two blades (the arc that goes around the body is far from them).
    let canon = {
        let mut first = std::collections::HashMap::new();
        (0..m.vertex_count())
            .map(|v| {
                *first
                    .entry(m.positions[v].to_array().map(f64::to_bits))
                    .or_insert(v as u32)
            })
            .collect::<Vec<u32>>()
    };
    let edges: HashSet<(u32, u32)> = m
        .triangles
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
        .map(|(a, b)| {
            let (a, b) = (canon[a as usize], canon[b as usize]);
            (a.min(b), a.max(b))
        })
        .collect();
    for w in r.incision.windows(2) {
        let (a, b) = (canon[w[0] as usize], canon[w[1] as usize]);
        assert!(
            edges.contains(&(a.min(b), a.max(b))),
            "incision {w:?} is no edge"
        );
    }
    let margin = 0.02 * diag;
    for &v in &r.incision {
        let p = m.positions[v as usize];
        let inside = blades.windows(2).any(|s| {
            let lo = s[0].a.min(s[0].b).min(s[1].a.min(s[1].b)) - DVec3::splat(margin);
            let hi = s[0].a.max(s[0].b).max(s[1].a.max(s[1].b)) + DVec3::splat(margin);
            p.cmpge(lo).all() && p.cmple(hi).all()
        });
        assert!(inside, "incision point {p} strays from the swept blades");
    }
    assert!(r.incision.len() >= blades.len());
    assert_eq!(
        r.duplicated,
        r.incision.len() - 2,
        "every inner point has two lips"
    );
}

/// Tear closed and opened, check both, and return the closed one.
fn tear_both(s: &Surgery, mesh: &Mesh, blades: &[Scalpel], open: f64) -> TearResult {
    let closed = s
        .tear(blades, Frame::Rest, &TearOptions::default())
        .unwrap();
    check(mesh, blades, &closed, 0.0);
    let options = TearOptions {
        open,
        ..TearOptions::default()
    };
    let opened = s.tear(blades, Frame::Rest, &options).unwrap();
    check(mesh, blades, &opened, open);
    assert_eq!(closed.boundary_loops, opened.boundary_loops);
    assert_eq!(closed.incision.len(), opened.incision.len());
    closed
}

fn cesium_man() -> Option<Rig> {
    let dir = common::data_dir()?;
    Some(read_gltf(dir.join("gltf/CesiumMan.glb")).unwrap())
}

/// CesiumMan (Z-up, about 1.5 high, split along UV seams): scalpel steps of a tenth of its
/// height, down its side off and on its mirror plane, and round its chest.
#[test]
fn long_steps_over_cesium_man() {
    let Some(rig) = cesium_man() else {
        return;
    };
    let mesh = &rig.mesh;
    let bb = mesh.bounding_box().unwrap();
    let step = (bb.max.z - bb.min.z) / 10.0;
    let s = Surgery::new(mesh, &rig.influences).unwrap();
    // Up the front, into the skin along -x: beside the mirror plane y = 0 (over belly and
    // chest), on it (where the plane runs through the model's own vertices and edges), and
    // up a leg.
    for (y, z0) in [(0.02, 0.85), (0.0, 0.9), (0.05, 0.3)] {
        let blades: Vec<Scalpel> = (0..4)
            .map(|k| {
                let z = z0 + k as f64 * step;
                blade(DVec3::new(0.3, y, z), DVec3::new(0.0, y, z))
            })
            .collect();
        let r = tear_both(&s, mesh, &blades, 0.01);
        assert_eq!(r.boundary_loops, 1, "one slit (y = {y}, from z = {z0})");
    }
    // Round the belly (issue 21's example, 0.1 apart, and steps of a tenth of the height).
    for ys in [vec![0.0, 0.1], vec![-step, 0.0, step]] {
        let blades: Vec<Scalpel> = ys
            .iter()
            .map(|&y| blade(DVec3::new(0.3, y, 1.05), DVec3::new(0.0, y, 1.05)))
            .collect();
        let r = tear_both(&s, mesh, &blades, 0.01);
        assert_eq!(r.boundary_loops, 1, "one slit ({ys:?})");
        assert!(r.incision.len() > 3, "{} points", r.incision.len());
    }
}

/// The Fox (Y-up, about 79 high, every triangle with its own three vertices): steps of a
/// tenth of its height along its flank and up it.
#[test]
fn long_steps_over_the_fox() {
    let Some(dir) = common::data_dir() else {
        return;
    };
    let rig = read_gltf(dir.join("gltf/Fox.glb")).unwrap();
    let mesh = &rig.mesh;
    let bb = mesh.bounding_box().unwrap();
    let step = (bb.max.y - bb.min.y) / 10.0;
    let s = Surgery::new(mesh, &rig.influences).unwrap();
    let flank = |y: f64, z: f64| blade(DVec3::new(30.0, y, z), DVec3::new(0.0, y, z));
    let along: Vec<Scalpel> = (0..4)
        .map(|k| flank(40.0, -20.0 + k as f64 * step))
        .collect();
    let up: Vec<Scalpel> = (0..3)
        .map(|k| flank(40.0 + k as f64 * step, -20.0))
        .collect();
    for blades in [along, up] {
        let r = tear_both(&s, mesh, &blades, 0.5);
        assert_eq!(r.boundary_loops, 1);
        // Each step crosses several faces.
        assert!(r.incision.len() > blades.len() + 2, "{}", r.incision.len());
    }
}

/// Linear blend skinning by the skin matrices themselves (what `Frame::Posed` is given).
fn lbs(rest: &[DVec3], inf: &Influences, skin: &[DAffine3]) -> Vec<DVec3> {
    rest.iter()
        .enumerate()
        .map(|(v, &p)| {
            inf.row(v)
                .map(|(j, w)| w * skin[j as usize].transform_point3(p))
                .sum()
        })
        .collect()
}

/// A tear on a posed frame reports what the same tear on the rest pose reports: on a frame
/// that moves the whole model rigidly, every count; on a frame of its walk, blades carried
/// by the joint that moves their part of the body, the same loops.
#[test]
fn rest_and_posed_tears_count_alike() {
    let Some(rig) = cesium_man() else {
        return;
    };
    let mesh = &rig.mesh;
    let s = Surgery::new(mesh, &rig.influences).unwrap();
    let step = 0.15;
    let blades: Vec<Scalpel> = (0..4)
        .map(|k| {
            let z = 0.85 + k as f64 * step;
            blade(DVec3::new(0.3, 0.02, z), DVec3::new(0.0, 0.02, z))
        })
        .collect();
    let rest = s
        .tear(&blades, Frame::Rest, &TearOptions::default())
        .unwrap();
    assert_eq!(rest.boundary_loops, 1);
    let carried = |m: &DAffine3| -> Vec<Scalpel> {
        blades
            .iter()
            .map(|b| blade(m.transform_point3(b.a), m.transform_point3(b.b)))
            .collect()
    };
    // Rigidly moved: the same tear.
    let m = DAffine3::from_rotation_translation(
        DQuat::from_rotation_x(-std::f64::consts::FRAC_PI_2),
        DVec3::new(0.25, -0.5, 2.0),
    );
    let skin = vec![m; rig.joints.len()];
    let posed = lbs(&mesh.positions, &rig.influences, &skin);
    let frame = Frame::Posed {
        positions: &posed,
        skin: &skin,
    };
    let r = s
        .tear(&carried(&m), frame, &TearOptions::default())
        .unwrap();
    assert_eq!(
        (
            r.boundary_loops,
            r.incision.len(),
            r.duplicated,
            r.new_vertices
        ),
        (
            rest.boundary_loops,
            rest.incision.len(),
            rest.duplicated,
            rest.new_vertices
        )
    );
    assert_manifold(&r.mesh.mesh);
    // A frame of the walk, posed as the program poses it (`--time 0`).
    let pose = rig.pose(Some(0), 0.0, &[]).unwrap();
    let lbs_rig = Skinning::bind(&rig, BlendMethod::Matrix).unwrap();
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    lbs_rig
        .pose(pose.skin_motors().unwrap(), &mut posed)
        .unwrap();
    // The joint with most weight where the first blade enters carries the blades.
    let entry = rest.mesh.mesh.positions[rest.incision[0] as usize];
    let near = (0..mesh.vertex_count())
        .min_by(|&a, &b| {
            mesh.positions[a]
                .distance(entry)
                .total_cmp(&mesh.positions[b].distance(entry))
        })
        .unwrap();
    let (joint, _) = rig
        .influences
        .row(near)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    let m = pose.skin_matrices[joint as usize];
    let frame = Frame::Posed {
        positions: &posed,
        skin: &pose.skin_matrices,
    };
    let r = s
        .tear(&carried(&m), frame, &TearOptions::default())
        .unwrap();
    assert_eq!(r.boundary_loops, rest.boundary_loops);
    assert_eq!(r.duplicated, r.incision.len() - 2);
    assert_manifold(&r.mesh.mesh);
    common::assert_oriented_manifold(&welded(&r.mesh.mesh), r.mesh.mesh.vertex_count());
}

/// The procedural arm with the vertices of every face past `x0` copied: a UV seam round the
/// arm, as glTF writes one.
fn seamed(rig: &Rig, x0: f64) -> (Mesh, Influences) {
    let m = &rig.mesh;
    let mut positions = m.positions.clone();
    let mut inf = rig.influences.clone();
    let mut copy = vec![u32::MAX; m.vertex_count()];
    let mut triangles = m.triangles.clone();
    for t in &mut triangles {
        let centre = t.iter().map(|&v| m.positions[v as usize]).sum::<DVec3>() / 3.0;
        if centre.x <= x0 {
            continue;
        }
        for v in t.iter_mut() {
            if copy[*v as usize] == u32::MAX {
                copy[*v as usize] = positions.len() as u32;
                positions.push(m.positions[*v as usize]);
                let w = inf.width;
                let row = *v as usize * w..(*v as usize + 1) * w;
                let (j, wt) = (inf.joints[row.clone()].to_vec(), inf.weights[row].to_vec());
                inf.joints.extend(j);
                inf.weights.extend(wt);
            }
            *v = copy[*v as usize];
        }
    }
    (Mesh::new(positions, triangles), inf)
}

/// A long step across a seam tears the seamed arm as it tears the whole one: same loops,
/// same incision, and both copies of each crossed seam edge split at one point.
#[test]
fn a_long_step_crosses_a_seam() {
    let rig = procedural_arm(24, 41);
    let whole = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let (mesh, inf) = seamed(&rig, 3.0);
    assert!(
        deform::mesh::adjacency::boundary_loops(&mesh.triangles, mesh.vertex_count()).len() >= 2
    );
    assert_eq!(welded_loops(&mesh), 0);
    let split = Surgery::new(&mesh, &inf).unwrap();
    let at = |x: f64| blade(DVec3::new(x, 1.2, 0.05), DVec3::new(x, 0.2, 0.05));
    let blades = [at(1.6), at(2.6), at(3.6), at(4.6)];
    let a = whole
        .tear(&blades, Frame::Rest, &TearOptions::default())
        .unwrap();
    let b = tear_both(&split, &mesh, &blades, 0.1);
    assert_eq!(a.boundary_loops, 1);
    assert_eq!(b.boundary_loops, 1);
    assert_eq!(a.incision.len(), b.incision.len());
    assert_eq!(a.duplicated, b.duplicated);
    let pa: Vec<DVec3> = a
        .incision
        .iter()
        .map(|&v| a.mesh.mesh.positions[v as usize])
        .collect();
    let pb: Vec<DVec3> = b
        .incision
        .iter()
        .map(|&v| b.mesh.mesh.positions[v as usize])
        .collect();
    assert_eq!(pa, pb, "the same incision points");
}

/// Two arms side by side: the plane through a point on one and a blade into the other meets
/// the first only in a closed curve. The error says where that curve goes and how near it
/// comes to the second point.
#[test]
fn points_the_curve_does_not_join_say_where_the_curve_goes() {
    let rig = procedural_arm(12, 21);
    let m = &rig.mesh;
    let n = m.vertex_count() as u32;
    let mut positions = m.positions.clone();
    positions.extend(m.positions.iter().map(|p| *p + DVec3::new(0.0, 0.0, 3.0)));
    let mut triangles = m.triangles.clone();
    triangles.extend(m.triangles.iter().map(|t| t.map(|v| v + n)));
    let mut inf = rig.influences.clone();
    inf.joints.extend_from_slice(&rig.influences.joints);
    inf.weights.extend_from_slice(&rig.influences.weights);
    let two = Mesh::new(positions, triangles);
    let s = Surgery::new(&two, &inf).unwrap();
    // Straight down into the first arm, then into the second: the plane x = 4 cuts each
    // arm round.
    let blades = [
        blade(DVec3::new(4.0, 2.0, 0.0), DVec3::new(4.0, 0.0, 0.0)),
        blade(DVec3::new(4.0, 2.0, 3.0), DVec3::new(4.0, 0.0, 3.0)),
    ];
    match s.tear(&blades, Frame::Rest, &TearOptions::default()) {
        Err(SurgeryError::BadTool(text)) => {
            for part in [
                "step 0:",
                "blade 1 (from (4, 2, 3) to (4, 0, 3))",
                "does not join scalpel point 0 to scalpel point 1 at (4, 0.",
                "closes on itself",
                "from scalpel point 1 at best (nearest curve point (4,",
            ] {
                assert!(text.contains(part), "{text:?} lacks {part:?}");
            }
            // The nearest point of the first arm's curve to the second arm's top: the first
            // arm's radius (0.6) below the gap of 3 between the axes, at most.
            let gap: f64 = text
                .split("it passes ")
                .nth(1)
                .and_then(|t| t.split(' ').next())
                .and_then(|d| d.parse().ok())
                .expect("a distance");
            assert!(gap > 2.0 && gap < 3.1, "{gap}");
        }
        other => panic!("expected a refusal, got {:?}", other.map(|_| ())),
    }
}
