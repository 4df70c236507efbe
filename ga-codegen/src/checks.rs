//! Emits a self-check harness for a generated module: every emitted product, method,
//! sandwich, matrix form and conversion is compared with the slow generic [`crate::Multivector`]
//! on seeded random inputs.
//!
//! The harness is Rust code meant to be included next to the generated module (it uses
//! `super::*`); `tests/` builds it for every spec in `algebras/`.

use crate::blade::grade;
use crate::emit::{snake, Generated};
use crate::spec::Spec;
use std::fmt::Write;

/// Emit the check harness for `spec` and the code generated from it (f64 or f32: the harness
/// reads the module's `Scalar`, and compares in f64 with a tolerance for the scalar type).
/// It defines `pub fn check_all(n: usize, seed: u64) -> (usize, Vec<String>)`, returning the
/// number of comparisons made and a description of each failure.
pub fn emit_checks(spec: &Spec, generated: &Generated, runtime: &str) -> String {
    let rt = runtime;
    let mut s = String::new();
    let n = spec.metric.dim();
    let _ = write!(
        s,
        r#"
use super::*;
use {rt}::Multivector;

/// A small seeded generator (xorshift64*), uniform in [-1, 1).
pub struct Rng(pub u64);
impl Rng {{
    /// Next value.
    pub fn next(&mut self) -> f64 {{
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }}
}}

/// Conversion of a result to the generic multivector.
pub trait ToMv {{
    /// As a generic multivector.
    fn mv(self) -> Multivector;
}}
impl ToMv for f64 {{
    fn mv(self) -> Multivector {{ Multivector::scalar(&algebra(), self) }}
}}
impl ToMv for f32 {{
    fn mv(self) -> Multivector {{ Multivector::scalar(&algebra(), self as f64) }}
}}

/// Relative tolerance of a comparison: 1e-12 for f64, 1e-4 for f32.
pub const TOL: f64 = if ::core::mem::size_of::<Scalar>() == 4 {{ 1e-4 }} else {{ 1e-12 }};

fn check(count: &mut usize, fails: &mut Vec<String>, what: &str, got: Multivector, want: Multivector) {{
    *count += 1;
    let tol = TOL * (1.0 + want.max_abs());
    let finite = got.coeffs().iter().all(|x| x.is_finite());
    if !finite || got.max_diff(&want) > tol {{
        if fails.len() < 50 {{
            fails.push(format!("{{what}}: generated {{got:?}}, generic {{want:?}}"));
        }}
    }}
}}
"#
    );
    for t in &spec.types {
        let sn = snake(&t.name);
        let _ = write!(
            s,
            "impl ToMv for {name} {{ fn mv(self) -> Multivector {{ self.to_multivector() }} }}\n\
             /// A random `{name}` (coefficients uniform in [-1, 1)).\n\
             pub fn rand_{sn}(rng: &mut Rng) -> {name} {{ {name}::from_array(::core::array::from_fn(|_| rng.next() as Scalar)) }}\n",
            name = t.name
        );
        if t.versor {
            let biv: Vec<u32> = t
                .fields
                .iter()
                .filter(|f| grade(f.bitmap) == 2)
                .map(|f| f.bitmap)
                .collect();
            let sets: String = biv
                .iter()
                .map(|b| format!("b.set({b}, rng.next());"))
                .collect();
            if biv.is_empty() {
                // No bivector generator (an odd versor such as a reflection): a random element
                // of the type scaled so that its reversion norm a ~a is +-1.
                let _ = write!(
                    s,
                    "/// A random unit `{name}`: a random element scaled so that `|a ~a| = 1`.\n\
                     pub fn unit_{sn}(rng: &mut Rng) -> {name} {{ let m = rand_{sn}(rng).mv(); let n = m.gp(&m.rev()).get(0).abs().sqrt(); {name}::from_multivector(&m.scale(1.0 / n)) }}\n",
                    name = t.name
                );
            } else {
                let _ = write!(
                    s,
                    "/// A random unit `{name}`: the normalised exponential of a random bivector in the type.\n\
                     pub fn unit_{sn}(rng: &mut Rng) -> {name} {{ let mut b = Multivector::zero(&algebra()); {sets} let m = b.exp(); let m = m.scale(1.0 / m.norm()); {name}::from_multivector(&m) }}\n",
                    name = t.name
                );
            }
        }
    }
    s.push_str(
        "/// Compare every generated function with the generic multivector on `n` random inputs.\n\
         pub fn check_all(n: usize, seed: u64) -> (usize, Vec<String>) {\n\
         let mut rng = Rng(seed.max(1));\n\
         let mut count = 0usize;\n\
         let mut fails = Vec::new();\n\
         let c = &mut count; let f = &mut fails;\n\
         for _ in 0..n {\n",
    );
    for t in &spec.types {
        let sn = snake(&t.name);
        let name = &t.name;
        let _ = write!(
            s,
            "{{ let a = rand_{sn}(&mut rng); let ma = a.mv();\n\
             check(c, f, \"-{name}\", (-a).mv(), -&ma);\n\
             check(c, f, \"{name} * 1.7\", (a * 1.7).mv(), ma.scale(1.7));\n\
             check(c, f, \"1.7 * {name}\", (1.7 * a).mv(), ma.scale(1.7));\n\
             check(c, f, \"{name} / 1.7\", (a / 1.7).mv(), ma.scale(1.0 / 1.7));\n\
             check(c, f, \"{name}::norm_squared\", a.norm_squared().mv(), ma.norm_squared().mv());\n\
             check(c, f, \"{name}::from_multivector\", {name}::from_multivector(&ma).mv(), ma.clone());\n"
        );
        for (tn, m) in &generated.methods {
            if tn != name {
                continue;
            }
            let line = match m.as_str() {
                "rev" | "involute" | "conjugate" | "dual" => {
                    format!("check(c, f, \"{name}::{m}\", a.{m}().mv(), ma.{m}());\n")
                }
                "grade" => (0..=n)
                    .map(|k| format!("check(c, f, \"{name}::grade({k})\", a.grade({k}).mv(), ma.grade({k}));\n"))
                    .collect(),
                "normalized" => format!(
                    "if ma.norm() > 1e-3 {{ check(c, f, \"{name}::normalized\", a.normalized().mv(), ma.scale(1.0 / ma.norm())); }}\n"
                ),
                "inverse" => format!(
                    "if ma.norm_squared().abs() > 1e-3 {{ check(c, f, \"{name}::inverse\", a.inverse().mv(), ma.rev().scale(1.0 / ma.norm_squared())); }}\n"
                ),
                _ => String::new(),
            };
            s.push_str(&line);
        }
        if t.versor {
            // On unit versors the versor inverse is the true inverse: check against the
            // generic inverse (a linear solve), which does not assume anything.
            if t.unit {
                // The generator of true unit versors really gives `u ~u = 1`: the reductions of
                // the sandwiches rely on it.
                let _ = writeln!(
                    s,
                    "{{ let mu = unit_{sn}(&mut rng).mv(); check(c, f, \"unit {name}: u ~u = 1\", mu.gp(&mu.rev()), Multivector::scalar(&algebra(), 1.0)); }}"
                );
            }
            let _ = writeln!(
                s,
                "{{ let u = unit_{sn}(&mut rng); let mu = u.mv(); if let Some(inv) = mu.inverse() {{ check(c, f, \"unit {name}::inverse vs generic inverse\", u.inverse().mv(), inv); }} else {{ f.push(\"unit {name} has no generic inverse\".to_string()); }} }}"
            );
        }
        s.push_str("}\n");
    }
    for o in &generated.ops {
        let (l, r) = (snake(&o.left), snake(&o.right));
        let (ln, rn) = (&o.left, &o.right);
        let body = match o.op.as_str() {
            "*" => format!("check(c, f, \"{ln} * {rn}\", (a * b).mv(), ma.gp(&mb));"),
            "^" => format!("check(c, f, \"{ln} ^ {rn}\", (a ^ b).mv(), ma.outer(&mb));"),
            "|" => format!("check(c, f, \"{ln} | {rn}\", (a | b).mv(), ma.left_contraction(&mb));"),
            "+" => format!("check(c, f, \"{ln} + {rn}\", (a + b).mv(), &ma + &mb);"),
            "-" => format!("check(c, f, \"{ln} - {rn}\", (a - b).mv(), &ma - &mb);"),
            "from" => {
                let _ = writeln!(
                    s,
                    "{{ let a = rand_{l}(&mut rng); check(c, f, \"{rn}::from({ln})\", {rn}::from(a).mv(), a.mv()); }}"
                );
                continue;
            }
            "sandwich" => {
                let vt = spec
                    .types
                    .iter()
                    .find(|t| &t.name == ln)
                    .expect("versor type");
                let gen = if vt.unit { "unit" } else { "rand" };
                let _ = write!(
                    s,
                    "{{ let a = {gen}_{l}(&mut rng); let b = rand_{r}(&mut rng); let (ma, mb) = (a.mv(), b.mv()); let want = ma.gp(&mb).gp(&ma.rev());\n\
                     check(c, f, \"{ln}.sandwich({rn})\", a.sandwich(b).mv(), want.clone());\n\
                     check(c, f, \"{ln}.{r}_matrix().apply({rn})\", a.{r}_matrix().apply(b).mv(), want); }}\n"
                );
                if vt.unit {
                    // A unit versor's sandwich is reduced with `a ~a = 1` and keeps the grades of
                    // the operand: check it also on a product of two true unit versors (a
                    // screw, a boost and a rotation, ...), which is again a unit versor, when that
                    // product stays in the type.
                    let _ = write!(
                        s,
                        "{{ let m2 = unit_{l}(&mut rng).mv().gp(&unit_{l}(&mut rng).mv()); let a = {ln}::from_multivector(&m2);\n\
                         if m2.max_diff(&a.mv()) < 1e-6 {{ let b = rand_{r}(&mut rng); let (ma, mb) = (a.mv(), b.mv()); let want = ma.gp(&mb).gp(&ma.rev());\n\
                         check(c, f, \"{ln}.sandwich({rn}) (product of unit versors)\", a.sandwich(b).mv(), want.clone());\n\
                         check(c, f, \"{ln}.{r}_matrix().apply({rn}) (product of unit versors)\", a.{r}_matrix().apply(b).mv(), want); }} }}\n"
                    );
                }
                continue;
            }
            _ => continue,
        };
        let _ = writeln!(
            s,
            "{{ let a = rand_{l}(&mut rng); let b = rand_{r}(&mut rng); let (ma, mb) = (a.mv(), b.mv()); {body} }}"
        );
    }
    s.push_str("}\n(count, fails)\n}\n");
    let file = syn::parse_file(&s).expect("check harness parses");
    prettyplease::unparse(&file)
}
