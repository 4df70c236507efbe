//! The algebra spec: basis, metric, specialised types and sandwiches, read from TOML (or
//! built by the `algebra!` macro) and validated.
//!
//! # Format
//!
//! ```toml
//! name = "cga"                          # used in generated docs
//! doc = "Conformal GA G(4,1)."          # optional
//! basis = ["eo", "e1", "e2", "e3", "ei"] # names: `e` + suffix; blade names concatenate suffixes
//! # The metric, one of:
//! metric = [[0, 0, 0, 0, -1],           # full symmetric matrix of inner products
//!           [0, 1, 0, 0, 0],
//!           [0, 0, 1, 0, 0],
//!           [0, 0, 0, 1, 0],
//!           [-1, 0, 0, 0, 0]]
//! # diagonal = [1, 1, 1, 0]             # or only the squares of an orthogonal basis
//!
//! [[type]]
//! name = "Point"                        # a Rust type name
//! doc = "A normalised point."           # optional
//! blades = ["eo", "e1", "e2", "e3", "ei"] # any order inside a name: `e31` is `-e13`
//! constants = { eo = 1 }                # blades with a fixed coefficient, not stored
//!
//! [[type]]
//! name = "Motor"
//! blades = ["s", "e12", "e13", "e23", "e1i", "e2i", "e3i", "e123i"]   # `s` is the scalar
//! versor = true                          # gets `sandwich`
//! unit = true                            # assumed normalised: M ~M = 1
//!
//! [[sandwich]]                           # emit Motor.sandwich(Point) -> Point and its matrix
//! versor = "Motor"
//! operand = "Point"
//! output = "Point"                       # optional; inferred when left out
//! ```
//!
//! A type holding every blade (the general multivector, `Mv`) is added when the spec has none,
//! up to [`MAX_GENERAL_DIMENSION`] basis vectors. Above, a spec has only its declared types:
//! a product or method whose result no declared type holds is not emitted (the summary lists
//! it, and the module's `SKIPPED` names it). Above [`MAX_DENSE_REFERENCE_DIMENSION`] the
//! generated code's generic reference is the sparse multivector instead of the dense one
//! ([`Spec::sparse_reference`]).
//!
//! # Rules
//!
//! - Metric entries are read as the decimal they are written as (`0.1` is exactly 1/10) and
//!   their exact products must fit in 128-bit rationals (`exact.rs`).
//! - Basis names are `e` + letters or digits, not Rust keywords, and their suffixes are
//!   prefix-free (not `e1` with `e12`), so every blade name reads one way, in linear time.
//! - Type names are UpperCamelCase, not keywords, not `Scalar`, `Sandwich`, `F64x2`, `F32x4`,
//!   and do not end in `Matrix` (the generated versor matrices are `<Versor><Operand>Matrix`).
//! - The spec must fit the size budget ([`budget`]): at most 16 basis vectors and an estimated
//!   work proportional to the code emitted (with `unit_cost`, the check of each unit versor's
//!   sandwich on sample unit versors).
//!
//! Validation runs in phases, one module each: `metric` (basis and metric),
//! `types`, `sandwiches`, [`budget`], `exact`. Every error carries a [`SpecLocation`].

pub mod budget;
mod error;
mod exact;
mod metric;
mod names;
mod sandwiches;
mod signature;
mod types;
mod unit_cost;

pub use error::{SpecError, SpecErrorInfo, SpecErrorKind, SpecLocation, TooLarge};

use crate::runtime::blade::Bitmap;
use crate::runtime::metric::Metric;
use crate::runtime::rational::Rational;
use serde::Deserialize;
use std::collections::BTreeMap;

/// The spec as written, before validation.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSpec {
    /// Algebra name.
    pub name: Option<String>,
    /// Documentation for the generated module.
    pub doc: Option<String>,
    /// Basis vector names.
    pub basis: Vec<String>,
    /// Full metric matrix.
    pub metric: Option<Vec<Vec<f64>>>,
    /// Squares of an orthogonal basis.
    pub diagonal: Option<Vec<f64>>,
    /// Specialised types.
    #[serde(default, rename = "type")]
    pub types: Vec<RawType>,
    /// Sandwich products to emit.
    #[serde(default)]
    pub sandwich: Vec<RawSandwich>,
}

/// A type as written.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawType {
    /// Rust type name.
    pub name: String,
    /// Documentation.
    pub doc: Option<String>,
    /// Blade names.
    pub blades: Vec<String>,
    /// Blades with a fixed coefficient.
    #[serde(default)]
    pub constants: BTreeMap<String, f64>,
    /// A versor type (gets `sandwich`).
    #[serde(default)]
    pub versor: bool,
    /// Assumed normalised (`x ~x = 1`).
    #[serde(default)]
    pub unit: bool,
}

/// A sandwich as written.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSandwich {
    /// The versor type.
    pub versor: String,
    /// The operand type.
    pub operand: String,
    /// The output type; inferred when absent.
    pub output: Option<String>,
}

/// One stored coefficient of a type: a blade, written in the order of `name`.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// Field name, the blade name as written in the spec (`e31`).
    pub name: String,
    /// Canonical bitmap.
    pub bitmap: Bitmap,
    /// `field blade = sign * canonical blade`.
    pub sign: i32,
}

/// A validated specialised type.
#[derive(Clone, Debug, PartialEq)]
pub struct TypeDef {
    /// Rust name.
    pub name: String,
    /// Documentation.
    pub doc: Option<String>,
    /// Stored coefficients.
    pub fields: Vec<Field>,
    /// Constant blades: canonical bitmap and the coefficient on the canonical blade.
    pub constants: Vec<(Bitmap, Rational)>,
    /// Gets `sandwich`.
    pub versor: bool,
    /// Assumed normalised.
    pub unit: bool,
}

impl TypeDef {
    /// Every blade the type can hold (fields and constants).
    pub fn blades(&self) -> impl Iterator<Item = Bitmap> + '_ {
        self.fields
            .iter()
            .map(|f| f.bitmap)
            .chain(self.constants.iter().map(|c| c.0))
    }

    /// The field for a canonical bitmap.
    pub fn field(&self, b: Bitmap) -> Option<(usize, &Field)> {
        self.fields.iter().enumerate().find(|(_, f)| f.bitmap == b)
    }

    /// The constant on a canonical bitmap.
    pub fn constant(&self, b: Bitmap) -> Option<Rational> {
        self.constants.iter().find(|c| c.0 == b).map(|c| c.1)
    }
}

/// A validated sandwich declaration (indices into [`Spec::types`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SandwichDef {
    /// Versor type.
    pub versor: usize,
    /// Operand type.
    pub operand: usize,
    /// Declared output type.
    pub output: Option<usize>,
}

/// A validated spec.
///
/// Its fields are public to be read. A spec edited after [`Spec::from_toml`] (or
/// [`Spec::from_raw`]) must keep what they checked: blades within the metric's dimension,
/// sandwich type indices in range, a metric whose exact products fit in 128 bits;
/// [`crate::generate`] trusts them and panics otherwise. To change a spec, change its TOML (or
/// `RawSpec`) and read it again.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    /// Where it came from (file path or `algebra!`).
    pub source: String,
    /// Algebra name.
    pub name: String,
    /// Documentation.
    pub doc: Option<String>,
    /// The metric.
    pub metric: Metric,
    /// Types, in declaration order (the general multivector last if it was added: never
    /// above [`MAX_GENERAL_DIMENSION`] basis vectors).
    pub types: Vec<TypeDef>,
    /// Sandwiches.
    pub sandwiches: Vec<SandwichDef>,
}

/// Name of the general multivector type added when a spec declares none.
pub(crate) const GENERAL_TYPE: &str = "Mv";

/// Most basis vectors of an algebra that gets the general multivector when no declared type
/// holds every blade (`2^n` blades, whose products with every type cost `4^n`-ish work: 64
/// blades at 6; at 8, its 256 blades made a null-basis G(4,4) spec of a vector, a bivector
/// and a rotor take 24 s instead of a few). Above, only the declared types are emitted, and
/// a result none holds is skipped (the same limit as the exactness check of the whole
/// product table, `exact.rs`).
pub const MAX_GENERAL_DIMENSION: usize = 6;

/// Most basis vectors of an algebra whose generated code is checked against the dense generic
/// [`Multivector`](crate::runtime::multivector::Multivector) (a `2^n x 2^n` table); above,
/// against the sparse reference
/// ([`SparseMultivector`](crate::runtime::sparse::multivector::SparseMultivector)).
pub const MAX_DENSE_REFERENCE_DIMENSION: usize = 8;

impl Spec {
    /// Whether the generated code's generic reference (`algebra()`, `to_multivector`, the
    /// check harness) is the sparse multivector: above [`MAX_DENSE_REFERENCE_DIMENSION`]
    /// basis vectors, where the dense one's `2^n x 2^n` table is too large.
    pub fn sparse_reference(&self) -> bool {
        self.metric.dim() > MAX_DENSE_REFERENCE_DIMENSION
    }

    /// Read and validate a TOML spec; `source` names it in errors.
    pub fn from_toml(text: &str, source: &str) -> Result<Spec, SpecError> {
        let raw: RawSpec = toml::from_str(text).map_err(|e| {
            SpecError::new(
                source,
                SpecLocation::Spec,
                SpecErrorKind::Parse(e.to_string()),
            )
        })?;
        Spec::from_raw(raw, source)
    }

    /// Read a TOML spec file (a regular file or a pipe of at most [`MAX_SPEC_BYTES`]; a
    /// device such as `/dev/zero` is refused before it is read).
    pub fn from_file(path: &std::path::Path) -> Result<Spec, SpecError> {
        use std::io::Read;
        let source = path.display().to_string();
        let fail = |m: String| SpecError::new(&source, SpecLocation::Spec, SpecErrorKind::Parse(m));
        let file = std::fs::File::open(path).map_err(|e| fail(e.to_string()))?;
        let kind = file
            .metadata()
            .map_err(|e| fail(e.to_string()))?
            .file_type();
        if kind.is_dir() {
            return Err(fail("a folder, not a spec file".into()));
        }
        if is_device(&kind) {
            return Err(fail("a device, not a file: refusing to read it".into()));
        }
        let mut bytes = Vec::new();
        file.take(MAX_SPEC_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| fail(e.to_string()))?;
        if bytes.len() as u64 > MAX_SPEC_BYTES {
            return Err(fail(format!(
                "more than {MAX_SPEC_BYTES} bytes, far more than any algebra's spec"
            )));
        }
        let text = String::from_utf8(bytes).map_err(|e| fail(format!("not UTF-8 text: {e}")))?;
        Spec::from_toml(&text, &source)
    }

    /// Validate a raw spec: metric, types, sandwiches, size budget, exactness, in that
    /// order; the first error found is returned, located.
    pub fn from_raw(raw: RawSpec, source: &str) -> Result<Spec, SpecError> {
        let metric = metric::read(&raw, source)?;
        let types = types::read(&raw.types, &metric, source)?;
        let sandwiches = sandwiches::read(&raw.sandwich, &types, source)?;
        budget::check(&metric, &types, &sandwiches, source)?;
        exact::check(&metric, &raw.basis, &types, &sandwiches, &raw.types, source)?;
        Ok(Spec {
            source: source.to_string(),
            name: raw.name.unwrap_or_else(|| "algebra".to_string()),
            doc: raw.doc,
            metric,
            types,
            sandwiches,
        })
    }
}

/// The most bytes [`Spec::from_file`] reads (a spec is a few kilobytes).
pub const MAX_SPEC_BYTES: u64 = 1 << 22;

/// Whether a file type is a character or block device.
#[cfg(unix)]
fn is_device(kind: &std::fs::FileType) -> bool {
    use std::os::unix::fs::FileTypeExt;
    kind.is_char_device() || kind.is_block_device()
}

/// Whether a file type is a character or block device (never, off Unix).
#[cfg(not(unix))]
fn is_device(_: &std::fs::FileType) -> bool {
    false
}

/// A spec shipped in `algebras/` by name (`"qcga"`), for unit tests.
#[cfg(test)]
pub(crate) fn shipped_spec(name: &str) -> Spec {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../algebras")
        .join(format!("{name}.toml"));
    Spec::from_file(&path).expect("valid spec")
}
