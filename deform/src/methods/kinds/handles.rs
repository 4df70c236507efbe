//! Motor handles on harmonic coordinates (the first paper's section V): a motor per handle
//! group, blended at each vertex by its harmonic weights.

use crate::blend::{BlendMethod, BoundBlend, PreparedKeys};
use crate::deformers::handles::{HandleOptions, MotorHandles};
use crate::methods::error::MethodsError;
use crate::methods::kind::{BindInput, MethodKind, PoseMethod};
use crate::methods::values::OptionValues;
use cga::ScaledMotor;
use glam::DVec3;

/// The method.
pub struct HandlesMethod;

/// A mesh bound to its handles: the blend kept apart, so another blend method reuses the
/// weights.
struct Bound {
    handles: MotorHandles,
    blend: BoundBlend,
    scratch: PreparedKeys,
}

impl MethodKind for HandlesMethod {
    fn name(&self) -> &'static str {
        "handles"
    }

    /// Its own subcommand, `deform handles`.
    fn command(&self) -> Vec<&'static str> {
        vec![self.name()]
    }

    fn inputs(&self) -> &'static [(&'static str, &'static str)] {
        &[("select", "selection"), ("motors", "motors")]
    }

    fn bind(
        &self,
        input: BindInput<'_>,
        settings: &OptionValues,
    ) -> Result<Box<dyn PoseMethod>, MethodsError> {
        let (mesh, groups) = (input.mesh, input.groups);
        let sets: Vec<&[u32]> = groups.iter().map(Vec::as_slice).collect();
        input
            .budget
            .handle_groups("the selection", sets.len(), mesh.vertex_count())?;
        let rest = vec![ScaledMotor::IDENTITY; sets.len()];
        let options = HandleOptions {
            method: settings.blend,
            ..HandleOptions::default()
        };
        let analysis = input.cache.of(mesh, &options.harmonic)?;
        let handles = MotorHandles::bind_with_analysis(mesh, analysis, &sets, &rest, options)?;
        let blend = handles.blend().clone();
        let scratch = blend.scratch();
        Ok(Box::new(Bound {
            handles,
            blend,
            scratch,
        }))
    }
}

impl PoseMethod for Bound {
    fn key_count(&self) -> usize {
        self.blend.key_count()
    }

    fn reblend(&mut self, positions: &[DVec3], method: BlendMethod) -> Result<bool, MethodsError> {
        let rest = vec![ScaledMotor::IDENTITY; self.blend.key_count()];
        self.blend = BoundBlend::bind(positions, self.blend.weights().clone(), &rest, method)?;
        self.scratch = self.blend.scratch();
        Ok(true)
    }

    fn pose(
        &mut self,
        motors: &[ScaledMotor],
        out: &mut [DVec3],
    ) -> Result<Option<f64>, MethodsError> {
        self.blend.pose_using(motors, &mut self.scratch, out)?;
        Ok(None)
    }

    fn fields(&self) -> &'static [&'static str] {
        &["harmonic"]
    }

    fn field(&self, name: &str, group: usize) -> Option<Vec<f64>> {
        let n = self.blend.vertex_count();
        let j = group.min(self.key_count().saturating_sub(1));
        (name == "harmonic").then(|| (0..n).map(|i| self.handles.coordinate(i, j)).collect())
    }
}
