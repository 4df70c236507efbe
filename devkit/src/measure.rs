//! Wall-clock timings for the quick reports: the median of repeated runs with their spread.

use crate::grade::Spread;
use std::time::Instant;

/// Wall time in milliseconds of `runs` calls: the median, and the fastest and slowest call.
pub fn spread_ms(runs: usize, mut f: impl FnMut()) -> Spread {
    let mut t: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    Spread::median_of(&mut t)
}

/// Median wall time in milliseconds of `runs` calls.
pub fn median_ms(runs: usize, f: impl FnMut()) -> f64 {
    spread_ms(runs, f).value
}
