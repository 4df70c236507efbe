//! Prefactored sparse solves with Dirichlet conditions (faer's sparse Cholesky).
//!
//! [`DirichletSolver`] minimises `x^T Q x / 2 - x^T b` over `x` with `x_c` prescribed on a
//! set of constrained rows `c`, i.e. it solves `Q_ff x_f = b_f - Q_fc x_c`. `Q` is a symmetric
//! positive semi-definite matrix such as `-L` (harmonic) or `L M^-1 L` (biharmonic), and
//! `Q_ff` must be positive definite. The symbolic analysis (fill-reducing ordering,
//! elimination tree) and the numeric factor are computed once; solves for new boundary values
//! or right-hand sides (any number of columns) only do triangular solves.

mod components;
mod scratch;
mod shared;
mod structure;

pub use scratch::SolveScratch;
pub use shared::SystemAnalysis;

use crate::mesh::IndexList;
use crate::mesh::MeshError;
use crate::operators::laplacian::ensure_finite;
use crate::operators::Result;
use crate::operators::SolveError;
use components::ensure_csr;
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::LltError;
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::cholesky::{LltRef, SymbolicCholesky, SymbolicCholeskyRaw};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par, Side};
use sprs::CsMat;
use structure::{split, Reduced, Split};

/// The index type of the factor's pattern: 32 bits halve the index traffic of the ordering,
/// the symbolic analysis and the triangular solves against `usize` (AMD and the analysis of
/// armadillo-50k's harmonic system 29.8 -> 24.2 ms). A system whose pattern does not fit
/// gets [`SolveError::Solver`].
pub(crate) type FactorIndex = u32;

/// Fails unless every index of `constrained` is below `n` and listed once
/// ([`MeshError::ConstraintOutOfRange`], [`MeshError::OverlappingConstraints`]).
pub(crate) fn check_constrained(n: usize, constrained: &[u32]) -> Result<()> {
    structure::classify(n, constrained).map(|_| ())
}

/// Threads used by the factorisation and the triangular solves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Parallelism {
    /// Single-threaded (the default: on a 2-core machine faer's parallel multi-column
    /// solves were measured 20-35x slower than sequential ones).
    #[default]
    Sequential,
    /// Use rayon's global pool with this many threads (`0`: all of the pool's threads).
    Rayon(usize),
}

impl Parallelism {
    /// The corresponding faer setting.
    pub fn to_faer(self) -> Par {
        match self {
            Parallelism::Sequential => Par::Seq,
            Parallelism::Rayon(n) => Par::rayon(n),
        }
    }
}

/// How the Cholesky factor is laid out (faer's simplicial or supernodal factorisation).
///
/// Measured on the armadillo (43k vertices, 2 cores): the supernodal factorisation is 1.6-2x
/// faster to compute there, where faer's own choice is simplicial, but its three-column
/// solves are slower, which doubled an ARAP iteration (on armadillo-50k, where faer's own
/// choice is supernodal, a three-column solve takes 10 ms supernodal against 4 simplicial).
/// Solve once (harmonic fields, binds): [`Factorization::Supernodal`]; solve every frame
/// (ARAP's default): [`Factorization::Simplicial`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Factorization {
    /// faer's choice, by the flop count per factor entry (the default).
    #[default]
    Auto,
    /// Dense blocks of columns: the fastest factorisation of large mesh systems.
    Supernodal,
    /// Column by column.
    Simplicial,
}

/// Options for [`DirichletSolver`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SolverOptions {
    /// Threads for factorisation and solves.
    pub parallelism: Parallelism,
    /// Before factorising, check that every connected component of `Q`'s graph contains a
    /// constrained row and report the vertices of those that do not
    /// ([`SolveError::Unconstrained`]). Right for Laplacian-like `Q` (whose null space is the
    /// constants on each component); turn off for a `Q` that is definite on its own.
    pub check_components: bool,
    /// The factor's layout (default [`Factorization::Auto`]).
    pub factorization: Factorization,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            parallelism: Parallelism::Sequential,
            check_components: true,
            factorization: Factorization::Auto,
        }
    }
}

/// A prefactored Dirichlet problem; see the [module docs](self).
///
/// ```
/// use deform::operators::laplacian::cotangent_laplacian;
/// use deform::operators::solve::{DirichletSolver, SolverOptions};
/// use deform::Mesh;
/// use glam::DVec3;
/// // A strip of two triangles; fix vertex 0 to 0 and vertex 3 to 1.
/// let m = Mesh::new(
///     vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE.with_z(0.0)],
///     vec![[0, 1, 3], [0, 3, 2]],
/// );
/// let q = cotangent_laplacian(&m, Default::default()).unwrap().map(|x| -x);
/// let s = DirichletSolver::new(&q, &[0, 3], SolverOptions::default()).unwrap();
/// let x = s.solve(&[0.0, 1.0], 1).unwrap();
/// assert!((x[1] - 0.5).abs() < 1e-12 && (x[2] - 0.5).abs() < 1e-12);
/// ```
#[derive(Debug)]
pub struct DirichletSolver {
    n: usize,
    options: SolverOptions,
    constrained: Vec<u32>,
    free: Vec<u32>,
    /// Pattern of the `Q` the solver was built from (for [`Self::update_values`]).
    q_indptr: Vec<usize>,
    q_indices: Vec<usize>,
    /// Upper triangle of `Q_ff`, compressed columns; `ff_src[k]` indexes `Q`'s data.
    ff_col_ptr: Vec<FactorIndex>,
    ff_row_idx: Vec<FactorIndex>,
    ff_src: Vec<usize>,
    ff_values: Vec<f64>,
    /// `Q_fc` by free rows; columns are positions in `constrained`.
    fc_ptr: Vec<usize>,
    fc_col: Vec<u32>,
    fc_src: Vec<usize>,
    fc_values: Vec<f64>,
    /// Shared with the [`SystemAnalysis`] it came from, if any.
    symbolic: std::sync::Arc<SymbolicCholesky<FactorIndex>>,
    l_values: Vec<f64>,
    /// With a [`SystemAnalysis`]: every row is an unknown of the factor (the constrained ones
    /// as identity rows), `0..n`. Otherwise the free rows.
    unknowns: Option<Vec<u32>>,
}

impl DirichletSolver {
    /// Analyses and factorises `Q_ff` for the given constrained rows (their order is the order
    /// of the boundary values passed to [`Self::solve`]). `q` must be square and symmetric.
    ///
    /// Errors: [`MeshError::DimensionMismatch`] (non-square), [`MeshError::Overflow`] (a non-finite
    /// entry of `q` or of its factor), [`MeshError::ConstraintOutOfRange`],
    /// [`MeshError::OverlappingConstraints`] (an index listed twice), [`SolveError::Unconstrained`]
    /// (see [`SolverOptions::check_components`]), [`SolveError::NotPositiveDefinite`].
    pub fn new(q: &CsMat<f64>, constrained: &[u32], options: SolverOptions) -> Result<Self> {
        let n = q.rows();
        if q.cols() != n {
            return Err(MeshError::DimensionMismatch {
                what: "columns of the system matrix",
                expected: n,
                got: q.cols(),
            }
            .into());
        }
        let q = ensure_csr(q);
        ensure_finite(&q, "system matrix row")?;
        let Split {
            slot,
            indptr,
            indices,
            free,
        } = split(&q, constrained, options)?;
        let reduced = Reduced::new(&indptr, &indices, &slot, free, options.factorization)?;
        DirichletSolver::from_reduced(options, constrained, indptr, indices, reduced, q.data())
    }

    /// The solver of a reduced structure and `Q`'s values (`data`, in the pattern
    /// `indptr`, `indices` the structure was made from), factorised.
    fn from_reduced(
        options: SolverOptions,
        constrained: &[u32],
        q_indptr: Vec<usize>,
        q_indices: Vec<usize>,
        reduced: Reduced,
        data: &[f64],
    ) -> Result<Self> {
        let mut s = DirichletSolver {
            n: q_indptr.len() - 1,
            options,
            constrained: constrained.to_vec(),
            ff_values: vec![0.0; reduced.ff_src.len()],
            fc_values: vec![0.0; reduced.fc_src.len()],
            free: reduced.free,
            q_indptr,
            q_indices,
            ff_col_ptr: reduced.ff_col_ptr,
            ff_row_idx: reduced.ff_row_idx,
            ff_src: reduced.ff_src,
            fc_ptr: reduced.fc_ptr,
            fc_col: reduced.fc_col,
            fc_src: reduced.fc_src,
            l_values: Vec::new(),
            symbolic: std::sync::Arc::new(reduced.symbolic),
            unknowns: None,
        };
        s.fill_values(data);
        s.factorize()?;
        Ok(s)
    }

    /// The rows of the factor, in the order of its unknowns: the free rows, or every row when
    /// the solver shares a [`SystemAnalysis`].
    fn rows(&self) -> &[u32] {
        self.unknowns.as_deref().unwrap_or(&self.free)
    }

    /// `ff_values` and `fc_values` from `Q`'s values (`data`), through `ff_src` and `fc_src`
    /// (the sentinels of `shared.rs` stand for the identity rows of constrained vertices).
    fn fill_values(&mut self, data: &[f64]) {
        for (v, &k) in self.ff_values.iter_mut().zip(&self.ff_src) {
            *v = shared::value(data, k);
        }
        for (v, &k) in self.fc_values.iter_mut().zip(&self.fc_src) {
            *v = shared::value(data, k);
        }
    }

    /// Numeric factorisation of the current `Q_ff` values.
    fn factorize(&mut self) -> Result<()> {
        let nf = self.rows().len();
        if nf == 0 {
            return Ok(());
        }
        let par = self.options.parallelism.to_faer();
        self.l_values.clear();
        self.l_values.resize(self.symbolic.len_val(), 0.0);
        let sym =
            SymbolicSparseColMatRef::new_checked(nf, nf, &self.ff_col_ptr, None, &self.ff_row_idx);
        let a = SparseColMatRef::new(sym, &self.ff_values);
        let mut mem = MemBuffer::try_new(
            self.symbolic
                .factorize_numeric_llt_scratch::<f64>(par, Default::default()),
        )
        .map_err(|_| SolveError::Solver("out of memory".into()))?;
        let res = self.symbolic.factorize_numeric_llt(
            &mut self.l_values,
            a,
            Side::Upper,
            LltRegularization::default(),
            par,
            MemStack::new(&mut mem),
            Default::default(),
        );
        match res {
            Ok(_) => match self.l_values.iter().position(|x| !x.is_finite()) {
                Some(index) => Err(MeshError::Overflow {
                    what: "Cholesky factor value",
                    index,
                }
                .into()),
                None => Ok(()),
            },
            Err(LltError::NonPositivePivot { index }) => {
                // `index` counts in the fill-reducing order, 1-based in faer's simplicial
                // factorisation and 0-based in its supernodal one; name the vertex.
                let index = match self.symbolic.raw() {
                    SymbolicCholeskyRaw::Simplicial(_) => index.saturating_sub(1),
                    SymbolicCholeskyRaw::Supernodal(_) => index,
                };
                let local = match self.symbolic.perm() {
                    Some(p) => p.arrays().0.get(index).map(|&i| i as usize),
                    None => Some(index),
                };
                let vertex = local.and_then(|i| self.rows().get(i));
                Err(SolveError::NotPositiveDefinite(match vertex {
                    Some(v) => format!("non-positive pivot at free vertex {v}"),
                    None => format!("non-positive pivot {index}"),
                }))
            }
        }
    }

    /// Number of rows of `Q`.
    pub fn len(&self) -> usize {
        self.n
    }

    /// True for a 0x0 system.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The constrained rows, in the order boundary values are given.
    pub fn constrained(&self) -> &[u32] {
        &self.constrained
    }

    /// The free rows, increasing.
    pub fn free(&self) -> &[u32] {
        &self.free
    }

    /// Refactors after the *values* of `Q` changed but not its sparsity pattern (nor the
    /// constrained set): the symbolic analysis is reused. Errors with
    /// [`SolveError::PatternChanged`] when the pattern differs.
    pub fn update_values(&mut self, q: &CsMat<f64>) -> Result<()> {
        let q = ensure_csr(q);
        if q.rows() != self.n
            || q.cols() != self.n
            || q.indptr().into_raw_storage() != self.q_indptr.as_slice()
            || q.indices() != self.q_indices.as_slice()
        {
            return Err(SolveError::PatternChanged);
        }
        ensure_finite(&q, "system matrix row")?;
        self.fill_values(q.data());
        self.factorize()
    }

    /// Rebuilds everything (ordering included) for a new constrained set; equivalent to
    /// [`Self::new`] with the same options.
    pub fn set_constrained(&mut self, q: &CsMat<f64>, constrained: &[u32]) -> Result<()> {
        *self = DirichletSolver::new(q, constrained, self.options)?;
        Ok(())
    }

    /// Workspace for [`Self::solve_into`] with up to `ncols` columns: allocate it once and
    /// reuse it for every solve (faer style), so that solving allocates nothing. It stays
    /// valid until [`Self::set_constrained`]; [`Self::update_values`] keeps it valid.
    pub fn scratch(&self, ncols: usize) -> Result<SolveScratch> {
        let nf = self.rows().len();
        let len = nf.checked_mul(ncols).ok_or(MeshError::Overflow {
            what: "scratch size",
            index: ncols,
        })?;
        let req = self.solve_req(ncols);
        let mem =
            MemBuffer::try_new(req).map_err(|_| SolveError::Solver("out of memory".into()))?;
        Ok(SolveScratch {
            y: vec![0.0; len],
            mem,
            free: nf,
            ncols,
            size: req.size_bytes(),
            align: req.align_bytes(),
        })
    }

    /// faer's workspace requirement of a triangular solve with `ncols` columns.
    fn solve_req(&self, ncols: usize) -> StackReq {
        if self.rows().is_empty() || ncols == 0 {
            StackReq::EMPTY
        } else {
            let par = self.options.parallelism.to_faer();
            self.symbolic.solve_in_place_scratch::<f64>(ncols, par)
        }
    }

    /// Solves with zero `b`: `boundary` holds `ncols` columns of boundary values (column-major,
    /// `constrained().len()` rows each). Returns the full `len() x ncols` solution,
    /// column-major, equal to `boundary` on the constrained rows. Allocates the result and a
    /// [`SolveScratch`]; per-frame callers use [`Self::solve_into`].
    pub fn solve(&self, boundary: &[f64], ncols: usize) -> Result<Vec<f64>> {
        let mut scratch = self.scratch(ncols)?;
        let len = self.n.checked_mul(ncols).ok_or(MeshError::Overflow {
            what: "solution size",
            index: ncols,
        })?;
        let mut out = vec![0.0; len];
        self.solve_into(None, boundary, ncols, &mut out, &mut scratch)?;
        Ok(out)
    }

    /// Like [`Self::solve`] with a right-hand side `b` (`len() x ncols`, column-major; only
    /// its free rows are used), written into `out` (`len() x ncols`), using `scratch` from
    /// [`Self::scratch`] (with at least `ncols` columns). Allocation-free with
    /// [`Parallelism::Sequential`]. Gives bit-for-bit the result of [`Self::solve`].
    ///
    /// Errors: [`MeshError::DimensionMismatch`] (buffer sizes, or a scratch too small or made
    /// for another constrained set), [`MeshError::NonFinite`] (a boundary value),
    /// [`SolveError::NotPositiveDefinite`] (a non-finite solution).
    pub fn solve_into(
        &self,
        rhs: Option<&[f64]>,
        boundary: &[f64],
        ncols: usize,
        out: &mut [f64],
        scratch: &mut SolveScratch,
    ) -> Result<()> {
        let (n, nc, nf) = (self.n, self.constrained.len(), self.rows().len());
        let check = |what, expected, got| {
            if expected == got {
                Ok(())
            } else {
                Err(MeshError::DimensionMismatch {
                    what,
                    expected,
                    got,
                })
            }
        };
        check("boundary values", nc * ncols, boundary.len())?;
        check("solution buffer", n * ncols, out.len())?;
        if let Some(b) = rhs {
            check("right-hand side", n * ncols, b.len())?;
        }
        check("free rows of the scratch", nf, scratch.free)?;
        if ncols > scratch.ncols {
            return Err(MeshError::DimensionMismatch {
                what: "columns of the scratch",
                expected: ncols,
                got: scratch.ncols,
            }
            .into());
        }
        let req = self.solve_req(ncols);
        if req.size_bytes() > scratch.size || req.align_bytes() > scratch.align {
            return Err(MeshError::DimensionMismatch {
                what: "bytes of the scratch",
                expected: req.size_bytes(),
                got: scratch.size,
            }
            .into());
        }
        if let Some(i) = boundary.iter().position(|x| !x.is_finite()) {
            let v = self.constrained[i % nc.max(1)];
            return Err(MeshError::NonFinite {
                vertices: IndexList(vec![v]),
            }
            .into());
        }
        // Reduced right-hand side b_f - Q_fc x_c, column-major nf x ncols.
        let y = &mut scratch.y[..nf * ncols];
        for c in 0..ncols {
            let bc = &boundary[c * nc..(c + 1) * nc];
            let yc = &mut y[c * nf..(c + 1) * nf];
            for (i, yi) in yc.iter_mut().enumerate() {
                let mut s = match rhs {
                    Some(b) => b[c * n + self.rows()[i] as usize],
                    None => 0.0,
                };
                for k in self.fc_ptr[i]..self.fc_ptr[i + 1] {
                    s -= self.fc_values[k] * bc[self.fc_col[k] as usize];
                }
                *yi = s;
            }
        }
        if nf > 0 && ncols > 0 {
            let par = self.options.parallelism.to_faer();
            let llt = LltRef::<FactorIndex, f64>::new(&self.symbolic, &self.l_values);
            llt.solve_in_place_with_conj(
                Conj::No,
                MatMut::from_column_major_slice_mut(y, nf, ncols),
                par,
                MemStack::new(&mut scratch.mem),
            );
        }
        for c in 0..ncols {
            let oc = &mut out[c * n..(c + 1) * n];
            for (i, &v) in self.rows().iter().enumerate() {
                oc[v as usize] = y[c * nf + i];
            }
            for (k, &v) in self.constrained.iter().enumerate() {
                oc[v as usize] = boundary[c * nc + k];
            }
        }
        if let Some(i) = out.iter().position(|x| !x.is_finite()) {
            return Err(SolveError::NotPositiveDefinite(format!(
                "non-finite solution at vertex {}",
                i % n.max(1)
            )));
        }
        Ok(())
    }
}
