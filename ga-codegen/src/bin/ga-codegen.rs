//! `ga-codegen`: regenerate an algebra's Rust module from a spec file or a signature.
//!
//! ```text
//! ga-codegen SPEC.toml [-o FILE] [--scalar f32|f64] [--summary] [--runtime PATH] [--library] [--exp-log] [--wide]
//! ga-codegen --signature P,Q,R [-o FILE] [--scalar f32|f64] [--summary] [--runtime PATH] [--library] [--exp-log] [--wide]
//! ga-codegen SPEC.toml|--signature P,Q,R --wgsl [-o FILE]
//! ```
//! `--wgsl` writes the algebra as WGSL instead (f32 structs, products, reverses, fused
//! sandwiches and sandwich matrices; see `ga_codegen::generate_wgsl`).
//! Without `-o` the module is printed. `--summary` prints the types and the product table
//! instead of the code (the time taken goes to stderr, so the listing is reproducible:
//! `algebras/cga.summary.txt` is `ga-codegen algebras/cga.toml --summary`). `--library` adds
//! the `serde`/`bytemuck` impls behind cargo features and the `types` module (as the `cga`
//! crate compiles it). Every bivector and even versor type gets closed-form `exp`, `log`, `sqrt`
//! and `normalize` where the invariant decomposition is closed form (spans of at most five basis
//! vectors, real squares); a type that cannot have them is named in a note on stderr, and
//! `--exp-log` makes it an error instead. `--wide` adds `pub mod wide`, structure-of-arrays twins of
//! the versor types over a lane type (`F64x4`, `F32x8`), for loops over many operands. Errors name the file, the type and the blade, and exit with code 2.

use ga_codegen::generator::spec::SpecErrorKind;
use ga_codegen::{generate, EmitOptions, ScalarType, Spec};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

const USAGE: &str =
    "usage: ga-codegen SPEC.toml [-o FILE] [--scalar f32|f64] [--summary] [--runtime PATH] [--library] [--exp-log] [--wide]
       ga-codegen --signature P,Q,R [-o FILE] [--scalar f32|f64] [--summary] [--runtime PATH] [--library] [--exp-log] [--wide]
       ga-codegen SPEC.toml|--signature P,Q,R --wgsl [-o FILE]";

/// `--help`: the usage, then what each argument does.
const OPTIONS: &str = "
Generate the Rust module (or WGSL) of a geometric algebra from a spec file (TOML: basis, metric,
types, sandwiches; see algebras/*.toml) or from a signature, and print it or write it.

  SPEC.toml            the algebra's spec
  --signature P,Q,R    G(P,Q,R): P vectors squaring to +1, Q to -1, R to 0, with a type for every
                       grade, the even part and the whole algebra (P,Q for R = 0)
  -o, --output FILE    write the module to FILE (refused when FILE is the spec); default: print
  --scalar f32|f64     the coefficient type (default f64)
  --summary            print the types and the product table instead of the code (the time
                       taken goes to stderr)
  --runtime PATH       the path of the ga-codegen runtime crate in the module (default ::ga_codegen)
  --library            add the serde/bytemuck impls behind cargo features and the `types` module,
                       as the cga crate compiles it
  --exp-log            refuse the spec when a bivector or even versor type gets no closed-form
                       exp, log, sqrt and normalize (without it, such types are named in a note)
  --wide               add `pub mod wide`: structure-of-arrays twins of the versor types over a
                       lane type (F64x4, F32x8), for loops over many operands
  --wgsl               write WGSL instead (f32 structs, products, reverses, fused sandwiches and
                       their matrices); takes only -o
  -h, --help           this text

Errors name the file, the type and the blade, and exit with code 2.";

struct Args {
    spec: Option<PathBuf>,
    signature: Option<(usize, usize, usize)>,
    out: Option<PathBuf>,
    scalar: ScalarType,
    summary: bool,
    library: bool,
    runtime: Option<String>,
    exp_log: bool,
    wide: bool,
    wgsl: bool,
    scalar_given: bool,
}

fn parse_args() -> Result<Args, String> {
    let mut a = Args {
        spec: None,
        signature: None,
        out: None,
        scalar: ScalarType::F64,
        summary: false,
        library: false,
        runtime: None,
        exp_log: false,
        wide: false,
        wgsl: false,
        scalar_given: false,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "-h" | "--help" => return Err(String::new()),
            "-o" | "--output" => a.out = Some(it.next().ok_or("-o needs a file")?.into()),
            "--scalar" => {
                a.scalar_given = true;
                a.scalar = match it.next().as_deref() {
                    Some("f32") => ScalarType::F32,
                    Some("f64") => ScalarType::F64,
                    Some(other) => {
                        return Err(format!("--scalar must be f32 or f64, not `{other}`"))
                    }
                    None => return Err("--scalar needs f32 or f64".into()),
                }
            }
            "--summary" => a.summary = true,
            "--library" => a.library = true,
            "--exp-log" => a.exp_log = true,
            "--wide" => a.wide = true,
            "--wgsl" => a.wgsl = true,
            "--runtime" => a.runtime = Some(it.next().ok_or("--runtime needs a path")?),
            "--signature" => {
                let v = it.next().ok_or("--signature needs P,Q,R")?;
                a.signature = Some(parse_signature(&v)?);
            }
            s if s.starts_with('-') => return Err(format!("unknown option `{s}`")),
            s => {
                if a.spec.is_some() {
                    return Err(format!("more than one spec file given (`{s}`)"));
                }
                a.spec = Some(s.into())
            }
        }
    }
    if a.spec.is_some() == a.signature.is_some() {
        return Err("give either a spec file or --signature P,Q,R".into());
    }
    if a.wgsl && (a.summary || a.library || a.runtime.is_some() || a.scalar_given || a.wide) {
        return Err(
            "--wgsl writes f32 WGSL and takes only -o (not --scalar, --summary, --library, --runtime or --wide)"
                .into(),
        );
    }
    Ok(a)
}

/// `P,Q,R` or `P,Q`: non-negative counts whose sum does not overflow, at least 1 and at most
/// the generator's limit (the tighter limit of a type for every grade is
/// `Spec::for_signature`'s, whose error says so).
fn parse_signature(v: &str) -> Result<(usize, usize, usize), String> {
    let bad = || format!("--signature needs P,Q,R (non-negative integers), not `{v}`");
    let parts: Vec<usize> = v
        .split(',')
        .map(|x| x.trim().parse::<usize>().map_err(|_| bad()))
        .collect::<Result<_, _>>()?;
    let (p, q, r) = match parts.as_slice() {
        [p, q, r] => (*p, *q, *r),
        [p, q] => (*p, *q, 0),
        _ => return Err(bad()),
    };
    let most = ga_codegen::generator::spec::budget::MAX_DIMENSION;
    match p.checked_add(q).and_then(|s| s.checked_add(r)) {
        Some(n) if (1..=most).contains(&n) => Ok((p, q, r)),
        _ => Err(format!(
            "--signature {v}: P + Q + R must be between 1 and {most} (the generator's limit)"
        )),
    }
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            if e.is_empty() {
                println!("{USAGE}\n{OPTIONS}");
                return ExitCode::SUCCESS;
            }
            eprintln!("error: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    if let Err(e) = output_is_not_the_spec(args.spec.as_deref(), args.out.as_deref()) {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    let start = Instant::now();
    let spec = match (&args.spec, args.signature) {
        (Some(p), _) => Spec::from_file(p),
        (None, Some((p, q, r))) => Spec::for_signature(p, q, r),
        _ => unreachable!(),
    };
    let spec = match spec {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            if args.signature.is_some() && matches!(e.kind, SpecErrorKind::TooLarge(_)) {
                eprintln!(
                    "note: --signature declares a type for every grade, the even and the whole \
                     algebra, with their sandwiches; with this many basis vectors write a spec \
                     with only the types you need (see algebras/*.toml)"
                );
            }
            return ExitCode::from(2);
        }
    };
    if !args.exp_log {
        for (t, why) in ga_codegen::generator::emit::refusals(&spec) {
            eprintln!(
                "note: {}: type `{t}` gets no closed-form exp/log: {why} (--exp-log makes this an error)",
                spec.source
            );
        }
    }
    if args.wgsl {
        return write_wgsl(&spec, args.out.as_deref(), start);
    }
    let mut opts = EmitOptions {
        scalar: args.scalar,
        library: args.library,
        require_exp_log: args.exp_log,
        wide: args.wide,
        output: args.out.as_ref().map(|p| p.display().to_string()),
        ..EmitOptions::default()
    };
    if let Some(r) = args.runtime {
        opts.runtime = r;
    }
    let generated = match generate(&spec, &opts) {
        Ok(g) => g,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    // Format the module (prettyplease); its line count is part of the summary.
    let code = match generated.code() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let elapsed = start.elapsed();
    if args.summary {
        let header = format!(
            "algebra `{}` from {} ({} basis vectors)\n",
            spec.name,
            spec.source,
            spec.metric.dim()
        );
        if let Err(code) = to_stdout(&(header + &generated.summary())) {
            return code;
        }
        eprintln!("generated in {:.1} ms", elapsed.as_secs_f64() * 1e3);
    }
    match &args.out {
        Some(path) => {
            if let Err(e) = std::fs::write(path, code) {
                eprintln!("error: cannot write {}: {e}", path.display());
                return ExitCode::from(2);
            }
            eprintln!(
                "wrote {} ({} lines, {:.1} ms)",
                path.display(),
                generated.lines(),
                elapsed.as_secs_f64() * 1e3
            );
        }
        None if !args.summary => {
            if let Err(code) = to_stdout(code) {
                return code;
            }
        }
        None => {}
    }
    ExitCode::SUCCESS
}

/// Write `text` to standard output. A reader that stops early (`| head`) is not an error:
/// the program stops quietly with success, as `cat` does; any other write error is exit 2.
fn to_stdout(text: &str) -> Result<(), ExitCode> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Err(ExitCode::SUCCESS),
        Err(e) => {
            eprintln!("error: cannot write to standard output: {e}");
            Err(ExitCode::from(2))
        }
    }
}

/// `--wgsl`: the WGSL source to `out` or stdout.
fn write_wgsl(spec: &Spec, out: Option<&std::path::Path>, start: Instant) -> ExitCode {
    let named = out.map(|p| p.display().to_string());
    let code = match ga_codegen::generator::emit::generate_wgsl_to(spec, named.as_deref()) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let ms = start.elapsed().as_secs_f64() * 1e3;
    match out {
        Some(path) => {
            if let Err(e) = std::fs::write(path, &code) {
                eprintln!("error: cannot write {}: {e}", path.display());
                return ExitCode::from(2);
            }
            eprintln!(
                "wrote {} ({} lines of WGSL, {ms:.1} ms)",
                path.display(),
                code.lines().count()
            );
        }
        None => {
            if let Err(code) = to_stdout(&code) {
                return code;
            }
        }
    }
    ExitCode::SUCCESS
}

/// `-o` must not name the spec file: writing there would destroy the user's input.
fn output_is_not_the_spec(
    spec: Option<&std::path::Path>,
    out: Option<&std::path::Path>,
) -> Result<(), String> {
    let (Some(spec), Some(out)) = (spec, out) else {
        return Ok(());
    };
    let same = match (spec.canonicalize(), out.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if same {
        return Err(format!(
            "-o {}: that is the spec file; write the generated code elsewhere",
            out.display()
        ));
    }
    Ok(())
}
