//! Reading a rig by the model's extension: a glTF file, or a mesh rigged by libigl's skeleton
//! and weights files (as reading a mesh by extension is [`crate::mesh::io::read_mesh`]).

use super::accessor::GltfReadOptions;
use super::gltf_read::read_gltf_with;
use super::libigl_rig::libigl_rig;
use super::rig::Rig;
use super::SkinError;
use std::path::Path;

/// Read the rig of `model`: glTF for `.gltf` and `.glb` (with `options`), else a mesh (OBJ,
/// OFF, MEDIT; checked for deformation) rigged by `libigl`'s skeleton (TGF) and weights
/// (DMAT, vertices x bones).
///
/// # Errors
/// [`SkinError::InvalidArgument`] for a mesh without skeleton and weights; what the readers
/// and [`libigl_rig`] refuse, naming the file.
pub fn read_rig(
    model: &Path,
    libigl: Option<(&Path, &Path)>,
    options: &GltfReadOptions,
) -> Result<Rig, SkinError> {
    let ext = model
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if ext == "gltf" || ext == "glb" {
        return read_gltf_with(model, options);
    }
    let name = model.display().to_string();
    let Some((skeleton, weights)) = libigl else {
        return Err(SkinError::InvalidArgument(format!(
            "{name}: a mesh model needs a skeleton and weights (--skeleton, --weights), or \
             give a .gltf/.glb"
        )));
    };
    let data = |file: &Path, e: crate::mesh::MeshError| SkinError::Data {
        name: file.display().to_string(),
        message: e.to_string(),
    };
    let mesh = crate::mesh::io::read_mesh(model).map_err(|e| data(model, e))?;
    crate::mesh::validate::check_solvable(&mesh).map_err(|e| SkinError::Data {
        name: name.clone(),
        message: format!("not a usable mesh: {e}"),
    })?;
    let skeleton = crate::mesh::io::read_tgf(skeleton).map_err(|e| data(skeleton, e))?;
    let weights = crate::mesh::io::read_dmat(weights).map_err(|e| data(weights, e))?;
    libigl_rig(mesh, &skeleton, &weights).map_err(|e| SkinError::Data {
        name,
        message: format!("cannot rig: {e}"),
    })
}
