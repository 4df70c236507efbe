//! `deform demo`: every method on procedural meshes (no files needed). Writes one OBJ and one
//! PNG per scene and a contact sheet of them all, and prints a table of bind and pose times.

use crate::output_files::{write_glb, write_mesh, write_png};
use anyhow::{Context, Result};
use clap::Args;
use deform::methods::showcase::{showcase, PosedScene};
use deform::render::preview::{self, Look};
use deform::skinning::GlbOptions;
use deform::Mesh;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct DemoArgs {
    /// Where the OBJ files and PNG previews go.
    #[arg(long, default_value = "deform-demo")]
    pub out: PathBuf,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
    /// Print the table as JSON.
    #[arg(long)]
    pub json: bool,
}

/// One scene's result.
#[derive(Clone)]
struct Row {
    name: &'static str,
    method: String,
    vertices: usize,
    bind_ms: f64,
    pose_ms: f64,
}

pub fn run(a: &DemoArgs) -> Result<()> {
    std::fs::create_dir_all(&a.out)
        .with_context(|| format!("{}: cannot create", a.out.display()))?;
    let mut rows = Vec::new();
    let mut images = Vec::new();
    for scene in showcase()? {
        rows.push(Row {
            name: scene.name,
            method: scene.method.clone(),
            vertices: scene.rest.vertex_count(),
            bind_ms: scene.bind_ms,
            pose_ms: scene.pose_ms,
        });
        if let Some(rig) = &scene.rig {
            // Mesh, skin and animations: any glTF viewer replays it.
            let glb = a.out.join(format!("{}.glb", scene.name));
            write_glb(&glb, rig, &GlbOptions::default())?;
        }
        images.push(save(a, scene)?);
    }
    let sheet = preview::sheet(&images, 4);
    let sheet_path = a.out.join("contact-sheet.png");
    write_png(&sheet_path, &sheet)?;
    print_table(&rows, a, &sheet_path);
    Ok(())
}

/// One OBJ and one before-and-after PNG of `s`, titled with the scene, its method and how far
/// it moved; returns its tile of the contact sheet.
fn save(a: &DemoArgs, s: PosedScene) -> Result<deform::render::Image> {
    let posed = Mesh::new(s.posed.clone(), s.rest.triangles.clone());
    let name = s.name;
    write_mesh(&a.out.join(format!("{name}.obj")), &posed)?;
    let moved = preview::max_move(&s.rest, &posed.positions);
    let look = Look {
        title: format!("{name}  {}  {moved}", s.method),
        ..s.look
    };
    let (rest, scalar) = (&s.rest, &s.scalar);
    let image = preview::before_after(rest, &posed, scalar, &look)?;
    write_png(&a.out.join(format!("{name}.png")), &image)?;
    Ok(preview::tile(rest, &posed, scalar, &look)?)
}

fn print_table(rows: &[Row], a: &DemoArgs, sheet: &std::path::Path) {
    if a.json {
        let v: Vec<serde_json::Value> = rows
            .iter()
            .map(|r| {
                serde_json::json!({
                    "scene": r.name, "method": r.method, "vertices": r.vertices,
                    "bind_ms": r.bind_ms, "pose_ms": r.pose_ms,
                })
            })
            .collect();
        println!(
            "{}",
            serde_json::json!({ "out": a.out.display().to_string(), "scenes": v })
        );
        return;
    }
    if a.quiet {
        return;
    }
    // Columns as wide as their longest entry.
    let scene = rows.iter().map(|r| r.name.len()).max().unwrap_or(0).max(5);
    let method = rows
        .iter()
        .map(|r| r.method.len())
        .max()
        .unwrap_or(0)
        .max(6);
    println!(
        "{:<scene$} {:<method$} {:>8} {:>9} {:>9}",
        "scene", "method", "vertices", "bind ms", "pose ms"
    );
    for r in rows {
        println!(
            "{:<scene$} {:<method$} {:>8} {:>9.2} {:>9.3}",
            r.name, r.method, r.vertices, r.bind_ms, r.pose_ms
        );
    }
    println!(
        "wrote {} OBJ files and PNG previews to {}, contact sheet {}",
        rows.len(),
        a.out.display(),
        sheet.display()
    );
}
