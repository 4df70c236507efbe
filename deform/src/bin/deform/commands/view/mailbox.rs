//! Requests waiting for the session thread. A pose request (handle motors, a rig frame)
//! replaces one of its kind not yet taken: while a bind or a slow pose runs, edits coalesce
//! and the latest wins, so the server never falls behind a drag.

use deform::editor::protocol::Request;
use std::collections::VecDeque;
use std::sync::{Condvar, Mutex};

/// A queue of requests with "latest wins" for poses, closed when the connection ends.
#[derive(Default)]
pub struct Mailbox {
    state: Mutex<(VecDeque<Request>, bool)>,
    ready: Condvar,
}

/// Requests that a newer one of the same kind makes pointless.
fn pose_kind(r: &Request) -> Option<u8> {
    match r {
        Request::Motors { .. } => Some(0),
        Request::Rig { .. } => Some(1),
        _ => None,
    }
}

impl Mailbox {
    /// Queue `request`, dropping a waiting pose of its kind.
    pub fn push(&self, request: Request) {
        let mut guard = self.state.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(kind) = pose_kind(&request) {
            guard.0.retain(|r| pose_kind(r) != Some(kind));
        }
        guard.0.push_back(request);
        self.ready.notify_one();
    }

    /// The next request; `None` once closed.
    pub fn pop(&self) -> Option<Request> {
        let mut guard = self.state.lock().unwrap_or_else(|p| p.into_inner());
        loop {
            if guard.1 {
                return None;
            }
            if let Some(r) = guard.0.pop_front() {
                return Some(r);
            }
            guard = self.ready.wait(guard).unwrap_or_else(|p| p.into_inner());
        }
    }

    /// No more requests: [`Mailbox::pop`] returns `None`.
    pub fn close(&self) {
        let mut guard = self.state.lock().unwrap_or_else(|p| p.into_inner());
        guard.1 = true;
        self.ready.notify_all();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motors(seq: u32) -> Request {
        Request::Motors {
            seq,
            motors: Vec::new(),
        }
    }

    #[test]
    fn a_newer_pose_replaces_a_waiting_one_and_other_requests_keep_their_order() {
        let m = Mailbox::default();
        m.push(motors(1));
        m.push(Request::Bind);
        m.push(motors(2));
        m.push(motors(3));
        m.push(Request::Undo);
        assert!(matches!(m.pop(), Some(Request::Bind)));
        assert!(matches!(m.pop(), Some(Request::Motors { seq: 3, .. })));
        assert!(matches!(m.pop(), Some(Request::Undo)));
        m.close();
        assert!(m.pop().is_none());
    }
}
