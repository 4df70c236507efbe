//! Typed errors of the fallible (`try_`) constructors and conversions.

use thiserror::Error;

/// What went wrong in a fallible constructor, conversion or logarithm.
///
/// Every `try_` function of this crate returns one of these instead of panicking or producing
/// NaNs: it returns `Ok` only when its result is finite and valid (the result is checked, not
/// only the input). The infallible twins document which inputs they assume.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
pub enum CgaError {
    /// An input coordinate, angle, scale or coefficient was NaN or infinite.
    #[error("non-finite input: {what}")]
    NonFinite {
        /// Which input.
        what: &'static str,
    },
    /// A rotation axis (or plane normal, or line direction) of zero length.
    #[error("zero-length {what}")]
    ZeroAxis {
        /// Which input.
        what: &'static str,
    },
    /// A scale factor that is zero or negative (a dilator scales by `d > 0`).
    #[error("scale must be positive and finite")]
    NonPositiveScale,
    /// The value is not a (scaled) motor: zero rotor part, or not a versor of the expected kind.
    #[error("not a {what}: {why}")]
    NotAMotor {
        /// The kind expected (`motor`, `scaled motor`, ...).
        what: &'static str,
        /// Why it was rejected.
        why: &'static str,
    },
    /// A matrix or transform that is not a rigid motion (it scales, shears, reflects or
    /// projects).
    #[error("not a rigid transform: {why}")]
    NotRigid {
        /// Why it was rejected.
        why: &'static str,
    },
    /// A bivector that is not a generator of the expected kind (for example it has `eo^ek`
    /// parts, which generate transversions, not rigid motions).
    #[error("not a {what} generator: {why}")]
    NotAGenerator {
        /// The kind expected.
        what: &'static str,
        /// Why it was rejected.
        why: &'static str,
    },
    /// Geometrically degenerate input: coincident or collinear points, parallel elements.
    #[error("degenerate input: {why}")]
    Degenerate {
        /// Why it was rejected.
        why: &'static str,
    },
    /// Finite input whose result overflowed, underflowed to nothing or lost every significant
    /// digit (for example a point at `1e300`, whose `0.5 |x|^2` is infinite, or a dilator by
    /// `1e300`, whose scale cannot be recovered). The input is valid in principle but outside
    /// the range this representation can hold.
    #[error("result not representable: {what}")]
    Overflow {
        /// Which result.
        what: &'static str,
    },
    /// Weights and motors of different lengths, or no motor at all.
    #[error("blend: {why}")]
    BadBlend {
        /// Why it was rejected.
        why: &'static str,
    },
}

/// `Result` with [`CgaError`].
pub type Result<T> = core::result::Result<T, CgaError>;
