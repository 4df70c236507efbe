//! Clamped uniform B-splines over motor logarithms: the basis (Cox-de Boor) and the
//! least-squares fit of control motors to key motors (first paper, section III.C, equations
//! (3)-(5)); and the Bernstein basis that Bezier keys and lattices share.
//!
//! A clamped uniform B-spline of degree `p` over `n` control points has knots `0` (`p + 1`
//! times), `k / (n - p)` for `k = 1 .. n - p - 1`, and `1` (`p + 1` times), so it starts at the
//! first control point and ends at the last: `S(0) = R_0`, `S(1) = R_{n-1}` exactly.

use crate::blend::KeyError;
use crate::deformers::Result;
use cga::{Bivector, ScaledMotor};
use nalgebra::{DMatrix, DVector};

/// The Bernstein polynomials `C(n, k) t^k (1 - t)^(n - k)`, `k = 0 ..= n`, by de Casteljau's
/// recurrence (non-negative, summing to one): `(n + 1)^2 / 2` steps.
///
/// # Panics
/// When `out` holds fewer than `n + 1` values.
pub fn bernstein(n: usize, t: f64, out: &mut [f64]) {
    out[..=n].fill(0.0);
    out[0] = 1.0;
    for j in 1..=n {
        for k in (0..=j).rev() {
            let prev = if k > 0 { out[k - 1] } else { 0.0 };
            out[k] = (1.0 - t) * out[k] + t * prev;
        }
    }
}

/// The degree used for `n` control points: cubic, lowered when there are too few points.
pub fn bspline_degree(n: usize) -> usize {
    n.saturating_sub(1).min(3)
}

/// Knot `k` of the clamped uniform knot vector of degree `p` over `n` control points.
#[inline]
pub(crate) fn knot(k: usize, n: usize, p: usize) -> f64 {
    if k <= p {
        0.0
    } else if k >= n {
        1.0
    } else {
        (k - p) as f64 / (n - p) as f64
    }
}

/// The non-zero basis functions at `t` in `[0, 1]` (clamped): writes the `p + 1` weights of
/// control points `first ..= first + p` into `out[..p + 1]` and returns `first`. The weights
/// are non-negative and sum to one.
///
/// ```
/// let mut w = [0.0; 4];
/// let first = deform::deformers::bspline::bspline_basis(6, 3, 1.0, &mut w);
/// assert_eq!((first, w), (2, [0.0, 0.0, 0.0, 1.0]));
/// ```
///
/// # Panics
/// Unless `p <= 3`, `n > p` and `out` holds `p + 1` weights (what [`bspline_degree`] gives
/// satisfies the first two).
pub fn bspline_basis(n: usize, p: usize, t: f64, out: &mut [f64]) -> usize {
    assert!(
        p <= 3 && n > p && out.len() > p,
        "bspline_basis: degree {p} over {n} control points into {} weights (needs p <= 3, \
         n > p, p + 1 weights)",
        out.len()
    );
    let t = t.clamp(0.0, 1.0);
    // The span s with knot(s) <= t < knot(s + 1), in p ..= n - 1.
    let segments = n - p;
    let s = p + ((t * segments as f64) as usize).min(segments - 1);
    let mut left = [0.0f64; 4];
    let mut right = [0.0f64; 4];
    out[0] = 1.0;
    for j in 1..=p {
        left[j] = t - knot(s + 1 - j, n, p);
        right[j] = knot(s + j, n, p) - t;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = out[r] / (right[r + 1] + left[j - r]);
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
    s - p
}

/// The spline `exp(sum_j N_j(t) log R_j)` through the control motors, at `t`.
///
/// # Errors
/// [`KeyError::WrongCount`] for fewer than 2 controls, [`KeyError::Invalid`] for a control
/// that is not a scaled motor or a blend that overflows.
pub fn bspline_motor(controls: &[ScaledMotor], t: f64) -> Result<ScaledMotor> {
    let n = controls.len();
    if n < 2 {
        return Err(KeyError::WrongCount {
            what: "a B-spline",
            expected: "at least 2".into(),
            got: n,
        }
        .into());
    }
    let p = bspline_degree(n);
    let mut w = [0.0; 4];
    let first = bspline_basis(n, p, t, &mut w);
    let mut logs = [Bivector::default(); 4];
    for k in 0..=p {
        logs[k] = controls[first + k]
            .try_log()
            .map_err(|source| KeyError::Invalid {
                index: first + k,
                source,
            })?;
    }
    Bivector::weighted_sum(logs, &w[..=p])
        .try_exp_scaled()
        .map_err(|source| {
            KeyError::Invalid {
                index: first,
                source,
            }
            .into()
        })
}

/// How the normal equations of a fit were solved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FitSolver {
    /// Cholesky factorisation of `A^T A`.
    Cholesky,
    /// SVD of `A` (when `A^T A` is ill-conditioned).
    Svd,
}

/// The control motors of a least-squares B-spline fit.
#[derive(Clone, Debug)]
pub struct BsplineFit {
    /// The `m` control motors `R_j`.
    pub controls: Vec<ScaledMotor>,
    /// The largest residual `|log Q_i - sum_j N_j(lambda_i) log R_j|` over the keys.
    pub max_residual: f64,
    /// How the system was solved.
    pub solver: FitSolver,
}

/// Reciprocal condition number of `A^T A` below which the fit switches to SVD.
const ILL_CONDITIONED: f64 = 1e-10;

/// Fit `control_count` control motors to the keys `Q_i` at parameters `lambda_i` (equations
/// (3)-(5)): `log Q = A log R` with `A_ij = N_j(lambda_i)`, in the least-squares sense, for
/// every coefficient of the logarithm (the six of a rigid motion, and the dilation when keys
/// scale). The normal equations `A^T A R = A^T Q` are solved by Cholesky, or by the SVD of `A`
/// when `A^T A` is ill-conditioned (its reciprocal condition number below `1e-10`) or
/// singular (a control point no parameter reaches).
///
/// # Errors
/// [`KeyError::BadSetup`] when `control_count < 2`, `control_count > keys.len()`, the lengths
/// differ, or a parameter is not finite; [`KeyError::ParameterOutOfRange`];
/// [`KeyError::Invalid`] for a key that is not a scaled motor or a control that overflows.
pub fn fit_bspline(
    keys: &[ScaledMotor],
    lambda: &[f64],
    control_count: usize,
) -> Result<BsplineFit> {
    let n = keys.len();
    if lambda.len() != n {
        return Err(KeyError::BadSetup(format!("{n} keys but {} parameters", lambda.len())).into());
    }
    if control_count < 2 || control_count > n {
        return Err(KeyError::BadSetup(format!(
            "{control_count} control motors for {n} keys: need 2 <= controls <= keys"
        ))
        .into());
    }
    if let Some(i) = lambda.iter().position(|l| !(0.0..=1.0).contains(l)) {
        return Err(KeyError::ParameterOutOfRange {
            index: i,
            value: lambda[i],
        }
        .into());
    }
    let m = control_count;
    let p = bspline_degree(m);
    let mut a = DMatrix::<f64>::zeros(n, m);
    let mut w = [0.0; 4];
    for (i, &l) in lambda.iter().enumerate() {
        let first = bspline_basis(m, p, l, &mut w);
        for k in 0..=p {
            a[(i, first + k)] = w[k];
        }
    }
    let mut q = DMatrix::<f64>::zeros(n, 10);
    for (i, k) in keys.iter().enumerate() {
        let b = k
            .try_log()
            .map_err(|source| KeyError::Invalid { index: i, source })?;
        for (c, v) in b.to_array().iter().enumerate() {
            q[(i, c)] = *v;
        }
    }
    let ata = a.transpose() * &a;
    let atq = a.transpose() * &q;
    let (r, solver) = match solve_normal(&ata, &atq) {
        Some(r) => (r, FitSolver::Cholesky),
        None => {
            let svd = a.clone().svd(true, true);
            let r = svd
                .solve(&q, 1e-12)
                .map_err(|e| KeyError::BadSetup(format!("SVD failed: {e}")))?;
            (r, FitSolver::Svd)
        }
    };
    let residual = &a * &r - &q;
    let max_residual = (0..n).map(|i| residual.row(i).norm()).fold(0.0, f64::max);
    let mut controls = Vec::with_capacity(m);
    for j in 0..m {
        let mut c = [0.0; 10];
        for (k, v) in c.iter_mut().enumerate() {
            *v = r[(j, k)];
        }
        let motor = Bivector::from_array(c)
            .try_exp_scaled()
            .map_err(|source| KeyError::Invalid { index: j, source })?;
        controls.push(motor);
    }
    Ok(BsplineFit {
        controls,
        max_residual,
        solver,
    })
}

/// Cholesky solve of the normal equations, or `None` when `A^T A` is singular or
/// ill-conditioned.
fn solve_normal(ata: &DMatrix<f64>, atq: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    let chol = ata.clone().cholesky()?;
    let l = chol.l();
    let d = DVector::from_iterator(l.nrows(), (0..l.nrows()).map(|i| l[(i, i)]));
    let (lo, hi) = (d.min(), d.max());
    // cond(A^T A) = cond(L)^2, estimated from the diagonal of L.
    if lo.is_nan() || lo <= 0.0 || (lo / hi).powi(2) < ILL_CONDITIONED {
        return None;
    }
    Some(chol.solve(atq))
}
