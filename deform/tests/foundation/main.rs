//! The foundation: meshes and their repair, mesh I/O (also hostile and mutated files), motor
//! and selection input, the cotangent Laplacian, harmonic fields and their solver, properties
//! and libigl references.

#[path = "../common/mod.rs"]
mod common;

mod harmonic;
mod hostile;
mod input;
mod io;
mod laplacian;
mod mesh;
mod mutation;
mod properties;
mod reference;
mod shared_analysis;
mod solve_scratch;
