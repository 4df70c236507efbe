//! Free-form deformation: a motor per point of a lattice over the mesh's box.

use crate::deformers::ffd::{Ffd, FfdOptions, LatticeBasis};
use crate::methods::error::{MethodError, MethodsError};
use crate::methods::kind::ControlPoints;
use crate::methods::kind::{BindInput, MethodKind, PoseMethod};
use crate::methods::kinds::control::ControlBound;
use crate::methods::option::{OptionKind, OptionSpec, OptionValue};
use crate::methods::values::OptionValues;

/// Control points per axis of the lattice (the editor's limits: 2 to 8).
pub const LATTICE: OptionSpec = OptionSpec {
    name: "lattice",
    help: "Control points per axis: LxMxN (each at least 2).",
    kind: OptionKind::Dims(2..=8),
    default: OptionValue::Dims([4, 3, 3]),
    replay: None,
};
/// The lattice's basis.
pub const BASIS: OptionSpec = OptionSpec {
    name: "basis",
    help: "The lattice's basis: Bernstein polynomials of degree L-1, M-1, N-1, or clamped \
           uniform B-splines of degree 1 to 3.",
    kind: OptionKind::choice::<LatticeBasis>(),
    default: OptionValue::Name("bernstein"),
    replay: None,
};
/// At most this many control points in a Bernstein lattice, where every point moves every
/// vertex (B-splines blend at most `(degree + 1)^3` per vertex).
pub const MAX_BERNSTEIN_POINTS: usize = 64;

/// The method.
pub struct FfdMethod;

impl MethodKind for FfdMethod {
    fn name(&self) -> &'static str {
        "ffd"
    }

    fn groups_needed(&self) -> usize {
        0
    }

    /// Its own subcommand, `deform ffd`.
    fn command(&self) -> Vec<&'static str> {
        vec![self.name()]
    }

    fn inputs(&self) -> &'static [(&'static str, &'static str)] {
        &[("motors", "motors")]
    }

    fn controls(&self) -> bool {
        true
    }

    fn options(&self) -> &'static [OptionSpec] {
        &[LATTICE, BASIS]
    }

    fn check(&self, settings: &OptionValues) -> Result<(), MethodError> {
        let dims = settings.dims(&LATTICE);
        let points: usize = dims.iter().product();
        let basis: LatticeBasis = settings.choice(&BASIS);
        if basis == LatticeBasis::Bernstein && points > MAX_BERNSTEIN_POINTS {
            return Err(MethodError::BernsteinTooLarge {
                dims,
                points,
                max: MAX_BERNSTEIN_POINTS,
            });
        }
        Ok(())
    }

    fn bind(
        &self,
        input: BindInput<'_>,
        settings: &OptionValues,
    ) -> Result<Box<dyn PoseMethod>, MethodsError> {
        let options = FfdOptions {
            form: settings.form(),
            basis: settings.choice(&BASIS),
        };
        let ffd = Ffd::bind(input.mesh, settings.dims(&LATTICE), None, options)?;
        let controls = ControlPoints {
            points: ffd.lattice().rest_points(),
            edges: ffd.lattice().edges(),
        };
        Ok(Box::new(ControlBound::new(ffd, controls)))
    }
}
