//! Dense products through the matrix-unit basis (`generator/matrix_units.rs`): a type that
//! holds every blade, or every even blade, of an algebra with a 2 x 2 matrix factor is
//! multiplied as matrices over the smaller algebra beside the factor.
//!
//! The body converts both operands into a local `Blocks` value (one field per matrix entry
//! and blade of that algebra; each a sum of a few operand fields), multiplies those (in
//! paired lanes for f64, four lanes for f32, where the lane builders take it) and converts the
//! result back. Emitted only where it takes fewer operations than the blade form.

use crate::generator::emit::lanes::quad;
use crate::generator::emit::render::{ident, lit, Names};
use crate::generator::emit::{Gen, ScalarType};
use crate::generator::matrix_units::{matrix_units, MatrixUnits};
use crate::generator::spec::{Field, TypeDef};
use crate::generator::symbolic::{shared_magnitude, Poly, SymMv, Var};
use crate::runtime::rational::Rational;
use proc_macro2::TokenStream;
use quote::quote;

/// Operations of a linear combination `c1 x1 + c2 x2 + ...`: the adds, and one multiply when
/// the coefficients are not all `+-1` (a shared magnitude is factored out; mixed magnitudes
/// cost one multiply per term).
fn linear_ops(terms: &[(usize, Rational)]) -> usize {
    let adds = terms.len().saturating_sub(1);
    let muls = match shared_magnitude(terms.iter().map(|t| t.1)) {
        Some(g) => usize::from(g != Rational::ONE),
        None => terms.len(),
    };
    adds + muls
}

/// `p` rendered with a magnitude shared by all its terms factored out: `(x - y) * 0.5`.
fn factored(p: &Poly, names: &Names) -> TokenStream {
    match shared_magnitude(p.0.values().copied()) {
        Some(g) if g != Rational::ONE => {
            let mut q = Poly::default();
            q.add_scaled(p, Rational::ONE / g);
            let (body, g) = (names.poly(&q), lit(g));
            if q.0.len() > 1 {
                quote!((#body) * #g)
            } else {
                quote!(#body * #g)
            }
        }
        _ => names.poly(p),
    }
}

/// The local type of the matrix entries: one field per coordinate of the new basis.
fn blocks_type(mu: &MatrixUnits) -> TypeDef {
    TypeDef {
        name: "Blocks".to_string(),
        doc: None,
        fields: mu
            .names
            .iter()
            .enumerate()
            .map(|(k, n)| Field {
                name: n.clone(),
                bitmap: k as u32,
                sign: 1,
            })
            .collect(),
        constants: Vec::new(),
        versor: true,
        unit: false,
    }
}

impl Gen<'_> {
    /// The body of `a * b` for operands and result of type `ti` through the matrix-unit basis,
    /// the doc line saying so and its multiplies; `None` when the type is not such a
    /// subalgebra or the form takes no fewer operations than `m`, the blade form.
    pub(crate) fn build_matrix_form(
        &mut self,
        ti: usize,
        m: &SymMv,
    ) -> Option<(TokenStream, String, usize)> {
        let t = &self.spec.types[ti];
        if !t.constants.is_empty() {
            return None;
        }
        let blades: Vec<u32> = t.fields.iter().map(|f| f.bitmap).collect();
        let mu = matrix_units(&mut self.table, &blades)?;
        // Operations of the blade form: a multiply per term, an add per term but the first.
        let direct_terms: usize = t.fields.iter().map(|f| m.get(f.bitmap).0.len()).sum();
        let direct = 2 * direct_terms - t.fields.len();
        let product_terms: usize = mu.products.iter().map(Vec::len).sum();
        let converted = 2 * mu.to_units.iter().map(|r| linear_ops(r)).sum::<usize>()
            + mu.from_units.iter().map(|r| linear_ops(r)).sum::<usize>();
        let blocks_ops = 2 * product_terms - mu.names.len() + converted;
        if 5 * blocks_ops > 4 * direct {
            return None;
        }
        let bt = blocks_type(&mu);
        let t = &self.spec.types[ti];
        // Operand conversions: `Blocks { m11_c0: a.s + a.e45, .. }` (fields carry their sign).
        let convert = |operand: u8| {
            let fields = bt.fields.iter().zip(&mu.to_units).map(|(f, row)| {
                let mut p = Poly::default();
                for &(bi, c) in row {
                    let v = Var {
                        operand,
                        field: bi as u16,
                    };
                    p.add_term(vec![v], c * Rational::int(t.fields[bi].sign as i64));
                }
                let names = Names::new(t, Some(t));
                let (id, e) = (ident(&f.name), factored(&p, &names));
                quote!(#id: #e,)
            });
            quote!(Blocks { #(#fields)* })
        };
        let (ya, yb) = (convert(0), convert(1));
        // The product of the blocks.
        let mut mb = SymMv::default();
        for (k, terms) in mu.products.iter().enumerate() {
            let mut p = Poly::default();
            for &(i, j, c) in terms {
                let (x, y) = (
                    Var {
                        operand: 0,
                        field: i as u16,
                    },
                    Var {
                        operand: 1,
                        field: j as u16,
                    },
                );
                p.add_term(vec![x, y], c);
            }
            mb.0.insert(k as u32, p);
        }
        let lanes = match self.scalar {
            ScalarType::F64 => self.build_paired_into(&bt, &mb, &bt, &bt),
            ScalarType::F32 => quad::build(&bt, &bt, &bt, &mb, &self.rt),
        };
        let product = lanes.unwrap_or_else(|| {
            let names = Names::new(&bt, Some(&bt));
            let fields = bt.fields.iter().map(|f| {
                let (id, e) = (ident(&f.name), names.poly(&mb.get(f.bitmap)));
                quote!(#id: #e,)
            });
            quote!(Blocks { #(#fields)* })
        });
        // The result back in blades: each field a sum of entries (its sign applied).
        let names = Names::new(&bt, None);
        let out_fields = t.fields.iter().zip(&mu.from_units).map(|(f, row)| {
            let mut p = Poly::default();
            for &(k, c) in row {
                let v = Var {
                    operand: 0,
                    field: k as u16,
                };
                p.add_term(vec![v], c * Rational::int(f.sign as i64));
            }
            let (id, e) = (ident(&f.name), factored(&p, &names));
            quote!(#id: #e,)
        });
        let (name, s) = (ident(&t.name), &self.s);
        let fields = bt.fields.iter().map(|f| {
            let id = ident(&f.name);
            quote!(#id: #s,)
        });
        let body = quote! {
            #[derive(Clone, Copy)]
            struct Blocks { #(#fields)* }
            let ya = #ya;
            let yb = #yb;
            let a = {
                let (a, b) = (ya, yb);
                #product
            };
            #name { #(#out_fields)* }
        };
        let c_dim = mu.c_basis.len();
        let doc = format!(
            "matrix form: the operands as {n} x {n} matrices over a {c_dim}-dimensional algebra \
             (`Blocks`, entry `mRC_cK` for row R, column C, its blade K), {product_terms} \
             multiplies in place of {direct_terms}",
            n = mu.size
        );
        Some((body, doc, product_terms))
    }
}
