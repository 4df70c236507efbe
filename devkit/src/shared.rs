//! Locating the shared data folder next to the workspace: `$CGA_DATA_DIR`, else
//! `../shared/data`; `$CGA_REFERENCE_DIR`, else `../shared/reference`. Missing data skips what
//! needs it (`None`, with a `skipped: ...` line on stderr) and is a panic under `CI=true`.

use std::fmt::Display;
use std::path::{Path, PathBuf};

/// The variable naming the data set's folder (default `../shared/data`).
pub const DATA_VAR: &str = "CGA_DATA_DIR";

/// The variable naming the reference results' folder (default `../shared/reference`).
pub const REFERENCE_VAR: &str = "CGA_REFERENCE_DIR";

/// Whether `CI=true`: missing data is then a failure, not a skip.
pub fn ci() -> bool {
    std::env::var("CI").as_deref() == Ok("true")
}

/// `$var` when set, else `<workspace>/../shared/<sub>`. Not checked.
pub fn shared_dir(var: &str, sub: &str) -> PathBuf {
    std::env::var_os(var).map(PathBuf::from).unwrap_or_else(|| {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../shared")
            .join(sub)
    })
}

/// Missing data: a panic with `failure` under `CI=true`, else `skipped: {skip}` on stderr and
/// `None`.
pub fn missing<T>(failure: impl Display, skip: impl Display) -> Option<T> {
    if ci() {
        panic!("{failure}");
    }
    eprintln!("skipped: {skip}");
    None
}

/// The folder `shared_dir(var, sub)` when it exists, else [`missing`].
fn locate(var: &str, sub: &str, what: &str) -> Option<PathBuf> {
    let dir = shared_dir(var, sub);
    if dir.is_dir() {
        return Some(dir);
    }
    missing(
        format_args!("{what} directory {} is missing (CI=true)", dir.display()),
        format_args!("{what} directory {} not found (set {var})", dir.display()),
    )
}

/// `$CGA_DATA_DIR`, else `../shared/data` next to the workspace; `None` (skipped) when absent,
/// a panic under `CI=true`.
pub fn data_dir() -> Option<PathBuf> {
    locate(DATA_VAR, "data", "test data")
}

/// `$CGA_REFERENCE_DIR`, else `../shared/reference`; `None` (skipped) when absent, a panic
/// under `CI=true`.
pub fn reference_dir() -> Option<PathBuf> {
    locate(REFERENCE_VAR, "reference", "reference")
}

/// A file of the data set, e.g. `data_file("meshes/libigl/arm.obj")`, under `$CGA_DATA_DIR`
/// (else `../shared/data`); `None` when absent (a panic under `CI=true`).
pub fn data_file(rel: &str) -> Option<PathBuf> {
    let path = shared_dir(DATA_VAR, "data").join(rel);
    if path.is_file() {
        return Some(path);
    }
    missing(
        format_args!("{} is missing (CI=true)", path.display()),
        format_args!("{} not found (set {DATA_VAR})", path.display()),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_is_the_shared_folder_next_to_the_workspace() {
        let dir = shared_dir("DEVKIT_TEST_VARIABLE_NEVER_SET", "data");
        assert!(dir.ends_with("../shared/data"), "{}", dir.display());
        let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        assert_eq!(
            dir.canonicalize().ok(),
            workspace.join("../shared/data").canonicalize().ok()
        );
    }
}
