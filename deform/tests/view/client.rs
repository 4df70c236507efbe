//! A test client: starts `deform view`, connects like the page, decodes the frames.

use glam::DVec3;
use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::Duration;
use tungstenite::stream::MaybeTlsStream;
use tungstenite::{Message, WebSocket};

/// The largest distance between corresponding points.
pub fn worst(a: &[DVec3], b: &[DVec3]) -> f64 {
    assert_eq!(a.len(), b.len(), "vertex counts");
    a.iter()
        .zip(b)
        .map(|(p, q)| (*p - *q).length())
        .fold(0.0, f64::max)
}

/// A running `deform view`, stopped on drop.
pub struct Server {
    child: Child,
    pub port: u16,
    pub token: String,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Server {
    /// `deform view ARGS --port 0`; waits for the address it prints.
    pub fn start(args: &[&str]) -> Server {
        // Tests get the program from cargo; the report example runs the release build.
        let program = option_env!("CARGO_BIN_EXE_deform").unwrap_or("target/release/deform");
        let mut child = Command::new(program)
            .arg("view")
            .args(args)
            .args(["--port", "0"])
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("deform starts");
        let mut line = String::new();
        BufReader::new(child.stdout.take().expect("stdout"))
            .read_line(&mut line)
            .expect("the address line");
        let url = line
            .split_whitespace()
            .find(|w| w.starts_with("http://"))
            .unwrap_or_else(|| panic!("no address in {line:?}"));
        let rest = url.trim_start_matches("http://127.0.0.1:");
        let (port, token) = rest.split_once("/?token=").expect("port and token");
        Server {
            child,
            port: port.parse().expect("a port"),
            token: token.to_string(),
        }
    }

    /// Whether the process still runs.
    pub fn alive(&mut self) -> bool {
        self.child.try_wait().expect("wait").is_none()
    }

    /// A raw HTTP GET of `path` with extra header lines; the status code.
    pub fn http_status(&self, path: &str, headers: &str) -> u16 {
        let mut s = TcpStream::connect(("127.0.0.1", self.port)).expect("connect");
        s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
        write!(
            s,
            "GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{}\r\n{headers}Connection: close\r\n\r\n",
            self.port
        )
        .unwrap();
        let mut head = [0u8; 12];
        s.read_exact(&mut head).expect("a status line");
        std::str::from_utf8(&head[9..12]).unwrap().parse().unwrap()
    }

    /// A WebSocket session with the token (and an `Origin`, if given).
    pub fn connect(&self, origin: Option<&str>) -> Result<Client, tungstenite::Error> {
        let headers: Vec<(&str, &str)> = origin.map(|o| ("Origin", o)).into_iter().collect();
        self.connect_with(&headers)
    }

    /// A WebSocket session with the token and these extra (or replaced) headers.
    pub fn connect_with(&self, headers: &[(&str, &str)]) -> Result<Client, tungstenite::Error> {
        let url = format!("ws://127.0.0.1:{}/ws?token={}", self.port, self.token);
        let mut request = tungstenite::client::IntoClientRequest::into_client_request(url)?;
        for (k, v) in headers {
            let name = tungstenite::http::HeaderName::from_bytes(k.as_bytes()).unwrap();
            request.headers_mut().insert(name, v.parse().unwrap());
        }
        let (ws, _) = tungstenite::connect(request)?;
        if let MaybeTlsStream::Plain(s) = ws.get_ref() {
            s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
        }
        Ok(Client {
            ws,
            internal_errors: 0,
        })
    }
}

/// A decoded frame from the server.
#[derive(Debug)]
pub enum Frame {
    Text(Value),
    Mesh {
        rest: Vec<DVec3>,
        triangles: Vec<[u32; 3]>,
    },
    Positions {
        seq: u32,
        posed: Vec<DVec3>,
    },
    /// Positions in f32 (after a `precision` request).
    PositionsF32 {
        seq: u32,
        posed: Vec<[f32; 3]>,
    },
    Field(Vec<f32>),
    Groups(Vec<u8>),
    Closed,
}

fn u32_at(b: &[u8], i: usize) -> u32 {
    u32::from_le_bytes(b[i..i + 4].try_into().unwrap())
}

fn points(b: &[u8], n: usize) -> Vec<DVec3> {
    (0..n)
        .map(|v| {
            let f = |k: usize| f64::from_le_bytes(b[24 * v + 8 * k..][..8].try_into().unwrap());
            DVec3::new(f(0), f(1), f(2))
        })
        .collect()
}

pub struct Client {
    ws: WebSocket<MaybeTlsStream<TcpStream>>,
    /// Error replies that report a bug ("internal error"), however they were read.
    pub internal_errors: usize,
}

impl Client {
    pub fn send(&mut self, v: Value) {
        self.ws.send(Message::Text(v.to_string().into())).unwrap();
    }

    pub fn send_raw(&mut self, m: Message) -> Result<(), tungstenite::Error> {
        self.ws.send(m)
    }

    /// The next frame (`Closed` when the server closed the socket).
    pub fn next(&mut self) -> Frame {
        loop {
            let m = match self.ws.read() {
                Ok(m) => m,
                Err(_) => return Frame::Closed,
            };
            return match m {
                Message::Text(t) => {
                    let v: Value = serde_json::from_str(&t).expect("JSON replies");
                    if v["type"] == "error"
                        && v["message"].as_str().unwrap().contains("internal error")
                    {
                        eprintln!("server: {}", v["message"]);
                        self.internal_errors += 1;
                    }
                    Frame::Text(v)
                }
                Message::Binary(b) => match u32_at(&b, 0) {
                    1 => {
                        let (n, m) = (u32_at(&b, 4) as usize, u32_at(&b, 8) as usize);
                        let t0 = 16 + 24 * n;
                        Frame::Mesh {
                            rest: points(&b[16..], n),
                            triangles: (0..m)
                                .map(|f| std::array::from_fn(|k| u32_at(&b, t0 + 12 * f + 4 * k)))
                                .collect(),
                        }
                    }
                    2 => Frame::Positions {
                        seq: u32_at(&b, 4),
                        posed: points(&b[16..], (b.len() - 16) / 24),
                    },
                    3 => Frame::Field(
                        b[12..]
                            .chunks(4)
                            .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
                            .collect(),
                    ),
                    4 => Frame::Groups(b[8..8 + u32_at(&b, 4) as usize].to_vec()),
                    5 => Frame::PositionsF32 {
                        seq: u32_at(&b, 4),
                        posed: b[16..]
                            .chunks(12)
                            .map(|c| {
                                std::array::from_fn(|k| {
                                    f32::from_le_bytes(c[4 * k..4 * k + 4].try_into().unwrap())
                                })
                            })
                            .collect(),
                    },
                    k => panic!("unknown frame kind {k}"),
                },
                Message::Close(_) => Frame::Closed,
                _ => continue,
            };
        }
    }

    /// Frames until `want` picks one; panics on a server error unless `errors_ok`.
    pub fn until<T>(&mut self, errors_ok: bool, mut want: impl FnMut(&Frame) -> Option<T>) -> T {
        for _ in 0..10_000 {
            let f = self.next();
            if let Frame::Text(v) = &f {
                if v["type"] == "error" && !errors_ok {
                    panic!("server error: {}", v["message"]);
                }
            }
            if let Some(t) = want(&f) {
                return t;
            }
            if matches!(f, Frame::Closed) {
                panic!("closed while waiting");
            }
        }
        panic!("no such frame in 10000");
    }

    /// The next state reply.
    pub fn state(&mut self) -> Value {
        self.until(false, |f| match f {
            Frame::Text(v) if v["type"] == "state" => Some(v.clone()),
            _ => None,
        })
    }

    /// The positions of pose `seq`.
    pub fn positions(&mut self, seq: u32) -> Vec<DVec3> {
        self.until(false, |f| match f {
            Frame::Positions { seq: s, posed } if *s == seq => Some(posed.clone()),
            _ => None,
        })
    }

    /// The next error message.
    pub fn error(&mut self) -> String {
        self.until(true, |f| match f {
            Frame::Text(v) if v["type"] == "error" => {
                Some(v["message"].as_str().unwrap().to_string())
            }
            _ => None,
        })
    }

    /// Whether the session still answers: a field request gets a field frame back.
    pub fn answers(&mut self) -> bool {
        let ask = json!({"op": "field", "name": "displacement"}).to_string();
        if self.ws.send(Message::Text(ask.into())).is_err() {
            return false;
        }
        loop {
            match self.next() {
                Frame::Field(_) => return true,
                Frame::Closed => return false,
                _ => {}
            }
        }
    }
}
