//! The deformers: motor blending, handles, splines, lattices (FFD), cages and ARAP.

#[path = "../common/mod.rs"]
mod common;

mod arap;
mod blend;
mod cage;
mod fabrik;
mod ffd;
mod handles;
mod pose_scratch;
mod spline;
