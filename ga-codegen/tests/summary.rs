//! The committed listing of `algebras/cga.toml` (every type, product, result type and term
//! count, and the lines generated) is what `ga-codegen algebras/cga.toml --library --summary`
//! prints, so any change to what is generated for CGA shows up in review as a change to
//! `algebras/cga.summary.txt`. Regenerate it with
//! `cargo run -p ga-codegen -- algebras/cga.toml --library --summary > algebras/cga.summary.txt`.

use std::path::Path;
use std::process::Command;

#[test]
fn cga_listing_is_current() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = Command::new(env!("CARGO_BIN_EXE_ga-codegen"))
        .args(["algebras/cga.toml", "--library", "--summary"])
        .current_dir(&root)
        .output()
        .expect("run ga-codegen");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let now = String::from_utf8(out.stdout).expect("utf-8");
    let committed = std::fs::read_to_string(root.join("algebras/cga.summary.txt"))
        .expect("read algebras/cga.summary.txt");
    if now != committed {
        let first = now
            .lines()
            .zip(committed.lines())
            .position(|(a, b)| a != b)
            .unwrap_or_else(|| now.lines().count().min(committed.lines().count()));
        panic!(
            "algebras/cga.summary.txt is not what the generator gives for algebras/cga.toml \
             (first difference at line {}):\n  committed: {:?}\n  generated: {:?}\n\
             Review the change, then regenerate the listing with `cargo run -p ga-codegen -- \
             algebras/cga.toml --library --summary > algebras/cga.summary.txt`.",
            first + 1,
            committed.lines().nth(first).unwrap_or("<end>"),
            now.lines().nth(first).unwrap_or("<end>"),
        );
    }
}
