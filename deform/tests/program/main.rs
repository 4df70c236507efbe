//! The program and its outputs: the `deform` command line end to end (also fuzzed), the
//! lattice commands, and the PNG preview renderer.

#[path = "../common/mod.rs"]
mod common;

mod cli;
mod cli_fuzz;
mod lattice_cli;
mod pose_cli;
mod render;
