//! Bind-time work: the cells' weights and rest edges, the constrained vertex list, and the
//! prefactored system `-L p' = b` (equation (13), a Poisson equation with Dirichlet rows).

use super::cells::{Cells, Rims, Spokes};
use super::rhs::Gather;
use super::{ArapEnergy, ArapError, ArapOptions};
use crate::blend::KeyError;
use crate::deformers::Result;
use crate::mesh::triangle::Frame;
use crate::mesh::union_find::UnionFind;
use crate::mesh::validate::check_solvable;
use crate::mesh::IndexList;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::operators::harmonic::constrained_of;
use crate::operators::laplacian::assemble;
use crate::operators::laplacian::cotangent_laplacian;
use crate::operators::laplacian::DegeneratePolicy;
use crate::operators::solve::DirichletSolver;
use glam::DVec3;
use rayon::prelude::*;

/// Everything bind computes.
#[derive(Debug)]
pub(crate) struct System {
    pub rest: Vec<DVec3>,
    pub cells: Cells,
    /// The right-hand side's rest vectors.
    pub gather: Gather,
    /// `sum |w| |e|^2` per cell (the rest part of the eigenvalue bound).
    pub b_abs: Vec<f64>,
    /// `sum w |e|^2` per cell (the rest part of the energy).
    pub b: Vec<f64>,
    /// Fixed vertices, then each handle group: the solver's constrained rows.
    pub constrained: Vec<u32>,
    /// Handle group `g` is `constrained[starts[g]..starts[g + 1]]`; fixed vertices come
    /// before `starts[0]`.
    pub starts: Vec<usize>,
    pub solver: DirichletSolver,
}

/// Checks the constraint sets: empty handle groups and at least one constraint here; ranges and
/// overlaps as harmonic fields check them ([`constrained_of`]).
fn constraints(n: usize, fixed: &[u32], handles: &[&[u32]]) -> Result<(Vec<u32>, Vec<usize>)> {
    if let Some(set) = handles.iter().position(|h| h.is_empty()) {
        return Err(KeyError::EmptyHandle { set }.into());
    }
    let mut sets = vec![fixed];
    sets.extend_from_slice(handles);
    if sets.iter().all(|s| s.is_empty()) {
        return Err(ArapError::NoConstraints.into());
    }
    let constrained = constrained_of(n, &sets)?;
    // Where each handle's vertices start in `constrained` (after the fixed ones).
    let mut starts = Vec::with_capacity(handles.len() + 1);
    let mut at = fixed.len();
    for h in handles {
        starts.push(at);
        at += h.len();
    }
    starts.push(at);
    Ok((constrained, starts))
}

/// Fails when every vertex of some connected component is constrained.
fn check_free_vertices(mesh: &Mesh, constrained: &[u32]) -> Result<()> {
    let n = mesh.positions.len();
    let mut uf = UnionFind::new(n);
    for t in &mesh.triangles {
        uf.union(t[0], t[1]);
        uf.union(t[1], t[2]);
    }
    let comps = uf.labels();
    let mut has_free = vec![false; comps.count];
    let mut is_constrained = vec![false; n];
    for &v in constrained {
        is_constrained[v as usize] = true;
    }
    for v in 0..n {
        if !is_constrained[v] {
            has_free[comps.labels[v] as usize] = true;
        }
    }
    let vertices: Vec<u32> = (0..n as u32)
        .filter(|&v| !has_free[comps.labels[v as usize] as usize])
        .collect();
    if vertices.is_empty() {
        Ok(())
    } else {
        Err(ArapError::NothingToDeform {
            vertices: IndexList(vertices),
        }
        .into())
    }
}

/// Per-triangle half-cotangent weights (zero for degenerate triangles), clamped at zero when
/// asked.
fn triangle_weights(mesh: &Mesh, options: &ArapOptions) -> Result<Vec<[f64; 3]>> {
    let per: Vec<Option<[f64; 3]>> = mesh
        .triangles
        .par_iter()
        .map(|t| Frame::new(t.map(|v| mesh.positions[v as usize])).map(|f| f.half_cotangents()))
        .collect();
    if options.cotangent.degenerate == DegeneratePolicy::Error {
        let bad: Vec<u32> = (0..per.len() as u32)
            .filter(|&f| per[f as usize].is_none())
            .collect();
        if !bad.is_empty() {
            return Err(MeshError::DegenerateTriangles {
                faces: IndexList(bad),
            }
            .into());
        }
    }
    let clamp = options.cotangent.clamp_negative;
    Ok(per
        .into_iter()
        .map(|w| {
            w.unwrap_or([0.0; 3])
                .map(|c| if clamp { c.max(0.0) } else { c })
        })
        .collect())
}

impl System {
    /// Builds the cells and prefactors the system; see [`super::Arap::bind`].
    pub fn new(
        mesh: &Mesh,
        fixed: &[u32],
        handles: &[&[u32]],
        options: &ArapOptions,
    ) -> Result<Self> {
        check_solvable(mesh)?;
        let n = mesh.positions.len();
        let (constrained, starts) = constraints(n, fixed, handles)?;
        check_free_vertices(mesh, &constrained)?;
        let p = &mesh.positions;
        let (cells, gather, laplacian, b, b_abs) = match options.energy {
            ArapEnergy::Spokes => {
                let l = cotangent_laplacian(mesh, options.cotangent)?;
                let (mut ptr, mut col, mut w, mut we) = (vec![0], vec![], vec![], vec![]);
                let (mut b, mut b_abs) = (vec![0.0; n], vec![0.0; n]);
                for (i, row) in l.outer_iterator().enumerate() {
                    for (j, &wij) in row.iter() {
                        if j == i || wij == 0.0 {
                            continue;
                        }
                        let e = p[i] - p[j];
                        col.push(j as u32);
                        w.push(wij);
                        we.push(wij * e);
                        b[i] += wij * e.length_squared();
                        b_abs[i] += wij.abs() * e.length_squared();
                    }
                    ptr.push(col.len());
                }
                let gather = Gather::spokes(&ptr, &col, &we);
                let cells = Cells::Spokes(Spokes { ptr, col, w, we });
                (cells, gather, l, b, b_abs)
            }
            ArapEnergy::SpokesAndRims => {
                let c = triangle_weights(mesh, options)?;
                let tris = mesh.triangles.clone();
                let weights: Vec<[[f64; 2]; 3]> = c.iter().map(|w| w.map(|x| [x, x])).collect();
                let l = assemble(n, &tris, &weights);
                let mut ce = Vec::with_capacity(tris.len());
                let mut tb = Vec::with_capacity(tris.len());
                for (t, w) in tris.iter().zip(&c) {
                    let q = t.map(|v| p[v as usize]);
                    let e: [DVec3; 3] = std::array::from_fn(|k| q[(k + 2) % 3] - q[(k + 1) % 3]);
                    ce.push(std::array::from_fn(|k| w[k] * e[k]));
                    let sum = |f: &dyn Fn(f64) -> f64| -> f64 {
                        (0..3).map(|k| f(w[k]) * e[k].length_squared()).sum()
                    };
                    tb.push((sum(&|x| x), sum(&|x| x.abs())));
                }
                let mut count = vec![0usize; n + 1];
                for t in &tris {
                    for &v in t {
                        count[v as usize + 1] += 1;
                    }
                }
                for i in 0..n {
                    count[i + 1] += count[i];
                }
                let ptr = count.clone();
                let mut inc = vec![0u32; ptr[n]];
                let mut f = vec![[DVec3::ZERO; 3]; tris.len()];
                let (mut b, mut b_abs) = (vec![0.0; n], vec![0.0; n]);
                for (ti, t) in tris.iter().enumerate() {
                    for m in 0..3 {
                        let v = t[m] as usize;
                        let slot = count[v];
                        count[v] += 1;
                        inc[slot] = ti as u32;
                        // Edge opposite corner m+1 joins m+2 and m: its e is p_m - p_{m+2};
                        // edge opposite m+2 joins m and m+1: its e is p_{m+1} - p_m.
                        f[ti][m] = ce[ti][(m + 1) % 3] - ce[ti][(m + 2) % 3];
                        b[v] += tb[ti].0;
                        b_abs[v] += tb[ti].1;
                    }
                }
                let gather = Gather::rims(&l, &tris, &f)?;
                let cells = Cells::Rims(Rims {
                    tris,
                    c,
                    ce,
                    ptr,
                    inc,
                });
                (cells, gather, l, b, b_abs)
            }
        };
        let mut q = laplacian;
        q.data_mut().iter_mut().for_each(|x| *x = -*x);
        let solver = DirichletSolver::new(&q, &constrained, options.solver)?;
        Ok(System {
            rest: p.clone(),
            cells,
            gather,
            b_abs,
            b,
            constrained,
            starts,
            solver,
        })
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.rest.len()
    }
}
