//! Models uploaded from the page: read by the CLI's readers and checks, opened as a scene of
//! the session; bad uploads are typed errors and the session goes on.

use crate::client::{Client, Frame, Server};
use base64::Engine;
use deform::mesh::shapes::icosphere;
use serde_json::json;

fn upload(c: &mut Client, name: &str, bytes: &[u8]) {
    let base64 = base64::engine::general_purpose::STANDARD.encode(bytes);
    c.send(json!({"op": "upload", "name": name, "base64": base64}));
}

#[test]
fn an_uploaded_mesh_opens_as_a_scene_and_poses() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    let ball = icosphere(2.0, 3);
    let mut obj = Vec::new();
    deform::mesh::io::write_obj_to(&ball, &mut obj).unwrap();
    // A path in the name is dropped: only the file's own name names the scene.
    upload(&mut c, "some/dir/ball.OBJ", &obj);
    let (rest, triangles) = c.until(false, |f| match f {
        Frame::Mesh { rest, triangles } => Some((rest.clone(), triangles.clone())),
        _ => None,
    });
    let want = deform::mesh::io::parse_obj(std::str::from_utf8(&obj).unwrap(), "ball").unwrap();
    assert_eq!(
        (rest, triangles),
        (want.positions.clone(), want.triangles.clone())
    );
    let s = c.state();
    assert_eq!(
        (s["scene"].as_str(), s["kind"].as_str()),
        (Some("ball.OBJ"), Some("mesh"))
    );
    assert!(s["scenes"]
        .as_array()
        .unwrap()
        .iter()
        .any(|n| n == "ball.OBJ"));
    // Paint a handle on it and pose: the uploaded scene is a scene like the others.
    c.send(
        json!({"op": "paint", "origin": [0.0, 0.0, 9.0], "direction": [0.0, 0.0, -1.0],
        "radius": 0.8, "group": 0, "begin": true}),
    );
    c.send(
        json!({"op": "paint", "origin": [0.0, 0.0, -9.0], "direction": [0.0, 0.0, 1.0],
        "radius": 0.8, "group": 1}),
    );
    c.send(json!({"op": "bind"}));
    c.send(json!({"op": "motors", "seq": 3, "motors": [{}, {"translate": [0, 0, -1]}]}));
    let posed = c.positions(3);
    assert_eq!(posed.len(), ball.vertex_count());
    assert!(posed
        .iter()
        .zip(&ball.positions)
        .any(|(a, b)| (*a - *b).length() > 0.5));
    // The same name again replaces the earlier upload.
    upload(&mut c, "ball.OBJ", &obj);
    let s = loop {
        let s = c.state();
        if s["groups"].as_array().unwrap().is_empty() {
            break s;
        }
    };
    let named = s["scenes"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|n| *n == "ball.OBJ");
    assert_eq!(named.count(), 1);
}

#[test]
fn an_uploaded_glb_opens_as_a_rig() {
    let Some(path) = devkit::shared::data_file("gltf/CesiumMan.glb") else {
        return;
    };
    let bytes = std::fs::read(path).unwrap();
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    upload(&mut c, "CesiumMan.glb", &bytes);
    let s = loop {
        let s = c.state();
        if s["scene"] == "CesiumMan.glb" {
            break s;
        }
    };
    let rig = deform::skinning::parse_gltf(&bytes, "CesiumMan", None).unwrap();
    assert_eq!(s["kind"], "rig");
    assert_eq!(s["vertices"], rig.mesh.vertex_count());
}

#[test]
fn bad_uploads_are_errors_and_the_session_goes_on() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    let text = |t: &str| t.as_bytes().to_vec();
    // A bow tie: two triangles sharing only vertex 0.
    let bow_tie = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n";
    // A glTF that asks for a file of the server's.
    let outside =
        r#"{"asset": {"version": "2.0"}, "buffers": [{"uri": "/etc/passwd", "byteLength": 8}]}"#;
    let cases: [(&str, Vec<u8>, &str); 6] = [
        ("model.stl", text("solid x"), "stl"),
        ("model.obj", vec![0xff, 0xfe, 0x00], "UTF-8"),
        ("model.obj", text("v 0 0 0\nf 1 2 3\n"), "usable"),
        ("bowtie.obj", text(bow_tie), "usable"),
        ("rig.gltf", text(outside), "rig.gltf"),
        ("..", text("v 0 0 0"), "file name"),
    ];
    for (name, bytes, says) in cases {
        upload(&mut c, name, &bytes);
        let message = c.error();
        assert!(message.contains(says), "{name}: {message:?}");
        assert!(c.answers(), "{name}: the session goes on");
    }
    c.send(json!({"op": "upload", "name": "x.obj", "base64": "not base64!"}));
    assert!(c.error().contains("base64"));
    // Larger than the upload limit (within the socket's message limit).
    let big = "A".repeat(22 << 20);
    c.send(json!({"op": "upload", "name": "big.obj", "base64": big}));
    assert!(c.error().contains("larger than 16 MiB"));
    assert!(c.answers());
}
