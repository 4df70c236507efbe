//! The `ga-codegen` binary: regeneration from spec files and signatures, and bad specs rejected
//! with exit code 2 and a message naming the file, the type and the blade.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ga-codegen"))
        .args(args)
        .current_dir(workspace())
        .output()
        .expect("run ga-codegen")
}

/// A scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ga-codegen-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create scratch dir");
    dir
}

#[test]
fn prints_exactly_what_the_library_generates() {
    let out = run(&["algebras/cga.toml"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(workspace().join("algebras/cga.toml")).unwrap();
    let spec = ga_codegen::Spec::from_toml(&text, "algebras/cga.toml").unwrap();
    let lib = ga_codegen::generate(&spec, &ga_codegen::EmitOptions::default()).unwrap();
    assert!(String::from_utf8(out.stdout).unwrap() == lib.code().unwrap());
}

#[test]
fn writes_a_file_and_f32() {
    let dir = scratch("write");
    let file = dir.join("g3_f32.rs");
    let out = run(&[
        "algebras/g3.toml",
        "--scalar",
        "f32",
        "-o",
        file.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let code = std::fs::read_to_string(&file).unwrap();
    assert!(code.contains("pub type Scalar = f32;"));
    assert!(code.contains("pub struct Rotor"));
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn signature_generates_default_spec() {
    let out = run(&["--signature", "3,0,1", "--summary"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let s = String::from_utf8(out.stdout).unwrap();
    // One type per grade, the even subalgebra and the general multivector.
    for t in ["Vector", "Bivector", "Trivector", "Even", "Mv"] {
        assert!(s.contains(t), "summary lacks {t}:\n{s}");
    }
}

fn expect_error(spec: &str, name: &str, needles: &[&str]) {
    let dir = scratch(name);
    let file = dir.join(format!("{name}.toml"));
    std::fs::write(&file, spec).unwrap();
    let out_file = dir.join("out.rs");
    std::fs::write(&out_file, "user content").unwrap();
    let out = run(&[file.to_str().unwrap(), "-o", out_file.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{name}: {err}");
    assert!(!err.contains("panicked"), "{name}: {err}");
    assert!(
        err.contains(&format!("{name}.toml")),
        "{name}: no file in `{err}`"
    );
    for n in needles {
        assert!(err.contains(n), "{name}: `{n}` not in `{err}`");
    }
    // Nothing the user had is overwritten when generation fails.
    assert_eq!(std::fs::read_to_string(&out_file).unwrap(), "user content");
    let _ = std::fs::remove_dir_all(dir);
}

const HEAD: &str = "basis = [\"e1\", \"e2\", \"e3\"]\ndiagonal = [1, 1, 1]\n";

#[test]
fn unknown_basis_name() {
    let spec = format!("{HEAD}[[type]]\nname = \"Rotor\"\nblades = [\"s\", \"e12\", \"e14\"]\n");
    expect_error(
        &spec,
        "unknown_basis",
        &["`Rotor`", "`e14`", "unknown blade"],
    );
}

#[test]
fn blade_listed_twice() {
    let spec = format!("{HEAD}[[type]]\nname = \"Biv\"\nblades = [\"e12\", \"e21\"]\n");
    expect_error(&spec, "blade_twice", &["`Biv`", "`e21`", "twice"]);
}

#[test]
fn non_symmetric_metric() {
    let spec = "basis = [\"e1\", \"e2\"]\nmetric = [[1, 2], [0, 1]]\n[[type]]\nname = \"V\"\nblades = [\"e1\"]\n";
    expect_error(spec, "non_symmetric", &["symmetric"]);
}

#[test]
fn wrongly_sized_metric() {
    let spec = "basis = [\"e1\", \"e2\", \"e3\"]\nmetric = [[1, 0], [0, 1]]\n[[type]]\nname = \"V\"\nblades = [\"e1\"]\n";
    expect_error(spec, "wrong_size", &["metric"]);
}

#[test]
fn empty_type() {
    let spec = format!("{HEAD}[[type]]\nname = \"Nothing\"\nblades = []\n");
    expect_error(&spec, "empty_type", &["`Nothing`", "no stored blades"]);
}

#[test]
fn duplicate_type_name() {
    let spec = format!(
        "{HEAD}[[type]]\nname = \"V\"\nblades = [\"e1\"]\n[[type]]\nname = \"V\"\nblades = [\"e2\"]\n"
    );
    expect_error(&spec, "duplicate_type", &["`V`", "twice"]);
}

#[test]
fn constant_not_in_type() {
    let spec = format!(
        "{HEAD}[[type]]\nname = \"P\"\nblades = [\"e1\", \"e2\"]\nconstants = {{ e3 = 1 }}\n"
    );
    expect_error(
        &spec,
        "constant_not_in_type",
        &["`P`", "`e3`", "does not list"],
    );
}

#[test]
fn malformed_toml_and_missing_file() {
    expect_error("basis = [\"e1\"\n", "malformed", &["cannot read spec"]);
    let out = run(&["no/such/spec.toml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no/such/spec.toml"));
}

#[test]
fn bad_arguments() {
    for args in [
        &["--signature", "3,x"][..],
        &["--scalar", "f16", "algebras/g3.toml"][..],
        &[][..],
        &["--bogus"][..],
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
    }
}

#[test]
fn blade_name_that_is_a_keyword() {
    // A keyword (`enum` = `e` + `num`) passes the spec's name rules but cannot be a field:
    // refused with the type and the blade named, before any code is emitted.
    let spec = "basis = [\"e1\", \"enum\"]\ndiagonal = [1, 1]\n[[type]]\nname = \"V\"\nblades = [\"e1\", \"enum\"]\n";
    expect_error(
        spec,
        "keyword_blade",
        &["`V`", "`enum`", "not a Rust identifier"],
    );
}
