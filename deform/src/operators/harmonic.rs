//! Harmonic (and biharmonic) fields with Dirichlet conditions, section VIII of
//! López Belón, "Applications of conformal geometric algebra in mesh deformation".
//!
//! The field `x` minimises the discrete Dirichlet energy `-x^T L x` (order 1: `L x = 0` at
//! the free vertices) or the Laplacian energy `x^T L M^-1 L x` (order 2: `L M^-1 L x = 0`),
//! with prescribed values on the constrained vertex sets.

use crate::mesh::validate::check_solvable;
use crate::mesh::validate::Scan;
use crate::mesh::IndexList;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::operators::laplacian::ensure_finite;
use crate::operators::laplacian::laplacian_on;
use crate::operators::laplacian::pattern_of;
use crate::operators::laplacian::LaplacianKind;
use crate::operators::mass::mass_diagonal;
use crate::operators::mass::MassKind;
use crate::operators::pattern::LaplacianPattern;
use crate::operators::solve::check_constrained;
use crate::operators::solve::DirichletSolver;
use crate::operators::solve::Factorization;
use crate::operators::solve::SolverOptions;
use crate::operators::solve::SystemAnalysis;
use crate::operators::Result;
use crate::operators::SolveError;
use sprs::CsMat;

/// Options for [`Harmonic`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicOptions {
    /// The Laplacian (default: libigl's cotangent matrix).
    pub laplacian: LaplacianKind,
    /// 1 for harmonic, 2 for biharmonic.
    pub order: u32,
    /// Mass matrix used for `order = 2`.
    pub mass: MassKind,
    /// Factorisation settings (default: [`SolverOptions`]'s, with the supernodal layout,
    /// the fastest to compute for a system solved once).
    pub solver: SolverOptions,
}

impl Default for HarmonicOptions {
    fn default() -> Self {
        HarmonicOptions {
            laplacian: LaplacianKind::Default,
            order: 1,
            mass: MassKind::Voronoi,
            solver: SolverOptions {
                factorization: Factorization::Supernodal,
                ..SolverOptions::default()
            },
        }
    }
}

/// The most nonzeros [`harmonic_system`] lets `L M^-1 L` have: this many per nonzero of `L`
/// (a regular triangle mesh needs about 3), or [`BIHARMONIC_FILL_FLOOR`] if that is larger.
pub const BIHARMONIC_FILL_PER_NONZERO: usize = 32;

/// The smallest fill limit of `L M^-1 L` (about 16 MB of values and indices).
pub const BIHARMONIC_FILL_FLOOR: usize = 1 << 20;

/// The symmetric positive semi-definite system matrix: `-L` for order 1, a positive multiple
/// of `L M^-1 L` for order 2 (`L` and `M` are divided by their largest entries first, which
/// keeps the product in floating-point range at any mesh scale and leaves the minimiser
/// unchanged). Checks the mesh first ([`crate::mesh::validate::check_solvable`]).
///
/// Errors, besides the mesh checks: [`SolveError::ZeroMass`] (order 2, a vertex whose triangles
/// are all degenerate), [`SolveError::TooDense`] (order 2, when an upper bound of the nonzeros of
/// `L M^-1 L`, the sum over vertices of the squared row lengths of `L`, exceeds
/// [`BIHARMONIC_FILL_PER_NONZERO`] times the nonzeros of `L` and [`BIHARMONIC_FILL_FLOOR`]:
/// a fan-triangulated polygon with thousands of corners would make it dense),
/// [`MeshError::Overflow`] (a non-finite entry).
pub fn harmonic_system(mesh: &Mesh, options: &HarmonicOptions) -> Result<CsMat<f64>> {
    check_solvable(mesh)?;
    checked_system(mesh, options, &pattern_of(mesh))
}

/// [`harmonic_system`] of a mesh that passed the checks, its Laplacian assembled into
/// `pattern` (the mesh's).
fn checked_system(
    mesh: &Mesh,
    options: &HarmonicOptions,
    pattern: &LaplacianPattern,
) -> Result<CsMat<f64>> {
    let mut l = laplacian_on(mesh, options.laplacian, pattern)?;
    match options.order {
        1 => {
            l.data_mut().iter_mut().for_each(|x| *x = -*x);
            Ok(l)
        }
        2 => {
            let estimated: usize = l.outer_iterator().map(|r| r.nnz() * r.nnz()).sum();
            let limit = (BIHARMONIC_FILL_PER_NONZERO * l.nnz()).max(BIHARMONIC_FILL_FLOOR);
            if estimated > limit {
                return Err(SolveError::TooDense {
                    what: "the biharmonic matrix L M^-1 L",
                    estimated,
                    limit,
                });
            }
            let m = mass_diagonal(mesh, options.mass)?;
            let lmax = l.data().iter().fold(0.0f64, |a, x| a.max(x.abs()));
            let mmax = m.iter().copied().fold(0.0f64, f64::max);
            let mut zero = Vec::new();
            let minv: Vec<f64> = (0..m.len())
                .map(|i| {
                    if m[i] > 0.0 {
                        // (L / lmax) rows scaled by mmax / m_i, at most 1 / lmax each.
                        (mmax / m[i]) / lmax
                    } else {
                        let row = l.outer_view(i).map(|r| r.data().iter().any(|&x| x != 0.0));
                        if row == Some(true) {
                            zero.push(i as u32);
                        }
                        0.0
                    }
                })
                .collect();
            if !zero.is_empty() {
                return Err(SolveError::ZeroMass {
                    vertices: IndexList(zero),
                });
            }
            if lmax == 0.0 {
                return Ok(&l * &l);
            }
            // (M / mmax)^-1 (L / lmax) scales rows; L is symmetric so L (M^-1 L) = L^T M^-1 L.
            let mut ml = l.clone();
            let indptr = ml.indptr().into_raw_storage().to_vec();
            let data = ml.data_mut();
            for (i, w) in minv.iter().enumerate() {
                data[indptr[i]..indptr[i + 1]]
                    .iter_mut()
                    .for_each(|x| *x *= w);
            }
            l.data_mut().iter_mut().for_each(|x| *x /= lmax);
            let q = &l * &ml;
            ensure_finite(&q, "biharmonic matrix row")?;
            Ok(q)
        }
        k => {
            Err(MeshError::InvalidArgument(format!("harmonic order {k} (supported: 1, 2)")).into())
        }
    }
}

/// A prefactored harmonic problem over several disjoint constrained vertex sets, each
/// holding one value per field.
///
/// ```
/// use deform::operators::harmonic::{Harmonic, HarmonicOptions};
/// use deform::Mesh;
/// use glam::DVec3;
/// // A 3x1 strip of squares along x; fix the left edge to 0, the right edge to 1.
/// let p: Vec<DVec3> = (0..8).map(|i| DVec3::new((i % 4) as f64, (i / 4) as f64, 0.0)).collect();
/// let t = (0..3).flat_map(|i| [[i, i + 1, i + 5], [i, i + 5, i + 4]]).collect();
/// let h = Harmonic::new(&Mesh::new(p, t), &[&[0, 4], &[3, 7]], HarmonicOptions::default()).unwrap();
/// let x = h.field(&[0.0, 1.0]).unwrap();
/// assert!((x[1] - 1.0 / 3.0).abs() < 1e-12 && (x[6] - 2.0 / 3.0).abs() < 1e-12);
/// ```
#[derive(Debug)]
pub struct Harmonic {
    solver: DirichletSolver,
    /// `constrained[starts[s]..starts[s + 1]]` is set `s`.
    starts: Vec<usize>,
}

impl Harmonic {
    /// Validates the mesh and the sets, builds the system and factorises it.
    ///
    /// Errors: [`MeshError::EmptyMesh`], [`MeshError::FaceIndexOutOfRange`], [`MeshError::NonFinite`],
    /// [`MeshError::NonManifold`], [`MeshError::ConstraintOutOfRange`],
    /// [`MeshError::OverlappingConstraints`] (a vertex in two sets or twice in one),
    /// [`SolveError::Unconstrained`] (a component without constrained vertices, e.g. unreferenced
    /// vertices: run [`crate::mesh::validate::clean()`]), [`SolveError::NotPositiveDefinite`].
    pub fn new(mesh: &Mesh, sets: &[&[u32]], options: HarmonicOptions) -> Result<Self> {
        let n = mesh.positions.len();
        let constrained = constrained_of(n, sets)?;
        let in_range = mesh.triangles.iter().flatten().all(|&v| (v as usize) < n);
        if options.order != 1 || !in_range {
            let q = harmonic_system(mesh, &options)?;
            let solver = DirichletSolver::new(&q, &constrained, options.solver)?;
            return Ok(Harmonic::of(solver, sets));
        }
        // -L has the Laplacian's pattern, laid out from the checks' edge table when every
        // triangle is usable: order it while the rest of the checks and the weights run.
        let scan = Scan::new(mesh, false);
        let pattern = if scan.covers_all() {
            LaplacianPattern::from_edges(n, &mesh.triangles, &scan.edges)
        } else {
            pattern_of(mesh)
        };
        let solver = DirichletSolver::overlapped(
            &pattern.indptr,
            &pattern.indices,
            &constrained,
            options.solver,
            || {
                scan.check_solvable()?;
                checked_system(mesh, &options, &pattern)
            },
        )?;
        Ok(Harmonic::of(solver, sets))
    }

    /// [`Harmonic::new`] with the system matrix already analysed ([`SystemAnalysis`] of
    /// [`harmonic_system`]): only the numeric factorisation is computed, so a new selection on
    /// the same mesh skips the matrix and its ordering (interactive rebinding).
    ///
    /// # Errors
    /// As [`Harmonic::new`] for the sets (checked against the analysed matrix's size).
    pub fn with_analysis(
        analysis: &SystemAnalysis,
        sets: &[&[u32]],
        solver: SolverOptions,
    ) -> Result<Self> {
        let constrained = constrained_of(analysis.len(), sets)?;
        let solver = DirichletSolver::with_analysis(analysis, &constrained, solver)?;
        Ok(Harmonic::of(solver, sets))
    }

    /// The sets' start offsets in the solver's constrained list.
    fn of(solver: DirichletSolver, sets: &[&[u32]]) -> Harmonic {
        let mut starts = vec![0];
        for s in sets {
            starts.push(starts.last().copied().unwrap_or(0) + s.len());
        }
        Harmonic { solver, starts }
    }

    /// How many constrained sets there are (the values per field).
    pub fn set_count(&self) -> usize {
        self.starts.len() - 1
    }

    /// The underlying prefactored solver (constrained rows are the sets concatenated).
    pub fn solver(&self) -> &DirichletSolver {
        &self.solver
    }

    /// Boundary values `values[s]` on set `s` for every field (`values` is
    /// `set_count() x ncols`, column-major) expanded to one value per constrained vertex.
    fn expand(&self, values: &[f64], ncols: usize) -> Result<Vec<f64>> {
        let m = self.set_count();
        let expected = m.checked_mul(ncols).ok_or(MeshError::Overflow {
            what: "values per set (sets times columns)",
            index: ncols,
        })?;
        if values.len() != expected {
            return Err(MeshError::DimensionMismatch {
                what: "values per set",
                expected,
                got: values.len(),
            }
            .into());
        }
        let nc = self.solver.constrained().len();
        let mut bc = vec![0.0; nc * ncols];
        for c in 0..ncols {
            for s in 0..m {
                bc[c * nc + self.starts[s]..c * nc + self.starts[s + 1]].fill(values[c * m + s]);
            }
        }
        Ok(bc)
    }

    /// The field with value `values[s]` on set `s`.
    pub fn field(&self, values: &[f64]) -> Result<Vec<f64>> {
        self.solver.solve(&self.expand(values, 1)?, 1)
    }

    /// Several fields at once: `values` is `set_count() x ncols`, column-major; the result is
    /// `vertex_count x ncols`, column-major.
    pub fn fields(&self, values: &[f64], ncols: usize) -> Result<Vec<f64>> {
        self.solver.solve(&self.expand(values, ncols)?, ncols)
    }

    /// Harmonic coordinates: field `j` is 1 on set `j` and 0 on the others. For order 1 (a
    /// maximum principle holds for the mean-value and uniform Laplacians, and for cotangent
    /// weights on meshes without obtuse angles) they lie in `[0, 1]`; for any order they sum
    /// to one at every vertex (up to rounding).
    pub fn coordinates(&self) -> Result<Vec<Vec<f64>>> {
        let m = self.set_count();
        let mut id = vec![0.0; m * m];
        for j in 0..m {
            id[j * m + j] = 1.0;
        }
        let all = self.fields(&id, m)?;
        let n = self.solver.len();
        Ok((0..m).map(|j| all[j * n..(j + 1) * n].to_vec()).collect())
    }
}

/// The harmonic field that is 0 on `fixed` and 1 on `handles` (paper, section VIII).
///
/// Pass the union of several fixed (or handle) sets as one slice.
pub fn harmonic_field(
    mesh: &Mesh,
    fixed: &[u32],
    handles: &[u32],
    options: HarmonicOptions,
) -> Result<Vec<f64>> {
    Harmonic::new(mesh, &[fixed, handles], options)?.field(&[0.0, 1.0])
}

/// Per-handle harmonic coordinates: one field per set, 1 on it and 0 on the other sets; they
/// form a partition of unity.
pub fn harmonic_coordinates(
    mesh: &Mesh,
    sets: &[&[u32]],
    options: HarmonicOptions,
) -> Result<Vec<Vec<f64>>> {
    Harmonic::new(mesh, sets, options)?.coordinates()
}

/// The sets' vertices in order, checked: in range of `n` and in one set at most (the checks
/// of every constrained list, [`crate::operators::solve::check_constrained`]).
pub(crate) fn constrained_of(n: usize, sets: &[&[u32]]) -> Result<Vec<u32>> {
    let constrained: Vec<u32> = sets.iter().flat_map(|s| s.iter().copied()).collect();
    check_constrained(n, &constrained)?;
    Ok(constrained)
}
