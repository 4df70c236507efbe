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

/// The header's "regenerate with" command is the command that was run: every flag given,
/// `-o` included (issue 46: it dropped `--wide`, `--runtime`, `--exp-log` and `-o`).
#[test]
fn the_header_names_every_flag_given() {
    let dir = scratch("header flags");
    let file = dir.join("g3 f32.rs");
    let out = run(&[
        "algebras/g3.toml",
        "--wide",
        "--exp-log",
        "--library",
        "--runtime",
        "crate::rt",
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
    let second = code.lines().nth(1).unwrap();
    let want = format!(
        "// `ga-codegen algebras/g3.toml -o '{}' --scalar f32 --runtime crate::rt --library --exp-log --wide`.",
        file.display()
    );
    assert_eq!(second, want);
    // WGSL too.
    let wgsl = dir.join("g3.wgsl");
    let out = run(&["algebras/g3.toml", "--wgsl", "-o", wgsl.to_str().unwrap()]);
    assert!(out.status.success());
    let code = std::fs::read_to_string(&wgsl).unwrap();
    assert_eq!(
        code.lines().nth(1).unwrap(),
        format!(
            "// `ga-codegen algebras/g3.toml -o '{}' --wgsl`.",
            wgsl.display()
        )
    );
    // A signature is named as it was given, and defaults add nothing.
    let out = run(&["--signature", "2,0,1"]);
    let code = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        code.lines().nth(1).unwrap(),
        "// `ga-codegen --signature 2,0,1`."
    );
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

/// Specs that are not small files: a device (read until memory ran out), a folder, a file
/// past the size limit; a pipe still reads.
#[test]
fn devices_folders_and_huge_specs_are_refused() {
    let dir = scratch("not-a-spec");
    let huge = dir.join("huge.toml");
    std::fs::write(
        &huge,
        "#".repeat(ga_codegen::generator::spec::MAX_SPEC_BYTES as usize + 1),
    )
    .unwrap();
    let huge = huge.to_string_lossy().into_owned();
    let folder = dir.to_string_lossy().into_owned();
    let mut cases = vec![
        (folder.as_str(), "a folder, not a spec file"),
        (huge.as_str(), "more than 4194304 bytes"),
    ];
    if cfg!(unix) {
        cases.push(("/dev/zero", "a device, not a file"));
    }
    for (spec, needle) in cases {
        let out = run(&[spec]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{spec}: {err}");
        assert!(err.contains(needle), "{spec}: {err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A `--runtime` that is not a Rust path is named as such (it read "internal generator
/// error: expected `,`").
#[test]
fn a_runtime_that_is_not_a_path_is_refused() {
    let out = run(&["algebras/g3.toml", "--runtime", "\"; panic!(); \""]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("is not a Rust path"), "{err}");
    // Generic arguments (they reached the formatter as a "generator bug"), and thousands of
    // segments (the formatter's parser overflowed its stack and aborted).
    let long = vec!["a"; 4000].join("::");
    for (path, words) in [
        ("a::<T>", "generic arguments"),
        (long.as_str(), "4000 segments"),
    ] {
        let out = run(&["algebras/g3.toml", "--runtime", path]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(words) && err.len() < 400, "{err}");
    }
    let out = run(&["algebras/g3.toml", "--runtime", "crate::ga_runtime"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("crate::ga_runtime::"));
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
    // The value is quoted as given, not as Rust's debug form of an option.
    let err =
        String::from_utf8_lossy(&run(&["--scalar", "f16", "algebras/g3.toml"]).stderr).into_owned();
    assert!(err.contains("not `f16`") && !err.contains("Some("), "{err}");
    let err = String::from_utf8_lossy(&run(&["algebras/g3.toml", "--scalar"]).stderr).into_owned();
    assert!(err.contains("--scalar needs f32 or f64"), "{err}");
}

/// A spec over `basis` with a diagonal metric of `diagonal` entries and the given items.
fn spec_with(basis: &str, diagonal: &str, items: &str) -> String {
    format!("basis = {basis}\ndiagonal = {diagonal}\n{items}")
}

#[test]
fn decimal_metric_entries_are_exact() {
    let dir = scratch("decimal");
    let file = dir.join("decimal.toml");
    std::fs::write(
        &file,
        spec_with(
            "[\"e1\", \"e2\", \"e3\"]",
            "[0.1, 0.3, 0.7]",
            "[[type]]\nname = \"Tri\"\nblades = [\"e123\"]\n",
        ),
    )
    .unwrap();
    let out = run(&[file.to_str().unwrap()]);
    let code = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // <e123 ~e123> = 0.1 * 0.3 * 0.7 = 0.021 exactly (as a decimal), not a rounded product.
    assert!(code.contains("0.021 * a.e123 * a.e123"), "{code}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn metrics_whose_exact_products_overflow_are_refused() {
    let basis = "[\"e1\", \"e2\", \"e3\"]";
    let ty = "[[type]]\nname = \"Tri\"\nblades = [\"e123\"]\n";
    for (name, diagonal, entry) in [
        ("big13", "[1e13, 1e13, 1e13]", "[0][0]"),
        ("big30", "[1e30, 1e30, 1]", "[0][0]"),
        (
            "thirds",
            "[0.3333333333333333, 0.3333333333333333, 0.3333333333333333]",
            "[0][0]",
        ),
        ("huge", "[1e300, 1, 1]", "[0][0]"),
        ("nan", "[1, nan, 1]", "[1][1]"),
        ("inf", "[1, 1, inf]", "[2][2]"),
        ("neginf", "[-inf, 1, 1]", "[0][0]"),
        ("tiny", "[1e-320, 1, 1]", "[0][0]"),
    ] {
        expect_error(
            &spec_with(basis, diagonal, ty),
            name,
            &[&format!("metric entry {entry}")],
        );
    }
}

#[test]
fn negative_zero_in_the_metric_is_zero() {
    let dir = scratch("negzero");
    let file = dir.join("negzero.toml");
    std::fs::write(
        &file,
        spec_with(
            "[\"e0\", \"e1\"]",
            "[-0.0, 1]",
            "[[type]]\nname = \"V\"\nblades = [\"e0\", \"e1\"]\n",
        ),
    )
    .unwrap();
    let out = run(&[file.to_str().unwrap(), "--summary"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn ambiguous_and_colliding_basis_names_are_refused() {
    // Suffixes `1` and `11`: blade names would read in many ways (and parsing used to
    // backtrack for 18 s on `e` + 44 ones + `x`).
    let long = format!("e{}x", "1".repeat(44));
    let spec = spec_with(
        "[\"e1\", \"e11\"]",
        "[1, 1]",
        &format!("[[type]]\nname = \"V\"\nblades = [\"{long}\"]\n"),
    );
    let start = std::time::Instant::now();
    expect_error(&spec, "prefix", &["`e11`", "prefix-free"]);
    assert!(start.elapsed().as_secs_f64() < 10.0);
    // `e12` would be both the basis vector and e1^e2: the general type would not compile.
    expect_error(
        &spec_with("[\"e1\", \"e2\", \"e12\"]", "[1, 1, 1]", ""),
        "collide",
        &["`e12`", "prefix-free"],
    );
}

#[test]
fn keyword_names_are_refused() {
    expect_error(
        &spec_with("[\"e1\", \"enum\"]", "[1, 1]", ""),
        "keyword_basis",
        &["`enum`", "keyword"],
    );
    // No basis name is a keyword, but their concatenation is: `e` + `n` + `um`.
    expect_error(
        &spec_with("[\"en\", \"eum\"]", "[1, 1]", ""),
        "keyword_blade",
        &["type `Mv`", "`enum`", "keyword"],
    );
    expect_error(
        &spec_with(
            "[\"el\", \"ese\"]",
            "[1, 1]",
            "[[type]]\nname = \"B\"\nblades = [\"else\"]\n",
        ),
        "keyword_field",
        &["type `B`", "`else`", "keyword"],
    );
}

#[test]
fn type_names_of_generated_items_are_refused() {
    let basis = "[\"e1\", \"e2\", \"e3\"]";
    for (name, ty) in [
        ("rv_matrix", "RVMatrix"),
        ("motor_point_matrix", "RotorPointMatrix"),
        ("sandwich_name", "Sandwich"),
        ("scalar_name", "Scalar"),
        ("lanes_name", "F64x2"),
        ("self_name", "Self"),
    ] {
        let items = format!(
            "[[type]]\nname = \"R\"\nblades = [\"s\", \"e12\"]\nversor = true\n\
             [[type]]\nname = \"V\"\nblades = [\"e1\", \"e2\"]\n\
             [[type]]\nname = \"{ty}\"\nblades = [\"e3\"]\n\
             [[sandwich]]\nversor = \"R\"\noperand = \"V\"\n"
        );
        expect_error(
            &spec_with(basis, "[1, 1, 1]", &items),
            name,
            &[&format!("type `{ty}`"), "reserved"],
        );
    }
}

#[test]
fn specs_too_large_to_generate_are_refused_up_front() {
    // Twelve basis vectors (one-letter suffixes, prefix-free) with a type of every blade: its
    // 2^12 blades are over the work budget; with no type declared, none is added (above 6).
    let twelve: Vec<String> = (0..12u8)
        .map(|i| format!("\"e{}\"", (b'a' + i) as char))
        .collect();
    let every: Vec<String> = (1..1u32 << 12)
        .map(|b| {
            let s: String = (0..12u8)
                .filter(|i| b >> i & 1 == 1)
                .map(|i| (b'a' + i) as char)
                .collect();
            format!("\"e{s}\"")
        })
        .collect();
    let (basis, diagonal) = (
        format!("[{}]", twelve.join(", ")),
        format!("[{}]", ["1"; 12].join(", ")),
    );
    let start = std::time::Instant::now();
    expect_error(
        &spec_with(
            &basis,
            &diagonal,
            &format!(
                "[[type]]\nname = \"All\"\nblades = [\"s\", {}]\n",
                every.join(", ")
            ),
        ),
        "twelve",
        &["too large", "units of work", "4096 blades"],
    );
    expect_error(
        &spec_with(&basis, &diagonal, ""),
        "twelve_untyped",
        &["no type declared", "above 6 basis vectors", "2^12 blades"],
    );
    let mut many = String::new();
    for t in 0..150 {
        many.push_str(&format!(
            "[[type]]\nname = \"T{t}\"\nblades = [\"e1\", \"e2\"]\n"
        ));
    }
    expect_error(
        &spec_with("[\"e1\", \"e2\", \"e3\"]", "[1, 1, 1]", &many),
        "many_types",
        &["too large", "151 types", "22801 ordered pairs"],
    );
    // 8 basis vectors are within the work budget's limit but not with a type for every grade
    // (the note says what to do instead); 9 are past --signature's limit of a type for every
    // grade, 17 past the generator's; the messages give the limits.
    for (sig, says) in [
        ("8,0,0", &["too large", "only the types you need"][..]),
        (
            "9,0,0",
            &["every grade only up to 8", "only the types you need"][..],
        ),
        ("8,2,0", &["every grade only up to 8", "2^10 blades"][..]),
        ("17,0,0", &["between 1 and 16"][..]),
        ("0,0,0", &["between 1 and 16"][..]),
    ] {
        let out = run(&["--signature", sig, "--summary"]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{sig}: {err}");
        assert!(err.contains(&format!("--signature {sig}")), "{sig}: {err}");
        for s in says {
            assert!(err.contains(s), "{sig}: {err}");
        }
    }
    // Refused before any product is expanded.
    assert!(start.elapsed().as_secs_f64() < 20.0);
}

#[test]
fn signature_sums_do_not_wrap() {
    for sig in ["18446744073709551615,2,0", "0,0,0", "5,5,0", "1,-1,0"] {
        let out = run(&["--signature", sig, "--summary"]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{sig}: {err}");
        assert!(err.contains("--signature"), "{sig}: {err}");
        assert!(!err.contains("panicked"), "{sig}: {err}");
    }
}

#[test]
fn blade_name_that_is_a_keyword() {
    // A keyword (`enum` = `e` + `num`) cannot be a field: the spec refuses the basis vector
    // by name, before any code is emitted.
    let spec = "basis = [\"e1\", \"enum\"]\ndiagonal = [1, 1]\n[[type]]\nname = \"V\"\nblades = [\"e1\", \"enum\"]\n";
    expect_error(
        spec,
        "keyword_blade",
        &["keyword_blade.toml", "`enum`", "keyword"],
    );
}

#[test]
fn exp_log_refused_above_five_dimensions() {
    // Without --exp-log a 6-D signature generates, without closed forms for its bivectors.
    let out = run(&["--signature", "6,0,0"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let code = String::from_utf8_lossy(&out.stdout);
    assert!(!code.contains("impl Log for"), "a 6-D log was emitted");
    // ... and says so: a note names the type and the way to make it an error.
    let note = String::from_utf8_lossy(&out.stderr);
    assert!(
        note.contains("note:") && note.contains("type `Bivector` gets no closed-form exp/log"),
        "{note}"
    );
    // With it, a clear error naming the spec, the type and the reason, exit code 2.
    let out = run(&["--signature", "6,0,0", "--exp-log"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("type `Bivector`") && err.contains("spans 6 basis vectors"),
        "{err}"
    );
    // Two time-like and two space-like directions (complex pairs of squares): all of them,
    // and no note.
    let out = run(&["--signature", "2,2,0", "--exp-log"]);
    assert!(out.status.success());
    let code = String::from_utf8_lossy(&out.stdout);
    assert!(code.contains("impl Log for Even") && code.contains("impl EvenVersor for Even"));
    let out = run(&["--signature", "2,2,0"]);
    assert!(!String::from_utf8_lossy(&out.stderr).contains("note:"));
    // Every spec in algebras/ gets them: --exp-log accepts it and the code has them.
    for name in ["cga", "pga3d", "g3", "sta"] {
        let spec = workspace().join(format!("algebras/{name}.toml"));
        let out = run(&[spec.to_str().expect("utf-8 path"), "--exp-log"]);
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let code = String::from_utf8_lossy(&out.stdout);
        assert!(
            code.contains("impl Log for") && code.contains("impl Exp<"),
            "{name}"
        );
    }
}

#[test]
fn output_onto_the_spec_is_refused_and_the_spec_kept() {
    let dir = std::env::temp_dir().join(format!("ga-codegen-self-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let spec = dir.join("g3.toml");
    let text = std::fs::read_to_string(workspace().join("algebras/g3.toml")).expect("g3.toml");
    std::fs::write(&spec, &text).expect("write spec");
    let path = spec.to_str().expect("utf-8 path");
    // Also through another spelling of the same path.
    let other = dir.join(".").join("g3.toml");
    for args in [
        vec![path, "-o", path],
        vec![path, "--wgsl", "-o", other.to_str().expect("utf-8 path")],
    ] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("that is the spec file"));
        assert_eq!(std::fs::read_to_string(&spec).expect("spec"), text);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `--help` says what every option of the usage lines does, on a line of its own.
#[test]
fn help_explains_every_option() {
    let out = run(&["--help"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let (usage, explained) = text.split_once("\n\n").expect("usage, then the options");
    let options: std::collections::BTreeSet<&str> = usage
        .split(|c: char| c.is_whitespace() || c == '[' || c == ']' || c == '|')
        .filter(|w| w.starts_with('-'))
        .collect();
    assert!(options.len() >= 9, "{options:?}");
    for o in options {
        let line = explained
            .lines()
            .find(|l| l.trim_start().split([' ', ',']).next() == Some(o))
            .or_else(|| explained.lines().find(|l| l.contains(&format!(", {o} "))));
        let line = line.unwrap_or_else(|| panic!("{o} is not explained:\n{explained}"));
        assert!(line.split_whitespace().count() > 2, "{line}");
    }
}

/// A reader that stops early (`ga-codegen spec.toml | head`) ends the program quietly with
/// success, as `cat` does (it panicked with "Broken pipe").
#[test]
fn a_reader_that_stops_early_is_not_an_error() {
    use std::io::Read;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_ga-codegen"))
        .arg("algebras/pga3d.toml")
        .current_dir(workspace())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run ga-codegen");
    let mut first = [0u8; 64];
    child
        .stdout
        .take()
        .expect("piped")
        .read_exact(&mut first)
        .expect("the start of the module");
    // The read end is dropped here: the rest of the module meets a closed pipe.
    let out = child.wait_with_output().expect("wait");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{:?}: {stderr}", out.status);
    assert!(!stderr.contains("panicked"), "{stderr}");
}
