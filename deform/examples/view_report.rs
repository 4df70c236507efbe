//! The editor's server without a browser: bind and pose rates of `deform view` over its
//! socket, as the page drives it (issue 24's speed targets, the server's share). Four handle
//! groups of about 800 vertices each are loaded as a selection (the bind timed), then motors
//! are sent one at a time (each waits for its positions: the round trip) and two in flight
//! (as the page sends while dragging), with handles and with ARAP at 2 iterations per frame.
//!
//! `cargo build --release -p deform && cargo run --release -p deform --example view_report -- MESH`
//! (default: the shared armadillo-50k).

// The test client; this report uses only part of it.
#[allow(dead_code)]
#[path = "../tests/view/client.rs"]
mod client;

use client::{Frame, Server};
use serde_json::json;
use std::time::Instant;

fn motors(k: usize) -> serde_json::Value {
    let a = k as f64 * 0.05;
    json!([{}, {"translate": [0.0, 2.0 * a.sin(), 0.0]},
        {"rotate": {"axis": [0, 0, 1], "degrees": 20.0 * a.cos(), "center": [0, 0, 0]}}, {"scale": 1.0 + 0.1 * a.sin()}])
}

/// Poses made per second with `depth` requests in flight, over `count` requests (some replaced
/// by newer ones before they start); mean round trip of the poses made (ms).
fn drive(c: &mut client::Client, count: usize, depth: usize) -> (f64, f64) {
    let t = Instant::now();
    let mut sent = Vec::new();
    let (mut trips, mut made) = (0.0, 0);
    let (mut next, mut done) = (1u32, 0);
    while done < count {
        while sent.len() < depth && (next as usize) <= count {
            c.send(json!({"op": "motors", "seq": next, "motors": motors(next as usize)}));
            sent.push((next, Instant::now()));
            next += 1;
        }
        // A pose answers its request and every older one (replaced before it started).
        if let Frame::Positions { seq, .. } = c.next() {
            if let Some(i) = sent.iter().position(|(s, _)| *s == seq) {
                trips += sent[i].1.elapsed().as_secs_f64() * 1e3;
                done += i + 1;
                made += 1;
                sent.drain(..=i);
            }
        }
    }
    (made as f64 / t.elapsed().as_secs_f64(), trips / made as f64)
}

fn main() {
    let mesh = std::env::args().nth(1).unwrap_or_else(|| {
        let dir = std::env::var("CGA_DATA_DIR").unwrap_or("../shared/data".into());
        format!("{dir}/meshes/large/armadillo-50k.obj")
    });
    let m = deform::mesh::io::read_mesh(&mesh).expect("a mesh");
    let n = m.vertex_count();
    // Four groups: the ~800 vertices nearest each of four vertices spread over the mesh.
    let groups: Vec<Vec<usize>> = [0.1, 0.35, 0.6, 0.85]
        .iter()
        .map(|f| {
            let c = m.positions[(f * n as f64) as usize];
            let mut d: Vec<(f64, usize)> =
                (0..n).map(|v| ((m.positions[v] - c).length(), v)).collect();
            d.sort_by(|a, b| a.0.total_cmp(&b.0));
            d[..800].iter().map(|x| x.1).collect()
        })
        .collect();
    let mut seen = vec![false; n];
    let sel: serde_json::Map<String, serde_json::Value> = groups
        .iter()
        .enumerate()
        .map(|(g, vs)| {
            let own: Vec<usize> = vs
                .iter()
                .copied()
                .filter(|&v| !std::mem::replace(&mut seen[v], true))
                .collect();
            (g.to_string(), json!(own))
        })
        .collect();
    let server = Server::start(&[&mesh]);
    let mut c = server.connect(None).expect("connects");
    c.until(true, |f| {
        matches!(f, Frame::Text(v) if v["type"] == "state").then_some(())
    });
    println!("deform view on {mesh} ({n} vertices), 4 groups of <= 800 vertices");
    for method in ["handles", "arap"] {
        let t = Instant::now();
        if method == "handles" {
            c.send(json!({"op": "load", "what": "selection", "text": serde_json::Value::Object(sel.clone()).to_string()}));
        } else {
            c.send(
                json!({"op": "method", "method": "arap", "blend": "motor-log", "iterations": 2}),
            );
        }
        let s = c.state();
        let seen_ms = t.elapsed().as_secs_f64() * 1e3;
        c.positions(0);
        println!(
            "{method}: bind {:.0} ms in the server, {seen_ms:.0} ms until the client had the state",
            s["bind_ms"].as_f64().unwrap()
        );
        for depth in [1, 2] {
            let (rate, trip) = drive(&mut c, 60, depth);
            println!("  {depth} in flight: {rate:.1} poses/s, round trip {trip:.1} ms");
        }
    }
}
