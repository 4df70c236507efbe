//! `deform view`: the interactive editor. A local server (loopback unless `--host`) serves one
//! page, compiled into the program, that drives every deformer by hand: the mesh lives here,
//! bound and posed by the library; the page sends edits and draws the positions it gets back
//! over a WebSocket.
//!
//! Why axum on tokio: the most used and maintained Rust HTTP stack, with WebSockets built in
//! (tokio-tungstenite), message size limits and a small surface; the editing itself runs on
//! plain threads, one per connection, so binds and poses never block the server.

mod mailbox;
mod server;

use anyhow::{bail, Context, Result};
use clap::Args;
use deform::methods::scenes::{catalogue, Scene};
use std::hash::{BuildHasher, Hasher};
use std::io::Write;
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::{Path, PathBuf};
use std::sync::Arc;

#[derive(Args, Debug)]
pub struct ViewArgs {
    /// A mesh (OBJ, OFF, MEDIT) to deform with handles, ARAP or a spline, or a rig (.gltf,
    /// .glb, or a mesh with --skeleton and --weights) to animate, edit and cut. Without it:
    /// the demo's procedural scenes.
    pub model: Option<PathBuf>,
    /// libigl skeleton (TGF) that makes the mesh a rig (with --weights).
    #[arg(long, requires = "weights", requires = "model")]
    pub skeleton: Option<PathBuf>,
    /// libigl weights (DMAT, vertices x bones) of the mesh's rig (with --skeleton).
    #[arg(long, requires = "skeleton")]
    pub weights: Option<PathBuf>,
    /// Handle groups of a mesh to start with: libigl DMAT or JSON {"k": [vertices]}.
    #[arg(long)]
    pub select: Option<PathBuf>,
    /// The port (0 picks a free one).
    #[arg(long, default_value_t = 0)]
    pub port: u16,
    /// The address to listen on. Loopback only unless given: anyone who can reach the
    /// address and has the printed token can edit.
    #[arg(long)]
    pub host: Option<IpAddr>,
}

/// A random session token (128 bits from the process's randomly seeded hashers).
fn token() -> String {
    (0..2)
        .map(|i| {
            let mut h = std::collections::hash_map::RandomState::new().build_hasher();
            h.write_u64(i ^ std::process::id() as u64);
            format!("{:016x}", h.finish())
        })
        .collect()
}

/// The scene of the model on the command line.
fn model_scene(a: &ViewArgs, path: &Path) -> Result<Scene> {
    // Nothing is written; the inputs are checked as every command checks them (no devices).
    let mut inputs = vec![path];
    inputs.extend(a.skeleton.as_deref());
    inputs.extend(a.weights.as_deref());
    inputs.extend(a.select.as_deref());
    crate::output_files::check_outputs(&inputs, &[])?;
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    let gltf = ext == "gltf" || ext == "glb";
    if gltf && a.skeleton.is_some() {
        bail!("--skeleton and --weights make a mesh a rig; a glTF model has its own");
    }
    if (gltf || a.skeleton.is_some()) && a.select.is_some() {
        bail!("--select is for a mesh; a rig's joints are its handles");
    }
    let libigl = a.skeleton.as_deref().zip(a.weights.as_deref());
    Ok(Scene::from_model(path, libigl, a.select.as_deref())?)
}

/// The page: HTML with its style and script put in.
fn page() -> String {
    include_str!("view/page/index.html")
        .replace("/*STYLE*/", include_str!("view/page/style.css"))
        .replace(
            "//SCRIPT",
            &[
                include_str!("view/page/math.js"),
                include_str!("view/page/camera.js"),
                include_str!("view/page/render.js"),
                include_str!("view/page/gizmo.js"),
                include_str!("view/page/app.js"),
            ]
            .concat(),
        )
}

pub fn run(a: &ViewArgs) -> Result<()> {
    let mut scenes = Vec::new();
    match &a.model {
        Some(path) => scenes.push(model_scene(a, path)?),
        None if a.select.is_some() => bail!("--select needs a MODEL"),
        None => {}
    }
    scenes.extend(catalogue());
    let host = a.host.unwrap_or(IpAddr::V4(Ipv4Addr::LOCALHOST));
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("cannot start the server's runtime")?;
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::bind(SocketAddr::new(host, a.port))
            .await
            .with_context(|| format!("cannot listen on {host} port {}", a.port))?;
        let addr = listener.local_addr()?;
        let port = addr.port();
        let shown = if addr.ip().is_unspecified() {
            SocketAddr::new(IpAddr::V4(Ipv4Addr::LOCALHOST), port)
        } else {
            addr
        };
        let app = Arc::new(server::App {
            token: token(),
            origins: vec![
                format!("http://{shown}"),
                format!("http://localhost:{port}"),
                format!("http://127.0.0.1:{port}"),
                format!("http://[::1]:{port}"),
            ],
            host_origin: a.host.is_some(),
            scenes,
            page: page(),
            sessions: Default::default(),
        });
        println!(
            "deform view: open http://{shown}/?token={} in a browser (Ctrl-C stops)",
            app.token
        );
        std::io::stdout().flush()?;
        axum::serve(listener, server::router(app))
            .await
            .context("the server stopped")
    })
}
