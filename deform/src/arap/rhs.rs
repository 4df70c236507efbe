//! The right-hand side of the global step (the paper's equation (12)):
//! `b_i = sum_j w_ij (R_i + R_j) (p_i - p_j) / 2` for spokes, and for spokes and rims
//! `b_i = sum over the triangles t around i of Rbar_t sum_(edges (i, j) of t) c (p_i - p_j)`
//! with `Rbar_t` the mean of the rotations of the triangle's three corners (each triangle's
//! edges belong to the cells of its three corners).

use super::energy::CHUNK;
use super::system::Cells;
use glam::{DMat3, DVec3};
use rayon::prelude::*;

/// Writes `b` (one vector per vertex) from the rotations `rots`; `tri_rot` is scratch.
pub(crate) fn right_hand_side(
    cells: &Cells,
    rots: &[DMat3],
    tri_rot: &mut [DMat3],
    b: &mut [DVec3],
) {
    match cells {
        Cells::Spokes(s) => {
            b.par_chunks_mut(CHUNK)
                .enumerate()
                .for_each(|(chunk, out)| {
                    for (k, bi) in out.iter_mut().enumerate() {
                        let i = chunk * CHUNK + k;
                        let mut acc = rots[i] * s.g[i];
                        for e in s.ptr[i]..s.ptr[i + 1] {
                            acc += rots[s.col[e] as usize] * (0.5 * s.we[e]);
                        }
                        *bi = acc;
                    }
                });
        }
        Cells::Rims(r) => {
            tri_rot
                .par_chunks_mut(CHUNK)
                .enumerate()
                .for_each(|(chunk, out)| {
                    for (k, m) in out.iter_mut().enumerate() {
                        let [a, bb, c] = r.tris[chunk * CHUNK + k];
                        let sum = rots[a as usize] + rots[bb as usize] + rots[c as usize];
                        *m = sum * (1.0 / 3.0);
                    }
                });
            let tri_rot = &*tri_rot;
            b.par_chunks_mut(CHUNK)
                .enumerate()
                .for_each(|(chunk, out)| {
                    for (k, bi) in out.iter_mut().enumerate() {
                        let i = chunk * CHUNK + k;
                        let mut acc = DVec3::ZERO;
                        for s in r.ptr[i]..r.ptr[i + 1] {
                            acc += tri_rot[r.inc[s] as usize] * r.f[s];
                        }
                        *bi = acc;
                    }
                });
        }
    }
}
