//! Result types: the smallest declared type that holds a symbolic result, and the expression
//! that builds it.

use crate::generator::emit::render::{ident, Names};
use crate::generator::emit::{Gen, OutType};
use crate::generator::symbolic::{Poly, Product, SymMv};
use crate::runtime::blade::{grade, reorder_sign, Bitmap};
use crate::runtime::rational::Rational;
use proc_macro2::TokenStream;
use quote::quote;

/// Multiply terms of a symbolic result (constant terms not counted).
pub(crate) fn terms(m: &SymMv) -> usize {
    m.0.values()
        .map(|p| p.0.keys().filter(|k| !k.is_empty()).count())
        .sum()
}

impl Gen<'_> {
    /// The result type of `m`: zero, a scalar, or the smallest declared type that holds every
    /// blade of `m` and whose constants `m` keeps; [`OutType::Unfit`] when none does (only in
    /// an algebra without the general multivector).
    pub(crate) fn infer(&self, m: &SymMv) -> OutType {
        let support = m.support();
        if support.is_empty() {
            return OutType::Zero;
        }
        if support == [0] {
            return OutType::Scalar;
        }
        self.holder(m).map_or(OutType::Unfit, OutType::Type)
    }

    /// The smallest declared type that holds every blade of `m` (the scalar included) and
    /// whose constants `m` keeps.
    pub(crate) fn holder(&self, m: &SymMv) -> Option<usize> {
        self.by_size.iter().copied().find(|&ti| self.holds(ti, m))
    }

    /// Whether type `ti` holds every blade of `m` and `m` keeps its constants.
    fn holds(&self, ti: usize, m: &SymMv) -> bool {
        let t = &self.spec.types[ti];
        let support = m.support();
        support.iter().all(|b| t.blades().any(|x| x == *b))
            && t.constants
                .iter()
                .all(|&(b, c)| m.get(b).as_constant() == Some(c))
    }

    /// The result type of the geometric product `m` of two versor types: a product of
    /// versors is a versor, so the smallest declared versor type that holds it (a translator
    /// times a dilator is a scaled motor, not the scalar-plus-bivector type that also holds
    /// it), else what [`Gen::infer`] gives.
    pub(crate) fn infer_versor_product(&self, m: &SymMv) -> OutType {
        match self.infer(m) {
            OutType::Type(_) => self
                .by_size
                .iter()
                .copied()
                .find(|&ti| self.spec.types[ti].versor && self.holds(ti, m))
                .map_or_else(|| self.infer(m), OutType::Type),
            o => o,
        }
    }

    /// The result type of `a op b` for operand types `ta`, `tb`: see
    /// [`Gen::infer_versor_product`] for the geometric product of two versor types, else
    /// [`Gen::infer`].
    pub(crate) fn infer_op(
        &self,
        m: &SymMv,
        op: crate::generator::emit::Op,
        (ta, tb): (
            &crate::generator::spec::TypeDef,
            &crate::generator::spec::TypeDef,
        ),
    ) -> OutType {
        if op == crate::generator::emit::Op::Geometric && ta.versor && tb.versor {
            self.infer_versor_product(m)
        } else {
            self.infer(m)
        }
    }

    /// Whether `o` is [`OutType::Unfit`]; if so, `what` (`Vector * Vector`, `Point::dual`)
    /// is recorded as skipped with the grades of `m`, the result no declared type holds.
    pub(crate) fn skip_unfit(&mut self, o: OutType, m: &SymMv, what: &str) -> bool {
        if o != OutType::Unfit {
            return false;
        }
        let mut grades: Vec<u32> = m.support().iter().map(|&b| grade(b)).collect();
        grades.dedup();
        grades.sort_unstable();
        grades.dedup();
        let list: Vec<String> = grades.iter().map(u32::to_string).collect();
        let word = if grades.len() == 1 { "grade" } else { "grades" };
        self.skipped
            .push(format!("{what} -> {word} {}", list.join(", ")));
        true
    }

    /// The name of a result type (the scalar type for scalars).
    pub(crate) fn out_name(&self, o: OutType) -> String {
        match o {
            OutType::Type(t) => self.spec.types[t].name.clone(),
            _ => self.scalar.name().to_string(),
        }
    }

    /// A result type as tokens.
    pub(crate) fn out_type(&self, o: OutType) -> TokenStream {
        match o {
            OutType::Type(t) => {
                let id = ident(&self.spec.types[t].name);
                quote!(#id)
            }
            _ => self.s.clone(),
        }
    }

    /// The expression building the result `o` from `m`.
    pub(crate) fn build(&self, o: OutType, m: &SymMv, names: &Names) -> TokenStream {
        match o {
            OutType::Zero => quote!(0.0),
            OutType::Unfit => unreachable!("a result no type holds is skipped, not built"),
            OutType::Scalar => names.poly(&m.get(0)),
            OutType::Type(ti) => {
                let t = &self.spec.types[ti];
                let name = ident(&t.name);
                let fields = t.fields.iter().map(|f| {
                    let mut p = Poly::default();
                    p.add_scaled(&m.get(f.bitmap), Rational::int(f.sign as i64));
                    let (id, e) = (ident(&f.name), names.poly(&p));
                    quote!(#id: #e,)
                });
                quote!(#name { #(#fields)* })
            }
        }
    }

    /// The symbolic expansion of the result `o` from `m`, one line per output field
    /// (`` - `e12` = a.s * b.e12 + ...``), for docs.
    pub(crate) fn expansion(&self, o: OutType, m: &SymMv, names: &Names) -> String {
        match o {
            OutType::Zero => "0".to_string(),
            OutType::Unfit => unreachable!("a result no type holds is skipped, not documented"),
            OutType::Scalar => format!("- `s` = {}", names.poly_text(&m.get(0))),
            OutType::Type(ti) => self.spec.types[ti]
                .fields
                .iter()
                .map(|f| {
                    let mut p = Poly::default();
                    p.add_scaled(&m.get(f.bitmap), Rational::int(f.sign as i64));
                    format!("- `{}` = {}", f.name, names.poly_text(&p))
                })
                .collect::<Vec<_>>()
                .join("\n"),
        }
    }

    /// Whether the metric is degenerate (a basis vector squares to zero).
    pub(crate) fn degenerate(&self) -> bool {
        self.table
            .metric()
            .orthogonal_basis()
            .1
            .iter()
            .any(|d| d.is_zero())
    }

    /// The doc of `dual`, which depends on the metric.
    pub(crate) fn dual_doc(&self) -> &'static str {
        if self.degenerate() {
            "The dual: the right complement (`x ^ dual(x) = I` blade by blade), as the metric is degenerate."
        } else {
            "The dual `x * I^-1`, with `I` the outer product of the basis in order."
        }
    }

    /// The dual of `a`: `a * I^-1`, or the right complement for a degenerate metric.
    pub(crate) fn dual(&mut self, a: &SymMv) -> SymMv {
        let n = self.spec.metric.dim();
        let full: Bitmap = (1 << n) - 1;
        if self.degenerate() {
            a.map_blades(|b| {
                let comp = full & !b;
                vec![(comp, Rational::int(reorder_sign(b, comp) as i64))]
            })
        } else {
            let mut i = SymMv::default();
            i.0.insert(full, Poly::constant(Rational::ONE));
            let ii = self.table.product(&i, &i.rev(), Product::Scalar).get(0);
            let ii = ii.as_constant().expect("constant");
            let mut inv = SymMv::default();
            inv.0.insert(
                full,
                Poly::constant(
                    Rational::int(crate::runtime::blade::reverse_sign(full) as i64) / ii,
                ),
            );
            self.table.product(a, &inv, Product::Geometric)
        }
    }

    /// The doc of `undual`, which depends on the metric.
    pub(crate) fn undual_doc(&self) -> &'static str {
        if self.degenerate() {
            "The undual, inverse of `dual`: the left complement (`undual(x) ^ x = I` blade by blade)."
        } else {
            "The undual `x * I`, inverse of `dual`, with `I` the outer product of the basis in order."
        }
    }

    /// The undual of `a`, inverse of [`Gen::dual`]: `a * I`, or the left complement for a
    /// degenerate metric.
    pub(crate) fn undual(&mut self, a: &SymMv) -> SymMv {
        let n = self.spec.metric.dim();
        let full: Bitmap = (1 << n) - 1;
        if self.degenerate() {
            a.map_blades(|b| {
                let comp = full & !b;
                vec![(comp, Rational::int(reorder_sign(comp, b) as i64))]
            })
        } else {
            let mut i = SymMv::default();
            i.0.insert(full, Poly::constant(Rational::ONE));
            self.table.product(a, &i, Product::Geometric)
        }
    }
}
