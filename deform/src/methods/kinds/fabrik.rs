//! B-spline + FABRIK (the first paper's Fig. 5): a straight chain of joints from the first
//! handle group's centre to the last's; the last group's motor moves the chain's end
//! effector, FABRIK solves the chain, a cubic B-spline of control motors is fitted to its
//! joint frames and poses the mesh by spline-aligned deformation. The root stays; the motors
//! of the groups before the last are not used.

use crate::deformers::fabrik::{straight_chain, ChainDeformer, ChainScratch, FabrikOptions};
use crate::deformers::spline::SplineOptions;
use crate::methods::error::{MethodError, MethodsError};
use crate::methods::harmonic_cache::group_centres;
use crate::methods::kind::{BindInput, MethodKind, PoseMethod};
use crate::methods::option::{OptionKind, OptionSpec, OptionValue};
use crate::methods::values::OptionValues;
use cga::ScaledMotor;
use glam::DVec3;

/// Joints of the chain.
pub const JOINTS: OptionSpec = OptionSpec {
    name: "joints",
    help: "Joints of the straight chain from the first group's centre to the last's.",
    kind: OptionKind::Number(2..=32),
    default: OptionValue::Number(6),
    replay: None,
};
/// Control motors of the fitted B-spline.
pub const CONTROLS: OptionSpec = OptionSpec {
    name: "controls",
    help: "Control motors of the B-spline fitted to the chain's joint frames (at most the \
           joints).",
    kind: OptionKind::Number(2..=32),
    default: OptionValue::Number(4),
    replay: None,
};

/// The method.
pub struct FabrikMethod;

/// A mesh bound to its chain.
struct Bound {
    chain: ChainDeformer,
    /// The pose's working memory (a warm pose allocates nothing).
    scratch: ChainScratch,
    /// The end effector at rest (the last group's centre).
    tip: DVec3,
    groups: usize,
}

impl MethodKind for FabrikMethod {
    fn name(&self) -> &'static str {
        "fabrik"
    }

    fn groups_needed(&self) -> usize {
        2
    }

    fn inputs(&self) -> &'static [(&'static str, &'static str)] {
        &[("select", "selection"), ("motors", "motors")]
    }

    fn options(&self) -> &'static [OptionSpec] {
        &[JOINTS, CONTROLS]
    }

    fn check(&self, settings: &OptionValues) -> Result<(), MethodError> {
        let (joints, controls) = (settings.number(&JOINTS), settings.number(&CONTROLS));
        if controls > joints {
            return Err(MethodError::OutOfRange {
                option: CONTROLS.name,
                value: controls.to_string(),
                range: format!("2..={joints} (the joints)"),
            });
        }
        Ok(())
    }

    fn bind(
        &self,
        input: BindInput<'_>,
        settings: &OptionValues,
    ) -> Result<Box<dyn PoseMethod>, MethodsError> {
        let (mesh, groups) = (input.mesh, input.groups);
        let (root, tip) = (&groups[0], &groups[groups.len() - 1]);
        let joints = straight_chain(mesh, root, tip, settings.number(&JOINTS));
        let options = SplineOptions {
            method: settings.blend,
            ..SplineOptions::default()
        };
        let controls = settings.number(&CONTROLS);
        let chain = ChainDeformer::bind(mesh, root, tip, &joints, controls, options)?;
        Ok(Box::new(Bound {
            scratch: chain.chain_scratch(),
            chain,
            tip: group_centres(mesh, std::slice::from_ref(tip))[0],
            groups: groups.len(),
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
        let Some(last) = motors
            .get(self.groups - 1)
            .filter(|_| motors.len() == self.groups)
        else {
            let (given, expected) = (motors.len(), self.groups);
            let keys = "groups";
            return Err(MethodError::KeyCount {
                given,
                expected,
                keys,
            }
            .into());
        };
        let target = last.transform_point(self.tip);
        let options = FabrikOptions::default();
        self.chain
            .pose_to_target_using(target, &options, &mut self.scratch, out)?;
        Ok(None)
    }

    fn fields(&self) -> &'static [&'static str] {
        &["lambda"]
    }

    fn field(&self, name: &str, _group: usize) -> Option<Vec<f64>> {
        (name == "lambda").then(|| self.chain.spline().lambda().to_vec())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes::{tube, tube_ring};
    use crate::methods::budget::WorkBudget;
    use crate::methods::harmonic_cache::HarmonicCache;

    #[test]
    fn a_pose_with_too_few_motors_is_an_error_and_the_tip_group_moves_the_end() {
        let bar = tube(1.0, 10.0, 8, 21);
        let groups = vec![tube_ring(8, 0), tube_ring(8, 20)];
        let input = BindInput {
            mesh: &bar,
            groups: &groups,
            cage: None,
            budget: &WorkBudget::default(),
            cache: &mut HarmonicCache::default(),
        };
        let mut bound = FabrikMethod.bind(input, &OptionValues::default()).unwrap();
        let mut out = bar.positions.clone();
        assert!(bound.pose(&[ScaledMotor::IDENTITY], &mut out).is_err());
        let up = cga::Motor::from_translation(DVec3::new(0.0, 2.0, 0.0));
        let motors = [ScaledMotor::IDENTITY, ScaledMotor::from_motor(up)];
        bound.pose(&motors, &mut out).unwrap();
        // The root ring turns with the chain's first joint about its centre, which stays.
        let posed = crate::mesh::Mesh::new(out, bar.triangles.clone());
        let centres = |m| group_centres(m, &groups);
        let (rest, now) = (centres(&bar), centres(&posed));
        assert!(
            (now[0] - rest[0]).length() < 1e-6,
            "the root stays: {}",
            now[0] - rest[0]
        );
        assert!(now[1].y - rest[1].y > 1.0, "the tip follows its motor");
    }
}
