//! The HTTP and WebSocket side (axum on tokio): the page at `/`, the editing socket at `/ws`,
//! both behind the session token; each socket gets its own [`Session`] on its own thread, fed
//! through a [`Mailbox`] where a newer pose replaces one not yet made.

use super::mailbox::Mailbox;
use axum::extract::ws::{Message, WebSocket, WebSocketUpgrade};
use axum::extract::{Query, State};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::Router;
use deform::editor::protocol::{Reply, Request};
use deform::editor::{Out, Session, MAX_UPLOAD};
use deform::methods::scenes::Scene;
use std::collections::HashMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use tokio::sync::mpsc;

/// The largest message the page may send: an uploaded model of up to [`MAX_UPLOAD`] bytes
/// in base64 with room for its JSON, or a selection or motors file it loads.
pub const MAX_MESSAGE: usize = MAX_UPLOAD.div_ceil(3) * 4 + (1 << 20);
/// Sockets open at once (each holds its own bound mesh).
pub const MAX_SESSIONS: usize = 8;
/// Frames queued for a page that does not read before the session waits.
const QUEUE: usize = 64;

/// What every request handler shares.
pub struct App {
    pub token: String,
    /// `Origin` values a socket may come from (this server's own loopback addresses).
    pub origins: Vec<String>,
    /// Also `http://` + the request's `Host` (a server given `--host`, reached by other names).
    pub host_origin: bool,
    pub scenes: Vec<Scene>,
    pub page: String,
    pub sessions: AtomicUsize,
}

/// The router: `/` (the page) and `/ws` (the socket).
pub fn router(app: Arc<App>) -> Router {
    Router::new()
        .route("/", get(page))
        .route("/ws", get(socket))
        .with_state(app)
}

/// Equal without stopping at the first difference (the token is a secret).
fn same(a: &str, b: &str) -> bool {
    a.len() == b.len() && a.bytes().zip(b.bytes()).fold(0u8, |d, (x, y)| d | (x ^ y)) == 0
}

fn authorised(app: &App, query: &HashMap<String, String>) -> bool {
    query.get("token").is_some_and(|t| same(t, &app.token))
}

fn refuse(status: StatusCode, why: &'static str) -> Response {
    (status, why).into_response()
}

async fn page(State(app): State<Arc<App>>, Query(q): Query<HashMap<String, String>>) -> Response {
    if !authorised(&app, &q) {
        return refuse(
            StatusCode::FORBIDDEN,
            "forbidden: open the address `deform view` printed (it carries the session token)\n",
        );
    }
    (
        [
            (header::CONTENT_TYPE, "text/html; charset=utf-8"),
            (header::CACHE_CONTROL, "no-store"),
            (header::REFERRER_POLICY, "no-referrer"),
            (header::X_FRAME_OPTIONS, "DENY"),
            (
                header::CONTENT_SECURITY_POLICY,
                "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; \
                 connect-src 'self'; img-src data: blob:",
            ),
        ],
        app.page.clone(),
    )
        .into_response()
}

async fn socket(
    State(app): State<Arc<App>>,
    Query(q): Query<HashMap<String, String>>,
    headers: HeaderMap,
    ws: WebSocketUpgrade,
) -> Response {
    if !authorised(&app, &q) {
        return refuse(StatusCode::FORBIDDEN, "forbidden: wrong or missing token\n");
    }
    // A browser always sends Origin: only this server's own page may connect. (A client
    // without one is not a browser page, and it has the token.)
    if let Some(origin) = headers.get(header::ORIGIN) {
        let host = headers
            .get(header::HOST)
            .and_then(|h| h.to_str().ok())
            .filter(|_| app.host_origin)
            .map(|h| format!("http://{h}"));
        let ok = origin
            .to_str()
            .is_ok_and(|o| app.origins.iter().any(|a| a == o) || host.as_deref() == Some(o));
        if !ok {
            return refuse(StatusCode::FORBIDDEN, "forbidden: foreign Origin\n");
        }
    }
    let open = app.sessions.fetch_add(1, Ordering::SeqCst);
    if open >= MAX_SESSIONS {
        app.sessions.fetch_sub(1, Ordering::SeqCst);
        return refuse(StatusCode::SERVICE_UNAVAILABLE, "too many open sessions\n");
    }
    ws.max_message_size(MAX_MESSAGE)
        .max_frame_size(MAX_MESSAGE)
        .on_upgrade(move |socket| async move {
            serve_socket(socket, app.clone()).await;
            app.sessions.fetch_sub(1, Ordering::SeqCst);
        })
}

fn encode(out: Out) -> Message {
    match out {
        Out::Text(r) => Message::Text(
            serde_json::to_string(&r)
                .unwrap_or_else(|e| format!(r#"{{"type":"error","message":"{e}"}}"#))
                .into(),
        ),
        Out::Binary(f) => Message::Binary(f.0.into()),
    }
}

/// One connection: reads requests into the mailbox, writes what the session thread sends.
async fn serve_socket(mut socket: WebSocket, app: Arc<App>) {
    let mailbox = Arc::new(Mailbox::default());
    let (tx, mut rx) = mpsc::channel::<Out>(QUEUE);
    let worker = {
        let (mailbox, scenes) = (mailbox.clone(), app.scenes.clone());
        std::thread::spawn(move || run_session(scenes, &mailbox, &tx))
    };
    loop {
        tokio::select! {
            message = socket.recv() => {
                let text = match message {
                    Some(Ok(Message::Text(t))) => t,
                    Some(Ok(Message::Ping(_) | Message::Pong(_))) => continue,
                    Some(Ok(Message::Binary(_))) => {
                        close_with(&mut socket, "binary frames are not requests").await;
                        break;
                    }
                    // Closed, or a protocol error (an oversized message among them).
                    Some(Ok(Message::Close(_)) | Err(_)) | None => break,
                };
                match serde_json::from_str::<Request>(&text) {
                    Ok(request) => mailbox.push(request),
                    Err(e) => {
                        close_with(&mut socket, &format!("malformed request: {e}")).await;
                        break;
                    }
                }
            }
            out = rx.recv() => match out {
                Some(out) => {
                    if socket.send(encode(out)).await.is_err() {
                        break;
                    }
                }
                None => break, // the session ended (an internal error it reported)
            }
        }
    }
    mailbox.close();
    drop(rx);
    let _ = tokio::task::spawn_blocking(move || worker.join()).await;
}

/// Say why, then close (one bad message closes its connection, never the server).
async fn close_with(socket: &mut WebSocket, why: &str) {
    let reply = Reply::Error {
        message: why.into(),
    };
    let _ = socket.send(encode(Out::Text(reply))).await;
    let _ = socket.send(Message::Close(None)).await;
}

/// The session thread: one request at a time; an error is reported and the session goes on,
/// a panic (a bug) is reported and ends this session only.
fn run_session(scenes: Vec<Scene>, mailbox: &Mailbox, tx: &mpsc::Sender<Out>) {
    let send = |out: Out| tx.blocking_send(out).is_ok();
    let report = |e: anyhow::Error| {
        send(Out::Text(Reply::Error {
            message: format!("{e:#}"),
        }))
    };
    let opened = std::panic::catch_unwind(|| Session::new(scenes, crate::budget::get()));
    let mut session = match opened {
        Ok(Ok((s, out))) => {
            if !out.into_iter().all(send) {
                return;
            }
            s
        }
        Ok(Err(e)) => {
            report(e.into());
            return;
        }
        Err(_) => {
            report(anyhow::anyhow!("internal error opening the scene"));
            return;
        }
    };
    // How long the last slow request of each kind took (`Session::slow_key`).
    let mut took: std::collections::HashMap<String, f64> = std::collections::HashMap::new();
    while let Some(request) = mailbox.pop() {
        let slow = request.slow();
        let key = slow.map(|what| session.slow_key(&request, what));
        if let (Some(what), Some(key)) = (slow, &key) {
            let expect_ms = took.get(key).copied();
            if !send(Out::Text(Reply::Binding {
                what: what.into(),
                expect_ms,
            })) {
                return;
            }
        }
        let started = std::time::Instant::now();
        let result =
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| session.handle(request)));
        if let (Some(key), Ok(Ok(_))) = (key, &result) {
            took.insert(key, started.elapsed().as_secs_f64() * 1e3);
        }
        let ok = match result {
            Ok(Ok(out)) => {
                out.into_iter().all(send) && (slow.is_none() || send(Out::Text(Reply::Idle)))
            }
            Ok(Err(e)) => report(e.into()) && (slow.is_none() || send(Out::Text(Reply::Idle))),
            Err(_) => {
                report(anyhow::anyhow!(
                    "internal error: this session ends (reload the page)"
                ));
                return;
            }
        };
        if !ok {
            return;
        }
    }
}
