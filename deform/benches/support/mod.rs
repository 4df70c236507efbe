//! The scenes the criterion benches and the quick reports (`examples/*_report.rs`, which
//! include one file each by path) share. A folder, so Cargo does not take it for a bench.

pub mod scenes;
pub mod skin_scenes;
pub mod surgery_scenes;
