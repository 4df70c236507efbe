//! ARAP's options, targets, stop rule, report and errors.

use super::LocalStep;
pub use crate::deformers::error::ArapError;
use crate::deformers::Result;
use crate::mesh::MeshError;
use crate::operators::laplacian::CotangentOptions;
use crate::operators::solve::Factorization;
use crate::operators::solve::SolverOptions;
use cga::ScaledMotor;
use glam::DVec3;

/// The rigidity energy.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ArapEnergy {
    /// Each cell is the vertex's one-ring of edges (Sorkine and Alexa, the paper's).
    Spokes,
    /// Each cell is every edge of the triangles around the vertex (libigl's default).
    #[default]
    SpokesAndRims,
}

impl ArapEnergy {
    /// A short name (`spokes`, `spokes-and-rims`).
    pub fn name(self) -> &'static str {
        match self {
            ArapEnergy::Spokes => "spokes",
            ArapEnergy::SpokesAndRims => "spokes-and-rims",
        }
    }
}

/// When [`Arap::pose`](super::Arap::pose) stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stop {
    /// After exactly this many iterations (at least 1).
    Iterations(usize),
    /// When `|E_k - E_(k-1)| <= tolerance * |E_(k-1)|` (with a floor of `1e-14` times the
    /// rest-size term `sum w |e|^2`, so a zero energy stops at once), or after
    /// `max_iterations`.
    RelativeChange {
        /// The relative energy change that counts as converged (finite, `>= 0`).
        tolerance: f64,
        /// The most iterations (at least 1).
        max_iterations: usize,
    },
}

impl Default for Stop {
    fn default() -> Self {
        Stop::Iterations(10)
    }
}

impl Stop {
    pub(super) fn max_iterations(self) -> Result<usize> {
        let (max, tol) = match self {
            Stop::Iterations(n) => (n, 0.0),
            Stop::RelativeChange {
                tolerance,
                max_iterations,
            } => (max_iterations, tolerance),
        };
        if max == 0 || tol.is_nan() || tol < 0.0 || tol.is_infinite() {
            return Err(MeshError::InvalidArgument(format!(
                "ARAP stop rule {self:?}: needs at least one iteration and a finite tolerance >= 0"
            ))
            .into());
        }
        Ok(max)
    }
}

/// Options of [`Arap::bind`](super::Arap::bind).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArapOptions {
    /// The rigidity energy (default: spokes and rims, as libigl).
    pub energy: ArapEnergy,
    /// The local fit (default: the paper's rotor).
    pub local_step: LocalStep,
    /// Cotangent weights: raw (libigl, the default) or clamped (CGAL); degenerate triangles.
    pub cotangent: CotangentOptions,
    /// Factorisation settings of the global step (default: [`SolverOptions`]'s with the
    /// simplicial layout, whose three-column solves, one per iteration, are the fastest:
    /// faer's own choice on armadillo-50k is supernodal, 25.6 ms an iteration against 15.3-18.3
    /// simplicial, one thread, for 20-80 ms more in the bind).
    pub solver: SolverOptions,
    /// The stop rule of [`Deformer::pose`](crate::deformers::Deformer::pose) (which always starts from the rest pose).
    pub stop: Stop,
}

impl Default for ArapOptions {
    fn default() -> Self {
        ArapOptions {
            energy: ArapEnergy::default(),
            local_step: LocalStep::default(),
            cotangent: CotangentOptions::default(),
            solver: SolverOptions {
                factorization: Factorization::Simplicial,
                ..SolverOptions::default()
            },
            stop: Stop::default(),
        }
    }
}

/// Where the constrained vertices go in [`Arap::pose`](super::Arap::pose).
#[derive(Debug, Clone, Copy)]
pub enum Targets<'a> {
    /// One position per constrained vertex, in [`Arap::constrained`](super::Arap::constrained) order: the fixed
    /// vertices, then each handle group's vertices.
    Positions(&'a [DVec3]),
    /// One motor per handle group, applied to the group's rest positions; fixed vertices stay
    /// at rest.
    Motors(&'a [ScaledMotor]),
}

/// What [`Arap::pose`](super::Arap::pose) did.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ArapReport {
    /// The energy after each iteration (of the new positions with the rotations that
    /// produced them).
    pub energies: Vec<f64>,
    /// Whether [`Stop::RelativeChange`] was met (always false for [`Stop::Iterations`]).
    pub converged: bool,
}

impl ArapReport {
    /// Iterations done.
    pub fn iterations(&self) -> usize {
        self.energies.len()
    }
}
