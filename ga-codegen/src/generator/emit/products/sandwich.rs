//! Fused sandwich products `v * x * ~v` and their matrix (outermorphism) form.
//!
//! Phases: [`Gen::sandwich_output`] picks (or checks) the output type, [`linear_form`] writes
//! the result as a linear map of the operand whose entries are polynomials in the versor,
//! [`Gen::sandwich_kernel`] turns that map into a straight-line program (temporaries, then one
//! expression per output field) and [`Kernel::body`] is the one place where a program becomes
//! tokens; the matrix form reuses the same temporaries.

use crate::generator::emit::render::{doc, ident, Names};
use crate::generator::emit::{snake, Gen, GenError, Op, OpSummary, OutType};
use crate::generator::spec::{SandwichDef, TypeDef};
use crate::generator::symbolic::{Monomial, Poly, Product, SymMv, Var};
use crate::generator::unit_versor::UnitIdeal;
use crate::runtime::blade::blade_name;
use crate::runtime::rational::Rational;
use proc_macro2::{Ident, TokenStream};
use quote::quote;
use std::collections::BTreeMap;

/// What [`Gen::sandwich_parts`] computes for one sandwich.
pub(crate) struct SandwichParts {
    /// Versor, operand and output type indices.
    pub versor: usize,
    pub operand: usize,
    pub output: usize,
    /// `coef[k][j]`, see [`linear_form`].
    pub coef: Vec<Vec<Poly>>,
    /// The straight-line program of the fused sandwich.
    pub kernel: Kernel,
    /// The matrix entries, row by row, in terms of `matrix_lets`' temporaries.
    pub matrix: Vec<Vec<TokenStream>>,
    /// The temporaries of the matrix form.
    pub matrix_lets: TokenStream,
    /// The doc: the expansion, and the factored form's cost when there is one.
    pub doc: String,
    /// Terms of the expansion.
    pub terms: usize,
}

impl SandwichParts {
    /// The versor, operand and output types.
    pub fn types<'s>(
        &self,
        spec: &'s crate::generator::spec::Spec,
    ) -> (&'s TypeDef, &'s TypeDef, &'s TypeDef) {
        (
            &spec.types[self.versor],
            &spec.types[self.operand],
            &spec.types[self.output],
        )
    }
}

/// A straight-line program for a sandwich: temporaries computed in order, then one expression
/// per output field (in terms of `a`, the versor, `b`, the operand, and the temporaries).
pub(crate) struct Kernel {
    /// `let name = expr;`, in order.
    pub temps: Vec<(Ident, TokenStream)>,
    /// The output fields and their expressions.
    pub outputs: Vec<(Ident, TokenStream)>,
}

impl Kernel {
    /// The temporaries as `let` statements.
    fn lets(&self) -> TokenStream {
        let (names, exprs): (Vec<_>, Vec<_>) = self.temps.iter().cloned().unzip();
        quote!(#(let #names = #exprs;)*)
    }

    /// The kernel as a function body building a value of type `out`.
    fn body(&self, out: &Ident) -> TokenStream {
        let lets = self.lets();
        let (fields, exprs): (Vec<_>, Vec<_>) = self.outputs.iter().cloned().unzip();
        quote!(let a = self; #lets #out { #(#fields: #exprs,)* })
    }
}

/// `coef[k][j]`: the coefficient polynomial (in the versor) of operand field `j` in output
/// field `k`; column `nx` (the number of operand fields) is the constant part.
fn linear_form(r: &SymMv, tx: &TypeDef, to: &TypeDef) -> Vec<Vec<Poly>> {
    let nx = tx.fields.len();
    let mut coef: Vec<Vec<Poly>> = vec![vec![Poly::default(); nx + 1]; to.fields.len()];
    for (k, f) in to.fields.iter().enumerate() {
        let p = r.get(f.bitmap);
        for (m, &c) in &p.0 {
            let j = m
                .iter()
                .find(|v| v.operand == 1)
                .map(|v| v.field as usize)
                .unwrap_or(nx);
            let rest: Monomial = m.iter().copied().filter(|v| v.operand != 1).collect();
            coef[k][j].add_term(rest, c * Rational::int(f.sign as i64));
        }
    }
    coef
}

impl Gen<'_> {
    /// The symbolic sandwich `v * x * ~v` and its output type: the declared one (checked),
    /// else the inferred one.
    ///
    /// A unit versor's sandwich is reduced modulo `a ~a = 1` and keeps the grades of the
    /// operand (see [`crate::generator::unit_versor`]); the identities used come back with it.
    fn sandwich_output(&mut self, d: &SandwichDef) -> Result<(SymMv, UnitIdeal, usize), GenError> {
        let spec = self.spec;
        let (tv, tx) = (&spec.types[d.versor], &spec.types[d.operand]);
        let (r, ideal) = if tv.unit {
            crate::generator::unit_versor::unit_sandwich(&mut self.table, &self.alg, tv, tx)
        } else {
            let a = SymMv::of_type(tv, 0);
            let b = SymMv::of_type(tx, 1);
            let ab = self.table.product(&a, &b, Product::Geometric);
            let r = self.table.product(&ab, &a.rev(), Product::Geometric);
            (r, UnitIdeal::default())
        };
        let oi = match d.output {
            Some(oi) => {
                let to = &spec.types[oi];
                let err = |bm| GenError::SandwichOutput {
                    file: spec.source.clone(),
                    versor: tv.name.clone(),
                    operand: tx.name.clone(),
                    output: to.name.clone(),
                    blade: blade_name(bm, spec.metric.names()),
                };
                // For a unit versor, blades the output type does not hold (and its constants)
                // are those that vanish because `x ~x = 1` (e.g. the grade-5 part of a motor
                // sandwich, which is zero by the motor constraint). They are dropped only
                // after checking numerically on random unit versors of the type.
                let unit_ok = tv.unit
                    && crate::generator::verify::unit_versor_drop_ok(
                        &self.alg, spec, d.versor, d.operand, &r, oi,
                    );
                for bm in r.support() {
                    if to.field(bm).is_some() {
                        continue;
                    }
                    match to.constant(bm) {
                        Some(c) if unit_ok || r.get(bm).as_constant() == Some(c) => {}
                        _ if unit_ok => {}
                        _ => return Err(err(bm)),
                    }
                }
                for &(bm, c) in &to.constants {
                    if !unit_ok && r.get(bm).as_constant() != Some(c) {
                        return Err(err(bm));
                    }
                }
                oi
            }
            None => match self.infer(&r) {
                OutType::Zero => {
                    return Err(GenError::ZeroSandwich {
                        file: spec.source.clone(),
                        versor: tv.name.clone(),
                        operand: tx.name.clone(),
                    })
                }
                _ => self.holder(&r).ok_or_else(|| GenError::NoSandwichOutput {
                    file: spec.source.clone(),
                    versor: tv.name.clone(),
                    operand: tx.name.clone(),
                })?,
            },
        };
        Ok((r, ideal, oi))
    }

    /// The straight-line program of a sandwich from its linear form: every product of two
    /// versor coefficients is a temporary (`s_e12`), shared by every output field, and each
    /// output field is linear in the operand. Also the matrix entries (rows of `coef`) in
    /// terms of the same temporaries, for the matrix form.
    fn sandwich_kernel(
        &self,
        tv: &TypeDef,
        tx: &TypeDef,
        to: &TypeDef,
        coef: &[Vec<Poly>],
    ) -> (Kernel, Vec<Vec<TokenStream>>) {
        let nx = tx.fields.len();
        let names = Names::new(tv, Some(tx));
        // Shared subexpressions: every product of two versor coefficients.
        let mut shared: BTreeMap<Monomial, Ident> = BTreeMap::new();
        for row in coef {
            for p in row {
                for m in p.0.keys() {
                    if m.len() == 2 {
                        let name = format!(
                            "{}_{}",
                            tv.fields[m[0].field as usize].name,
                            tv.fields[m[1].field as usize].name
                        );
                        shared.insert(m.clone(), ident(&name));
                    }
                }
            }
        }
        let temps = shared
            .iter()
            .map(|(m, n)| (n.clone(), names.monomial(m)))
            .collect();
        let mono = |m: &Monomial| -> TokenStream {
            match shared.get(m) {
                Some(n) => quote!(#n),
                None => names.monomial(m),
            }
        };
        let outputs = to
            .fields
            .iter()
            .enumerate()
            .map(|(k, f)| {
                let mut e = TokenStream::new();
                for j in 0..=nx {
                    let p = &coef[k][j];
                    if p.is_zero() {
                        continue;
                    }
                    if !e.is_empty() {
                        e.extend(quote!(+));
                    }
                    let inner = names.poly_with(p, mono);
                    if j < nx {
                        let x = ident(&tx.fields[j].name);
                        e.extend(quote!(b.#x * (#inner)));
                    } else {
                        e.extend(quote!((#inner)));
                    }
                }
                if e.is_empty() {
                    e = quote!(0.0);
                }
                (ident(&f.name), e)
            })
            .collect();
        let entries = coef
            .iter()
            .map(|row| row.iter().map(|p| names.poly_with(p, mono)).collect())
            .collect();
        (Kernel { temps, outputs }, entries)
    }

    /// Everything a sandwich's emitters need: the types, the linear form, the straight-line
    /// kernel (the factored program where one is proven cheaper), the matrix entries and the
    /// doc with its expansion.
    pub(crate) fn sandwich_parts(&mut self, d: &SandwichDef) -> Result<SandwichParts, GenError> {
        let (r, ideal, oi) = self.sandwich_output(d)?;
        let spec = self.spec;
        let (tv, tx, to) = (
            &spec.types[d.versor],
            &spec.types[d.operand],
            &spec.types[oi],
        );
        let coef = linear_form(&r, tx, to);
        let (mut kernel, matrix) = self.sandwich_kernel(tv, tx, to, &coef);
        // The matrix form keeps the pairwise products of the term-by-term kernel.
        let matrix_lets = kernel.lets();
        let (mut doc, terms) = self.sandwich_doc(tv, tx, to, &coef);
        // A cheaper straight-line program (two half products sharing work), proven equal to
        // the expansion, replaces the term-by-term body (see `factor`).
        let case = crate::generator::factor::SandwichCase {
            basis: spec.metric.names(),
            tv,
            tx,
            to,
            reduced: &r,
            ideal: &ideal,
        };
        if let Some(prog) = crate::generator::factor::sandwich_program(&mut self.table, &case) {
            let names = Names::new(tv, Some(tx));
            let var = |v: Var| names.var(v);
            kernel = Kernel {
                temps: prog.render_temps(&var),
                outputs: to
                    .fields
                    .iter()
                    .enumerate()
                    .map(|(k, f)| (ident(&f.name), prog.render_output(k, &var)))
                    .collect(),
            };
            let (m, ad) = prog.ops();
            doc.push_str(&format!(
                "\n\nComputed as {} ({m} multiplies, {ad} adds).",
                prog.form
            ));
        }
        Ok(SandwichParts {
            versor: d.versor,
            operand: d.operand,
            output: oi,
            coef,
            kernel,
            matrix,
            matrix_lets,
            doc,
            terms,
        })
    }

    /// The fused sandwich `impl Sandwich<X> for V`, the matrix type `VXMatrix` with `apply`,
    /// and `V::x_matrix()`.
    pub(crate) fn sandwich(&mut self, d: &SandwichDef) -> Result<(), GenError> {
        let parts = self.sandwich_parts(d)?;
        let (tv, tx, to) = parts.types(self.spec);
        let SandwichParts {
            coef,
            kernel,
            matrix,
            matrix_lets: lets,
            doc: sdoc,
            terms: nterms,
            ..
        } = parts;
        let (vn, xn, on) = (ident(&tv.name), ident(&tx.name), ident(&to.name));
        let body = kernel.body(&on);
        let sdoc = doc(&sdoc);
        let matrix = self.sandwich_matrix(&super::matrix::MatrixInput {
            tv,
            tx,
            to,
            coef: &coef,
            entries: &matrix,
            lets: &lets,
        });
        self.out.extend(quote! {
            impl Sandwich<#xn> for #vn {
                type Output = #on;
                #sdoc
                #[inline]
                fn sandwich(&self, b: #xn) -> #on { #body }
            }
            #matrix
        });
        self.ops.push(OpSummary {
            op: Op::Sandwich,
            left: tv.name.clone(),
            right: tx.name.clone(),
            output: to.name.clone(),
            terms: nterms,
            matrix_form: None,
        });
        Ok(())
    }

    /// The doc of a fused sandwich with its symbolic expansion, and the number of terms.
    fn sandwich_doc(
        &self,
        tv: &TypeDef,
        tx: &TypeDef,
        to: &TypeDef,
        coef: &[Vec<Poly>],
    ) -> (String, usize) {
        let names = Names::new(tv, Some(tx));
        let nx = tx.fields.len();
        let mut doc = format!(
            "`{v} * {x} * ~{v}`, fused into one function. To apply one `{v}` to many operands, \
             build its matrix form once (`{v}::{m}_matrix`, a `{v}{x}Matrix`) and `apply` it: \
             a matrix product per operand.\n\nSymbolic expansion (`a` the versor, `b` the \
             operand; each output coefficient is linear in the operand):\n",
            v = tv.name,
            x = tx.name,
            m = snake(&tx.name),
        );
        let mut nterms = 0;
        for (k, f) in to.fields.iter().enumerate() {
            let mut dparts = Vec::new();
            for j in 0..=nx {
                let p = &coef[k][j];
                if p.is_zero() {
                    continue;
                }
                nterms += p.0.len();
                let dinner = names.poly_text(p);
                if j < nx {
                    dparts.push(format!("b.{} * ({dinner})", tx.fields[j].name));
                } else {
                    dparts.push(format!("({dinner})"));
                }
            }
            doc.push_str(&format!(
                "\n- `{}` = {}",
                f.name,
                if dparts.is_empty() {
                    "0".to_string()
                } else {
                    dparts.join(" + ")
                }
            ));
        }
        for &(bm, c) in &to.constants {
            doc.push_str(&format!(
                "\n- `{}` = {} (constant of `{}`)",
                blade_name(bm, self.spec.metric.names()),
                c,
                to.name
            ));
        }
        (doc, nterms)
    }
}
