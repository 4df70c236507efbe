//! Lattices and cages in the editor: the mesh bound to control points (an FFD lattice over its
//! box, or the scene's cage), one motor per control point, and the lines the page draws
//! between the points. [`ControlChoice`] is what the page chooses: the lattice's size and
//! basis, the cage's coordinates.

use anyhow::{anyhow, bail, Result};
use deform::blend::control::{ControlForm, ControlScratch};
use deform::deformers::cage::{CageCoordinates, CageDeformer, CageOptions, HarmonicGrid};
use deform::deformers::ffd::{Ffd, FfdOptions, LatticeBasis};
use deform::{Deformer, Mesh};
use glam::DVec3;
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;

/// The lattice of a mesh without a cage, until the page asks for another: 4 x 3 x 3 control
/// points over its box.
pub const LATTICE: [usize; 3] = [4, 3, 3];

/// Control points per axis the page may ask for.
pub const LATTICE_AXIS: std::ops::RangeInclusive<usize> = 2..=8;

/// At most this many control points with Bernstein polynomials, where every point moves every
/// vertex (a pose blends them all; B-splines blend at most `(degree + 1)^3` per vertex).
pub const MAX_BERNSTEIN_POINTS: usize = 64;

/// Harmonic cage grids the page may ask for (nodes along the cage's longest side).
pub const GRID: std::ops::RangeInclusive<usize> = 16..=64;

/// The lattice and cage options of a `Request::Method` (the protocol's); each one given replaces the
/// session's.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ControlRequest {
    /// Control points per axis (each 2 to 8).
    #[serde(default)]
    pub lattice: Option<[usize; 3]>,
    /// `bernstein` or `bspline-1`, `bspline-2`, `bspline-3`.
    #[serde(default)]
    pub basis: Option<String>,
    /// The cage's `mean-value` or `harmonic` coordinates.
    #[serde(default)]
    pub coordinates: Option<String>,
    /// Harmonic coordinates' grid nodes along the cage's longest side (16 to 64).
    #[serde(default)]
    pub grid: Option<usize>,
}

/// A cage's coordinates, as the page names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Coordinates {
    MeanValue,
    Harmonic,
}

/// The lattice and cage options of a session.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ControlChoice {
    /// Control points per axis.
    pub lattice: [usize; 3],
    /// The lattice's basis (sent by its name: `bernstein`, `bspline-1` .. `bspline-3`).
    #[serde(serialize_with = "basis_name")]
    pub basis: LatticeBasis,
    /// The cage's coordinates.
    pub coordinates: Coordinates,
    /// Harmonic coordinates' grid nodes along the cage's longest side.
    pub grid: usize,
}

fn basis_name<S: serde::Serializer>(b: &LatticeBasis, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&b.name())
}

impl Default for ControlChoice {
    fn default() -> Self {
        ControlChoice {
            lattice: LATTICE,
            basis: LatticeBasis::Bernstein,
            coordinates: Coordinates::MeanValue,
            grid: 32,
        }
    }
}

impl ControlChoice {
    /// This choice with what `r` asks for changed, checked.
    pub fn with(self, r: &ControlRequest) -> Result<ControlChoice> {
        let mut c = self;
        if let Some(l) = r.lattice {
            if let Some(bad) = l.iter().find(|n| !LATTICE_AXIS.contains(*n)) {
                bail!(
                    "lattice: {bad} control points on an axis (each axis takes {} to {})",
                    LATTICE_AXIS.start(),
                    LATTICE_AXIS.end()
                );
            }
            c.lattice = l;
        }
        if let Some(b) = &r.basis {
            c.basis = LatticeBasis::parse(b).ok_or_else(|| {
                anyhow!("no lattice basis {b:?} (bernstein, bspline-1, bspline-2, bspline-3)")
            })?;
        }
        if let Some(k) = &r.coordinates {
            c.coordinates = match k.as_str() {
                "mean-value" => Coordinates::MeanValue,
                "harmonic" => Coordinates::Harmonic,
                _ => bail!("no cage coordinates {k:?} (mean-value, harmonic)"),
            };
        }
        if let Some(g) = r.grid {
            if !GRID.contains(&g) {
                bail!(
                    "harmonic grid: {g} nodes per side is not in {}..={}",
                    GRID.start(),
                    GRID.end()
                );
            }
            c.grid = g;
        }
        let points: usize = c.lattice.iter().product();
        if c.basis == LatticeBasis::Bernstein && points > MAX_BERNSTEIN_POINTS {
            bail!(
                "a {}x{}x{} Bernstein lattice has {points} control points, each moving every \
                 vertex (at most {MAX_BERNSTEIN_POINTS} here; a B-spline basis takes more)",
                c.lattice[0],
                c.lattice[1],
                c.lattice[2]
            );
        }
        Ok(c)
    }

    /// The cage coordinates.
    fn cage_coordinates(&self) -> CageCoordinates {
        match self.coordinates {
            Coordinates::Harmonic => CageCoordinates::Harmonic(HarmonicGrid {
                resolution: self.grid,
            }),
            Coordinates::MeanValue => CageCoordinates::MeanValue,
        }
    }
}

/// A mesh bound to control points.
pub struct Controls {
    pub deformer: Box<dyn Deformer<Scratch = ControlScratch>>,
    /// The control points at rest (the page's gizmos turn about them).
    pub points: Vec<DVec3>,
    /// Pairs of points the page joins with a line.
    pub edges: Vec<[u32; 2]>,
}

/// Bind `mesh` to the chosen FFD lattice over its box.
pub fn lattice(mesh: &Mesh, form: ControlForm, choice: &ControlChoice) -> Result<Controls> {
    let options = FfdOptions {
        form,
        basis: choice.basis,
    };
    let ffd = Ffd::bind(mesh, choice.lattice, None, options)?;
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

/// Bind `mesh` to its `cage` by the chosen coordinates.
pub fn cage(
    mesh: &Mesh,
    cage: &Mesh,
    form: ControlForm,
    choice: &ControlChoice,
) -> Result<Controls> {
    let options = CageOptions {
        form,
        coordinates: choice.cage_coordinates(),
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
