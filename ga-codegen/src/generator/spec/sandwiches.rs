//! Phase 3: the sandwich declarations, as indices into the validated types.

use super::error::{SpecError, SpecErrorKind, SpecLocation};
use super::{RawSandwich, SandwichDef, TypeDef};

/// Validate every sandwich declaration, in order.
pub(super) fn read(
    raw: &[RawSandwich],
    types: &[TypeDef],
    source: &str,
) -> Result<Vec<SandwichDef>, SpecError> {
    let find = |name: &str, loc: SpecLocation| {
        types
            .iter()
            .position(|t| t.name == name)
            .ok_or_else(|| SpecError::new(source, loc, SpecErrorKind::UnknownType).in_type(name))
    };
    let mut sandwiches: Vec<SandwichDef> = Vec::with_capacity(raw.len());
    for (si, s) in raw.iter().enumerate() {
        let versor = find(&s.versor, SpecLocation::SandwichVersor(si))?;
        if !types[versor].versor {
            return Err(SpecError::new(
                source,
                SpecLocation::SandwichVersor(si),
                SpecErrorKind::NotVersor,
            )
            .in_type(&s.versor));
        }
        let operand = find(&s.operand, SpecLocation::SandwichOperand(si))?;
        let output = match &s.output {
            Some(o) => Some(find(o, SpecLocation::SandwichOutput(si))?),
            None => None,
        };
        if sandwiches
            .iter()
            .any(|d| d.versor == versor && d.operand == operand)
        {
            return Err(SpecError::new(
                source,
                SpecLocation::Sandwich(si),
                SpecErrorKind::DuplicateSandwich,
            )
            .in_type(&s.versor)
            .at_blade(&s.operand));
        }
        sandwiches.push(SandwichDef {
            versor,
            operand,
            output,
        });
    }
    Ok(sandwiches)
}
