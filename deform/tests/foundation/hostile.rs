//! The hostile-input findings of issue 9: each is a typed error or a correct result.

use crate::common;
use deform::mesh::MeshError;
use deform::operators::SolveError;

use deform::mesh::io::{parse_dmat, parse_medit, parse_obj, parse_tgf};
use deform::mesh::validate::check_solvable;
use deform::mesh::validate::validate;
use deform::operators::harmonic::{harmonic_field, harmonic_system, HarmonicOptions};
use deform::operators::laplacian::{cotangent_laplacian, mean_value_laplacian, LaplacianKind};
use deform::operators::mass::{mass_diagonal, MassKind};
use deform::Mesh;
use glam::DVec3;

/// A closed tetrahedron scaled by `s`.
fn tet(s: f64) -> Mesh {
    Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::new(s, 0.0, 0.0),
            DVec3::new(0.0, s, 0.0),
            DVec3::new(0.0, 0.0, s),
        ],
        vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
}

/// A disc: centre 0 and `n` rim vertices, as the fan of one `n`-gon.
fn fan(n: u32) -> Mesh {
    let mut positions = vec![DVec3::ZERO];
    positions.extend((0..n).map(|i| {
        let a = std::f64::consts::TAU * i as f64 / n as f64;
        DVec3::new(a.cos(), a.sin(), 0.0)
    }));
    let triangles = (0..n).map(|i| [0, 1 + i, 1 + (i + 1) % n]).collect();
    Mesh::new(positions, triangles)
}

#[test]
fn dmat_with_zero_columns_is_not_a_selection() {
    let m = parse_dmat(b"0 5\n", "text").expect("a 5x0 matrix parses");
    assert_eq!((m.rows, m.cols, m.data.len()), (5, 0, 0));
    assert!(matches!(
        m.rows_equal_to(0),
        Err(MeshError::DimensionMismatch { got: 0, .. })
    ));
    let b = parse_dmat(b"0 0\n0 4\n", "binary").expect("a binary 4x0 matrix parses");
    assert_eq!((b.rows, b.cols), (4, 0));
    assert!(b.rows_equal_to(1).is_err());
    // A two-column matrix is not a selection either; a one-column one is.
    assert!(parse_dmat(b"2 1\n1 2\n", "t")
        .expect("1x2")
        .rows_equal_to(1)
        .is_err());
    let one = parse_dmat(b"1 3\n-1\n0\n0\n", "t").expect("3x1");
    assert_eq!(one.rows_equal_to(0).expect("selection"), vec![1, 2]);
}

#[test]
fn dmat_tgf_and_meshes_reject_non_finite_numbers() {
    for text in [
        "1 2\n1\nNaN\n",
        "1 1\ninf\n",
        "1 1\n-infinity\n",
        "1 1\n1e400\n",
    ] {
        assert!(
            matches!(
                parse_dmat(text.as_bytes(), "t"),
                Err(MeshError::Parse { .. })
            ),
            "{text:?}"
        );
    }
    let mut bin = b"0 0\n1 2\n".to_vec();
    bin.extend(1.0f64.to_le_bytes());
    bin.extend(f64::NAN.to_le_bytes());
    assert!(matches!(
        parse_dmat(&bin, "b"),
        Err(MeshError::Parse { .. })
    ));
    assert!(parse_tgf("1 0 NaN 0\n2 0 1 0\n#\n1 2\n", "s").is_err());
    assert!(parse_tgf("1 0 inf 0\n#\n", "s").is_err());
    assert!(parse_obj("v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "o").is_err());
}

#[test]
fn medit_tetrahedra_must_refer_to_existing_vertices() {
    let head =
        "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
    let ok = format!("{head}Tetrahedra\n1\n1 2 3 4 0\nEnd\n");
    assert_eq!(
        parse_medit(&ok, "m").expect("valid").tetrahedra,
        vec![[0, 1, 2, 3]]
    );
    let bad = format!("{head}Tetrahedra\n1\n1 2 3 99 0\nEnd\n");
    assert!(matches!(
        parse_medit(&bad, "m"),
        Err(MeshError::Parse { .. })
    ));
    // Tetrahedra before the vertices are checked against the final vertex count.
    let early = "MeshVersionFormatted 1\nDimension 3\nTetrahedra\n1\n1 2 3 4 0\nVertices\n1\n0 0 0 0\nEnd\n";
    assert!(parse_medit(early, "m").is_err());
}

#[test]
fn huge_and_tiny_meshes_give_the_unit_meshs_field() {
    let unit = harmonic_field(&tet(1.0), &[0], &[3], HarmonicOptions::default()).expect("unit");
    for s in [1e-300, 1e-150, 1e100, 1e200, 1e299] {
        let x = harmonic_field(&tet(s), &[0], &[3], HarmonicOptions::default())
            .unwrap_or_else(|e| panic!("scale {s:e}: {e}"));
        for (a, b) in x.iter().zip(&unit) {
            assert!((a - b).abs() < 1e-12, "scale {s:e}: {x:?} vs {unit:?}");
        }
        let l = cotangent_laplacian(&tet(s), Default::default()).expect("L");
        assert!(l.data().iter().all(|v| v.is_finite()));
    }
}

#[test]
fn mean_value_and_mass_are_finite_or_overflow() {
    for s in [1e-300, 1e-100, 1.0, 1e100, 1e150, 1e200, 1e299] {
        let m = tet(s);
        match mean_value_laplacian(&m) {
            Ok(l) => assert!(l.data().iter().all(|v| v.is_finite()), "scale {s:e}"),
            Err(e) => assert!(
                matches!(e, SolveError::Mesh(MeshError::Overflow { .. })),
                "scale {s:e}: {e}"
            ),
        }
        for kind in [MassKind::Voronoi, MassKind::Barycentric] {
            match mass_diagonal(&m, kind) {
                Ok(d) => assert!(d.iter().all(|v| v.is_finite() && *v > 0.0), "{s:e}"),
                Err(e) => assert!(
                    matches!(e, SolveError::Mesh(MeshError::Overflow { .. })),
                    "scale {s:e}: {e}"
                ),
            }
        }
    }
    // The 1e100 case of the report is finite now; 1e200 has areas beyond f64.
    assert!(mean_value_laplacian(&tet(1e100)).is_ok());
    assert!(mass_diagonal(&tet(1e100), MassKind::Voronoi).is_ok());
    assert!(matches!(
        mass_diagonal(&tet(1e200), MassKind::Voronoi),
        Err(SolveError::Mesh(MeshError::Overflow { .. }))
    ));
    // Mean-value fields do not depend on the scale either.
    let mv = HarmonicOptions {
        laplacian: LaplacianKind::MeanValue,
        ..Default::default()
    };
    let a = harmonic_field(&tet(1.0), &[0], &[3], mv).expect("unit");
    let b = harmonic_field(&tet(1e100), &[0], &[3], mv).expect("1e100");
    assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12));
}

#[test]
fn biharmonic_is_scale_invariant_or_a_typed_error() {
    let o2 = HarmonicOptions {
        order: 2,
        ..Default::default()
    };
    let m = common::grid(6, 6, true);
    let scaled = |s: f64| {
        Mesh::new(
            m.positions.iter().map(|p| *p * s).collect(),
            m.triangles.clone(),
        )
    };
    let sets: (&[u32], &[u32]) = (&[0, 1, 6, 7], &[28, 29, 34, 35]);
    let unit = harmonic_field(&m, sets.0, sets.1, o2).expect("unit");
    for s in [1e-100, 1e100] {
        let x = harmonic_field(&scaled(s), sets.0, sets.1, o2).expect("scaled");
        assert!(
            x.iter().zip(&unit).all(|(a, b)| (a - b).abs() < 1e-9),
            "{s:e}"
        );
    }
    // Areas beyond f64: a typed error, not a NaN field.
    assert!(matches!(
        harmonic_field(&scaled(1e200), sets.0, sets.1, o2),
        Err(SolveError::Mesh(MeshError::Overflow { .. }))
    ));
}

#[test]
fn coordinates_beyond_the_usable_range_are_refused() {
    let mut m = tet(1.0);
    m.positions[2].y = 1e305;
    let r = validate(&m);
    assert_eq!(r.huge_vertices, vec![2]);
    assert!(!r.is_clean());
    assert!(matches!(
        check_solvable(&m),
        Err(MeshError::CoordinateRange { .. })
    ));
    // Positions whose differences overflow never produce NaN weights.
    m.positions[1].y = -1e308;
    assert!(harmonic_field(&m, &[0], &[3], HarmonicOptions::default()).is_err());
}

#[test]
fn validate_is_linear_in_the_valence() {
    // 200,000 triangles around one vertex: quadratic link tests would take minutes.
    let n = 200_000;
    let m = fan(n);
    let r = validate(&m);
    assert!(r.non_manifold_vertices.is_empty() && r.non_manifold_edges.is_empty());
    assert!(r.unreferenced_vertices.is_empty() && r.degenerate_faces.is_empty());
    assert_eq!(r.boundary_edges, n as usize);
    assert_eq!(r.components, vec![0]);
    // Two such fans glued at the centre: a bow-tie, found just as fast.
    let mut bow = m.clone();
    let off = bow.positions.len() as u32;
    bow.positions
        .extend(m.positions[1..].iter().map(|p| *p + DVec3::Z));
    bow.triangles
        .extend((0..n).map(|i| [0, off + i, off + (i + 1) % n]));
    let r = validate(&bow);
    assert_eq!(r.non_manifold_vertices, vec![0]);
    assert!(r.non_manifold_edges.is_empty());
}

#[test]
fn a_huge_polygon_goes_through_the_order_1_pipeline() {
    // One 20,000-gon read as OBJ, fan-triangulated from its first corner.
    let n = 20_000;
    let mut text = String::new();
    for i in 0..n {
        let a = std::f64::consts::TAU * i as f64 / n as f64;
        text += &format!("v {} {} 0\n", a.cos(), a.sin());
    }
    text += "f";
    for i in 1..=n {
        text += &format!(" {i}");
    }
    let m = parse_obj(&text, "polygon").expect("parses");
    assert_eq!(m.triangle_count(), n - 2);
    assert!(validate(&m).check_solvable().is_ok());
    let x = harmonic_field(&m, &[1], &[n as u32 / 2], HarmonicOptions::default()).expect("field");
    assert!(x.iter().all(|v| v.is_finite()));
}

#[test]
fn biharmonic_fill_of_a_huge_polygon_is_refused() {
    let o2 = HarmonicOptions {
        order: 2,
        ..Default::default()
    };
    match harmonic_system(&fan(2000), &o2) {
        Err(SolveError::TooDense {
            estimated, limit, ..
        }) => assert!(estimated > limit),
        other => panic!("expected TooDense, got {other:?}"),
    }
    // A small fan is fine.
    assert!(harmonic_system(&fan(50), &o2).is_ok());
}

#[test]
fn a_non_finite_system_matrix_is_refused() {
    let q = cotangent_laplacian(&tet(1.0), Default::default())
        .expect("L")
        .map(|v| -v);
    let opts = deform::operators::solve::SolverOptions::default();
    let mut s = deform::operators::solve::DirichletSolver::new(&q, &[0], opts).expect("solver");
    let mut bad = q.map(|v| v * 1e308 * 10.0);
    assert!(matches!(
        deform::operators::solve::DirichletSolver::new(&bad, &[0], opts),
        Err(SolveError::Mesh(MeshError::Overflow { .. }))
    ));
    assert!(matches!(
        s.update_values(&bad),
        Err(SolveError::Mesh(MeshError::Overflow { .. }))
    ));
    bad = q.map(|v| v * f64::MAX);
    // Finite entries whose factor overflows are refused too, never a NaN solution.
    match deform::operators::solve::DirichletSolver::new(&bad, &[0], opts) {
        Ok(s) => assert!(s
            .solve(&[1.0], 1)
            .expect("finite")
            .iter()
            .all(|x| x.is_finite())),
        Err(e) => assert!(
            matches!(
                e,
                SolveError::Mesh(MeshError::Overflow { .. }) | SolveError::NotPositiveDefinite(_)
            ),
            "{e}"
        ),
    }
}

/// Counts near `usize::MAX` given to the library: typed errors (each overflowed a
/// multiplication or an allocation and panicked).
#[test]
fn huge_counts_are_errors_not_overflows() {
    use deform::blend::KeyWeights;
    use deform::input::parse_group_motors;
    use deform::mesh::io::Dmat;
    use deform::operators::harmonic::Harmonic;
    use deform::operators::solve::{DirichletSolver, SolverOptions};
    use deform::skinning::read_libigl_animation;
    let m = tet(1.0);
    let h = Harmonic::new(&m, &[&[0], &[3]], HarmonicOptions::default()).unwrap();
    assert!(h.fields(&[0.0, 1.0], usize::MAX).is_err());
    assert!(h.fields(&[0.0, 1.0], usize::MAX / 2 + 1).is_err());
    let q = cotangent_laplacian(&m, Default::default())
        .unwrap()
        .map(|x| -x);
    let solver = DirichletSolver::new(&q, &[0, 3], SolverOptions::default()).unwrap();
    assert!(solver.solve(&[0.0, 1.0], usize::MAX).is_err());
    assert!(KeyWeights::new(10, usize::MAX, vec![1], vec![]).is_err());
    let dmat = Dmat {
        rows: 12,
        cols: 1,
        data: vec![0.0; 12],
    };
    assert!(read_libigl_animation(&dmat, usize::MAX).is_err());
    for groups in [usize::MAX, 1 << 40] {
        assert!(parse_group_motors("{}", "g", groups).is_err(), "{groups}");
    }
}

/// A number too large for `f64` is named as such, not as "non-finite", and a token of
/// hundreds of characters is cut in the message (it was printed whole).
#[test]
fn parse_errors_name_overflow_and_cut_long_tokens() {
    let e = deform::mesh::io::parse_obj("v 1e400 0 0\n", "o.obj").unwrap_err();
    assert_eq!(
        e.to_string(),
        "o.obj:1: x coordinate \"1e400\" overflows f64"
    );
    let e = deform::mesh::io::parse_obj("v 0 -inf 0\n", "o.obj").unwrap_err();
    assert_eq!(e.to_string(), "o.obj:1: non-finite y coordinate \"-inf\"");
    let digits = "9".repeat(500);
    let e = deform::mesh::io::parse_obj(&format!("v 0 0 {digits}\n"), "o.obj").unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("overflows f64") && text.contains("(500 bytes)"),
        "{text}"
    );
    assert!(text.len() < 120, "{} characters: {text}", text.len());
    let e =
        deform::mesh::io::parse_obj(&format!("v 0 0 0\nf 1 2 {digits}x\n"), "o.obj").unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("bad face index") && text.contains("(501 bytes)"),
        "{text}"
    );
    assert!(text.len() < 120, "{text}");
}
