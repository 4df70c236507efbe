//! Phase 2: the specialised types (names, blades, constants) and, up to
//! [`MAX_GENERAL_DIMENSION`] basis vectors, the general multivector.

use super::error::{SpecError, SpecErrorKind, SpecLocation};
use super::names::{check_type_name, GENERAL_NAME_TAKEN};
use super::{Field, RawType, TypeDef, GENERAL_TYPE, MAX_GENERAL_DIMENSION};
use crate::runtime::blade::{blade_name, canonical_order, parse_blade, Bitmap, BladeNameError};
use crate::runtime::metric::Metric;
use crate::runtime::rational::Rational;

/// Validate every declared type, in order, and add the general multivector when no type
/// holds every blade and the algebra has at most [`MAX_GENERAL_DIMENSION`] basis vectors.
pub(super) fn read(
    raw: &[RawType],
    metric: &Metric,
    source: &str,
) -> Result<Vec<TypeDef>, SpecError> {
    let mut types: Vec<TypeDef> = Vec::with_capacity(raw.len() + 1);
    for (ti, rt) in raw.iter().enumerate() {
        let err = |loc, kind| SpecError::new(source, loc, kind).in_type(&rt.name);
        check_type_name(&rt.name).map_err(|k| err(SpecLocation::TypeName(ti), k))?;
        if types.iter().any(|t| t.name == rt.name) {
            return Err(err(
                SpecLocation::TypeName(ti),
                SpecErrorKind::DuplicateType,
            ));
        }
        types.push(read_type(ti, rt, metric.names(), source)?);
    }
    if metric.dim() > MAX_GENERAL_DIMENSION {
        // Only the declared types: results that none holds are not emitted.
        if types.is_empty() {
            let (n, max) = (metric.dim(), MAX_GENERAL_DIMENSION);
            let kind = SpecErrorKind::NoTypes { n, max };
            return Err(SpecError::new(source, SpecLocation::Spec, kind));
        }
        return Ok(types);
    }
    let size = 1usize << metric.dim();
    let has_general = types
        .iter()
        .any(|t| t.constants.is_empty() && t.fields.len() == size);
    if !has_general {
        if let Some(ti) = types.iter().position(|t| t.name == GENERAL_TYPE) {
            return Err(SpecError::new(
                source,
                SpecLocation::TypeName(ti),
                SpecErrorKind::ReservedTypeName(GENERAL_NAME_TAKEN),
            )
            .in_type(GENERAL_TYPE));
        }
        types.push(general(metric, source)?);
    }
    Ok(types)
}

/// One declared type.
fn read_type(
    ti: usize,
    rt: &RawType,
    basis: &[String],
    source: &str,
) -> Result<TypeDef, SpecError> {
    let err = |loc, kind, name: &str| {
        SpecError::new(source, loc, kind)
            .in_type(&rt.name)
            .at_blade(name)
    };
    let mut fields: Vec<Field> = Vec::new();
    let mut constants = Vec::new();
    let mut seen: Vec<Bitmap> = Vec::new();
    for (bi, bname) in rt.blades.iter().enumerate() {
        let at = SpecLocation::TypeBlade { ty: ti, blade: bi };
        let (bitmap, sign) = parse_blade(bname, basis).map_err(|e| {
            let kind = match e {
                BladeNameError::Unknown => SpecErrorKind::UnknownBlade,
                BladeNameError::Ambiguous => SpecErrorKind::AmbiguousBlade,
                BladeNameError::Repeated => SpecErrorKind::RepeatedBasis,
            };
            err(at.clone(), kind, bname)
        })?;
        if seen.contains(&bitmap) {
            return Err(err(at, SpecErrorKind::DuplicateBlade, bname));
        }
        seen.push(bitmap);
        if let Some(&c) = rt.constants.get(bname) {
            let value = SpecLocation::ConstantValue {
                ty: ti,
                key: bname.clone(),
            };
            let c = Rational::from_f64(c)
                .ok_or_else(|| err(value, SpecErrorKind::BadConstant, bname))?;
            constants.push((bitmap, if sign < 0 { -c } else { c }));
        } else {
            let name = if bitmap == 0 {
                "s".to_string()
            } else {
                bname.clone()
            };
            if crate::runtime::ident::is_keyword(&name) {
                return Err(err(at, SpecErrorKind::KeywordBlade, bname));
            }
            fields.push(Field { name, bitmap, sign });
        }
    }
    if let Some(key) = rt.constants.keys().find(|k| !rt.blades.contains(k)) {
        let at = SpecLocation::ConstantKey {
            ty: ti,
            key: key.clone(),
        };
        return Err(err(at, SpecErrorKind::ConstantNotInType, key));
    }
    if fields.is_empty() {
        return Err(
            SpecError::new(source, SpecLocation::TypeName(ti), SpecErrorKind::EmptyType)
                .in_type(&rt.name),
        );
    }
    Ok(TypeDef {
        name: rt.name.clone(),
        doc: rt.doc.clone(),
        fields,
        constants,
        versor: rt.versor,
        unit: rt.unit,
    })
}

/// The general multivector: every blade, by canonical name. Its field names concatenate
/// basis suffixes, so a basis such as `en`, `um` would name a field `enum`: refused.
fn general(metric: &Metric, source: &str) -> Result<TypeDef, SpecError> {
    let basis = metric.names();
    let mut fields = Vec::with_capacity(1 << basis.len());
    for b in canonical_order(metric.dim()) {
        let name = blade_name(b, basis);
        if crate::runtime::ident::is_keyword(&name) {
            return Err(SpecError::new(
                source,
                SpecLocation::BasisList,
                SpecErrorKind::KeywordBlade,
            )
            .in_type(GENERAL_TYPE)
            .at_blade(&name));
        }
        fields.push(Field {
            name,
            bitmap: b,
            sign: 1,
        });
    }
    Ok(TypeDef {
        name: GENERAL_TYPE.to_string(),
        doc: Some("The general multivector: every blade of the algebra.".to_string()),
        fields,
        constants: Vec::new(),
        versor: false,
        unit: false,
    })
}
