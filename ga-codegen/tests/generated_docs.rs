//! Generated code is reviewable: every doc line starts with a space (`/// text`, never
//! `///text` or `/** .. */`), and every paired-lane kernel carries its scalar symbolic
//! expansion, as klein's kernels do.

use ga_codegen::{generate, EmitOptions, ScalarType, Spec};
use std::path::Path;

fn code(name: &str, scalar: ScalarType, library: bool) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../algebras/{name}.toml"));
    let spec = Spec::from_file(&path).expect("valid spec");
    let opts = EmitOptions {
        scalar,
        library,
        ..EmitOptions::default()
    };
    generate(&spec, &opts)
        .expect("generates")
        .code()
        .expect("formats")
        .to_string()
}

#[test]
fn doc_lines_start_with_a_space() {
    for name in ["cga", "pga3d", "g3", "sta"] {
        for (scalar, library) in [
            (ScalarType::F64, false),
            (ScalarType::F32, false),
            (ScalarType::F64, true),
        ] {
            let code = code(name, scalar, library);
            assert!(!code.contains("/**"), "{name}: a block doc comment");
            assert!(
                !code.contains("#[doc"),
                "{name}: a doc attribute left as such"
            );
            for (i, line) in code.lines().enumerate() {
                let t = line.trim_start();
                if let Some(rest) = t.strip_prefix("///") {
                    assert!(
                        rest.is_empty() || rest.starts_with(' '),
                        "{name} line {}: `{t}`",
                        i + 1
                    );
                }
            }
        }
    }
}

#[test]
fn paired_lane_kernels_carry_their_scalar_expansion() {
    let code = code("cga", ScalarType::F64, false);
    let mut kernels = 0;
    for (i, _) in code.match_indices("paired-lane form") {
        kernels += 1;
        let doc: String = code[i..]
            .lines()
            .take_while(|l| l.trim_start().starts_with("///") || l.contains("paired-lane"))
            .collect::<Vec<_>>()
            .join("\n");
        assert!(doc.contains("Scalar expansion"), "{doc}");
        // Motor * Motor: one line per output field, each a sum of products of `a` and `b`.
        assert!(doc.matches("\n    /// - `").count() >= 4, "{doc}");
        assert!(doc.contains("a.s * b."), "{doc}");
    }
    assert!(kernels >= 4, "only {kernels} paired-lane kernels");
}
