//! What the benches and quick reports share: locating the data set, median timings with their
//! spread, and the targets that grade them (`grade`).
#![allow(dead_code)]

#[path = "grade.rs"]
pub mod grade;

#[allow(unused_imports)]
pub use grade::{Spread, Tally, Target};

use std::path::PathBuf;
use std::time::Instant;

/// A file of the data set, e.g. `data("meshes/libigl/arm.obj")`, from `$CGA_DATA_DIR` (else
/// `../shared/data`); `None` when absent (a panic under `CI=true`).
pub fn data(rel: &str) -> Option<PathBuf> {
    let dir = std::env::var_os("CGA_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data"));
    let path = dir.join(rel);
    if !path.is_file() {
        if std::env::var("CI").as_deref() == Ok("true") {
            panic!("{} is missing (CI=true)", path.display());
        }
        eprintln!("skipped: {} not found (set CGA_DATA_DIR)", path.display());
        return None;
    }
    Some(path)
}

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
