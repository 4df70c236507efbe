//! Writing outputs safely: an output path that names an input is refused, an output must end
//! in a format the command writes, and every file is written to a temporary file beside it
//! and renamed, so a failure never leaves a half-written file.

use crate::obj_extras::ObjInputExtras;
use crate::shared_args::OutputArgs;
use anyhow::{bail, Context, Result};
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
    let obj = path
        .extension()
        .is_none_or(|e| !(e.eq_ignore_ascii_case("ply") || e.eq_ignore_ascii_case("glb")));
    let Some(input) = input.filter(|_| obj) else {
        return write_mesh(path, mesh);
    };
    let normals = input.normals.then(|| mesh.seamless_vertex_normals());
    let extras = deform::mesh::io::ObjExtras {
        texture: input.texture.as_ref(),
        normals: normals.as_deref(),
        uvs: None,
    };
    write_obj_with(path, mesh, extras)
}

/// The mesh formats every command that writes a mesh writes, by `-o` extension.
pub const MESH_FORMATS: [&str; 3] = ["obj", "glb", "ply"];

/// Write a mesh in the format its extension names: `.glb` (a static binary glTF with smooth
/// normals), `.ply` (binary PLY), else OBJ; the vertex order and count as given.
pub fn write_mesh(path: &Path, mesh: &Mesh) -> Result<()> {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    match ext.as_str() {
        "glb" => {
            check_finite(path, mesh)?;
            let bytes = deform::mesh::io::glb_bytes(mesh)?;
            write_atomic(path, |w| {
                w.write_all(&bytes)?;
                Ok(())
            })
        }
        "ply" => {
            check_finite(path, mesh)?;
            write_atomic(path, |w| {
                deform::mesh::io::write_ply_to(mesh, w)?;
                Ok(())
            })
        }
        _ => write_obj(path, mesh),
    }
}

/// Every command's result goes through here: a non-finite vertex, or one beyond the
/// coordinates every reader of this program accepts (`MAX_COORDINATE`, 1e300: a result the
/// program could not read back), is an error, never a file.
fn check_finite(path: &Path, mesh: &Mesh) -> Result<()> {
    if let Some(i) = mesh.positions.iter().position(|p| !p.is_finite()) {
        bail!(
            "{}: not written: vertex {i} of the result is not finite ({})",
            path.display(),
            mesh.positions[i]
        );
    }
    let limit = deform::mesh::validate::MAX_COORDINATE;
    if let Some(i) = mesh
        .positions
        .iter()
        .position(|p| p.abs().max_element() > limit)
    {
        bail!(
            "{}: not written: vertex {i} of the result lies beyond +-{limit:e} ({}), where no \
             reader of this program would take it back",
            path.display(),
            mesh.positions[i]
        );
    }
    Ok(())
}

/// Write a mesh as OBJ (the vertex order and count as given).
pub fn write_obj(path: &Path, mesh: &Mesh) -> Result<()> {
    write_obj_with(path, mesh, deform::mesh::io::ObjExtras::default())
}

/// Write a rig's mesh (rest or posed) as OBJ with the texture coordinates of its look
/// (`TEXCOORD_0`) as `vt` and, where the model has normals, this mesh's smooth normals
/// (seamless across UV seams) as `vn`; or, for a `.ply` or `.glb` name, as [`write_mesh`].
pub fn write_rig_mesh(path: &Path, mesh: &Mesh, look: &deform::skinning::Look) -> Result<()> {
    let obj = path
        .extension()
        .is_none_or(|e| !(e.eq_ignore_ascii_case("ply") || e.eq_ignore_ascii_case("glb")));
    if !obj {
        return write_mesh(path, mesh);
    }
    let uv = look
        .attribute("TEXCOORD_0")
        .filter(|a| a.width == 2 && a.vertex_count() == mesh.vertex_count());
    let normals = look
        .attribute("NORMAL")
        .map(|_| mesh.seamless_vertex_normals());
    let extras = deform::mesh::io::ObjExtras {
        uvs: uv.map(|a| &a.values[..]),
        normals: normals.as_deref(),
        texture: None,
    };
    write_obj_with(path, mesh, extras)
}

/// Write a mesh as OBJ with texture coordinates and normals.
fn write_obj_with(path: &Path, mesh: &Mesh, extras: deform::mesh::io::ObjExtras) -> Result<()> {
    check_finite(path, mesh)?;
    write_atomic(path, |w| {
        deform::mesh::io::write_obj_with_to(mesh, extras, w)?;
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
