//! A motor per vertex of a closed cage around the mesh, by mean value or harmonic
//! coordinates.

use crate::deformers::cage::{CageCoordinates, CageDeformer, CageOptions, HarmonicGrid};
use crate::methods::error::{MethodError, MethodsError};
use crate::methods::kind::ControlPoints;
use crate::methods::kind::{BindInput, MethodKind, PoseMethod};
use crate::methods::kinds::control::ControlBound;
use crate::methods::named::Coordinates;
use crate::methods::option::{OptionKind, OptionSpec, OptionValue};
use crate::methods::values::OptionValues;

/// The cage's coordinates.
pub const COORDINATES: OptionSpec = OptionSpec {
    name: "coordinates",
    help: "The cage's coordinates: mean value or harmonic.",
    kind: OptionKind::choice::<Coordinates>(),
    default: OptionValue::Name("mean-value"),
    replay: None,
};
/// Harmonic coordinates' grid nodes along the cage's longest side (the editor's limits: 16
/// to 64).
pub const GRID: OptionSpec = OptionSpec {
    name: "grid",
    help: "Grid nodes along the cage's longest side (harmonic coordinates).",
    kind: OptionKind::Number(16..=64),
    default: OptionValue::Number(32),
    replay: None,
};

/// The method.
pub struct CageMethod;

/// The cage coordinates `settings` name.
fn cage_coordinates(settings: &OptionValues) -> CageCoordinates {
    match settings.choice(&COORDINATES) {
        Coordinates::MeanValue => CageCoordinates::MeanValue,
        Coordinates::Harmonic => CageCoordinates::Harmonic(HarmonicGrid {
            resolution: settings.number(&GRID),
        }),
    }
}

impl MethodKind for CageMethod {
    fn name(&self) -> &'static str {
        "cage"
    }

    fn groups_needed(&self) -> usize {
        0
    }

    /// Its own subcommand, `deform cage`.
    fn command(&self) -> Vec<&'static str> {
        vec![self.name()]
    }

    fn inputs(&self) -> &'static [(&'static str, &'static str)] {
        &[("cage", "cage"), ("motors", "motors")]
    }

    fn controls(&self) -> bool {
        true
    }

    fn options(&self) -> &'static [OptionSpec] {
        &[COORDINATES, GRID]
    }

    fn bind(
        &self,
        input: BindInput<'_>,
        settings: &OptionValues,
    ) -> Result<Box<dyn PoseMethod>, MethodsError> {
        let cage = input.cage.ok_or(MethodError::NoCage)?;
        let options = CageOptions {
            form: settings.form(),
            coordinates: cage_coordinates(settings),
            ..CageOptions::default()
        };
        let deformer = CageDeformer::bind(input.mesh, cage, options)?;
        let controls = ControlPoints {
            points: cage.positions.clone(),
            edges: cage.edges().edges,
        };
        Ok(Box::new(ControlBound::new(deformer, controls)))
    }
}
