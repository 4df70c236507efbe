//! One file per method: its options, its [`MethodKind`](super::kind::MethodKind) (the
//! description and the bind) and its bound mesh ([`PoseMethod`](super::kind::PoseMethod)).

pub mod arap;
pub mod cage;
pub mod control;
pub mod fabrik;
pub mod ffd;
pub mod handles;
pub mod spline;
