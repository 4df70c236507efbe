//! The vocabulary of what the emitter emits: result kinds ([`OutType`]), binary operations
//! ([`Op`]: operators, named products, sandwiches, conversions), unary methods whose result
//! type is inferred ([`Method`]) and the summary row of an emitted operation ([`OpSummary`]).

use std::fmt;

/// What a product returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutType {
    /// Identically zero: not emitted.
    Zero,
    /// A pure scalar: the scalar type.
    Scalar,
    /// A declared type (index).
    Type(usize),
    /// No declared type holds it (only above
    /// [`MAX_GENERAL_DIMENSION`](crate::generator::spec::MAX_GENERAL_DIMENSION) basis vectors,
    /// where no general multivector is added): not emitted, listed in
    /// [`Generated::skipped`](super::Generated::skipped).
    Unfit,
}

/// An emitted binary operation between two declared types (or a type and the scalar, for
/// the named products).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Op {
    /// `a * b`, the geometric product.
    Geometric,
    /// `a ^ b`, the outer product.
    Outer,
    /// `a | b`, the left contraction.
    LeftContraction,
    /// `a + b`.
    Add,
    /// `a - b`.
    Sub,
    /// `a.right_contraction(b)`, `a ⌊ b`.
    RightContraction,
    /// `a.scalar_product(b)`, `<a b>_0`.
    ScalarProduct,
    /// `a.dot_product(b)`, Dorst's dot product (GATL's `dot`).
    DotProduct,
    /// `a.hestenes_inner_product(b)`, the Hestenes inner product (GATL's `hip`).
    HestenesInnerProduct,
    /// `a.commutator_product(b)`, `(a b - b a) / 2`.
    CommutatorProduct,
    /// `a.regressive_product(b)`, `undual(dual(a) ^ dual(b))`.
    RegressiveProduct,
    /// `a.inverse_geometric_product(b)`, `a b^-1` as `a ~b / <b ~b>_0`.
    InverseGeometricProduct,
    /// `a.sandwich(b)`, `a * b * ~a` fused (with its matrix form).
    Sandwich,
    /// `B::from(a)`, a conversion into a type that holds every blade of `a`.
    From,
}

impl Op {
    /// The binary operators, in the order they are emitted for each pair of types.
    pub const OPERATORS: [Op; 5] = [
        Op::Geometric,
        Op::Outer,
        Op::LeftContraction,
        Op::Add,
        Op::Sub,
    ];

    /// The named products (methods of a trait of the same name), in the order they are
    /// emitted for each pair of operands: ga-benchmark's binary operations that are not
    /// operators.
    pub const NAMED: [Op; 7] = [
        Op::RightContraction,
        Op::ScalarProduct,
        Op::DotProduct,
        Op::HestenesInnerProduct,
        Op::CommutatorProduct,
        Op::RegressiveProduct,
        Op::InverseGeometricProduct,
    ];

    /// The trait of a named product (`RightContraction`, ...), `None` for the others.
    pub fn trait_name(self) -> Option<&'static str> {
        Some(match self {
            Op::RightContraction => "RightContraction",
            Op::ScalarProduct => "ScalarProduct",
            Op::DotProduct => "DotProduct",
            Op::HestenesInnerProduct => "HestenesInnerProduct",
            Op::CommutatorProduct => "CommutatorProduct",
            Op::RegressiveProduct => "RegressiveProduct",
            Op::InverseGeometricProduct => "InverseGeometricProduct",
            _ => return None,
        })
    }

    /// The operator as written (`*`, `^`, `|`, `+`, `-`), the method of a named product
    /// (`right_contraction`, ...), or `sandwich` / `from`.
    pub fn symbol(self) -> &'static str {
        match self {
            Op::RightContraction => "right_contraction",
            Op::ScalarProduct => "scalar_product",
            Op::DotProduct => "dot_product",
            Op::HestenesInnerProduct => "hestenes_inner_product",
            Op::CommutatorProduct => "commutator_product",
            Op::RegressiveProduct => "regressive_product",
            Op::InverseGeometricProduct => "inverse_geometric_product",
            Op::Geometric => "*",
            Op::Outer => "^",
            Op::LeftContraction => "|",
            Op::Add => "+",
            Op::Sub => "-",
            Op::Sandwich => "sandwich",
            Op::From => "from",
        }
    }
}

impl fmt::Display for Op {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.symbol())
    }
}

/// An emitted unary method whose result is not fixed by the type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// `rev()`: the reverse.
    Rev,
    /// `involute()`: the grade involution.
    Involute,
    /// `conjugate()`: the Clifford conjugate.
    Conjugate,
    /// `dual()`.
    Dual,
    /// `undual()`: the inverse of `dual()`.
    Undual,
    /// `square()`: `x * x` expanded in one set of coefficients.
    Square,
    /// `grade(k)`: the grade-`k` part.
    Grade,
    /// `normalized()`.
    Normalized,
    /// `inverse()`: the versor inverse.
    Inverse,
}

impl Method {
    /// The method's name.
    pub fn name(self) -> &'static str {
        match self {
            Method::Rev => "rev",
            Method::Involute => "involute",
            Method::Conjugate => "conjugate",
            Method::Dual => "dual",
            Method::Undual => "undual",
            Method::Square => "square",
            Method::Grade => "grade",
            Method::Normalized => "normalized",
            Method::Inverse => "inverse",
        }
    }
}

/// One emitted binary operation, for the summary and the check harness.
#[derive(Clone, Debug, PartialEq)]
pub struct OpSummary {
    /// The operation.
    pub op: Op,
    /// Left type.
    pub left: String,
    /// Right type.
    pub right: String,
    /// Result type name (the scalar type's name for scalars).
    pub output: String,
    /// Number of multiply terms after simplification.
    pub terms: usize,
    /// The multiplies of its matrix form, when it is computed through the matrix-unit basis
    /// (a geometric product of a type holding every blade, or every even blade).
    pub matrix_form: Option<usize>,
}
