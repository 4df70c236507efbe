//! What the editor opens: the demo's procedural scenes (no files needed) and the model named
//! on the command line, each with the method it starts with.

use deform::mesh::shapes::{icosphere, tube, tube_ring};
use deform::skinning::{procedural_arm, Rig};
use deform::Mesh;
use glam::DVec3;
use std::sync::Arc;

/// How a mesh scene is deformed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Motor handles on harmonic coordinates.
    Handles,
    /// ARAP with rotors, groups as handles.
    Arap,
    /// Spline-aligned deformation, groups as keys (the first and last bound the spine).
    Spline,
    /// Free-form deformation: a motor per point of a lattice over the mesh's box.
    Ffd,
    /// A motor per vertex of the scene's cage (mean value coordinates).
    Cage,
}

impl Method {
    pub const ALL: [Method; 5] = [
        Method::Handles,
        Method::Arap,
        Method::Spline,
        Method::Ffd,
        Method::Cage,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Method::Handles => "handles",
            Method::Arap => "arap",
            Method::Spline => "spline",
            Method::Ffd => "ffd",
            Method::Cage => "cage",
        }
    }

    /// Whether its keys are control points (a lattice's or a cage's), not painted groups.
    pub fn controls(self) -> bool {
        matches!(self, Method::Ffd | Method::Cage)
    }

    pub fn parse(name: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == name)
    }
}

/// A scene's content.
pub enum Content {
    /// A mesh with its starting handle groups and method.
    Mesh {
        mesh: Mesh,
        groups: Vec<Vec<u32>>,
        method: Method,
        /// A cage around the mesh (for [`Method::Cage`]).
        cage: Option<Mesh>,
    },
    /// A skinned rig (animations, joints, surgery).
    Rig(Box<Rig>),
}

/// A named scene.
#[derive(Clone)]
pub struct Scene {
    pub name: String,
    pub content: Arc<Content>,
}

/// The vertices of `mesh` with `dir . p > cos`.
fn cap(mesh: &Mesh, dir: DVec3, cos: f64) -> Vec<u32> {
    (0..mesh.vertex_count() as u32)
        .filter(|&v| mesh.positions[v as usize].normalize_or_zero().dot(dir) > cos)
        .collect()
}

fn scene(name: &str, content: Content) -> Scene {
    Scene {
        name: name.into(),
        content: Arc::new(content),
    }
}

/// A square tube of 6 rings around the 10-long bar (the demo's cage).
fn bar_cage() -> Mesh {
    let mut c = tube(1.6, 12.0, 4, 6);
    c.positions.iter_mut().for_each(|p| p.x -= 1.0);
    c
}

/// The demo scenes: motor handles on a sphere, an ARAP beam, a spline bar, a bar in an FFD
/// lattice and one in a cage, and the rigged arm (animated, for skinning and surgery).
pub fn demo_scenes() -> Vec<Scene> {
    let ball = icosphere(1.0, 4);
    let sphere_groups = vec![
        cap(&ball, -DVec3::Y, 0.85),
        cap(&ball, DVec3::Y, 0.85),
        cap(&ball, DVec3::X, 0.85),
    ];
    let beam = tube(1.0, 10.0, 6, 41);
    let bar = tube(1.0, 10.0, 16, 41);
    vec![
        scene(
            "sphere",
            Content::Mesh {
                mesh: ball,
                groups: sphere_groups,
                method: Method::Handles,
                cage: None,
            },
        ),
        scene(
            "beam",
            Content::Mesh {
                mesh: beam,
                groups: vec![tube_ring(6, 0), tube_ring(6, 40)],
                method: Method::Arap,
                cage: None,
            },
        ),
        scene(
            "bar",
            Content::Mesh {
                mesh: bar,
                groups: vec![tube_ring(16, 0), tube_ring(16, 20), tube_ring(16, 40)],
                method: Method::Spline,
                cage: None,
            },
        ),
        scene(
            "lattice",
            Content::Mesh {
                mesh: tube(1.0, 10.0, 16, 41),
                groups: Vec::new(),
                method: Method::Ffd,
                cage: None,
            },
        ),
        scene(
            "cage",
            Content::Mesh {
                mesh: tube(1.0, 10.0, 16, 41),
                groups: Vec::new(),
                method: Method::Cage,
                cage: Some(bar_cage()),
            },
        ),
        scene("arm", Content::Rig(Box::new(procedural_arm(24, 81)))),
    ]
}
