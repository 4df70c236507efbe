//! Reading inputs: meshes validated for deformation, selections, text files and rigs, and
//! the checks every command makes before reading (no output names an input, each output
//! names a format the command writes).

use crate::obj_extras::ObjInputExtras;
use crate::output_files::{check_formats, check_outputs, MESH_FORMATS};
use crate::shared_args::{MeshInput, OutputArgs, RigInput};
use anyhow::{bail, Context, Result};
use deform::input::{parse_selection_json, selection_from_dmat, Selection};
use deform::skinning::{libigl_rig, read_gltf_with, GltfReadOptions, Rig};
use deform::Mesh;
use std::path::Path;

/// Read a mesh, validated for deformation.
pub fn read_mesh(path: &Path) -> Result<Mesh> {
    usable(path, deform::mesh::io::read_mesh(path)?)
}

/// `mesh`, read from `path`, if it passes the checks for deformation.
fn usable(path: &Path, mesh: Mesh) -> Result<Mesh> {
    deform::mesh::validate::check_solvable(&mesh)
        .with_context(|| format!("{}: not a usable mesh", path.display()))?;
    Ok(mesh)
}

/// Read a selection: `.dmat` (libigl) or `.json`.
pub fn read_selection(path: &Path, vertex_count: usize) -> Result<Selection> {
    let name = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let sel = match ext.as_deref() {
        Some("dmat") => {
            let m = deform::mesh::io::read_dmat(path)?;
            selection_from_dmat(&m, vertex_count, &name)?
        }
        Some("json") => {
            let text = read_text(path)?;
            parse_selection_json(&text, vertex_count, &name)?
        }
        _ => bail!("{name}: a selection is a .dmat (libigl) or .json file"),
    };
    Ok(sel)
}

/// The largest JSON document (motors, keys, selections, animations) a command reads: 1 GiB,
/// room for a selection of every vertex of a 50-million-vertex mesh. A file or pipe that
/// gives more is refused before it fills memory.
pub const MAX_DOCUMENT_BYTES: u64 = 1 << 30;

/// Read a text file (or pipe) of at most [`MAX_DOCUMENT_BYTES`].
pub fn read_text(path: &Path) -> Result<String> {
    let shown = path.display();
    let bytes = deform::mesh::io::read_limited(path, MAX_DOCUMENT_BYTES)
        .with_context(|| format!("{shown}: cannot read"))?;
    String::from_utf8(bytes).with_context(|| format!("{shown}: not UTF-8 text"))
}

/// Read the rig: glTF by extension, else a libigl mesh with skeleton and weights.
pub fn read_rig(input: &RigInput) -> Result<Rig> {
    let ext = input
        .model
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if ext == "gltf" || ext == "glb" {
        let options = GltfReadOptions {
            allow_external: input.allow_external,
            ..GltfReadOptions::default()
        };
        return Ok(read_gltf_with(&input.model, &options)?);
    }
    let (Some(s), Some(w)) = (&input.skeleton, &input.weights) else {
        bail!(
            "{}: a mesh model needs --skeleton and --weights (or give a .gltf/.glb)",
            input.model.display()
        );
    };
    let mesh = read_mesh(&input.model)?;
    let skeleton = deform::mesh::io::read_tgf(s)?;
    let weights = deform::mesh::io::read_dmat(w)?;
    libigl_rig(mesh, &skeleton, &weights)
        .with_context(|| format!("{}: cannot rig", input.model.display()))
}

/// Refuse outputs that are inputs (`mesh` and `extra`) or not in
/// [`MESH_FORMATS`], then read the mesh.
pub fn read_mesh_checked(mesh: &Path, extra: &[&Path], out: &OutputArgs) -> Result<Mesh> {
    let mut inputs = vec![mesh];
    inputs.extend_from_slice(extra);
    check_outputs(&inputs, &out.paths())?;
    check_formats(out, &MESH_FORMATS)?;
    let (read, extras) = ObjInputExtras::read_with_mesh(mesh)?;
    let read = usable(mesh, read)?;
    let _ = out.input_extras.set(extras);
    Ok(read)
}

/// Read the mesh and selection, refusing outputs that are inputs (these and `extra`) or not
/// in [`MESH_FORMATS`].
pub fn read_mesh_input(
    input: &MeshInput,
    extra: &[&Path],
    out: &OutputArgs,
) -> Result<(Mesh, Selection)> {
    let mut inputs = vec![input.select.as_path()];
    inputs.extend_from_slice(extra);
    let mesh = read_mesh_checked(&input.mesh, &inputs, out)?;
    let sel = read_selection(&input.select, mesh.vertex_count())?;
    Ok((mesh, sel))
}
