//! Phase 1: the basis names and the metric, exact.

use super::error::{SpecError, SpecErrorKind, SpecLocation};
use super::RawSpec;
use crate::runtime::metric::{Metric, MetricError};
use crate::runtime::rational::Rational;

/// The metric of a raw spec (`metric` or `diagonal`), every entry read exactly.
pub(super) fn read(raw: &RawSpec, source: &str) -> Result<Metric, SpecError> {
    let metric = match (&raw.metric, &raw.diagonal) {
        (Some(m), None) => Metric::from_f64(raw.basis.clone(), m),
        (None, Some(d)) => diagonal(&raw.basis, d),
        _ => {
            return Err(SpecError::new(
                source,
                SpecLocation::Spec,
                SpecErrorKind::MetricMissing,
            ))
        }
    };
    metric.map_err(|e| error(source, &raw.basis, e))
}

fn diagonal(basis: &[String], d: &[f64]) -> Result<Metric, MetricError> {
    if d.len() != basis.len() {
        return Err(MetricError::Size {
            expected: basis.len(),
            got: d.len(),
            row: None,
        });
    }
    let squares = d
        .iter()
        .enumerate()
        .map(|(i, &x)| Rational::from_f64(x).ok_or(MetricError::NotExact { i, j: i }))
        .collect::<Result<Vec<_>, _>>()?;
    Metric::diagonal(basis.to_vec(), &squares)
}

/// A metric error as a spec error, located.
pub(super) fn error(source: &str, basis: &[String], e: MetricError) -> SpecError {
    SpecError::new(source, location(&e, basis), SpecErrorKind::Metric(e))
}

/// Where a metric error is: the basis name or the metric entry it names.
fn location(e: &MetricError, basis: &[String]) -> SpecLocation {
    let named = |name: &str, nth: usize| {
        basis
            .iter()
            .enumerate()
            .filter(|(_, b)| *b == name)
            .nth(nth)
            .map_or(SpecLocation::BasisList, |(i, _)| SpecLocation::Basis(i))
    };
    match e {
        MetricError::Dimension(_) => SpecLocation::BasisList,
        MetricError::BadName(n) | MetricError::KeywordName(n) => named(n, 0),
        MetricError::DuplicateName(n) => named(n, 1),
        MetricError::PrefixName { longer, .. } => named(longer, 0),
        MetricError::Size { row: Some(r), .. } => SpecLocation::MetricRow(*r),
        MetricError::Size { row: None, .. } => SpecLocation::Metric,
        MetricError::NotSymmetric { i, j }
        | MetricError::NotExact { i, j }
        | MetricError::Overflow { i, j, .. } => SpecLocation::MetricEntry { row: *i, col: *j },
    }
}
