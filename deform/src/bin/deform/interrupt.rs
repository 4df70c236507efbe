//! Ctrl-C: the run stops at once, removes the files it was writing (the temporary files of
//! atomic writes, the frames of an unfinished sequence) and exits with code 130, so an
//! interrupted run leaves no partial output.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Files to remove if the run is interrupted now.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Installs the handler (once, at start).
pub fn install() {
    let _ = ctrlc::set_handler(|| {
        // The lock is held until the process exits: the run cannot register (and so cannot
        // create) another file after these are removed.
        let guard = PENDING.lock();
        let pending: &[PathBuf] = guard.as_deref().map_or(&[], |p| p.as_slice());
        // Newest first: a temporary file goes before the frame it is renamed to, so a rename
        // racing this loop cannot leave the frame behind.
        for path in pending.iter().rev() {
            let _ = std::fs::remove_file(path);
        }
        eprintln!(
            "interrupted: stopped, {} unfinished file(s) removed",
            pending.len()
        );
        std::process::exit(130);
    });
}

/// `path` is removed if the run is interrupted before the guard is dropped.
pub struct Pending(Vec<PathBuf>);

/// Registers `paths` as unfinished until the returned guard is dropped (or [`Pending::add`]ed
/// to and then dropped).
pub fn pending(paths: &[&Path]) -> Pending {
    let mut guard = Pending(Vec::new());
    for p in paths {
        guard.add(p);
    }
    guard
}

impl Pending {
    /// One more unfinished file.
    pub fn add(&mut self, path: &Path) {
        if let Ok(mut p) = PENDING.lock() {
            p.push(path.to_path_buf());
        }
        self.0.push(path.to_path_buf());
    }
}

impl Drop for Pending {
    fn drop(&mut self) {
        if let Ok(mut p) = PENDING.lock() {
            p.retain(|x| !self.0.contains(x));
        }
    }
}
