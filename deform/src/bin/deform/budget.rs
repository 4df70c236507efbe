//! This run's work budget (`--max-work`), set once; the estimates and the refusals are the
//! library's ([`deform::methods::budget`]).

use deform::methods::budget::WorkBudget;
use std::sync::OnceLock;

/// The budget when `--max-work` is not given.
pub const DEFAULT_MAX_WORK: u64 = WorkBudget::DEFAULT_MAX_WORK;

static MAX_WORK: OnceLock<u64> = OnceLock::new();

/// Sets this run's budget (once, from `--max-work`).
pub fn set(max_work: u64) {
    let _ = MAX_WORK.set(max_work);
}

/// This run's budget.
pub fn get() -> WorkBudget {
    WorkBudget {
        max_work: *MAX_WORK.get().unwrap_or(&DEFAULT_MAX_WORK),
    }
}
