//! A mesh bound to weighted control points (an FFD lattice, a cage), posed in either form:
//!
//! * positional (the classic FFD and cage deformers): `p_i = sum_j w_ij P_j`, with each
//!   control point moved by its key motor, `P_j = R_j(P_j^rest)`, or given directly
//!   ([`ControlBinding::pose_points`]);
//! * motor-valued (first paper, equations (7)-(8) and section VI):
//!   `M_i = exp(sum_j w_ij log R_j)` applied to the vertex, through [`BoundBlend`].
//!
//! Both are allocation-free and parallel over the vertices, and run the batch loop of
//! `blend/batch.rs` (the positional form's kernel sums the control points over four lanes in
//! the per-vertex order, so it gives the same bits).

use crate::blend::batch::Batches;
use crate::blend::kernels;
use crate::blend::Result;
use crate::blend::{check_key_count, check_positions, KeyError};
use crate::blend::{BlendMethod, BoundBlend, KeyWeights, PreparedKeys};
use crate::mesh::MeshError;
use cga::ScaledMotor;
use glam::DVec3;

/// How control keys deform the mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ControlForm {
    /// `p = sum w P_j` with `P_j` the control points moved by their motors (classic).
    Positional,
    /// The blend of the control motors applied to the vertex (the paper's motor form).
    Motor(BlendMethod),
}

impl Default for ControlForm {
    fn default() -> Self {
        ControlForm::Motor(BlendMethod::MotorLog)
    }
}

impl ControlForm {
    /// `positional` or the blend method's name.
    pub fn name(self) -> &'static str {
        match self {
            ControlForm::Positional => "positional",
            ControlForm::Motor(m) => m.name(),
        }
    }
}

#[derive(Debug, Clone)]
enum Inner {
    /// The weights, and their rows laid out for the batch loop.
    Positional {
        weights: KeyWeights,
        batches: Batches,
    },
    Motor(BoundBlend),
}

/// A mesh bound to control points with per-vertex weights.
#[derive(Debug, Clone)]
pub struct ControlBinding {
    rest: Vec<DVec3>,
    vertices: usize,
    form: ControlForm,
    inner: Inner,
}

impl ControlBinding {
    /// Bind `positions` to the control points `rest` (one weight column per point) in `form`;
    /// rest motors are the identity.
    ///
    /// # Errors
    /// [`MeshError::DimensionMismatch`] when the weights do not match the positions or the
    /// control points, and the errors of [`BoundBlend::bind`].
    pub fn bind(
        positions: &[DVec3],
        rest: Vec<DVec3>,
        weights: KeyWeights,
        form: ControlForm,
    ) -> Result<Self> {
        check_positions(weights.vertex_count(), positions.len())?;
        check_key_count("the control points", weights.key_count(), rest.len())?;
        let inner = match form {
            ControlForm::Positional => Inner::Positional {
                batches: Batches::new(&weights, positions),
                weights,
            },
            ControlForm::Motor(method) => {
                let identity = vec![ScaledMotor::IDENTITY; rest.len()];
                Inner::Motor(BoundBlend::bind(positions, weights, &identity, method)?)
            }
        };
        Ok(ControlBinding {
            rest,
            vertices: positions.len(),
            form,
            inner,
        })
    }

    /// The rest control points.
    pub fn rest_points(&self) -> &[DVec3] {
        &self.rest
    }

    /// The form.
    pub fn form(&self) -> ControlForm {
        self.form
    }

    /// The bound blend of the motor form (`None` in the positional form): what `pose_using`
    /// poses with motor-valued control points, for `deform::gpu::GpuBlend::bind`.
    pub fn motor_blend(&self) -> Option<&BoundBlend> {
        match &self.inner {
            Inner::Positional { .. } => None,
            Inner::Motor(b) => Some(b),
        }
    }

    /// The weights.
    pub fn weights(&self) -> &KeyWeights {
        match &self.inner {
            Inner::Positional { weights, .. } => weights,
            Inner::Motor(b) => b.weights(),
        }
    }

    /// The positional form with control points given directly: `p_i = sum_j w_ij P_j`
    /// (whatever the bound form).
    ///
    /// # Errors
    /// [`MeshError::DimensionMismatch`] for slices of the wrong length,
    /// [`MeshError::InvalidArgument`] for a control point that is not finite;
    /// [`MeshError::Overflow`] for a posed vertex that is not (weights and points whose sum
    /// leaves the `f64` range).
    pub fn pose_points(&self, control: &[DVec3], out: &mut [DVec3]) -> Result<()> {
        check_points(self.rest.len(), control)?;
        check_positions(self.vertices, out.len())?;
        let weights = self.weights();
        let single = |i: usize| {
            weights
                .row(i)
                .fold(DVec3::ZERO, |a, k, w| a + w * control[k])
        };
        let finite = match &self.inner {
            Inner::Positional { batches, .. } if !batches.is_empty() => {
                kernels::run_positional(batches, control, &single, out)
            }
            _ => crate::blend::for_each_vertex(out, single),
        };
        crate::blend::finite_pose(finite, out)
    }
}

/// The per-pose buffers of a [`ControlBinding`]: the prepared keys and the moved control
/// points. Made by [`ControlBinding::scratch`], owned by the caller.
#[derive(Debug, Clone, Default)]
pub struct ControlScratch {
    keys: PreparedKeys,
    moved: Vec<DVec3>,
}

impl ControlBinding {
    /// Number of vertices it poses.
    pub fn vertex_count(&self) -> usize {
        self.vertices
    }

    /// Fresh per-pose buffers.
    pub fn scratch(&self) -> ControlScratch {
        ControlScratch {
            keys: PreparedKeys::default(),
            moved: Vec::with_capacity(self.rest.len()),
        }
    }

    /// Pose with motors at the control points (one per point), using the caller's `scratch`:
    /// no allocation once the scratch has served one pose.
    ///
    /// # Errors
    /// [`KeyError`] for a bad key or a key list of the wrong length,
    /// [`MeshError::DimensionMismatch`] for `positions` of the wrong length.
    pub fn pose_using(
        &self,
        keys: &[ScaledMotor],
        scratch: &mut ControlScratch,
        positions: &mut [DVec3],
    ) -> Result<()> {
        match &self.inner {
            Inner::Motor(b) => b.pose_using(keys, &mut scratch.keys, positions),
            Inner::Positional { .. } => {
                check_positions(self.vertices, positions.len())?;
                move_points(&self.rest, keys, &mut scratch.moved)?;
                self.pose_points(&scratch.moved, positions)
            }
        }
    }
}

/// `moved[j] = keys[j](rest[j])`: the control points moved by their motors (the positional
/// form's pose, on the CPU and the GPU).
///
/// # Errors
/// [`KeyError`] for a key list of the wrong length or a key that is not a finite scaled motor.
pub(crate) fn move_points(
    rest: &[DVec3],
    keys: &[ScaledMotor],
    moved: &mut Vec<DVec3>,
) -> Result<()> {
    check_key_count("this deformer", rest.len(), keys.len())?;
    for (index, k) in keys.iter().enumerate() {
        k.try_log()
            .map_err(|source| KeyError::Invalid { index, source })?;
    }
    moved.clear();
    moved.extend(keys.iter().zip(rest).map(|(k, &p)| k.transform_point(p)));
    Ok(())
}

/// Check control points given directly: one per rest point, each finite.
///
/// # Errors
/// As [`ControlBinding::pose_points`].
pub(crate) fn check_points(rest: usize, control: &[DVec3]) -> Result<()> {
    check_key_count("the control points", rest, control.len())?;
    if let Some(j) = control.iter().position(|p| !p.is_finite()) {
        return Err(MeshError::InvalidArgument(format!("control point {j} is not finite")).into());
    }
    Ok(())
}
