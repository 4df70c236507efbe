//! The motor JSON format and the selection formats shared by every subcommand.

use deform::input::{
    parse_group_motors, parse_key_list, parse_selection_json, selection_from_dmat,
};
use deform::mesh::io::parse_dmat;
use glam::{DQuat, DVec3};

#[test]
fn a_motor_scales_then_rotates_about_its_centre_then_translates() {
    let k = parse_key_list(
        r#"[{"scale": 2, "rotate": {"axis": [0, 0, 5], "degrees": 90, "center": [1, 1, 0]}, "translate": [0, 0, 3]}, {}]"#,
        "k",
    )
    .unwrap();
    let c = DVec3::new(1.0, 1.0, 0.0);
    for x in [DVec3::ZERO, DVec3::new(2.0, -1.0, 4.0)] {
        let expect = c
            + 2.0 * (DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2) * (x - c))
            + DVec3::Z * 3.0;
        assert!((k[0].transform_point(x) - expect).length() < 1e-14);
        assert_eq!(k[1].transform_point(x), x);
    }
    let s = parse_key_list(r#"[{"scale": 3, "center": [1, 0, 0]}]"#, "k").unwrap();
    assert!(
        (s[0].transform_point(DVec3::new(2.0, 0.0, 0.0)) - DVec3::new(4.0, 0.0, 0.0)).length()
            < 1e-14
    );
}

#[test]
fn group_motors_default_to_star_then_identity() {
    let m = parse_group_motors(
        r#"{"1": {"translate": [1, 0, 0]}, "*": {"translate": [0, 1, 0]}}"#,
        "m",
        3,
    )
    .unwrap();
    assert_eq!(m[0].transform_point(DVec3::ZERO), DVec3::Y);
    assert_eq!(m[1].transform_point(DVec3::ZERO), DVec3::X);
    assert_eq!(m[2].transform_point(DVec3::ZERO), DVec3::Y);
    let m = parse_group_motors(r#"{"1": {}}"#, "m", 2).unwrap();
    assert_eq!(m[0].transform_point(DVec3::X), DVec3::X);
}

#[test]
fn bad_motor_files_name_the_item() {
    let cases = [
        (r#"[{}, {"scale": 0}]"#, "key 1"),
        (r#"[{"rotate": {"axis": [1, 0, 0]}}]"#, "key 0"),
        (r#"[{"spin": 3}]"#, "unknown field"),
        (r#"[{"translate": [1, 2]}]"#, "key 0"),
        (r#"{"a": 1}"#, "expected an array"),
        ("[", "JSON"),
        (r#"[{"scale": 1e300}]"#, "key 0"),
    ];
    for (text, needle) in cases {
        let e = parse_key_list(text, "keys.json").unwrap_err().to_string();
        assert!(e.contains(needle) && e.contains("keys.json"), "{text}: {e}");
    }
    for (text, needle) in [
        (r#"{"x": {}}"#, "group \"x\""),
        (r#"{"5": {}}"#, "no such group"),
        ("[]", "expected an object"),
    ] {
        let e = parse_group_motors(text, "m.json", 2)
            .unwrap_err()
            .to_string();
        assert!(e.contains(needle), "{text}: {e}");
    }
}

#[test]
fn selections_from_dmat_and_json() {
    let m = parse_dmat(b"1 5\n-1\n0\n1\n0\n-1\n", "s.dmat").unwrap();
    let s = selection_from_dmat(&m, 5, "s.dmat").unwrap();
    assert_eq!(s.groups, vec![vec![1, 3], vec![2]]);
    let s = parse_selection_json(r#"{"1": [4, 0], "0": [2]}"#, 5, "s.json").unwrap();
    assert_eq!(s.groups, vec![vec![2], vec![0, 4]]);
    let bad_json = [
        (r#"{"0": [5]}"#, "does not exist"),
        (r#"{"0": [1], "1": [1]}"#, "also in group 0"),
        (r#"{"0": [1, 1]}"#, "listed twice"),
        (r#"{"1": [1]}"#, "empty group"),
        (r#"{"0": [-1]}"#, "not a vertex index"),
        (r#"{"0": [1.5]}"#, "not a vertex index"),
        (r#"{"zero": [1]}"#, "not a group number"),
        ("[1, 2]", "expected an object"),
    ];
    for (text, needle) in bad_json {
        let e = parse_selection_json(text, 5, "s.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains(needle), "{text}: {e}");
    }
    let m = parse_dmat(b"1 5\n-1\n0.5\n1\n0\n-1\n", "s.dmat").unwrap();
    assert!(selection_from_dmat(&m, 5, "s.dmat")
        .unwrap_err()
        .to_string()
        .contains("vertex 1"));
    let m = parse_dmat(b"1 4\n-1\n0\n1\n0\n", "s.dmat").unwrap();
    assert!(selection_from_dmat(&m, 5, "s.dmat").is_err());
    let m = parse_dmat(b"1 5\n-2\n0\n1\n0\n-1\n", "s.dmat").unwrap();
    assert!(selection_from_dmat(&m, 5, "s.dmat").is_err());
}
