//! Cage validation: a cage must be a closed, edge-manifold triangle mesh with finite
//! coordinates and no degenerate (zero-area) faces.

use super::CageError;
use crate::deformers::Result;
use crate::mesh::IndexList;
use crate::mesh::Mesh;
use std::collections::HashMap;

/// Faces whose area is below this fraction of the squared bounding-box diagonal are
/// degenerate.
pub const DEGENERATE_AREA: f64 = 1e-14;

/// Check that `cage` can carry coordinates: at least 4 vertices and 4 faces, finite
/// coordinates, face indices in range, every edge shared by exactly two faces (closed,
/// edge-manifold), no face of (numerically) zero area, no faces crossing each other
/// ([`super::intersect::self_intersections`]).
///
/// # Errors
/// The [`CageError`] naming the offending vertices or faces.
pub fn check_cage(cage: &Mesh) -> Result<()> {
    check_cage_with(cage, false)
}

/// [`check_cage`], skipping the self-intersection test when `allow_self_intersecting`.
///
/// # Errors
/// As [`check_cage`].
pub fn check_cage_with(cage: &Mesh, allow_self_intersecting: bool) -> Result<()> {
    check_cage_elements(cage)?;
    let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
    for t in &cage.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *edges.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let pick = |pred: &dyn Fn(u32) -> bool| -> IndexList {
        let mut v: Vec<u32> = edges
            .iter()
            .filter(|(_, &c)| pred(c))
            .flat_map(|(&(a, b), _)| [a, b])
            .collect();
        v.sort_unstable();
        v.dedup();
        v.into()
    };
    let open = pick(&|c| c == 1);
    if !open.0.is_empty() {
        return Err(CageError::Open { vertices: open }.into());
    }
    let shared = pick(&|c| c > 2);
    if !shared.0.is_empty() {
        return Err(CageError::NonManifold { vertices: shared }.into());
    }
    let diag = cage.bounding_box().map_or(0.0, |b| b.diagonal());
    let floor = DEGENERATE_AREA * diag * diag;
    let bad: Vec<u32> = (0..cage.triangle_count())
        .filter(|&f| {
            let [a, b, c] = cage.corners(f);
            let area = 0.5 * (b - a).cross(c - a).length();
            area.is_nan() || area <= floor
        })
        .map(|f| f as u32)
        .collect();
    if !bad.is_empty() {
        return Err(CageError::Degenerate { faces: bad.into() }.into());
    }
    if allow_self_intersecting {
        return Ok(());
    }
    let crossing = super::intersect::self_intersections(cage, usize::MAX);
    if let Some(&first) = crossing.first() {
        return Err(CageError::SelfIntersecting {
            pairs: crossing.len(),
            first,
        }
        .into());
    }
    Ok(())
}

/// The part of [`check_cage`] that every reader of a cage's faces needs first (mean value
/// coordinates too): at least 4 vertices and 4 faces, finite vertices, faces in range with
/// three distinct corners.
pub(crate) fn check_cage_elements(cage: &Mesh) -> Result<()> {
    let n = cage.vertex_count();
    if n < 4 || cage.triangle_count() < 4 {
        return Err(CageError::TooSmall {
            vertices: n,
            faces: cage.triangle_count(),
        }
        .into());
    }
    let bad: Vec<u32> = (0..n as u32)
        .filter(|&i| !cage.positions[i as usize].is_finite())
        .collect();
    if !bad.is_empty() {
        return Err(CageError::NonFinite {
            vertices: bad.into(),
        }
        .into());
    }
    let bad: Vec<u32> = (0..cage.triangle_count() as u32)
        .filter(|&f| {
            let t = cage.triangles[f as usize];
            t.iter().any(|&v| v as usize >= n) || t[0] == t[1] || t[1] == t[2] || t[0] == t[2]
        })
        .collect();
    if !bad.is_empty() {
        return Err(CageError::BadFaces { faces: bad.into() }.into());
    }
    Ok(())
}
