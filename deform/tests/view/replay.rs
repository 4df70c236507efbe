//! The replay command the page shows, run as written on the files the page exports, poses
//! what the server posed: handles under two blends, the spline, an FFD lattice, a cage with
//! harmonic coordinates in the positional form, ARAP (to convergence) and B-spline + FABRIK.

use crate::client::{worst, Client, Frame, Server};
use glam::DVec3;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A fresh folder under `target/` for one case's files.
fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../target/view-replay")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Export `what` and save it under the name the server gives it.
fn save(c: &mut Client, dir: &Path, what: &str) {
    c.send(json!({"op": "export", "what": what}));
    let (name, text) = c.until(false, |f| match f {
        Frame::Text(v) if v["type"] == "file" => Some((
            v["name"].as_str().unwrap().to_string(),
            v["text"].as_str().unwrap().to_string(),
        )),
        _ => None,
    });
    assert!(!name.contains('/') && !name.contains(".."), "{name}");
    std::fs::write(dir.join(name), text).unwrap();
}

/// Save `files`, run the state's replay line in `dir` and read the mesh it writes.
fn replayed(c: &mut Client, state: &Value, dir: &Path, files: &[&str]) -> Vec<DVec3> {
    for what in files {
        save(c, dir, what);
    }
    let line = state["replay"].as_str().unwrap();
    let words: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(words[0], "deform", "{line}");
    let out = Command::new(env!("CARGO_BIN_EXE_deform"))
        .args(&words[1..])
        .arg("-q")
        .current_dir(dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{line}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let written = words[words.iter().position(|w| *w == "-o").unwrap() + 1];
    deform::mesh::io::read_obj(dir.join(written))
        .unwrap()
        .positions
}

/// A `deform view` on its first scene (the sphere), a client and the last pose's number.
struct Session {
    c: Client,
    seq: u32,
    _server: Server,
}

impl Session {
    fn start() -> Session {
        let server = Server::start(&[]);
        let mut c = server.connect(None).expect("connects");
        let s = c.state();
        assert_eq!(s["scene"], "sphere");
        Session {
            c,
            seq: 30,
            _server: server,
        }
    }

    /// Send `specs` as the next pose and read the positions the server posed.
    fn pose(&mut self, specs: &Value) -> Vec<DVec3> {
        self.seq += 1;
        let seq = self.seq;
        self.c
            .send(json!({"op": "motors", "seq": seq, "motors": specs}));
        self.c.positions(seq)
    }
}

/// Motors for the sphere's three groups.
fn specs() -> Value {
    json!([{"translate": [0, 0.3, 0]}, {"translate": [0, 0.8, 0], "scale": 1.4, "center": [0, 1, 0]},
        {"rotate": {"axis": [1, 0, 0], "degrees": 90, "center": [1, 0, 0]}, "translate": [0.1, 0, 0]}])
}

/// The replayed sphere is within `tol` of the server's pose and moved off the rest sphere.
fn check(what: &str, got: &[DVec3], want: &[DVec3], tol: f64) {
    let rest = deform::mesh::shapes::icosphere(1.0, 4).positions;
    let e = worst(got, want);
    assert!(e <= tol, "{what}: {e}");
    assert!(worst(got, &rest) > 0.2, "{what}: it moved");
}

/// Motors for a scene's control points: those past x = 5 turn and lift, the others stay.
fn lift(s: &Value) -> Value {
    let points: Vec<[f64; 3]> = serde_json::from_value(s["controls"]["points"].clone()).unwrap();
    points
        .iter()
        .map(|p| {
            if p[0] > 5.0 {
                json!({"rotate": {"axis": [1, 0, 0], "degrees": 40, "center": [p[0], 0, 0]}, "translate": [0, 0.5, 0]})
            } else {
                json!({})
            }
        })
        .collect()
}

/// Handles, motor log blending, then dual quaternions.
#[test]
fn handles_replay_poses_as_the_server_under_both_blends() {
    let mut t = Session::start();
    for blend in ["motor-log", "dual-quaternion"] {
        t.c.send(json!({"op": "method", "method": "handles", "blend": blend}));
        let s = t.c.state();
        assert!(s["replay"].as_str().unwrap().contains(blend));
        let got = t.pose(&specs());
        let dir = folder(&format!("handles-{blend}"));
        let files = ["rest", "selection", "motors"];
        check(blend, &replayed(&mut t.c, &s, &dir, &files), &got, 1e-12);
    }
}

/// The spline between the first and last group, its keys after their centres; a group painted
/// and not yet bound leaves no replay line and no keys to export.
#[test]
fn spline_replay_poses_as_the_server_and_unbound_groups_have_no_keys() {
    let mut t = Session::start();
    let c = &mut t.c;
    c.send(json!({"op": "method", "method": "spline", "blend": "motor-log"}));
    let s = c.state();
    let got = t.pose(&specs());
    let c = &mut t.c;
    let dir = folder("spline");
    let files = ["rest", "selection", "keys", "rest-keys"];
    check("spline", &replayed(c, &s, &dir, &files), &got, 1e-12);
    // A new group painted and not yet bound: the keys would not match the groups.
    c.send(
        json!({"op": "paint", "origin": [0.0, 0.0, 5.0], "direction": [0.0, 0.0, -1.0],
        "radius": 0.3, "group": 3, "begin": true}),
    );
    let s = c.state();
    assert_eq!(s["stale"], true);
    assert!(s["replay"].as_str().unwrap().starts_with("none yet"));
    c.send(json!({"op": "export", "what": "keys"}));
    assert!(c.error().contains("since the last bind"));
    c.send(json!({"op": "undo"}));
    assert_eq!(c.state()["groups"].as_array().unwrap().len(), 3);
}

/// B-spline + FABRIK, the method added last (one library file and a variant): the page
/// offers it and its options, and replays it with `deform pose fabrik`.
#[test]
fn fabrik_is_offered_with_its_options_and_replays_as_posed() {
    let mut t = Session::start();
    t.c.send(
        json!({"op": "method", "method": "fabrik", "blend": "motor-log",
        "options": {"joints": 5, "controls": 3}}),
    );
    let s = t.c.state();
    let specs_shown: Vec<&str> = (s["option_specs"].as_array().unwrap().iter())
        .map(|o| o["name"].as_str().unwrap())
        .collect();
    assert_eq!(specs_shown, ["joints", "controls"]);
    let line = s["replay"].as_str().unwrap();
    assert!(
        line.starts_with("deform pose fabrik ") && line.contains("--joints 5"),
        "{line}"
    );
    // The last group's motor moves the end effector (the others are not used).
    let got = t.pose(&json!([{}, {}, {"translate": [0, 0.8, 0]}]));
    let dir = folder("fabrik");
    let files = ["rest", "selection", "motors"];
    check("fabrik", &replayed(&mut t.c, &s, &dir, &files), &got, 1e-12);
    t.c.send(
        json!({"op": "method", "method": "fabrik", "blend": "motor-log",
        "options": {"controls": 6}}),
    );
    assert!(
        t.c.error().contains("controls"),
        "more controls than joints"
    );
}

/// ARAP: the page iterates twice per frame from the last frame; after enough frames of one
/// drag it rests where the CLI's run to convergence ends.
#[test]
fn arap_replay_to_convergence_ends_where_the_page_rests() {
    let mut t = Session::start();
    t.c.send(json!({"op": "method", "method": "arap", "blend": "motor-log", "options": {"iterations": 50}}));
    let s = t.c.state();
    let mut got = t.pose(&specs());
    for _ in 0..20 {
        got = t.pose(&specs());
    }
    let dir = folder("arap");
    let files = ["rest", "selection", "motors"];
    check("arap", &replayed(&mut t.c, &s, &dir, &files), &got, 1e-6);
}

/// A 5x3x3 quadratic B-spline lattice, motor linear blending; then the cage with harmonic
/// coordinates on a 24-node grid, positional form; then exports that do not belong to the
/// method are refused and the connection stays.
#[test]
fn lattice_and_cage_replays_pose_as_the_server_and_foreign_exports_are_refused() {
    let mut t = Session::start();
    t.c.send(json!({"op": "scene", "name": "lattice"}));
    t.c.state();
    t.c.send(
        json!({"op": "method", "method": "ffd", "blend": "motor-linear",
        "options": {"lattice": [5, 3, 3], "basis": "bspline-2"}}),
    );
    let s = t.c.state();
    let bar = deform::mesh::shapes::tube(1.0, 10.0, 16, 41).positions;
    let got = t.pose(&lift(&s));
    let dir = folder("ffd");
    let moved = replayed(&mut t.c, &s, &dir, &["rest", "motors"]);
    assert!(worst(&moved, &got) <= 1e-12, "ffd: {}", worst(&moved, &got));
    assert!(worst(&got, &bar) > 0.2, "ffd: it moved");

    t.c.send(json!({"op": "scene", "name": "cage"}));
    t.c.state();
    t.c.send(
        json!({"op": "method", "method": "cage", "blend": "positional",
        "options": {"coordinates": "harmonic", "grid": 24}}),
    );
    let s = t.c.state();
    assert!(s["replay"].as_str().unwrap().contains("--grid 24"));
    let got = t.pose(&lift(&s));
    let dir = folder("cage");
    let moved = replayed(&mut t.c, &s, &dir, &["rest", "cage", "motors"]);
    assert!(
        worst(&moved, &got) <= 1e-12,
        "cage: {}",
        worst(&moved, &got)
    );
    assert!(worst(&got, &bar) > 0.2, "cage: it moved");

    let c = &mut t.c;
    for what in ["cage", "keys"] {
        c.send(json!({"op": "scene", "name": "sphere"}));
        c.state();
        c.send(json!({"op": "export", "what": what}));
        assert!(c.error().contains("the method is not"), "{what}");
    }
    c.send(json!({"op": "export", "what": "../../etc/passwd"}));
    assert!(c.error().contains("cannot export"));
}
