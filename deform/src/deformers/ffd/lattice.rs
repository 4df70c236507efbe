//! The FFD lattice: an `l x m x n` grid of control points over a box, its basis (Bernstein of
//! degree `count - 1` per axis, or clamped uniform B-splines of a given degree) and the
//! per-vertex weights over the control points (equation (8)), computed once at bind from the
//! vertices' local lattice coordinates.

use super::FfdError;
use crate::blend::KeyWeights;
use crate::blend::MAX_KEYS;
use crate::deformers::bspline::{bernstein, bspline_basis};
use crate::deformers::Result;
use glam::DVec3;

/// How far (relative to the box's extent) a vertex may lie outside the box and still be
/// clamped onto it rather than refused: rounding of the box itself.
pub const OUTSIDE_TOLERANCE: f64 = 1e-9;

/// The basis functions along each axis of the lattice.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LatticeBasis {
    /// Sederberg-Parry: Bernstein polynomials of degree `count - 1` along each axis (every
    /// control point influences every vertex).
    #[default]
    Bernstein,
    /// Clamped uniform B-splines of this degree (1 to 3; lowered to `count - 1` on an axis with
    /// fewer points): each vertex depends on a block of at most `(degree + 1)^3` points.
    BSpline(usize),
}

impl LatticeBasis {
    /// `bernstein` or `bspline-D` (`D` the degree), as the program and the editor name it.
    pub fn name(self) -> String {
        match self {
            LatticeBasis::Bernstein => "bernstein".into(),
            LatticeBasis::BSpline(d) => format!("bspline-{d}"),
        }
    }

    /// The basis [`LatticeBasis::name`] names (B-spline degrees 1 to 3), `None` otherwise.
    pub fn parse(name: &str) -> Option<LatticeBasis> {
        match name {
            "bernstein" => Some(LatticeBasis::Bernstein),
            "bspline-1" => Some(LatticeBasis::BSpline(1)),
            "bspline-2" => Some(LatticeBasis::BSpline(2)),
            "bspline-3" => Some(LatticeBasis::BSpline(3)),
            _ => None,
        }
    }
}

/// A lattice of `dims[0] x dims[1] x dims[2]` control points over the box `min .. max`.
/// Control point `(u, v, w)` has index `u + L * (v + M * w)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Lattice {
    dims: [usize; 3],
    min: DVec3,
    max: DVec3,
    basis: LatticeBasis,
}

impl Lattice {
    /// [`FfdError::Dims`] unless every axis has at least 2 control points and there are at
    /// most [`MAX_KEYS`] in all (what [`Lattice::new`] checks first; a program can ask before
    /// it sizes anything by `dims`).
    pub fn check_dims(dims: [usize; 3]) -> std::result::Result<(), FfdError> {
        let count = dims.iter().try_fold(1usize, |a, &d| a.checked_mul(d));
        if dims.iter().any(|&d| d < 2) || count.is_none_or(|n| n > MAX_KEYS) {
            return Err(FfdError::Dims { dims });
        }
        Ok(())
    }

    /// A lattice of `dims` control points over the box `min .. max`.
    ///
    /// # Errors
    /// [`FfdError::Dims`] for an axis with fewer than 2 points or more than
    /// [`MAX_KEYS`] points in all, [`FfdError::ZeroExtent`] for a box that is empty, flat
    /// or not finite along an axis, [`FfdError::Degree`] for a B-spline degree outside 1..=3.
    pub fn new(dims: [usize; 3], min: DVec3, max: DVec3, basis: LatticeBasis) -> Result<Self> {
        Lattice::check_dims(dims)?;
        for axis in 0..3 {
            let (lo, hi) = (min[axis], max[axis]);
            if !(lo.is_finite() && hi.is_finite() && hi - lo > 0.0 && (hi - lo).is_finite()) {
                return Err(FfdError::ZeroExtent {
                    axis,
                    min: lo,
                    max: hi,
                }
                .into());
            }
        }
        if let LatticeBasis::BSpline(d) = basis {
            if !(1..=3).contains(&d) {
                return Err(FfdError::Degree(d).into());
            }
        }
        Ok(Lattice {
            dims,
            min,
            max,
            basis,
        })
    }

    /// Control points per axis.
    pub fn dims(&self) -> [usize; 3] {
        self.dims
    }

    /// The number of control points.
    pub fn len(&self) -> usize {
        self.dims.iter().product()
    }

    /// Never: a lattice has at least 8 points.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The box's corners.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        (self.min, self.max)
    }

    /// The basis.
    pub fn basis(&self) -> LatticeBasis {
        self.basis
    }

    /// The index `u + L * (v + M * w)` of control point `(u, v, w)`.
    pub fn index(&self, u: usize, v: usize, w: usize) -> usize {
        u + self.dims[0] * (v + self.dims[1] * w)
    }

    /// The lattice's grid lines: each pair of neighbouring control points `[i, j]` (by
    /// [`Lattice::index`]), along u, v and w ([`crate::mesh::shapes::grid_edges`]).
    pub fn edges(&self) -> Vec<[u32; 2]> {
        crate::mesh::shapes::grid_edges(self.dims)
    }

    /// The degree along `axis`.
    fn degree(&self, axis: usize) -> usize {
        let n = self.dims[axis];
        match self.basis {
            LatticeBasis::Bernstein => n - 1,
            LatticeBasis::BSpline(d) => d.min(n - 1),
        }
    }

    /// The rest control points: the lattice points in parameter space at the Greville
    /// abscissae of the basis (evenly spaced for Bernstein), so the rest lattice reproduces
    /// every point of the box (linear precision).
    pub fn rest_points(&self) -> Vec<DVec3> {
        let g: [Vec<f64>; 3] = std::array::from_fn(|a| greville(self.dims[a], self.degree(a)));
        let mut out = Vec::with_capacity(self.len());
        for w in 0..self.dims[2] {
            for v in 0..self.dims[1] {
                for u in 0..self.dims[0] {
                    let s = DVec3::new(g[0][u], g[1][v], g[2][w]);
                    out.push(self.min + s * (self.max - self.min));
                }
            }
        }
        out
    }

    /// The local lattice coordinates of `p` in `[0, 1]^3`, clamping points within
    /// [`OUTSIDE_TOLERANCE`] of the box.
    ///
    /// # Errors
    /// [`FfdError::Outside`] (naming `index`) for a point outside the box or not finite.
    pub fn local(&self, index: usize, p: DVec3) -> Result<DVec3> {
        let s = (p - self.min) / (self.max - self.min);
        let tol = OUTSIDE_TOLERANCE;
        if !s.is_finite() || s.min_element() < -tol || s.max_element() > 1.0 + tol {
            return Err(FfdError::Outside {
                vertex: index,
                position: p.to_array(),
            }
            .into());
        }
        Ok(s.clamp(DVec3::ZERO, DVec3::ONE))
    }

    /// The per-vertex weights over the control points (equation (8)): for each point, the
    /// product of the three univariate bases at its local coordinates, over the block of
    /// control points it depends on.
    ///
    /// # Errors
    /// As [`Lattice::local`].
    pub fn weights(&self, points: &[DVec3]) -> Result<KeyWeights> {
        let p: [usize; 3] = std::array::from_fn(|a| self.degree(a));
        let block = [p[0] + 1, p[1] + 1, p[2] + 1];
        let width = block.iter().product::<usize>();
        let mut keys = Vec::with_capacity(points.len() * width);
        let mut weights = Vec::with_capacity(points.len() * width);
        let mut b = [[0.0; 4], [0.0; 4], [0.0; 4]];
        let mut bern: [Vec<f64>; 3] = std::array::from_fn(|a| vec![0.0; block[a]]);
        for (i, &x) in points.iter().enumerate() {
            let s = self.local(i, x)?;
            let mut first = [0usize; 3];
            for a in 0..3 {
                match self.basis {
                    LatticeBasis::Bernstein => bernstein(p[a], s[a], &mut bern[a]),
                    LatticeBasis::BSpline(_) => {
                        first[a] = bspline_basis(self.dims[a], p[a], s[a], &mut b[a]);
                        bern[a].copy_from_slice(&b[a][..block[a]]);
                    }
                }
            }
            for w in 0..block[2] {
                for v in 0..block[1] {
                    for u in 0..block[0] {
                        let k = self.index(first[0] + u, first[1] + v, first[2] + w);
                        keys.push(k as u32);
                        weights.push(bern[0][u] * bern[1][v] * bern[2][w]);
                    }
                }
            }
        }
        Ok(KeyWeights::gathered(self.len(), width, keys, weights)?)
    }
}

/// The Greville abscissae of the clamped uniform knot vector of degree `p` over `n` control
/// points: the averages of `p` consecutive interior knots (`k / (n - 1)` for `p = n - 1`).
fn greville(n: usize, p: usize) -> Vec<f64> {
    let knot = |k: usize| crate::deformers::bspline::knot(k, n, p);
    (0..n)
        .map(|j| (1..=p).map(|k| knot(j + k)).sum::<f64>() / p as f64)
        .collect()
}
