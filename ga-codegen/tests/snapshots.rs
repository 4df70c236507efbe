//! insta snapshots of generated CGA code, so that any change to generated code shows up in
//! review: every geometric product between versor types (the paired-lane kernels among them),
//! every fused sandwich the spec declares, the matrix form of the motor-point sandwich, and the
//! f32 motor product in four-lane form.
//! `algebras/cga.summary.txt` (tested in `summary.rs`) lists everything else.

use std::path::Path;

fn cga() -> (ga_codegen::Spec, String) {
    cga_in(ga_codegen::ScalarType::F64)
}

fn cga_in(scalar: ga_codegen::ScalarType) -> (ga_codegen::Spec, String) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/cga.toml");
    let text = std::fs::read_to_string(path).expect("read cga.toml");
    let spec = ga_codegen::Spec::from_toml(&text, "algebras/cga.toml").expect("valid spec");
    let opts = ga_codegen::EmitOptions {
        scalar,
        ..ga_codegen::EmitOptions::default()
    };
    let code = ga_codegen::generate(&spec, &opts)
        .expect("generate")
        .code()
        .expect("formats")
        .to_string();
    (spec, code)
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

fn snake(name: &str) -> String {
    ga_codegen::generator::emit::snake(name)
}

#[test]
fn every_versor_product() {
    let (spec, code) = cga();
    let versors: Vec<&str> = spec
        .types
        .iter()
        .filter(|t| t.versor)
        .map(|t| t.name.as_str())
        .collect();
    assert!(versors.len() >= 5, "{versors:?}");
    for a in &versors {
        for b in &versors {
            insta::assert_snapshot!(
                format!("mul_{}_{}", snake(a), snake(b)),
                item(&code, &format!("impl ::core::ops::Mul<{b}> for {a} {{"))
            );
        }
    }
}

#[test]
fn every_fused_sandwich() {
    let (spec, code) = cga();
    assert!(!spec.sandwiches.is_empty());
    for d in &spec.sandwiches {
        let (v, x) = (&spec.types[d.versor].name, &spec.types[d.operand].name);
        insta::assert_snapshot!(
            format!("sandwich_{}_{}", snake(v), snake(x)),
            item(&code, &format!("impl Sandwich<{x}> for {v} {{"))
        );
    }
}

#[test]
fn motor_point_matrix() {
    insta::assert_snapshot!(item(&cga().1, "impl MotorPointMatrix {"));
}

#[test]
fn motor_times_motor_f32_four_lanes() {
    insta::assert_snapshot!(item(
        &cga_in(ga_codegen::ScalarType::F32).1,
        "impl ::core::ops::Mul<Motor> for Motor {"
    ));
}

/// Vector operations of a 4-lane body: (shuffles, multiplies, sign flips).
fn lane_ops(body: &str) -> (usize, usize, usize) {
    let multiplies = body
        .split_whitespace()
        .collect::<Vec<_>>()
        .windows(3)
        .filter(|w| w[1] == "*" && [w[0], w[2]].iter().all(|x| x.contains("_q")))
        .count();
    (
        body.matches(".shuffle::<").count(),
        multiplies,
        body.matches(".flip::<").count(),
    )
}

/// PGA's f32 motor product against klein's hand-written SSE one (`gpMM` in
/// `detail/x86/x86_geometric_product.hpp`: 15 shuffles, 12 multiplies, 2 sign flips): the slot
/// form's placement search finds at most as many shuffles.
#[test]
fn pga_motor_product_f32_needs_no_more_shuffles_than_klein() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/pga3d.toml");
    let text = std::fs::read_to_string(path).expect("read pga3d.toml");
    let spec = ga_codegen::Spec::from_toml(&text, "algebras/pga3d.toml").expect("valid spec");
    let opts = ga_codegen::EmitOptions {
        scalar: ga_codegen::ScalarType::F32,
        ..ga_codegen::EmitOptions::default()
    };
    let generated = ga_codegen::generate(&spec, &opts).expect("generate");
    let body = item(
        generated.code().expect("formats"),
        "impl ::core::ops::Mul<Motor> for Motor {",
    );
    let (shuffles, multiplies, flips) = lane_ops(&body);
    assert_eq!(multiplies, 12, "{body}");
    assert!(
        shuffles <= 15 && flips <= 2,
        "{shuffles} shuffles, {flips} flips:\n{body}"
    );
}
