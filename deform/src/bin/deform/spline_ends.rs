//! The ends of a spline deformer on a mesh: the first and last selection groups (H_1 and
//! H_n), and the straight chain of joints between them.

use anyhow::{bail, Result};
use deform::input::Selection;
use deform::Mesh;
use glam::DVec3;
use std::path::Path;

/// The first and last groups of a selection, for the spline deformers.
pub fn ends(sel: &Selection, name: &Path) -> Result<(Vec<u32>, Vec<u32>)> {
    if sel.groups.len() < 2 {
        bail!(
            "{}: a spline needs at least two groups (0 = H_1, highest = H_n), found {}",
            name.display(),
            sel.groups.len()
        );
    }
    Ok((
        sel.groups[0].clone(),
        sel.groups[sel.groups.len() - 1].clone(),
    ))
}

/// A straight chain of `n` joints from the centroid of `a` to the centroid of `b`.
pub fn straight_chain(mesh: &Mesh, a: &[u32], b: &[u32], n: usize) -> Vec<DVec3> {
    let centroid =
        |s: &[u32]| s.iter().map(|&v| mesh.positions[v as usize]).sum::<DVec3>() / s.len() as f64;
    let (p, q) = (centroid(a), centroid(b));
    (0..n)
        .map(|i| p.lerp(q, i as f64 / (n - 1) as f64))
        .collect()
}
