//! Large algebras with the sparse reference: the DCGA worked example of Easter and Hitzer (a
//! point on an ellipsoid satisfies `P . E = 0`; a rotor moves both), on the sparse reference
//! and, in a fresh crate, on the types the CLI generates from `algebras/dcga.toml`, whose every
//! function is also checked against the sparse reference (`tests/large/dcga_main.rs`). The
//! generator's and the reference's exact routes agree on every DCGA blade pair
//! (`runtime/sparse/blades.rs`). QCGA likewise (`algebras/qcga.toml`, `tests/large/qcga_main.rs`):
//! Breuils, Nozick, Sugimoto and Hitzer's dual quadric from implicit coefficients (`x . Q` is
//! the implicit function) and their quadric through nine points, which holds a tenth. The mother
//! algebra G(4,4) in its null basis (`algebras/mother.toml`, `tests/large/mother_main.rs`):
//! Goldman and Mann's R(4,4) rotors (GL+(3), translator, scaling, pseudoperspective) move points
//! and planes as the 4x4 matrices they stand for, outer products meet planes and join points,
//! and a rotated ellipsoid bivector holds the rotated points; with 8 basis vectors the harness
//! compares with the dense reference, and the example's results also with the sparse one.

use ga_codegen::generator::spec::RawSpec;
use ga_codegen::runtime::sparse::multivector::{SparseAlgebra, SparseMultivector};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

mod fresh_crate;
use std::sync::Arc;

/// The DCGA spec (basis, metric, types) as written.
fn dcga() -> RawSpec {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/dcga.toml");
    toml::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn algebra(raw: &RawSpec) -> Arc<SparseAlgebra> {
    let names: Vec<&str> = raw.basis.iter().map(String::as_str).collect();
    SparseAlgebra::from_metric(&names, raw.metric.as_ref().unwrap()).unwrap()
}

/// The basis vector or blade named `name`, times `x`.
fn blade(alg: &Arc<SparseAlgebra>, name: &str, x: f64) -> SparseMultivector {
    let (b, sign) = alg.parse_blade(name).unwrap();
    SparseMultivector::blade(alg, b, x * f64::from(sign))
}

/// The CGA point of copy `k` (1 or 2): `x + 0.5 |x|^2 eik + eok`.
fn cga_point(alg: &Arc<SparseAlgebra>, k: usize, p: [f64; 3]) -> SparseMultivector {
    let axes = if k == 1 {
        ["e1", "e2", "e3"]
    } else {
        ["e4", "e5", "e6"]
    };
    let mut m = blade(alg, &format!("eo{k}"), 1.0);
    m = m.add_scaled(
        &blade(alg, &format!("ei{k}"), 1.0),
        0.5 * p.iter().map(|x| x * x).sum::<f64>(),
    );
    for (a, x) in axes.iter().zip(p) {
        m = m.add_scaled(&blade(alg, a, 1.0), x);
    }
    m
}

/// The DCGA point `P1 ^ P2`.
fn point(alg: &Arc<SparseAlgebra>, p: [f64; 3]) -> SparseMultivector {
    cga_point(alg, 1, p).outer(&cga_point(alg, 2, p))
}

/// `u ^ v` of two basis vectors.
fn wedge(alg: &Arc<SparseAlgebra>, u: &str, v: &str) -> SparseMultivector {
    blade(alg, u, 1.0).outer(&blade(alg, v, 1.0))
}

/// The ellipsoid `x^2/a^2 + y^2/b^2 + z^2/c^2 = 1` as `T_x^2/a^2 + T_y^2/b^2 + T_z^2/c^2 - T_1`
/// (Easter and Hitzer: `T_x^2 = e6 ^ e1` in their numbering, `T_1 = -ei1 ^ ei2`).
fn ellipsoid(alg: &Arc<SparseAlgebra>, [a, b, c]: [f64; 3]) -> SparseMultivector {
    let t1 = wedge(alg, "ei1", "ei2").scale(-1.0);
    wedge(alg, "e4", "e1")
        .scale(1.0 / (a * a))
        .add_scaled(&wedge(alg, "e5", "e2"), 1.0 / (b * b))
        .add_scaled(&wedge(alg, "e6", "e3"), 1.0 / (c * c))
        .add_scaled(&t1, -1.0)
}

#[test]
fn dcga_point_on_an_ellipsoid_satisfies_its_inner_product_equation() {
    let raw = dcga();
    let alg = algebra(&raw);
    let axes = [2.0, 3.0, 0.5];
    let e = ellipsoid(&alg, axes);
    let implicit = |p: [f64; 3]| {
        p.iter()
            .zip(axes)
            .map(|(x, a)| x * x / (a * a))
            .sum::<f64>()
            - 1.0
    };
    // T_x . P = x: the value-extraction bivector T_x = 0.5 (e1 ^ ei2 + ei1 ^ e4).
    let tx = wedge(&alg, "e1", "ei2")
        .add_scaled(&wedge(&alg, "ei1", "e4"), 1.0)
        .scale(0.5);
    // A rotation by 0.7 about z in both copies: R = R1 R2.
    let half = 0.35f64;
    let r1 = blade(&alg, "e12", -half.sin())
        .add_scaled(&SparseMultivector::scalar(&alg, 1.0), half.cos());
    let r2 = blade(&alg, "e45", -half.sin())
        .add_scaled(&SparseMultivector::scalar(&alg, 1.0), half.cos());
    let r = r1.gp(&r2);
    let moved = |m: &SparseMultivector| r.gp(m).gp(&r.rev());
    let e_moved = moved(&e);
    for (u, v) in [(0.3, 0.4), (1.9, 2.2), (4.0, 1.0), (5.5, 2.9)] {
        let on = [
            axes[0] * f64::cos(u) * f64::sin(v),
            axes[1] * f64::sin(u) * f64::sin(v),
            axes[2] * f64::cos(v),
        ];
        let p = point(&alg, on);
        assert!(
            p.scalar_product(&e).abs() < 1e-12,
            "{on:?}: {}",
            p.scalar_product(&e)
        );
        assert!((tx.scalar_product(&p) - on[0]).abs() < 1e-12);
        // Off the surface, P . E is the implicit function.
        let off = [on[0] * 1.3, on[1] - 0.2, on[2] + 0.1];
        assert!((point(&alg, off).scalar_product(&e) - implicit(off)).abs() < 1e-12);
        // The rotor moves the point to the point of the rotated coordinates, on the moved
        // ellipsoid.
        let (c, s) = (0.7f64.cos(), 0.7f64.sin());
        let rotated = [c * on[0] - s * on[1], s * on[0] + c * on[1], on[2]];
        let pm = moved(&p);
        assert!(pm.max_diff(&point(&alg, rotated)) < 1e-12, "{pm:?}");
        assert!(pm.scalar_product(&e_moved).abs() < 1e-12);
    }
}

/// Generate `algebras/NAME.toml` with the CLI into a fresh crate (`large-flow-NAME`) whose
/// library is the module with its check harness and whose `main` is `main`, then build and
/// run it: the harness against the generic reference (sparse above 8 basis vectors), then the
/// paper's example; `extra` are more files of `src/` (name, text) that `main` includes.
/// Returns the spec, which has no general multivector.
fn cli_flow(name: &str, main: &str, extra: &[(&str, &str)]) -> ga_codegen::Spec {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("ga-codegen-large-{name}"));
    let lib = format!(
        "//! {name} generated by the CLI, with its check harness.\n\
         pub mod {name} {{\n    include!(\"{name}.rs\");\n    \
         /// The check harness against the generic reference.\n    \
         #[allow(unused_variables, clippy::all, missing_docs)]\n    \
         pub mod checks {{\n        include!(\"{name}_checks.rs\");\n    }}\n}}\n"
    );
    let src = fresh_crate::write(&root, &format!("large-flow-{name}"), 1, &lib, main);
    for (file, text) in extra {
        std::fs::write(src.join(file), text).unwrap();
    }
    let spec_path = format!("algebras/{name}.toml");
    let run = Command::new(env!("CARGO_BIN_EXE_ga-codegen"))
        .args([spec_path.as_str(), "-o"])
        .arg(src.join(format!("{name}.rs")))
        .current_dir(&workspace)
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let spec = ga_codegen::Spec::from_file(&workspace.join(&spec_path)).unwrap();
    // The harness's reference: the sparse one above 8 basis vectors, the dense one up to 8
    // (the mother algebra's `main` compares with the sparse one itself).
    assert_eq!(
        spec.sparse_reference(),
        spec.metric.dim() > ga_codegen::generator::spec::MAX_DENSE_REFERENCE_DIMENSION
    );
    let g = ga_codegen::generate(&spec, &ga_codegen::EmitOptions::default()).unwrap();
    assert!(
        !g.skipped.is_empty(),
        "{name} declares no general multivector"
    );
    let checks = ga_codegen::generator::checks::emit_checks(&spec, &g, "::ga_codegen");
    std::fs::write(src.join(format!("{name}_checks.rs")), checks).unwrap();
    fresh_crate::run(&src, &root);
    spec
}

#[test]
fn dcga_generated_by_the_cli_compiles_matches_the_sparse_reference_and_reproduces_the_example() {
    let spec = cli_flow("dcga", include_str!("large/dcga_main.rs"), &[]);
    assert_eq!(spec.metric.dim(), 10);
}

#[test]
fn qcga_generated_by_the_cli_compiles_matches_the_sparse_reference_and_reproduces_the_examples() {
    let motions = ("qcga_motions.rs", include_str!("large/qcga_motions.rs"));
    let spec = cli_flow("qcga", include_str!("large/qcga_main.rs"), &[motions]);
    assert_eq!(spec.metric.dim(), 15);
}

#[test]
fn mother_algebra_generated_by_the_cli_compiles_matches_the_references_and_reproduces_the_maps() {
    let spec = cli_flow("mother", include_str!("large/mother_main.rs"), &[]);
    assert_eq!(spec.metric.dim(), 8);
    assert!(!spec.sparse_reference());
}

/// Every spec in `algebras/` is checked against a generic reference by some test: the small
/// ones by the `tests` crate (`tests/build.rs` generates them with their check harness, run by
/// `tests/tests/generated_vs_generic.rs`), the large ones here by `cli_flow` (generating them
/// in the `tests` crate would compile tens of thousands of lines into every workspace test
/// build). A new spec in `algebras/` fails this test until one of the two lists names it.
#[test]
fn every_spec_in_algebras_is_checked_by_a_test() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let build = std::fs::read_to_string(workspace.join("tests/build.rs")).unwrap();
    let list = build
        .split("for name in [")
        .nth(1)
        .and_then(|rest| rest.split(']').next())
        .expect("tests/build.rs lists its specs as `for name in [...]`");
    let small: Vec<&str> = list
        .split(',')
        .map(|s| s.trim().trim_matches('"'))
        .collect();
    let here = include_str!("large_algebras.rs");
    let large: Vec<&str> = here
        .split("cli_flow(\"")
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .collect();
    assert!(
        small.contains(&"cga") && large.contains(&"qcga"),
        "{small:?} {large:?}"
    );
    let mut specs: Vec<String> = std::fs::read_dir(workspace.join("algebras"))
        .unwrap()
        .filter_map(|e| e.unwrap().file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".toml").map(str::to_string))
        .collect();
    specs.sort();
    assert!(specs.len() >= 7, "{specs:?}");
    for spec in &specs {
        assert!(
            small.contains(&spec.as_str()) || large.contains(&spec.as_str()),
            "algebras/{spec}.toml is checked by no test: add it to tests/build.rs (up to 6 basis \
             vectors) or give it a cli_flow test in ga-codegen/tests/large_algebras.rs"
        );
    }
}
