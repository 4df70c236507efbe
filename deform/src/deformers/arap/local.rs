//! The local step: the best rotation of each cell, from its covariance
//! `S = sum_j w_j e_j e'_j^T` (`e_j` rest edges, `e'_j` current edges), maximising
//! `tr(R S) = sum_j w_j e'_j . (R e_j)`.
//!
//! Two interchangeable fits:
//!
//! * [`fit_rotor`]: the paper's rotor, the eigenvector of the largest eigenvalue of Horn's
//!   symmetric 4x4 matrix `P` built from `S` (equations (11)-(12)). The eigenvalue is the
//!   largest root of `P`'s characteristic polynomial, found by Newton's method from an upper
//!   bound (from above, Newton converges monotonically to the largest root of a polynomial
//!   with real roots; for near-rigid cells the bound is almost exact, so two or three steps
//!   suffice, as in `GARotorEstimator.cpp` of arap-sr and Theobald's QCP). The eigenvector
//!   is `adj(P - lambda I) q0`: the adjugate of `P - lambda I` is a multiple of `v v^T`, so
//!   applying it to the previous iteration's rotor `q0` (the warm start) projects `q0` onto
//!   the eigenvector, with the sign of `q0`. A top eigenvalue that is (nearly) double, where
//!   the rotation is not determined, falls back to a symmetric eigen-solver.
//! * [`fit_svd`]: Sorkine and Alexa's `R = V U^T` from the SVD `S = U Sigma V^T`, with the
//!   column of the smallest singular value negated when `det(V U^T) < 0` (the reflection
//!   fix).

// `!(x > y)` is deliberate: NaN must fail every check.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::cells::{Covariance, CHUNK};
use glam::{DMat3, DQuat};
use nalgebra::{Matrix3, Matrix4, SymmetricEigen};

/// Horn's symmetric matrix `P` of the paper's equation (12), row-major, traceless.
#[inline]
pub(crate) fn horn_matrix(s: &[f64; 9]) -> [[f64; 4]; 4] {
    let [sxx, sxy, sxz, syx, syy, syz, szx, szy, szz] = *s;
    [
        [sxx + syy + szz, syz - szy, szx - sxz, sxy - syx],
        [syz - szy, sxx - syy - szz, sxy + syx, szx + sxz],
        [szx - sxz, sxy + syx, -sxx + syy - szz, syz + szy],
        [sxy - syx, szx + sxz, syz + szy, -sxx - syy + szz],
    ]
}

/// The 2x2 minors of a 4x4 matrix's first two rows (`s`) and last two rows (`c`), the
/// shared part of [`adjugate`] and [`det4`].
#[inline]
fn minors(m: &[[f64; 4]; 4]) -> ([f64; 6], [f64; 6]) {
    let s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1];
    let s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];
    let s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3];
    let s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];
    let s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3];
    let s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
    let c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3];
    let c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];
    let c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2];
    let c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];
    let c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2];
    let c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
    ([s0, s1, s2, s3, s4, s5], [c0, c1, c2, c3, c4, c5])
}

/// The adjugate of a 4x4 matrix (`adj(M) M = det(M) I`), through its 2x2 minors.
#[inline]
pub(crate) fn adjugate(m: &[[f64; 4]; 4]) -> [[f64; 4]; 4] {
    let ([s0, s1, s2, s3, s4, s5], [c0, c1, c2, c3, c4, c5]) = minors(m);
    [
        [
            m[1][1] * c5 - m[1][2] * c4 + m[1][3] * c3,
            -m[0][1] * c5 + m[0][2] * c4 - m[0][3] * c3,
            m[3][1] * s5 - m[3][2] * s4 + m[3][3] * s3,
            -m[2][1] * s5 + m[2][2] * s4 - m[2][3] * s3,
        ],
        [
            -m[1][0] * c5 + m[1][2] * c2 - m[1][3] * c1,
            m[0][0] * c5 - m[0][2] * c2 + m[0][3] * c1,
            -m[3][0] * s5 + m[3][2] * s2 - m[3][3] * s1,
            m[2][0] * s5 - m[2][2] * s2 + m[2][3] * s1,
        ],
        [
            m[1][0] * c4 - m[1][1] * c2 + m[1][3] * c0,
            -m[0][0] * c4 + m[0][1] * c2 - m[0][3] * c0,
            m[3][0] * s4 - m[3][1] * s2 + m[3][3] * s0,
            -m[2][0] * s4 + m[2][1] * s2 - m[2][3] * s0,
        ],
        [
            -m[1][0] * c3 + m[1][1] * c1 - m[1][2] * c0,
            m[0][0] * c3 - m[0][1] * c1 + m[0][2] * c0,
            -m[3][0] * s3 + m[3][1] * s1 - m[3][2] * s0,
            m[2][0] * s3 - m[2][1] * s1 + m[2][2] * s0,
        ],
    ]
}

/// `det(S)` of the row-major 3x3 matrix.
#[inline]
fn det3(s: &[f64; 9]) -> f64 {
    s[0] * (s[4] * s[8] - s[5] * s[7]) - s[1] * (s[3] * s[8] - s[5] * s[6])
        + s[2] * (s[3] * s[7] - s[4] * s[6])
}

/// `det(M)` through the 2x2 minors of its first two and last two rows.
#[inline]
fn det4(m: &[[f64; 4]; 4]) -> f64 {
    let ([s0, s1, s2, s3, s4, s5], [c0, c1, c2, c3, c4, c5]) = minors(m);
    s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0
}

/// The quaternion `(w; x, y, z)` as a glam quaternion.
#[inline]
fn quat(v: [f64; 4]) -> DQuat {
    DQuat::from_xyzw(v[1], v[2], v[3], v[0])
}

/// The rotor (as a unit quaternion) maximising `tr(R S)` for the row-major covariance
/// `s[3 r + c] = sum_j w_j e_j[r] e'_j[c]`: the paper's local step, the top eigenvector of
/// Horn's 4x4 matrix `P` (equation (12)), its eigenvalue by Newton's method on `P`'s
/// characteristic polynomial from `bound` downwards, the vector as `adj(P - lambda I) warm`
/// (a symmetric eigen-solver when the top eigenvalue is nearly double). `bound` is an upper
/// bound of `max_R tr(R S)`, such as `(sum |w| |e|^2 + sum |w| |e'|^2) / 2` (tight for
/// near-rigid cells, so Newton's method takes two or three steps), or `f64::INFINITY`
/// (`sqrt(3) |S|_F` is used when smaller); `warm` is the previous rotor (the result has its
/// sign). A zero or non-finite covariance gives `warm`.
pub fn fit_rotor(s: &[f64; 9], bound: f64, warm: DQuat) -> DQuat {
    let norm2: f64 = s.iter().map(|x| x * x).sum();
    let mut lambda = bound.min((3.0 * norm2).sqrt());
    if !(lambda > 0.0) || !lambda.is_finite() || !norm2.is_finite() {
        return warm;
    }
    let p = horn_matrix(s);
    // Characteristic polynomial of the traceless P: x^4 + c2 x^2 + c1 x + c0.
    let c2 = -2.0 * norm2;
    let c1 = -8.0 * det3(s);
    let c0 = det4(&p);
    let scale = lambda;
    for _ in 0..64 {
        let l2 = lambda * lambda;
        let f = (l2 + c2) * l2 + c1 * lambda + c0;
        let df = (4.0 * l2 + 2.0 * c2) * lambda + c1;
        if !(df > 0.0) {
            break;
        }
        let step = f / df;
        lambda -= step;
        if !(step.abs() > 1e-15 * scale) {
            break;
        }
    }
    let mut m = p;
    for (k, row) in m.iter_mut().enumerate() {
        row[k] -= lambda;
    }
    let adj = adjugate(&m);
    let q0 = [warm.w, warm.x, warm.y, warm.z];
    let mul = |a: &[[f64; 4]; 4], x: &[f64; 4]| -> [f64; 4] {
        std::array::from_fn(|r| (0..4).map(|c| a[r][c] * x[c]).sum())
    };
    let norm = |v: &[f64; 4]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let mut v = mul(&adj, &q0);
    // The adjugate is mu v v^T with |mu| ~ (gap to the other eigenvalues)^3.
    let (best_col, col_norm) =
        (0..4)
            .map(|c| (c, norm(&adj[c])))
            .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
    if !(col_norm > 1e-8 * scale * scale * scale) {
        return eigen_fallback(&p, warm);
    }
    if !(norm(&v) > 0.1 * col_norm) {
        v = adj[best_col];
    }
    let dot: f64 = v.iter().zip(&q0).map(|(a, b)| a * b).sum();
    let n = norm(&v);
    let sign = if dot < 0.0 { -1.0 } else { 1.0 };
    let q = quat(v.map(|x| sign * x / n));
    if q.is_finite() {
        q
    } else {
        eigen_fallback(&p, warm)
    }
}

/// The top eigenvector of `p` by nalgebra's symmetric eigen-solver, signed like `warm`.
fn eigen_fallback(p: &[[f64; 4]; 4], warm: DQuat) -> DQuat {
    let m = Matrix4::from_fn(|r, c| p[r][c]);
    let e = SymmetricEigen::new(m);
    let k = e.eigenvalues.imax();
    let v = e.eigenvectors.column(k);
    let q = quat([v[0], v[1], v[2], v[3]]);
    let q = if q.dot(warm) < 0.0 { -q } else { q };
    if q.is_finite() && q.length_squared() > 0.0 {
        q.normalize()
    } else {
        warm
    }
}

/// The rotation maximising `tr(R S)` (row-major covariance as in [`fit_rotor`]) by the 3x3
/// SVD `S = U Sigma V^T`: `R = V U^T`, with the column of `U` of the smallest singular value
/// negated when `det(V U^T) < 0` (the reflection fix). A zero or non-finite covariance gives
/// the identity.
pub fn fit_svd(s: &[f64; 9]) -> DMat3 {
    if s.iter().all(|&x| x == 0.0) || !s.iter().all(|x| x.is_finite()) {
        return DMat3::IDENTITY;
    }
    let m = Matrix3::from_row_slice(s);
    let svd = m.svd(true, true);
    let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else {
        return DMat3::IDENTITY;
    };
    let mut u = u;
    let v = v_t.transpose();
    if (v * u.transpose()).determinant() < 0.0 {
        let k = svd.singular_values.imin();
        u.column_mut(k).neg_mut();
    }
    let r = v * u.transpose();
    DMat3::from_cols_array(&std::array::from_fn(|i| r[(i % 3, i / 3)]))
}

/// Which fit the local step uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LocalStep {
    /// The paper's rotor: top eigenvector of Horn's 4x4 matrix, warm-started.
    #[default]
    Rotor,
    /// Sorkine and Alexa's 3x3 SVD with the reflection fix.
    Svd,
}

impl LocalStep {
    /// The name the CLI and the editor use: `rotor` or `svd`.
    pub fn name(self) -> &'static str {
        match self {
            LocalStep::Rotor => "rotor",
            LocalStep::Svd => "svd",
        }
    }
}

/// Fits every cell's rotation: `quats` hold the previous rotors on entry (the warm start)
/// and the new ones on exit (for [`LocalStep::Svd`] they are left as they were), `rots` the
/// new rotation matrices.
pub(crate) fn fit_all(
    step: LocalStep,
    cov: &[Covariance],
    b_abs: &[f64],
    quats: &mut [DQuat],
    rots: &mut [DMat3],
) {
    use rayon::prelude::*;
    quats
        .par_chunks_mut(CHUNK)
        .zip(rots.par_chunks_mut(CHUNK))
        .enumerate()
        .for_each(|(chunk, (qs, rs))| {
            let base = chunk * CHUNK;
            for (k, (q, r)) in qs.iter_mut().zip(rs.iter_mut()).enumerate() {
                let c = &cov[base + k];
                match step {
                    LocalStep::Rotor => {
                        *q = fit_rotor(&c.s, 0.5 * (c.a_abs + b_abs[base + k]), *q);
                        *r = DMat3::from_quat(*q);
                    }
                    LocalStep::Svd => *r = fit_svd(&c.s),
                }
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A deterministic pseudo-random generator for the tests.
    fn rng(seed: &mut u64) -> f64 {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }

    fn covariance(
        r: DQuat,
        seed: &mut u64,
        noise: f64,
        negative: bool,
    ) -> (Covariance, f64, DMat3) {
        let mut c = Covariance::default();
        let mut b = 0.0;
        for k in 0..6 {
            let e = DVec3::new(rng(seed), rng(seed), 0.3 * rng(seed));
            let e1 = r * e + noise * DVec3::new(rng(seed), rng(seed), rng(seed));
            let w = if negative && k == 2 {
                -0.1
            } else {
                0.5 + rng(seed).abs()
            };
            c.add(w, w * e, e1);
            b += w.abs() * e.length_squared();
        }
        let bound = 0.5 * (b + c.a_abs);
        (c, bound, DMat3::from_quat(r))
    }

    #[test]
    fn adjugate_times_matrix_is_determinant() {
        let mut seed = 7;
        let m: [[f64; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| rng(&mut seed)));
        let a = adjugate(&m);
        let det = det4(&m);
        for (r, row) in a.iter().enumerate() {
            for c in 0..4 {
                let x: f64 = row.iter().zip(m.iter()).map(|(a, mk)| a * mk[c]).sum();
                let want = if r == c { det } else { 0.0 };
                assert!((x - want).abs() < 1e-12, "{r} {c}: {x} vs {want}");
            }
        }
    }

    #[test]
    fn rotor_and_svd_recover_the_rotation() {
        let mut seed = 3;
        for case in 0..200 {
            let axis = DVec3::new(rng(&mut seed), rng(&mut seed), rng(&mut seed));
            let r = DQuat::from_axis_angle(axis.normalize(), 3.0 * rng(&mut seed));
            let noise = if case % 2 == 0 { 0.0 } else { 0.05 };
            let (c, bound, m) = covariance(r, &mut seed, noise, case % 3 == 0);
            let q = fit_rotor(&c.s, bound, DQuat::IDENTITY);
            let from_rotor = DMat3::from_quat(q);
            let from_svd = fit_svd(&c.s);
            assert!(
                from_rotor.abs_diff_eq(from_svd, 1e-9),
                "case {case}: {from_rotor} vs {from_svd}"
            );
            if noise == 0.0 {
                assert!(from_rotor.abs_diff_eq(m, 1e-9), "case {case}");
            }
            // The warm start changes nothing but the sign.
            let q2 = fit_rotor(&c.s, bound, -q);
            assert!((q2 + q).length() < 1e-9, "case {case}");
        }
    }

    #[test]
    fn degenerate_covariances_are_finite() {
        let q = fit_rotor(&[0.0; 9], 0.0, DQuat::IDENTITY);
        assert_eq!(q, DQuat::IDENTITY);
        assert_eq!(fit_svd(&[0.0; 9]), DMat3::IDENTITY);
        // Rank one: every edge along x.
        let s = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let q = fit_rotor(&s, 1.0, DQuat::IDENTITY);
        assert!(q.is_finite() && (q.length() - 1.0).abs() < 1e-12);
        assert!((q * DVec3::X - DVec3::X).length() < 1e-9);
    }
}
