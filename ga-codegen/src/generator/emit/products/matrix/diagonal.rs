//! The diagonal layout of an f32 matrix form (see the parent module): diagonal `k` of the
//! 4 x 4 block of output quad `q` and operand quad `p` holds, in lane `i`, the entry of row
//! `4q + i` and operand field `4p + (i ^ k)`, so `apply` multiplies it by the operand quad
//! permuted the same way, with no shuffle for `k = 0`. Built from the column quads of the
//! column layout by eight shuffles per block; chosen where `apply` costs fewer vector
//! operations than by columns.

use super::{chunk_kind, quad_chunk, Chunk, ChunkKind, MatrixInput, Role};
use crate::generator::emit::lanes::quad::QuadLoads;
use crate::generator::emit::render::{ident, lit};
use crate::generator::emit::{Gen, ScalarType};
use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;
use std::collections::BTreeSet;

impl Gen<'_> {
    /// The f32 chunks by block diagonals (see the module docs), then the constant column's
    /// chunks as in the column form.
    fn diagonal_chunks(&self, m: &MatrixInput<'_>) -> Vec<Chunk> {
        let (nx, ny) = (m.tx.fields.len(), m.to.fields.len());
        let mut chunks = Vec::new();
        for p in 0..nx.div_ceil(4) {
            for q in 0..ny.div_ceil(4) {
                for k in 0..4 {
                    let entries: Vec<_> = (0..4)
                        .map(|i| {
                            let (row, col) = (4 * q + i, 4 * p + (i ^ k));
                            (row < ny && col < nx).then_some((row, col))
                        })
                        .collect();
                    // Named after the entry of its first lane: `d_ROW_COLUMN`.
                    let col =
                        m.tx.fields
                            .get(4 * p + k)
                            .map_or(format!("p{p}k{k}"), |f| f.name.clone());
                    let name = format!("d_{}_{col}", m.to.fields[4 * q].name);
                    chunks.push(Chunk {
                        role: Role::Diagonal { q, p, k },
                        kind: chunk_kind(m, &entries, &name),
                        entries,
                    });
                }
            }
        }
        chunks.extend(
            self.matrix_chunks(m, 4)
                .into_iter()
                .filter(|c| matches!(c.role, Role::Column { col: None, .. })),
        );
        chunks
    }

    /// The chunks of the form `apply` is emitted in: by columns, or in f32 by block diagonals
    /// where that takes fewer vector operations.
    pub(super) fn matrix_layout(&self, m: &MatrixInput<'_>, width: usize) -> Vec<Chunk> {
        let columns = self.matrix_chunks(m, width);
        if self.scalar != ScalarType::F32 {
            return columns;
        }
        let diagonals = self.diagonal_chunks(m);
        if apply_cost(&diagonals, width) < apply_cost(&columns, width) {
            diagonals
        } else {
            columns
        }
    }
}

impl Gen<'_> {
    /// The stored chunks of the diagonal layout (f32): each block's column quads in 4-lane
    /// form as the column layout builds them, turned into the block's four diagonals by
    /// eight shuffles (`d_k[i] = column_(i ^ k)[i]`); `None` when a column is not in 4-lane
    /// form.
    pub(super) fn diagonal_values(
        &self,
        m: &MatrixInput<'_>,
        stored: &[(&Ident, &Chunk)],
    ) -> Option<(TokenStream, Vec<TokenStream>)> {
        let columns = self.matrix_chunks(m, 4);
        let mut loads = QuadLoads::default();
        let mut lets = TokenStream::new();
        let blocks: BTreeSet<(usize, usize)> = stored
            .iter()
            .filter_map(|(_, c)| match c.role {
                Role::Diagonal { q, p, .. } => Some((q, p)),
                Role::Column { .. } => None,
            })
            .collect();
        for &(q, p) in &blocks {
            let mut cols = Vec::new();
            for l in 0..4 {
                let j = 4 * p + l;
                let chunk = columns.iter().find(|c| {
                    matches!(c.role, Role::Column { col: Some(cj), first_row }
                        if cj == j && first_row == 4 * q)
                });
                let value = match chunk.map(|c| (c, &c.kind)) {
                    None | Some((_, ChunkKind::Zero)) => quote!(F32x4::splat(0.0)),
                    Some((_, ChunkKind::Constant(cs))) => {
                        let cs = cs.iter().map(|&c| lit(c));
                        quote!(F32x4::new(#(#cs),*))
                    }
                    Some((c, ChunkKind::Stored(_))) => quad_chunk(m, c, &mut loads)?,
                };
                let name = ident(&format!("col_{q}_{j}"));
                lets.extend(quote!(let #name = #value;));
                cols.push(name);
            }
            let [x, y, z, w] = ["x", "y", "z", "w"].map(|t| ident(&format!("t{t}_{q}_{p}")));
            let [c0, c1, c2, c3] = [&cols[0], &cols[1], &cols[2], &cols[3]];
            // Diagonals 0 and 1 come from (x, y), 2 and 3 from (z, w): only the pairs of the
            // stored ones are written.
            let stored_k = |ks: [usize; 2]| {
                stored.iter().any(|(_, c)| {
                    matches!(c.role, Role::Diagonal { q: cq, p: cp, k }
                        if cq == q && cp == p && ks.contains(&k))
                })
            };
            if stored_k([0, 1]) {
                lets.extend(quote! {
                    let #x = #c0.unpack_lo(#c1);
                    let #y = #c2.unpack_hi(#c3);
                });
            }
            if stored_k([2, 3]) {
                lets.extend(quote! {
                    let #z = #c2.unpack_lo(#c3);
                    let #w = #c0.unpack_hi(#c1);
                });
            }
        }
        // Lanes (0, 3) and (1, 2) of each pair: `shuffle_imm([0, 3, 0, 3])`, `([1, 2, 1, 2])`.
        let (even, odd) = (Literal::i32_unsuffixed(204), Literal::i32_unsuffixed(153));
        let mut values = Vec::new();
        for (_, c) in stored {
            values.push(match c.role {
                Role::Diagonal { q, p, k } => {
                    let [x, y, z, w] =
                        ["x", "y", "z", "w"].map(|t| ident(&format!("t{t}_{q}_{p}")));
                    match k {
                        0 => quote!(#x.shuffle2::<#even>(#y)),
                        1 => quote!(#x.shuffle2::<#odd>(#y)),
                        2 => quote!(#z.shuffle2::<#even>(#w)),
                        _ => quote!(#z.shuffle2::<#odd>(#w)),
                    }
                }
                Role::Column { .. } => quad_chunk(m, c, &mut loads)?,
            });
        }
        // The loads bring `F32x4` into scope.
        let loads = loads.tokens(&self.rt, m.tv, m.tv);
        Some((quote!(let a = self; let b = self; #loads #lets), values))
    }
}

/// The vector operations of `apply` in a layout: a multiply and an add per chunk times an
/// operand field or permuted quad, a lane per lane written for a constant column chunk of
/// an operand field, an add per constant-column chunk, and a shuffle per operand field
/// splatted or per operand quad permutation other than the identity.
fn apply_cost(chunks: &[Chunk], width: usize) -> usize {
    let mut ops = 0;
    let mut shuffles = BTreeSet::new();
    for c in chunks {
        match (&c.kind, c.role) {
            (ChunkKind::Zero, _) => {}
            (_, Role::Column { col: None, .. }) => ops += 1,
            (ChunkKind::Stored(_), Role::Column { col: Some(j), .. }) => {
                ops += 2;
                shuffles.insert((j, 0));
            }
            (_, Role::Column { col: Some(_), .. }) => ops += 1 + width,
            (_, Role::Diagonal { p, k, .. }) => {
                ops += 2;
                if k != 0 {
                    shuffles.insert((p, k));
                }
            }
        }
    }
    ops + shuffles.len()
}

/// Operand quad `p` with lane `i` taken from lane `i ^ k` (f32).
pub(super) fn permuted(p: usize, k: usize) -> TokenStream {
    let q = ident(&format!("bq{p}"));
    if k == 0 {
        return quote!(#q);
    }
    let imm: i32 = (0..4).map(|i| ((i ^ k) as i32) << (2 * i)).sum();
    let imm = Literal::i32_unsuffixed(imm);
    quote!(#q.shuffle::<#imm>())
}
