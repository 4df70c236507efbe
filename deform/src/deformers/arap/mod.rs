//! As-rigid-as-possible surface modeling with rotors (first paper, section VII; Sorkine and
//! Alexa 2007).
//!
//! Each vertex `i` owns a cell (its one-ring edges, or every edge of the triangles around it)
//! and a rotation `R_i`; the energy
//! `E = sum_i sum_(j,k in cell i) w_jk |(p'_j - p'_k) - R_i (p_j - p_k)|^2` is minimised by
//! alternating
//!
//! 1. the **local step**: each `R_i` maximises `tr(R_i S_i)` for the cell covariance
//!    `S_i = sum w e e'^T`; as the paper does, it is fitted as a rotor, the top eigenvector of
//!    Horn's 4x4 matrix ([`LocalStep::Rotor`], warm-started from the previous rotor), or by
//!    the classic 3x3 SVD with the reflection fix ([`LocalStep::Svd`]); both give the same
//!    rotations to rounding;
//! 2. the **global step**: the Poisson system `-L p' = b(R)` with the constrained vertices as
//!    Dirichlet rows (equation (13)), prefactored once at bind by [`crate::operators::solve::DirichletSolver`].
//!
//! Energies: [`ArapEnergy::Spokes`] (Sorkine and Alexa's, the paper's) and
//! [`ArapEnergy::SpokesAndRims`] (libigl's default for triangle meshes; Chao et al. 2010).
//! Weights are libigl's raw cotangent weights (`cotmatrix`, half cotangents, negative for
//! obtuse angles) unless [`crate::operators::laplacian::CotangentOptions::clamp_negative`] clamps them to zero as
//! CGAL does: the edge sums for spokes, each triangle's share for spokes and rims. Zero-area
//! triangles follow [`crate::operators::laplacian::CotangentOptions::degenerate`].
//!
//! Constraints: fixed vertices, which stay at rest (or at given targets), and handle groups,
//! moved as a whole by one motor each (the paper's handle metaphor, [`Targets::Motors`]) or
//! vertex by vertex ([`Targets::Positions`]). [`Arap::pose`] iterates from the positions it is
//! given (warm start: pass the previous result while editing) and reports the energy after
//! every iteration; [`Stop`] ends it after a number of iterations or when the energy's
//! relative change is small. The energy is non-increasing from the first iteration on.
//!
//! ```
//! use deform::deformers::arap::{Arap, ArapOptions, Stop, Targets};
//! use deform::mesh::shapes::{tube, tube_ring};
//! use cga::ScaledMotor;
//! use glam::{DQuat, DVec3};
//! let bar = tube(1.0, 10.0, 8, 11);
//! let (left, right) = (tube_ring(8, 0), tube_ring(8, 10));
//! let arap = Arap::bind(&bar, &left, &[&right], ArapOptions::default()).unwrap();
//! let lift = ScaledMotor::from_scale_rotation_translation(1.0, DQuat::IDENTITY, DVec3::Y);
//! let mut p = bar.positions.clone();
//! let report = arap.pose(&Targets::Motors(&[lift]), Stop::Iterations(5), &mut p).unwrap();
//! assert_eq!(report.energies.len(), 5);
//! assert!((p[right[0] as usize] - bar.positions[right[0] as usize] - DVec3::Y).length() < 1e-12);
//! assert!(report.energies.windows(2).all(|e| e[1] <= e[0] + 1e-12));
//! ```

mod cells;
mod energy;
mod local;
mod options;
mod rhs;
mod system;

pub use local::{fit_rotor, fit_svd, LocalStep};
pub use options::{ArapEnergy, ArapError, ArapOptions, ArapReport, Stop, Targets};

use crate::blend::{check_key_count, check_positions, KeyError};
use crate::deformers::Deformer;
use crate::deformers::Result;
use crate::mesh::IndexList;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::operators::solve::SolveScratch;
use cells::{Cells, Covariance};
use cga::{Rotor, ScaledMotor};
use glam::{DMat3, DQuat, DVec3};
use system::System;

/// The per-pose buffers of an [`Arap`], owned by the caller (one per thread that poses):
/// made by [`Arap::scratch`], reused by every [`Arap::pose_using`] it is given. It also keeps
/// the rotations of the last iteration of its last pose ([`ArapScratch::rotors`]).
#[derive(Debug)]
pub struct ArapScratch {
    quats: Vec<DQuat>,
    rots: Vec<DMat3>,
    cov: Vec<Covariance>,
    tri_cov: Vec<Covariance>,
    b: Vec<DVec3>,
    rhs: Vec<f64>,
    sol: Vec<f64>,
    boundary: Vec<f64>,
    positions: Vec<DVec3>,
    /// Per-chunk sums of the energy.
    partial: Vec<f64>,
    scratch: SolveScratch,
}

impl ArapScratch {
    /// The rotation of every cell used by the last iteration of the last pose, as rotors
    /// (identities before the first pose).
    pub fn rotors(&self) -> Vec<Rotor> {
        self.rots
            .iter()
            .map(|m| Rotor::from_quat(DQuat::from_mat3(m).normalize()))
            .collect()
    }

    /// The rotation matrices of the last iteration (see [`ArapScratch::rotors`]).
    pub fn rotation_matrices(&self) -> &[DMat3] {
        &self.rots
    }
}

/// A mesh bound for ARAP: weights, cells and the prefactored system; see the
/// [module docs](self).
#[derive(Debug)]
pub struct Arap {
    system: System,
    options: ArapOptions,
}

impl Arap {
    /// Assembles the cotangent weights and cells, checks the constraints and prefactors the
    /// constrained system. `fixed` vertices and the `handles` groups are the constrained
    /// vertices (in that order, see [`Arap::constrained`]).
    ///
    /// # Errors
    /// The mesh checks of [`crate::mesh::validate::check_solvable`]; [`ArapError::NoConstraints`];
    /// [`KeyError::EmptyHandle`]; [`MeshError::ConstraintOutOfRange`];
    /// [`MeshError::OverlappingConstraints`] (a vertex fixed and in a handle, in two handles, or
    /// listed twice); [`ArapError::NothingToDeform`] (a component whose every vertex is
    /// constrained, such as a handle covering a whole component); [`SolveError::Unconstrained`](crate::operators::SolveError::Unconstrained)
    /// (a component without constraints); [`MeshError::DegenerateTriangles`] with
    /// [`crate::operators::laplacian::DegeneratePolicy::Error`]; the solver's errors.
    pub fn bind(
        mesh: &Mesh,
        fixed: &[u32],
        handles: &[&[u32]],
        options: ArapOptions,
    ) -> Result<Self> {
        options.stop.max_iterations()?;
        let system = System::new(mesh, fixed, handles, &options)?;
        let arap = Arap { system, options };
        // The first scratch proves the solve's buffers fit in memory.
        arap.scratch()?;
        Ok(arap)
    }

    /// Fresh per-pose buffers for [`Arap::pose_using`] (about `30 n` doubles and the sparse
    /// solve's scratch).
    ///
    /// # Errors
    /// [`crate::operators::SolveError::Solver`] when the solve's scratch does not fit in
    /// memory.
    pub fn scratch(&self) -> Result<ArapScratch> {
        let system = &self.system;
        let n = system.len();
        let triangles = match &system.cells {
            Cells::Rims(r) => r.tris.len(),
            Cells::Spokes(_) => 0,
        };
        let nc = system.constrained.len();
        Ok(ArapScratch {
            quats: vec![DQuat::IDENTITY; n],
            rots: vec![DMat3::IDENTITY; n],
            cov: vec![Covariance::default(); n],
            tri_cov: vec![Covariance::default(); triangles],
            b: vec![DVec3::ZERO; n],
            rhs: vec![0.0; 3 * n],
            sol: vec![0.0; 3 * n],
            boundary: vec![0.0; 3 * nc],
            positions: vec![DVec3::ZERO; n],
            partial: Vec::with_capacity(n.div_ceil(cells::CHUNK)),
            scratch: system.solver.scratch(3)?,
        })
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.system.len()
    }

    /// The options it was bound with.
    pub fn options(&self) -> &ArapOptions {
        &self.options
    }

    /// The rest positions.
    pub fn rest(&self) -> &[DVec3] {
        &self.system.rest
    }

    /// The constrained vertices: fixed first, then each handle group.
    pub fn constrained(&self) -> &[u32] {
        &self.system.constrained
    }

    /// Number of handle groups.
    pub fn handle_count(&self) -> usize {
        self.system.starts.len() - 1
    }

    /// The vertices of handle group `g` (`None` when `g >= handle_count()`).
    pub fn handle(&self, g: usize) -> Option<&[u32]> {
        let (a, b) = (*self.system.starts.get(g)?, *self.system.starts.get(g + 1)?);
        self.system.constrained.get(a..b)
    }

    /// Iterates from `positions` (the warm start, e.g. the rest pose or the previous result)
    /// until `stop`, moving the constrained vertices to `targets`, and writes the result
    /// into `positions`. The constrained vertices are first set to their targets (as libigl's
    /// `arap_solve` does); each iteration then fits the rotations to the current positions
    /// and solves for new ones.
    ///
    /// # Errors
    /// [`MeshError::DimensionMismatch`] (`positions` or a target list of the wrong length,
    /// a motor list without one motor per handle group), [`MeshError::NonFinite`] (non-finite
    /// starting positions or targets, naming the vertices), [`KeyError::Invalid`] (a motor
    /// that is not finite or not a motor), [`MeshError::InvalidArgument`] (a bad [`Stop`]).
    /// Input errors leave `positions` untouched; a numerical failure of the solve (not
    /// expected once the input is valid) leaves the last complete iterate.
    pub fn pose(
        &self,
        targets: &Targets<'_>,
        stop: Stop,
        positions: &mut [DVec3],
    ) -> Result<ArapReport> {
        let mut report = ArapReport::default();
        report.converged =
            self.pose_with(targets, stop, positions, |_, e| report.energies.push(e))?;
        Ok(report)
    }

    /// [`Arap::pose_using`] with a fresh scratch (allocated per call; pose loops keep an
    /// [`ArapScratch`]), calling `on_iteration(k, energy)` after iteration `k` (from 1)
    /// instead of collecting a report; returns whether [`Stop::RelativeChange`] was met.
    ///
    /// # Errors
    /// As [`Arap::pose`].
    pub fn pose_with(
        &self,
        targets: &Targets<'_>,
        stop: Stop,
        positions: &mut [DVec3],
        on_iteration: impl FnMut(usize, f64),
    ) -> Result<bool> {
        let mut scratch = self.scratch()?;
        self.pose_using(targets, stop, &mut scratch, positions, on_iteration)
    }

    /// [`Arap::pose_with`] in the caller's `scratch` (from [`Arap::scratch`] of this
    /// deformer): no allocation, and any number of threads can pose one bound `Arap` at
    /// once, each with its own scratch.
    ///
    /// # Errors
    /// As [`Arap::pose`], and [`crate::mesh::MeshError::DimensionMismatch`] for a scratch
    /// made by another `Arap`.
    pub fn pose_using(
        &self,
        targets: &Targets<'_>,
        stop: Stop,
        scratch: &mut ArapScratch,
        positions: &mut [DVec3],
        on_iteration: impl FnMut(usize, f64),
    ) -> Result<bool> {
        self.check_scratch(scratch)?;
        check_positions(self.vertex_count(), positions.len())?;
        let bad: Vec<u32> = (0..positions.len() as u32)
            .filter(|&i| !positions[i as usize].is_finite())
            .collect();
        if !bad.is_empty() {
            return Err(MeshError::NonFinite {
                vertices: IndexList(bad),
            }
            .into());
        }
        self.fill_boundary(targets, &mut scratch.boundary)?;
        self.run(scratch, stop, positions, on_iteration)
    }

    /// A scratch of another `Arap` (other sizes) is refused.
    fn check_scratch(&self, w: &ArapScratch) -> Result<()> {
        let triangles = match &self.system.cells {
            Cells::Rims(r) => r.tris.len(),
            Cells::Spokes(_) => 0,
        };
        let fits = w.quats.len() == self.system.len()
            && w.tri_cov.len() == triangles
            && w.boundary.len() == 3 * self.system.constrained.len();
        if !fits {
            return Err(MeshError::DimensionMismatch {
                what: "ARAP scratch (made by another Arap)",
                expected: self.system.len(),
                got: w.quats.len(),
            }
            .into());
        }
        Ok(())
    }

    /// Writes the boundary values (column-major, `constrained().len()` rows) for `targets`.
    fn fill_boundary(&self, targets: &Targets<'_>, boundary: &mut [f64]) -> Result<()> {
        let s = &self.system;
        let nc = s.constrained.len();
        let mut put = |k: usize, p: DVec3| {
            boundary[k] = p.x;
            boundary[nc + k] = p.y;
            boundary[2 * nc + k] = p.z;
        };
        match targets {
            Targets::Positions(t) => {
                if t.len() != nc {
                    return Err(MeshError::DimensionMismatch {
                        what: "ARAP target positions",
                        expected: nc,
                        got: t.len(),
                    }
                    .into());
                }
                let bad: Vec<u32> = (0..nc)
                    .filter(|&k| !t[k].is_finite())
                    .map(|k| s.constrained[k])
                    .collect();
                if !bad.is_empty() {
                    return Err(MeshError::NonFinite {
                        vertices: IndexList(bad),
                    }
                    .into());
                }
                for (k, &p) in t.iter().enumerate() {
                    put(k, p);
                }
            }
            Targets::Motors(m) => {
                check_key_count("ARAP handles", self.handle_count(), m.len())?;
                for (index, k) in m.iter().enumerate() {
                    k.try_log()
                        .map_err(|source| KeyError::Invalid { index, source })?;
                }
                for k in 0..s.starts[0] {
                    put(k, s.rest[s.constrained[k] as usize]);
                }
                let mut bad = Vec::new();
                for (g, motor) in m.iter().enumerate() {
                    for k in s.starts[g]..s.starts[g + 1] {
                        let v = s.constrained[k];
                        let p = motor.transform_point(s.rest[v as usize]);
                        if !p.is_finite() {
                            bad.push(v);
                        }
                        put(k, p);
                    }
                }
                if !bad.is_empty() {
                    return Err(MeshError::NonFinite {
                        vertices: IndexList(bad),
                    }
                    .into());
                }
            }
        }
        Ok(())
    }

    /// The iterations; `w.boundary` is filled.
    fn run(
        &self,
        w: &mut ArapScratch,
        stop: Stop,
        positions: &mut [DVec3],
        mut on_iteration: impl FnMut(usize, f64),
    ) -> Result<bool> {
        let max = stop.max_iterations()?;
        let s = &self.system;
        let n = s.len();
        let floor = 1e-14 * s.b.iter().map(|x| x.abs()).sum::<f64>();
        let w = &mut *w;
        // The constrained vertices start at their targets (as libigl's arap_solve does), so
        // the first rotations already see the moved handles.
        let nc = s.constrained.len();
        for (k, &v) in s.constrained.iter().enumerate() {
            let b = &w.boundary;
            positions[v as usize] = DVec3::new(b[k], b[nc + k], b[2 * nc + k]);
        }
        energy::covariances(&s.cells, positions, &mut w.cov, &mut w.tri_cov);
        let mut previous: Option<f64> = None;
        for k in 1..=max {
            local::fit_all(
                self.options.local_step,
                &w.cov,
                &s.b_abs,
                &mut w.quats,
                &mut w.rots,
            );
            rhs::right_hand_side(&s.gather, &w.rots, &mut w.b);
            for (i, b) in w.b.iter().enumerate() {
                w.rhs[i] = b.x;
                w.rhs[n + i] = b.y;
                w.rhs[2 * n + i] = b.z;
            }
            s.solver
                .solve_into(Some(&w.rhs), &w.boundary, 3, &mut w.sol, &mut w.scratch)?;
            for (i, p) in positions.iter_mut().enumerate() {
                *p = DVec3::new(w.sol[i], w.sol[n + i], w.sol[2 * n + i]);
            }
            energy::covariances(&s.cells, positions, &mut w.cov, &mut w.tri_cov);
            let e = energy::energy(&w.cov, &s.b, &w.rots, &mut w.partial);
            on_iteration(k, e);
            if let (Stop::RelativeChange { tolerance, .. }, Some(prev)) = (stop, previous) {
                if (prev - e).abs() <= tolerance * prev.abs().max(floor) {
                    return Ok(true);
                }
            }
            previous = Some(e);
        }
        Ok(false)
    }
}

/// Keys are one motor per handle group; every pose starts from the rest pose and runs
/// [`ArapOptions::stop`]. The scratch is made on the first pose (where a failure to allocate
/// the solve's scratch is an error), and replaced when it came from another `Arap`.
impl Deformer for Arap {
    type Scratch = Option<ArapScratch>;

    fn vertex_count(&self) -> usize {
        self.system.len()
    }

    fn key_count(&self) -> usize {
        self.handle_count()
    }

    fn scratch(&self) -> Option<ArapScratch> {
        None
    }

    fn pose_using(
        &self,
        keys: &[ScaledMotor],
        scratch: &mut Option<ArapScratch>,
        positions: &mut [DVec3],
    ) -> Result<()> {
        check_positions(self.vertex_count(), positions.len())?;
        if scratch
            .as_ref()
            .is_none_or(|w| self.check_scratch(w).is_err())
        {
            // Empty, or the scratch of another `Arap`: made for this one.
            *scratch = None;
        }
        let w = match scratch {
            Some(w) => w,
            None => scratch.insert(Arap::scratch(self)?),
        };
        self.fill_boundary(&Targets::Motors(keys), &mut w.boundary)?;
        let mut p = std::mem::take(&mut w.positions);
        p.copy_from_slice(&self.system.rest);
        let result = self.run(w, self.options.stop, &mut p, |_, _| {});
        if result.is_ok() {
            positions.copy_from_slice(&p);
        }
        w.positions = p;
        result.map(|_| ())
    }
}
