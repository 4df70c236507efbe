//! The procedural scenes the demo and the editor open (no files needed): a mesh with its
//! handle groups and the method it starts with, or a rigged arm. The demo poses its own keys
//! on the same meshes.

use super::error::{MethodError, MethodsError};
use super::method::Method;
use crate::mesh::shapes::{icosphere, tube, tube_ring};
use crate::mesh::Mesh;
use crate::skinning::{procedural_arm, Rig};
use glam::DVec3;
use std::sync::Arc;

/// A scene's content.
pub enum Content {
    /// A mesh with its starting handle groups and method.
    Mesh {
        /// The mesh.
        mesh: Mesh,
        /// The handle groups (vertex indices).
        groups: Vec<Vec<u32>>,
        /// The method it opens with.
        method: Method,
        /// A cage around the mesh (for [`Method::Cage`]).
        cage: Option<Mesh>,
    },
    /// A skinned rig (animations, joints, surgery).
    Rig(Box<Rig>),
}

/// A named scene; cloning shares the content.
#[derive(Clone)]
pub struct Scene {
    /// Its name.
    pub name: String,
    /// Its mesh or rig.
    pub content: Arc<Content>,
}

impl Scene {
    /// A scene named `name`.
    pub fn new(name: &str, content: Content) -> Scene {
        Scene {
            name: name.into(),
            content: Arc::new(content),
        }
    }

    /// A mesh scene without groups, opened with motor handles.
    pub fn mesh(name: &str, mesh: Mesh) -> Scene {
        let (groups, cage) = (Vec::new(), None);
        let method = Method::Handles;
        Scene::new(
            name,
            Content::Mesh {
                mesh,
                groups,
                method,
                cage,
            },
        )
    }
}

impl Scene {
    /// The scene of a model file, named by its file name: a rig for glTF (`.gltf`, `.glb`,
    /// buffers inside its folder) or a mesh with `libigl`'s skeleton and weights; else a mesh
    /// (checked for deformation) with the handle groups of `select`, opened with motor
    /// handles.
    ///
    /// # Errors
    /// What the readers refuse, naming the file; a selection given with a rig.
    pub fn from_model(
        path: &std::path::Path,
        libigl: Option<(&std::path::Path, &std::path::Path)>,
        select: Option<&std::path::Path>,
    ) -> Result<Scene, MethodsError> {
        let name = path
            .file_name()
            .map_or("model".into(), |n| n.to_string_lossy().into_owned());
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        let gltf = ext.eq_ignore_ascii_case("gltf") || ext.eq_ignore_ascii_case("glb");
        if gltf || libigl.is_some() {
            if select.is_some() {
                let message = "a selection is for a mesh; a rig's joints are its handles";
                return Err(MethodError::Refused(message.into()).into());
            }
            let options = crate::skinning::GltfReadOptions::default();
            let rig = crate::skinning::read_rig(path, libigl, &options)?;
            return Ok(Scene::new(&name, Content::Rig(Box::new(rig))));
        }
        let mesh = crate::mesh::io::read_mesh(path)?;
        crate::mesh::validate::check_solvable(&mesh)?;
        let groups = match select {
            Some(s) => crate::input::read_selection(s, mesh.vertex_count())?.groups,
            None => Vec::new(),
        };
        let (method, cage) = (Method::Handles, None);
        Ok(Scene::new(
            &name,
            Content::Mesh {
                mesh,
                groups,
                method,
                cage,
            },
        ))
    }
}

/// The vertices of `mesh` with `dir . p > cos` (for a sphere about the origin: a cap).
pub fn cap(mesh: &Mesh, dir: DVec3, cos: f64) -> Vec<u32> {
    (0..mesh.vertex_count() as u32)
        .filter(|&v| mesh.positions[v as usize].normalize_or_zero().dot(dir) > cos)
        .collect()
}

/// The unit icosphere (subdivided 4 times) and its bottom, top and +x caps.
pub fn sphere_with_caps() -> (Mesh, Vec<Vec<u32>>) {
    let ball = icosphere(1.0, 4);
    let caps = [-DVec3::Y, DVec3::Y, DVec3::X].map(|d| cap(&ball, d, 0.85));
    (ball, caps.to_vec())
}

/// A hexagonal beam of radius 1 and length 10 along +x (41 rings) and its two end rings.
pub fn beam_with_ends() -> (Mesh, Vec<Vec<u32>>) {
    (
        tube(1.0, 10.0, 6, 41),
        vec![tube_ring(6, 0), tube_ring(6, 40)],
    )
}

/// A round bar of radius 1 and length 10 along +x (16 sides, 41 rings).
pub fn bar() -> Mesh {
    tube(1.0, 10.0, 16, 41)
}

/// A square tube of 6 rings around [`bar`], from x = -1 to 11 (the cage scenes' cage).
pub fn bar_cage() -> Mesh {
    let mut c = tube(1.6, 12.0, 4, 6);
    c.positions.iter_mut().for_each(|p| p.x -= 1.0);
    c
}

/// The scenes: motor handles on a sphere, an ARAP beam, a spline bar, a bar in an FFD
/// lattice and one in a cage, and the rigged arm (animated, for skinning and surgery).
pub fn catalogue() -> Vec<Scene> {
    let (ball, caps) = sphere_with_caps();
    let mesh = |mesh, groups, method, cage| Content::Mesh {
        mesh,
        groups,
        method,
        cage,
    };
    let (beam, beam_ends) = beam_with_ends();
    let bar_keys = vec![tube_ring(16, 0), tube_ring(16, 20), tube_ring(16, 40)];
    vec![
        Scene::new("sphere", mesh(ball, caps, Method::Handles, None)),
        Scene::new("beam", mesh(beam, beam_ends, Method::Arap, None)),
        Scene::new("bar", mesh(bar(), bar_keys, Method::Spline, None)),
        Scene::new("lattice", mesh(bar(), Vec::new(), Method::Ffd, None)),
        Scene::new(
            "cage",
            mesh(bar(), Vec::new(), Method::Cage, Some(bar_cage())),
        ),
        Scene::new("arm", Content::Rig(Box::new(procedural_arm(24, 81)))),
    ]
}
