//! `deform view` over its socket: the program is started on an ephemeral port and driven as
//! the page drives it; what comes back is compared with the library's own poses, and hostile
//! clients (no token, a foreign Origin, malformed, oversized and out-of-order messages) must
//! never bring the server down.

#[path = "../common/mod.rs"]
mod common;

mod client;
mod controls;
mod hostile;
mod models;
mod poses;
mod replay;
mod selection_undo;
mod upload;
