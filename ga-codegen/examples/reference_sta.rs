//! The generic [`Multivector`] (the slow reference every generated function is checked
//! against) in the spacetime algebra G(1,3), and the STA module generated from a spec with the
//! library API, as a library (`--library --wide` on the CLI).
//!
//! ```text
//! cargo run -p ga-codegen --example reference_sta
//! ```
//!
//! Checked: a boost built as `exp(-(phi/2) e01)` by the reference's series exponential equals
//! the closed form `cosh(phi/2) - sinh(phi/2) e01`, moves `e0` to `cosh(phi) e0 + sinh(phi) e1`
//! (the Lorentz transformation of a particle at rest) and keeps the interval; two boosts along
//! x compose to the boost with the summed rapidity (relativistic velocity addition); and the
//! generated module declares the rotor's sandwich and, as a library, its serde and bytemuck
//! impls behind features. Sign conventions as in `algebras/sta.toml`.

use ga_codegen::{generate, Algebra, EmitOptions, Multivector, Spec};
use std::sync::Arc;

const STA: &str = r#"
name = "sta"
doc = "The spacetime algebra G(1,3)."
basis = ["e0", "e1", "e2", "e3"]
diagonal = [1, -1, -1, -1]

[[type]]
name = "Vector"
blades = ["e0", "e1", "e2", "e3"]

[[type]]
name = "Rotor"
doc = "A Lorentz rotor: `cosh(phi/2) - sinh(phi/2) e01` boosts towards +x with rapidity `phi`."
blades = ["s", "e01", "e02", "e03", "e23", "e31", "e12", "e0123"]
versor = true
unit = true

[[sandwich]]
versor = "Rotor"
operand = "Vector"
output = "Vector"
"#;

/// The blade named `name` times `x`.
fn blade(alg: &Arc<Algebra>, name: &str, x: f64) -> Multivector {
    let (b, sign) = alg.parse_blade(name).expect("a blade of G(1,3)");
    Multivector::blade(alg, b, f64::from(sign) * x)
}

/// `R v ~R`.
fn sandwich(r: &Multivector, v: &Multivector) -> Multivector {
    r.gp(v).gp(&r.rev())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let diag = |i: usize| [1.0, -1.0, -1.0, -1.0][i];
    let g: Vec<Vec<f64>> = (0..4)
        .map(|i| (0..4).map(|j| if i == j { diag(i) } else { 0.0 }).collect())
        .collect();
    let alg = Algebra::from_metric(&["e0", "e1", "e2", "e3"], &g)?;

    // A boost by the reference's exponential against its closed form.
    let phi = 0.8_f64;
    let boost = blade(&alg, "e01", -phi / 2.0).exp();
    let closed =
        &Multivector::scalar(&alg, (phi / 2.0).cosh()) + &blade(&alg, "e01", -(phi / 2.0).sinh());
    let err = boost.max_diff(&closed);
    println!("exp(-(phi/2) e01) against cosh - sinh e01: {err:.1e}");
    assert!(err < 1e-14);

    // A particle at rest: e0 -> cosh(phi) e0 + sinh(phi) e1, interval kept.
    let moved = sandwich(&boost, &blade(&alg, "e0", 1.0));
    let want = &blade(&alg, "e0", phi.cosh()) + &blade(&alg, "e1", phi.sinh());
    let err = moved.max_diff(&want);
    let interval = moved.gp(&moved).get_named("s").ok_or("no scalar")?;
    println!("boosted e0 against the Lorentz transformation: {err:.1e}; interval {interval}");
    assert!(err < 1e-14 && (interval - 1.0).abs() < 1e-14);

    // Velocity addition: rapidities add, velocities combine as (u + v) / (1 + u v).
    let (a, b) = (0.5_f64, 0.9_f64);
    let composed = blade(&alg, "e01", -b / 2.0)
        .exp()
        .gp(&blade(&alg, "e01", -a / 2.0).exp());
    let v = sandwich(&composed, &blade(&alg, "e0", 1.0));
    let velocity = v.get_named("e1").ok_or("e1")? / v.get_named("e0").ok_or("e0")?;
    let (u, w) = (a.tanh(), b.tanh());
    let err = (velocity - (u + w) / (1.0 + u * w)).abs();
    println!("composed boosts: velocity {velocity:.15} against (u + v) / (1 + u v): {err:.1e}");
    assert!(err < 1e-15);

    // The module, as the CLI writes it with `--library --wide`.
    let spec = Spec::from_toml(STA, "sta.toml")?;
    let opts = EmitOptions {
        library: true,
        wide: true,
        ..EmitOptions::default()
    };
    let module = generate(&spec, &opts)?;
    let code = module.code()?;
    assert!(code.contains("impl Sandwich<Vector> for Rotor"));
    assert!(code.contains("feature = \"serde\""));
    println!(
        "sta module (library, wide): {} lines, {} types, {} operations",
        module.lines(),
        module.types.len(),
        module.ops.len()
    );
    Ok(())
}
