//! The matrix (outermorphism) form of a fused sandwich, in lanes: one versor applied to many
//! operands.
//!
//! The map `x -> v x ~v` is linear in the operand, so its matrix (entries: polynomials in the
//! versor) is built once per versor and applied per operand. The matrix is stored by columns:
//! column `j` (operand field `j`, or the constant column) cut into chunks of as many output
//! rows as a lane type holds (4 for f32 in [`crate::runtime::f32x4::F32x4`], 2 for f64 in
//! [`crate::runtime::f64x2::F64x2`]). A chunk whose entries are the same for every versor
//! (the constant row of a point's weight, the zero constant column) is not stored: `apply`
//! writes it as a constant, or skips it when it is zero. `apply` is then, per output chunk,
//! a sum of `column chunk * splat(operand field)`: for a 4-field point in f32, 4 shuffles,
//! 4 multiplies and 3 adds.
//!
//! In f32 the matrix may instead be stored by diagonals of its 4 x 4 blocks: diagonal `k` of
//! the block of output quad `q` and operand quad `p` holds, in lane `i`, the entry of row
//! `4q + i` and operand field `4p + (i ^ k)`, and `apply` multiplies it by the operand quad
//! with its lanes permuted the same way. The four permutations (`i ^ k`) cover the block, and
//! the first is the identity: for a 4-field point, 3 shuffles, 4 multiplies and 3 adds, what
//! klein's hand-written SSE batch loop does. The form with fewer vector operations in `apply`
//! is emitted.

use crate::generator::emit::lanes::quad::{quad_sum, QuadLoads};
use crate::generator::emit::lanes::LaneTerms;
use crate::generator::emit::render::{doc, ident, int, lit};
use crate::generator::emit::{snake, Gen, ScalarType};
use crate::generator::spec::TypeDef;
use crate::generator::symbolic::{shared_magnitude, Poly};
use crate::runtime::rational::Rational;
use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;
use std::collections::BTreeSet;

mod diagonal;
use diagonal::permuted;

/// Where `apply` uses a chunk.
#[derive(Clone, Copy)]
enum Role {
    /// Column `col` (`None`: the constant column), output rows from `first_row` on: times
    /// that operand field in every lane.
    Column {
        col: Option<usize>,
        first_row: usize,
    },
    /// Diagonal `k` of the block of output quad `q` and operand quad `p` (f32): times the
    /// operand quad `p` with lane `i` taken from lane `i ^ k`.
    Diagonal { q: usize, p: usize, k: usize },
}

/// One chunk of the matrix: its role in `apply`, the entry `(row, column)` each lane holds
/// (column `nx` is the constant column; `None` past the last row or operand field), and how
/// `apply` gets it.
struct Chunk {
    role: Role,
    entries: Vec<Option<(usize, usize)>>,
    kind: ChunkKind,
}

impl Chunk {
    /// The output chunk (`first_row / width`) the chunk adds to.
    fn out_quad(&self, width: usize) -> usize {
        match self.role {
            Role::Column { first_row, .. } => first_row / width,
            Role::Diagonal { q, .. } => q,
        }
    }
}

enum ChunkKind {
    /// Every entry is zero for every versor: skipped.
    Zero,
    /// Every entry is a constant (lane by lane): written into `apply`.
    Constant(Vec<Rational>),
    /// Stored in the matrix, as this field.
    Stored(Ident),
}

/// What [`Gen::sandwich_matrix`] needs of a sandwich.
pub(crate) struct MatrixInput<'a> {
    pub tv: &'a TypeDef,
    pub tx: &'a TypeDef,
    pub to: &'a TypeDef,
    /// `coef[k][j]`: the entry polynomials (see `sandwich::linear_form`).
    pub coef: &'a [Vec<Poly>],
    /// The entries as expressions of `a` (the versor) and `lets`' temporaries.
    pub entries: &'a [Vec<TokenStream>],
    /// The temporaries the entries use.
    pub lets: &'a TokenStream,
}

impl Gen<'_> {
    /// Lanes per chunk and the lane type.
    fn matrix_lanes(&self) -> (usize, TokenStream) {
        let rt = &self.rt;
        match self.scalar {
            ScalarType::F32 => (4, quote!(#rt::runtime::f32x4::F32x4)),
            ScalarType::F64 => (2, quote!(#rt::runtime::f64x2::F64x2)),
        }
    }

    /// The column chunks of a matrix, column by column, output chunk by output chunk.
    fn matrix_chunks(&self, m: &MatrixInput<'_>, width: usize) -> Vec<Chunk> {
        let (nx, ny) = (m.tx.fields.len(), m.to.fields.len());
        let mut chunks = Vec::new();
        for j in 0..=nx {
            for first_row in (0..ny).step_by(width) {
                let entries: Vec<_> = (first_row..first_row + width)
                    .map(|k| (k < ny).then_some((k, j)))
                    .collect();
                let col = match j < nx {
                    true => m.tx.fields[j].name.clone(),
                    false => "1".to_string(),
                };
                let name = format!("c_{col}_{}", first_row / width);
                chunks.push(Chunk {
                    role: Role::Column {
                        col: (j < nx).then_some(j),
                        first_row,
                    },
                    kind: chunk_kind(m, &entries, &name),
                    entries,
                });
            }
        }
        chunks
    }

    /// The matrix type `VXMatrix` (stored column chunks), its `apply` and `rows`, and
    /// `V::x_matrix()`.
    pub(crate) fn sandwich_matrix(&self, m: &MatrixInput<'_>) -> TokenStream {
        let (tv, tx, to) = (m.tv, m.tx, m.to);
        let (width, lane) = self.matrix_lanes();
        let chunks = self.matrix_layout(m, width);
        let s = &self.s;
        let (nx, ny) = (tx.fields.len(), to.fields.len());
        let (xn, on, vn) = (ident(&tx.name), ident(&to.name), ident(&tv.name));
        let mat = ident(&format!("{}{}Matrix", tv.name, tx.name));
        let stored: Vec<(&Ident, &Chunk)> = chunks
            .iter()
            .filter_map(|c| match &c.kind {
                ChunkKind::Stored(n) => Some((n, c)),
                _ => None,
            })
            .collect();
        // The struct and its construction.
        let field_docs = stored.iter().map(|(_, c)| {
            let rows: Vec<&str> = c
                .entries
                .iter()
                .flatten()
                .map(|&(k, _)| to.fields[k].name.as_str())
                .collect();
            match c.role {
                Role::Column { col, .. } => {
                    let col = col.map_or("The constant column".to_string(), |j| {
                        format!("Column `{}`", tx.fields[j].name)
                    });
                    doc(&format!("{col}, rows `{}`.", rows.join("`, `")))
                }
                Role::Diagonal { .. } => {
                    let pairs: Vec<String> = c
                        .entries
                        .iter()
                        .map(|e| match e {
                            Some((k, j)) => {
                                format!("`{}` from `{}`", to.fields[*k].name, tx.fields[*j].name)
                            }
                            None => "0".to_string(),
                        })
                        .collect();
                    doc(&format!(
                        "A block diagonal, lane by lane: {}.",
                        pairs.join(", ")
                    ))
                }
            }
        });
        let names: Vec<&Ident> = stored.iter().map(|(n, _)| *n).collect();
        let (lets, values) = self.chunk_values(m, &stored);
        let rows_fn = rows_fn(&chunks, &stored, (nx, ny), self.scalar);
        let mut apply = apply_body(&chunks, tx, to, width, self.scalar);
        // The lane type, where the body uses it.
        let ln = lane_name(self.scalar);
        if apply.to_string().contains(&format!("{ln} ::")) {
            apply = quote!(use #lane; #apply);
        }
        let cols: Vec<String> = tx
            .fields
            .iter()
            .map(|f| format!("`{}`", f.name))
            .chain(std::iter::once("1".to_string()))
            .collect();
        let out_rows: Vec<String> = to.fields.iter().map(|f| format!("`{}`", f.name)).collect();
        let mdoc = doc(&format!(
            "The linear (outermorphism) form of the sandwich of a `{x}` by a `{v}`: build it \
             once per versor (`{v}::{f}_matrix`) and `apply` it to many operands.\n\nRows: {}. \
             Columns: {}. Stored in {width}-lane chunks, {form}; chunks that are the same \
             for every versor (zeros, the constant entries) are not stored. `rows()` gives \
             every entry.",
            out_rows.join(", "),
            cols.join(", "),
            x = tx.name,
            v = tv.name,
            f = snake(&tx.name),
            form = match chunks
                .iter()
                .any(|c| matches!(c.role, Role::Diagonal { .. }))
            {
                true => "by diagonals of its 4 x 4 blocks (`apply` permutes the operand's lanes)",
                false => "by columns",
            },
        ));
        let fdoc = doc(&format!(
            "The matrix form of `self.sandwich(x)` for `x: {}`; see [`{mat}`].",
            tx.name
        ));
        let fname = ident(&format!("{}_matrix", snake(&tx.name)));
        let (ncols, nrows) = (int(nx + 1), int(ny));
        quote! {
            #mdoc
            #[derive(Clone, Copy, Debug)]
            pub struct #mat { #(#field_docs #names: #lane,)* }
            impl #mat {
                /// Apply the map: the same result as the sandwich, at matrix cost.
                #[inline]
                #[must_use]
                pub fn apply(&self, b: #xn) -> #on { #apply }
                /// Every entry, row by row: `rows()[row][col]`, rows the output fields,
                /// columns the operand fields then the constant column.
                #[must_use]
                pub fn rows(&self) -> [[#s; #ncols]; #nrows] { #rows_fn }
            }
            impl ::core::cmp::PartialEq for #mat {
                fn eq(&self, other: &Self) -> bool { self.rows() == other.rows() }
            }
            impl #vn {
                #fdoc
                #[inline]
                #[must_use]
                pub fn #fname(&self) -> #mat {
                    #lets
                    #mat { #(#names: #values,)* }
                }
            }
        }
    }
}

impl Gen<'_> {
    /// The stored chunks' values and the statements before them. f32: each chunk in 4-lane
    /// form (`splat(a.x) * shuffle of a's quads`, as the 4-lane products), when every entry
    /// is quadratic in the versor plus a constant; otherwise, and for f64, the entries
    /// computed one by one (sharing the pairwise products) and put in lanes.
    fn chunk_values(
        &self,
        m: &MatrixInput<'_>,
        stored: &[(&Ident, &Chunk)],
    ) -> (TokenStream, Vec<TokenStream>) {
        if stored.is_empty() {
            return (TokenStream::new(), Vec::new());
        }
        let diagonal = stored
            .iter()
            .any(|(_, c)| matches!(c.role, Role::Diagonal { .. }));
        if self.scalar == ScalarType::F32 && diagonal {
            if let Some(built) = self.diagonal_values(m, stored) {
                return built;
            }
        } else if self.scalar == ScalarType::F32 {
            let mut loads = QuadLoads::default();
            let quads: Option<Vec<TokenStream>> = stored
                .iter()
                .map(|(_, c)| quad_chunk(m, c, &mut loads))
                .collect();
            if let Some(values) = quads {
                let loads = loads.tokens(&self.rt, m.tv, m.tv);
                return (quote!(let a = self; let b = self; #loads), values);
            }
        }
        let (_, lane) = self.matrix_lanes();
        let values = stored
            .iter()
            .map(|(_, c)| {
                let lanes = c.entries.iter().map(|e| match *e {
                    Some((k, j)) => m.entries[k][j].clone(),
                    None => quote!(0.0),
                });
                let ln = lane_name(self.scalar);
                quote!(#ln::new(#(#lanes),*))
            })
            .collect();
        let lets = m.lets;
        (quote!(use #lane; let a = self; #lets), values)
    }
}

/// A stored f32 chunk in 4-lane form, `None` when an entry has a term that is not a constant
/// or a product of two versor fields. Lanes whose entry is a constant (or past the last row)
/// are free in the lane sums and set by a mask and the constants at the end.
fn quad_chunk(m: &MatrixInput<'_>, c: &Chunk, loads: &mut QuadLoads) -> Option<TokenStream> {
    let mut consts = [Rational::ZERO; 4];
    // The quadratic terms `c a.x a.y` of each lane.
    let mut quadratic: Vec<Vec<(u16, u16, Rational)>> = vec![Vec::new(); 4];
    for (i, terms) in quadratic.iter_mut().enumerate() {
        let Some((k, j)) = c.entries[i] else {
            continue;
        };
        for (mono, &coef) in &m.coef[k][j].0 {
            match mono.as_slice() {
                [] => consts[i] = coef,
                [x, y] if x.operand == 0 && y.operand == 0 => terms.push((x.field, y.field, coef)),
                _ => return None,
            }
        }
    }
    // The factor splatted is the one found in more lanes (so the other factors line up in
    // one shuffle), and a magnitude shared by every term is applied once at the end.
    let in_lanes = |f: u16| {
        quadratic
            .iter()
            .filter(|t| t.iter().any(|&(x, y, _)| x == f || y == f))
            .count()
    };
    let scale =
        shared_magnitude(quadratic.iter().flatten().map(|&(_, _, c)| c)).unwrap_or(Rational::ONE);
    let lanes: Vec<LaneTerms> = quadratic
        .iter()
        .map(|terms| {
            let mut lane = LaneTerms::new();
            for &(x, y, coef) in terms {
                let (s, o) = if in_lanes(y) > in_lanes(x) {
                    (y, x)
                } else {
                    (x, y)
                };
                lane.entry(s).or_default().push((o, coef / scale));
            }
            lane
        })
        .collect();
    let free: [bool; 4] = std::array::from_fn(|i| lanes[i].is_empty());
    let (mut expr, _) = quad_sum(&lanes, m.tv, m.tv, free, loads);
    if free.iter().any(|&f| f) || scale != Rational::ONE {
        let mask = free.map(|f| lit(if f { Rational::ZERO } else { scale }));
        // Parenthesised unless it already is one group.
        let mut trees = expr.clone().into_iter();
        let grouped = matches!(
            (trees.next(), trees.next()),
            (Some(proc_macro2::TokenTree::Group(g)), None)
                if g.delimiter() == proc_macro2::Delimiter::Parenthesis
        );
        expr = if grouped {
            quote!(#expr * F32x4::new(#(#mask),*))
        } else {
            quote!((#expr) * F32x4::new(#(#mask),*))
        };
    }
    if consts.iter().any(|c| *c != Rational::ZERO) {
        let cs = consts.map(lit);
        expr = quote!(#expr + F32x4::new(#(#cs),*));
    }
    Some(expr)
}

/// The lane type's name: `F32x4` or `F64x2` (as the 4-lane and paired products name them).
fn lane_name(scalar: ScalarType) -> Ident {
    ident(match scalar {
        ScalarType::F32 => "F32x4",
        ScalarType::F64 => "F64x2",
    })
}

/// The zero polynomial, for rows past the last output field.
static ZERO: Poly = Poly(std::collections::BTreeMap::new());

/// How a chunk with these entries is had: zero, constant, or stored as field `name`.
fn chunk_kind(m: &MatrixInput<'_>, entries: &[Option<(usize, usize)>], name: &str) -> ChunkKind {
    let lanes: Vec<&Poly> = entries
        .iter()
        .map(|e| e.map_or(&ZERO, |(k, j)| &m.coef[k][j]))
        .collect();
    if lanes.iter().all(|p| p.is_zero()) {
        ChunkKind::Zero
    } else if let Some(cs) = lanes
        .iter()
        .map(|p| p.as_constant())
        .collect::<Option<Vec<_>>>()
    {
        ChunkKind::Constant(cs)
    } else {
        ChunkKind::Stored(ident(name))
    }
}

/// The lanes of a chunk as an array expression (`self.c_x_q` read out).
fn lanes_of(name: &Ident, scalar: ScalarType) -> TokenStream {
    match scalar {
        ScalarType::F32 => quote!(self.#name.to_array()),
        ScalarType::F64 => quote!([self.#name.lo(), self.#name.hi()]),
    }
}

/// The body of `rows()`: stored chunks read out, constants written.
fn rows_fn(
    chunks: &[Chunk],
    stored: &[(&Ident, &Chunk)],
    (nx, ny): (usize, usize),
    scalar: ScalarType,
) -> TokenStream {
    let reads = stored.iter().map(|(n, _)| {
        let v = lanes_of(n, scalar);
        quote!(let #n = #v;)
    });
    let rows = (0..ny).map(|k| {
        let entries = (0..=nx).map(|j| {
            let (chunk, lane) = chunks
                .iter()
                .find_map(|c| {
                    let lane = c.entries.iter().position(|e| *e == Some((k, j)))?;
                    Some((c, lane))
                })
                .expect("every entry is in a chunk");
            match &chunk.kind {
                ChunkKind::Zero => quote!(0.0),
                ChunkKind::Constant(cs) => lit(cs[lane]),
                ChunkKind::Stored(n) => {
                    let lane = Literal::usize_unsuffixed(lane);
                    quote!(#n[#lane])
                }
            }
        });
        quote!([#(#entries),*])
    });
    quote!(#(#reads)* [#(#rows),*])
}

/// The body of `apply`: per output chunk, the sum of its column chunks times the operand's
/// fields splatted, or of its diagonal chunks times the operand's quads permuted.
fn apply_body(
    chunks: &[Chunk],
    tx: &TypeDef,
    to: &TypeDef,
    width: usize,
    scalar: ScalarType,
) -> TokenStream {
    let ny = to.fields.len();
    let nq = ny.div_ceil(width);
    let ln = lane_name(scalar);
    let mut stmts = TokenStream::new();
    let mut outs = Vec::new();
    for q in 0..nq {
        let mut terms = Vec::new();
        for c in chunks.iter().filter(|c| c.out_quad(width) == q) {
            let col = match c.role {
                Role::Column { col, .. } => col,
                Role::Diagonal { p, k, .. } => {
                    let x = permuted(p, k);
                    let term = match &c.kind {
                        ChunkKind::Zero => continue,
                        ChunkKind::Stored(n) => quote!(self.#n * #x),
                        ChunkKind::Constant(cs) if cs.iter().all(|&c| c == Rational::ONE) => x,
                        ChunkKind::Constant(cs) => {
                            let cs = cs.iter().map(|&c| lit(c));
                            quote!(#ln::new(#(#cs),*) * #x)
                        }
                    };
                    terms.push(term);
                    continue;
                }
            };
            let term = match (&c.kind, col) {
                (ChunkKind::Zero, _) => continue,
                (ChunkKind::Stored(n), Some(j)) => {
                    let x = splat(tx, j, scalar);
                    quote!(self.#n * #x)
                }
                (ChunkKind::Stored(n), None) => quote!(self.#n),
                // A constant chunk of an operand field: the field, scaled per lane, written
                // lane by lane (a zero lane stays zero whatever the field holds).
                (ChunkKind::Constant(cs), Some(j)) => {
                    let x = ident(&tx.fields[j].name);
                    let lanes = cs.iter().map(|&c| {
                        if c == Rational::ZERO {
                            quote!(0.0)
                        } else if c == Rational::ONE {
                            quote!(b.#x)
                        } else {
                            let c = lit(c);
                            quote!(#c * b.#x)
                        }
                    });
                    quote!(#ln::new(#(#lanes),*))
                }
                (ChunkKind::Constant(cs), None) => {
                    let cs = cs.iter().map(|&c| lit(c));
                    quote!(#ln::new(#(#cs),*))
                }
            };
            terms.push(term);
        }
        let o = ident(&format!("o{q}"));
        let sum = if terms.is_empty() {
            quote!(#ln::splat(0.0))
        } else {
            quote!(#(#terms)+*)
        };
        let read = match scalar {
            ScalarType::F32 => quote!(let #o = (#sum).to_array();),
            ScalarType::F64 => quote!(let #o = #sum; let #o = [#o.lo(), #o.hi()];),
        };
        stmts.extend(read);
        outs.push(o);
    }
    let fields = to.fields.iter().enumerate().map(|(k, f)| {
        let (o, lane) = (&outs[k / width], Literal::usize_unsuffixed(k % width));
        let f = ident(&f.name);
        quote!(#f: #o[#lane])
    });
    let used: BTreeSet<usize> = chunks
        .iter()
        .filter_map(|c| match (&c.kind, c.role) {
            (ChunkKind::Zero, _) => None,
            (_, Role::Diagonal { p, .. }) => Some(p),
            (ChunkKind::Stored(_), Role::Column { col: Some(j), .. }) => Some(j / 4),
            _ => None,
        })
        .collect();
    let loads = operand_loads(tx, scalar, &used);
    let on = ident(&to.name);
    quote!(#loads #stmts #on { #(#fields),* })
}

/// The operand's fields as lane loads: the f32 quads in `used` (shuffled per field); none
/// for f64 (each field is splatted where it is used).
fn operand_loads(tx: &TypeDef, scalar: ScalarType, used: &BTreeSet<usize>) -> TokenStream {
    match scalar {
        ScalarType::F32 => {
            let quads = tx
                .fields
                .chunks(4)
                .enumerate()
                .filter(|(i, _)| used.contains(i));
            let quads = quads.map(|(i, fs)| {
                let q = ident(&format!("bq{i}"));
                let mut lanes: Vec<TokenStream> = fs
                    .iter()
                    .map(|f| {
                        let f = ident(&f.name);
                        quote!(b.#f)
                    })
                    .collect();
                lanes.resize(4, quote!(0.0));
                quote!(let #q = F32x4::new(#(#lanes),*);)
            });
            quote!(#(#quads)*)
        }
        ScalarType::F64 => TokenStream::new(),
    }
}

/// Operand field `j` in every lane.
fn splat(tx: &TypeDef, j: usize, scalar: ScalarType) -> TokenStream {
    match scalar {
        ScalarType::F32 => {
            let q = ident(&format!("bq{}", j / 4));
            let l = (j % 4) as i32;
            let imm = Literal::i32_unsuffixed(l | l << 2 | l << 4 | l << 6);
            quote!(#q.shuffle::<#imm>())
        }
        ScalarType::F64 => {
            let f = ident(&tx.fields[j].name);
            quote!(F64x2::splat(b.#f))
        }
    }
}
