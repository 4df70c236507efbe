//! Lattices and cages driven from the page: control points dragged and turned pose as the
//! library poses them, and the lattice's size and basis and the cage's coordinates chosen from
//! the page rebind as the library binds with the same options.

use crate::client::{worst, Server};
use deform::input::parse_key_list;
use deform::mesh::shapes::tube;
use deform::Deformer;
use glam::DVec3;
use serde_json::{json, Value};

#[test]
fn lattice_and_cage_control_points_pose_as_the_library_poses_them() {
    use deform::blend::control::ControlForm;
    use deform::deformers::cage::{CageDeformer, CageOptions};
    use deform::deformers::ffd::{Ffd, FfdOptions};
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    let bar = tube(1.0, 10.0, 16, 41);
    // A twist of the far layer of points about the bar's axis (and a small lift each).
    let spec = |i: usize, p: [f64; 3]| {
        if p[0] > 9.0 {
            json!({"rotate": {"axis": [1, 0, 0], "degrees": 60, "center": [p[0], 0, 0]}, "translate": [0, i as f64 * 0.01, 0]})
        } else {
            json!({})
        }
    };
    for (scene, blend) in [("lattice", "motor-log"), ("cage", "positional")] {
        c.send(json!({"op": "scene", "name": scene}));
        let mut s = c.state();
        if blend == "positional" {
            c.send(
                json!({"op": "method", "method": scene.replace("lattice", "ffd"), "blend": blend}),
            );
            s = c.state();
        }
        assert_eq!(s["blend"], blend);
        let points: Vec<[f64; 3]> =
            serde_json::from_value(s["controls"]["points"].clone()).unwrap();
        let specs: Vec<Value> = points
            .iter()
            .enumerate()
            .map(|(i, p)| spec(i, *p))
            .collect();
        let keys = parse_key_list(&json!(specs).to_string(), "k").unwrap();
        c.send(json!({"op": "motors", "seq": 11, "motors": specs}));
        let got = c.positions(11);
        let mut want = bar.positions.clone();
        if scene == "lattice" {
            assert_eq!(points.len(), 36);
            let ffd = Ffd::bind(&bar, [4, 3, 3], None, FfdOptions::default()).unwrap();
            ffd.pose(&keys, &mut want).unwrap();
        } else {
            let mut cage = tube(1.6, 12.0, 4, 6);
            cage.positions.iter_mut().for_each(|p| p.x -= 1.0);
            assert_eq!(points.len(), cage.vertex_count());
            let options = CageOptions {
                form: ControlForm::Positional,
                ..CageOptions::default()
            };
            let d = CageDeformer::bind(&bar, &cage, options).unwrap();
            d.pose(&keys, &mut want).unwrap();
        }
        assert!(
            worst(&got, &want) <= 1e-12,
            "{scene}: {}",
            worst(&got, &want)
        );
        assert!(worst(&got, &bar.positions) > 0.5, "{scene}: it moved");
        // Painting belongs to handle groups.
        c.send(json!({"op": "paint", "origin": [5, 0, 5], "direction": [0, 0, -1], "radius": 0.5, "group": 0}));
        assert!(c.error().contains("lattice or cage"));
    }
}

/// The page chooses the lattice's size and basis and the cage's coordinates: each choice
/// rebinds and poses as the library does with the same options; choices out of range are
/// refused and leave the session as it was.
#[test]
fn lattice_size_basis_and_cage_coordinates_are_chosen_from_the_page() {
    use deform::deformers::cage::{CageCoordinates, CageDeformer, CageOptions, HarmonicGrid};
    use deform::deformers::ffd::{Ffd, FfdOptions, LatticeBasis};
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    let bar = tube(1.0, 10.0, 16, 41);
    // Lift the far half of the control points, turn the near end.
    let spec = |p: [f64; 3]| {
        if p[0] > 5.0 {
            json!({"translate": [0, 0.4, 0.1]})
        } else {
            json!({"rotate": {"axis": [1, 0, 0], "degrees": 20, "center": [p[0], 0, 0]}})
        }
    };
    let mut seq = 20;
    let mut check = |c: &mut crate::client::Client,
                     want_points: usize,
                     want: &dyn Fn(&[cga::ScaledMotor]) -> Vec<DVec3>| {
        let s = c.state();
        let points: Vec<[f64; 3]> =
            serde_json::from_value(s["controls"]["points"].clone()).unwrap();
        assert_eq!(points.len(), want_points);
        let specs: Vec<Value> = points.iter().map(|p| spec(*p)).collect();
        let keys = parse_key_list(&json!(specs).to_string(), "k").unwrap();
        seq += 1;
        c.send(json!({"op": "motors", "seq": seq, "motors": specs}));
        let got = c.positions(seq);
        let want = want(&keys);
        assert!(worst(&got, &want) <= 1e-12, "{}", worst(&got, &want));
        assert!(worst(&got, &bar.positions) > 0.1, "it moved");
        s
    };
    c.send(json!({"op": "scene", "name": "lattice"}));
    c.state();
    for (dims, basis, lattice_basis) in [
        ([2, 2, 2], "bernstein", LatticeBasis::Bernstein),
        ([6, 3, 3], "bspline-2", LatticeBasis::BSpline(2)),
        ([8, 4, 4], "bspline-3", LatticeBasis::BSpline(3)),
    ] {
        c.send(
            json!({"op": "method", "method": "ffd", "blend": "motor-log",
            "options": {"lattice": dims, "basis": basis}}),
        );
        let s = check(&mut c, dims.iter().product(), &|keys| {
            let options = FfdOptions {
                basis: lattice_basis,
                ..FfdOptions::default()
            };
            let ffd = Ffd::bind(&bar, dims, None, options).unwrap();
            let mut want = bar.positions.clone();
            ffd.pose(keys, &mut want).unwrap();
            want
        });
        assert_eq!(s["options"]["lattice"], json!(dims));
        assert_eq!(s["options"]["basis"], basis);
    }
    // Refused: an axis out of range, a dense Bernstein lattice, unknown names and options, a
    // value of the wrong shape; the session keeps its 8x4x4 B-spline lattice.
    for bad in [
        json!({"lattice": [1, 3, 3]}),
        json!({"lattice": [9, 3, 3]}),
        json!({"lattice": [5, 5, 5], "basis": "bernstein"}),
        json!({"basis": "bspline-4"}),
        json!({"coordinates": "green"}),
        json!({"grid": 4}),
        json!({"colour": "red"}),
        json!({"lattice": [4, 4]}),
        json!({"lattice": [4.5, 4, 4]}),
        json!({"grid": {"nodes": 24}}),
    ] {
        c.send(json!({"op": "method", "method": "ffd", "blend": "motor-log", "options": bad}));
        let e = c.error();
        assert!(!e.is_empty(), "{bad} refused");
        // The same method without options: the state as it was.
        c.send(json!({"op": "method", "method": "ffd", "blend": "motor-log"}));
        let s = c.state();
        assert_eq!(s["options"]["lattice"], json!([8, 4, 4]), "{bad}: {e}");
        assert_eq!(s["options"]["basis"], "bspline-3", "{bad}: {e}");
        assert_eq!(s["controls"]["points"].as_array().unwrap().len(), 128);
    }
    // The cage with harmonic coordinates on a 24-node grid.
    c.send(json!({"op": "scene", "name": "cage"}));
    c.state();
    c.send(
        json!({"op": "method", "method": "cage", "blend": "motor-log",
        "options": {"coordinates": "harmonic", "grid": 24}}),
    );
    let mut cage = tube(1.6, 12.0, 4, 6);
    cage.positions.iter_mut().for_each(|p| p.x -= 1.0);
    let s = check(&mut c, cage.vertex_count(), &|keys| {
        let options = CageOptions {
            coordinates: CageCoordinates::Harmonic(HarmonicGrid { resolution: 24 }),
            ..CageOptions::default()
        };
        let d = CageDeformer::bind(&bar, &cage, options).unwrap();
        let mut want = bar.positions.clone();
        d.pose(keys, &mut want).unwrap();
        want
    });
    assert_eq!(s["options"]["coordinates"], "harmonic");
    assert_eq!(s["options"]["grid"], 24);
}
