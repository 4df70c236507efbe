//! A crate written from scratch that depends on the `ga-codegen` runtime only (as a user's
//! crate would), built and run offline with warnings denied: how the tests check that
//! generated modules compile and run outside the workspace.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Write crate `name` under `root` with `src/lib.rs` = `lib` and `src/main.rs` = `main`, the
/// dev profile at `opt_level`; returns its `src/` folder.
pub fn write(root: &Path, name: &str, opt_level: u8, lib: &str, main: &str) -> PathBuf {
    let manifest_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let krate = root.join("crate");
    let src = krate.join("src");
    std::fs::create_dir_all(&src).unwrap();
    std::fs::write(
        krate.join("Cargo.toml"),
        format!(
            "[package]\nname = \"{name}\"\nversion = \"0.0.0\"\nedition = \"2021\"\n\
             publish = false\n\n[workspace]\n\n[profile.dev]\ndebug = 0\nopt-level = {opt_level}\n\n\
             [dependencies]\nga-codegen = {{ path = {:?}, default-features = false }}\n",
            manifest_dir.display().to_string()
        ),
    )
    .unwrap();
    // The workspace's lock file, so `--offline` resolves.
    std::fs::copy(manifest_dir.join("../Cargo.lock"), krate.join("Cargo.lock")).unwrap();
    std::fs::write(src.join("lib.rs"), lib).unwrap();
    std::fs::write(src.join("main.rs"), main).unwrap();
    src
}

/// `cargo run --offline` of the crate whose `src/` is `src`, into `root`'s target folder,
/// with warnings denied; asserts it built and ran, printed `ok` last and no warning.
pub fn run(src: &Path, root: &Path) {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let output = Command::new(cargo)
        .current_dir(src.join(".."))
        .args(["run", "--offline", "--quiet"])
        .env("CARGO_TARGET_DIR", root.join("target"))
        .env("CARGO_ENCODED_RUSTFLAGS", "-Dwarnings")
        .env_remove("RUSTFLAGS")
        .env_remove("RUSTC_WORKSPACE_WRAPPER")
        .env_remove("CARGO_MAKEFLAGS")
        .env_remove("MAKEFLAGS")
        .env_remove("MFLAGS")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr),
    );
    assert!(
        output.status.success(),
        "the crate did not build or run:\n{stderr}\n{stdout}"
    );
    assert!(stdout.ends_with("ok\n"), "{stdout}");
    assert!(!stderr.contains("warning"), "{stderr}");
}
