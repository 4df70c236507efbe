//! The closed-form exponentials of [`crate::generator::emit::exp_log`] as WGSL functions
//! (`bivector_exp_scaled_motor`), from the same parts ([`Gen::exp_parts`]) as the Rust
//! `impl Exp<V> for B`, with the scalar helpers written for WGSL (vectors for the tuples,
//! `select` for the branch-free limit, and series where GPUs' `sin` and `sinh` lose the
//! relative precision of small arguments).

use super::text;
use crate::generator::emit::exp_log::ExpBranch;
use crate::generator::emit::render::{float_text, snake};
use crate::generator::emit::Gen;
use std::fmt::Write as _;

/// The shared scalar helpers, as in `decompose::helpers` (f32).
fn helpers() -> String {
    // Taylor coefficients of ds/dl = sum_k k l^(k-1) / (2k+1)!, k = 1..8, used for |l| < 0.1.
    let series: Vec<String> = (1..=8u32)
        .rev()
        .map(|k| {
            let fact: f64 = (1..=2 * k + 1).map(f64::from).product();
            format!("    acc = acc * l + {};", float_text(f64::from(k) / fact))
        })
        .collect();
    format!(
        r#"
// `sin(t)/t` (`l = -t^2`) or `sinh(t)/t` (`l = t^2`) by its series `sum l^k / (2k+1)!`,
// for `|l| < 0.25`: GPUs compute `sin` to an absolute error only (Vulkan allows 2^-11) and
// `sinh` as a difference of exponentials, both useless relative to small `t`.
fn exp_log_s_series(l: f32) -> f32 {{
    return 1.0 + l * (1.0 / 6.0 + l * (1.0 / 120.0 + l * (1.0 / 5040.0 + l * (1.0 / 362880.0))));
}}

// `(c, s)` with `exp(b) = c + s b` for a simple bivector `b` squaring to `l`: `cos t, sin(t)/t`
// (`t = sqrt(-l)`, a rotation), `cosh t, sinh(t)/t` (a boost), `1, 1` (a translation).
fn exp_log_simple(l: f32) -> vec2<f32> {{
    if abs(l) < 0.25 {{
        let t = sqrt(abs(l));
        let c = select(cos(t), cosh(t), l > 0.0);
        return vec2<f32>(c, exp_log_s_series(l));
    }}
    if l < 0.0 {{
        let t = sqrt(-l);
        return vec2<f32>(cos(t), sin(t) / t);
    }}
    let t = sqrt(l);
    return vec2<f32>(cosh(t), sinh(t) / t);
}}

// `d s / d l` of `exp_log_simple` at `l`, given its `(c, s)`: its Taylor series near zero.
fn exp_log_simple_dl(l: f32, c: f32, s: f32) -> f32 {{
    if abs(l) < 0.1 {{
        var acc = 0.0;
{series}
        return acc;
    }}
    return (c - s) / (2.0 * l);
}}

// `sin(x) / x`, by its series below 0.5 (see `exp_log_s_series`).
fn exp_log_sinc(x: f32) -> f32 {{
    if abs(x) < 0.5 {{
        return exp_log_s_series(-x * x);
    }}
    return sin(x) / x;
}}

// The squares `(lo, hi)` of the two commuting parts: the roots of `l^2 - s l + q/4`, neither
// cancelling.
fn exp_log_squares(s: f32, q: f32) -> vec2<f32> {{
    let d = sqrt(max(s * s - q, 0.0));
    if s >= 0.0 {{
        let hi = 0.5 * (s + d);
        let lo = select(0.0, 0.25 * q / hi, hi != 0.0);
        return vec2<f32>(min(lo, hi), max(hi, lo));
    }}
    let lo = 0.5 * (s - d);
    let hi = select(0.0, 0.25 * q / lo, lo != 0.0);
    return vec2<f32>(min(lo, hi), max(hi, lo));
}}

// `(c1 c2, alpha, beta, s1 s2)` with `exp(B) = c1 c2 + alpha B + beta (W B)/2 + s1 s2 W/2`.
fn exp_log_coefficients(l1: f32, l2: f32) -> vec4<f32> {{
    let a = exp_log_simple(l1);
    let b = exp_log_simple(l2);
    let d = l1 - l2;
    let t1 = sqrt(max(-l1, 0.0));
    let t2 = sqrt(max(-l2, 0.0));
    if l1 < 0.0 && l2 < 0.0 && abs(d) <= 0.5 * max(abs(l1), abs(l2)) && t1 * t2 >= 1.1754944e-38 {{
        let fs = exp_log_sinc(t1 + t2);
        let fd = exp_log_sinc(t1 - t2);
        return vec4<f32>(a.x * b.x, 0.5 * (fs + fd), -0.5 * (fs - fd) / (t1 * t2), a.y * b.y);
    }}
    if abs(d) > 5e-3 * max(abs(l1), abs(l2)) {{
        return vec4<f32>(
            a.x * b.x,
            (l1 * a.y * b.x - l2 * a.x * b.y) / d,
            (a.x * b.y - a.y * b.x) / d,
            a.y * b.y,
        );
    }}
    let l = 0.5 * (l1 + l2);
    let m = exp_log_simple(l);
    let ds = exp_log_simple_dl(l, m.x, m.y);
    return vec4<f32>(m.x * m.x, 0.5 * (m.y * m.x + 1.0), 0.5 * m.y * m.y - m.x * ds, m.y * m.y);
}}
"#,
        series = series.join("\n")
    )
}

impl Gen<'_> {
    /// Every exponential of the spec as a WGSL function, after the helpers (nothing when the
    /// spec has none).
    pub(crate) fn wgsl_exps(&mut self, out: &mut String) {
        let spec = self.spec;
        // The complex-pair coefficients have no WGSL helper: those `exp`s are Rust only.
        let pairs: Vec<(usize, usize)> = self
            .exp_pairs()
            .into_iter()
            .filter(|&(bi, vi)| {
                let (_, keep) = self.exp_keep(bi, vi);
                !self.complex_squares(&spec.types[bi], &keep)
            })
            .collect();
        if pairs.is_empty() {
            return;
        }
        out.push_str(&helpers());
        for (bi, vi) in pairs {
            let (bt, vt) = (&spec.types[bi], &spec.types[vi]);
            let (_, keep) = self.exp_keep(bi, vi);
            let p = self.exp_parts(bt, vt, &keep);
            let _ = write!(
                out,
                "\n// The exponential{} of a `{}` into a `{}`, in closed form (as `Exp<{}>` in Rust).\nfn {}_exp_{}(a: {}) -> {} {{\n    let s: f32 = {};\n",
                p.part,
                bt.name,
                vt.name,
                vt.name,
                snake(&bt.name),
                snake(&vt.name),
                bt.name,
                vt.name,
                text(&p.square)
            );
            for (name, vals) in [("w", &p.w), ("wb", &p.wb)] {
                if !vals.is_empty() {
                    let v: Vec<String> = vals.iter().map(text).collect();
                    let _ = writeln!(
                        out,
                        "    let {name} = array<f32, {}>({});",
                        v.len(),
                        v.join(", ")
                    );
                }
            }
            let coeffs = match &p.branch {
                ExpBranch::Simple => "    let cs = exp_log_simple(s);\n    let c = cs.x;\n    let alpha = cs.y;\n    let beta = 0.0;\n    let s12 = 0.0;\n".to_string(),
                ExpBranch::Null => "    let cs = exp_log_simple(s);\n    let c = cs.x;\n    let alpha = cs.y;\n    let beta = select(1.0 / 3.0, (c - cs.y) / s, s != 0.0);\n    let s12 = cs.y;\n".to_string(),
                ExpBranch::General(q) => format!(
                    "    let q = 4.0 * ({});\n    let l = exp_log_squares(s, q);\n    let k = exp_log_coefficients(l.x, l.y);\n    let c = k.x;\n    let alpha = k.y;\n    let beta = k.z;\n    let s12 = k.w;\n",
                    text(q)
                ),
                ExpBranch::Complex(_) => unreachable!("complex spans are filtered out above"),
            };
            out.push_str(&coeffs);
            let fields: Vec<String> = p.fields.iter().map(text).collect();
            let _ = writeln!(out, "    return {}({});\n}}", vt.name, fields.join(", "));
        }
    }
}
