//! Choices with one name per value: the same name on the command line (a flag's value), in the
//! editor's messages and in the command the editor replays. Each is parsed and printed here
//! and nowhere else.

use super::error::MethodError;
use crate::blend::BlendMethod;
use crate::deformers::arap::{ArapEnergy, LocalStep};
use crate::deformers::ffd::LatticeBasis;

/// A choice among a few values, each with one name.
///
/// ```
/// use deform::methods::named::Named;
/// use deform::deformers::arap::LocalStep;
/// assert_eq!(LocalStep::from_name("svd").unwrap(), LocalStep::Svd);
/// assert_eq!(Named::name(LocalStep::Rotor), "rotor");
/// assert!(LocalStep::from_name("SVD").is_err());
/// ```
pub trait Named: Copy + PartialEq + 'static {
    /// Every value, in the order lists show them.
    const ALL: &'static [Self];
    /// What a value is, for messages ("ARAP energy").
    const WHAT: &'static str;

    /// The value's name.
    fn name(self) -> &'static str;

    /// The value named `name` (exactly), or an error that lists every name.
    fn from_name(name: &str) -> Result<Self, MethodError> {
        Self::ALL
            .iter()
            .copied()
            .find(|v| v.name() == name)
            .ok_or_else(|| MethodError::UnknownName {
                what: Self::WHAT,
                given: name.to_string(),
                expected: Self::names().join(", "),
            })
    }

    /// Every name, in [`Named::ALL`]'s order.
    fn names() -> Vec<&'static str> {
        Self::ALL.iter().map(|v| v.name()).collect()
    }
}

impl Named for BlendMethod {
    const ALL: &'static [Self] = &BlendMethod::ALL;
    const WHAT: &'static str = "blend method";
    fn name(self) -> &'static str {
        BlendMethod::name(self)
    }
}

impl Named for ArapEnergy {
    const ALL: &'static [Self] = &[ArapEnergy::Spokes, ArapEnergy::SpokesAndRims];
    const WHAT: &'static str = "ARAP energy";
    fn name(self) -> &'static str {
        ArapEnergy::name(self)
    }
}

impl Named for LocalStep {
    const ALL: &'static [Self] = &[LocalStep::Rotor, LocalStep::Svd];
    const WHAT: &'static str = "ARAP local step";
    fn name(self) -> &'static str {
        LocalStep::name(self)
    }
}

impl Named for LatticeBasis {
    const ALL: &'static [Self] = &[
        LatticeBasis::Bernstein,
        LatticeBasis::BSpline(1),
        LatticeBasis::BSpline(2),
        LatticeBasis::BSpline(3),
    ];
    const WHAT: &'static str = "lattice basis";
    /// `bernstein`, `bspline-1` .. `bspline-3`; a degree outside 1..=3 (which no lattice
    /// binds) is `bspline`.
    fn name(self) -> &'static str {
        match self {
            LatticeBasis::Bernstein => "bernstein",
            LatticeBasis::BSpline(1) => "bspline-1",
            LatticeBasis::BSpline(2) => "bspline-2",
            LatticeBasis::BSpline(3) => "bspline-3",
            LatticeBasis::BSpline(_) => "bspline",
        }
    }
}

/// A cage's coordinates by name (the harmonic grid is its own option).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Coordinates {
    /// Mean value coordinates (Ju, Schaefer and Warren).
    #[default]
    MeanValue,
    /// Harmonic coordinates on a grid (Joshi et al.).
    Harmonic,
}

impl Named for Coordinates {
    const ALL: &'static [Self] = &[Coordinates::MeanValue, Coordinates::Harmonic];
    const WHAT: &'static str = "cage coordinates";
    fn name(self) -> &'static str {
        match self {
            Coordinates::MeanValue => "mean-value",
            Coordinates::Harmonic => "harmonic",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::Method;

    fn round_trip<T: Named + std::fmt::Debug>() {
        for &v in T::ALL {
            assert_eq!(T::from_name(v.name()).unwrap(), v);
        }
        let e = T::from_name("no such name").unwrap_err().to_string();
        for n in T::names() {
            assert!(e.contains(n), "{e}");
        }
    }

    #[test]
    fn every_name_parses_back_and_others_list_the_names() {
        round_trip::<BlendMethod>();
        round_trip::<ArapEnergy>();
        round_trip::<LocalStep>();
        round_trip::<LatticeBasis>();
        round_trip::<Coordinates>();
        round_trip::<Method>();
    }
}
