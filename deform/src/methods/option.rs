//! An option a method binds by, described once: its name (the program's flag is `--` and the
//! name, the editor's messages carry the same name), its help, the values it takes (with the
//! editor's limits) and its default. A method's file lists its own ([`super::MethodKind::options`]);
//! [`super::MethodSettings`] keeps their values and [`OptionSpec::parse`] checks them.

use super::error::MethodError;
use super::named::Named;
use std::fmt;
use std::ops::RangeInclusive;

/// What values an option takes.
#[derive(Clone, Debug)]
pub enum OptionKind {
    /// One of a few names ([`Named`]'s).
    Choice {
        /// What a value is, for messages ("ARAP energy").
        what: &'static str,
        /// Every name, in the order lists show them.
        names: fn() -> Vec<&'static str>,
    },
    /// A whole number in a range (the editor's limits).
    Number(RangeInclusive<usize>),
    /// Points per axis, `LxMxN`, each in the range.
    Dims(RangeInclusive<usize>),
    /// On or off: a flag without a value.
    Switch,
}

impl OptionKind {
    /// The choice among `T`'s names.
    pub const fn choice<T: Named>() -> OptionKind {
        OptionKind::Choice {
            what: T::WHAT,
            names: T::names,
        }
    }
}

/// `LxMxN` as three counts: whole numbers separated by `x` or `X`, each with or without spaces
/// around it; `None` for anything else. The one reader of lattice sizes, for the methods' options
/// and the program's `deform ffd --lattice`.
///
/// ```
/// use deform::methods::option::parse_dims;
/// assert_eq!(parse_dims("4x3X 3"), Some([4, 3, 3]));
/// assert_eq!(parse_dims("4x3"), None);
/// ```
pub fn parse_dims(text: &str) -> Option<[usize; 3]> {
    let counts: Option<Vec<usize>> = text
        .split(['x', 'X'])
        .map(|n| n.trim().parse().ok())
        .collect();
    counts?.try_into().ok()
}

/// An option's value; in JSON a string, a number, `[l, m, n]` or a boolean.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(untagged)]
pub enum OptionValue {
    /// A choice by its name.
    Name(&'static str),
    /// A whole number.
    Number(usize),
    /// Points per axis.
    Dims([usize; 3]),
    /// On or off.
    Switch(bool),
}

/// Printed as the program's flags take it: the name, the number, `LxMxN`, `true`/`false`.
impl fmt::Display for OptionValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OptionValue::Name(n) => f.write_str(n),
            OptionValue::Number(n) => write!(f, "{n}"),
            OptionValue::Dims([l, m, n]) => write!(f, "{l}x{m}x{n}"),
            OptionValue::Switch(on) => write!(f, "{on}"),
        }
    }
}

/// One option of a method.
#[derive(Clone, Debug)]
pub struct OptionSpec {
    /// The name.
    pub name: &'static str,
    /// One line of help.
    pub help: &'static str,
    /// The values it takes.
    pub kind: OptionKind,
    /// Its value until one is set.
    pub default: OptionValue,
    /// The value the replayed command asks for instead of the editor's, where the editor's
    /// means something else there (ARAP's iterations per frame against a run from rest).
    pub replay: Option<OptionValue>,
}

impl OptionSpec {
    /// The value `text` names (as [`OptionValue`] prints it), checked against the kind.
    pub fn parse(&self, text: &str) -> Result<OptionValue, MethodError> {
        let out_of = |range: String| MethodError::OutOfRange {
            option: self.name,
            value: text.to_string(),
            range,
        };
        let span = |r: &RangeInclusive<usize>| format!("{}..={}", r.start(), r.end());
        match &self.kind {
            OptionKind::Choice { what, names } => {
                let names = names();
                names
                    .iter()
                    .find(|n| **n == text)
                    .map(|n| OptionValue::Name(n))
                    .ok_or_else(|| MethodError::UnknownName {
                        what,
                        given: text.to_string(),
                        expected: names.join(", "),
                    })
            }
            OptionKind::Number(range) => match text.parse::<usize>() {
                Ok(n) if range.contains(&n) => Ok(OptionValue::Number(n)),
                _ => Err(out_of(span(range))),
            },
            OptionKind::Dims(range) => {
                let dims = parse_dims(text).ok_or_else(|| out_of("LxMxN".into()))?;
                if dims.iter().all(|n| range.contains(n)) {
                    Ok(OptionValue::Dims(dims))
                } else {
                    Err(out_of(format!("LxMxN, each in {}", span(range))))
                }
            }
            OptionKind::Switch => match text {
                "true" => Ok(OptionValue::Switch(true)),
                "false" => Ok(OptionValue::Switch(false)),
                _ => Err(MethodError::UnknownName {
                    what: self.name,
                    given: text.to_string(),
                    expected: "true, false".into(),
                }),
            },
        }
    }

    /// The names a choice takes (`None` for the other kinds).
    pub fn values(&self) -> Option<Vec<&'static str>> {
        match &self.kind {
            OptionKind::Choice { names, .. } => Some(names()),
            _ => None,
        }
    }

    /// The range of a number or of each axis (`None` for the other kinds).
    pub fn range(&self) -> Option<&RangeInclusive<usize>> {
        match &self.kind {
            OptionKind::Number(r) | OptionKind::Dims(r) => Some(r),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deformers::arap::LocalStep;

    #[test]
    fn every_kind_parses_what_it_prints_and_refuses_the_rest() {
        let spec = |kind, default| OptionSpec {
            name: "x",
            help: "",
            kind,
            default,
            replay: None,
        };
        let choice = spec(
            OptionKind::choice::<LocalStep>(),
            OptionValue::Name("rotor"),
        );
        let number = spec(OptionKind::Number(2..=9), OptionValue::Number(2));
        let dims = spec(OptionKind::Dims(2..=8), OptionValue::Dims([2, 2, 2]));
        let switch = spec(OptionKind::Switch, OptionValue::Switch(false));
        for (s, v) in [
            (&choice, OptionValue::Name("svd")),
            (&number, OptionValue::Number(9)),
            (&dims, OptionValue::Dims([8, 2, 5])),
            (&switch, OptionValue::Switch(true)),
        ] {
            assert_eq!(s.parse(&v.to_string()).unwrap(), v);
        }
        for (s, text) in [
            (&choice, "SVD"),
            (&number, "10"),
            (&number, "-1"),
            (&number, "2.5"),
            (&dims, "9x2x2"),
            (&dims, "2x2"),
            (&dims, "2x2x2x2"),
            (&dims, "axbxc"),
            (&switch, "yes"),
        ] {
            assert!(s.parse(text).is_err(), "{text}");
        }
        // The program's `deform ffd --lattice` reads the same forms.
        assert_eq!(
            dims.parse(" 2X3 x 4").unwrap(),
            OptionValue::Dims([2, 3, 4])
        );
    }
}
