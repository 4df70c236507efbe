//! One module per subcommand: its arguments (clap) and its `run`. A subcommand uses the
//! shared modules (`crate::shared_args`, `crate::input_files`, ...), never another subcommand.

pub mod arap;
pub mod cage;
pub mod cut;
pub mod demo;
pub mod drill;
pub mod fabrik;
pub mod ffd;
pub mod handles;
pub mod pose;
pub mod skin;
pub mod spline;
pub mod tear;
pub mod view;
