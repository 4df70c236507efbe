//! Mapping spec and generator errors back to the tokens of an inline spec.
//!
//! [`SpecError`] names the type and the blade (or other name) it concerns as strings, and a
//! metric error names rows and entries by index; the ranges recorded while parsing
//! ([`Spans`]) are searched for them, replaying the order in which `Spec::from_raw` checks
//! things where a name can occur more than once.

use crate::grammar::{Range, Spans};
use ga_codegen::blade::parse_blade;
use ga_codegen::spec::{RawSpec, SpecError, SpecErrorKind};
use ga_codegen::{GenError, MetricError};

/// Where a spec error should be reported.
pub(crate) fn spec_error(e: &SpecError, raw: &RawSpec, spans: &Spans) -> Range {
    let ty = e.type_name.as_deref();
    let blade = e.blade.as_deref();
    let fallback = Range::call_site();
    match &e.kind {
        SpecErrorKind::Parse(_) => fallback,
        // Both given is rejected while parsing, so here neither was given.
        SpecErrorKind::MetricMissing => fallback,
        SpecErrorKind::Metric(m) => metric_error(m, raw, spans).unwrap_or(fallback),
        SpecErrorKind::UnknownBlade
        | SpecErrorKind::AmbiguousBlade
        | SpecErrorKind::RepeatedBasis => type_index(raw, ty, 0)
            .and_then(|t| {
                let i = raw.types[t]
                    .blades
                    .iter()
                    .position(|b| Some(b.as_str()) == blade)?;
                Some(spans.types[t].blades[i])
            })
            .unwrap_or(fallback),
        SpecErrorKind::DuplicateBlade => type_index(raw, ty, 0)
            .and_then(|t| {
                let i = first_repeated_blade(&raw.types[t].blades, &raw.basis)?;
                Some(spans.types[t].blades[i])
            })
            .unwrap_or(fallback),
        SpecErrorKind::ConstantNotInType | SpecErrorKind::BadConstant => {
            let value = matches!(e.kind, SpecErrorKind::BadConstant);
            type_index(raw, ty, 0)
                .and_then(|t| {
                    let (_, key, val) = spans.types[t]
                        .constants
                        .iter()
                        .find(|c| Some(c.0.as_str()) == blade)?;
                    Some(if value { *val } else { *key })
                })
                .unwrap_or(fallback)
        }
        SpecErrorKind::EmptyType | SpecErrorKind::BadTypeName => type_index(raw, ty, 0)
            .map(|t| spans.types[t].name)
            .unwrap_or(fallback),
        SpecErrorKind::DuplicateType => type_index(raw, ty, 1)
            .or_else(|| type_index(raw, ty, 0))
            .map(|t| spans.types[t].name)
            .unwrap_or(fallback),
        SpecErrorKind::UnknownType => {
            // The first reference to the name, in the order sandwiches are checked.
            raw.sandwich
                .iter()
                .zip(&spans.sandwiches)
                .find_map(|(s, r)| {
                    if Some(s.versor.as_str()) == ty {
                        Some(r.versor)
                    } else if Some(s.operand.as_str()) == ty {
                        Some(r.operand)
                    } else if s.output.as_deref() == ty {
                        r.output
                    } else {
                        None
                    }
                })
                .unwrap_or(fallback)
        }
        SpecErrorKind::NotVersor => raw
            .sandwich
            .iter()
            .zip(&spans.sandwiches)
            .find(|(s, _)| Some(s.versor.as_str()) == ty)
            .map(|(_, r)| r.versor)
            .unwrap_or(fallback),
        SpecErrorKind::DuplicateSandwich => raw
            .sandwich
            .iter()
            .zip(&spans.sandwiches)
            .filter(|(s, _)| Some(s.versor.as_str()) == ty && Some(s.operand.as_str()) == blade)
            .nth(1)
            .map(|(_, r)| r.whole)
            .unwrap_or(fallback),
    }
}

/// Where a generator error should be reported: the sandwich it concerns (its output type
/// when the output cannot hold the result).
pub(crate) fn gen_error(e: &GenError, raw: &RawSpec, spans: &Spans) -> Range {
    let find = |versor: &str, operand: &str| {
        raw.sandwich
            .iter()
            .zip(&spans.sandwiches)
            .find(|(s, _)| s.versor == versor && s.operand == operand)
            .map(|(_, r)| r)
    };
    match e {
        GenError::SandwichOutput {
            versor, operand, ..
        } => find(versor, operand).map(|r| r.output.unwrap_or(r.whole)),
        GenError::ZeroSandwich {
            versor, operand, ..
        } => find(versor, operand).map(|r| r.whole),
        GenError::Internal(_) => None,
    }
    .unwrap_or_else(Range::call_site)
}

/// The `nth` (0-based) type declared with the name `name`.
fn type_index(raw: &RawSpec, name: Option<&str>, nth: usize) -> Option<usize> {
    let name = name?;
    raw.types
        .iter()
        .enumerate()
        .filter(|(_, t)| t.name == name)
        .nth(nth)
        .map(|(i, _)| i)
}

/// The index of the first blade that repeats an earlier one (maybe written in another order).
fn first_repeated_blade(blades: &[String], basis: &[String]) -> Option<usize> {
    let mut seen = Vec::new();
    for (i, b) in blades.iter().enumerate() {
        let (bitmap, _) = parse_blade(b, basis).ok()?;
        if seen.contains(&bitmap) {
            return Some(i);
        }
        seen.push(bitmap);
    }
    None
}

/// Where a metric error should be reported.
fn metric_error(e: &MetricError, raw: &RawSpec, spans: &Spans) -> Option<Range> {
    let basis_named = |name: &str, nth: usize| {
        raw.basis
            .iter()
            .zip(&spans.basis)
            .filter(|(b, _)| *b == name)
            .nth(nth)
            .map(|(_, r)| *r)
    };
    match e {
        MetricError::Dimension(_) => spans.basis_list,
        MetricError::BadName(n) => basis_named(n, 0),
        MetricError::DuplicateName(n) => basis_named(n, 1),
        MetricError::Size { row: Some(r), .. } => spans.metric.as_ref()?.rows.get(*r).copied(),
        MetricError::Size { row: None, .. } => match (&spans.metric, &spans.diagonal) {
            (Some(m), _) => Some(m.whole),
            (None, Some(d)) => Some(d.whole),
            _ => None,
        },
        MetricError::NotSymmetric { i, j } => {
            spans.metric.as_ref()?.entries.get(*i)?.get(*j).copied()
        }
        MetricError::NotExact { i, j } => match (&spans.metric, &spans.diagonal) {
            (Some(m), _) => m.entries.get(*i)?.get(*j).copied(),
            (None, Some(d)) => d.entries.get(*i).copied(),
            _ => None,
        },
    }
}
