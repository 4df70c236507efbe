//! Lattices and cages in the editor: the mesh bound to control points (an FFD lattice over its
//! box, or the scene's cage), one motor per control point, and the lines the page draws
//! between the points.

use anyhow::Result;
use deform::cage::{CageDeformer, CageOptions};
use deform::control::ControlForm;
use deform::ffd::{Ffd, FfdOptions};
use deform::{Deformer, Mesh};
use glam::DVec3;
use std::collections::BTreeSet;

/// The lattice of a mesh without a cage: 4 x 3 x 3 control points over its box.
pub const LATTICE: [usize; 3] = [4, 3, 3];

/// A mesh bound to control points.
pub struct Controls {
    pub deformer: Box<dyn Deformer>,
    /// The control points at rest (the page's gizmos turn about them).
    pub points: Vec<DVec3>,
    /// Pairs of points the page joins with a line.
    pub edges: Vec<[u32; 2]>,
}

/// Bind `mesh` to an FFD lattice over its box.
pub fn lattice(mesh: &Mesh, form: ControlForm) -> Result<Controls> {
    let options = FfdOptions {
        form,
        ..FfdOptions::default()
    };
    let ffd = Ffd::bind(mesh, LATTICE, None, options)?;
    let l = ffd.lattice();
    let [a, b, c] = l.dims();
    let mut edges = Vec::new();
    for w in 0..c {
        for v in 0..b {
            for u in 0..a {
                let i = l.index(u, v, w) as u32;
                for (du, dv, dw) in [(1, 0, 0), (0, 1, 0), (0, 0, 1)] {
                    if u + du < a && v + dv < b && w + dw < c {
                        edges.push([i, l.index(u + du, v + dv, w + dw) as u32]);
                    }
                }
            }
        }
    }
    Ok(Controls {
        points: l.rest_points(),
        edges,
        deformer: Box::new(ffd),
    })
}

/// Bind `mesh` to its `cage` (mean value coordinates).
pub fn cage(mesh: &Mesh, cage: &Mesh, form: ControlForm) -> Result<Controls> {
    let options = CageOptions {
        form,
        ..CageOptions::default()
    };
    let deformer = CageDeformer::bind(mesh, cage, options)?;
    let edges: BTreeSet<[u32; 2]> = cage
        .triangles
        .iter()
        .flat_map(|t| (0..3).map(move |k| [t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3])]))
        .collect();
    Ok(Controls {
        points: cage.positions.clone(),
        edges: edges.into_iter().collect(),
        deformer: Box::new(deformer),
    })
}
