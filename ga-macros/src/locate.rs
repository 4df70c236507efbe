//! Mapping spec and generator errors back to the tokens of an inline spec.
//!
//! A [`SpecError`] carries its [`SpecLocation`] (indices into the spec as written), so a
//! spec error is located by looking it up in the ranges recorded while parsing ([`Spans`]).

use crate::grammar::{Range, Spans};
use ga_codegen::generator::spec::{RawSpec, SpecError, SpecLocation};
use ga_codegen::GenError;

/// Where a spec error should be reported (the whole invocation when the spans lack it).
pub(crate) fn spec_error(e: &SpecError, spans: &Spans) -> Range {
    location(&e.location, spans).unwrap_or_else(Range::call_site)
}

/// The range of a location.
fn location(at: &SpecLocation, spans: &Spans) -> Option<Range> {
    let constant =
        |ty: usize, key: &str| spans.types.get(ty)?.constants.iter().find(|c| c.0 == key);
    match at {
        SpecLocation::Spec => None,
        SpecLocation::BasisList => spans.basis_list,
        SpecLocation::Basis(i) => spans.basis.get(*i).copied(),
        SpecLocation::Metric => match (&spans.metric, &spans.diagonal) {
            (Some(m), _) => Some(m.whole),
            (None, Some(d)) => Some(d.whole),
            _ => None,
        },
        SpecLocation::MetricRow(r) => spans.metric.as_ref()?.rows.get(*r).copied(),
        SpecLocation::MetricEntry { row, col } => match (&spans.metric, &spans.diagonal) {
            (Some(m), _) => m.entries.get(*row)?.get(*col).copied(),
            (None, Some(d)) => d.entries.get(*row).copied(),
            _ => None,
        },
        SpecLocation::TypeName(t) => Some(spans.types.get(*t)?.name),
        SpecLocation::TypeBlade { ty, blade } => spans.types.get(*ty)?.blades.get(*blade).copied(),
        SpecLocation::ConstantKey { ty, key } => constant(*ty, key).map(|c| c.1),
        SpecLocation::ConstantValue { ty, key } => constant(*ty, key).map(|c| c.2),
        SpecLocation::Sandwich(i) => Some(spans.sandwiches.get(*i)?.whole),
        SpecLocation::SandwichVersor(i) => Some(spans.sandwiches.get(*i)?.versor),
        SpecLocation::SandwichOperand(i) => Some(spans.sandwiches.get(*i)?.operand),
        SpecLocation::SandwichOutput(i) => spans.sandwiches.get(*i)?.output,
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
        }
        | GenError::NoSandwichOutput {
            versor, operand, ..
        } => find(versor, operand).map(|r| r.whole),
        GenError::NoClosedForm { ty, .. } => raw
            .types
            .iter()
            .zip(&spans.types)
            .find(|(t, _)| &t.name == ty)
            .map(|(_, r)| r.name),
        GenError::RuntimePath { .. } | GenError::Internal(_) => None,
    }
    .unwrap_or_else(Range::call_site)
}
