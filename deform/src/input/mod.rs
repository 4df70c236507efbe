//! What the `deform` program reads besides meshes: key motors in JSON ([`parse_motor`],
//! [`parse_key_list`], [`parse_group_motors`]) and handle selections ([`Selection`]). One
//! format for every subcommand.
//!
//! **May use**: the mesh foundation (selection files in DMAT). **Must not use**: any other
//! layer or the crate-level `Error`; its error is [`InputError`].

mod files;
mod json;
mod motors;
mod selection;

pub use files::{read_document, read_selection, MAX_DOCUMENT_BYTES};
pub use motors::{parse_group_motors, parse_key_list, parse_motor, MotorSpec, RotateSpec};
pub use selection::{parse_selection_json, selection_from_dmat, Selection};

/// Bad content in a motor or selection file, naming the item.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{source_name}: {item}: {message}")]
pub struct InputError {
    /// The file (or `<memory>`).
    pub source_name: String,
    /// Which item (`key 2`, `group "3"`, `vertex 17`, `JSON`).
    pub item: String,
    /// What was wrong.
    pub message: String,
}

impl InputError {
    pub(crate) fn new(
        source_name: &str,
        item: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        InputError {
            source_name: source_name.to_string(),
            item: item.into(),
            message: message.into(),
        }
    }
}
