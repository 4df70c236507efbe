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
    let mesh = deform::io::read_mesh(path)?;
    deform::check_solvable(&mesh)
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
            let m = deform::io::read_dmat(path)?;
            selection_from_dmat(&m, vertex_count, &name)?
        }
        Some("json") => {
            let text =
                std::fs::read_to_string(path).with_context(|| format!("{name}: cannot read"))?;
            parse_selection_json(&text, vertex_count, &name)?
        }
        _ => bail!("{name}: a selection is a .dmat (libigl) or .json file"),
    };
    Ok(sel)
}

/// Read a text file.
pub fn read_text(path: &Path) -> Result<String> {
    std::fs::read_to_string(path).with_context(|| format!("{}: cannot read", path.display()))
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
    let skeleton = deform::io::read_tgf(s)?;
    let weights = deform::io::read_dmat(w)?;
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
    let read = read_mesh(mesh)?;
    let _ = out.input_extras.set(ObjInputExtras::read(mesh));
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
