//! The Rust emitter: turns a validated [`Spec`] into a formatted Rust module.
//!
//! Every product of two declared types is expanded symbolically ([`crate::symbolic`]), every
//! identically-zero term is dropped, and the result type is the smallest declared type that
//! holds every remaining blade (a pure scalar is returned as the scalar type itself; a product
//! that is identically zero is not emitted at all). The output is meant for `include!` inside a
//! module: it has no inner attributes.

use crate::blade::{blade_name, grade, reorder_sign, Bitmap};
use crate::rational::Rational;
use crate::spec::{Spec, TypeDef};
use crate::symbolic::{BladeTable, Monomial, Poly, Product, SymMv, Var};
use std::collections::BTreeMap;
use std::fmt::{self, Write};

/// The scalar type of the generated code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ScalarType {
    /// `f32`.
    F32,
    /// `f64`.
    #[default]
    F64,
}

impl ScalarType {
    /// The Rust type name.
    pub fn name(self) -> &'static str {
        match self {
            ScalarType::F32 => "f32",
            ScalarType::F64 => "f64",
        }
    }
}

/// Options of the emitter.
#[derive(Clone, Debug)]
pub struct EmitOptions {
    /// Scalar type.
    pub scalar: ScalarType,
    /// Path of the `ga-codegen` runtime crate in the generated code.
    pub runtime: String,
}

impl Default for EmitOptions {
    fn default() -> Self {
        EmitOptions {
            scalar: ScalarType::F64,
            runtime: "::ga_codegen".to_string(),
        }
    }
}

/// Why code could not be generated from a valid spec.
#[derive(Clone, Debug, PartialEq)]
pub enum GenError {
    /// A sandwich's declared output type cannot hold a blade of the result.
    SandwichOutput {
        /// The spec file.
        file: String,
        /// Versor type.
        versor: String,
        /// Operand type.
        operand: String,
        /// Declared output type.
        output: String,
        /// The blade it cannot hold (or a constant it does not keep).
        blade: String,
    },
    /// A sandwich that is identically zero.
    ZeroSandwich {
        /// The spec file.
        file: String,
        /// Versor type.
        versor: String,
        /// Operand type.
        operand: String,
    },
    /// The emitted code did not parse (a generator bug).
    Internal(String),
}

impl fmt::Display for GenError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GenError::SandwichOutput { file, versor, operand, output, blade } => write!(
                f,
                "{file}: type `{output}`: `{blade}`: output of the sandwich of `{operand}` by `{versor}` cannot hold this blade (or keep this constant; constants need a `unit` versor)"
            ),
            GenError::ZeroSandwich { file, versor, operand } => {
                write!(f, "{file}: type `{versor}`: `{operand}`: the sandwich is identically zero")
            }
            GenError::Internal(m) => write!(f, "internal generator error: {m}"),
        }
    }
}

impl std::error::Error for GenError {}

/// What a product returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutType {
    /// Identically zero: not emitted.
    Zero,
    /// A pure scalar: the scalar type.
    Scalar,
    /// A declared type (index).
    Type(usize),
}

/// One emitted binary operation, for the summary.
#[derive(Clone, Debug, PartialEq)]
pub struct OpSummary {
    /// Operator (`*`, `^`, `|`, `+`, `-`, `sandwich`).
    pub op: String,
    /// Left type.
    pub left: String,
    /// Right type.
    pub right: String,
    /// Result type name (`f64` for scalars).
    pub output: String,
    /// Number of multiply terms after simplification.
    pub terms: usize,
}

/// Generated code and its summary.
#[derive(Clone, Debug)]
pub struct Generated {
    /// The formatted module.
    pub code: String,
    /// Types: name and number of stored fields.
    pub types: Vec<(String, usize)>,
    /// Every emitted binary operation, sandwich and conversion (`from`).
    pub ops: Vec<OpSummary>,
    /// Emitted unary methods whose result is not fixed: (type, method).
    pub methods: Vec<(String, String)>,
    /// Operations skipped because identically zero.
    pub zero_ops: usize,
}

impl Generated {
    /// Lines of generated code.
    pub fn lines(&self) -> usize {
        self.code.lines().count()
    }

    /// A human-readable summary: types, then the product table.
    pub fn summary(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "types ({}):", self.types.len());
        for (n, f) in &self.types {
            let _ = writeln!(s, "  {n:<16} {f} fields");
        }
        let total: usize = self.ops.iter().map(|o| o.terms).sum();
        let _ = writeln!(
            s,
            "operations: {} emitted ({} multiply terms), {} identically zero and skipped",
            self.ops.len(),
            total,
            self.zero_ops
        );
        for o in self
            .ops
            .iter()
            .filter(|o| o.op == "*" || o.op == "sandwich")
        {
            let _ = writeln!(
                s,
                "  {:<12} {:<9} {:<12} -> {:<12} {:>5} terms",
                o.left, o.op, o.right, o.output, o.terms
            );
        }
        let _ = writeln!(s, "lines of code: {}", self.lines());
        s
    }
}

fn lit(c: Rational) -> String {
    let x = c.to_f64();
    let s = format!("{x:?}");
    if s.contains('.') || s.contains('e') {
        s
    } else {
        format!("{s}.0")
    }
}

/// snake_case of an UpperCamel name.
pub fn snake(name: &str) -> String {
    let mut s = String::new();
    for (i, ch) in name.chars().enumerate() {
        if ch.is_ascii_uppercase() {
            if i > 0 {
                s.push('_');
            }
            s.push(ch.to_ascii_lowercase());
        } else {
            s.push(ch);
        }
    }
    s
}

/// Renders polynomials with variable names.
struct Names<'a> {
    types: [Option<&'a TypeDef>; 2],
    prefix: [&'a str; 2],
}

impl Names<'_> {
    fn var(&self, v: Var) -> String {
        match v.operand {
            0 | 1 => {
                let t = self.types[v.operand as usize].expect("operand type");
                format!(
                    "{}.{}",
                    self.prefix[v.operand as usize], t.fields[v.field as usize].name
                )
            }
            _ => "s".to_string(),
        }
    }

    fn monomial(&self, m: &Monomial) -> String {
        m.iter()
            .map(|v| self.var(*v))
            .collect::<Vec<_>>()
            .join(" * ")
    }

    /// `c1 * m1 + c2 * m2 - ...`, or `0.0`.
    fn poly(&self, p: &Poly) -> String {
        self.poly_with(p, |m| self.monomial(m))
    }

    fn poly_with(&self, p: &Poly, mono: impl Fn(&Monomial) -> String) -> String {
        if p.is_zero() {
            return "0.0".to_string();
        }
        let mut s = String::new();
        for (i, (m, &c)) in p.0.iter().enumerate() {
            let neg = c < Rational::ZERO;
            let mag = if neg { -c } else { c };
            if i == 0 {
                if neg {
                    s.push('-');
                }
            } else {
                s.push_str(if neg { " - " } else { " + " });
            }
            let ms = mono(m);
            if m.is_empty() {
                s.push_str(&lit(mag));
            } else if mag == Rational::ONE {
                s.push_str(&ms);
            } else {
                let _ = write!(s, "{} * {}", lit(mag), ms);
            }
        }
        s
    }
}

fn terms(m: &SymMv) -> usize {
    m.0.values()
        .map(|p| p.0.keys().filter(|k| !k.is_empty()).count())
        .sum()
}

struct Gen<'a> {
    spec: &'a Spec,
    table: BladeTable,
    s: &'static str,
    rt: String,
    out: String,
    ops: Vec<OpSummary>,
    methods: Vec<(String, String)>,
    zero_ops: usize,
    /// Type indices ordered by size, for result inference.
    by_size: Vec<usize>,
    /// The generic algebra, for numerical checks at generation time.
    alg: std::sync::Arc<crate::Algebra>,
}

impl<'a> Gen<'a> {
    fn infer(&self, m: &SymMv) -> OutType {
        let support = m.support();
        if support.is_empty() {
            return OutType::Zero;
        }
        if support == [0] {
            return OutType::Scalar;
        }
        for &ti in &self.by_size {
            let t = &self.spec.types[ti];
            let holds = support.iter().all(|b| t.blades().any(|x| x == *b));
            let consts_ok = t
                .constants
                .iter()
                .all(|&(b, c)| m.get(b).as_constant() == Some(c));
            if holds && consts_ok {
                return OutType::Type(ti);
            }
        }
        unreachable!("the general multivector holds every blade")
    }

    fn out_name(&self, o: OutType) -> String {
        match o {
            OutType::Type(t) => self.spec.types[t].name.clone(),
            _ => self.s.to_string(),
        }
    }

    /// The body expression building the result `o` from `m`.
    fn build(&self, o: OutType, m: &SymMv, names: &Names) -> String {
        match o {
            OutType::Zero => "0.0".to_string(),
            OutType::Scalar => names.poly(&m.get(0)),
            OutType::Type(ti) => {
                let t = &self.spec.types[ti];
                let mut s = format!("{} {{ ", t.name);
                for f in &t.fields {
                    let mut p = Poly::default();
                    p.add_scaled(&m.get(f.bitmap), Rational::int(f.sign as i64));
                    let _ = write!(s, "{}: {}, ", f.name, names.poly(&p));
                }
                s.push('}');
                s
            }
        }
    }

    fn header(&mut self) {
        let spec = self.spec;
        let n = spec.metric.dim();
        let s = self.s;
        let rt = &self.rt;
        let basis: Vec<String> = spec
            .metric
            .names()
            .iter()
            .map(|b| format!("{b:?}"))
            .collect();
        let metric: Vec<String> = (0..n)
            .map(|i| {
                format!(
                    "[{}]",
                    (0..n)
                        .map(|j| lit(spec.metric.get(i, j)))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            })
            .collect();
        let _ = write!(
            self.out,
            r#"
/// Names of the basis vectors, in order (blade bitmaps use this order).
pub const BASIS: [&str; {n}] = [{basis}];

/// The metric: `METRIC[i][j]` is the inner product of basis vectors `i` and `j`.
pub const METRIC: [[f64; {n}]; {n}] = [{metric}];

/// The generic algebra of this module, for the slow reference [`{rt}::Multivector`].
pub fn algebra() -> ::std::sync::Arc<{rt}::Algebra> {{
    static ALGEBRA: ::std::sync::OnceLock<::std::sync::Arc<{rt}::Algebra>> = ::std::sync::OnceLock::new();
    ALGEBRA
        .get_or_init(|| {{
            let rows: ::std::vec::Vec<::std::vec::Vec<f64>> = METRIC.iter().map(|r| r.to_vec()).collect();
            {rt}::Algebra::from_metric(&BASIS, &rows).expect("the metric was validated when the code was generated")
        }})
        .clone()
}}

/// The sandwich product `self * x * ~self` of a versor with `x`, fused into one expression.
pub trait Sandwich<X> {{
    /// The type of the result.
    type Output;
    /// `self * x * ~self`.
    fn sandwich(&self, x: X) -> Self::Output;
}}

/// The scalar type of this module.
pub type Scalar = {s};
"#,
            basis = basis.join(", "),
            metric = metric.join(", "),
        );
    }

    fn type_def(&mut self, ti: usize) {
        let spec = self.spec;
        let t = &spec.types[ti];
        let s = self.s;
        let rt = self.rt.clone();
        let basis = spec.metric.names();
        let mut doc = t
            .doc
            .clone()
            .unwrap_or_else(|| format!("The `{}` type.", t.name));
        let _ = write!(
            doc,
            "\n\nStored blades: {}.",
            t.fields
                .iter()
                .map(|f| format!("`{}`", f.name))
                .collect::<Vec<_>>()
                .join(", ")
        );
        if !t.constants.is_empty() {
            let _ = write!(
                doc,
                " Constant blades (not stored): {}.",
                t.constants
                    .iter()
                    .map(|&(b, c)| format!("`{}` = {}", blade_name(b, basis), c))
                    .collect::<Vec<_>>()
                    .join(", ")
            );
        }
        if t.unit {
            doc.push_str(" Assumed normalised (`x * ~x = 1`) by its sandwich products.");
        }
        let _ = write!(
            self.out,
            "#[doc = {doc:?}]\n#[repr(C)]\n#[derive(Clone, Copy, Debug, PartialEq, Default)]\npub struct {} {{\n",
            t.name
        );
        for f in &t.fields {
            let _ = writeln!(
                self.out,
                "#[doc = {:?}] pub {}: {s},",
                format!("Coefficient of `{}`.", f.name),
                f.name
            );
        }
        self.out.push_str("}\n");

        let names1 = Names {
            types: [Some(t), None],
            prefix: ["a", "b"],
        };
        let a = SymMv::of_type(t, 0);
        let args: Vec<String> = t
            .fields
            .iter()
            .map(|f| format!("{}: {s}", f.name))
            .collect();
        let fnames: Vec<String> = t.fields.iter().map(|f| f.name.clone()).collect();
        let nf = t.fields.len();
        let _ = write!(
            self.out,
            r#"impl {name} {{
    /// Number of stored coefficients.
    pub const LEN: usize = {nf};
    /// Field (blade) names in storage order.
    pub const BLADES: [&'static str; {nf}] = [{blade_list}];
    /// A value from its coefficients, in storage order.
    #[inline]
    #[must_use]
    #[allow(clippy::too_many_arguments)]
    pub const fn new({args}) -> Self {{ Self {{ {fields} }} }}
    /// The coefficients in storage order.
    #[inline]
    #[must_use]
    pub const fn to_array(self) -> [{s}; {nf}] {{ [{self_fields}] }}
    /// A value from coefficients in storage order.
    #[inline]
    #[must_use]
    pub const fn from_array(c: [{s}; {nf}]) -> Self {{ Self {{ {from_arr} }} }}
"#,
            name = t.name,
            blade_list = fnames
                .iter()
                .map(|n| format!("{n:?}"))
                .collect::<Vec<_>>()
                .join(", "),
            args = args.join(", "),
            fields = fnames.join(", "),
            self_fields = fnames
                .iter()
                .map(|n| format!("self.{n}"))
                .collect::<Vec<_>>()
                .join(", "),
            from_arr = fnames
                .iter()
                .enumerate()
                .map(|(i, n)| format!("{n}: c[{i}]"))
                .collect::<Vec<_>>()
                .join(", "),
        );
        // Unary operations with inferred result types.
        let unary: [(&str, &str, SymMv); 4] = [
            (
                "rev",
                "The reverse (reverses the order of every outer product).",
                a.rev(),
            ),
            (
                "involute",
                "The grade involution (negates odd grades).",
                a.involute(),
            ),
            (
                "conjugate",
                "The Clifford conjugate (reverse of the grade involution).",
                a.conjugate(),
            ),
            ("dual", self.dual_doc(), self.dual(&a)),
        ];
        for (fname, fdoc, m) in unary.iter() {
            let o = self.infer(m);
            if o == OutType::Zero {
                continue;
            }
            self.methods.push((t.name.clone(), fname.to_string()));
            let _ = writeln!(
                self.out,
                "#[doc = {fdoc:?}] #[inline] #[must_use] pub fn {fname}(self) -> {} {{ {} }}",
                self.out_name(o),
                bind_self(&self.build(o, m, &names1))
            );
        }
        let nsq = self.table.product(&a, &a.rev(), Product::Scalar);
        let _ = write!(
            self.out,
            r#"/// `<x ~x>_0`, the squared norm (zero for null elements such as conformal points).
    #[inline] #[must_use] pub fn norm_squared(self) -> {s} {{ {nsq} }}
    /// `sqrt(|<x ~x>_0|)`.
    #[inline] #[must_use] pub fn norm(self) -> {s} {{ self.norm_squared().abs().sqrt() }}
"#,
            nsq = bind_self(&names1.poly(&nsq.get(0))),
        );
        if t.constants.is_empty() {
            for m in ["grade", "normalized", "inverse"] {
                self.methods.push((t.name.clone(), m.to_string()));
            }
            let scaled = |sign: &dyn Fn(Bitmap) -> i32, factor: &str| -> String {
                let parts: Vec<String> = t
                    .fields
                    .iter()
                    .map(|f| {
                        let sg = if sign(f.bitmap) < 0 { "-" } else { "" };
                        format!("{}: {sg}self.{} * {factor}", f.name, f.name)
                    })
                    .collect();
                format!("Self {{ {} }}", parts.join(", "))
            };
            let grades: Vec<String> = t
                .fields
                .iter()
                .map(|f| {
                    format!(
                        "{}: if k == {} {{ self.{} }} else {{ 0.0 }}",
                        f.name,
                        grade(f.bitmap),
                        f.name
                    )
                })
                .collect();
            let _ = write!(
                self.out,
                r#"/// The grade-`k` part.
    #[inline] #[must_use] pub fn grade(self, k: u32) -> Self {{ Self {{ {grades} }} }}
    /// `x / norm(x)`; not finite when the norm is zero.
    #[inline] #[must_use] pub fn normalized(self) -> Self {{ let r = 1.0 / self.norm(); {normed} }}
    /// The versor (and blade) inverse `~x / <x ~x>_0`. It is the inverse of `x` whenever
    /// `x ~x` is a scalar, as for every versor and blade; not finite when that scalar is zero.
    #[inline] #[must_use] pub fn inverse(self) -> Self {{ let r = 1.0 / self.norm_squared(); {inv} }}
"#,
                grades = grades.join(", "),
                normed = scaled(&|_| 1, "r"),
                inv = scaled(&crate::blade::reverse_sign, "r"),
            );
        }
        // Conversions to and from the generic multivector.
        let mut to_mv = String::new();
        for f in &t.fields {
            let _ = write!(
                to_mv,
                "m.set({}, {}self.{}{});",
                f.bitmap,
                if f.sign < 0 { "-" } else { "" },
                f.name,
                // The generic multivector is f64: widen f32 coefficients, leave f64 ones alone.
                if self.s == "f64" { "" } else { " as f64" }
            );
        }
        for &(b, c) in &t.constants {
            let _ = write!(to_mv, "m.set({b}, {});", lit(c));
        }
        let from_mv: Vec<String> = t
            .fields
            .iter()
            .map(|f| {
                let sign = if f.sign < 0 { "-" } else { "" };
                if s == "f64" {
                    format!("{}: {sign}m.get({})", f.name, f.bitmap)
                } else {
                    format!("{}: ({sign}m.get({})) as {s}", f.name, f.bitmap)
                }
            })
            .collect();
        let _ = write!(
            self.out,
            r#"/// This value as a generic multivector (constant blades included).
    #[must_use] pub fn to_multivector(self) -> {rt}::Multivector {{ let mut m = {rt}::Multivector::zero(&algebra()); {to_mv} m }}
    /// The stored blades of a generic multivector; other blades and constant blades are ignored.
    #[must_use] pub fn from_multivector(m: &{rt}::Multivector) -> Self {{ Self {{ {from} }} }}
}}
impl ::core::convert::From<{name}> for {rt}::Multivector {{
    fn from(x: {name}) -> Self {{ x.to_multivector() }}
}}
"#,
            name = t.name,
            from = from_mv.join(", "),
        );
        // Negation and scalar products.
        let scalar_ops: [(&str, &str, &str, SymMv, &str); 2] = [
            ("Neg", "neg", "", a.add_scaled(&a, Rational::int(-2)), ""),
            (
                "Mul",
                "mul",
                s,
                self.table
                    .product(&a, &SymMv::scalar_var(), Product::Geometric),
                "",
            ),
        ];
        for (tr, method, rhs, m, pre) in scalar_ops.iter() {
            let o = self.infer(m);
            let arg = if rhs.is_empty() {
                String::new()
            } else {
                format!(", s: {rhs}")
            };
            let gen = if rhs.is_empty() {
                String::new()
            } else {
                format!("<{rhs}>")
            };
            let _ = writeln!(
                self.out,
                "impl ::core::ops::{tr}{gen} for {name} {{ type Output = {on}; #[inline] fn {method}(self{arg}) -> {on} {{ let a = self; {pre} {body} }} }}",
                name = t.name,
                on = self.out_name(o),
                body = self.build(o, m, &names1),
            );
            if *tr == "Mul" {
                let _ = write!(
                    self.out,
                    "impl ::core::ops::Mul<{name}> for {s} {{ type Output = {on}; #[inline] fn mul(self, a: {name}) -> {on} {{ let s = self; {body} }} }}\n\
                     impl ::core::ops::Div<{s}> for {name} {{ type Output = {on}; #[inline] #[allow(clippy::suspicious_arithmetic_impl)] fn div(self, s: {s}) -> {on} {{ let a = self; let s = 1.0 / s; {body} }} }}\n",
                    name = t.name,
                    on = self.out_name(o),
                    body = self.build(o, m, &names1),
                );
            }
        }
    }

    fn dual_doc(&self) -> &'static str {
        if self
            .table
            .metric()
            .orthogonal_basis()
            .1
            .iter()
            .any(|d| d.is_zero())
        {
            "The dual: the right complement (`x ^ dual(x) = I` blade by blade), as the metric is degenerate."
        } else {
            "The dual `x * I^-1`, with `I` the outer product of the basis in order."
        }
    }

    fn dual(&mut self, a: &SymMv) -> SymMv {
        let n = self.spec.metric.dim();
        let full: Bitmap = (1 << n) - 1;
        let degenerate = self
            .table
            .metric()
            .orthogonal_basis()
            .1
            .iter()
            .any(|d| d.is_zero());
        if degenerate {
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
                Poly::constant(Rational::int(crate::blade::reverse_sign(full) as i64) / ii),
            );
            self.table.product(a, &inv, Product::Geometric)
        }
    }

    fn binary(&mut self, ai: usize, bi: usize) {
        let spec = self.spec;
        let (ta, tb) = (&spec.types[ai], &spec.types[bi]);
        let names = Names {
            types: [Some(ta), Some(tb)],
            prefix: ["a", "b"],
        };
        let a = SymMv::of_type(ta, 0);
        let b = SymMv::of_type(tb, 1);
        let ops: [(&str, &str, &str, SymMv); 5] = [
            (
                "Mul",
                "mul",
                "*",
                self.table.product(&a, &b, Product::Geometric),
            ),
            (
                "BitXor",
                "bitxor",
                "^",
                self.table.product(&a, &b, Product::Outer),
            ),
            (
                "BitOr",
                "bitor",
                "|",
                self.table.product(&a, &b, Product::Left),
            ),
            ("Add", "add", "+", a.add_scaled(&b, Rational::ONE)),
            ("Sub", "sub", "-", a.add_scaled(&b, -Rational::ONE)),
        ];
        for (tr, method, sym, m) in ops.iter() {
            let o = self.infer(m);
            if o == OutType::Zero {
                self.zero_ops += 1;
                continue;
            }
            let doc = match *sym {
                "*" => "Geometric product.",
                "^" => "Outer product.",
                "|" => "Left contraction.",
                "+" => "Sum.",
                _ => "Difference.",
            };
            let on = self.out_name(o);
            let paired = match o {
                OutType::Type(ti) if *sym == "*" => self.build_paired(ti, m, ta, tb),
                _ => None,
            };
            // issue 8: f32 products between versor types in 4-lane form (see `quad_lanes`).
            let mut lane_doc = match (&paired, o) {
                (Some(_), OutType::Type(ti)) => crate::quad_lanes::expansion_doc(
                    " Geometric product (paired-lane form: two output fields per `F64x2`).",
                    &spec.types[ti],
                    m,
                    &|p| names.poly(p),
                ),
                _ => doc.to_string(),
            };
            let paired = match (paired, o) {
                (None, OutType::Type(ti)) if *sym == "*" && self.s == "f32" => {
                    crate::quad_lanes::build(ta, tb, &spec.types[ti], m, &self.rt, &|p| {
                        names.poly(p)
                    })
                    .map(|(body, qdoc)| {
                        lane_doc = qdoc;
                        body
                    })
                }
                (p, _) => p,
            };
            let _ = writeln!(
                self.out,
                "impl ::core::ops::{tr}<{bn}> for {an} {{ type Output = {on}; #[doc = {doc:?}] #[inline] {allow}fn {method}(self, b: {bn}) -> {on} {{ let a = self; {body} }} }}",
                an = ta.name,
                bn = tb.name,
                doc = lane_doc,
                body = paired.unwrap_or_else(|| self.build(o, m, &names)),
                // `^` and `|` are products written with `*`: say that this is meant.
                allow = if matches!(*tr, "BitXor" | "BitOr") {
                    "#[allow(clippy::suspicious_arithmetic_impl)] "
                } else {
                    ""
                },
            );
            self.ops.push(OpSummary {
                op: sym.to_string(),
                left: ta.name.clone(),
                right: tb.name.clone(),
                output: on,
                terms: terms(m),
            });
        }
        // Conversion into a type that holds every blade of this one.
        if ai != bi && tb.constants.is_empty() && ta.blades().all(|x| tb.field(x).is_some()) {
            let m = SymMv::of_type(ta, 0);
            let names1 = Names {
                types: [Some(ta), None],
                prefix: ["a", "b"],
            };
            self.ops.push(OpSummary {
                op: "from".to_string(),
                left: ta.name.clone(),
                right: tb.name.clone(),
                output: tb.name.clone(),
                terms: 0,
            });
            let _ = writeln!(
                self.out,
                "impl ::core::convert::From<{an}> for {bn} {{ #[inline] fn from(a: {an}) -> {bn} {{ {body} }} }}",
                an = ta.name,
                bn = tb.name,
                body = self.build(OutType::Type(bi), &m, &names1),
            );
        }
    }

    /// True when, on random unit versors of type `vi` (exponentials of random bivectors in
    /// the type, normalised), every blade of the sandwich `r` that output type `oi` does not
    /// store is zero and every constant of `oi` is met, to 1e-9.
    fn unit_versor_drop_ok(&self, vi: usize, xi: usize, r: &SymMv, oi: usize) -> bool {
        let spec = self.spec;
        let (tv, tx, to) = (&spec.types[vi], &spec.types[xi], &spec.types[oi]);
        let mut rng = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            (rng >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let bivector_fields: Vec<usize> = (0..tv.fields.len())
            .filter(|&i| grade(tv.fields[i].bitmap) == 2)
            .collect();
        if bivector_fields.is_empty() {
            return false;
        }
        for _ in 0..16 {
            let mut bv = crate::Multivector::zero(&self.alg);
            for &i in &bivector_fields {
                bv.set(tv.fields[i].bitmap, next());
            }
            let mut m = bv.exp();
            let n = m.norm();
            if n.is_nan() || n <= 1e-6 {
                return false;
            }
            m = m.scale(1.0 / n);
            // The exponential must lie in the type.
            let outside: f64 = (0..self.alg.size() as Bitmap)
                .filter(|b| !tv.blades().any(|x| x == *b))
                .map(|b| m.get(b).abs())
                .fold(0.0, f64::max);
            if outside > 1e-9 {
                return false;
            }
            let vals0: Vec<f64> = tv
                .fields
                .iter()
                .map(|f| f.sign as f64 * m.get(f.bitmap))
                .collect();
            let vals1: Vec<f64> = tx.fields.iter().map(|_| next()).collect();
            let eval = |p: &Poly| -> f64 {
                p.0.iter()
                    .map(|(mono, c)| {
                        mono.iter().fold(c.to_f64(), |acc, v| {
                            acc * if v.operand == 0 {
                                vals0[v.field as usize]
                            } else {
                                vals1[v.field as usize]
                            }
                        })
                    })
                    .sum()
            };
            for bm in r.support() {
                let target = if to.field(bm).is_some() {
                    continue;
                } else {
                    to.constant(bm).map(|c| c.to_f64()).unwrap_or(0.0)
                };
                if (eval(&r.get(bm)) - target).abs() > 1e-9 {
                    return false;
                }
            }
            for &(bm, c) in &to.constants {
                if (eval(&r.get(bm)) - c.to_f64()).abs() > 1e-9 {
                    return false;
                }
            }
        }
        true
    }

    fn sandwich(&mut self, d: &crate::spec::SandwichDef) -> Result<(), GenError> {
        let spec = self.spec;
        let (tv, tx) = (&spec.types[d.versor], &spec.types[d.operand]);
        let a = SymMv::of_type(tv, 0);
        let b = SymMv::of_type(tx, 1);
        // issue 8: a unit versor's sandwich is reduced modulo `a ~a = 1` and keeps the grades
        // of the operand (see `unit_versor`).
        let (r, ideal) = if tv.unit {
            crate::unit_versor::unit_sandwich(&mut self.table, &self.alg, tv, tx)
        } else {
            let ab = self.table.product(&a, &b, Product::Geometric);
            let r = self.table.product(&ab, &a.rev(), Product::Geometric);
            (r, crate::unit_versor::UnitIdeal::default())
        };
        let oi = match d.output {
            Some(oi) => {
                let to = &spec.types[oi];
                // For a unit versor, blades the output type does not hold (and its constants)
                // are those that vanish because `x ~x = 1` (e.g. the grade-5 part of a motor
                // sandwich, which is zero by the motor constraint). They are dropped only
                // after checking numerically on random unit versors of the type.
                let unit_ok = tv.unit && self.unit_versor_drop_ok(d.versor, d.operand, &r, oi);
                for bm in r.support() {
                    let err = || GenError::SandwichOutput {
                        file: spec.source.clone(),
                        versor: tv.name.clone(),
                        operand: tx.name.clone(),
                        output: to.name.clone(),
                        blade: blade_name(bm, spec.metric.names()),
                    };
                    if to.field(bm).is_some() {
                        continue;
                    }
                    match to.constant(bm) {
                        Some(c) if unit_ok || r.get(bm).as_constant() == Some(c) => {}
                        _ if unit_ok => {}
                        _ => return Err(err()),
                    }
                }
                for &(bm, c) in &to.constants {
                    if !unit_ok && r.get(bm).as_constant() != Some(c) {
                        return Err(GenError::SandwichOutput {
                            file: spec.source.clone(),
                            versor: tv.name.clone(),
                            operand: tx.name.clone(),
                            output: to.name.clone(),
                            blade: blade_name(bm, spec.metric.names()),
                        });
                    }
                }
                oi
            }
            None => match self.infer(&r) {
                OutType::Type(t) => t,
                OutType::Scalar => self
                    .by_size
                    .iter()
                    .copied()
                    .find(|&t| {
                        spec.types[t].fields.iter().any(|f| f.bitmap == 0)
                            && spec.types[t].constants.is_empty()
                    })
                    .unwrap_or(spec.types.len() - 1),
                OutType::Zero => {
                    return Err(GenError::ZeroSandwich {
                        file: spec.source.clone(),
                        versor: tv.name.clone(),
                        operand: tx.name.clone(),
                    })
                }
            },
        };
        let to = &spec.types[oi];
        // coef[k][j]: coefficient polynomial (in the versor) of operand field j (nx = constant)
        // in output field k.
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
        // Shared subexpressions: every product of two versor coefficients.
        let mut shared: BTreeMap<Monomial, String> = BTreeMap::new();
        for row in &coef {
            for p in row {
                for m in p.0.keys() {
                    if m.len() == 2 {
                        let name = format!(
                            "{}_{}",
                            tv.fields[m[0].field as usize].name,
                            tv.fields[m[1].field as usize].name
                        );
                        shared.insert(m.clone(), name);
                    }
                }
            }
        }
        let names = Names {
            types: [Some(tv), Some(tx)],
            prefix: ["a", "b"],
        };
        let mono = |m: &Monomial| -> String {
            shared.get(m).cloned().unwrap_or_else(|| names.monomial(m))
        };
        let lets: String = shared
            .iter()
            .map(|(m, n)| format!("let {n} = {};", names.monomial(m)))
            .collect();
        let mut fields = String::new();
        let mut doc = format!(
            "`{v} * {x} * ~{v}`, fused: every product of two versor coefficients is computed once \
             and each output coefficient is linear in the operand (in a loop the compiler hoists \
             the versor part, so this costs about a matrix product).\n\nSymbolic expansion (`a` \
             the versor, `b` the operand):\n",
            v = tv.name,
            x = tx.name
        );
        let mut nterms = 0;
        for (k, f) in to.fields.iter().enumerate() {
            let mut parts = Vec::new();
            let mut dparts = Vec::new();
            for j in 0..=nx {
                let p = &coef[k][j];
                if p.is_zero() {
                    continue;
                }
                nterms += p.0.len();
                let inner = names.poly_with(p, mono);
                let dinner = names.poly(p);
                if j < nx {
                    parts.push(format!("b.{} * ({inner})", tx.fields[j].name));
                    dparts.push(format!("b.{} * ({dinner})", tx.fields[j].name));
                } else {
                    parts.push(format!("({inner})"));
                    dparts.push(format!("({dinner})"));
                }
            }
            let e = if parts.is_empty() {
                "0.0".to_string()
            } else {
                parts.join(" + ")
            };
            let _ = write!(fields, "{}: {e}, ", f.name);
            let _ = write!(
                doc,
                "\n- `{}` = {}",
                f.name,
                if dparts.is_empty() {
                    "0".to_string()
                } else {
                    dparts.join(" + ")
                }
            );
        }
        for &(bm, c) in &to.constants {
            let _ = write!(
                doc,
                "\n- `{}` = {} (constant of `{}`)",
                blade_name(bm, spec.metric.names()),
                c,
                to.name
            );
        }
        let (vn, xn, on) = (&tv.name, &tx.name, &to.name);
        // issue 8: a cheaper straight-line program (two half products sharing work), proven
        // equal to the expansion above, replaces the term-by-term body (see `factor`).
        let mut sw_body = format!("{lets} {on} {{ {fields} }}");
        if let Some(prog) = crate::factor::sandwich_program(
            &mut self.table,
            spec.metric.names(),
            tv,
            tx,
            to,
            &r,
            &ideal,
        ) {
            let var = |v: Var| names.var(v);
            let outs: Vec<String> = to
                .fields
                .iter()
                .enumerate()
                .map(|(k, f)| format!("{}: {}", f.name, prog.render_output(k, &var)))
                .collect();
            sw_body = format!("{} {on} {{ {} }}", prog.render_lets(&var), outs.join(", "));
            let (m, ad) = prog.ops();
            let _ = write!(
                doc,
                "\n\nComputed as {} ({m} multiplies, {ad} adds).",
                prog.form
            );
        }
        let s = self.s;
        let mat = format!("{vn}{xn}Matrix");
        let ny = to.fields.len();
        let entries: Vec<String> = coef
            .iter()
            .map(|row| {
                format!(
                    "[{}]",
                    row.iter()
                        .map(|p| names.poly_with(p, mono))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            })
            .collect();
        let mut apply = String::new();
        for (k, f) in to.fields.iter().enumerate() {
            let mut parts = Vec::new();
            for j in 0..=nx {
                if coef[k][j].is_zero() {
                    continue;
                }
                parts.push(if j < nx {
                    format!("m[{k}][{j}] * b.{}", tx.fields[j].name)
                } else {
                    format!("m[{k}][{nx}]")
                });
            }
            let e = if parts.is_empty() {
                "0.0".to_string()
            } else {
                parts.join(" + ")
            };
            let _ = write!(apply, "{}: {e}, ", f.name);
        }
        let cols: Vec<String> = tx
            .fields
            .iter()
            .map(|f| format!("`{}`", f.name))
            .chain(std::iter::once("1".to_string()))
            .collect();
        let rows: Vec<String> = to.fields.iter().map(|f| format!("`{}`", f.name)).collect();
        #[allow(clippy::format_in_format_args)] // named pieces of a long template read better
        let _ = write!(
            self.out,
            r#"impl Sandwich<{xn}> for {vn} {{
    type Output = {on};
    #[doc = {doc:?}]
    #[inline]
    fn sandwich(&self, b: {xn}) -> {on} {{ let a = self; {sw_body} }}
}}
#[doc = {mdoc:?}]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct {mat} {{
    /// `m[row][col]`: rows are the output fields, columns the operand fields then the constant column.
    pub m: [[{s}; {ncols}]; {ny}],
}}
impl {mat} {{
    /// Apply the map: the same result as the sandwich, at matrix cost. Entries that are
    /// identically zero for every versor are skipped.
    #[inline]
    #[must_use]
    pub fn apply(&self, b: {xn}) -> {on} {{ let m = &self.m; {on} {{ {apply} }} }}
}}
impl {vn} {{
    #[doc = {fdoc:?}]
    #[must_use]
    pub fn {fname}(&self) -> {mat} {{ let a = self; {lets} {mat} {{ m: [{entries}] }} }}
}}
"#,
            mdoc = format!(
                "The linear (outermorphism) form of the sandwich of a `{xn}` by a `{vn}`, for applying one versor to many operands.\n\nRows: {}. Columns: {}.",
                rows.join(", "),
                cols.join(", ")
            ),
            fdoc = format!("The matrix form of `self.sandwich(x)` for `x: {xn}`; see [`{mat}`]."),
            fname = format!("{}_matrix", snake(xn)),
            ncols = nx + 1,
            entries = entries.join(", "),
        );
        self.ops.push(OpSummary {
            op: "sandwich".to_string(),
            left: vn.clone(),
            right: xn.clone(),
            output: on.clone(),
            terms: nterms,
        });
        Ok(())
    }
}

/// Generate the Rust module for a spec.
pub fn generate(spec: &Spec, opts: &EmitOptions) -> Result<Generated, GenError> {
    let mut by_size: Vec<usize> = (0..spec.types.len()).collect();
    by_size.sort_by_key(|&i| spec.types[i].fields.len() + spec.types[i].constants.len());
    let mut g = Gen {
        spec,
        table: BladeTable::new(&spec.metric),
        s: opts.scalar.name(),
        rt: opts.runtime.clone(),
        out: String::new(),
        ops: Vec::new(),
        methods: Vec::new(),
        zero_ops: 0,
        by_size,
        alg: crate::Algebra::new(spec.metric.clone()),
    };
    g.header();
    for ti in 0..spec.types.len() {
        g.type_def(ti);
    }
    for ai in 0..spec.types.len() {
        for bi in 0..spec.types.len() {
            g.binary(ai, bi);
        }
    }
    for d in &spec.sandwiches {
        g.sandwich(d)?;
    }
    let file = syn::parse_file(&g.out).map_err(|e| GenError::Internal(format!("{e}")))?;
    let body = prettyplease::unparse(&file);
    let header = format!(
        "// Generated by ga-codegen from {} ({}, scalar {}). Do not edit: regenerate with\n// `ga-codegen {}{}`.\n",
        spec.source,
        spec.name,
        opts.scalar.name(),
        spec.source,
        if opts.scalar == ScalarType::F32 { " --scalar f32" } else { "" }
    );
    Ok(Generated {
        code: header + &body,
        types: spec
            .types
            .iter()
            .map(|t| (t.name.clone(), t.fields.len()))
            .collect(),
        ops: g.ops,
        methods: g.methods,
        zero_ops: g.zero_ops,
    })
}

/// `let a = self;` in front of a method body, when the body reads `a` at all.
fn bind_self(body: &str) -> String {
    let reads_a = body.match_indices("a.").any(|(i, _)| {
        i == 0 || !body.as_bytes()[i - 1].is_ascii_alphanumeric() && body.as_bytes()[i - 1] != b'_'
    });
    if reads_a {
        format!("let a = self; {body}")
    } else {
        body.to_string()
    }
}

/// One term of a paired-lane product: `splat(a_j) * bvec`, where `bvec` holds the operand
/// fields of the two lanes (`None`: that lane has no term).
struct LaneTerm {
    a: u16,
    b: [Option<u16>; 2],
}

impl Gen<'_> {
    /// The body of a geometric product between two versor types in paired-lane form, or `None`
    /// when the product does not qualify (f32, constants, small types, non-bilinear terms).
    ///
    /// The output fields are taken two by two; each pair is one [`crate::lanes::F64x2`]
    /// computed as a sum of `splat(a.x) * (b.y, b.z)` terms, grouped by their pair of
    /// coefficients so that each group is scaled once. Operand fields that sit next to each
    /// other in storage (`b.s, b.e12`) load as one pair, or as that pair swapped.
    fn build_paired(&self, ti: usize, m: &SymMv, ta: &TypeDef, tb: &TypeDef) -> Option<String> {
        let t = &self.spec.types[ti];
        let qualifies = self.s == "f64"
            && ta.versor
            && tb.versor
            && ta.constants.is_empty()
            && tb.constants.is_empty()
            && ta.fields.len() >= 4
            && tb.fields.len() >= 4
            && t.fields.len() >= 4;
        if !qualifies {
            return None;
        }
        // Per output field: a_j -> [(b_k, c)].
        let mut lanes: Vec<BTreeMap<u16, Vec<(u16, Rational)>>> = Vec::new();
        for f in &t.fields {
            let mut by_a: BTreeMap<u16, Vec<(u16, Rational)>> = BTreeMap::new();
            for (mono, &c) in &m.get(f.bitmap).0 {
                match mono.as_slice() {
                    [x, y] if x.operand == 0 && y.operand == 1 => by_a
                        .entry(x.field)
                        .or_default()
                        .push((y.field, c * Rational::int(f.sign as i64))),
                    _ => return None,
                }
            }
            lanes.push(by_a);
        }
        let af = |j: u16| &ta.fields[j as usize].name;
        let bf = |k: u16| &tb.fields[k as usize].name;
        let mut body = format!("use {}::lanes::F64x2;", self.rt);
        let mut used_a = std::collections::BTreeSet::new();
        let mut used_pairs = std::collections::BTreeSet::new();
        let mut outputs = Vec::new();
        let mut lane_terms = 0usize;
        for (pi, pair) in t.fields.chunks(2).enumerate() {
            let l0 = &lanes[2 * pi];
            let empty = BTreeMap::new();
            let l1 = lanes
                .get(2 * pi + 1)
                .filter(|_| pair.len() == 2)
                .unwrap_or(&empty);
            // Coefficient pair (first one positive) -> signed terms; a lane without a term takes
            // the other lane's coefficient. `(c0, c1)` and `(-c0, -c1)` share a group.
            let mut groups: BTreeMap<(Rational, Rational), Vec<(bool, LaneTerm)>> = BTreeMap::new();
            let js: std::collections::BTreeSet<u16> = l0.keys().chain(l1.keys()).copied().collect();
            for j in js {
                let (t0, t1) = (
                    l0.get(&j).map_or(&[][..], |v| v),
                    l1.get(&j).map_or(&[][..], |v| v),
                );
                for i in 0..t0.len().max(t1.len()) {
                    let (x0, x1) = (t0.get(i), t1.get(i));
                    let c0 = x0.or(x1).map(|x| x.1).expect("a term");
                    let c1 = x1.or(x0).map(|x| x.1).expect("a term");
                    let neg = c0 < Rational::ZERO;
                    let key = if neg { (-c0, -c1) } else { (c0, c1) };
                    used_a.insert(j);
                    groups.entry(key).or_default().push((
                        neg,
                        LaneTerm {
                            a: j,
                            b: [x0.map(|x| x.0), x1.map(|x| x.0)],
                        },
                    ));
                }
            }
            let mut parts: Vec<(bool, String)> = Vec::new();
            let parts_terms: usize = groups.values().map(Vec::len).sum();
            for ((c0, c1), mut terms) in groups {
                // Lead with an added term; if every term is subtracted, negate the group.
                let all_neg = terms.iter().all(|t| t.0);
                if all_neg {
                    terms.iter_mut().for_each(|t| t.0 = false);
                }
                if let Some(first) = terms.iter().position(|t| !t.0) {
                    terms.swap(0, first);
                }
                let mut sum = String::new();
                for (i, (neg, lt)) in terms.iter().enumerate() {
                    let bvec = match lt.b {
                        [Some(k0), Some(k1)] if k0 % 2 == 0 && k1 == k0 + 1 => {
                            used_pairs.insert((k0, false));
                            format!("b_{}_{}", bf(k0), bf(k1))
                        }
                        [Some(k0), Some(k1)] if k1 % 2 == 0 && k0 == k1 + 1 => {
                            used_pairs.insert((k1, true));
                            format!("b_{}_{}", bf(k0), bf(k1))
                        }
                        [k0, k1] => format!(
                            "F64x2::new({}, {})",
                            k0.map_or("0.0".to_string(), |k| format!("b.{}", bf(k))),
                            k1.map_or("0.0".to_string(), |k| format!("b.{}", bf(k)))
                        ),
                    };
                    if i > 0 {
                        sum.push_str(if *neg { " - " } else { " + " });
                    }
                    let _ = write!(sum, "a_{} * {bvec}", af(lt.a));
                }
                let grouped = if terms.len() > 1 {
                    format!("({sum})")
                } else {
                    sum
                };
                let part = if c0 == c1 && c0 == Rational::ONE {
                    (all_neg, grouped)
                } else if c0 == c1 {
                    (all_neg, format!("{grouped} * F64x2::splat({})", lit(c0)))
                } else {
                    (
                        all_neg,
                        format!("{grouped} * F64x2::new({}, {})", lit(c0), lit(c1)),
                    )
                };
                parts.push(part);
            }
            // Start with a group that is added, so that no negation is needed up front.
            if let Some(first) = parts.iter().position(|p| !p.0) {
                parts.swap(0, first);
            }
            let mut expr = String::new();
            for (i, (neg, part)) in parts.iter().enumerate() {
                if i == 0 {
                    expr = if *neg {
                        format!("F64x2::splat(0.0) - {part}")
                    } else {
                        part.clone()
                    };
                } else {
                    let _ = write!(expr, " {} {part}", if *neg { "-" } else { "+" });
                }
            }
            if expr.is_empty() {
                expr = "F64x2::splat(0.0)".to_string();
            }
            lane_terms += parts_terms;
            outputs.push(format!("let o{pi} = {};", strip_outer_parens(&expr)));
        }
        // Worth it only when pairing saves most multiplies (sparse products stay scalar).
        let scalar_terms: usize = lanes.iter().flat_map(|l| l.values()).map(Vec::len).sum();
        if 5 * lane_terms > 3 * scalar_terms {
            return None;
        }
        for j in &used_a {
            let _ = write!(body, " let a_{0} = F64x2::splat(a.{0});", af(*j));
        }
        for &(k, swapped) in &used_pairs {
            if !swapped || !used_pairs.contains(&(k, false)) {
                let _ = write!(
                    body,
                    " let b_{0}_{1} = F64x2::new(b.{0}, b.{1});",
                    bf(k),
                    bf(k + 1)
                );
            }
        }
        for &(k, swapped) in &used_pairs {
            if swapped {
                let _ = write!(body, " let b_{1}_{0} = b_{0}_{1}.swap();", bf(k), bf(k + 1));
            }
        }
        for o in outputs {
            body.push(' ');
            body.push_str(&o);
        }
        let _ = write!(body, " {} {{", t.name);
        for (i, f) in t.fields.iter().enumerate() {
            let lane = if i % 2 == 0 { "lo" } else { "hi" };
            let _ = write!(body, " {}: o{}.{lane}(),", f.name, i / 2);
        }
        body.push_str(" }");
        Some(body)
    }
}

/// `(x + y)` -> `x + y` when the outer parentheses enclose the whole expression.
fn strip_outer_parens(e: &str) -> &str {
    if !(e.starts_with('(') && e.ends_with(')')) {
        return e;
    }
    let mut depth = 0i32;
    for (i, ch) in e.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 && i + 1 < e.len() {
                    return e;
                }
            }
            _ => {}
        }
    }
    &e[1..e.len() - 1]
}
