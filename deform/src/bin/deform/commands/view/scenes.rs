//! What the editor opens: the demo's procedural scenes (no files needed) and the model named
//! on the command line, each with the method it starts with.

use deform::shapes::{icosphere, tube, tube_ring};
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
}

impl Method {
    pub const ALL: [Method; 3] = [Method::Handles, Method::Arap, Method::Spline];

    pub fn name(self) -> &'static str {
        match self {
            Method::Handles => "handles",
            Method::Arap => "arap",
            Method::Spline => "spline",
        }
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

/// The demo scenes: motor handles on a sphere, an ARAP beam, a spline bar and the rigged arm
/// (animated, for skinning and surgery).
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
            },
        ),
        scene(
            "beam",
            Content::Mesh {
                mesh: beam,
                groups: vec![tube_ring(6, 0), tube_ring(6, 40)],
                method: Method::Arap,
            },
        ),
        scene(
            "bar",
            Content::Mesh {
                mesh: bar,
                groups: vec![tube_ring(16, 0), tube_ring(16, 20), tube_ring(16, 40)],
                method: Method::Spline,
            },
        ),
        scene("arm", Content::Rig(Box::new(procedural_arm(24, 81)))),
    ]
}
