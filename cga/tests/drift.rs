//! `ga-codegen algebras/cga.toml` prints exactly the code this crate compiles (drift check): the
//! build script's output is compared with a fresh generation from the spec, in f64 and f32.

use ga_codegen::{generate, EmitOptions, ScalarType, Spec};

fn fresh(scalar: ScalarType) -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../algebras/cga.toml");
    let text = std::fs::read_to_string(path).expect("read cga.toml");
    let spec = Spec::from_toml(&text, "algebras/cga.toml").expect("valid spec");
    let opts = EmitOptions {
        scalar,
        ..EmitOptions::default()
    };
    generate(&spec, &opts)
        .expect("generate")
        .code()
        .expect("formats")
        .to_string()
}

#[test]
fn compiled_f64_code_is_what_the_cli_prints() {
    let compiled = include_str!(concat!(env!("OUT_DIR"), "/cga_f64.rs"));
    assert!(
        compiled == fresh(ScalarType::F64),
        "cga_f64.rs drifted from algebras/cga.toml"
    );
    assert!(compiled.contains("algebras/cga.toml"));
}

#[test]
fn compiled_f32_code_is_what_the_cli_prints_with_scalar_f32() {
    let compiled = include_str!(concat!(env!("OUT_DIR"), "/cga_f32.rs"));
    assert!(
        compiled == fresh(ScalarType::F32),
        "cga_f32.rs drifted from algebras/cga.toml"
    );
}
