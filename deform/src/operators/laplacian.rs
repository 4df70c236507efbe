//! Discrete Laplacians as `sprs::CsMat<f64>` (CSR, symmetric, negative semi-definite).
//!
//! All three follow libigl's sign convention: `L_ij = w_ij >= 0`-ish off the diagonal for
//! every edge `ij`, `L_ii = -sum_j L_ij`, so every row sums to zero, constants are in the
//! null space and `-L` is positive semi-definite. Nothing is divided by area (use
//! [`crate::operators::mass::mass_matrix`] for that). The sparsity pattern is always the diagonal plus every
//! mesh edge (entries may be zero), so matrices of the same mesh share one pattern.
//!
//! Angles are computed scale-invariantly (see [`crate::mesh::is_degenerate_triangle`]): the
//! cotangent Laplacian of a mesh scaled by `1e-300` or `1e300` is the same matrix. The
//! mean-value weights have units of 1/length and are checked after assembly; a matrix with a
//! non-finite entry is [`MeshError::Overflow`], never `Ok`.
//!
//! Out-of-range triangle indices and non-finite coordinates, or coordinates beyond
//! [`MAX_COORDINATE`](crate::mesh::validate::MAX_COORDINATE), are refused first ([`check_elements`]).

use crate::mesh::triangle::Frame;
use crate::mesh::validate::check_elements;
use crate::mesh::IndexList;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::operators::pattern::LaplacianPattern;
use crate::operators::Result;
use sprs::CsMat;

/// What to do with triangles of (numerically) zero area, see
/// [`crate::mesh::is_degenerate_triangle`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DegeneratePolicy {
    /// Skip them: they add nothing to any weight (their cotangents are infinite or undefined,
    /// and a linear function's gradient over a zero-area triangle is meaningless). Their edges
    /// stay in the sparsity pattern. If this leaves a vertex without weights the solver
    /// reports it as unconstrained.
    #[default]
    Skip,
    /// Fail with [`MeshError::DegenerateTriangles`] naming them.
    Error,
}

/// Options for [`cotangent_laplacian`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CotangentOptions {
    /// Clamp negative edge weights to zero (after summing the two half-weights of an edge),
    /// as CGAL does for ARAP. Off by default, like libigl: with obtuse triangles a weight
    /// `(cot a + cot b) / 2` can be negative, but `-L` stays positive semi-definite anyway.
    pub clamp_negative: bool,
    /// Treatment of zero-area triangles.
    pub degenerate: DegeneratePolicy,
}

/// Which Laplacian to build (see [`laplacian`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum LaplacianKind {
    /// Cotangent weights [`cotangent_laplacian`].
    Cotangent(CotangentOptions),
    /// Symmetrised mean-value weights [`mean_value_laplacian`].
    MeanValue,
    /// Uniform (graph) weights [`uniform_laplacian`].
    Uniform,
    /// libigl-compatible default: cotangent without clamping, degenerate triangles skipped.
    #[default]
    Default,
}

/// Builds the Laplacian of the given kind.
pub fn laplacian(mesh: &Mesh, kind: LaplacianKind) -> Result<CsMat<f64>> {
    check_elements(mesh)?;
    laplacian_on(mesh, kind, &pattern_of(mesh))
}

/// The pattern of every Laplacian of `mesh`.
pub(crate) fn pattern_of(mesh: &Mesh) -> LaplacianPattern {
    LaplacianPattern::new(mesh.positions.len(), &mesh.triangles)
}

/// [`laplacian`] assembled into the mesh's pattern, already built.
pub(crate) fn laplacian_on(
    mesh: &Mesh,
    kind: LaplacianKind,
    pattern: &LaplacianPattern,
) -> Result<CsMat<f64>> {
    match kind {
        LaplacianKind::Cotangent(o) => cotangent(mesh, o, pattern),
        LaplacianKind::Default => cotangent(mesh, CotangentOptions::default(), pattern),
        LaplacianKind::MeanValue => mean_value(mesh, true, pattern),
        LaplacianKind::Uniform => Ok(uniform(mesh, pattern)),
    }
}

/// The cotangent Laplacian, libigl's `cotmatrix`: `L_ij = (cot a_ij + cot b_ij) / 2` where
/// `a_ij, b_ij` are the angles opposite edge `ij`, `L_ii = -sum_j L_ij`. A boundary edge has
/// only one angle. Obtuse angles give negative cotangents and these are kept unless
/// [`CotangentOptions::clamp_negative`]; zero-area triangles follow
/// [`CotangentOptions::degenerate`].
///
/// ```
/// use deform::operators::laplacian::cotangent_laplacian;
/// use deform::Mesh;
/// use glam::DVec3;
/// // A right isosceles triangle: the right angle (cot 0) faces the hypotenuse.
/// let m = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
/// let l = cotangent_laplacian(&m, Default::default()).unwrap();
/// assert!((l.get(0, 1).unwrap() - 0.5).abs() < 1e-15);
/// assert!(l.get(1, 2).unwrap().abs() < 1e-15);
/// assert!((l.get(0, 0).unwrap() + 1.0).abs() < 1e-15);
/// ```
pub fn cotangent_laplacian(mesh: &Mesh, options: CotangentOptions) -> Result<CsMat<f64>> {
    check_elements(mesh)?;
    cotangent(mesh, options, &pattern_of(mesh))
}

fn cotangent(
    mesh: &Mesh,
    options: CotangentOptions,
    pattern: &LaplacianPattern,
) -> Result<CsMat<f64>> {
    // Each triangle's weights computed as they are added (`None`: degenerate, skipped).
    let mut degenerate = Vec::new();
    let mut l = pattern.assemble_with(&mesh.triangles, |f, t| {
        let frame = Frame::new(t.map(|v| mesh.positions[v as usize]));
        if frame.is_none() {
            degenerate.push(f as u32);
        }
        frame.map(|frame| frame.half_cotangents().map(|w| [w, w]))
    });
    if options.degenerate == DegeneratePolicy::Error && !degenerate.is_empty() {
        return Err(MeshError::DegenerateTriangles {
            faces: IndexList(degenerate),
        }
        .into());
    }
    if options.clamp_negative {
        for_each_off_diagonal(&mut l, |w| *w = w.max(0.0));
        rebuild_diagonal(&mut l);
    }
    ensure_finite(&l, "cotangent Laplacian row")?;
    Ok(l)
}

/// The mean-value Laplacian (Floater 2003), symmetrised.
///
/// Floater's weight of the directed edge `i -> j` is
/// `w_ij = (tan(a_ij / 2) + tan(b_ij / 2)) / |p_j - p_i|`, where `a_ij, b_ij` are the angles
/// *at `p_i`* of the two triangles sharing edge `ij`. These weights are positive for any
/// non-degenerate triangle but not symmetric (`w_ij != w_ji`). We use the symmetric part
/// `(w_ij + w_ji) / 2` as the edge weight, so `L` is a weighted graph Laplacian with positive
/// weights: symmetric, negative semi-definite, and `-L` restricted to the free vertices is
/// symmetric positive definite when every component has a constrained vertex (a
/// Cholesky-friendly system). The per-row normalisation `1 / sum_j w_ij` of the paper's
/// eq. (14) only scales rows; it does not change the solution of `L x = 0` with Dirichlet
/// values and is left out to keep the matrix symmetric. Zero-area triangles are skipped.
///
/// ```
/// use deform::operators::laplacian::mean_value_laplacian;
/// use deform::Mesh;
/// use glam::DVec3;
/// let m = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
/// let l = mean_value_laplacian(&m).unwrap();
/// // Edge 0-1 (length 1): tan(90°/2) at vertex 0 and tan(45°/2) at vertex 1, averaged.
/// let expect = (1.0 + std::f64::consts::FRAC_PI_8.tan()) / 2.0;
/// assert!((l.get(0, 1).unwrap() - expect).abs() < 1e-15);
/// ```
pub fn mean_value_laplacian(mesh: &Mesh) -> Result<CsMat<f64>> {
    check_elements(mesh)?;
    mean_value(mesh, true, &pattern_of(mesh))
}

/// Floater's original, non-symmetric mean-value matrix: row `i` holds the directed weights
/// `w_ij` (see [`mean_value_laplacian`]) and `-sum_j w_ij` on the diagonal. Dividing row `i`
/// by `sum_j w_ij` gives the mean-value coordinates, which reproduce linear functions on a
/// planar mesh (the symmetrised matrix does not).
pub fn mean_value_weights(mesh: &Mesh) -> Result<CsMat<f64>> {
    check_elements(mesh)?;
    mean_value(mesh, false, &pattern_of(mesh))
}

fn mean_value(mesh: &Mesh, symmetric: bool, pattern: &LaplacianPattern) -> Result<CsMat<f64>> {
    let weights: Vec<[[f64; 2]; 3]> = mesh
        .triangles
        .iter()
        .map(|t| {
            let Some(f) = Frame::new(t.map(|v| mesh.positions[v as usize])) else {
                return [[0.0; 2]; 3];
            };
            let th = f.tan_half_angles();
            std::array::from_fn(|k| {
                let (a, b) = ((k + 1) % 3, (k + 2) % 3);
                // Weights are 1/length: divide in normalised units, then scale back.
                let inv = |x: f64| f.unscale(x / f.edge_length(k), -1);
                if symmetric {
                    let w = inv(0.5 * (th[a] + th[b]));
                    [w, w]
                } else {
                    [inv(th[a]), inv(th[b])]
                }
            })
        })
        .collect();
    let l = pattern.assemble(&mesh.triangles, &weights);
    ensure_finite(&l, "mean-value Laplacian row")?;
    Ok(l)
}

/// [`MeshError::Overflow`] naming the first row of `m` with a non-finite entry.
pub(crate) fn ensure_finite(m: &CsMat<f64>, what: &'static str) -> Result<()> {
    match m
        .outer_iterator()
        .position(|r| r.data().iter().any(|x| !x.is_finite()))
    {
        Some(index) => Err(MeshError::Overflow { what, index }.into()),
        None => Ok(()),
    }
}

/// The uniform (graph) Laplacian: `L_ij = 1` for every edge, `L_ii = -valence(i)`.
///
/// ```
/// use deform::operators::laplacian::uniform_laplacian;
/// use deform::Mesh;
/// use glam::DVec3;
/// let m = Mesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE], vec![[0, 1, 2], [1, 3, 2]]);
/// let l = uniform_laplacian(&m).unwrap();
/// assert_eq!(l.get(1, 1), Some(&-3.0));
/// assert_eq!(l.get(1, 2), Some(&1.0));
/// ```
pub fn uniform_laplacian(mesh: &Mesh) -> Result<CsMat<f64>> {
    check_elements(mesh)?;
    Ok(uniform(mesh, &pattern_of(mesh)))
}

fn uniform(mesh: &Mesh, pattern: &LaplacianPattern) -> CsMat<f64> {
    let weights = vec![[[1.0; 2]; 3]; mesh.triangles.len()];
    let mut l = pattern.assemble(&mesh.triangles, &weights);
    for_each_off_diagonal(&mut l, |w| *w = 1.0);
    rebuild_diagonal(&mut l);
    l
}

/// Applies `f` to every stored off-diagonal value.
fn for_each_off_diagonal(m: &mut CsMat<f64>, mut f: impl FnMut(&mut f64)) {
    let n = m.rows();
    let indptr = m.indptr().into_raw_storage().to_vec();
    let indices = m.indices().to_vec();
    let data = m.data_mut();
    for i in 0..n {
        for k in indptr[i]..indptr[i + 1] {
            if indices[k] != i {
                f(&mut data[k]);
            }
        }
    }
}

/// Sets every diagonal entry to minus the sum of the row's off-diagonal entries.
pub(crate) fn rebuild_diagonal(m: &mut CsMat<f64>) {
    let n = m.rows();
    let indptr = m.indptr().into_raw_storage().to_vec();
    let indices = m.indices().to_vec();
    let data = m.data_mut();
    for i in 0..n {
        let mut sum = 0.0;
        let mut diag = None;
        for k in indptr[i]..indptr[i + 1] {
            if indices[k] == i {
                diag = Some(k);
            } else {
                sum += data[k];
            }
        }
        if let Some(k) = diag {
            data[k] = -sum;
        }
    }
}

/// Assembles `L` from per-triangle edge weights (see [`LaplacianPattern::assemble`]). The
/// pattern is the diagonal plus all edges, rows sorted, duplicates summed.
pub(crate) fn assemble(n: usize, triangles: &[[u32; 3]], weights: &[[[f64; 2]; 3]]) -> CsMat<f64> {
    LaplacianPattern::new(n, triangles).assemble(triangles, weights)
}
