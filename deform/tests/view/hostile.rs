//! Hostile and careless clients: no token, a foreign page, malformed, oversized, binary and
//! out-of-order messages, and a fuzzer of mutated requests. None may stop the server; a
//! malformed message closes its own connection only; a refused request leaves the session
//! answering.

use crate::client::{Frame, Server};
use proptest::prelude::Rng;
use proptest::test_runner::{RngAlgorithm, TestRng};
use serde_json::{json, Value};
use tungstenite::Message;

#[test]
fn the_page_and_the_socket_need_the_token_and_the_socket_refuses_other_origins() {
    let server = Server::start(&[]);
    assert_eq!(server.http_status("/", ""), 403);
    assert_eq!(server.http_status("/?token=0123", ""), 403);
    assert_eq!(
        server.http_status(&format!("/?token={}", server.token), ""),
        200
    );
    let upgrade = "Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n\
                   Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n";
    assert_eq!(server.http_status("/ws", upgrade), 403);
    assert_eq!(server.http_status("/ws?token=wrong", upgrade), 403);
    assert!(server.connect(Some("http://evil.example")).is_err());
    assert!(server
        .connect(Some(&format!("http://localhost:{}", server.port + 1)))
        .is_err());
    let mut c = server
        .connect(Some(&format!("http://127.0.0.1:{}", server.port)))
        .expect("the page's own origin");
    assert_eq!(c.state()["scene"], "sphere");
}

#[test]
fn only_an_explicit_host_accepts_a_page_served_under_another_name() {
    for explicit in [false, true] {
        let args: &[&str] = if explicit {
            &["--host", "127.0.0.1"]
        } else {
            &[]
        };
        let server = Server::start(args);
        let host = format!("devbox:{}", server.port);
        let origin = format!("http://{host}");
        let c = server.connect_with(&[("Host", &host), ("Origin", &origin)]);
        assert_eq!(c.is_ok(), explicit, "--host given: {explicit}");
        let foreign = server.connect_with(&[("Host", &host), ("Origin", "http://evil.example")]);
        assert!(foreign.is_err());
    }
}

#[test]
fn malformed_oversized_and_binary_messages_close_their_connection_only() {
    let mut server = Server::start(&[]);
    let bad: Vec<Message> = vec![
        Message::Text("not json".into()),
        Message::Text(r#"{"op": "fly"}"#.into()),
        Message::Text(r#"{"op": "scene", "name": "sphere", "extra": 1}"#.into()),
        Message::Text(r#"{"op": "motors", "seq": -1, "motors": []}"#.into()),
        Message::Binary(vec![1, 2, 3].into()),
        Message::Text(
            format!(
                r#"{{"op": "load", "what": "selection", "text": "{}"}}"#,
                "x".repeat(30 << 20)
            )
            .into(),
        ),
    ];
    for m in bad {
        let mut c = server.connect(None).expect("connects");
        c.state();
        let _ = c.send_raw(m);
        // Whatever it said first, the connection ends.
        let closed = (0..100).any(|_| matches!(c.next(), Frame::Closed));
        assert!(closed, "a malformed message closes its connection");
        assert!(server.alive(), "the server lives");
    }
    let mut c = server.connect(None).expect("still serving");
    assert_eq!(c.state()["scene"], "sphere");
}

#[test]
fn refused_requests_are_errors_and_the_session_goes_on() {
    let server = Server::start(&[]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    c.positions(0);
    let refused = [
        (
            json!({"op": "motors", "seq": 1, "motors": [{}]}),
            "1 motors for 3 groups",
        ),
        (
            json!({"op": "motors", "seq": 1, "motors": [{}, {}, {"scale": -1}]}),
            "group 2",
        ),
        (
            json!({"op": "motors", "seq": 1, "motors": [{}, {}, {"rotate": {"axis": [0, 0, 0], "degrees": 5}}]}),
            "group 2",
        ),
        (
            json!({"op": "motors", "seq": 1, "motors": [{}, {}, {"translate": [1e308, 1e308, 1e308]}]}),
            "",
        ),
        (
            json!({"op": "paint", "origin": [0, 0, 5], "direction": [0, 0, -1], "radius": -1, "group": 0}),
            "radius",
        ),
        (
            json!({"op": "paint", "origin": [0, 0, 5], "direction": [0, 0, -1], "radius": 0.1, "group": 999}),
            "group 999",
        ),
        (
            json!({"op": "scene", "name": "../../etc/passwd"}),
            "no scene",
        ),
        (
            json!({"op": "method", "method": "magic", "blend": "motor-log"}),
            "no method",
        ),
        (
            json!({"op": "method", "method": "arap", "blend": "motor-log", "options": {"iterations": 0}}),
            "iterations",
        ),
        (
            json!({"op": "method", "method": "handles", "blend": "quaternions"}),
            "quaternions",
        ),
        (
            json!({"op": "rig", "seq": 1, "animation": 0, "time": 0, "backend": "matrix"}),
            "no rig",
        ),
        (
            json!({"op": "cut", "point": [0, 0, 0], "normal": [1, 0, 0]}),
            "no rig",
        ),
        (json!({"op": "undo"}), "nothing to undo"),
        (json!({"op": "export", "what": "exe"}), "cannot export"),
        (
            json!({"op": "load", "what": "selection", "text": "{\"0\": [99999999]}"}),
            "does not exist",
        ),
        (
            json!({"op": "load", "what": "motors", "text": "[1, 2]"}),
            "expected an object",
        ),
        (json!({"op": "field", "name": "lambda"}), "no field"),
    ];
    for (request, says) in refused {
        c.send(request.clone());
        let message = c.until(true, |f| match f {
            Frame::Text(v) if v["type"] == "error" => {
                Some(v["message"].as_str().unwrap().to_string())
            }
            Frame::Positions { seq: 1, .. } => Some(String::new()),
            _ => None,
        });
        assert!(message.contains(says), "{request}: {message:?}");
        assert!(c.answers(), "{request}: the session goes on");
    }
    // Huge translations are finite, so they pose (far away), and the state is still usable.
    c.send(json!({"op": "motors", "seq": 9, "motors": [{}, {}, {}]}));
    assert_eq!(c.positions(9).len(), 2562);
}

/// Deterministic random choices (the same run every time).
struct Lcg(TestRng);
impl Lcg {
    fn new() -> Lcg {
        Lcg(TestRng::deterministic_rng(RngAlgorithm::ChaCha))
    }
    fn next(&mut self) -> u64 {
        self.0.next_u64()
    }
    fn pick<'a, T>(&mut self, v: &'a [T]) -> &'a T {
        &v[self.next() as usize % v.len()]
    }
}

/// Replace one leaf (or drop or add a key) of `v`.
fn mutate(v: &mut Value, rng: &mut Lcg) {
    let junk = [
        json!(null),
        json!(-1),
        json!(1e308),
        json!(-1e308),
        json!("x"),
        json!([]),
        json!({}),
        json!(true),
        json!(4294967296u64),
        json!(1.5),
        json!(0),
        json!([1e300, 0, 0]),
        json!({"scale": 0}),
        json!([[0, 0, 0]]),
    ];
    match v {
        Value::Object(m) if !m.is_empty() => {
            let keys: Vec<String> = m.keys().cloned().collect();
            let k = rng.pick(&keys).clone();
            match rng.next() % 6 {
                0 => {
                    m.remove(&k);
                }
                1 => {
                    m.insert("surprise".into(), json!(1));
                }
                2 | 3 => mutate(m.get_mut(&k).unwrap(), rng),
                _ => {
                    if k != "op" {
                        m.insert(k, rng.pick(&junk).clone());
                    }
                }
            }
        }
        Value::Array(a) if !a.is_empty() => {
            let i = rng.next() as usize % a.len();
            mutate(&mut a[i], rng);
        }
        leaf => *leaf = rng.pick(&junk).clone(),
    }
}

#[test]
fn mutated_requests_never_stop_the_server() {
    let mut server = Server::start(&[]);
    let valid = [
        json!({"op": "paint", "origin": [0, 0, 5], "direction": [0, 0, -1], "radius": 0.2, "group": 1}),
        json!({"op": "bind"}),
        json!({"op": "motors", "seq": 1, "motors": [{}, {"scale": 1.2, "center": [0, 1, 0]}, {"rotate": {"axis": [1, 0, 0], "degrees": 30}}]}),
        json!({"op": "method", "method": "arap", "blend": "motor-linear", "options": {"iterations": 2}}),
        json!({"op": "field", "name": "harmonic", "group": 1}),
        json!({"op": "export", "what": "motors"}),
        json!({"op": "load", "what": "selection", "text": "{\"0\": [1, 2, 3], \"1\": [40, 41]}"}),
        json!({"op": "scene", "name": "arm"}),
        json!({"op": "rig", "seq": 2, "animation": 0, "time": 0.5, "backend": "matrix", "edits": [{"joint": 1, "motor": {"scale": 1.1}}]}),
        json!({"op": "cut", "point": [3, 0, 0], "normal": [1, 0, 0]}),
        json!({"op": "tear", "rays": [[[5.0, 0.05, 5.0], [0, 0, -1]], [[6.0, 0.05, 5.0], [0, 0, -1]]], "open": 0.2}),
        json!({"op": "drill", "origin": [5.0, 0.05, 5.0], "direction": [0, 0, -1], "radius": 0.01, "depth": 0.15}),
        json!({"op": "undo"}),
        json!({"op": "scene", "name": "lattice"}),
        json!({"op": "motors", "seq": 3, "motors": [{"translate": [0, 1, 0]}]}),
        json!({"op": "method", "method": "cage", "blend": "positional"}),
        json!({"op": "scene", "name": "sphere"}),
    ];
    let mut rng = Lcg::new();
    let mut c = server.connect(None).expect("connects");
    let (mut closed, mut sent) = (0, 0);
    for i in 0..240 {
        let mut request = rng.pick(&valid).clone();
        for _ in 0..(rng.next() % 3) {
            mutate(&mut request, &mut rng);
        }
        sent += 1;
        let text = request.to_string();
        if c.send_raw(Message::Text(request.to_string().into()))
            .is_err()
            || !c.answers()
        {
            closed += 1;
            assert_eq!(c.internal_errors, 0, "request {i} hit a bug: {text}");
            assert!(server.alive(), "request {i} stopped the server");
            c = server
                .connect(None)
                .expect("a new connection after a closed one");
            c.state();
        }
    }
    assert!(server.alive());
    assert_eq!(c.internal_errors, 0, "a request hit a bug");
    assert!(
        closed > 0 && closed < sent,
        "{closed} of {sent} closed: both kinds were sent"
    );
}

/// A loaded selection whose groups would need more than the run's budget (a weight per vertex
/// and group) is refused before any work, and the session goes on with a smaller one.
#[test]
fn a_selection_with_too_many_groups_is_refused() {
    // The sphere (2,562 vertices) starts with 3 groups: 3 * 2562 * 4 fits, 4 groups do not.
    let server = Server::start(&["--max-work", "35000"]);
    let mut c = server.connect(None).expect("connects");
    c.state();
    c.positions(0);
    let groups = |n: u32| {
        let sel: serde_json::Map<String, Value> =
            (0..n).map(|k| (k.to_string(), json!([k * 10]))).collect();
        json!({"op": "load", "what": "selection", "text": Value::Object(sel).to_string()})
    };
    c.send(groups(4));
    let message = c.until(true, |f| match f {
        Frame::Text(v) if v["type"] == "error" => Some(v["message"].as_str().unwrap().to_string()),
        _ => None,
    });
    assert!(
        message.contains("4 groups on 2562 vertices") && message.contains("--max-work"),
        "{message}"
    );
    assert!(c.answers(), "the session goes on");
    c.send(groups(2));
    c.send(json!({"op": "motors", "seq": 5, "motors": [{}, {"translate": [0, 0.5, 0]}]}));
    assert_eq!(c.positions(5).len(), 2562, "two groups bind and pose");
}
