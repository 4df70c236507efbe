//! One demo scene's result, as the lattice and surgery scenes hand it to the demo.

use deform::render::preview::Look;
use deform::Mesh;
use glam::DVec3;

/// One scene's meshes and times.
pub struct DemoScene {
    pub name: &'static str,
    pub method: String,
    pub rest: Mesh,
    pub posed: Vec<DVec3>,
    pub scalar: Vec<f64>,
    pub bind_ms: f64,
    pub pose_ms: f64,
    /// The preview's scalar name, overlays and focus (its title is the demo's).
    pub look: Look,
}
