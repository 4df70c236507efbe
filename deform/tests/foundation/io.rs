//! Readers and writers, on the shared data set and on small inline files.

use crate::common;
use deform::mesh::MeshError;

use deform::mesh::io::{self, read_dmat, read_medit, read_mesh, read_tgf};
use deform::Mesh;

/// (file, vertices, triangles after fan triangulation) from the data README.
const COUNTS: &[(&str, usize, usize)] = &[
    ("libigl/decimated-knight.off", 502, 1000),
    ("libigl/cheburashka.off", 6669, 13334),
    ("libigl/decimated-max.obj", 5272, 10540),
    ("libigl/bump-domain.obj", 4172, 8058),
    ("libigl/armadillo.obj", 43243, 86482),
    ("libigl/arm.obj", 8311, 16618),
    ("libigl/hand.mesh", 7234, 9556),
    ("libigl/elephant.obj", 6034, 12064),
    ("libigl/cow.off", 2762, 5520),
    ("libigl/bunny.off", 3485, 6966),
    // 200 quads + 2 twenty-gons: 200 * 2 + 2 * 18 triangles.
    ("libigl/cylinder.obj", 220, 436),
    ("libigl/xcylinder.obj", 42, 80),
    ("common-3d-test-models/stanford-bunny.obj", 35947, 69451),
    ("common-3d-test-models/spot.obj", 2930, 5856),
    ("common-3d-test-models/alligator.obj", 3208, 5981),
    ("common-3d-test-models/woody.obj", 694, 1267),
    ("large/armadillo-50k.obj", 49999, 99994),
    ("large/cactus-100kf.obj", 49999, 99994),
    ("large/cactus-5k.off", 5261, 10518),
    ("cages/armadillo-dense.obj", 3990, 7976),
    ("cages/armadillo-cage-robust-6.obj", 77, 150),
    ("cages/cactus-dense.obj", 3813, 7622),
    ("cages/cactus_cage.obj", 92, 180),
    ("cages/bar.OBJ", 386, 768),
    ("cages/bar_cage.OBJ", 8, 12),
    ("cages/bar_cage_partial.OBJ", 8, 12),
    ("cages/hand_bones.obj", 5497, 11026),
    ("cages/hand_bones_cage_coarse.obj", 172, 340),
];

#[test]
fn every_mesh_file_loads_with_the_readme_counts() {
    let Some(dir) = common::data_dir() else {
        return;
    };
    let meshes = dir.join("meshes");
    let mut seen = 0;
    for sub in std::fs::read_dir(&meshes).expect("meshes dir") {
        let sub = sub.expect("entry").path();
        for f in std::fs::read_dir(&sub).expect("subdir") {
            let path = f.expect("entry").path();
            let ext = path
                .extension()
                .and_then(|e| e.to_str())
                .unwrap_or("")
                .to_ascii_lowercase();
            if !matches!(ext.as_str(), "obj" | "off" | "mesh") {
                continue;
            }
            let rel = path
                .strip_prefix(&meshes)
                .expect("under meshes")
                .to_string_lossy()
                .replace('\\', "/");
            let m = read_mesh(&path).unwrap_or_else(|e| panic!("{rel}: {e}"));
            let &(_, v, f) = COUNTS
                .iter()
                .find(|c| c.0 == rel)
                .unwrap_or_else(|| panic!("{rel} is not in the README table"));
            assert_eq!((m.vertex_count(), m.triangle_count()), (v, f), "{rel}");
            let r = deform::mesh::validate::validate(&m);
            assert!(r.out_of_range_faces.is_empty(), "{rel}");
            assert!(r.non_finite_vertices.is_empty(), "{rel}");
            seen += 1;
        }
    }
    assert_eq!(seen, COUNTS.len());
}

#[test]
fn hand_mesh_has_tetrahedra() {
    let Some(p) = common::mesh_path("libigl/hand.mesh") else {
        return;
    };
    let m = read_medit(p).expect("hand.mesh");
    assert_eq!(
        (m.positions.len(), m.triangles.len(), m.tetrahedra.len()),
        (7234, 9556, 29998)
    );
    assert!(m.tetrahedra.iter().flatten().all(|&v| v < 7234));
}

#[test]
fn dmat_files_ascii_and_binary() {
    let Some(dir) = common::data_dir() else {
        return;
    };
    let lib = dir.join("meshes/libigl");
    let shapes = [
        ("arm-weights.dmat", 8311, 4),
        ("armadillo-weights.dmat", 43243, 5),
        ("cheburashka-scalar.dmat", 6669, 1),
        ("decimated-knight-selection.dmat", 502, 1),
        ("decimated-max-selection.dmat", 5272, 1),
        ("elephant-anim.dmat", 288, 457),
        ("elephant-weights.dmat", 6034, 24),
        ("hand-pose.dmat", 80, 1),
    ];
    for (f, r, c) in shapes {
        let m = read_dmat(lib.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        assert_eq!((m.rows, m.cols, m.data.len()), (r, c, r * c), "{f}");
    }
    // Skinning weights (one ASCII, two binary files) are partitions of unity: this fails if
    // the column-major order or the binary layout were misread.
    for f in [
        "arm-weights.dmat",
        "armadillo-weights.dmat",
        "elephant-weights.dmat",
    ] {
        let m = read_dmat(lib.join(f)).expect(f);
        for i in 0..m.rows {
            let s: f64 = (0..m.cols).map(|j| m.get(i, j)).sum();
            assert!((s - 1.0).abs() < 1e-12, "{f} row {i} sums to {s}");
        }
    }
    let knight = read_dmat(lib.join("decimated-knight-selection.dmat")).expect("knight");
    let groups: Vec<usize> = (-1..=2)
        .map(|g| knight.rows_equal_to(g).expect("one column").len())
        .collect();
    assert_eq!(groups, vec![429, 21, 27, 25]);
    let max = read_dmat(lib.join("decimated-max-selection.dmat")).expect("max");
    let groups: Vec<usize> = (-1..=2)
        .map(|g| max.rows_equal_to(g).expect("one column").len())
        .collect();
    assert_eq!(groups, vec![2901, 2214, 90, 67]);
}

#[test]
fn tgf_skeletons() {
    let Some(dir) = common::data_dir() else {
        return;
    };
    for (f, j, b) in [
        ("arm.tgf", 5, 4),
        ("hand.tgf", 21, 20),
        ("elephant.tgf", 25, 24),
    ] {
        let s = read_tgf(dir.join("meshes/libigl").join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        assert_eq!((s.joints.len(), s.bones.len()), (j, b), "{f}");
    }
    let arm = read_tgf(dir.join("meshes/libigl/arm.tgf")).expect("arm");
    assert_eq!(arm.bones, vec![[0, 1], [1, 2], [2, 3], [3, 4]]);
    assert_eq!(
        arm.joints[0],
        glam::DVec3::new(-0.72962893, 0.011729617, -0.1327604)
    );
}

#[test]
fn obj_round_trip_is_exact() {
    let m = Mesh::new(
        vec![
            glam::DVec3::new(0.1, -2.5e-7, 3.0),
            glam::DVec3::new(1.0 / 3.0, 2.0, -0.0),
            glam::DVec3::new(1e300, 5.0, 7.25),
        ],
        vec![[0, 1, 2]],
    );
    let mut buf = Vec::new();
    io::write_obj_to(&m, &mut buf).expect("write");
    let back = io::parse_obj(std::str::from_utf8(&buf).expect("utf8"), "mem").expect("parse");
    assert_eq!(back, m);
    let path = std::env::temp_dir().join(format!("deform-rt-{}.obj", std::process::id()));
    io::write_obj(&m, &path).expect("write file");
    let back = read_mesh(&path).expect("read file");
    std::fs::remove_file(&path).ok();
    assert_eq!(back, m);
}

#[test]
fn obj_negative_and_slashed_indices() {
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nf -3/1/1 -2//1 -1/1\n";
    let m = io::parse_obj(text, "mem").expect("parse");
    assert_eq!(m.triangles, vec![[0, 1, 2]]);
}

#[test]
fn malformed_files_are_errors_with_lines() {
    let cases: Vec<(Result<Mesh, MeshError>, usize)> = vec![
        (io::parse_obj("v 0 0 0\nv 1 x 0\n", "a"), 2),
        (io::parse_obj("v 0 0 0\nf 1 0 1\n", "a"), 2),
        (io::parse_obj("v 0 0 0\nf 1 2\n", "a"), 2),
        (io::parse_obj("v 0 0 0\nf 1 2 -5\n", "a"), 2),
        (io::parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n", "a"), 4),
        (io::parse_off("PLY\n", "a"), 1),
        (io::parse_off("OFF\n1 1 0\n0 0 0\n3 0 1 -1\n", "a"), 4),
        (
            io::parse_medit("Vertices\n1\n0 0 0 0\nFoo\n", "a").map(|m| m.surface()),
            4,
        ),
        (
            io::parse_medit("Vertices\n1\n0 0 0 0\nTriangles\n1\n0 1 1 0\n", "a")
                .map(|m| m.surface()),
            6,
        ),
    ];
    for (k, (r, line)) in cases.into_iter().enumerate() {
        match r {
            Err(MeshError::Parse { line: l, .. }) => assert_eq!(l, line, "case {k}"),
            other => panic!("case {k}: expected a parse error, got {other:?}"),
        }
    }
    assert!(matches!(
        io::parse_dmat(b"2 2\n1 2 3\n", "a"),
        Err(MeshError::Parse { .. })
    ));
    assert!(matches!(
        io::parse_dmat(b"0 0\n1 2\n\x00\x00", "a"),
        Err(MeshError::Parse { .. })
    ));
    assert!(matches!(
        io::parse_dmat(b"1 x\n", "a"),
        Err(MeshError::Parse { .. })
    ));
    assert!(matches!(
        io::parse_tgf("1 0 0 0\n#\n1 3\n", "a"),
        Err(MeshError::Parse { line: 3, .. })
    ));
    assert!(matches!(
        read_mesh("/nonexistent/x.obj"),
        Err(MeshError::Io { .. })
    ));
    assert!(matches!(
        read_mesh("x.ply"),
        Err(MeshError::UnsupportedFormat(_))
    ));
}

#[test]
fn binary_dmat_round_trip() {
    let mut bytes = b"0 0\n2 3\n".to_vec();
    for i in 0..6 {
        bytes.extend_from_slice(&(i as f64 * 0.5).to_le_bytes());
    }
    let m = io::parse_dmat(&bytes, "mem").expect("binary");
    assert_eq!((m.rows, m.cols), (3, 2));
    assert_eq!(m.column(1), &[1.5, 2.0, 2.5]);
    let path = std::env::temp_dir().join(format!("deform-rt-{}.dmat", std::process::id()));
    io::write_dmat(&m, &path).expect("write");
    let back = read_dmat(&path).expect("read");
    std::fs::remove_file(&path).ok();
    assert_eq!(back, m);
}

#[test]
fn obj_with_texture_coordinates_and_normals() {
    let m = Mesh::new(
        vec![glam::DVec3::ZERO, glam::DVec3::X, glam::DVec3::Y],
        vec![[0, 1, 2]],
    );
    let uv = [0.0f32, 0.25, 1.0, 0.25, 0.0, 1.0];
    let normals = m.seamless_vertex_normals();
    let extras = io::ObjExtras {
        uvs: Some(&uv),
        normals: Some(&normals),
        texture: None,
    };
    let mut text = Vec::new();
    io::write_obj_with_to(&m, extras, &mut text).unwrap();
    let text = String::from_utf8(text).unwrap();
    // OBJ's texture origin is bottom left, glTF's top left: v is flipped.
    assert!(text.contains("vt 0 0.75\nvt 1 0.75\nvt 0 0\n"), "{text}");
    assert!(text.contains("vn 0 0 1\n"), "{text}");
    assert!(text.contains("f 1/1/1 2/2/2 3/3/3"), "{text}");
    assert_eq!(io::parse_obj(&text, "t").unwrap(), m);
    let short = io::ObjExtras {
        uvs: Some(&uv[..4]),
        normals: None,
        texture: None,
    };
    let err = io::write_obj_with_to(&m, short, &mut Vec::new()).unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
}

/// An OBJ's texture coordinates are per face corner: read with the fans, written back as they
/// were around new positions.
#[test]
fn obj_texture_corners_round_trip() {
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n\
                f 1/1 2/2 3/3 4/4\nf 1/5 3/3 2/2\n";
    let (m, t) = io::parse_obj_textured(text, "quad").unwrap();
    let t = t.expect("every face has vt");
    assert_eq!(t.corners, vec![[0, 1, 2], [0, 2, 3], [4, 2, 1]]);
    assert_eq!(t.uvs.len(), 5);
    let extras = io::ObjExtras {
        texture: Some(&t),
        ..io::ObjExtras::default()
    };
    let mut out = Vec::new();
    io::write_obj_with_to(&m, extras, &mut out).unwrap();
    let out = String::from_utf8(out).unwrap();
    let (back, t2) = io::parse_obj_textured(&out, "back").unwrap();
    assert_eq!(back, m);
    assert_eq!(t2.as_ref(), Some(&t));
    // A face without vt: no texture.
    let (_, none) =
        io::parse_obj_textured("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3\n", "x").unwrap();
    assert!(none.is_none());
}
