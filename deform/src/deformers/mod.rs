//! The deformers of the two papers, each "bind once, pose many times":
//!
//! * [`spline`]: spline-aligned deformation with motor keys along a curve ([`bspline`] fits
//!   and evaluates the B-spline of motors), [`fabrik`] drives it by an inverse-kinematics
//!   chain;
//! * [`handles`]: motor handles blended with harmonic coordinates;
//! * [`arap`]: as-rigid-as-possible deformation with rotors;
//! * [`ffd`]: free-form deformation lattices;
//! * [`cage`]: mean-value and harmonic cage coordinates.
//!
//! **May use**: the mesh foundation, the operators and the blend core. **Must not use**:
//! skinning, surgery, render, input, or the crate-level `Error`.

pub mod arap;
pub mod bspline;
pub mod cage;
pub(crate) mod deformer;
mod error;
pub mod fabrik;
pub mod ffd;
pub mod handles;
pub mod spline;

pub use deformer::{Deformer, Poser};
pub use error::{DeformError, Result};
