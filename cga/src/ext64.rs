//! The hand-written extensions for the `f64` types: precision aliases, then the shared files.

pub(crate) use crate::error::{CgaError, Result};
pub(crate) use crate::f64::*;
pub(crate) type S = f64;
pub(crate) type V3 = glam::DVec3;
pub(crate) type Vec4 = glam::DVec4;
pub(crate) type Quat = glam::DQuat;
pub(crate) type Mat3 = glam::DMat3;
pub(crate) type Mat4 = glam::DMat4;
pub(crate) use quat_map::{dual_coeffs, dual_quat, rotor_coeffs, rotor_quat};
pub(crate) use validity::{
    all_finite, finite3, finite_input, finite_result, max_abs, precise_scale, try_unit_direction,
    unit_direction,
};
pub(crate) type Affine = glam::DAffine3;
/// Relative tolerance of validity checks (versor condition, degeneracy).
pub(crate) const TOL: S = 1e-9;
/// Absolute tolerance on `R^T R - I` and on the last row of a rigid matrix.
pub(crate) const TOL_MATRIX: S = 1e-9;
/// Relative tolerance of the versor condition of motors (accepts accumulated drift, rejects
/// non-versors).
pub(crate) const TOL_VERSOR: S = 1e-6;

#[path = "dual_quat.rs"]
pub(crate) mod dual_quat;
#[path = "exp_log.rs"]
pub(crate) mod exp_log;
#[path = "glam_interop.rs"]
mod glam_interop;
#[path = "interpolate.rs"]
mod interpolate;
#[path = "motor.rs"]
pub(crate) mod motor;
#[path = "objects/mod.rs"]
pub(crate) mod objects;
#[path = "point.rs"]
mod point;
#[path = "quat_map.rs"]
mod quat_map;
#[path = "rotor.rs"]
mod rotor;
#[path = "scaled.rs"]
pub(crate) mod scaled;
#[path = "validity.rs"]
mod validity;
