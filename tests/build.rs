//! Generates every algebra in `algebras/` (f64 and f32), plus the default spec of a signature and
//! a metric that is not orthogonal (`SKEW`), each with the check harness that compares its
//! generated functions with the generic multivector.

use ga_codegen::generator::checks::emit_checks;
use ga_codegen::{generate, EmitOptions, ScalarType, Spec};
use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets this"));
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets this"));
    let opts = EmitOptions::default();
    let mut specs = Vec::new();
    for name in ["cga", "pga3d", "g3", "sta"] {
        let path = manifest.join(format!("../algebras/{name}.toml"));
        println!("cargo:rerun-if-changed={}", path.display());
        let spec = Spec::from_file(&path).unwrap_or_else(|e| panic!("{e}"));
        specs.push((name.to_string(), spec));
    }
    specs.push((
        "sig201".to_string(),
        Spec::for_signature(2, 0, 1).unwrap_or_else(|e| panic!("{e}")),
    ));
    // Euclidean 4D: every rotor a double rotation (the isoclinic cases of exp/log).
    specs.push((
        "sig400".to_string(),
        Spec::for_signature(4, 0, 0).unwrap_or_else(|e| panic!("{e}")),
    ));
    // Two directions of each sign: the squares of a bivector's commuting parts may be a
    // complex pair (exp only, in complex arithmetic).
    specs.push((
        "sig220".to_string(),
        Spec::for_signature(2, 2, 0).unwrap_or_else(|e| panic!("{e}")),
    ));
    specs.push((
        "sig320".to_string(),
        Spec::for_signature(3, 2, 0).unwrap_or_else(|e| panic!("{e}")),
    ));
    // A metric that is not orthogonal (rational entries off the diagonal): its `Mv` and `Even`
    // products go through the matrix-unit basis found in the orthogonalised basis.
    specs.push((
        "skew".to_string(),
        Spec::from_toml(SKEW, "tests/build.rs (SKEW)").unwrap_or_else(|e| panic!("{e}")),
    ));
    // The f32 twin of every module too (CGA's with 4-lane products), checked with an f32
    // tolerance; the closed-form exp/log tests use both.
    let f32_opts = EmitOptions {
        scalar: ScalarType::F32,
        ..EmitOptions::default()
    };
    let mut all: Vec<(String, Spec, EmitOptions)> = Vec::new();
    for (n, s) in specs {
        all.push((format!("{n}_f32"), s.clone(), f32_opts.clone()));
        all.push((n, s, opts.clone()));
    }
    for (name, spec, opts) in all {
        let g = generate(&spec, &opts).unwrap_or_else(|e| panic!("{e}"));
        let checks = emit_checks(&spec, &g, "::ga_codegen");
        let code = g.code().unwrap_or_else(|e| panic!("{e}"));
        std::fs::write(out.join(format!("{name}.rs")), code).expect("write");
        std::fs::write(out.join(format!("{name}_checks.rs")), checks).expect("write");
    }
}

/// G(3,1) written in a basis that is not orthogonal.
const SKEW: &str = r#"
name = "skew"
doc = "A non-orthogonal metric with rational entries (signature (3,1))."
basis = ["e1", "e2", "e3", "e4"]
metric = [
    [1, 0.5, 0, 0.4],
    [0.5, 1, 0.25, 0],
    [0, 0.25, -1, 0.125],
    [0.4, 0, 0.125, 1.5],
]

[[type]]
name = "Vector"
doc = "Grade 1."
blades = ["e1", "e2", "e3", "e4"]

[[type]]
name = "Bivector"
doc = "Grade 2."
blades = ["e12", "e13", "e14", "e23", "e24", "e34"]

[[type]]
name = "Even"
doc = "The even subalgebra."
blades = ["s", "e12", "e13", "e14", "e23", "e24", "e34", "e1234"]

[[type]]
name = "Mv"
doc = "Every blade."
blades = ["s", "e1", "e2", "e3", "e4", "e12", "e13", "e14", "e23", "e24", "e34", "e123", "e124", "e134", "e234", "e1234"]
"#;
