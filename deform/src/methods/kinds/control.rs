//! Lattices and cages bound as a [`PoseMethod`]: one motor per control point.

use crate::blend::control::ControlScratch;
use crate::deformers::Deformer;
use crate::methods::error::MethodsError;
use crate::methods::kind::{ControlPoints, PoseMethod};
use cga::ScaledMotor;
use glam::DVec3;

/// A lattice or cage bound as a [`PoseMethod`]: one motor per control point.
pub struct ControlBound<D: Deformer<Scratch = ControlScratch>> {
    deformer: D,
    controls: ControlPoints,
    scratch: ControlScratch,
}

impl<D: Deformer<Scratch = ControlScratch>> ControlBound<D> {
    /// `deformer` with its control points (its scratch made here).
    pub fn new(deformer: D, controls: ControlPoints) -> Self {
        let scratch = deformer.scratch();
        ControlBound {
            deformer,
            controls,
            scratch,
        }
    }
}

impl<D: Deformer<Scratch = ControlScratch> + 'static> PoseMethod for ControlBound<D> {
    fn key_count(&self) -> usize {
        self.controls.points.len()
    }

    fn controls(&self) -> Option<&ControlPoints> {
        Some(&self.controls)
    }

    fn pose(
        &mut self,
        motors: &[ScaledMotor],
        out: &mut [DVec3],
    ) -> Result<Option<f64>, MethodsError> {
        self.deformer.pose_using(motors, &mut self.scratch, out)?;
        Ok(None)
    }
}
