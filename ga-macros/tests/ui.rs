//! Compile-fail tests: spec errors in `algebra!` are reported at the offending token with a
//! message naming the type and the blade (hostile specs in `ui/hostile_specs.rs`: an
//! overflowing metric entry, colliding basis names, a reserved type name). Each `tests/ui/*.rs`
//! must fail to compile with exactly the diagnostics of its `.stderr` file (message and span).
//! Regenerate them with `GA_MACROS_UI=overwrite cargo test -p ga-macros --test ui` and read the
//! diff before committing.
//!
//! This is our own harness (`harness = false`), not trybuild. Why: trybuild sends the output of
//! its `cargo --keep-going` capability probe and of `cargo clean` to `/dev/null`, and cargo
//! learns about the target by running `rustc -` with `/dev/null` as the program. On a machine
//! whose `/dev/null` is a regular file (it happens when something deletes the device and a later
//! `> /dev/null` recreates it as a file), the first write fills "/dev/null" with cargo's text,
//! the next probe fails on it, cargo compiles nothing, and trybuild, receiving no diagnostics,
//! reported all 12 cases as compiled ("Expected test case to fail to compile, but it
//! succeeded"). Here:
//! - every child's standard streams are explicit: an empty stdin pipe, captured output; nothing
//!   is written to `/dev/null`;
//! - cargo runs rustc through this very binary as `RUSTC_WRAPPER` (the `shim` below), which gives
//!   rustc an empty stdin pipe, so cargo's `rustc -` probe reads an empty program whatever
//!   `/dev/null` holds;
//! - a case with no error diagnostic at all fails, and shows cargo's own stderr.

use std::collections::BTreeMap;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};

/// Set (by this harness, for cargo) when the binary runs as cargo's rustc wrapper.
const SHIM: &str = "GA_MACROS_UI_RUSTC_SHIM";
/// `GA_MACROS_UI=overwrite` rewrites the `.stderr` files from the compiler's output.
const MODE: &str = "GA_MACROS_UI";

fn main() -> ExitCode {
    if std::env::var_os(SHIM).is_some() {
        return shim();
    }
    match run() {
        Ok(0) => ExitCode::SUCCESS,
        Ok(_) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("compile-fail harness: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Cargo's rustc wrapper: `ui RUSTC ARGS...` runs `RUSTC ARGS...` with an empty stdin pipe,
/// passing its output and exit status through.
fn shim() -> ExitCode {
    let mut args = std::env::args_os().skip(1);
    let Some(rustc) = args.next() else {
        eprintln!("{SHIM}: expected the rustc path as the first argument");
        return ExitCode::FAILURE;
    };
    let child = Command::new(rustc)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::inherit())
        .stderr(Stdio::inherit())
        .spawn();
    match child {
        Ok(mut child) => {
            drop(child.stdin.take()); // rustc reading `-` sees an empty program
            match child.wait() {
                Ok(status) => ExitCode::from(status.code().unwrap_or(101).clamp(0, 255) as u8),
                Err(e) => {
                    eprintln!("{SHIM}: waiting for rustc: {e}");
                    ExitCode::FAILURE
                }
            }
        }
        Err(e) => {
            eprintln!("{SHIM}: cannot run rustc: {e}");
            ExitCode::FAILURE
        }
    }
}

/// One case: `tests/ui/NAME.rs` and its expected `tests/ui/NAME.stderr`.
struct Case {
    name: String,
    source: PathBuf,
    expected: PathBuf,
}

fn cases(dir: &Path) -> Result<Vec<Case>, String> {
    let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut cases: Vec<Case> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .map(|source| {
            let name = source
                .file_stem()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            Case {
                expected: source.with_extension("stderr"),
                name,
                source,
            }
        })
        .collect();
    cases.sort_by(|a, b| a.name.cmp(&b.name));
    if cases.is_empty() {
        return Err(format!("no cases in {}", dir.display()));
    }
    Ok(cases)
}

/// Writes the scratch crate: one `[[bin]]` per case, depending on this package by path, outside
/// the workspace, with the workspace's lock file (so `--offline` resolves).
fn scratch_crate(root: &Path, manifest_dir: &Path, cases: &[Case]) -> Result<PathBuf, String> {
    let dir = root.join("crate");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut toml = format!(
        "[package]\nname = \"ga-macros-ui\"\nversion = \"0.0.0\"\nedition = \"2021\"\n\
         publish = false\n\n[workspace]\n\n[profile.dev]\ndebug = 0\n\n[dependencies]\n\
         ga-macros = {{ path = {:?} }}\n",
        manifest_dir.display().to_string()
    );
    for c in cases {
        toml += &format!(
            "\n[[bin]]\nname = {:?}\npath = {:?}\n",
            c.name,
            c.source.display().to_string()
        );
    }
    write_whole(&dir.join("Cargo.toml"), toml.as_bytes())?;
    let lock = manifest_dir.join("../Cargo.lock");
    if lock.is_file() {
        let bytes = std::fs::read(&lock).map_err(|e| format!("Cargo.lock: {e}"))?;
        write_whole(&dir.join("Cargo.lock"), &bytes)?;
    }
    Ok(dir)
}

/// Writes `path` through a temporary file and a rename, so a concurrent run never reads it
/// half-written.
fn write_whole(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let tmp = path.with_extension(format!("tmp-{}", std::process::id()));
    std::fs::write(&tmp, bytes).map_err(|e| format!("{}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| format!("{}: {e}", path.display()))
}

/// What `cargo check --message-format=json` said: the rendered diagnostics per bin, whether any
/// was an error, and cargo's own stderr.
struct Checked {
    rendered: BTreeMap<String, Vec<String>>,
    errors: BTreeMap<String, usize>,
    stderr: String,
}

fn check(dir: &Path, target_dir: &Path, manifest_dir: &Path) -> Result<Checked, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let me = std::env::current_exe().map_err(|e| format!("current_exe: {e}"))?;
    let output = Command::new(cargo)
        .current_dir(dir)
        .args(["check", "--bins", "--keep-going", "--offline", "--quiet"])
        .args(["--color=never", "--message-format=json"])
        .env("CARGO_TARGET_DIR", target_dir)
        .env("RUSTC_WRAPPER", &me)
        .env(SHIM, "1")
        .env("CARGO_ENCODED_RUSTFLAGS", "--diagnostic-width=140")
        .env("CARGO_INCREMENTAL", "0")
        .env("CARGO_TERM_COLOR", "never")
        .env_remove("RUSTFLAGS")
        .env_remove("RUSTC_WORKSPACE_WRAPPER")
        .env_remove("CARGO_BUILD_RUSTC_WRAPPER")
        .env_remove("CARGO_MAKEFLAGS")
        .env_remove("MAKEFLAGS")
        .env_remove("MFLAGS")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    let prefix = format!("{}/", manifest_dir.display());
    let mut checked = Checked {
        rendered: BTreeMap::new(),
        errors: BTreeMap::new(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
    };
    for line in String::from_utf8_lossy(&output.stdout).lines() {
        let Ok(v) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        if v["reason"] != "compiler-message" {
            continue;
        }
        let bin = v["target"]["name"].as_str().unwrap_or_default().to_string();
        let m = &v["message"];
        let text = m["message"].as_str().unwrap_or_default();
        let level = m["level"].as_str().unwrap_or_default();
        if level == "failure-note" || text.starts_with("aborting due to") {
            continue;
        }
        if level == "error" {
            *checked.errors.entry(bin.clone()).or_default() += 1;
        }
        let rendered = m["rendered"].as_str().unwrap_or_default();
        let rendered = rendered.replace(&prefix, "").trim_end().to_string();
        checked.rendered.entry(bin).or_default().push(rendered);
    }
    Ok(checked)
}

/// A note when `/dev/null` is not the null device (what broke trybuild); the harness copes.
fn dev_null_note() -> Option<String> {
    use std::os::unix::fs::FileTypeExt;
    let meta = std::fs::metadata("/dev/null").ok()?;
    (!meta.file_type().is_char_device()).then(|| {
        format!(
            "note: /dev/null is not the null device but a {} of {} bytes; cargo reads and \
             writes it as one (this harness does not depend on it)",
            if meta.is_file() {
                "regular file"
            } else {
                "non-device"
            },
            meta.len()
        )
    })
}

/// The libtest arguments this harness honours: name filters (`--exact`), `--list`, and
/// `--ignored` (there are no ignored cases); others (`--nocapture`, ...) are accepted and unused.
fn select(mut cases: Vec<Case>) -> (Vec<Case>, bool) {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let exact = args.iter().any(|a| a == "--exact");
    let filters: Vec<&String> = args.iter().filter(|a| !a.starts_with('-')).collect();
    if args.iter().any(|a| a == "--ignored") {
        cases.clear();
    }
    cases.retain(|c| {
        let name = format!("ui::{}", c.name);
        filters.is_empty()
            || filters.iter().any(|f| {
                if exact {
                    name == **f
                } else {
                    name.contains(f.as_str())
                }
            })
    });
    (cases, args.iter().any(|a| a == "--list"))
}

fn run() -> Result<usize, String> {
    let manifest_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ga-macros-ui");
    let all = cases(&manifest_dir.join("tests/ui"))?;
    let (cases, list) = select(cases(&manifest_dir.join("tests/ui"))?);
    if list {
        for c in &cases {
            println!("ui::{}: test", c.name);
        }
        return Ok(0);
    }
    if cases.is_empty() {
        println!(
            "\nrunning 0 tests\n\ntest result: ok. 0 passed; 0 failed; 0 ignored; 0 measured\n"
        );
        return Ok(0);
    }
    if let Some(note) = dev_null_note() {
        println!("{note}");
    }
    let overwrite = std::env::var(MODE).as_deref() == Ok("overwrite");
    println!("\nrunning {} compile-fail cases", cases.len());
    // The scratch crate always holds every case, so runs of different selections at once (a
    // runner that starts one process per case) write the same manifest; cargo's lock on the
    // target folder serialises their builds.
    let dir = scratch_crate(&root, &manifest_dir, &all)?;
    let checked = check(&dir, &root.join("target"), &manifest_dir)?;
    let mut failed = Vec::new();
    for c in &cases {
        let actual = checked
            .rendered
            .get(&c.name)
            .map(|r| r.join("\n\n"))
            .unwrap_or_default();
        let errors = checked.errors.get(&c.name).copied().unwrap_or(0);
        let verdict = if errors == 0 {
            Err(format!(
                "no error diagnostic at all: the case compiled, or cargo failed before compiling \
                 it. cargo's stderr:\n{}",
                checked.stderr.trim_end()
            ))
        } else if overwrite {
            std::fs::write(&c.expected, format!("{actual}\n"))
                .map_err(|e| format!("{}: {e}", c.expected.display()))
        } else {
            let expected = std::fs::read_to_string(&c.expected)
                .map_err(|e| format!("{}: {e}", c.expected.display()))?;
            if expected.trim_end() == actual {
                Ok(())
            } else {
                Err(format!(
                    "diagnostics differ from {}\n--- expected\n{}\n--- actual\n{actual}",
                    c.expected.display(),
                    expected.trim_end()
                ))
            }
        };
        match verdict {
            Ok(()) => println!("test ui::{} ... ok", c.name),
            Err(why) => {
                println!("test ui::{} ... FAILED", c.name);
                failed.push((c.name.clone(), why));
            }
        }
    }
    for (name, why) in &failed {
        println!("\n---- ui::{name} ----\n{why}");
    }
    let passed = cases.len() - failed.len();
    println!(
        "\ntest result: {}. {passed} passed; {} failed; 0 ignored; 0 measured; 0 filtered out\n",
        if failed.is_empty() { "ok" } else { "FAILED" },
        failed.len()
    );
    let _ = std::io::stdout().flush();
    Ok(failed.len())
}
