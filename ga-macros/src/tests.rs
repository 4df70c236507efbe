//! Unit tests of the expansion, run outside the compiler (proc-macro2's fallback): the inline
//! form expands to exactly the tokens of `ga_codegen::generate` on the equivalent TOML, and
//! errors carry the messages the binary gives. Where errors point is checked by the compile-fail
//! tests in `tests/ui`.

use crate::expand::expand;
use ga_codegen::{generate, EmitOptions, ScalarType, Spec};
use proc_macro2::TokenStream;
use quote::quote;

/// The tokens of the code `ga-codegen` generates for a TOML spec.
fn generated(toml: &str, source: &str, scalar: ScalarType) -> String {
    let spec = Spec::from_toml(toml, source).expect("valid spec");
    let opts = EmitOptions {
        scalar,
        ..EmitOptions::default()
    };
    generate(&spec, &opts)
        .expect("generates")
        .tokens
        .to_string()
}

fn expanded(tokens: TokenStream) -> String {
    expand(tokens)
        .unwrap_or_else(|e| panic!("expansion failed: {e}"))
        .to_string()
}

fn error(tokens: TokenStream) -> String {
    match expand(tokens) {
        Ok(_) => panic!("expected an error"),
        Err(e) => e.to_string(),
    }
}

const CGA_LIKE_TOML: &str = r#"
name = "c2"
doc = "A small conformal algebra."
basis = ["eo", "e1", "ei"]
metric = [[0, 0, -1], [0, 1, 0], [-1, 0, 0]]

[[type]]
name = "Vector"
blades = ["eo", "e1", "ei"]

[[type]]
name = "Point"
doc = "A normalised point.\nTwo lines."
blades = ["eo", "e1", "ei"]
constants = { eo = 1 }

[[type]]
name = "Bivector"
blades = ["e1i", "eo1", "eoi"]

[[type]]
name = "Motor"
blades = ["s", "e1i"]
versor = true
unit = true

[[sandwich]]
versor = "Motor"
operand = "Point"
output = "Point"

[[sandwich]]
versor = "Motor"
operand = "Vector"
"#;

fn cga_like_inline(scalar: TokenStream) -> TokenStream {
    quote! {
        //! A small conformal algebra.
        name = "c2";
        basis = [eo, e1, ei];
        metric = [[0, 0, -1], [0, 1, 0], [-1, 0, 0.0]];
        type Vector { blades = [eo, e1, ei] }
        /// A normalised point.
        /// Two lines.
        type Point { blades = [eo, e1, ei], constants = { eo = 1 } }
        type Bivector { blades = [e1i, "eo1", eoi] }
        type Motor { blades = [s, e1i], versor = true, unit = true, }
        sandwich Motor(Point) -> Point;
        sandwich Motor(Vector);
        #scalar
    }
}

#[test]
fn inline_expands_to_the_generated_code() {
    let want = generated(CGA_LIKE_TOML, "c2.toml", ScalarType::F64);
    assert_eq!(expanded(cga_like_inline(quote!())), want);
    assert_eq!(expanded(cga_like_inline(quote!(scalar = f64;))), want);
    let want32 = generated(CGA_LIKE_TOML, "c2.toml", ScalarType::F32);
    assert_ne!(want, want32);
    assert_eq!(expanded(cga_like_inline(quote!(scalar = f32;))), want32);
}

#[test]
fn inline_builds_the_same_spec_as_toml() {
    let input: crate::grammar::Input = syn::parse2(cga_like_inline(quote!())).unwrap();
    let crate::grammar::Source::Inline(inline) = input.source else {
        panic!("inline")
    };
    let from_tokens = Spec::from_raw(inline.raw, "x").unwrap();
    let from_toml = Spec::from_toml(CGA_LIKE_TOML, "x").unwrap();
    assert_eq!(from_tokens, from_toml);
}

#[test]
fn inline_g3_matches_the_spec_file() {
    let toml = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../algebras/g3.toml"))
        .unwrap();
    let inline = quote! {
        name = "g3";
        doc = "The geometric algebra of Euclidean 3-space G(3,0,0).";
        basis = [e1, e2, e3];
        diagonal = [1, 1, 1];
        type Vector { blades = [e1, e2, e3] }
        type Bivector {
            doc = "A bivector, written with e31 (not e13) as is usual for rotations.",
            blades = [e23, e31, e12],
        }
        type Trivector { blades = [e123] }
        /// A rotor (a unit quaternion in disguise).
        type Rotor { blades = [s, e23, e31, e12], versor = true, unit = true }
        /// The odd part: vectors and the pseudoscalar.
        type Odd { blades = [e1, e2, e3, e123], versor = true }
        sandwich Rotor(Vector) -> Vector;
        sandwich Rotor(Bivector) -> Bivector;
        sandwich Odd(Vector);
    };
    assert_eq!(
        expanded(inline),
        generated(&toml, "algebras/g3.toml", ScalarType::F64)
    );
}

#[test]
fn path_form_expands_to_the_generated_code_and_tracks_the_file() {
    let toml = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../algebras/g3.toml"))
        .unwrap();
    let want = generated(&toml, "../algebras/g3.toml", ScalarType::F32);
    let got = expanded(quote!(path = "../algebras/g3.toml", scalar = f32));
    let rest = got
        .strip_prefix(&want)
        .expect("the generated code comes first");
    assert!(rest.contains("include_bytes"), "{rest}");
    assert!(rest.contains("algebras/g3.toml"), "{rest}");
}

#[test]
fn runtime_path_is_used() {
    let got = expanded(quote! {
        basis = [e1]; diagonal = [1]; runtime = crate::rt;
        type V { blades = [e1] }
    });
    assert!(got.contains("crate :: rt :: Multivector"), "{got}");
    assert!(!got.contains("ga_codegen"), "{got}");
}

#[test]
fn spec_errors_name_the_type_and_blade() {
    let e = error(quote! {
        basis = [e1, e2]; diagonal = [1, 1];
        type V { blades = [e1, e3] }
    });
    assert_eq!(
        e,
        "type `V`: `e3`: unknown blade: not made of the basis names"
    );
    let e = error(quote! {
        basis = [e1, e2]; diagonal = [1, 1];
        type V { blades = [e1], constants = { e2 = 1 } }
    });
    assert_eq!(
        e,
        "type `V`: `e2`: constant on a blade the type does not list"
    );
    let e = error(quote! {
        basis = [e1, e2]; diagonal = [1, 1];
        type V { blades = [e1] }
        type R { blades = [s, e12] }
        sandwich R(V);
    });
    assert_eq!(e, "type `R`: versor type is not marked `versor = true`");
}

#[test]
fn grammar_errors() {
    assert!(error(quote!()).starts_with("missing `basis"));
    assert!(error(quote!(basis = [e1]; diagonal = [1]; metric = [[1]];))
        .contains("only one of `metric`"));
    assert!(error(quote!(basis = [e1]; basis = [e2];)).contains("`basis` given twice"));
    assert!(error(quote!(colour = "red";)).contains("unknown key `colour`"));
    assert!(error(quote!(path = "a.toml"; basis = [e1];)).contains("cannot be given with `path"));
    assert!(
        error(quote!(basis = [e1]; diagonal = [1]; type V { blades = [e1], size = 3 }))
            .contains("unknown field `size` of type `V`")
    );
    assert!(error(quote!(basis = [e1]; diagonal = [x];)).contains("expected a number"));
    assert!(error(quote!(basis = [e1]; diagonal = [1]; scalar = f16;)).contains("`f32` or `f64`"));
}

#[test]
fn path_form_errors_name_the_file() {
    let e = error(quote!(path = "no/such/spec.toml"));
    assert!(
        e.starts_with("cannot read spec file `no/such/spec.toml`"),
        "{e}"
    );
    let dir = std::env::temp_dir().join(format!("ga-macros-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("bad.toml");
    std::fs::write(
        &file,
        "basis = [\"e1\"]\ndiagonal = [1]\n[[type]]\nname = \"V\"\nblades = [\"e2\"]\n",
    )
    .unwrap();
    let lit = file.to_str().unwrap();
    let e = error(quote!(path = #lit));
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(
        e,
        format!("{lit}: type `V`: `e2`: unknown blade: not made of the basis names")
    );
}

#[test]
fn hostile_specs_are_refused_with_the_binary_messages() {
    assert_eq!(
        error(quote!(basis = [e1, e11]; diagonal = [1, 1];)),
        "basis vector `e11`: its suffix starts with the suffix of `e1`, so blade names would be \
         ambiguous (basis suffixes must be prefix-free)"
    );
    assert!(
        error(quote!(basis = [e1, e2, e3]; diagonal = [1e13, 1e13, 1e13];))
            .starts_with("metric entry [0][0] = 10000000000000: exact products")
    );
    assert!(
        error(quote!(basis = [e1, e2, e3]; diagonal = [0.1, 0.2, 1e-30];))
            .starts_with("metric entry [2][2]")
    );
    let e = error(quote! {
        basis = [e1, e2]; diagonal = [1, 1];
        type RVMatrix { blades = [e1] }
    });
    assert!(
        e.starts_with("type `RVMatrix`: type name is reserved: names ending in `Matrix`"),
        "{e}"
    );
    let e = error(quote! {
        basis = [el, ese]; diagonal = [1, 1];
        type B { blades = [else] }
    });
    assert_eq!(
        e,
        "type `B`: `else`: blade name is a Rust keyword and cannot name a field"
    );
    let e = error(
        quote!(basis = [e1, e2, e3, e4, e5, e6, e7, e8, e9]; diagonal = [1, 1, 1, 1, 1, 1, 1, 1, 1];),
    );
    assert!(
        e.starts_with("no type declared: above 6 basis vectors no general multivector"),
        "{e}"
    );
    let e = error(quote!(
        basis = [a, b, c, d, f, g, h, i, j, k, l, m, n, o, p, q, r];
        diagonal = [1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1];
        type V { blades = [a] }
    ));
    assert!(e.contains("17"), "{e}");
}

#[test]
fn decimal_metrics_expand() {
    let got = expanded(quote! {
        basis = [e1, e2, e3]; diagonal = [0.1, 0.3, 0.7];
        type Tri { blades = [e123] }
    });
    assert!(got.contains("0.021 * a . e123 * a . e123"), "{got}");
}
