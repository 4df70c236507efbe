//! What the editing session refuses: a request that does not fit the session's state (said in
//! one line the page shows), or what the library refuses while binding, posing, reading or
//! cutting. The session is unchanged where the refusal says so.

use crate::blend::BlendError;
use crate::deformers::DeformError;
use crate::input::InputError;
use crate::mesh::MeshError;
use crate::methods::budget::BudgetError;
use crate::methods::{MethodError, MethodsError};
use crate::skinning::SkinError;
use crate::surgery::SurgeryError;

/// A refused request.
#[derive(Debug, thiserror::Error)]
pub enum EditError {
    /// A request that does not fit the session (no rig, no such scene, nothing to undo, a
    /// tool that misses), or a library refusal with what was asked in front.
    #[error("{0}")]
    Refused(String),
    /// A method, option or pose the methods layer refuses.
    #[error(transparent)]
    Methods(#[from] MethodsError),
    /// A bad rig, animation or joint edit.
    #[error(transparent)]
    Skin(#[from] SkinError),
    /// A cut, tear or drill that cannot be made.
    #[error(transparent)]
    Surgery(#[from] SurgeryError),
    /// A bad motor or selection file.
    #[error(transparent)]
    Input(#[from] InputError),
    /// A bad mesh or file.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// A file the page sent that is not the JSON asked for.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
}

impl From<MethodError> for EditError {
    fn from(e: MethodError) -> Self {
        EditError::Methods(e.into())
    }
}

impl From<BudgetError> for EditError {
    fn from(e: BudgetError) -> Self {
        EditError::Methods(e.into())
    }
}

impl From<DeformError> for EditError {
    fn from(e: DeformError) -> Self {
        EditError::Methods(e.into())
    }
}

impl From<BlendError> for EditError {
    fn from(e: BlendError) -> Self {
        EditError::Methods(e.into())
    }
}

impl From<std::io::Error> for EditError {
    fn from(e: std::io::Error) -> Self {
        EditError::Refused(e.to_string())
    }
}

impl From<std::string::FromUtf8Error> for EditError {
    fn from(e: std::string::FromUtf8Error) -> Self {
        EditError::Refused(format!("not UTF-8: {e}"))
    }
}

/// `Result` with [`EditError`].
pub type Result<T, E = EditError> = std::result::Result<T, E>;

/// What was asked, in front of why it was refused.
pub(crate) trait Context<T> {
    /// `context: why` on an error, `context` made only then.
    fn with_context<C: std::fmt::Display>(self, context: impl FnOnce() -> C) -> Result<T>;
}

impl<T, E: Into<EditError>> Context<T> for std::result::Result<T, E> {
    fn with_context<C: std::fmt::Display>(self, context: impl FnOnce() -> C) -> Result<T> {
        self.map_err(|e| EditError::Refused(format!("{}: {}", context(), e.into())))
    }
}

/// A refusal with a formatted message.
macro_rules! refused {
    ($($message:tt)*) => {
        $crate::editor::error::EditError::Refused(format!($($message)*))
    };
}

/// Return a refusal with a formatted message.
macro_rules! bail {
    ($($message:tt)*) => {
        return Err($crate::editor::error::refused!($($message)*))
    };
}

pub(crate) use {bail, refused};
