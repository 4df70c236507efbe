//! The mesh foundation: the [`Mesh`] type, its adjacency, validation and cleaning, procedural
//! shapes and mesh files.
//!
//! * [`Mesh`] and [`Aabb`], with on-demand [`adjacency`];
//! * [`validate()`](validate::validate) and [`clean()`](validate::clean) with the offending
//!   indices;
//! * [`shapes`]: procedural meshes (tube, sphere) for demos, tests and benches;
//! * [`io`]: OBJ, OFF, MEDIT, libigl DMAT and TGF files;
//! * `numbers`: numbers and points printed short, for every layer's messages and labels.
//!
//! **May use**: `glam`, `cga` (nothing else of this crate). **Must not use**: any other layer
//! (operators, blend, deformers, skinning, surgery, render, input) or the crate-level
//! `Error`; its errors are [`MeshError`].

pub mod adjacency;
mod error;
pub mod io;
pub(crate) mod numbers;
pub mod shapes;
pub(crate) mod triangle;
mod triangle_mesh;
pub(crate) mod union_find;
pub mod validate;

pub use error::{IndexList, MeshError, Result};
pub use triangle::is_degenerate_triangle;
pub use triangle_mesh::{Aabb, Mesh};
pub use union_find::Components;
