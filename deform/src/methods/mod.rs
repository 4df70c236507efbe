//! The methods layer: what the `deform` program, its editor and a library caller share above
//! the deformers, skinning and surgery:
//! - [`method`]: the methods ([`Method`]) a mesh is posed by, and [`MethodError`];
//! - [`named`]: every choice's names ([`named::Named`]), parsed and printed in one place;
//! - [`kind`]: what a method is ([`MethodKind`]: its description and bind) and a mesh bound
//!   by it ([`PoseMethod`]); [`kinds`]: one file per method;
//! - [`option`]: an option described once ([`option::OptionSpec`]: name, help, values,
//!   default) for the program's flags, the editor's panel and the replayed command;
//! - [`values`]: the blend, the positional form and every option's value, what a method's
//!   file reads; [`settings`]: a method with them ([`MethodSettings`]), every value checked;
//! - [`harmonic_cache`]: the harmonic analysis kept between binds;
//! - [`bound`]: a mesh bound by its settings ([`BoundMethod`]), posed from a motor per key;
//! - [`frame`]: which pose of a rig a request means, and the posed frame of a surgery tool;
//! - [`scenes`]: the procedural scenes the demo and the editor open;
//! - [`showcase`]: every method of both papers posed on them, as the demo writes them;
//! - [`budget`]: the work budget that refuses oversized requests before anything is
//!   allocated.
//!
//! **May use**: every layer below (mesh, operators, blend, deformers, skinning, surgery,
//! render, input). Nothing below may use it.

pub mod bound;
pub mod budget;
mod error;
pub mod frame;
pub mod harmonic_cache;
pub mod kind;
pub mod kinds;
pub mod method;
pub mod named;
pub mod option;
pub mod scenes;
pub mod settings;
pub mod showcase;
pub mod values;

pub use bound::BoundMethod;
pub use error::{MethodError, MethodsError};
pub use kind::{BindInput, MethodKind, PoseMethod};
pub use method::Method;
pub use settings::MethodSettings;
