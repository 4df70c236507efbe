//! What a model looks like survives surgery: every vertex's sources reproduce its rest
//! position from input vertices of one input face (so UVs interpolated with them stay in that
//! face's texture chart), and the `.glb` written from the result reads back with the input's
//! materials and images, UVs on every vertex (caps planar, inside their rim's UVs).

use super::common::data_dir;
use deform::skinning::{glb_bytes, parse_gltf, read_gltf, GlbOptions, Rig, RigPart};
use deform::surgery::{
    CutOptions, Drill, DrillOptions, Frame, Scalpel, SkinnedMesh, Surgery, TearOptions,
};
use glam::DVec3;
use serde_json::json;
use std::collections::HashSet;

fn model(name: &str) -> Option<Rig> {
    Some(read_gltf(data_dir()?.join("gltf").join(name)).expect(name))
}

/// Every vertex's sources are input vertices of one input triangle, on the rest pose their
/// combination is the vertex's rest position (to 1e-9 of the diagonal), and the sources of
/// each result triangle's three corners together lie in one input triangle: its texture
/// chart, also where the triangle touches a UV seam.
fn check_sources(rig: &Rig, result: &SkinnedMesh, what: &str) {
    check_triangle_sources(rig, result, what);
    let faces: HashSet<[u32; 3]> = rig
        .mesh
        .triangles
        .iter()
        .map(|t| {
            let mut s = *t;
            s.sort_unstable();
            s
        })
        .collect();
    let diag = rig.mesh.bounding_box().unwrap().diagonal();
    let rows = result.sources.vertex_count();
    assert_eq!(
        rows,
        result.mesh.vertex_count(),
        "{what}: one row per vertex"
    );
    let mut combined = 0;
    for v in 0..rows {
        let row: Vec<(u32, f64)> = result.sources.row(v).filter(|s| s.1 != 0.0).collect();
        let sum: f64 = row.iter().map(|s| s.1).sum();
        assert!(
            (sum - 1.0).abs() < 1e-12,
            "{what}: vertex {v} sources sum to {sum}"
        );
        let p: DVec3 = row
            .iter()
            .map(|&(s, c)| c * rig.mesh.positions[s as usize])
            .sum();
        let gap = p.distance(result.mesh.positions[v]);
        assert!(
            gap < 1e-9 * diag,
            "{what}: vertex {v} is {gap} from its sources"
        );
        if row.len() > 1 {
            combined += 1;
            let ids: Vec<u32> = row.iter().map(|s| s.0).collect();
            let in_a_face = faces.iter().any(|f| ids.iter().all(|i| f.contains(i)));
            assert!(
                in_a_face,
                "{what}: vertex {v}'s sources {ids:?} are not in one face"
            );
        }
    }
    assert!(combined > 0, "{what}: no new vertex");
}

/// The sources of each triangle's corners lie in one input triangle (or one of its edges).
fn check_triangle_sources(rig: &Rig, result: &SkinnedMesh, what: &str) {
    let mut faces: HashSet<Vec<u32>> = HashSet::new();
    for t in &rig.mesh.triangles {
        for k in 0..3 {
            let mut e = vec![t[k], t[(k + 1) % 3]];
            e.sort_unstable();
            faces.insert(e);
        }
        let mut f = t.to_vec();
        f.sort_unstable();
        faces.insert(f);
    }
    for (f, t) in result.mesh.triangles.iter().enumerate() {
        let mut ids: Vec<u32> = t
            .iter()
            .flat_map(|&v| result.sources.row(v as usize).filter(|s| s.1 != 0.0))
            .map(|s| s.0)
            .collect();
        ids.sort_unstable();
        ids.dedup();
        assert!(
            ids.len() == 1 || faces.contains(&ids),
            "{what}: triangle {f}'s corners come from {ids:?}, not one input triangle"
        );
    }
}

/// The first texture coordinates of a written and re-read rig.
fn uvs(rig: &Rig) -> Vec<[f32; 2]> {
    let uv = rig.look.attribute("TEXCOORD_0").expect("TEXCOORD_0 kept");
    uv.values.chunks_exact(2).map(|c| [c[0], c[1]]).collect()
}

/// Write `parts` as `.glb`, read it back, and compare the look with the input's.
fn round_trip(rig: &Rig, parts: &[RigPart], name: &str) -> Rig {
    let made = rig.with_parts(parts).expect("a rig");
    let bytes = glb_bytes(&made, &GlbOptions::default()).expect("written");
    let out = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gltf-out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join(name), &bytes).unwrap();
    let back = parse_gltf(&bytes, name, None).expect("read back");
    assert_eq!(back.look.materials, rig.look.materials, "{name}: materials");
    assert_eq!(back.look.textures, rig.look.textures, "{name}: textures");
    assert_eq!(back.look.samplers, rig.look.samplers, "{name}: samplers");
    let bytes_of = |r: &Rig| -> Vec<Option<Vec<u8>>> {
        r.look.images.iter().map(|i| i.bytes.clone()).collect()
    };
    assert_eq!(bytes_of(&back), bytes_of(rig), "{name}: images");
    assert_eq!(back.mesh.vertex_count(), made.mesh.vertex_count());
    assert!(back.look.primitive_materials.iter().all(|m| *m == Some(0)));
    let uv = uvs(&back);
    assert_eq!(
        uv.len(),
        back.mesh.vertex_count(),
        "{name}: a UV per vertex"
    );
    assert_eq!(uv, uvs(&made), "{name}: UVs as made");
    back
}

#[test]
fn cut_tear_and_drill_keep_the_look() {
    for name in ["CesiumMan.glb", "Fox.glb"] {
        let Some(rig) = model(name) else {
            common_skip(name);
            continue;
        };
        assert!(!rig.look.materials.is_empty() && !rig.look.images.is_empty());
        let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
        let b = rig.mesh.bounding_box().unwrap();
        let (c, e) = (b.center(), b.max - b.min);
        // Across the longest axis at 60%, capped.
        let axis = (0..3).max_by(|&i, &j| e[i].total_cmp(&e[j])).unwrap();
        let mut n = DVec3::ZERO;
        n[axis] = 1.0;
        let plane = cga::Plane::from_normal_distance(n, b.min[axis] + 0.6 * e[axis]);
        let cut = s
            .cut(
                &plane,
                Frame::Rest,
                &CutOptions {
                    cap: true,
                    ..CutOptions::default()
                },
            )
            .unwrap();
        let mut parts = Vec::new();
        let split: Vec<_> = cut.pieces.iter().map(|p| p.surface_and_caps()).collect();
        for (k, (surface, caps)) in split.iter().enumerate() {
            check_sources(&rig, surface, &format!("{name} cut piece {k}"));
            parts.push(surface.part());
            if let Some(cap) = caps {
                parts.push(RigPart {
                    cap: Some(n),
                    ..cap.part()
                });
            }
        }
        round_trip(&rig, &parts, &format!("look-cut-{name}"));
        assert!(
            cut.pieces.iter().any(|p| p.cap_triangles > 0),
            "{name}: the cut has caps"
        );

        // A tear across CesiumMan's chest (the example, with a short step), and a
        // drill through the middle of both.
        if name == "CesiumMan.glb" {
            let blade = |y: f64| Scalpel {
                a: DVec3::new(0.3, y, 1.05),
                b: DVec3::new(0.0, y, 1.05),
            };
            let tear = s
                .tear(
                    &[blade(0.0), blade(0.1)],
                    Frame::Rest,
                    &TearOptions::default(),
                )
                .unwrap();
            check_sources(&rig, &tear.mesh, &format!("{name} tear"));
            round_trip(&rig, &[tear.mesh.part()], &format!("look-tear-{name}"));
        }
        let side = (axis + 1) % 3;
        let mut tip = c;
        tip[side] -= e[side];
        let mut end = c;
        end[side] += e[side];
        let drill = s
            .drill(
                &Drill {
                    tip,
                    end,
                    radius: 0.03 * e[axis],
                },
                Frame::Rest,
                &DrillOptions::default(),
            )
            .unwrap();
        check_sources(&rig, &drill.mesh, &format!("{name} drill"));
        round_trip(&rig, &[drill.mesh.part()], &format!("look-drill-{name}"));
    }
}

fn common_skip(name: &str) {
    assert!(
        std::env::var_os("CI").is_none(),
        "{name}: the shared data is missing"
    );
    eprintln!("skipped: {name} is not in the shared data");
}

#[test]
fn caps_get_planar_uvs_inside_their_rim() {
    let Some(rig) = model("CesiumMan.glb") else {
        return common_skip("CesiumMan.glb");
    };
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let b = rig.mesh.bounding_box().unwrap();
    let plane = cga::Plane::from_normal_distance(DVec3::Z, b.min.z + 0.6 * (b.max.z - b.min.z));
    let options = CutOptions {
        cap: true,
        ..CutOptions::default()
    };
    let cut = s.cut(&plane, Frame::Rest, &options).unwrap();
    let (surface, caps) = cut.pieces[0].surface_and_caps();
    let caps = caps.expect("capped");
    assert_eq!(
        surface.mesh.triangle_count() + caps.mesh.triangle_count(),
        cut.pieces[0].mesh.mesh.triangle_count()
    );
    let made = rig
        .with_parts(&[
            surface.part(),
            RigPart {
                cap: Some(DVec3::Z),
                ..caps.part()
            },
        ])
        .unwrap();
    let uv = uvs(&made);
    let cap = &made.primitives[made.primitives.len() - 1];
    assert_eq!(cap.primitive, 1);
    // The rim's UVs as the surface has them: interpolated from the cap vertices' sources.
    let surface_uv = rig
        .look
        .attribute("TEXCOORD_0")
        .unwrap()
        .interpolated(&caps.sources);
    let (mut lo, mut hi) = ([f32::INFINITY; 2], [f32::NEG_INFINITY; 2]);
    for t in surface_uv.values.chunks_exact(2) {
        for k in 0..2 {
            lo[k] = lo[k].min(t[k]);
            hi[k] = hi[k].max(t[k]);
        }
    }
    let cap_uv = &uv[cap.vertex_offset..cap.vertex_offset + cap.vertex_count];
    for k in 0..2 {
        let got_lo = cap_uv.iter().map(|t| t[k]).fold(f32::INFINITY, f32::min);
        let got_hi = cap_uv
            .iter()
            .map(|t| t[k])
            .fold(f32::NEG_INFINITY, f32::max);
        assert!((got_lo - lo[k]).abs() < 1e-6 && (got_hi - hi[k]).abs() < 1e-6);
    }
    // Planar: UV differences are proportional to in-plane position differences.
    let p = &caps.mesh.positions;
    let (i, j) = (0, p.len() / 2);
    assert!(p[i].distance(p[j]) > 0.0 && cap_uv[i] != cap_uv[j]);
}

/// A model of two primitives with two materials, cut across both: every written primitive
/// holds triangles of one input primitive and carries that primitive's material.
#[test]
fn a_cut_keeps_each_material_on_its_own_triangles() {
    use deform::skinning::{procedural_arm, VertexAttribute};
    use deform::surgery::identity_sources;
    let arm = procedural_arm(12, 20);
    let n = arm.mesh.vertex_count();
    // Two primitives: the triangles of the lower and the upper side (by centroid y).
    let up = |t: &[u32; 3]| {
        t.iter()
            .map(|&v| arm.mesh.positions[v as usize].y)
            .sum::<f64>()
            > 0.0
    };
    let whole = SkinnedMesh {
        mesh: arm.mesh.clone(),
        influences: arm.influences.clone(),
        sources: identity_sources(n),
    };
    let idx: Vec<bool> = arm.mesh.triangles.iter().map(up).collect();
    let (low, high) = (
        whole.with_triangles(|f| !idx[f]),
        whole.with_triangles(|f| idx[f]),
    );
    let mut rig = arm.with_parts(&[low.part(), high.part()]).unwrap();
    assert_eq!(rig.primitives.len(), 2);
    let m = rig.mesh.vertex_count();
    rig.look.materials = vec![json!({"name": "low"}), json!({"name": "high"})];
    rig.look.primitive_materials = vec![Some(0), Some(1)];
    // A custom attribute naming each vertex's primitive: interpolation within a primitive
    // keeps it, so a written primitive mixing the two would show it.
    let side: Vec<f32> = rig
        .primitives
        .iter()
        .flat_map(|p| std::iter::repeat_n(p.primitive as f32, p.vertex_count))
        .collect();
    assert_eq!(side.len(), m);
    rig.look.attributes = vec![VertexAttribute {
        name: "_PRIMITIVE".into(),
        width: 1,
        values: side,
    }];
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let plane = cga::Plane::from_normal_distance(DVec3::X, 4.1);
    let cut = s.cut(&plane, Frame::Rest, &CutOptions::default()).unwrap();
    let parts: Vec<RigPart> = cut.pieces.iter().map(|p| p.mesh.part()).collect();
    let made = rig.with_parts(&parts).unwrap();
    // Each piece crosses both sides: two primitives per piece.
    assert_eq!(made.primitives.len(), 4);
    let bytes = glb_bytes(&made, &GlbOptions::default()).unwrap();
    let out = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/gltf-out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("look-two-materials.glb"), &bytes).unwrap();
    // Custom (`_`-prefixed) attributes are read back, as glTF allows them.
    let back = parse_gltf(&bytes, "two-materials", None).unwrap();
    assert_eq!(back.look.primitive_materials, made.look.primitive_materials);
    for (k, p) in back.primitives.iter().enumerate() {
        let material = back.look.primitive_materials[k].expect("a material") as f32;
        let tag = back.look.attribute("_PRIMITIVE").unwrap();
        for v in p.vertex_offset..p.vertex_offset + p.vertex_count {
            let got = tag.row(v)[0];
            assert!(
                (got - material).abs() < 1e-6,
                "primitive {k} (material {material}): vertex {v} comes from primitive {got}"
            );
        }
    }
}
