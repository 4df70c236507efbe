//! Reading inputs: meshes validated for deformation, selections, text files and rigs, and
//! the checks every command makes before reading (no output names an input, each output
//! names a format the command writes).

use crate::output_files::{check_formats, check_outputs, MESH_FORMATS};
use crate::shared_args::{MeshInput, OutputArgs, RigInput};
use anyhow::{Context, Result};
use deform::input::Selection;
use deform::mesh::io::ObjInputExtras;
use deform::skinning::{GltfReadOptions, Rig};
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

/// Read a selection by its extension (the library's reader).
pub fn read_selection(path: &Path, vertex_count: usize) -> Result<Selection> {
    Ok(deform::input::read_selection(path, vertex_count)?)
}

/// Read a text file (or pipe) of at most `deform::input::MAX_DOCUMENT_BYTES`.
pub fn read_text(path: &Path) -> Result<String> {
    Ok(deform::input::read_document(path)?)
}

/// Read the rig by the library's reader: glTF by extension, else a libigl mesh with
/// `--skeleton` and `--weights`.
pub fn read_rig(input: &RigInput) -> Result<Rig> {
    let options = GltfReadOptions {
        allow_external: input.allow_external,
        ..GltfReadOptions::default()
    };
    let libigl = input.skeleton.as_deref().zip(input.weights.as_deref());
    Ok(deform::skinning::read_rig(&input.model, libigl, &options)?)
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
