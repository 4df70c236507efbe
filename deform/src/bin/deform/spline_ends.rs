//! The ends of a spline deformer on a mesh: the first and last selection groups (H_1 and
//! H_n).

use anyhow::{bail, Result};
use deform::input::Selection;
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
