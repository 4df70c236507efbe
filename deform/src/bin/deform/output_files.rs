//! Writing outputs safely: an output path that names an input is refused, an output must end
//! in a format the command writes, and every file is written to a temporary file beside it
//! and renamed, so a failure never leaves a half-written file.

use crate::shared_args::OutputArgs;
use anyhow::{bail, Context, Result};
use deform::mesh::io::ObjInputExtras;
use deform::mesh::io::{write_mesh_to, MeshFormat, ObjExtras};
use deform::Mesh;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The canonical form of a path that may not exist yet (its parent canonicalised).
fn canonical(p: &Path) -> PathBuf {
    if let Ok(c) = p.canonicalize() {
        return c;
    }
    let parent = p
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    match (parent.canonicalize(), p.file_name()) {
        (Ok(d), Some(f)) => d.join(f),
        _ => p.to_path_buf(),
    }
}

/// Refuse outputs that are inputs (or each other), and inputs that are devices (a link to
/// `/dev/zero` named as a mesh was read until memory ran out); files and pipes are read.
pub fn check_outputs(inputs: &[&Path], outputs: &[&Path]) -> Result<()> {
    for i in inputs {
        if let Ok(m) = std::fs::metadata(i) {
            if deform::mesh::io::is_device(&m.file_type()) {
                bail!("{}: a device, not a file: refusing to read it", i.display());
            }
        }
    }
    let ins: Vec<PathBuf> = inputs.iter().map(|p| canonical(p)).collect();
    let mut seen: Vec<PathBuf> = Vec::new();
    for o in outputs {
        let c = canonical(o);
        if ins.contains(&c) {
            bail!("{}: refusing to overwrite an input file", o.display());
        }
        if seen.contains(&c) {
            bail!("{}: named as two outputs", o.display());
        }
        seen.push(c);
    }
    Ok(())
}

/// Refuses an output whose extension names a format this command does not write (it would
/// otherwise get another format's bytes under the asked name): `-o` must end in one of
/// `formats`, `--png` in `.png`.
pub fn check_formats(out: &OutputArgs, formats: &[&str]) -> Result<()> {
    let ext = |p: &Path| {
        p.extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default()
    };
    let o = ext(&out.output);
    if !formats.contains(&o.as_str()) {
        let list: Vec<String> = formats.iter().map(|f| format!(".{f}")).collect();
        bail!(
            "{}: this command writes {}; give -o a name ending in one of them",
            out.output.display(),
            list.join(" or ")
        );
    }
    if let Some(png) = &out.png {
        if ext(png) != "png" {
            bail!(
                "{}: --png writes PNG; give it a name ending in .png",
                png.display()
            );
        }
    }
    Ok(())
}

/// Write a file atomically: `write` fills a temporary file in the same folder, which is then
/// renamed over `path`.
pub fn write_atomic(path: &Path, write: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .with_context(|| format!("{}: not a file name", path.display()))?;
    let tmp = dir.join(format!(
        ".{}.tmp-{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let _unfinished = crate::interrupt::pending(&[&tmp]);
    let result = (|| -> Result<()> {
        let file = std::fs::File::create(&tmp)
            .with_context(|| format!("{}: cannot create", tmp.display()))?;
        let mut w = std::io::BufWriter::new(file);
        write(&mut w)?;
        let file = w.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        std::fs::rename(&tmp, path).with_context(|| format!("{}: cannot write", path.display()))?;
        Ok(())
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result.with_context(|| format!("writing {}", path.display()))
}

/// Write a deformed mesh as [`write_mesh`] does; an OBJ keeps the OBJ input's texture
/// coordinates and, where it had normals, gets this mesh's smooth normals.
pub fn write_deformed(path: &Path, mesh: &Mesh, input: Option<&ObjInputExtras>) -> Result<()> {
    let normals = input
        .filter(|i| i.normals && MeshFormat::from_path(path).is_none_or(|f| f == MeshFormat::Obj))
        .map(|_| mesh.seamless_vertex_normals());
    let extras = ObjExtras {
        texture: input.and_then(|i| i.texture.as_ref()),
        normals: normals.as_deref(),
        uvs: None,
    };
    write_mesh_with(path, mesh, extras)
}

/// The mesh formats every command that writes a mesh writes, by `-o` extension.
pub const MESH_FORMATS: [&str; 3] = MeshFormat::EXTENSIONS;

/// Write a mesh in the format its extension names (the library's [`MeshFormat`]; OBJ for
/// any other name), atomically; the vertex order and count as given.
pub fn write_mesh(path: &Path, mesh: &Mesh) -> Result<()> {
    write_mesh_with(path, mesh, ObjExtras::default())
}

/// Write a rig's mesh (rest or posed) as OBJ with the texture coordinates of its look
/// (`TEXCOORD_0`) as `vt` and, where the model has normals, this mesh's smooth normals
/// (seamless across UV seams) as `vn`; or, for a `.ply` or `.glb` name, as [`write_mesh`].
pub fn write_rig_mesh(path: &Path, mesh: &Mesh, look: &deform::skinning::Look) -> Result<()> {
    let uv = look
        .attribute("TEXCOORD_0")
        .filter(|a| a.width == 2 && a.vertex_count() == mesh.vertex_count());
    let normals = look
        .attribute("NORMAL")
        .map(|_| mesh.seamless_vertex_normals());
    let extras = ObjExtras {
        uvs: uv.map(|a| &a.values[..]),
        normals: normals.as_deref(),
        texture: None,
    };
    write_mesh_with(path, mesh, extras)
}

/// Write a mesh by extension with OBJ extras; every command's result goes through here, so a
/// non-finite vertex, or one beyond what every reader of this program accepts, is an error
/// (the library's check), never a file.
fn write_mesh_with(path: &Path, mesh: &Mesh, extras: ObjExtras) -> Result<()> {
    let format = MeshFormat::from_path(path).unwrap_or(MeshFormat::Obj);
    deform::mesh::validate::check_elements(mesh)
        .with_context(|| format!("{}: not written: the result", path.display()))?;
    write_atomic(path, |w| {
        write_mesh_to(mesh, format, extras, w)?;
        Ok(())
    })
}

/// Write an image as PNG.
pub fn write_png(path: &Path, image: &deform::render::Image) -> Result<()> {
    write_atomic(path, |w| {
        image.write_png_to(w)?;
        Ok(())
    })
}

/// Write a rig as `.glb`, atomically like every output (an interrupted run leaves nothing).
pub fn write_glb(
    path: &Path,
    rig: &deform::skinning::Rig,
    options: &deform::skinning::GlbOptions,
) -> Result<()> {
    let bytes = deform::skinning::glb_bytes(rig, options)?;
    write_atomic(path, |w| {
        w.write_all(&bytes)?;
        Ok(())
    })
}
