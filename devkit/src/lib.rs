//! What the workspace's tests, benches and examples share, in plain `std` (no dependencies):
//!
//! - [`shared`]: locating the shared data set and reference results (`../shared/data`,
//!   `../shared/reference`), with the rule that missing data skips, or fails under `CI=true`;
//! - [`measure`]: wall-clock timings with their spread;
//! - [`grade`]: targets that grade those figures (`met` / `MISSED`) and the closing tally.

#![warn(missing_docs)]

pub mod grade;
pub mod measure;
pub mod shared;
