//! insta snapshots of a few generated CGA functions, so that any change to generated code shows
//! up in review: the motor product (f64 paired lanes, f32 four lanes) and the fused motor
//! sandwich on a normalised point.

use std::path::Path;

fn cga_code() -> String {
    cga_code_in(ga_codegen::ScalarType::F64)
}

fn cga_code_in(scalar: ga_codegen::ScalarType) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/cga.toml");
    let text = std::fs::read_to_string(path).expect("read cga.toml");
    let spec = ga_codegen::Spec::from_toml(&text, "algebras/cga.toml").expect("valid spec");
    let opts = ga_codegen::EmitOptions {
        scalar,
        ..ga_codegen::EmitOptions::default()
    };
    ga_codegen::generate(&spec, &opts).expect("generate").code
}

/// The item starting at the line that begins with `head`, up to its matching closing brace.
fn item(code: &str, head: &str) -> String {
    let start = code
        .find(&format!("\n{head}"))
        .unwrap_or_else(|| panic!("`{head}` not in generated code"))
        + 1;
    let mut depth = 0i32;
    for (i, ch) in code[start..].char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return code[start..=start + i].to_string();
                }
            }
            _ => {}
        }
    }
    panic!("unbalanced item `{head}`")
}

#[test]
fn motor_times_motor() {
    insta::assert_snapshot!(item(
        &cga_code(),
        "impl ::core::ops::Mul<Motor> for Motor {"
    ));
}

#[test]
fn motor_sandwich_point() {
    insta::assert_snapshot!(item(&cga_code(), "impl Sandwich<Point> for Motor {"));
}

#[test]
fn motor_point_matrix() {
    insta::assert_snapshot!(item(&cga_code(), "impl MotorPointMatrix {"));
}

#[test]
fn motor_times_motor_f32_four_lanes() {
    insta::assert_snapshot!(item(
        &cga_code_in(ga_codegen::ScalarType::F32),
        "impl ::core::ops::Mul<Motor> for Motor {"
    ));
}
