//! Property tests: hostile numbers (huge, tiny, subnormal, NaN, infinities) fed to every
//! fallible function of `deform` never panic, and `Ok` always holds finite values.

use deform::mesh::io::{parse_dmat, parse_medit, parse_obj, parse_off, parse_tgf};
use deform::mesh::validate::check_solvable;
use deform::mesh::validate::validate;
use deform::operators::harmonic::{harmonic_field, HarmonicOptions};
use deform::operators::laplacian::{cotangent_laplacian, mean_value_laplacian, LaplacianKind};
use deform::operators::mass::{mass_diagonal, MassKind};
use deform::Mesh;
use glam::DVec3;
use proptest::prelude::*;

/// A number from one of the hostile classes, or an ordinary one.
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0..10.0f64,
        1 => (-1.0..1.0f64).prop_map(|x| x * 1e300),
        1 => (-1.0..1.0f64).prop_map(|x| x * 1e-300),
        1 => (1u64..1 << 52).prop_map(f64::from_bits),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(f64::MAX),
        1 => Just(0.0),
    ]
}

/// A small mesh with hostile coordinates and some out-of-range or repeated indices.
fn mesh() -> impl Strategy<Value = Mesh> {
    (3usize..10).prop_flat_map(|n| {
        (
            proptest::collection::vec((hostile(), hostile(), hostile()), n),
            proptest::collection::vec([0..n as u32 + 1, 0..n as u32 + 1, 0..n as u32 + 1], 1..12),
        )
            .prop_map(|(p, t)| {
                Mesh::new(
                    p.into_iter().map(|(x, y, z)| DVec3::new(x, y, z)).collect(),
                    t,
                )
            })
    })
}

/// A closed tetrahedron with hostile scale and offset.
fn scaled_tet() -> impl Strategy<Value = Mesh> {
    (hostile(), hostile()).prop_map(|(s, o)| {
        let p = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        Mesh::new(
            p.iter().map(|q| *q * s + DVec3::splat(o)).collect(),
            vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        )
    })
}

fn all_finite(x: &[f64]) -> bool {
    x.iter().all(|v| v.is_finite())
}

/// Every mesh-level fallible function; Ok results must be finite.
fn exercise(m: &Mesh) -> Result<(), TestCaseError> {
    let report = validate(m);
    prop_assert_eq!(report.vertex_count, m.vertex_count());
    if check_solvable(m).is_err() {
        return Ok(());
    }
    if let Ok(l) = cotangent_laplacian(m, Default::default()) {
        prop_assert!(all_finite(l.data()));
    }
    if let Ok(l) = mean_value_laplacian(m) {
        prop_assert!(all_finite(l.data()));
    }
    for kind in [MassKind::Voronoi, MassKind::Barycentric] {
        if let Ok(d) = mass_diagonal(m, kind) {
            prop_assert!(all_finite(&d));
        }
    }
    let last = m.vertex_count() as u32 - 1;
    for (order, laplacian) in [
        (1, LaplacianKind::Default),
        (1, LaplacianKind::MeanValue),
        (2, LaplacianKind::Default),
    ] {
        let o = HarmonicOptions {
            order,
            laplacian,
            ..Default::default()
        };
        if let Ok(x) = harmonic_field(m, &[0], &[last], o) {
            prop_assert!(all_finite(&x), "order {} {:?}", order, laplacian);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(192))]

    #[test]
    fn hostile_meshes_never_panic_and_ok_is_finite(m in mesh()) {
        exercise(&m)?;
    }

    #[test]
    fn hostile_scales_never_panic_and_ok_is_finite(m in scaled_tet()) {
        exercise(&m)?;
    }

    #[test]
    fn parsers_never_accept_non_finite_numbers(
        xs in proptest::collection::vec(hostile(), 9),
        idx in proptest::collection::vec(0u64..6, 3),
    ) {
        let v: Vec<String> = xs.iter().map(|x| format!("{x:e}")).collect();
        let obj = format!(
            "v {} {} {}\nv {} {} {}\nv {} {} {}\nf {} {} {}\n",
            v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8],
            idx[0] + 1, idx[1] + 1, idx[2] + 1
        );
        if let Ok(m) = parse_obj(&obj, "p") {
            prop_assert!(m.positions.iter().all(|p| p.is_finite()));
        }
        let off = format!(
            "OFF\n3 1 0\n{} {} {}\n{} {} {}\n{} {} {}\n3 {} {} {}\n",
            v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], idx[0], idx[1], idx[2]
        );
        if let Ok(m) = parse_off(&off, "p") {
            prop_assert!(m.positions.iter().all(|p| p.is_finite()));
            exercise(&m)?;
        }
        let medit = format!(
            "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n{} {} {} 0\n{} {} {} 0\n{} {} {} 0\n\
             Tetrahedra\n1\n{} {} {} 1 0\nEnd\n",
            v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8],
            idx[0] + 1, idx[1] + 1, idx[2] + 1
        );
        if let Ok(m) = parse_medit(&medit, "p") {
            prop_assert!(m.positions.iter().all(|p| p.is_finite()));
            prop_assert!(m.tetrahedra.iter().flatten().all(|&i| (i as usize) < m.positions.len()));
        }
        let dmat = format!("3 3\n{}\n", v.join("\n"));
        if let Ok(d) = parse_dmat(dmat.as_bytes(), "p") {
            prop_assert!(all_finite(&d.data));
        }
        let mut bin = b"0 0\n3 3\n".to_vec();
        xs.iter().for_each(|x| bin.extend(x.to_le_bytes()));
        if let Ok(d) = parse_dmat(&bin, "p") {
            prop_assert!(all_finite(&d.data));
        }
        let tgf = format!("1 {} {} {}\n2 {} {} {}\n#\n1 2\n", v[0], v[1], v[2], v[3], v[4], v[5]);
        if let Ok(s) = parse_tgf(&tgf, "p") {
            prop_assert!(s.joints.iter().all(|p| p.is_finite()));
        }
    }

    #[test]
    fn arbitrary_bytes_never_panic_a_parser(bytes in proptest::collection::vec(any::<u8>(), 0..64)) {
        if let Ok(d) = parse_dmat(&bytes, "p") {
            prop_assert!(all_finite(&d.data));
            if d.cols == 1 {
                prop_assert!(d.rows_equal_to(0).is_ok());
            }
        }
        let text = String::from_utf8_lossy(&bytes);
        let _ = parse_obj(&text, "p");
        let _ = parse_off(&text, "p");
        let _ = parse_medit(&text, "p");
        let _ = parse_tgf(&text, "p");
    }
}
