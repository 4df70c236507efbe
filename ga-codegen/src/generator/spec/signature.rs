//! The default spec of a diagonal signature, for `ga-codegen --signature P,Q,R`.

use super::GENERAL_TYPE;
use super::{RawSandwich, RawSpec, RawType, Spec, SpecError, SpecErrorKind, SpecLocation};
use crate::runtime::blade::blade_name;
use crate::runtime::metric::Metric;

/// Most basis vectors of a default spec: it declares every grade and the whole algebra, whose
/// products grow as `4^n` (8 is already over the work budget; 9 and more are refused here,
/// before any product, with the advice to write a spec of the types needed).
pub const MAX_SIGNATURE_DIMENSION: usize = 8;

impl Spec {
    /// The default spec of a diagonal signature G(p, q, r): one type per grade 1..n, the even
    /// subalgebra (a versor, sandwiching every grade type), and the general multivector; up to
    /// `MAX_SIGNATURE_DIMENSION` (8) basis vectors.
    pub fn for_signature(p: usize, q: usize, r: usize) -> Result<Spec, SpecError> {
        let source = format!("--signature {p},{q},{r}");
        let n = p.saturating_add(q).saturating_add(r);
        if n > MAX_SIGNATURE_DIMENSION {
            return Err(SpecError::new(
                &source,
                SpecLocation::BasisList,
                SpecErrorKind::TooLarge(super::TooLarge::EveryGrade {
                    n,
                    max: MAX_SIGNATURE_DIMENSION,
                }),
            ));
        }
        let metric = Metric::signature(p, q, r).map_err(|e| {
            SpecError::new(&source, SpecLocation::BasisList, SpecErrorKind::Metric(e))
        })?;
        let n = metric.dim();
        let basis = metric.names().to_vec();
        let order = crate::runtime::blade::canonical_order(n);
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
                    .filter(|&&b| crate::runtime::blade::grade(b) as usize == k)
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
                .filter(|&&b| crate::runtime::blade::grade(b).is_multiple_of(2))
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
        Spec::from_raw(raw, &source)
    }
}
