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
//! A type holding every blade (the general multivector, `Mv`) is added when the spec has none.

use crate::blade::{blade_name, parse_blade, Bitmap, BladeNameError};
use crate::metric::{Metric, MetricError};
use crate::rational::Rational;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::fmt;

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
    /// Types, in declaration order (the general multivector last if it was added).
    pub types: Vec<TypeDef>,
    /// Sandwiches.
    pub sandwiches: Vec<SandwichDef>,
}

/// What is wrong with a spec.
#[derive(Clone, Debug, PartialEq)]
pub enum SpecErrorKind {
    /// Not valid TOML or not the expected shape.
    Parse(String),
    /// No metric, or both `metric` and `diagonal`.
    MetricMissing,
    /// The metric is malformed.
    Metric(MetricError),
    /// A blade name that is not made of basis names.
    UnknownBlade,
    /// A blade name that splits into basis names in two ways.
    AmbiguousBlade,
    /// A blade naming one basis vector twice (`e11`).
    RepeatedBasis,
    /// The same blade listed twice in a type (maybe in another order: `e12`, `e21`).
    DuplicateBlade,
    /// A type with no blades (or only constants).
    EmptyType,
    /// Two types with one name.
    DuplicateType,
    /// A type name that is not an UpperCamelCase Rust identifier, or is reserved.
    BadTypeName,
    /// A constant on a blade the type does not list.
    ConstantNotInType,
    /// A constant that is not finite.
    BadConstant,
    /// A sandwich naming a type that does not exist.
    UnknownType,
    /// A sandwich declared twice for one versor and operand.
    DuplicateSandwich,
    /// A sandwich whose versor type is not marked `versor = true`.
    NotVersor,
}

impl fmt::Display for SpecErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = match self {
            SpecErrorKind::Parse(m) => return write!(f, "cannot read spec: {m}"),
            SpecErrorKind::MetricMissing => {
                "give exactly one of `metric` (full matrix) or `diagonal` (squares)"
            }
            SpecErrorKind::Metric(m) => return write!(f, "{m}"),
            SpecErrorKind::UnknownBlade => "unknown blade: not made of the basis names",
            SpecErrorKind::AmbiguousBlade => {
                "ambiguous blade name: splits into basis names in two ways"
            }
            SpecErrorKind::RepeatedBasis => "blade names a basis vector twice",
            SpecErrorKind::DuplicateBlade => "blade listed twice",
            SpecErrorKind::EmptyType => "type has no stored blades",
            SpecErrorKind::DuplicateType => "type name used twice",
            SpecErrorKind::BadTypeName => {
                "type name must be an UpperCamelCase identifier other than `Scalar`, `Sandwich` or `F64x2`"
            }
            SpecErrorKind::ConstantNotInType => "constant on a blade the type does not list",
            SpecErrorKind::BadConstant => "constant is not a finite number",
            SpecErrorKind::UnknownType => "no type of this name",
            SpecErrorKind::DuplicateSandwich => {
                "sandwich declared twice for this versor and operand"
            }
            SpecErrorKind::NotVersor => "versor type is not marked `versor = true`",
        };
        f.write_str(s)
    }
}

/// A spec error: the file, the type and the blade it concerns, and what is wrong.
#[derive(Clone, Debug, PartialEq)]
pub struct SpecError {
    /// The spec file (or `algebra!`).
    pub file: String,
    /// The type concerned.
    pub type_name: Option<String>,
    /// The blade (or other name) concerned.
    pub blade: Option<String>,
    /// What is wrong.
    pub kind: SpecErrorKind,
}

impl fmt::Display for SpecError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.file)?;
        if let Some(t) = &self.type_name {
            write!(f, "type `{t}`: ")?;
        }
        if let Some(b) = &self.blade {
            write!(f, "`{b}`: ")?;
        }
        write!(f, "{}", self.kind)
    }
}

impl std::error::Error for SpecError {}

/// Name of the general multivector type added when a spec declares none.
pub const GENERAL_TYPE: &str = "Mv";

fn valid_type_name(n: &str) -> bool {
    let mut c = n.chars();
    matches!(c.next(), Some(ch) if ch.is_ascii_uppercase())
        && n.chars().all(|ch| ch.is_ascii_alphanumeric())
        && !["Scalar", "Sandwich", "Self", "F64x2"].contains(&n)
}

impl Spec {
    /// Read and validate a TOML spec; `source` names it in errors.
    pub fn from_toml(text: &str, source: &str) -> Result<Spec, SpecError> {
        let raw: RawSpec = toml::from_str(text).map_err(|e| SpecError {
            file: source.to_string(),
            type_name: None,
            blade: None,
            kind: SpecErrorKind::Parse(e.to_string()),
        })?;
        Spec::from_raw(raw, source)
    }

    /// Read a TOML spec file.
    pub fn from_file(path: &std::path::Path) -> Result<Spec, SpecError> {
        let source = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| SpecError {
            file: source.clone(),
            type_name: None,
            blade: None,
            kind: SpecErrorKind::Parse(e.to_string()),
        })?;
        Spec::from_toml(&text, &source)
    }

    /// Validate a raw spec.
    pub fn from_raw(raw: RawSpec, source: &str) -> Result<Spec, SpecError> {
        let err = |t: Option<&str>, b: Option<&str>, kind| SpecError {
            file: source.to_string(),
            type_name: t.map(str::to_string),
            blade: b.map(str::to_string),
            kind,
        };
        let metric = match (&raw.metric, &raw.diagonal) {
            (Some(m), None) => Metric::from_f64(raw.basis.clone(), m),
            (None, Some(d)) => {
                let n = raw.basis.len();
                if d.len() != n {
                    Err(MetricError::Size {
                        expected: n,
                        got: d.len(),
                        row: None,
                    })
                } else {
                    let sq: Result<Vec<Rational>, MetricError> = d
                        .iter()
                        .enumerate()
                        .map(|(i, &x)| {
                            Rational::from_f64(x).ok_or(MetricError::NotExact { i, j: i })
                        })
                        .collect();
                    sq.and_then(|sq| Metric::diagonal(raw.basis.clone(), &sq))
                }
            }
            _ => return Err(err(None, None, SpecErrorKind::MetricMissing)),
        }
        .map_err(|e| err(None, None, SpecErrorKind::Metric(e)))?;
        let basis = metric.names().to_vec();
        let mut types: Vec<TypeDef> = Vec::new();
        for rt in &raw.types {
            let tn = Some(rt.name.as_str());
            if !valid_type_name(&rt.name) {
                return Err(err(tn, None, SpecErrorKind::BadTypeName));
            }
            if types.iter().any(|t| t.name == rt.name) {
                return Err(err(tn, None, SpecErrorKind::DuplicateType));
            }
            let mut fields: Vec<Field> = Vec::new();
            let mut constants = Vec::new();
            let mut seen: Vec<Bitmap> = Vec::new();
            for bname in &rt.blades {
                let bn = Some(bname.as_str());
                let (bitmap, sign) = parse_blade(bname, &basis).map_err(|e| {
                    err(
                        tn,
                        bn,
                        match e {
                            BladeNameError::Unknown => SpecErrorKind::UnknownBlade,
                            BladeNameError::Ambiguous => SpecErrorKind::AmbiguousBlade,
                            BladeNameError::Repeated => SpecErrorKind::RepeatedBasis,
                        },
                    )
                })?;
                if seen.contains(&bitmap) {
                    return Err(err(tn, bn, SpecErrorKind::DuplicateBlade));
                }
                seen.push(bitmap);
                if let Some(&c) = rt.constants.get(bname) {
                    let c = Rational::from_f64(c)
                        .ok_or_else(|| err(tn, bn, SpecErrorKind::BadConstant))?;
                    constants.push((bitmap, c * Rational::int(sign as i64)));
                } else {
                    let name = if bitmap == 0 {
                        "s".to_string()
                    } else {
                        bname.clone()
                    };
                    fields.push(Field { name, bitmap, sign });
                }
            }
            for cname in rt.constants.keys() {
                if !rt.blades.contains(cname) {
                    return Err(err(tn, Some(cname), SpecErrorKind::ConstantNotInType));
                }
            }
            if fields.is_empty() {
                return Err(err(tn, None, SpecErrorKind::EmptyType));
            }
            types.push(TypeDef {
                name: rt.name.clone(),
                doc: rt.doc.clone(),
                fields,
                constants,
                versor: rt.versor,
                unit: rt.unit,
            });
        }
        let size = 1u32 << metric.dim();
        let has_general = types
            .iter()
            .any(|t| t.constants.is_empty() && t.fields.len() == size as usize);
        if !has_general {
            if types.iter().any(|t| t.name == GENERAL_TYPE) {
                return Err(err(Some(GENERAL_TYPE), None, SpecErrorKind::DuplicateType));
            }
            let mut order = crate::blade::canonical_order(metric.dim());
            order.retain(|_| true);
            types.push(TypeDef {
                name: GENERAL_TYPE.to_string(),
                doc: Some("The general multivector: every blade of the algebra.".to_string()),
                fields: order
                    .into_iter()
                    .map(|b| Field {
                        name: blade_name(b, &basis),
                        bitmap: b,
                        sign: 1,
                    })
                    .collect(),
                constants: Vec::new(),
                versor: false,
                unit: false,
            });
        }
        let find = |name: &str| types.iter().position(|t| t.name == name);
        let mut sandwiches: Vec<SandwichDef> = Vec::new();
        for s in &raw.sandwich {
            let versor = find(&s.versor)
                .ok_or_else(|| err(Some(&s.versor), None, SpecErrorKind::UnknownType))?;
            if !types[versor].versor {
                return Err(err(Some(&s.versor), None, SpecErrorKind::NotVersor));
            }
            let operand = find(&s.operand)
                .ok_or_else(|| err(Some(&s.operand), None, SpecErrorKind::UnknownType))?;
            let output = match &s.output {
                Some(o) => {
                    Some(find(o).ok_or_else(|| err(Some(o), None, SpecErrorKind::UnknownType))?)
                }
                None => None,
            };
            if sandwiches
                .iter()
                .any(|d| d.versor == versor && d.operand == operand)
            {
                return Err(err(
                    Some(&s.versor),
                    Some(&s.operand),
                    SpecErrorKind::DuplicateSandwich,
                ));
            }
            sandwiches.push(SandwichDef {
                versor,
                operand,
                output,
            });
        }
        Ok(Spec {
            source: source.to_string(),
            name: raw.name.unwrap_or_else(|| "algebra".to_string()),
            doc: raw.doc,
            metric,
            types,
            sandwiches,
        })
    }

    /// The default spec of a diagonal signature G(p, q, r): one type per grade 1..n, the even
    /// subalgebra (a versor, sandwiching every grade type), and the general multivector.
    pub fn for_signature(p: usize, q: usize, r: usize) -> Result<Spec, SpecError> {
        let metric = Metric::signature(p, q, r).map_err(|e| SpecError {
            file: format!("--signature {p},{q},{r}"),
            type_name: None,
            blade: None,
            kind: SpecErrorKind::Metric(e),
        })?;
        let n = metric.dim();
        let basis = metric.names().to_vec();
        let order = crate::blade::canonical_order(n);
        let grade_names = [
            "Scalar",
            "Vector",
            "Bivector",
            "Trivector",
            "Quadvector",
            "Pentavector",
            "Hexavector",
            "Heptavector",
            "Octavector",
            "Nonavector",
            "Decavector",
        ];
        let mut raw = RawSpec {
            name: Some(format!("g{p}{q}{r}")),
            doc: Some(format!(
                "The geometric algebra G({p},{q},{r}), generated from its signature."
            )),
            basis: basis.clone(),
            diagonal: Some((0..n).map(|i| metric.get(i, i).to_f64()).collect()),
            ..RawSpec::default()
        };
        for k in 1..=n {
            let name = if k == n && n > 1 {
                "Pseudoscalar"
            } else {
                grade_names[k]
            };
            raw.types.push(RawType {
                name: name.to_string(),
                doc: Some(format!("A grade-{k} element.")),
                blades: order
                    .iter()
                    .filter(|&&b| crate::blade::grade(b) as usize == k)
                    .map(|&b| blade_name(b, &basis))
                    .collect(),
                ..RawType::default()
            });
        }
        raw.types.push(RawType {
            name: "Even".to_string(),
            doc: Some("An element of the even subalgebra (rotors, motors).".to_string()),
            blades: order
                .iter()
                .filter(|&&b| crate::blade::grade(b).is_multiple_of(2))
                .map(|&b| blade_name(b, &basis))
                .collect(),
            versor: true,
            ..RawType::default()
        });
        raw.types.push(RawType {
            name: GENERAL_TYPE.to_string(),
            doc: Some("The general multivector: every blade of the algebra.".to_string()),
            blades: order.iter().map(|&b| blade_name(b, &basis)).collect(),
            ..RawType::default()
        });
        for k in 1..=n {
            let name = if k == n && n > 1 {
                "Pseudoscalar"
            } else {
                grade_names[k]
            };
            raw.sandwich.push(RawSandwich {
                versor: "Even".to_string(),
                operand: name.to_string(),
                output: None,
            });
        }
        Spec::from_raw(raw, &format!("--signature {p},{q},{r}"))
    }
}
