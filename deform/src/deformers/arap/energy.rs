//! Cell covariances at the current positions and the energy they give.
//!
//! The energy of positions `p'` with rotations `R_i` is
//! `E = sum_i sum_(j, k) w_jk |(p'_j - p'_k) - R_i (p_j - p_k)|^2` over the edges `(j, k)` of
//! each cell `i`: the spokes `(i, j)` of its one-ring (the spokes energy, each undirected
//! edge once per endpoint), or every edge of every triangle around `i` (spokes and rims).
//! Expanding the square, a cell contributes `A_i + B_i - 2 tr(R_i S_i)` with
//! `A_i = sum w |e'|^2`, `B_i = sum w |e|^2` (fixed at bind) and the covariance `S_i`; the
//! covariances the next local step needs give the energy of the last iterate for free.

use super::cells::{Cells, Covariance, CHUNK};
use glam::{DMat3, DVec3};
use rayon::prelude::*;

/// The covariance of every cell at positions `p` (`tri_cov` is scratch for spokes and rims).
pub(crate) fn covariances(
    cells: &Cells,
    p: &[DVec3],
    cov: &mut [Covariance],
    tri_cov: &mut [Covariance],
) {
    match cells {
        Cells::Spokes(s) => {
            cov.par_chunks_mut(CHUNK)
                .enumerate()
                .for_each(|(chunk, out)| {
                    for (k, c) in out.iter_mut().enumerate() {
                        let i = chunk * CHUNK + k;
                        let pi = p[i];
                        let mut acc = Covariance::default();
                        for e in s.ptr[i]..s.ptr[i + 1] {
                            let e1 = pi - p[s.col[e] as usize];
                            acc.add(s.w[e], s.we[e], e1);
                        }
                        *c = acc;
                    }
                });
        }
        Cells::Rims(r) => {
            tri_cov
                .par_chunks_mut(CHUNK)
                .enumerate()
                .for_each(|(chunk, out)| {
                    for (k, c) in out.iter_mut().enumerate() {
                        let t = chunk * CHUNK + k;
                        let [a, b, d] = r.tris[t].map(|v| p[v as usize]);
                        let e1 = [d - b, a - d, b - a];
                        let mut acc = Covariance::default();
                        for ((&c, &ce), &e1) in r.c[t].iter().zip(&r.ce[t]).zip(&e1) {
                            acc.add(c, ce, e1);
                        }
                        *c = acc;
                    }
                });
            let tri_cov = &*tri_cov;
            cov.par_chunks_mut(CHUNK)
                .enumerate()
                .for_each(|(chunk, out)| {
                    for (k, c) in out.iter_mut().enumerate() {
                        let i = chunk * CHUNK + k;
                        let mut acc = Covariance::default();
                        for &t in &r.inc[r.ptr[i]..r.ptr[i + 1]] {
                            acc.add_cov(&tri_cov[t as usize]);
                        }
                        *c = acc;
                    }
                });
        }
    }
}

/// `sum_i A_i + B_i - 2 tr(R_i S_i)`, summed in a fixed order (the same result on any number
/// of threads); `partial` holds the per-chunk sums (scratch, reused).
pub(crate) fn energy(cov: &[Covariance], b: &[f64], rots: &[DMat3], partial: &mut Vec<f64>) -> f64 {
    cov.par_chunks(CHUNK)
        .zip(b.par_chunks(CHUNK))
        .zip(rots.par_chunks(CHUNK))
        .map(|((c, b), r)| {
            c.iter()
                .zip(b)
                .zip(r)
                .map(|((c, b), r)| c.a + b - 2.0 * c.trace_with(r))
                .sum::<f64>()
        })
        .collect_into_vec(partial);
    partial.iter().sum()
}
