//! glTF 2.0 rigs in (`.gltf` with embedded or external buffers, `.glb`).

use super::accessor::{Buffers, GltfReadOptions, Layout};
use super::animation::{Animation, Channel, Interpolation, Property};
use super::influences::Influences;
use super::look_read::{merge_attributes, primitive_attributes, read_look};
use super::morph;
use super::primitive_read::read_primitive;
use super::rig::{LoadReport, PrimitiveInfo, Rig, RigNode};
use super::SkinError;
use super::Trs;
use crate::mesh::Mesh;
use glam::{DMat4, DQuat, DVec3, DVec4};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Read a glTF 2.0 rig (`.gltf` or `.glb`); see [`parse_gltf`].
///
/// # Errors
/// [`SkinError::Io`] when the file cannot be read or holds more than
/// [`crate::mesh::io::MAX_FILE_BYTES`], and the errors of [`parse_gltf`].
pub fn read_gltf(path: impl AsRef<Path>) -> Result<Rig, SkinError> {
    read_gltf_with(path, &GltfReadOptions::default())
}

/// [`read_gltf`] with explicit [`GltfReadOptions`] (external buffers, the byte limit).
///
/// # Errors
/// As [`read_gltf`].
pub fn read_gltf_with(path: impl AsRef<Path>, options: &GltfReadOptions) -> Result<Rig, SkinError> {
    let path = path.as_ref();
    let bytes =
        crate::mesh::io::read_limited(path, crate::mesh::io::MAX_FILE_BYTES).map_err(|source| {
            SkinError::Io {
                path: path.to_path_buf(),
                message: source.to_string(),
            }
        })?;
    let base = path.parent().map(|p| {
        if p.as_os_str().is_empty() {
            Path::new(".")
        } else {
            p
        }
    });
    parse_gltf_with(&bytes, &path.display().to_string(), base, options)
}

/// The external files a glTF model (`.gltf` or `.glb`) names: its buffers and images whose
/// URI is not a `data:` URI, resolved against the model's folder as [`read_gltf`] resolves
/// them (percent-decoded); of a `.glb` only the JSON chunk is read. Empty for a file that is not a glTF document (reading it fails
/// later, with the reason). A program that writes files checks its outputs against these too,
/// so that no output replaces a file the model is made of.
pub fn gltf_external_files(path: impl AsRef<Path>) -> Vec<PathBuf> {
    let path = path.as_ref();
    let Some(json) = super::glb_container::read_json_only(path) else {
        return Vec::new();
    };
    let Ok(raw) = gltf::Gltf::from_slice_without_validation(&json) else {
        return Vec::new();
    };
    let json = raw.document.as_json();
    let base = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let buffers = json.buffers.iter().filter_map(|b| b.uri.as_deref());
    let images = json.images.iter().filter_map(|i| i.uri.as_deref());
    buffers
        .chain(images)
        .filter(|uri| !uri.starts_with("data:"))
        .map(|uri| base.join(super::accessor::percent_decoded(uri)))
        .collect()
}

/// Parse a glTF 2.0 rig from its bytes (`.gltf` JSON or `.glb`); `base` is the folder that
/// external buffer files are relative to.
///
/// What is read: the node hierarchy (matrices or TRS), the first skin used by a mesh and every
/// triangle primitive of the nodes using it (in order of mesh, primitive, node; vertex index =
/// POSITION accessor index), `JOINTS_0`/`WEIGHTS_0` and a second set `JOINTS_1`/`WEIGHTS_1`
/// where present, inverse bind matrices (identity when absent, as the specification says),
/// and every animation's translation, rotation and scale channels with `LINEAR`, `STEP` and
/// `CUBICSPLINE` samplers. The model's look is kept in [`Rig::look`]: the other vertex
/// attributes of those primitives (UVs, colours, normals, custom `_NAME` ones; not tangents), their materials, and
/// the file's materials, textures, samplers and images (image files beside the model are read
/// under the same rules as buffers, and embedded when written).
///
/// Morph targets are kept in the look and their default weights applied to the rest shape
/// (see `morph.rs`). Handled and reported in [`Rig::report`]: weights not summing to 1
/// (normalised; an all-zero vertex is bound to its first joint), morph-weight channels (not
/// played), meshes without a skin (moved rigidly by their node), non-triangle primitives
/// (skipped). Typed errors: a truncated or corrupt file, accessors reaching past their
/// buffers, joint indices past the skin, negative or non-finite weights,
/// non-finite or non-decomposable transforms, keyframe times that do not increase,
/// non-finite keyframes.
///
/// # Errors
/// [`SkinError`] as above.
pub fn parse_gltf(bytes: &[u8], name: &str, base: Option<&Path>) -> Result<Rig, SkinError> {
    parse_gltf_with(bytes, name, base, &GltfReadOptions::default())
}

/// [`parse_gltf`] with explicit [`GltfReadOptions`]: external buffers are read only inside
/// `base` unless allowed, never past their declared `byteLength`, and within the byte limit.
///
/// # Errors
/// As [`parse_gltf`].
pub fn parse_gltf_with(
    bytes: &[u8],
    name: &str,
    base: Option<&Path>,
    options: &GltfReadOptions,
) -> Result<Rig, SkinError> {
    let gltf_error = |message: String| SkinError::Gltf {
        name: name.to_string(),
        message,
    };
    super::glb_container::check_glb_header(bytes).map_err(gltf_error)?;
    // Every index is checked before the `gltf` crate follows one: its own validation indexes
    // the POSITION accessor unchecked (gltf-json 1.4, `mesh.rs`) and panics on a missing one.
    let raw =
        gltf::Gltf::from_slice_without_validation(bytes).map_err(|e| gltf_error(e.to_string()))?;
    super::index_check::check_indices(raw.document.as_json()).map_err(gltf_error)?;
    // A required extension this crate does not read is refused by name, before the `gltf`
    // crate's checks list its symptoms (a Draco primitive's accessors have no buffer view).
    super::compressed::check_required(raw.document.as_json()).map_err(|message| {
        SkinError::Unsupported {
            name: name.to_string(),
            message,
        }
    })?;
    validate(raw.document.as_json()).map_err(gltf_error)?;
    let gltf = gltf::Gltf {
        document: gltf::Document::from_json_without_validation(raw.document.into_json()),
        blob: raw.blob,
    };
    let buffers = Buffers::load(&gltf.document, gltf.blob.as_deref(), base, name, options)?;
    let doc = &gltf.document;
    let mut report = LoadReport::default();
    let nodes = read_nodes(doc, &mut report.notes)?;
    let instances = mesh_instances(doc, &mut report, name)?;
    let (joints, inverse_bind, remaps) =
        gather_joints(doc, &buffers, &instances, name, &mut report)?;
    let mut mesh = Mesh::new(Vec::new(), Vec::new());
    let mut primitives = Vec::new();
    let mut attributes = Vec::new();
    let mut materials = Vec::new();
    let quantized = doc.extensions_used().any(|e| e == "KHR_mesh_quantization");
    let mut rows = Vec::with_capacity(instances.len());
    // Morph targets are numbered per mesh instance (node, mesh): its first target's number.
    let mut target_offsets = std::collections::HashMap::new();
    let mut morph_weights = Vec::new();
    for &(mesh_index, prim_index, node, binding) in &instances {
        let m = doc
            .meshes()
            .nth(mesh_index)
            .expect("index from the document");
        let p = m
            .primitives()
            .nth(prim_index)
            .expect("index from the document");
        let remap = &remaps[&binding];
        let (info, primitive_rows) =
            read_primitive(&p, &buffers, name, quantized, remap, &mut mesh)?;
        rows.push(primitive_rows);
        let mut kept =
            primitive_attributes(&p, info.vertex_count, &buffers, name, &mut report.notes)?;
        let first = *target_offsets.entry((node, mesh_index)).or_insert_with(|| {
            let n = doc.nodes().nth(node).expect("index from the document");
            let weights = morph::default_weights(&n, &m, p.morph_targets().count());
            morph_weights.extend(weights);
            morph_weights.len() - p.morph_targets().count()
        });
        let targets = morph::primitive_targets(&p, first, info.vertex_count, &buffers, name)?;
        let range = info.vertex_offset..info.vertex_offset + info.vertex_count;
        morph::displace(&mut mesh.positions[range], &targets, &morph_weights, 1.0);
        kept.extend(targets);
        attributes.push((info.vertex_count, kept));
        materials.push(p.material().index());
        primitives.push(PrimitiveInfo {
            node,
            mesh: mesh_index,
            primitive: prim_index,
            ..info
        });
    }
    let influences = Influences::padded(rows);
    let animations = read_animations(doc, &buffers, name, &mut report)?;
    let mut look = read_look(bytes, doc, &buffers, base, options, &mut report.notes);
    look.attributes = merge_attributes(attributes, &mut report.notes);
    look.morph_weights = morph_weights;
    look.flat = look.attribute("NORMAL").is_none();
    look.primitive_materials = materials;
    let mut rig = Rig::new(
        nodes,
        joints,
        inverse_bind,
        mesh,
        influences,
        primitives,
        animations,
        report,
    )?;
    rig.look = look;
    Ok(rig)
}

/// The `gltf` crate's schema checks, less two it makes where this crate knows better: an
/// accessor without a buffer view (glTF 2.0 allows it: zeros, sparse values, or the values of
/// a Draco-compressed primitive) and the required extensions it does not know
/// ([`super::compressed::check_required`] has checked them).
fn validate(root: &gltf::json::Root) -> Result<(), String> {
    use gltf::json::validation::{Error, Validate};
    let mut errors = Vec::new();
    root.validate(root, gltf::json::Path::new, &mut |path, error| {
        let path = path().to_string();
        let allowed = (path.starts_with("accessors[")
            && path.ends_with("].bufferView")
            && matches!(error, Error::Missing))
            || path.starts_with("extensionsRequired")
            || path.starts_with("extensionsUsed");
        if !allowed {
            errors.push(format!("{path}: {error}"));
        }
    });
    if errors.is_empty() {
        return Ok(());
    }
    let more = errors.len().saturating_sub(5);
    errors.truncate(5);
    let mut message = format!("invalid glTF: {}", errors.join("; "));
    if more > 0 {
        message.push_str(&format!(" (and {more} more)"));
    }
    Ok(()).and(Err(message))
}

/// Every node with its parent and rest transform.
/// A node matrix that is not `T R S` beyond rounding (glTF forbids it) is taken as its
/// decomposition, as three.js takes it, with a note.
fn read_nodes(doc: &gltf::Document, notes: &mut Vec<String>) -> Result<Vec<RigNode>, SkinError> {
    let mut nodes = Vec::new();
    for n in doc.nodes() {
        let what = format!("node {}", n.index());
        let rest = match n.transform() {
            gltf::scene::Transform::Matrix { matrix } => {
                let m = DMat4::from_cols_array_2d(&matrix.map(|c| c.map(f64::from)));
                let (trs, residual) = Trs::decompose(&m, &what)?;
                if residual > super::trs::DECOMPOSITION_NOISE {
                    notes.push(format!(
                        "{what}: its matrix is not translation * rotation * scale (it differs \
                         from its decomposition by {residual:.1e} of its largest entry); taken \
                         as the decomposition, as three.js takes it"
                    ));
                }
                trs
            }
            gltf::scene::Transform::Decomposed {
                translation,
                rotation,
                scale,
            } => {
                let trs = Trs {
                    translation: DVec3::from(translation.map(f64::from)),
                    rotation: DQuat::from_array(rotation.map(f64::from)),
                    scale: DVec3::from(scale.map(f64::from)),
                };
                let q = trs.rotation.length();
                // Values beyond the f32 range arrive as infinities: refused, as is a rotation
                // whose norm is not a finite positive number.
                if !trs.translation.is_finite()
                    || !trs.scale.is_finite()
                    || !trs.rotation.is_finite()
                    || !q.is_finite()
                    || q <= 1e-12
                {
                    return Err(SkinError::BadTransform {
                        what,
                        message: "non-finite or zero TRS".into(),
                    });
                }
                Trs {
                    rotation: trs.rotation / q,
                    ..trs
                }
            }
        };
        nodes.push(RigNode {
            name: n.name().map_or_else(|| what.clone(), str::to_string),
            parent: None,
            rest,
        });
    }
    for n in doc.nodes() {
        for c in n.children() {
            let child = &mut nodes[c.index()];
            if child.parent.is_some_and(|p| p != n.index()) {
                return Err(SkinError::BadTransform {
                    what: format!("node {}", c.index()),
                    message: "has more than one parent".into(),
                });
            }
            child.parent = Some(n.index());
        }
    }
    Ok(nodes)
}

/// What binds a primitive's vertices: a skin, or (a mesh without one) its node alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum Binding {
    /// Skin `k`: the vertices' `JOINTS_n` index its joints.
    Skin(usize),
    /// A mesh without a skin, moved rigidly by node `n` (as viewers show it).
    Rigid(usize),
}

/// A triangle primitive as `(mesh, primitive, node, binding)`.
type Instance = (usize, usize, usize, Binding);

/// Every triangle primitive of every node with a mesh, in order of mesh, primitive, node:
/// skinned ones bound by their skin, the others rigidly by their node (so that a scene reads
/// as viewers show it: a helmet parented to a head bone moves with it).
fn mesh_instances(
    doc: &gltf::Document,
    report: &mut LoadReport,
    name: &str,
) -> Result<Vec<Instance>, SkinError> {
    let mut uses: Vec<Instance> = Vec::new();
    for n in doc.nodes() {
        let Some(m) = n.mesh() else { continue };
        let binding = match n.skin() {
            Some(s) => Binding::Skin(s.index()),
            None => Binding::Rigid(n.index()),
        };
        for p in m.primitives() {
            if p.mode() != gltf::mesh::Mode::Triangles {
                report.notes.push(format!(
                    "mesh {} primitive {}: mode {:?} is not triangles (skipped)",
                    m.index(),
                    p.index(),
                    p.mode()
                ));
                continue;
            }
            uses.push((m.index(), p.index(), n.index(), binding));
        }
    }
    uses.sort_unstable();
    if !uses.iter().any(|u| matches!(u.3, Binding::Skin(_))) {
        return Err(SkinError::NoSkin(format!(
            "{name}: no skinned triangle mesh"
        )));
    }
    let rigid = uses
        .iter()
        .filter(|u| matches!(u.3, Binding::Rigid(_)))
        .count();
    if rigid > 0 {
        report.notes.push(format!(
            "{rigid} primitive(s) of meshes without a skin are bound rigidly to their node"
        ));
    }
    Ok(uses)
}

/// The rig's joints: every skin's joints, merged (a node bound by several skins with the same
/// inverse bind matrix, to single precision, is one joint), then the nodes of rigid meshes
/// (inverse bind the identity: their vertices are in the node's frame). Returns the joints,
/// their inverse bind matrices, and per binding the map from its joint indices to the rig's.
#[allow(clippy::type_complexity)]
fn gather_joints(
    doc: &gltf::Document,
    buffers: &Buffers,
    instances: &[Instance],
    name: &str,
    report: &mut LoadReport,
) -> Result<(Vec<usize>, Vec<DMat4>, HashMap<Binding, Vec<u32>>), SkinError> {
    let mut bindings: Vec<Binding> = instances.iter().map(|u| u.3).collect();
    bindings.sort_unstable();
    bindings.dedup();
    let mut joints: Vec<usize> = Vec::new();
    let mut inverse_bind: Vec<DMat4> = Vec::new();
    let mut remaps = HashMap::new();
    let mut add = |node: usize, ibm: DMat4| -> u32 {
        let same = |k: &usize| {
            joints[*k] == node && {
                let scale = ibm
                    .abs()
                    .to_cols_array()
                    .iter()
                    .fold(1.0f64, |a, &b| a.max(b));
                (inverse_bind[*k] - ibm)
                    .abs()
                    .to_cols_array()
                    .iter()
                    .all(|d| *d <= 1e-6 * scale)
            }
        };
        if let Some(k) = (0..joints.len()).find(same) {
            return k as u32;
        }
        joints.push(node);
        inverse_bind.push(ibm);
        (joints.len() - 1) as u32
    };
    let mut skins = 0;
    for &b in &bindings {
        let remap: Vec<u32> = match b {
            Binding::Skin(k) => {
                skins += 1;
                let skin = doc.skins().nth(k).expect("index from the document");
                let nodes: Vec<usize> = skin.joints().map(|n| n.index()).collect();
                let ibms = skin_inverse_binds(&skin, nodes.len(), buffers, name)?;
                nodes.iter().zip(ibms).map(|(&n, m)| add(n, m)).collect()
            }
            Binding::Rigid(n) => vec![add(n, DMat4::IDENTITY)],
        };
        remaps.insert(b, remap);
    }
    if skins > 1 {
        report.notes.push(format!(
            "{skins} skins merged into one list of {} joints",
            joints.len()
        ));
    }
    Ok((joints, inverse_bind, remaps))
}

/// A skin's inverse bind matrices (the identity where the file gives none, as the
/// specification says).
fn skin_inverse_binds(
    skin: &gltf::Skin,
    count: usize,
    buffers: &Buffers,
    name: &str,
) -> Result<Vec<DMat4>, SkinError> {
    let Some(a) = skin.inverse_bind_matrices() else {
        return Ok(vec![DMat4::IDENTITY; count]);
    };
    let (v, _) = buffers.read_as(&a, name, &Layout::INVERSE_BIND)?;
    if v.len() < 16 * count {
        return Err(SkinError::Data {
            name: name.to_string(),
            message: format!(
                "skin {}: {} inverse bind values for {count} joints",
                skin.index(),
                v.len()
            ),
        });
    }
    let m: Vec<DMat4> = v
        .chunks_exact(16)
        .take(count)
        .map(DMat4::from_cols_slice)
        .collect();
    if let Some(j) = m.iter().position(|m| !m.is_finite()) {
        return Err(SkinError::BadTransform {
            what: format!("skin {} inverse bind matrix of joint {j}", skin.index()),
            message: "not finite".into(),
        });
    }
    Ok(m)
}

/// Every animation's node channels.
fn read_animations(
    doc: &gltf::Document,
    buffers: &Buffers,
    name: &str,
    report: &mut LoadReport,
) -> Result<Vec<Animation>, SkinError> {
    let mut out = Vec::new();
    for a in doc.animations() {
        let aname = a
            .name()
            .map_or_else(|| format!("animation {}", a.index()), str::to_string);
        let mut channels = Vec::new();
        for (ci, c) in a.channels().enumerate() {
            let what = format!("animation {aname:?} channel {ci}");
            let property = match c.target().property() {
                gltf::animation::Property::Translation => Property::Translation,
                gltf::animation::Property::Rotation => Property::Rotation,
                gltf::animation::Property::Scale => Property::Scale,
                gltf::animation::Property::MorphTargetWeights => {
                    report.notes.push(format!(
                        "{what}: animated morph target weights are not played or written \
                         (the targets are kept, at their default weights)"
                    ));
                    continue;
                }
            };
            let s = c.sampler();
            let interpolation = match s.interpolation() {
                gltf::animation::Interpolation::Linear => Interpolation::Linear,
                gltf::animation::Interpolation::Step => Interpolation::Step,
                gltf::animation::Interpolation::CubicSpline => Interpolation::CubicSpline,
            };
            let keys = match property {
                Property::Rotation => &Layout::ROTATION_KEYS,
                _ => &Layout::VECTOR_KEYS,
            };
            let (times, _) = buffers.read_as(&s.input(), name, &Layout::TIMES)?;
            let (v, dim) = buffers.read_as(&s.output(), name, keys)?;
            let values = v
                .chunks_exact(dim)
                .map(|c| {
                    if dim == 4 {
                        DVec4::from_slice(c)
                    } else {
                        DVec3::from_slice(c).extend(0.0)
                    }
                })
                .collect();
            channels.push(Channel::new(
                c.target().node().index(),
                property,
                interpolation,
                times,
                values,
                &what,
            )?);
        }
        out.push(Animation {
            name: aname,
            channels,
        });
    }
    Ok(out)
}
