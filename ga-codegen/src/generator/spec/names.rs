//! Which type names a spec may use: UpperCamelCase identifiers that the generated module does
//! not already use for something else.

use super::error::SpecErrorKind;

/// Names of items the generated module defines or uses unqualified.
const GENERATED_ITEMS: &[&str] = &[
    "Scalar",
    "Sandwich",
    "F64x2",
    "F32x4",
    "Self",
    "Exp",
    "Log",
    "EvenVersor",
];

/// Suffix of the generated versor-matrix types (`MotorPointMatrix` for the matrix form of
/// `Motor.sandwich(Point)`).
const MATRIX_SUFFIX: &str = "Matrix";

/// Check a declared type name; `Ok` when it can name a generated struct.
pub(super) fn check_type_name(name: &str) -> Result<(), SpecErrorKind> {
    let mut chars = name.chars();
    let camel = matches!(chars.next(), Some(c) if c.is_ascii_uppercase())
        && chars.all(|c| c.is_ascii_alphanumeric());
    if !camel {
        return Err(SpecErrorKind::BadTypeName);
    }
    if crate::runtime::ident::is_keyword(name) {
        return Err(SpecErrorKind::ReservedTypeName("a Rust keyword"));
    }
    if GENERATED_ITEMS.contains(&name) {
        return Err(SpecErrorKind::ReservedTypeName(
            "the generated module defines or uses an item of this name \
             (`Scalar`, `Sandwich`, `F64x2`, `F32x4`, `Exp`, `Log`, `EvenVersor`)",
        ));
    }
    if name.ends_with(MATRIX_SUFFIX) {
        return Err(SpecErrorKind::ReservedTypeName(
            "names ending in `Matrix` are kept for the generated versor matrices \
             (`MotorPointMatrix` is the matrix of `Motor.sandwich(Point)`)",
        ));
    }
    Ok(())
}

/// The reason given when a spec names a type [`GENERAL_TYPE`] that does not hold every blade.
pub(super) const GENERAL_NAME_TAKEN: &str =
    "`Mv` names the general multivector, added when no type holds every blade";

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generator::spec::GENERAL_TYPE;

    #[test]
    fn type_names() {
        for ok in ["Motor", "Point", "V2", "ScaledMotor", "Mv", "Matrixish"] {
            assert_eq!(check_type_name(ok), Ok(()), "{ok}");
        }
        for bad in ["motor", "", "Motor_2", "Mötor", "2D"] {
            assert_eq!(
                check_type_name(bad),
                Err(SpecErrorKind::BadTypeName),
                "{bad}"
            );
        }
        for reserved in [
            "Self",
            "Scalar",
            "Sandwich",
            "F64x2",
            "Exp",
            "Log",
            "EvenVersor",
            "RVMatrix",
            "RotorPointMatrix",
        ] {
            assert!(
                matches!(
                    check_type_name(reserved),
                    Err(SpecErrorKind::ReservedTypeName(_))
                ),
                "{reserved}"
            );
        }
        assert_eq!(GENERAL_TYPE, "Mv");
    }
}
