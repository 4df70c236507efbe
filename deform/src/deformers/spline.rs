//! Spline-aligned deformation (first paper, section III): a harmonic field `lambda` in
//! `[0, 1]` runs from the first handle set (0) to the last (1); each vertex gets the motor
//! `M_i = S(lambda_i) = exp(sum_j W_j(lambda_i) log R_j)` (equation (1)) of the key motors.
//!
//! Bind: `p'_i = M~_i p_i M_i` with the rest keys (identity by default); pose:
//! `p_i = M_i p'_i M~_i` with the posed keys. Every scheme is clamped, `S(0) = R_1` and
//! `S(1) = R_n` exactly, so the vertices of the first and last handle sets move rigidly with
//! the first and last keys. Keys are scaled motors, so a handle can grow or shrink. How keys
//! are brought into one hemisphere, and what happens near a half-turn, is said in
//! [`crate::blend`].

use crate::blend::KeyError;
use crate::blend::{BlendMethod, BoundBlend, KeyWeights};
use crate::deformers::bspline::{bspline_basis, bspline_degree};
use crate::deformers::deformer::deformer_via_blend;
use crate::deformers::Result;
use crate::mesh::Mesh;
use crate::operators::harmonic::Harmonic;
use crate::operators::harmonic::HarmonicOptions;
use crate::operators::laplacian::LaplacianKind;
use cga::ScaledMotor;
use glam::DVec3;

/// The basis functions `W_j(lambda)` of equation (1). All are partitions of unity.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum WeightScheme {
    /// Piecewise linear over `n >= 2` keys at `lambda = j / (n - 1)`; with two keys the
    /// paper's `w_1 = 1 - lambda`, `w_2 = lambda` (Fig. 2).
    Linear,
    /// The quadratic Lagrange polynomials through three keys at `0, 1/2, 1` (Fig. 3):
    /// `w_1 = 2l^2 - 3l + 1`, `w_2 = -4l^2 + 4l`, `w_3 = 2l^2 - l` (exactly 3 keys).
    Quadratic,
    /// Bernstein polynomials of degree `n - 1` over `n >= 2` keys; 4 keys make the cubic Bezier.
    /// Every key weighs every vertex (`n` weights a vertex, `n^2 / 2` steps to compute them):
    /// meant for a few keys, not thousands.
    Bezier,
    /// Clamped uniform cubic B-spline over `n >= 2` keys (degree lowered to `n - 1` below
    /// four keys), the default (Fig. 4).
    #[default]
    BSpline,
}

impl WeightScheme {
    /// Every scheme.
    pub const ALL: [WeightScheme; 4] = [
        WeightScheme::Linear,
        WeightScheme::Quadratic,
        WeightScheme::Bezier,
        WeightScheme::BSpline,
    ];

    /// A short name (`linear`, `quadratic`, `bezier`, `bspline`).
    pub fn name(self) -> &'static str {
        match self {
            WeightScheme::Linear => "linear",
            WeightScheme::Quadratic => "quadratic",
            WeightScheme::Bezier => "bezier",
            WeightScheme::BSpline => "bspline",
        }
    }

    /// Check that the scheme takes `n` keys.
    ///
    /// # Errors
    /// [`KeyError::WrongCount`] or [`KeyError::TooMany`].
    pub fn check_key_count(self, n: usize) -> Result<()> {
        let (ok, expected) = match self {
            WeightScheme::Quadratic => (n == 3, "exactly 3"),
            _ => (n >= 2, "at least 2"),
        };
        if !ok {
            return Err(KeyError::WrongCount {
                what: self.name(),
                expected: expected.into(),
                got: n,
            }
            .into());
        }
        KeyError::check_count("keys", n)?;
        Ok(())
    }

    /// How many consecutive keys are non-zero at one parameter.
    pub fn width(self, n: usize) -> usize {
        match self {
            WeightScheme::Linear => 2,
            WeightScheme::Quadratic => 3,
            WeightScheme::Bezier => n,
            WeightScheme::BSpline => bspline_degree(n) + 1,
        }
    }

    /// The weights at `lambda` (clamped to `[0, 1]`) over `n` keys: writes
    /// [`WeightScheme::width`] weights into `out` and returns the index of the first key they
    /// apply to.
    ///
    /// # Panics
    /// When `n` is not valid for the scheme ([`WeightScheme::check_key_count`] says why) or
    /// `out` is shorter than [`WeightScheme::width`].
    pub fn weights(self, n: usize, lambda: f64, out: &mut [f64]) -> usize {
        let l = lambda.clamp(0.0, 1.0);
        match self {
            WeightScheme::Linear => {
                let segments = n - 1;
                let s = ((l * segments as f64) as usize).min(segments - 1);
                let u = l * segments as f64 - s as f64;
                out[0] = 1.0 - u;
                out[1] = u;
                s
            }
            WeightScheme::Quadratic => {
                out[0] = 2.0 * l * l - 3.0 * l + 1.0;
                out[1] = -4.0 * l * l + 4.0 * l;
                out[2] = 2.0 * l * l - l;
                0
            }
            WeightScheme::Bezier => {
                super::bspline::bernstein(n - 1, l, out);
                0
            }
            WeightScheme::BSpline => bspline_basis(n, bspline_degree(n), l, out),
        }
    }

    /// Per-vertex key weights for parameters `lambda`.
    ///
    /// # Errors
    /// As [`WeightScheme::check_key_count`]; [`KeyError::ParameterOutOfRange`] for a
    /// parameter outside `[0, 1]` by more than `1e-9` (rounding is clamped) or not finite.
    pub fn key_weights(self, n: usize, lambda: &[f64]) -> Result<KeyWeights> {
        self.check_key_count(n)?;
        if let Some(i) = lambda
            .iter()
            .position(|l| !(-1e-9..=1.0 + 1e-9).contains(l))
        {
            return Err(KeyError::ParameterOutOfRange {
                index: i,
                value: lambda[i],
            }
            .into());
        }
        let width = self.width(n);
        let mut first = Vec::with_capacity(lambda.len());
        let mut weights = vec![0.0; lambda.len() * width];
        for (l, row) in lambda.iter().zip(weights.chunks_mut(width)) {
            first.push(self.weights(n, *l, row) as u32);
        }
        Ok(KeyWeights::new(n, width, first, weights)?)
    }
}

/// Options of [`SplineDeformer::bind`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplineOptions {
    /// The basis functions (default: cubic B-spline).
    pub scheme: WeightScheme,
    /// How the field `lambda` is computed; the default uses the paper's mean-value weights.
    pub harmonic: HarmonicOptions,
    /// How the keys are blended (default: the paper's log blend).
    pub method: BlendMethod,
}

impl Default for SplineOptions {
    fn default() -> Self {
        SplineOptions {
            scheme: WeightScheme::BSpline,
            harmonic: HarmonicOptions {
                laplacian: LaplacianKind::MeanValue,
                ..HarmonicOptions::default()
            },
            method: BlendMethod::MotorLog,
        }
    }
}

/// A mesh bound for spline-aligned deformation.
#[derive(Clone, Debug)]
pub struct SplineDeformer {
    lambda: Vec<f64>,
    scheme: WeightScheme,
    blend: BoundBlend,
}

impl SplineDeformer {
    /// Bind `mesh`: `lambda` is the harmonic field that is 0 on `first` (the handle set
    /// `H_1`) and 1 on `last` (`H_n`); `rest` are the key motors of the rest pose (pass
    /// identities for keys that are relative to the rest pose).
    ///
    /// # Errors
    /// The mesh and constraint errors of [`Harmonic::new`] (an empty or overlapping set, a
    /// vertex out of range, a component without constraints); [`KeyError::EmptyHandle`];
    /// the key-count and key errors of [`SplineDeformer::bind_with_lambda`].
    pub fn bind(
        mesh: &Mesh,
        first: &[u32],
        last: &[u32],
        rest: &[ScaledMotor],
        options: SplineOptions,
    ) -> Result<Self> {
        options.scheme.check_key_count(rest.len())?;
        for (set, s) in [first, last].iter().enumerate() {
            if s.is_empty() {
                return Err(KeyError::EmptyHandle { set }.into());
            }
        }
        let lambda = Harmonic::new(mesh, &[first, last], options.harmonic)?.field(&[0.0, 1.0])?;
        Self::bind_with_lambda(
            &mesh.positions,
            lambda,
            rest,
            options.scheme,
            options.method,
        )
    }

    /// Bind with a given parameter field (one value in `[0, 1]` per vertex).
    ///
    /// # Errors
    /// [`KeyError::WrongCount`] for a key list of the wrong length for the scheme,
    /// [`KeyError::ParameterOutOfRange`], [`KeyError::Invalid`] for a rest key that is not a
    /// scaled motor, [`MeshError::DimensionMismatch`](crate::mesh::MeshError::DimensionMismatch).
    pub fn bind_with_lambda(
        positions: &[DVec3],
        lambda: Vec<f64>,
        rest: &[ScaledMotor],
        scheme: WeightScheme,
        method: BlendMethod,
    ) -> Result<Self> {
        let weights = scheme.key_weights(rest.len(), &lambda)?;
        let blend = BoundBlend::bind(positions, weights, rest, method)?;
        let lambda = lambda.into_iter().map(|l| l.clamp(0.0, 1.0)).collect();
        Ok(SplineDeformer {
            lambda,
            scheme,
            blend,
        })
    }

    /// The parameter field `lambda` (one value per vertex, in `[0, 1]`).
    pub fn lambda(&self) -> &[f64] {
        &self.lambda
    }

    /// The weight scheme.
    pub fn scheme(&self) -> WeightScheme {
        self.scheme
    }

    /// The bound blend (weights, method).
    pub fn blend(&self) -> &BoundBlend {
        &self.blend
    }
}

deformer_via_blend!(SplineDeformer, blend, crate::blend::PreparedKeys);
