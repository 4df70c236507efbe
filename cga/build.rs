//! Generates the G(4,1) types from `cga.toml` (this crate's own copy of the spec, so the
//! packaged crate builds alone; the workspace's `algebras/cga.toml` is a link to it) at build
//! time, in f64 and f32, and as WGSL.

use ga_codegen::{generate, EmitOptions, ScalarType, Spec};
use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets this"));
    let spec_path = manifest.join("cga.toml");
    println!("cargo:rerun-if-changed={}", spec_path.display());
    let text = std::fs::read_to_string(&spec_path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", spec_path.display()));
    // Name the spec as the CLI user in the workspace does, so the generated header is the
    // command that prints this file: `ga-codegen algebras/cga.toml --library --wide`.
    let spec = Spec::from_toml(&text, "algebras/cga.toml").unwrap_or_else(|e| panic!("{e}"));
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets this"));
    for (scalar, file) in [
        (ScalarType::F64, "cga_f64.rs"),
        (ScalarType::F32, "cga_f32.rs"),
    ] {
        // `library`: serde and bytemuck impls behind this crate's features of those names, and
        // the `types` module that the crate root re-exports.
        let opts = EmitOptions {
            scalar,
            library: true,
            // `cga::wide` (and `cga::f32::wide`): the versor types over 4 / 8 lanes, for
            // pose loops that move many points at once.
            wide: true,
            ..EmitOptions::default()
        };
        let g = generate(&spec, &opts).unwrap_or_else(|e| panic!("{e}"));
        let code = g.code().unwrap_or_else(|e| panic!("{e}"));
        std::fs::write(out.join(file), code).expect("write generated code");
    }
    // The same algebra as WGSL, for shaders (`cga::f32::WGSL`).
    let wgsl = ga_codegen::generate_wgsl(&spec).unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(out.join("cga.wgsl"), wgsl).expect("write generated WGSL");
}
