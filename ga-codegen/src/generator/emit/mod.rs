//! The Rust emitter: turns a validated [`Spec`] into a Rust module, as tokens.
//!
//! Every product of two declared types is expanded symbolically (`generator::symbolic`),
//! every identically-zero term is dropped, and the result type is the smallest declared type that
//! holds every remaining blade (a pure scalar is returned as the scalar type itself; a product
//! that is identically zero is not emitted at all, nor, in an algebra too large for the general
//! multivector, one whose result no declared type holds: see [`Generated::skipped`]). The output is meant for `include!` inside a
//! module (or a macro expansion): it has no inner attributes.
//!
//! The emitter works in phases, grouped by family, one file each:
//! - `ops.rs`: what is emitted (`Op`, `Method`, `OpSummary`, `OutType`);
//! - `render.rs`: literals, identifiers and polynomials as tokens (and as text for docs);
//! - `preamble.rs`: `BASIS`, `METRIC`, `algebra()` (the dense generic algebra, or the sparse
//!   one above [`MAX_DENSE_REFERENCE_DIMENSION`](crate::generator::spec::MAX_DENSE_REFERENCE_DIMENSION)
//!   basis vectors), the `Sandwich` trait, `Scalar`, and `SKIPPED` (what no declared type holds);
//! - `products/`: the module's types and products: `infer.rs` (result types of symbolic
//!   products and the expressions that build them), `types.rs` (one struct per declared type
//!   with its methods and scalar operators), `operators.rs` (binary operators between declared
//!   types and conversions), `named.rs` (the named products of ga-benchmark's set between the
//!   scalar and the types of one grade, a trait each), `sandwich.rs` (fused sandwich products and their matrix
//!   (outermorphism) form);
//! - `lanes/`: lane forms: `mod.rs` (paired-lane `F64x2` forms of dense geometric products),
//!   `quad.rs` (their 4-lane `F32x4` f32 forms), `wide.rs` (structure-of-arrays twins over a
//!   lane type, for batches of operands);
//! - `exp_log/`: closed-form `exp`, `log`, `sqrt` and `normalize` of even versors by the
//!   invariant decomposition of bivectors: `mod.rs`, `decompose.rs`, `logarithm.rs`,
//!   `log_double.rs`, `normalize.rs`, `turn_root.rs`;
//! - `wgsl/`: the same types, products and sandwiches as WGSL (`generate_wgsl`; `exp.rs`: the
//!   closed-form exponentials);
//! - `library.rs`: serde and bytemuck impls and the list of types, for a library's API;
//! - `summary.rs`: the human-readable table of what was emitted.
//!
//! Code is built as [`TokenStream`]s with `quote`; [`Generated::code`] parses them into a
//! `syn::File` and formats it with prettyplease, and the `algebra!` macro returns the tokens
//! as they are.

mod exp_log;
mod lanes;
mod library;
mod ops;
mod preamble;
mod products;
mod render;
mod summary;
mod wgsl;

pub use exp_log::decompose::Refusal;
pub use exp_log::refusals;
pub use ops::{Method, Op, OpSummary, OutType};
pub(crate) use products::scalar_ops::SCALAR_DUAL;
pub use render::snake;
pub use wgsl::{generate_wgsl, generate_wgsl_to};

use crate::generator::spec::Spec;
use crate::generator::symbolic::BladeTable;
use proc_macro2::TokenStream;
use quote::{quote, ToTokens};
use std::cell::OnceCell;
use std::fmt;

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

    /// The Rust type as tokens.
    pub fn tokens(self) -> TokenStream {
        match self {
            ScalarType::F32 => quote!(f32),
            ScalarType::F64 => quote!(f64),
        }
    }
}

/// Options of the emitter.
#[derive(Clone, Debug)]
pub struct EmitOptions {
    /// Scalar type.
    pub scalar: ScalarType,
    /// Path of the `ga-codegen` crate in the generated code (default `::ga_codegen`). The
    /// generated code names `{path}::Algebra` and `{path}::Multivector` (the crate's root
    /// prelude) and, in lane forms, the lane types under `{path}::runtime` (`f64x2::F64x2`,
    /// `f32x4::F32x4`, `wide_lanes::{Lane, F64x4, F32x8}`).
    pub runtime: String,
    /// The module is a library's public API: also emit `serde` and `bytemuck` impls behind
    /// cargo features of those names (of the crate that includes the module, which then
    /// depends on those crates optionally) and a `types` module re-exporting every
    /// generated type. `ga-codegen --library`.
    pub library: bool,
    /// Make a bivector or even versor type that gets no closed-form `exp`/`log` (its span is
    /// above the closed-form range, see [`refusals`]) an error ([`GenError::NoClosedForm`])
    /// instead of an omission. `ga-codegen --exp-log`, `algebra!(exp_log = required; ..)`.
    pub require_exp_log: bool,
    /// Also emit `pub mod wide`: structure-of-arrays twins of the versor types and of the
    /// types they act on, generic over a [`crate::runtime::wide_lanes::Lane`] (`F64x4`, `F32x8`, or the
    /// scalar itself), with their sums, products and fused sandwiches. `ga-codegen --wide`.
    pub wide: bool,
    /// The file the module is written to, named in the header's regenerate command only
    /// (`ga-codegen -o FILE`); it changes nothing else.
    pub output: Option<String>,
}

impl Default for EmitOptions {
    fn default() -> Self {
        EmitOptions {
            scalar: ScalarType::F64,
            runtime: "::ga_codegen".to_string(),
            library: false,
            require_exp_log: false,
            wide: false,
            output: None,
        }
    }
}

impl EmitOptions {
    /// The `ga-codegen` command line that generates this module from `source` (the spec's
    /// file, or `--signature P,Q,R`), with every option that differs from the default, in the
    /// order of the usage line: the command the generated header names.
    pub fn command_line(&self, source: &str) -> String {
        let mut cmd = String::from("ga-codegen ");
        if source.starts_with("--signature ") {
            cmd.push_str(&render::one_line(source));
        } else {
            cmd.push_str(&shell_word(source));
        }
        if let Some(out) = &self.output {
            cmd.push_str(" -o ");
            cmd.push_str(&shell_word(out));
        }
        if self.scalar == ScalarType::F32 {
            cmd.push_str(" --scalar f32");
        }
        if self.runtime != EmitOptions::default().runtime {
            cmd.push_str(" --runtime ");
            cmd.push_str(&shell_word(&self.runtime));
        }
        for (on, flag) in [
            (self.library, " --library"),
            (self.require_exp_log, " --exp-log"),
            (self.wide, " --wide"),
        ] {
            if on {
                cmd.push_str(flag);
            }
        }
        cmd
    }
}

/// `text` as one shell word: as it is when it holds only characters no shell treats specially,
/// else in single quotes (control characters escaped, so the header stays one comment line).
fn shell_word(text: &str) -> String {
    let plain = !text.is_empty()
        && text
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-./,:=+@%".contains(c));
    if plain {
        text.to_string()
    } else {
        format!("'{}'", render::one_line(text).replace('\'', r"'\''"))
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
    /// A sandwich without a declared output whose result no declared type holds (an algebra
    /// without the general multivector).
    NoSandwichOutput {
        /// The spec file.
        file: String,
        /// Versor type.
        versor: String,
        /// Operand type.
        operand: String,
    },
    /// Closed-form `exp`/`log` were required ([`EmitOptions::require_exp_log`]) and a type
    /// cannot have them.
    NoClosedForm {
        /// The spec file.
        file: String,
        /// The bivector or even versor type.
        ty: String,
        /// Why (the span of its blades).
        reason: String,
    },
    /// [`EmitOptions::runtime`] is not a Rust path.
    RuntimePath {
        /// The path as given.
        path: String,
        /// Why it does not parse.
        reason: String,
    },
    /// A name that cannot be written in Rust, or emitted code that does not parse (a
    /// generator bug).
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
            GenError::NoSandwichOutput { file, versor, operand } => write!(
                f,
                "{file}: type `{versor}`: `{operand}`: no declared type holds the sandwich's result; declare a type with its blades and name it as the sandwich's `output`"
            ),
            GenError::NoClosedForm { file, ty, reason } => {
                write!(f, "{file}: type `{ty}`: no closed-form exp/log: {reason}")
            }
            GenError::RuntimePath { path, reason } => {
                let shown: String = path.chars().take(80).collect();
                let more = if path.chars().nth(80).is_some() { "..." } else { "" };
                write!(
                    f,
                    "runtime path {shown:?}{more} is not a Rust path (names joined by `::`, \
                     such as `::ga_codegen` or `crate::ga_runtime`): {reason}"
                )
            }
            GenError::Internal(m) => write!(f, "internal generator error: {m}"),
        }
    }
}

impl std::error::Error for GenError {}

/// Generated code (as tokens) and its summary.
#[derive(Clone, Debug)]
pub struct Generated {
    /// The module's items.
    pub tokens: TokenStream,
    /// The comment that heads the formatted file (says it is generated, and from what).
    pub header: String,
    /// Types: name and number of stored fields.
    pub types: Vec<(String, usize)>,
    /// Every emitted binary operation, sandwich and conversion (`from`).
    pub ops: Vec<OpSummary>,
    /// Emitted unary methods whose result is not fixed: (type, method); the type is the scalar
    /// type's name (`f64`, `f32`) for its `dual` and `undual` (trait `ScalarDual`).
    pub methods: Vec<(String, Method)>,
    /// Operations skipped because identically zero.
    pub zero_ops: usize,
    /// Products, methods and scalar operators not emitted because no declared type holds
    /// their result (only in algebras without the general multivector), one line each:
    /// `Vector * Vector -> grades 0, 2`, `-Point -> grade 2`, `Vector::dual -> grade 9`.
    pub skipped: Vec<String>,
    /// The closed-form exp/log impls, one line each (`Bivector exp -> Motor`,
    /// `Motor log -> Bivector`, `Motor sqrt, normalize`).
    pub closed_forms: Vec<String>,
    code: OnceCell<Result<String, GenError>>,
}

impl Generated {
    /// The module as a syntax tree; an error only for a generator bug.
    pub fn file(&self) -> Result<syn::File, GenError> {
        syn::parse2(self.tokens.clone()).map_err(|e| GenError::Internal(format!("{e}")))
    }

    /// The module formatted with prettyplease, after the header comment (computed once).
    pub fn code(&self) -> Result<&str, GenError> {
        self.code
            .get_or_init(|| {
                let file = self.file()?;
                Ok(self.header.clone() + &prettyplease::unparse(&file))
            })
            .as_deref()
            .map_err(Clone::clone)
    }

    /// Lines of formatted code (0 if it does not parse).
    pub fn lines(&self) -> usize {
        self.code().map_or(0, |c| c.lines().count())
    }
}

/// The emitter's state: the spec, the symbolic engine and what has been emitted so far.
struct Gen<'a> {
    spec: &'a Spec,
    table: BladeTable,
    scalar: ScalarType,
    /// `f64` or `f32`.
    s: TokenStream,
    /// The runtime crate's path.
    rt: TokenStream,
    /// The runtime crate's path as written.
    runtime: String,
    out: TokenStream,
    ops: Vec<OpSummary>,
    methods: Vec<(String, Method)>,
    zero_ops: usize,
    /// What was not emitted because no declared type holds its result.
    skipped: Vec<String>,
    /// The closed-form exp/log impls emitted, for the summary.
    closed_forms: Vec<String>,
    /// Type indices ordered by size, for result inference.
    by_size: Vec<usize>,
    /// The generic algebra, for numerical checks at generation time.
    alg: std::sync::Arc<crate::runtime::sparse::multivector::SparseAlgebra>,
}

/// Every type and field name must be a Rust identifier.
fn check_names(spec: &Spec) -> Result<(), GenError> {
    for t in &spec.types {
        if !render::is_ident(&t.name) {
            return Err(GenError::Internal(format!(
                "{}: type `{}`: not a Rust identifier",
                spec.source, t.name
            )));
        }
        for f in &t.fields {
            if !render::is_ident(&f.name) {
                return Err(GenError::Internal(format!(
                    "{}: type `{}`: `{}`: the blade name is not a Rust identifier",
                    spec.source, t.name, f.name
                )));
            }
        }
    }
    Ok(())
}

/// The most segments a runtime path may have (`::ga_codegen` has one).
const MAX_RUNTIME_SEGMENTS: usize = 64;

/// The generator state for a checked spec.
fn gen<'a>(spec: &'a Spec, opts: &EmitOptions) -> Result<Gen<'a>, GenError> {
    let refuse = |reason: String| GenError::RuntimePath {
        path: opts.runtime.clone(),
        reason,
    };
    let path = syn::parse_str::<syn::Path>(&opts.runtime).map_err(|e| refuse(e.to_string()))?;
    // A path of thousands of segments overflowed the stack of the formatter's parser.
    if path.segments.len() > MAX_RUNTIME_SEGMENTS {
        return Err(refuse(format!(
            "{} segments, more than {MAX_RUNTIME_SEGMENTS}",
            path.segments.len()
        )));
    }
    if path.segments.iter().any(|s| !s.arguments.is_none()) {
        return Err(refuse(
            "generic arguments (a crate or module path has none)".into(),
        ));
    }
    let rt = path.to_token_stream();
    let mut by_size: Vec<usize> = (0..spec.types.len()).collect();
    by_size.sort_by_key(|&i| spec.types[i].fields.len() + spec.types[i].constants.len());
    Ok(Gen {
        spec,
        table: BladeTable::new(&spec.metric),
        scalar: opts.scalar,
        s: opts.scalar.tokens(),
        rt,
        runtime: opts.runtime.clone(),
        out: TokenStream::new(),
        ops: Vec::new(),
        methods: Vec::new(),
        zero_ops: 0,
        skipped: Vec::new(),
        closed_forms: Vec::new(),
        by_size,
        alg: crate::runtime::sparse::multivector::SparseAlgebra::try_new(spec.metric.clone())
            .expect("the spec's metric was checked for overflow"),
    })
}

/// Generate the Rust module for a spec.
pub fn generate(spec: &Spec, opts: &EmitOptions) -> Result<Generated, GenError> {
    check_names(spec)?;
    if opts.require_exp_log {
        if let Some((ty, why)) = refusals(spec).into_iter().next() {
            return Err(GenError::NoClosedForm {
                file: spec.source.clone(),
                ty,
                reason: why.to_string(),
            });
        }
    }
    let mut g = gen(spec, opts)?;
    g.header();
    for ti in 0..spec.types.len() {
        g.type_def(ti);
    }
    for ai in 0..spec.types.len() {
        for bi in 0..spec.types.len() {
            g.binary(ai, bi);
        }
    }
    g.named_products();
    g.grade_zero_operators();
    for d in &spec.sandwiches {
        g.sandwich(d)?;
    }
    g.exp_log();
    g.skipped_list();
    if opts.wide {
        g.wide_module()?;
    }
    if opts.library {
        g.library_items();
    }
    let header = format!(
        "// Generated by ga-codegen from {} ({}, scalar {}). Do not edit: regenerate with\n// `{}`.\n",
        render::one_line(&spec.source),
        render::one_line(&spec.name),
        opts.scalar.name(),
        opts.command_line(&spec.source),
    );
    Ok(Generated {
        tokens: g.out,
        header,
        types: spec
            .types
            .iter()
            .map(|t| (t.name.clone(), t.fields.len()))
            .collect(),
        ops: g.ops,
        methods: g.methods,
        zero_ops: g.zero_ops,
        skipped: g.skipped,
        closed_forms: g.closed_forms,
        code: OnceCell::new(),
    })
}
