//! `ga-codegen --wgsl`: every algebra in `algebras/` and a few signatures give WGSL that naga
//! (wgpu's shader compiler) parses and validates, with the functions the Rust module has.

use ga_codegen::{generate_wgsl, Spec};
use std::path::Path;

fn validate(name: &str, wgsl: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(wgsl)
        .unwrap_or_else(|e| panic!("{name}: WGSL does not parse:\n{}", e.emit_to_string(wgsl)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| {
        panic!(
            "{name}: WGSL does not validate:\n{}",
            e.emit_to_string(wgsl)
        )
    });
    module
}

fn has_fn(m: &naga::Module, name: &str) -> bool {
    m.functions
        .iter()
        .any(|(_, f)| f.name.as_deref() == Some(name))
}

#[test]
fn every_algebra_validates() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras");
    for name in ["cga", "pga3d", "g3", "sta"] {
        let spec = Spec::from_file(&root.join(format!("{name}.toml"))).expect("spec");
        let wgsl = generate_wgsl(&spec).expect("wgsl");
        let m = validate(name, &wgsl);
        // One struct per type, and the sandwiches of the spec.
        for t in &spec.types {
            assert!(
                m.types
                    .iter()
                    .any(|(_, ty)| ty.name.as_deref() == Some(&t.name)),
                "{name}: no struct {}",
                t.name
            );
        }
        assert!(!spec.sandwiches.is_empty());
    }
    for (p, q, r) in [(2, 0, 1), (3, 0, 0), (4, 1, 0), (1, 3, 0), (3, 0, 1)] {
        let spec = Spec::for_signature(p, q, r).expect("spec");
        validate(
            &format!("G({p},{q},{r})"),
            &generate_wgsl(&spec).expect("wgsl"),
        );
    }
}

#[test]
fn cga_has_products_sandwiches_and_matrices() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/cga.toml");
    let spec = Spec::from_file(&root).expect("spec");
    let wgsl = generate_wgsl(&spec).expect("wgsl");
    let m = validate("cga", &wgsl);
    for f in [
        "motor_gp_motor",
        "motor_rev",
        "motor_sandwich_point",
        "motor_point_matrix",
        "motor_point_matrix_apply",
        "vector_op_vector",
        "vector_lc_bivector",
    ] {
        assert!(has_fn(&m, f), "no fn {f}");
    }
    // The fused sandwich is the Rust module's factored kernel, with its cost in the comment.
    assert!(wgsl.contains("fn motor_sandwich_point(a: Motor, b: Point) -> Point {"));
    assert!(
        wgsl.contains("let c_e1 = a.e12 * b.e2"),
        "field access written tight"
    );
}
