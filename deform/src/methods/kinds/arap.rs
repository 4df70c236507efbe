//! ARAP with rotors, the handle groups as its handles: each pose runs a few iterations from
//! the last pose and returns the energy.

use crate::deformers::arap::{
    Arap, ArapEnergy, ArapOptions, ArapScratch, LocalStep, Stop, Targets,
};
use crate::methods::error::MethodsError;
use crate::methods::kind::{BindInput, MethodKind, PoseMethod};
use crate::methods::option::{OptionKind, OptionSpec, OptionValue};
use crate::methods::values::OptionValues;
use cga::ScaledMotor;
use glam::DVec3;

/// ARAP iterations per pose (the editor runs them from the last pose, once per frame); the
/// replayed command, which runs from the rest pose, asks for 1000 (ARAP's energy flattens long
/// before its positions settle).
pub const ITERATIONS: OptionSpec = OptionSpec {
    name: "iterations",
    help: "ARAP iterations (local and global steps).",
    kind: OptionKind::Number(1..=50),
    default: OptionValue::Number(2),
    replay: Some(OptionValue::Number(1000)),
};
/// ARAP's rigidity energy.
pub const ENERGY: OptionSpec = OptionSpec {
    name: "energy",
    help: "The rigidity energy: each cell a vertex's spokes (the paper's) or its triangles' \
           spokes and rims (libigl's default).",
    kind: OptionKind::choice::<ArapEnergy>(),
    default: OptionValue::Name("spokes-and-rims"),
    replay: None,
};
/// ARAP's local fit.
pub const LOCAL_STEP: OptionSpec = OptionSpec {
    name: "local-step",
    help: "The local fit: the paper's rotor or Sorkine and Alexa's SVD.",
    kind: OptionKind::choice::<LocalStep>(),
    default: OptionValue::Name("rotor"),
    replay: None,
};

/// The method.
pub struct ArapMethod;

/// ARAP options as `settings` name them (the solver and cotangents at their defaults).
fn arap_options(settings: &OptionValues) -> ArapOptions {
    ArapOptions {
        energy: settings.choice(&ENERGY),
        local_step: settings.choice(&LOCAL_STEP),
        ..ArapOptions::default()
    }
}

/// A mesh bound to ARAP; the scratch keeps the last pose, where the next starts.
struct Bound {
    arap: Arap,
    scratch: ArapScratch,
    iterations: usize,
    groups: usize,
}

impl MethodKind for ArapMethod {
    fn name(&self) -> &'static str {
        "arap"
    }

    /// Its own subcommand, `deform arap`.
    fn command(&self) -> Vec<&'static str> {
        vec![self.name()]
    }

    fn inputs(&self) -> &'static [(&'static str, &'static str)] {
        &[("select", "selection"), ("motors", "motors")]
    }

    fn blends(&self) -> bool {
        false
    }

    fn options(&self) -> &'static [OptionSpec] {
        &[ITERATIONS, ENERGY, LOCAL_STEP]
    }

    fn bind(
        &self,
        input: BindInput<'_>,
        settings: &OptionValues,
    ) -> Result<Box<dyn PoseMethod>, MethodsError> {
        let sets: Vec<&[u32]> = input.groups.iter().map(Vec::as_slice).collect();
        let arap = Arap::bind(input.mesh, &[], &sets, arap_options(settings))?;
        let scratch = arap.scratch()?;
        Ok(Box::new(Bound {
            arap,
            scratch,
            iterations: settings.number(&ITERATIONS),
            groups: sets.len(),
        }))
    }
}

impl PoseMethod for Bound {
    fn key_count(&self) -> usize {
        self.groups
    }

    fn pose(
        &mut self,
        motors: &[ScaledMotor],
        out: &mut [DVec3],
    ) -> Result<Option<f64>, MethodsError> {
        let mut last = f64::NAN;
        self.arap.pose_using(
            &Targets::Motors(motors),
            Stop::Iterations(self.iterations),
            &mut self.scratch,
            out,
            |_, e| last = e,
        )?;
        Ok(Some(last))
    }
}
