//! Spline-aligned deformation: the handle groups are its keys, a translation to each group's
//! centre at rest; the first and last group bound the spine.

use crate::blend::PreparedKeys;
use crate::deformers::spline::{SplineDeformer, SplineOptions};
use crate::deformers::Deformer;
use crate::methods::error::MethodsError;
use crate::methods::harmonic_cache::group_centres;
use crate::methods::kind::{BindInput, MethodKind, PoseMethod};
use crate::methods::values::OptionValues;
use cga::{Motor, ScaledMotor};
use glam::DVec3;

/// The method.
pub struct SplineMethod;

/// A mesh bound to its spline.
struct Bound {
    spline: SplineDeformer,
    /// The rest keys: a pose's motor follows each.
    rest: Vec<ScaledMotor>,
    scratch: PreparedKeys,
    /// The posed keys (each motor after its rest key), kept between poses.
    keys: Vec<ScaledMotor>,
}

impl MethodKind for SplineMethod {
    fn name(&self) -> &'static str {
        "spline"
    }

    fn groups_needed(&self) -> usize {
        2
    }

    /// Its own subcommand, `deform spline`.
    fn command(&self) -> Vec<&'static str> {
        vec![self.name()]
    }

    fn inputs(&self) -> &'static [(&'static str, &'static str)] {
        &[
            ("select", "selection"),
            ("keys", "keys"),
            ("rest-keys", "rest-keys"),
        ]
    }

    fn bind(
        &self,
        input: BindInput<'_>,
        settings: &OptionValues,
    ) -> Result<Box<dyn PoseMethod>, MethodsError> {
        let (mesh, groups) = (input.mesh, input.groups);
        let rest: Vec<ScaledMotor> = group_centres(mesh, groups)
            .into_iter()
            .map(|c| ScaledMotor::from_motor(Motor::from_translation(c)))
            .collect();
        let options = SplineOptions {
            method: settings.blend,
            ..SplineOptions::default()
        };
        let (first, last) = (&groups[0], &groups[groups.len() - 1]);
        let spline = SplineDeformer::bind(mesh, first, last, &rest, options)?;
        let scratch = spline.scratch();
        Ok(Box::new(Bound {
            spline,
            keys: Vec::with_capacity(rest.len()),
            rest,
            scratch,
        }))
    }
}

impl PoseMethod for Bound {
    fn key_count(&self) -> usize {
        self.rest.len()
    }

    fn pose(
        &mut self,
        motors: &[ScaledMotor],
        out: &mut [DVec3],
    ) -> Result<Option<f64>, MethodsError> {
        self.keys.clear();
        let posed = self.rest.iter().zip(motors).map(|(r, m)| r.then(*m));
        self.keys.extend(posed);
        self.spline.pose_using(&self.keys, &mut self.scratch, out)?;
        Ok(None)
    }

    fn fields(&self) -> &'static [&'static str] {
        &["lambda"]
    }

    fn field(&self, name: &str, _group: usize) -> Option<Vec<f64>> {
        (name == "lambda").then(|| self.spline.lambda().to_vec())
    }
}
