//! Selections in a mesh scene: a lasso takes the vertices seen inside it; undo and redo of
//! selection changes (a paint stroke of many dabs is one step, clearing and lassos are steps,
//! an undo rebinds, a new change drops the redo steps).

use crate::client::{Client, Frame, Server};
use deform::mesh::shapes::icosphere;
use glam::DVec3;
use serde_json::{json, Value};

/// The owners of the next groups frame and the state after it.
fn groups_and_state(c: &mut Client) -> (Vec<u8>, Value) {
    let owner = c.until(false, |f| match f {
        Frame::Groups(g) => Some(g.clone()),
        _ => None,
    });
    (owner, c.state())
}

fn dab(c: &mut Client, x: f64, begin: bool) {
    c.send(
        json!({"op": "paint", "origin": [x, 0.0, 5.0], "direction": [0.0, 0.0, -1.0],
        "radius": 0.25, "group": 3, "begin": begin}),
    );
}

#[test]
fn a_stroke_is_one_undo_step_and_an_undo_rebinds() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    let (start, s) = groups_and_state(&mut c);
    assert_eq!(s["groups"].as_array().unwrap().len(), 3);
    assert_eq!(
        (s["selection_undo"].as_u64(), s["selection_redo"].as_u64()),
        (Some(0), Some(0))
    );
    c.send(json!({"op": "undo"}));
    assert!(c.error().contains("nothing to undo"));
    // One stroke of three dabs, then its bind.
    dab(&mut c, -0.2, true);
    groups_and_state(&mut c);
    dab(&mut c, 0.0, false);
    groups_and_state(&mut c);
    dab(&mut c, 0.2, false);
    groups_and_state(&mut c);
    c.send(json!({"op": "bind"}));
    let (painted, s) = groups_and_state(&mut c);
    assert_eq!(s["groups"].as_array().unwrap().len(), 4);
    assert_eq!(
        s["selection_undo"], 1,
        "three dabs of one stroke are one step"
    );
    assert!(painted.iter().filter(|&&g| g == 4).count() > 10);
    c.send(json!({"op": "clear-groups"}));
    let (cleared, s) = groups_and_state(&mut c);
    assert!(cleared.iter().all(|&g| g == 0));
    assert_eq!(s["selection_undo"], 2);
    // Undo twice: the painted groups, then the scene's own, each bound again.
    c.send(json!({"op": "undo"}));
    let (back, s) = groups_and_state(&mut c);
    assert_eq!(back, painted);
    assert_eq!(
        (s["selection_undo"].as_u64(), s["selection_redo"].as_u64()),
        (Some(1), Some(1))
    );
    assert_eq!(s["stale"], false, "an undo rebinds");
    c.send(json!({"op": "undo"}));
    let (back, s) = groups_and_state(&mut c);
    assert_eq!(back, start);
    assert_eq!(s["groups"].as_array().unwrap().len(), 3);
    // Redo forward again, past the end.
    c.send(json!({"op": "redo"}));
    assert_eq!(groups_and_state(&mut c).0, painted);
    c.send(json!({"op": "redo"}));
    assert_eq!(groups_and_state(&mut c).0, cleared);
    c.send(json!({"op": "redo"}));
    assert!(c.error().contains("nothing to redo"));
    // After an undo (back to the painted groups), a dab that changes nothing is no step; a
    // change drops what could be redone.
    c.send(json!({"op": "undo"}));
    groups_and_state(&mut c);
    dab(&mut c, 0.0, true);
    c.send(json!({"op": "bind"}));
    let (_, s) = groups_and_state(&mut c);
    assert_eq!(
        (s["selection_undo"].as_u64(), s["selection_redo"].as_u64()),
        (Some(1), Some(1))
    );
    c.send(
        json!({"op": "paint", "origin": [0.0, 0.0, 5.0], "direction": [0.0, 0.0, -1.0],
        "radius": 0.25, "group": 0, "begin": true}),
    );
    c.send(json!({"op": "bind"}));
    let (_, s) = groups_and_state(&mut c);
    assert_eq!(
        (s["selection_undo"].as_u64(), s["selection_redo"].as_u64()),
        (Some(2), Some(0))
    );
    // A new scene starts a new history.
    c.send(json!({"op": "scene", "name": "bar"}));
    let s = loop {
        let s = c.state();
        if s["scene"] == "bar" {
            break s;
        }
    };
    assert_eq!(
        (s["selection_undo"].as_u64(), s["selection_redo"].as_u64()),
        (Some(0), Some(0))
    );
}

#[test]
fn a_lasso_takes_the_vertices_seen_inside_it_and_not_those_behind() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    c.send(json!({"op": "clear-groups"}));
    c.state();
    let eye = DVec3::new(0.0, 0.0, 5.0);
    let m = glam::dcamera::rh::proj::opengl::perspective(0.8, 1.0, 0.1, 100.0)
        * glam::dcamera::rh::view::look_at_mat4(eye, DVec3::ZERO, DVec3::Y);
    let polygon = json!([[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]]);
    c.send(
        json!({"op": "lasso", "eye": eye.to_array(), "view_proj": m.to_cols_array(),
        "polygon": polygon, "group": 0}),
    );
    let owner = c.until(false, |f| match f {
        Frame::Groups(g) => Some(g.clone()),
        _ => None,
    });
    let mesh = icosphere(1.0, 4);
    let chosen: Vec<usize> = (0..mesh.vertex_count())
        .filter(|&v| owner[v] == 1)
        .collect();
    let project = |p: DVec3| {
        let q = m * p.extend(1.0);
        (q.x / q.w, q.y / q.w)
    };
    let inside = |p: DVec3| {
        let (x, y) = project(p);
        x.abs() < 0.1 && y.abs() < 0.1
    };
    assert!(chosen.len() > 5);
    assert!(chosen
        .iter()
        .all(|&v| mesh.positions[v].z > 0.5 && inside(mesh.positions[v])));
    // Every front vertex inside is taken; the back ones that project inside are not.
    let front = (0..mesh.vertex_count())
        .filter(|&v| inside(mesh.positions[v]) && mesh.positions[v].z > 0.0);
    assert_eq!(front.count(), chosen.len());
    let behind = (0..mesh.vertex_count())
        .filter(|&v| inside(mesh.positions[v]) && mesh.positions[v].z < 0.0);
    assert!(
        behind.count() > 5,
        "the back of the sphere projects inside too"
    );
    c.send(
        json!({"op": "lasso", "eye": eye.to_array(), "view_proj": m.to_cols_array(),
        "polygon": [[0, 0], [1, 1]], "group": 1}),
    );
    assert!(c.error().contains("3 to 10000"));
}
