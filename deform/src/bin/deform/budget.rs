//! One work budget for every size a user can ask for (joints, lattice points, grid nodes,
//! frames, in-betweens, iterations): checked before anything is allocated, so a huge count is a
//! clear error (exit code 2) instead of an allocation failure that kills the process.
//!
//! The unit is one element of work or memory: one `f64` of a buffer, one grid node's share of a
//! factorisation, one vertex of one frame or one iteration. The default, 2^28 (2 GiB of `f64`s),
//! holds every size the README and the benchmarks use; `--max-work N` raises (or lowers) it.

use anyhow::{bail, Result};
use std::sync::OnceLock;

/// The budget when `--max-work` is not given.
pub const DEFAULT_MAX_WORK: u64 = 1 << 28;

static MAX_WORK: OnceLock<u64> = OnceLock::new();

/// Sets this run's budget (once, from `--max-work`).
pub fn set(max_work: u64) {
    let _ = MAX_WORK.set(max_work);
}

/// This run's budget.
pub fn max_work() -> u64 {
    *MAX_WORK.get().unwrap_or(&DEFAULT_MAX_WORK)
}

/// The product of `factors`, `None` on overflow.
pub fn product(factors: &[u64]) -> Option<u64> {
    factors.iter().try_fold(1u64, |acc, &f| acc.checked_mul(f))
}

/// Refuses `work` (the product of `factors`, described by `what`) when it exceeds the budget;
/// the message names `flag`, the figure and how to raise the limit.
pub fn check(flag: &str, what: &str, factors: &[u64]) -> Result<()> {
    let limit = max_work();
    match product(factors) {
        Some(w) if w <= limit => Ok(()),
        Some(w) => bail!(
            "{flag}: {what} comes to {w} elements of work, over this run's budget of {limit} \
             (raise it with --max-work {w} if the machine has the memory and time)"
        ),
        None => bail!(
            "{flag}: {what} overflows 64 bits, far over this run's budget of {limit} (--max-work)"
        ),
    }
}

/// `f64`s held per vertex and per handle group while a group's harmonic coordinates are bound
/// (the fields, their copy per group and the blend's weight rows): 2,000 groups on
/// armadillo-50k (100M vertex-group pairs) took 2.76 GB, about 3.5 `f64`s a pair.
pub const PER_COORDINATE: u64 = 4;

/// Refuses binding `groups` motor handle groups (a harmonic coordinate each) on `vertices`
/// vertices when it would come to more than the budget: a selection file with thousands of
/// groups asks for tens of gigabytes.
pub fn check_groups(flag: &str, groups: usize, vertices: usize) -> Result<()> {
    check(
        flag,
        &format!("{groups} groups on {vertices} vertices (a weight per vertex and group)"),
        &[groups as u64, vertices as u64, PER_COORDINATE],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_work_over_the_budget_and_overflow() {
        assert!(check("--joints", "6 joints", &[6, 24]).is_ok());
        let e = check("--joints", "many joints", &[u64::MAX, 24]).unwrap_err();
        assert!(e.to_string().contains("overflows"), "{e}");
        let e = check("--grid", "a grid", &[1 << 20, 1 << 20]).unwrap_err();
        assert!(e.to_string().contains("--max-work"), "{e}");
        // The default budget holds a thousand groups on armadillo-50k, not 65,536.
        assert!(check_groups("--select", 1000, 49_999).is_ok());
        let e = check_groups("--select", 65_536, 49_999).unwrap_err();
        assert!(e.to_string().contains("65536 groups"), "{e}");
    }
}
