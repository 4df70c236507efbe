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
/// singular (a control point no parameter reaches). To fit many key sets at the same
/// parameters, prepare a [`BsplineFitter`] once.
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
    let fitter = BsplineFitter::new(lambda, control_count)?;
    let mut scratch = FitScratch::default();
    let mut controls = vec![ScaledMotor::IDENTITY; control_count];
    let max_residual = fitter.fit_into(keys, &mut scratch, &mut controls)?;
    Ok(BsplineFit {
        controls,
        max_residual,
        solver: fitter.solver,
    })
}

/// The least-squares fit of [`fit_bspline`] prepared for fixed parameters `lambda_i` (bind
/// once, fit many key sets): the basis matrix `A` and the matrix `S` with `log R = S log Q`,
/// `S = (A^T A)^-1 A^T` by Cholesky, or the pseudo-inverse of `A` by SVD.
#[derive(Clone, Debug)]
pub struct BsplineFitter {
    /// `A_ij = N_j(lambda_i)`: keys by controls.
    basis: DMatrix<f64>,
    /// `S`: controls by keys.
    solve: DMatrix<f64>,
    solver: FitSolver,
}

/// The logarithms a [`BsplineFitter`] works on, kept by the caller between fits so that a fit
/// allocates nothing.
#[derive(Clone, Debug, Default)]
pub struct FitScratch {
    keys: Vec<[f64; 10]>,
    controls: Vec<[f64; 10]>,
}

impl BsplineFitter {
    /// Prepare the fit of `control_count` controls to keys at `lambda`.
    ///
    /// # Errors
    /// As [`fit_bspline`]'s setup: `control_count` below 2 or above the number of parameters,
    /// a parameter outside `[0, 1]`, or an SVD that fails.
    pub fn new(lambda: &[f64], control_count: usize) -> Result<Self> {
        let n = lambda.len();
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
        let at = a.transpose();
        let (solve, solver) = match solve_normal(&(&at * &a), &at) {
            Some(s) => (s, FitSolver::Cholesky),
            None => {
                let s = a
                    .clone()
                    .svd(true, true)
                    .pseudo_inverse(1e-12)
                    .map_err(|e| KeyError::BadSetup(format!("SVD failed: {e}")))?;
                (s, FitSolver::Svd)
            }
        };
        Ok(BsplineFitter {
            basis: a,
            solve,
            solver,
        })
    }

    /// How the normal equations were solved.
    pub fn solver(&self) -> FitSolver {
        self.solver
    }

    /// Fit the controls to `keys` (one per parameter), written to `controls` (one per
    /// control); returns the largest residual `|log Q_i - sum_j N_j(lambda_i) log R_j|`.
    /// Allocation-free once `scratch` has served a fit of this size.
    ///
    /// # Errors
    /// [`KeyError::BadSetup`] when the counts differ from the prepared ones;
    /// [`KeyError::Invalid`] for a key that is not a scaled motor or a control that overflows.
    pub fn fit_into(
        &self,
        keys: &[ScaledMotor],
        scratch: &mut FitScratch,
        controls: &mut [ScaledMotor],
    ) -> Result<f64> {
        let (n, m) = self.basis.shape();
        if keys.len() != n || controls.len() != m {
            return Err(KeyError::BadSetup(format!(
                "{} keys and {} controls for a fit of {n} keys and {m} controls",
                keys.len(),
                controls.len()
            ))
            .into());
        }
        scratch.keys.resize(n, [0.0; 10]);
        scratch.controls.resize(m, [0.0; 10]);
        for (i, (k, q)) in keys.iter().zip(&mut scratch.keys).enumerate() {
            let b = k
                .try_log()
                .map_err(|source| KeyError::Invalid { index: i, source })?;
            *q = b.to_array();
        }
        for (j, r) in scratch.controls.iter_mut().enumerate() {
            *r = [0.0; 10];
            for (i, q) in scratch.keys.iter().enumerate() {
                let s = self.solve[(j, i)];
                r.iter_mut().zip(q).for_each(|(r, q)| *r += s * q);
            }
        }
        let mut max_residual: f64 = 0.0;
        for (i, q) in scratch.keys.iter().enumerate() {
            let mut e = q.map(|x| -x);
            for (j, r) in scratch.controls.iter().enumerate() {
                let a = self.basis[(i, j)];
                e.iter_mut().zip(r).for_each(|(e, r)| *e += a * r);
            }
            max_residual = max_residual.max(e.iter().map(|e| e * e).sum::<f64>().sqrt());
        }
        for (j, (r, c)) in scratch.controls.iter().zip(controls).enumerate() {
            *c = Bivector::from_array(*r)
                .try_exp_scaled()
                .map_err(|source| KeyError::Invalid { index: j, source })?;
        }
        Ok(max_residual)
    }
}

/// Cholesky solve of the normal equations `A^T A X = rhs`, or `None` when `A^T A` is singular
/// or ill-conditioned.
fn solve_normal(ata: &DMatrix<f64>, rhs: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    let chol = ata.clone().cholesky()?;
    let l = chol.l();
    let d = DVector::from_iterator(l.nrows(), (0..l.nrows()).map(|i| l[(i, i)]));
    let (lo, hi) = (d.min(), d.max());
    // cond(A^T A) = cond(L)^2, estimated from the diagonal of L.
    if lo.is_nan() || lo <= 0.0 || (lo / hi).powi(2) < ILL_CONDITIONED {
        return None;
    }
    Some(chol.solve(rhs))
}
