//! insta snapshots of a few generated CGA functions, so that any change to generated code shows
//! up in review: the motor product and the fused motor sandwich on a normalised point.

use std::path::Path;

fn cga_code() -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/cga.toml");
    let text = std::fs::read_to_string(path).expect("read cga.toml");
    let spec = ga_codegen::Spec::from_toml(&text, "algebras/cga.toml").expect("valid spec");
    ga_codegen::generate(&spec, &ga_codegen::EmitOptions::default())
        .expect("generate")
        .code()
        .expect("formats")
        .to_string()
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
