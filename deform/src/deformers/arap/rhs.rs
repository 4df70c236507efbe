//! The right-hand side of the global step (the paper's equation (12)).
//!
//! Spokes: `b_i = sum_j w_ij (R_i + R_j) (p_i - p_j) / 2`. Spokes and rims: each triangle's
//! edges belong to the cells of its three corners, so
//! `b_i = sum over the triangles t around i of (R_i + R_j + R_k) / 3 f_ti` with
//! `f_ti = sum over the two edges (i, j) of t of c (p_i - p_j)`. Both are
//! `b_i = R_i g_i + sum_j R_j h_ij` over the neighbours `j` of `i`, with rest vectors `g_i`
//! and `h_ij` computed at bind ([`Gather::spokes`], [`Gather::rims`]): one gather of the
//! neighbours' rotations per vertex and no per-triangle pass.

use super::cells::CHUNK;
use crate::deformers::Result;
use crate::mesh::MeshError;
use glam::{DMat3, DVec3};
use rayon::prelude::*;
use sprs::CsMat;

/// `b_i = R_i g_i + sum_j R_j h_ij`, rows `ptr[i]..ptr[i + 1]` of `col` and `h`.
#[derive(Debug, Clone)]
pub(crate) struct Gather {
    ptr: Vec<usize>,
    col: Vec<u32>,
    h: Vec<DVec3>,
    g: Vec<DVec3>,
}

impl Gather {
    /// Spokes: `h_ij = w_ij (p_i - p_j) / 2`, `g_i = sum_j h_ij`.
    pub fn spokes(ptr: &[usize], col: &[u32], we: &[DVec3]) -> Gather {
        let h: Vec<DVec3> = we.iter().map(|&x| 0.5 * x).collect();
        let g = (0..ptr.len() - 1)
            .map(|i| h[ptr[i]..ptr[i + 1]].iter().sum())
            .collect();
        Gather {
            ptr: ptr.to_vec(),
            col: col.to_vec(),
            h,
            g,
        }
    }

    /// Spokes and rims on the off-diagonal pattern of `l` (every mesh edge):
    /// `g_i = sum_t f_ti / 3` and `h_ij = sum over the triangles t with edge ij of f_ti / 3`.
    /// `f[t][m]` is `f_ti` for the vertex `i` at corner `m` of triangle `t`.
    pub fn rims(l: &CsMat<f64>, tris: &[[u32; 3]], f: &[[DVec3; 3]]) -> Result<Gather> {
        let n = l.rows();
        let (mut ptr, mut col) = (vec![0], Vec::with_capacity(l.nnz()));
        for (i, row) in l.outer_iterator().enumerate() {
            col.extend(row.indices().iter().filter(|&&j| j != i).map(|&j| j as u32));
            ptr.push(col.len());
        }
        let mut h = vec![DVec3::ZERO; col.len()];
        let mut g = vec![DVec3::ZERO; n];
        for (t, ft) in tris.iter().zip(f) {
            for m in 0..3 {
                let i = t[m] as usize;
                let share = ft[m] / 3.0;
                g[i] += share;
                for j in [t[(m + 1) % 3], t[(m + 2) % 3]] {
                    let row = &col[ptr[i]..ptr[i + 1]];
                    let k = row
                        .binary_search(&j)
                        .map_err(|_| MeshError::InvalidArgument(format!("edge {i}-{j} missing")))?;
                    h[ptr[i] + k] += share;
                }
            }
        }
        Ok(Gather { ptr, col, h, g })
    }
}

/// Writes `b` (one vector per vertex) from the rotations `rots`.
pub(crate) fn right_hand_side(gather: &Gather, rots: &[DMat3], b: &mut [DVec3]) {
    let s = gather;
    b.par_chunks_mut(CHUNK)
        .enumerate()
        .for_each(|(chunk, out)| {
            for (k, bi) in out.iter_mut().enumerate() {
                let i = chunk * CHUNK + k;
                let mut acc = rots[i] * s.g[i];
                for e in s.ptr[i]..s.ptr[i + 1] {
                    acc += rots[s.col[e] as usize] * s.h[e];
                }
                *bi = acc;
            }
        });
}
