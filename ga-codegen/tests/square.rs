//! `square()`, `x * x` expanded in one set of coefficients: the terms `x_i x_j` and `x_j x_i`
//! of anticommuting blades cancel before code is emitted, so a bivector's square keeps no
//! bivector part and takes a small result type (CGA's `DualLine` squares to a `DualNumber`,
//! where `DualLine * DualLine` is a whole `Motor`). The values are checked against the generic
//! multivector by the check harness (`tests/tests/generated_vs_generic.rs`); this file checks
//! what is emitted. Also: a `log` returns the first declared bivector type that holds it.

use ga_codegen::{generate, EmitOptions, Spec};
use std::path::Path;

fn code_of(spec: &Spec) -> String {
    generate(spec, &EmitOptions::default())
        .expect("generates")
        .code()
        .expect("formats")
        .to_string()
}

fn algebra(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../algebras/{name}.toml"));
    code_of(&Spec::from_file(&path).expect("valid spec"))
}

/// The text of `fn name(self) -> ...` up to its closing brace, inside `impl Type {`.
fn method(code: &str, ty: &str, name: &str) -> String {
    let start = code
        .find(&format!("\nimpl {ty} {{"))
        .unwrap_or_else(|| panic!("no `impl {ty}`"));
    let rest = &code[start..];
    let at = rest
        .find(&format!("pub fn {name}(self)"))
        .unwrap_or_else(|| panic!("no `{ty}::{name}`"));
    let body = &rest[at..];
    let end = body.find("\n    }\n").expect("method end");
    body[..end].to_string()
}

#[test]
fn a_dual_line_squares_to_a_dual_number() {
    let code = algebra("cga");
    let sq = method(&code, "DualLine", "square");
    assert!(sq.contains("-> DualNumber"), "{sq}");
    // Only the scalar and `e123i`, each a sum of three products: nothing of the bivector.
    for field in ["s:", "e123i:"] {
        assert!(sq.contains(field), "{sq}");
    }
    assert_eq!(sq.matches("a.e").count(), 12, "{sq}");
    // The product of two independent lines is a whole motor: the cancellation is the square's.
    let mul = code
        .find("impl ::core::ops::Mul<DualLine> for DualLine {")
        .expect("DualLine * DualLine");
    assert!(
        code[mul..].starts_with(
            "impl ::core::ops::Mul<DualLine> for DualLine {\n    type Output = Motor;"
        ),
        "{}",
        &code[mul..mul + 120]
    );
    // A dual number's square is one again: (s + q I)^2 = s^2 + 2 s q I.
    let sq = method(&code, "DualNumber", "square");
    assert!(sq.contains("-> DualNumber"), "{sq}");
    // A versor's square is the smallest versor type holding it.
    assert!(method(&code, "Motor", "square").contains("-> Motor"));
}

#[test]
fn squares_of_bivectors_and_vectors_are_small() {
    // G(3): a bivector squares to a scalar, a vector to its norm.
    let g3 = algebra("g3");
    assert!(method(&g3, "Bivector", "square").contains("-> f64"));
    assert!(method(&g3, "Vector", "square").contains("-> f64"));
    // PGA: a line squares to a scalar plus the pseudoscalar; no declared type holds just
    // those, so the result is a motor whose line part is the constant zero (no terms).
    let pga = algebra("pga3d");
    let sq = method(&pga, "Line", "square");
    assert!(sq.contains("-> Motor"), "{sq}");
    for bivector in ["e01", "e02", "e03", "e23", "e31", "e12"] {
        assert!(sq.contains(&format!("{bivector}: 0.0,")), "{sq}");
    }
    assert!(sq.contains("e0123: 2.0 * a.e01 * a.e23"), "{sq}");
}

/// A 4D Euclidean spec with a rotor in `e1 e2 e3` and two bivector types that hold its
/// bivector blades, declared in the given order.
fn two_bivector_types(first: (&str, &str), second: (&str, &str)) -> Spec {
    let text = format!(
        r#"
name = "e4"
basis = ["e1", "e2", "e3", "e4"]
diagonal = [1, 1, 1, 1]
[[type]]
name = "{}"
blades = [{}]
[[type]]
name = "{}"
blades = [{}]
[[type]]
name = "Rotor"
blades = ["s", "e12", "e13", "e23"]
versor = true
unit = true
"#,
        first.0, first.1, second.0, second.1
    );
    Spec::from_toml(&text, "e4.toml").expect("valid spec")
}

#[test]
fn a_log_returns_the_first_declared_bivector_type_that_holds_it() {
    let all = ("Bivector", r#""e12", "e13", "e23", "e14", "e24", "e34""#);
    let part = ("Spatial", r#""e12", "e13", "e23""#);
    for (spec, want) in [
        (two_bivector_types(all, part), "Bivector"),
        (two_bivector_types(part, all), "Spatial"),
    ] {
        let code = code_of(&spec);
        let at = code.find("impl Log for Rotor {").expect("Rotor has a log");
        assert!(
            code[at..].starts_with(&format!("impl Log for Rotor {{\n    type Output = {want};")),
            "{}",
            &code[at..at + 80]
        );
    }
    // CGA's motor log stays a `Bivector` although the smaller `DualLine` holds it.
    let cga = algebra("cga");
    for v in ["Rotor", "Translator", "Motor"] {
        let at = cga.find(&format!("impl Log for {v} {{")).expect("log");
        assert!(
            cga[at..].starts_with(&format!("impl Log for {v} {{\n    type Output = Bivector;")),
            "{v}"
        );
    }
}
