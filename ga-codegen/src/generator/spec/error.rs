//! Spec errors: what is wrong, and where in the spec (so the `algebra!` macro can point at the
//! token by a lookup, and the CLI can name the file, the type and the blade).

use crate::runtime::metric::MetricError;
use thiserror::Error;

/// Where in the spec an error is, by position in the spec as written ([`super::RawSpec`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SpecLocation {
    /// The spec as a whole (it cannot be read, or its overall size).
    Spec,
    /// The list of basis names.
    BasisList,
    /// Basis name `i`.
    Basis(usize),
    /// The metric (`metric` or `diagonal`) as a whole.
    Metric,
    /// Row `i` of a full `metric`.
    MetricRow(usize),
    /// Entry `[row][col]` of `metric`, or entry `row` of `diagonal` (then `col == row`).
    MetricEntry {
        /// Row.
        row: usize,
        /// Column.
        col: usize,
    },
    /// The name of type `i`.
    TypeName(usize),
    /// Blade `blade` of type `ty`.
    TypeBlade {
        /// Type index.
        ty: usize,
        /// Blade index in its `blades` list.
        blade: usize,
    },
    /// The key (a blade name) of a constant of type `ty`.
    ConstantKey {
        /// Type index.
        ty: usize,
        /// The key as written.
        key: String,
    },
    /// The value of a constant of type `ty`.
    ConstantValue {
        /// Type index.
        ty: usize,
        /// The key as written.
        key: String,
    },
    /// Sandwich `i` as a whole.
    Sandwich(usize),
    /// The versor type name of sandwich `i`.
    SandwichVersor(usize),
    /// The operand type name of sandwich `i`.
    SandwichOperand(usize),
    /// The output type name of sandwich `i`.
    SandwichOutput(usize),
}

/// Why a spec is refused as too large to generate.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum TooLarge {
    /// More basis vectors than the generator takes.
    #[error(
        "too large to generate: {n} basis vectors; the generator takes at most {max} (blades \
         are computed pair by pair, so what a spec costs depends on its declared types)"
    )]
    Dimension {
        /// Basis vectors given.
        n: usize,
        /// The limit.
        max: usize,
    },
    /// `--signature` declares every grade and the whole algebra, which stays small only up to
    /// a few basis vectors.
    #[error(
        "too large to generate with a type for every grade: {n} basis vectors give a general \
         multivector of 2^{n} blades; --signature declares every grade only up to {max} basis \
         vectors (the generator takes up to 16 in a spec that declares only the types it needs)"
    )]
    EveryGrade {
        /// Basis vectors given.
        n: usize,
        /// The limit of `--signature`.
        max: usize,
    },
    /// The estimated work (and memory) exceeds the budget.
    #[error(
        "too large to generate: about {estimate} units of work (terms expanded and items \
         emitted), over the budget of {budget} (a few seconds and about 1 GB); mostly {cause}"
    )]
    Work {
        /// The estimate.
        estimate: u64,
        /// The budget.
        budget: u64,
        /// The largest contribution, in words.
        cause: String,
    },
}

/// What is wrong with a spec.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SpecErrorKind {
    /// Not valid TOML or not the expected shape.
    #[error("cannot read spec: {0}")]
    Parse(String),
    /// No metric, or both `metric` and `diagonal`.
    #[error("give exactly one of `metric` (full matrix) or `diagonal` (squares)")]
    MetricMissing,
    /// The metric is malformed, or its exact products overflow.
    #[error("{0}")]
    Metric(MetricError),
    /// A blade name that is not made of basis names.
    #[error("unknown blade: not made of the basis names")]
    UnknownBlade,
    /// A blade name that splits into basis names in two ways.
    #[error("ambiguous blade name: splits into basis names in two ways")]
    AmbiguousBlade,
    /// A blade naming one basis vector twice (`e11`).
    #[error("blade names a basis vector twice")]
    RepeatedBasis,
    /// A blade whose name, a field of the generated type, is a Rust keyword.
    #[error("blade name is a Rust keyword and cannot name a field")]
    KeywordBlade,
    /// The same blade listed twice in a type (maybe in another order: `e12`, `e21`).
    #[error("blade listed twice")]
    DuplicateBlade,
    /// A type with no blades (or only constants).
    #[error("type has no stored blades")]
    EmptyType,
    /// Two types with one name.
    #[error("type name used twice")]
    DuplicateType,
    /// A type name that is not an UpperCamelCase Rust identifier.
    #[error("type name must be an UpperCamelCase identifier (ASCII letters and digits)")]
    BadTypeName,
    /// A type name that the generated code already uses, or a keyword.
    #[error("type name is reserved: {0}")]
    ReservedTypeName(&'static str),
    /// A constant on a blade the type does not list.
    #[error("constant on a blade the type does not list")]
    ConstantNotInType,
    /// A constant that is not finite, or cannot be held exactly.
    #[error(
        "constant is not a finite number that can be held exactly (its exact products must \
         fit in 128-bit rationals)"
    )]
    BadConstant,
    /// A sandwich naming a type that does not exist.
    #[error("no type of this name")]
    UnknownType,
    /// A sandwich declared twice for one versor and operand.
    #[error("sandwich declared twice for this versor and operand")]
    DuplicateSandwich,
    /// A sandwich whose versor type is not marked `versor = true`.
    #[error("versor type is not marked `versor = true`")]
    NotVersor,
    /// A spec above [`MAX_GENERAL_DIMENSION`](super::MAX_GENERAL_DIMENSION) basis vectors
    /// that declares no type (none is added for it).
    #[error(
        "no type declared: above {max} basis vectors no general multivector is added (its \
         2^{n} blades are too many), so a spec of {n} declares the types it needs"
    )]
    NoTypes {
        /// Basis vectors given.
        n: usize,
        /// The most basis vectors with a general multivector.
        max: usize,
    },
    /// The spec would take too long or too much memory to generate.
    #[error("{0}")]
    TooLarge(TooLarge),
}

/// A spec error: the file, the type and the blade it concerns, where it is, and what is wrong
/// (the fields of [`SpecErrorInfo`], read through `Deref`: `e.kind`, `e.location`). Boxed,
/// so that `Result<_, SpecError>` stays one pointer wide.
#[derive(Clone, Debug, PartialEq, Error)]
#[error("{0}")]
pub struct SpecError(Box<SpecErrorInfo>);

/// What a [`SpecError`] says.
#[derive(Clone, Debug, PartialEq, Error)]
#[error("{file}: {}{kind}", context(.type_name, .blade))]
pub struct SpecErrorInfo {
    /// The spec file (or `algebra!`).
    pub file: String,
    /// The type concerned.
    pub type_name: Option<String>,
    /// The blade (or other name) concerned.
    pub blade: Option<String>,
    /// Where in the spec.
    pub location: SpecLocation,
    /// What is wrong.
    pub kind: SpecErrorKind,
}

impl std::ops::Deref for SpecError {
    type Target = SpecErrorInfo;
    fn deref(&self) -> &SpecErrorInfo {
        &self.0
    }
}

/// "type `T`: `b`: " for the parts that are known.
fn context(type_name: &Option<String>, blade: &Option<String>) -> String {
    let mut s = String::new();
    if let Some(t) = type_name {
        s.push_str(&format!("type `{t}`: "));
    }
    if let Some(b) = blade {
        s.push_str(&format!("`{b}`: "));
    }
    s
}

impl SpecError {
    /// An error about the spec file `file` at `location`.
    pub fn new(file: &str, location: SpecLocation, kind: SpecErrorKind) -> SpecError {
        SpecError(Box::new(SpecErrorInfo {
            file: file.to_string(),
            type_name: None,
            blade: None,
            location,
            kind,
        }))
    }

    /// Name the type concerned.
    pub fn in_type(mut self, name: &str) -> SpecError {
        self.0.type_name = Some(name.to_string());
        self
    }

    /// Name the blade (or other name) concerned.
    pub fn at_blade(mut self, name: &str) -> SpecError {
        self.0.blade = Some(name.to_string());
        self
    }
}
