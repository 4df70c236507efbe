//! Posing on the GPU through wgpu (the `gpu` feature): the same blends as [`crate::blend`],
//! as compute passes over buffers uploaded once at bind, in `f32`.
//!
//! **May use**: the mesh foundation and blending. The shader (`skin.wgsl`) is
//! written once against the WGSL that the generator makes from `algebras/cga.toml`
//! ([`cga::f32::WGSL`]): motor blending calls the generated `motor_sandwich_point`.
//!
//! Every [`BlendMethod`](crate::BlendMethod) has a GPU form: log blending (the generated
//! closed-form `exp` in WGSL), motor blending, dual quaternions, matrix LBS (f64 and f32
//! keys), equation (17) both ways.
//!
//! ```no_run
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! use deform::gpu::{GpuBlend, GpuContext};
//! let ctx = GpuContext::new()?; // GpuError::NoAdapter without a GPU or a software driver
//! # let blend: deform::blend::BoundBlend = unimplemented!();
//! # let keys: Vec<cga::ScaledMotor> = vec![];
//! let gpu = GpuBlend::bind(&ctx, &blend)?;
//! let mut out = vec![glam::DVec3::ZERO; blend.vertex_count()];
//! gpu.pose(&ctx, &keys, &mut out)?;
//! # Ok(())
//! # }
//! ```

mod blend;
mod context;

pub use blend::GpuBlend;
pub use context::GpuContext;

/// Why the GPU cannot pose.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// No adapter (no GPU and no software driver such as Mesa's lavapipe).
    #[error("no GPU adapter: {0}")]
    NoAdapter(String),
    /// The adapter refused a device.
    #[error("the GPU adapter refused a device: {0}")]
    Device(String),
    /// The keys are invalid, or the pose does not fit the bound mesh.
    #[error(transparent)]
    Blend(#[from] crate::blend::BlendError),
    /// More vertices, weights or keys than one GPU buffer holds.
    #[error("too large for the GPU: {0}")]
    TooLarge(String),
    /// Reading the result back failed.
    #[error("reading back from the GPU failed: {0}")]
    Readback(String),
}
