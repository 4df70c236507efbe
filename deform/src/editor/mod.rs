//! The editor's model: one editing session per connection (the scene, its handle groups, the
//! bound method and the latest pose, or a rig with its joint edits and surgery, with undo),
//! driven by requests and answering with replies and binary frames ([`protocol`]). No I/O
//! here: the `deform view` server and a library caller drive a [`Session`] the same way, and
//! every method, option and name comes from the methods layer.
//!
//! **May use**: every layer below. Nothing below may use it.

pub mod error;
pub mod protocol;
mod rig_edit;
mod session;

pub use error::{EditError, Result};
pub use session::{Out, Session, MAX_UPLOAD};

/// Milliseconds since `t`.
fn ms(t: std::time::Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}
