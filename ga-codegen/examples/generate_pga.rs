//! A PGA module generated from a spec with the library API (the calls the `ga-codegen` CLI
//! makes), inspected, and its products checked against the generic [`Multivector`].
//!
//! ```text
//! cargo run -p ga-codegen --example generate_pga            # summary and checks
//! cargo run -p ga-codegen --example generate_pga -- pga.rs  # also writes the module
//! ```
//!
//! The written file is what `ga-codegen pga.toml -o pga.rs` writes for the same spec: a crate
//! that compiles it depends on `ga-codegen = { version = "0.1", default-features = false }`
//! (the runtime part the module names as `::ga_codegen`), and declares it `pub mod pga;`.
//!
//! What is checked: the module parses; the fused `Motor` sandwich of a `Point` exists; the
//! number of multiply terms the generator kept for `Motor * Motor` equals the number of blade
//! pairs whose product is not zero in the generic algebra (`e0` squares to 0, so PGA drops
//! the pairs that meet in `e0`: nothing cancels between different coefficient products); and
//! `Point ^ Point` (a join, the line through two points) is absent as the spec declares no type
//! holding grade 6, while `Plane ^ Plane` (a meet) returns the declared `Line`.

use ga_codegen::generator::emit::Op;
use ga_codegen::{generate, Algebra, EmitOptions, Multivector, Spec};

/// 3D PGA G(3,0,1) with the conventions of `algebras/pga3d.toml`, cut to what this example
/// uses.
const PGA: &str = r#"
name = "pga"
doc = "3D projective geometric algebra G(3,0,1)."
basis = ["e0", "e1", "e2", "e3"]
diagonal = [0, 1, 1, 1]

[[type]]
name = "Plane"
doc = "A plane `a e1 + b e2 + c e3 + d e0`: the points with `a x + b y + c z + d = 0`."
blades = ["e0", "e1", "e2", "e3"]

[[type]]
name = "Line"
doc = "A line: direction part `e23, e31, e12` and moment part `e01, e02, e03`."
blades = ["e01", "e02", "e03", "e23", "e31", "e12"]

[[type]]
name = "Point"
doc = "A point `x e032 + y e013 + z e021 + w e123`."
blades = ["e032", "e013", "e021", "e123"]

[[type]]
name = "Motor"
doc = "A rigid motion, `exp(-B/2)` of a line `B`."
blades = ["s", "e23", "e31", "e12", "e01", "e02", "e03", "e0123"]
versor = true
unit = true

[[sandwich]]
versor = "Motor"
operand = "Point"
output = "Point"
"#;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // The file to write, if one is named: the header's regenerate command names it too.
    let out = std::env::args().nth(1);
    let spec = Spec::from_toml(PGA, "pga.toml")?;
    let opts = EmitOptions {
        output: out.clone(),
        ..EmitOptions::default()
    };
    let module = generate(&spec, &opts)?;
    let code = module.code()?;

    println!("{} lines; types:", module.lines());
    for (name, fields) in &module.types {
        println!("  {name:8} {fields} fields");
    }
    let find = |op: Op, l: &str, r: &str| {
        module
            .ops
            .iter()
            .find(|s| s.op == op && s.left == l && s.right == r)
    };

    // Motor * Motor: the generator's term count against the generic algebra's non-zero pairs.
    let mm = find(Op::Geometric, "Motor", "Motor").ok_or("no Motor * Motor")?;
    let alg = Algebra::from_metric(
        &["e0", "e1", "e2", "e3"],
        &[
            vec![0.0, 0.0, 0.0, 0.0],
            vec![0.0, 1.0, 0.0, 0.0],
            vec![0.0, 0.0, 1.0, 0.0],
            vec![0.0, 0.0, 0.0, 1.0],
        ],
    )?;
    let motor = ["s", "e23", "e31", "e12", "e01", "e02", "e03", "e0123"];
    let mut pairs = 0;
    for a in motor {
        for b in motor {
            let (ba, _) = alg.parse_blade(a).ok_or("blade")?;
            let (bb, _) = alg.parse_blade(b).ok_or("blade")?;
            let product = Multivector::blade(&alg, ba, 1.0).gp(&Multivector::blade(&alg, bb, 1.0));
            if product.max_abs() > 0.0 {
                pairs += 1;
            }
        }
    }
    println!(
        "Motor * Motor -> {}: {} multiply terms, {} non-zero blade pairs of 64",
        mm.output, mm.terms, pairs
    );
    assert_eq!(mm.terms, pairs, "terms kept against non-zero blade pairs");

    // The meet of two planes is a declared Line; the join of two points (grade 6 > 4) is not
    // a product at all in a 4-dimensional algebra, and Point ^ Point is identically zero.
    let meet = find(Op::Outer, "Plane", "Plane").ok_or("no Plane ^ Plane")?;
    assert_eq!(meet.output, "Line");
    assert!(find(Op::Outer, "Point", "Point").is_none());
    println!(
        "Plane ^ Plane -> {} ({} terms); Point ^ Point not emitted ({} identically zero products skipped)",
        meet.output, meet.terms, module.zero_ops
    );

    // The fused sandwich and its documentation are in the code, named after the blades.
    let sandwich = find(Op::Sandwich, "Motor", "Point").ok_or("no Motor sandwich of Point")?;
    assert!(code.contains("impl Sandwich<Point> for Motor"));
    println!("Motor.sandwich(Point): {} terms", sandwich.terms);

    if let Some(path) = out {
        let path = std::path::Path::new(&path);
        if path.exists() {
            return Err(format!("{} exists: not overwritten", path.display()).into());
        }
        std::fs::write(path, code)?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
