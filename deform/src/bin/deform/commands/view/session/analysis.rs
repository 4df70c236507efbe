//! The harmonic system of the session's mesh, analysed once (`SystemAnalysis`) and kept while
//! the mesh stays the same, so that a new handle selection binds with the numeric
//! factorisation and the solves only.

use anyhow::Result;
use deform::operators::harmonic::{harmonic_system, HarmonicOptions};
use deform::operators::solve::SystemAnalysis;
use deform::Mesh;
use std::hash::{Hash, Hasher};

/// The analysis and the mesh (positions, triangles, options) it was made for.
#[derive(Default)]
pub(super) struct Analysed {
    key: Option<u64>,
    analysis: Option<SystemAnalysis>,
}

/// A fingerprint of everything the system matrix depends on.
fn fingerprint(mesh: &Mesh, options: &HarmonicOptions) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for p in &mesh.positions {
        p.to_array().map(f64::to_bits).hash(&mut h);
    }
    mesh.triangles.hash(&mut h);
    format!("{options:?}").hash(&mut h);
    h.finish()
}

impl Analysed {
    /// The analysis of `mesh`'s harmonic system, made now if the mesh changed since.
    pub(super) fn of(&mut self, mesh: &Mesh, options: &HarmonicOptions) -> Result<&SystemAnalysis> {
        let key = fingerprint(mesh, options);
        if self.key != Some(key) || self.analysis.is_none() {
            self.analysis = None;
            let q = harmonic_system(mesh, options)?;
            self.analysis = Some(SystemAnalysis::new(&q)?);
            self.key = Some(key);
        }
        Ok(self.analysis.as_ref().expect("made above"))
    }
}
