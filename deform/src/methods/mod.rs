//! The methods layer: what the `deform` program, its editor and a library caller share above
//! the deformers, skinning and surgery. Today: the work budget that refuses oversized requests
//! before anything is allocated ([`budget`]).
//!
//! **May use**: every layer below (mesh, operators, blend, deformers, skinning, surgery,
//! render, input). Nothing below may use it.

pub mod budget;
