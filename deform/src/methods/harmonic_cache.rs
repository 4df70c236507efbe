//! What binds share: the harmonic analysis of a mesh kept between binds ([`HarmonicCache`])
//! and the centres of handle groups.

use super::error::MethodsError;
use crate::mesh::Mesh;
use crate::operators::harmonic::{harmonic_system, HarmonicOptions};
use crate::operators::solve::SystemAnalysis;
use glam::DVec3;
use std::hash::{Hash, Hasher};

type Result<T> = std::result::Result<T, MethodsError>;

/// The harmonic system's analysis of one mesh, kept while the mesh and options stay the same,
/// so that a new handle selection binds with the numeric factorisation and the solves only.
#[derive(Default)]
pub struct HarmonicCache {
    key: Option<u64>,
    analysis: Option<SystemAnalysis>,
}

impl HarmonicCache {
    /// The analysis of `mesh`'s harmonic system, made now if the mesh or options changed.
    pub fn of(&mut self, mesh: &Mesh, options: &HarmonicOptions) -> Result<&SystemAnalysis> {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        for p in &mesh.positions {
            p.to_array().map(f64::to_bits).hash(&mut h);
        }
        mesh.triangles.hash(&mut h);
        format!("{options:?}").hash(&mut h);
        let key = h.finish();
        if self.key != Some(key) || self.analysis.is_none() {
            self.analysis = None;
            let q = harmonic_system(mesh, options)?;
            self.analysis = Some(SystemAnalysis::new(&q)?);
            self.key = Some(key);
        }
        Ok(self.analysis.as_ref().expect("made above"))
    }
}

/// The centre of each group (the mean of its vertices).
pub fn group_centres(mesh: &Mesh, groups: &[Vec<u32>]) -> Vec<DVec3> {
    groups
        .iter()
        .map(|g| {
            let sum: DVec3 = g.iter().map(|&v| mesh.positions[v as usize]).sum();
            sum / g.len().max(1) as f64
        })
        .collect()
}
