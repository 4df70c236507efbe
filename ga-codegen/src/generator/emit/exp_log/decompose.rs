//! The invariant decomposition of a bivector (Roelfs and De Keninck, "Graded symmetry groups:
//! plane and simple", 2021), as the emitter uses it: which spans it is closed form on (decided
//! at generation time), and the scalar helper functions every emitted `exp` and `log` shares.
//!
//! A bivector `B` of an algebra of dimension `n <= 5` is a sum `B1 + B2` of at most two
//! commuting simple bivectors, `Bi Bi = li` a scalar. With `B B = s + W` (`s` scalar, `W` of
//! grade 4) and `W W = q` (a scalar for `n <= 5`), `l1 + l2 = s` and `4 l1 l2 = q`, so `l1`
//! and `l2` are the roots of `l^2 - s l + q/4`. They are real when the metric restricted to
//! the span has no two time-like and two space-like directions at once (`min(p, q) <= 1`); then
//! `exp(B) = exp(B1) exp(B2)` is a sum of four terms whose coefficients depend only on `l1`
//! and `l2` (see [`helpers`]). With two of each (G(2,2), G(3,2), G(2,3)) the roots may be a
//! complex-conjugate pair: the four coefficients are symmetric functions of `l1` and `l2`, so
//! they stay real, and `exp` computes them in complex arithmetic ([`complex_helpers`]); `log`
//! reads the pair from the sum and difference of the two (complex) angles, real and imaginary
//! (`log_double.rs`), and the square root takes the halves of the grade-4 part's `J` as
//! complex or split-complex numbers (`normalize.rs`). Above five dimensions a
//! bivector may have three or more parts and the roots are those of a cubic or worse: the
//! emitter refuses it.

use crate::generator::emit::render::float;
use crate::generator::emit::ScalarType;
use crate::runtime::blade::Bitmap;
use crate::runtime::metric::Metric;
use proc_macro2::TokenStream;
use quote::quote;

/// A positive constant as a literal of the scalar type, written with that type's shortest
/// round-trip digits (so f32 code carries no digits f32 cannot hold).
pub(crate) fn constant(scalar: ScalarType, x: f64) -> TokenStream {
    match scalar {
        ScalarType::F64 => float(x),
        ScalarType::F32 => {
            let text = format!("{:?}", x as f32);
            let text = if text.contains('.') || text.contains('e') {
                text
            } else {
                format!("{text}.0")
            };
            text.parse::<proc_macro2::Literal>()
                .map(|l| quote!(#l))
                .unwrap_or_else(|_| float(x))
        }
    }
}

/// Most basis vectors a bivector may span for the closed form (two commuting parts).
pub const MAX_SPAN: u32 = 5;

/// Why a span gets no closed-form exp and log.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// The bivector spans more than five basis vectors (`MAX_SPAN`): three or more commuting parts.
    TooManyDimensions(u32),
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Refusal::TooManyDimensions(k) => write!(
                f,
                "the bivector spans {k} basis vectors: above {MAX_SPAN} it can have three or more commuting simple parts, with no closed-form split"
            ),
        }
    }
}

/// What the decomposition looks like on a span.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpanKind {
    /// Basis vectors spanned.
    pub dimension: u32,
    /// Directions squaring to +1, -1 and 0 (the inertia of the restricted metric).
    pub inertia: (usize, usize, usize),
}

impl SpanKind {
    /// Whether both commuting parts can be rotations (a definite 4-dimensional subspace), which
    /// makes exactly equal squares (isoclinic rotations) possible with a non-simple bivector.
    pub fn double_rotation(&self) -> bool {
        self.inertia.0 >= 4 || self.inertia.1 >= 4
    }

    /// Whether the squares of the two commuting parts can be a complex-conjugate pair (two or
    /// more directions of each sign): `exp` and `log` use [`complex_helpers`] there.
    pub fn complex_squares(&self) -> bool {
        self.inertia.0 >= 2 && self.inertia.1 >= 2
    }
}

/// The union of the basis vectors of `blades`.
pub fn span(blades: impl IntoIterator<Item = Bitmap>) -> Bitmap {
    blades.into_iter().fold(0, |a, b| a | b)
}

/// Decide at generation time whether the closed form applies to bivectors over `span`.
pub fn classify(metric: &Metric, span: Bitmap) -> Result<SpanKind, Refusal> {
    let dimension = span.count_ones();
    if dimension > MAX_SPAN {
        return Err(Refusal::TooManyDimensions(dimension));
    }
    let idx: Vec<usize> = (0..metric.dim()).filter(|i| span >> i & 1 == 1).collect();
    let inertia = inertia(
        &idx.iter()
            .map(|&i| idx.iter().map(|&j| metric.get(i, j).to_f64()).collect())
            .collect::<Vec<Vec<f64>>>(),
    );
    Ok(SpanKind { dimension, inertia })
}

/// Numbers of positive, negative and zero eigenvalues of a small symmetric matrix (cyclic
/// Jacobi rotations; the metric's entries are small exact numbers, so a relative tolerance
/// separates zero from non-zero).
fn inertia(a: &[Vec<f64>]) -> (usize, usize, usize) {
    let n = a.len();
    let mut a = a.to_vec();
    for _ in 0..100 {
        let off: f64 = (0..n)
            .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        if off < 1e-30 {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[p][q] == 0.0 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..n {
                    let (akp, akq) = (a[k][p], a[k][q]);
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for k in 0..n {
                    let (apk, aqk) = (a[p][k], a[q][k]);
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
            }
        }
    }
    let scale = (0..n).map(|i| a[i][i].abs()).fold(1.0, f64::max);
    let mut out = (0, 0, 0);
    for (i, row) in a.iter().enumerate() {
        let d = row[i];
        if d > 1e-9 * scale {
            out.0 += 1;
        } else if d < -1e-9 * scale {
            out.1 += 1;
        } else {
            out.2 += 1;
        }
    }
    out
}

/// The scalar helper functions shared by every emitted `exp` and `log` (private items of the
/// generated module):
///
/// - `exp_log_sin_cos(x) -> (sin x, cos x)` and `exp_log_atan2(y, x)`: libm's in `f64`, the
///   runtime's inlined ones in `f32` ([`crate::runtime::trig`]: no call, so no spills around
///   it; within one ulp);
/// - `exp_log_simple(l) -> (c, s)`: for a simple bivector `b` with `b b = l`,
///   `exp(b) = c + s b`: `cos(t), sin(t)/t` with `t = sqrt(-l)` when `l < 0` (a rotation),
///   `cosh(t), sinh(t)/t` with `t = sqrt(l)` when `l > 0` (a boost), `1, 1` when `l = 0` (a
///   translation, `b b = 0`);
/// - `exp_log_x_over_sin(x, sin x)`: `x / sin x`, by its series near zero (the angle sum and
///   difference of a double rotation's logarithm);
/// - `exp_log_squares(s, q) -> (lo, hi)`: the squares of the two commuting parts, the roots of
///   `l^2 - s l + q/4`, each computed without cancellation (the larger in magnitude by the
///   quadratic formula, the other as `q / (4 root)`);
/// - `exp_log_coefficients(l1, l2) -> [c1 c2, alpha, beta, s1 s2]`: with `Bi = (li B - W B/2) /
///   (li - lj)`, `exp(B) = c1 c2 + alpha B + beta (W B)/2 + s1 s2 W/2`, where
///   `alpha = (l1 s1 c2 - l2 c1 s2)/(l1 - l2)` and `beta = (c1 s2 - s1 c2)/(l1 - l2)`; for two
///   rotations by angles within a factor about 1.4 of each other, by their sum and difference
///   (`sinc(t1 ± t2)`, no division by `l1 - l2`); when other squares are equal to within the
///   cube root of the precision (both near zero, or equal boosts) the limits `alpha = (s c + 1)/2`, `beta = s^2/2 - c ds/dl` at the mean are used, with an
///   error of the order of the squared difference.
pub fn helpers(scalar: ScalarType, rt: &TokenStream) -> TokenStream {
    let s = scalar.tokens();
    let mut out = trig_helpers(scalar, rt);
    out.extend(simple_helpers(scalar, rt));
    out.extend(simple_dl_helper(scalar));
    out.extend(squares_helper(&s));
    out.extend(coefficients_helper(scalar));
    out
}

/// The relative difference under which two squares count as equal (the equal-squares limit
/// is used): the cube root of the unit roundoff, which balances the quotient's rounding
/// against the limit's truncation.
fn equal_squares_tolerance(scalar: ScalarType) -> TokenStream {
    constant(
        scalar,
        match scalar {
            ScalarType::F64 => 6e-6,
            ScalarType::F32 => 5e-3,
        },
    )
}

/// `exp_log_sin_cos` and `exp_log_atan2`: libm's in `f64`, the runtime's inlined `f32` ones.
fn trig_helpers(scalar: ScalarType, rt: &TokenStream) -> TokenStream {
    let (sin_cos, atan2) = match scalar {
        ScalarType::F64 => (quote!(x.sin_cos()), quote!(y.atan2(x))),
        ScalarType::F32 => (
            quote!(#rt::runtime::trig::sin_cos_f32(x)),
            quote!(#rt::runtime::trig::atan2_f32(y, x)),
        ),
    };
    let s = scalar.tokens();
    quote! {
        /// `(sin x, cos x)` (in `f32` evaluated inline, without a libm call).
        #[inline]
        #[allow(dead_code)]
        fn exp_log_sin_cos(x: #s) -> (#s, #s) {
            #sin_cos
        }

        /// `atan2(y, x)` (in `f32` evaluated inline, without a libm call).
        #[inline]
        #[allow(dead_code)]
        fn exp_log_atan2(y: #s, x: #s) -> #s {
            #atan2
        }
    }
}

/// `exp_log_simple`, `exp_log_simple_slope`, `exp_log_sinc` and `exp_log_x_over_sin` over the
/// scalar type; in `f32` the first two take the runtime's series on the principal range
/// ([`crate::runtime::trig::simple_exp_series_f32`]: no square root, call or division).
fn simple_helpers(scalar: ScalarType, rt: &TokenStream) -> TokenStream {
    let s = scalar.tokens();
    let third = constant(scalar, 1.0 / 3.0);
    let (series_simple, series_slope) = match scalar {
        ScalarType::F64 => (TokenStream::new(), TokenStream::new()),
        ScalarType::F32 => (
            quote! {
                if l.abs() <= #rt::runtime::trig::SIMPLE_EXP_SERIES_MAX {
                    let [c, s, _] = #rt::runtime::trig::simple_exp_series_f32(l);
                    return (c, s);
                }
            },
            quote! {
                if l.abs() <= #rt::runtime::trig::SIMPLE_EXP_SERIES_MAX {
                    let [c, s, d] = #rt::runtime::trig::simple_exp_series_f32(l);
                    return (c, s, d);
                }
            },
        ),
    };
    quote! {
        /// `(c, s)` with `exp(b) = c + s b` for a simple bivector `b` squaring to `l`: `cos t,
        /// sin(t)/t` (`t = sqrt(-l)`, a rotation), `cosh t, sinh(t)/t` (`t = sqrt(l)`, a boost),
        /// or `1, 1` (`l = 0`, a null bivector: a translation). Exactly `(1, 1)` at zero and for
        /// squares below the smallest normal number.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_simple(l: #s) -> (#s, #s) {
            #series_simple
            if l < 0.0 {
                let t = (-l).sqrt();
                if t == 0.0 {
                    (1.0, 1.0)
                } else {
                    let (sn, c) = exp_log_sin_cos(t);
                    (c, sn / t)
                }
            } else if l > 0.0 {
                let t = l.sqrt();
                if t == 0.0 { (1.0, 1.0) } else { (t.cosh(), t.sinh() / t) }
            } else {
                (1.0, 1.0)
            }
        }

        /// `(c, s, (c - s) / l)` of [`exp_log_simple`] at `l`, the last `1/3` at `l = 0`.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_simple_slope(l: #s) -> (#s, #s, #s) {
            #series_slope
            let (c, s) = exp_log_simple(l);
            (c, s, if l != 0.0 { (c - s) / l } else { #third })
        }

        /// `sin(x) / x`, by its series below `1e-4`.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_sinc(x: #s) -> #s {
            if x.abs() < 1e-4 {
                let x2 = x * x;
                1.0 - x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0))
            } else {
                exp_log_sin_cos(x).0 / x
            }
        }

        /// `x / sin x` given `sn = sin x` (`x` in `[0, pi]`): its series `1 + x^2/6 +
        /// 7 x^4/360` below `1e-4`, where the quotient would be `0/0` at zero.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_x_over_sin(x: #s, sn: #s) -> #s {
            if x < 1e-4 {
                let x2 = x * x;
                1.0 + x2 * (1.0 / 6.0 + x2 * (7.0 / 360.0))
            } else {
                x / sn
            }
        }
    }
}

/// `exp_log_simple_dl`, with its Taylor series in the scalar type.
fn simple_dl_helper(scalar: ScalarType) -> TokenStream {
    let s = scalar.tokens();
    // Taylor coefficients of ds/dl = sum_k k l^(k-1) / (2k+1)!, k = 1..8, used for |l| < 0.1.
    let series: Vec<TokenStream> = (1..=8u32)
        .map(|k| {
            let fact: f64 = (1..=2 * k + 1).map(f64::from).product();
            constant(scalar, f64::from(k) / fact)
        })
        .rev()
        .collect();
    quote! {
        /// `d s / d l` of [`exp_log_simple`] at `l`, given its `(c, s)` there: `(c - s)/(2 l)`,
        /// or its Taylor series near zero, where that quotient cancels.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_simple_dl(l: #s, c: #s, s: #s) -> #s {
            if l.abs() < 0.1 {
                let mut acc: #s = 0.0;
                #( acc = acc * l + #series; )*
                acc
            } else {
                (c - s) / (2.0 * l)
            }
        }
    }
}

/// `exp_log_squares` over the scalar type `s`.
fn squares_helper(s: &TokenStream) -> TokenStream {
    quote! {
        /// The squares `(lo, hi)` of the two commuting simple parts of a bivector `B` with
        /// `<B B>_0 = s` and `W W = q` (`W = <B B>_4`): the roots of `l^2 - s l + q/4`, the larger
        /// in magnitude by the quadratic formula and the other as `q / (4 root)`, so neither
        /// cancels. A negative discriminant (rounding only, for the spans this module accepts) is
        /// taken as zero.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_squares(s: #s, q: #s) -> (#s, #s) {
            let d = (s * s - q).max(0.0).sqrt();
            if s >= 0.0 {
                let hi = 0.5 * (s + d);
                let lo = if hi != 0.0 { 0.25 * q / hi } else { 0.0 };
                (lo.min(hi), hi.max(lo))
            } else {
                let lo = 0.5 * (s - d);
                let hi = if lo != 0.0 { 0.25 * q / lo } else { 0.0 };
                (lo.min(hi), hi.max(lo))
            }
        }
    }
}

/// `exp_log_coefficients`, with the equal-squares tolerance of the scalar type.
fn coefficients_helper(scalar: ScalarType) -> TokenStream {
    let s = scalar.tokens();
    let tol = equal_squares_tolerance(scalar);
    quote! {
        /// `[c1 c2, alpha, beta, s1 s2]` with `exp(B) = c1 c2 + alpha B + beta (W B)/2 +
        /// s1 s2 W/2` for a bivector whose commuting parts square to `l1` and `l2`
        /// (`W = <B B>_4`). `alpha = (l1 s1 c2 - l2 c1 s2)/(l1 - l2)`, `beta = (c1 s2 - s1 c2)/(l1 - l2)`;
        /// two rotations (`l1, l2 < 0`, `ti = sqrt(-li)`) whose squares are within a factor two
        /// use the sum and difference of their angles instead, `alpha = (sinc(t1 + t2) +
        /// sinc(t1 - t2))/2`, `beta = -(sinc(t1 + t2) - sinc(t1 - t2))/(2 t1 t2)`, exact for
        /// equal angles (isoclinic); otherwise, when the squares agree to within the cube root of
        /// the precision, the limits `alpha = (s c + 1)/2`, `beta = s^2/2 - c ds/dl` at their
        /// mean.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_coefficients(l1: #s, l2: #s) -> [#s; 4] {
            let (c1, s1) = exp_log_simple(l1);
            let (c2, s2) = exp_log_simple(l2);
            let d = l1 - l2;
            let (t1, t2) = ((-l1).max(0.0).sqrt(), (-l2).max(0.0).sqrt());
            if l1 < 0.0 && l2 < 0.0 && d.abs() <= 0.5 * l1.abs().max(l2.abs())
                && t1 * t2 >= #s::MIN_POSITIVE
            {
                // Two rotations by nearly equal angles: by their sum and difference, which
                // divides by neither `d` nor a small product of angles.
                let (fs, fd) = (exp_log_sinc(t1 + t2), exp_log_sinc(t1 - t2));
                [c1 * c2, 0.5 * (fs + fd), -0.5 * (fs - fd) / (t1 * t2), s1 * s2]
            } else if d.abs() > #tol * l1.abs().max(l2.abs()) {
                [
                    c1 * c2,
                    (l1 * s1 * c2 - l2 * c1 * s2) / d,
                    (c1 * s2 - s1 * c2) / d,
                    s1 * s2,
                ]
            } else {
                let l = 0.5 * (l1 + l2);
                let (c, s) = exp_log_simple(l);
                let ds = exp_log_simple_dl(l, c, s);
                [c * c, 0.5 * (s * c + 1.0), 0.5 * s * s - c * ds, s * s]
            }
        }
    }
}

/// Taylor terms of `cosh z` and `sinh(z)/z` in `l = z^2` that the complex series sums (for
/// `|l| <= 1` the next is under `1e-19`).
const SERIES_TERMS: u32 = 11;

/// The helpers of `exp` and `log` on a span whose squares may be complex (emitted only there):
///
/// - `exp_log_x_over_sin_or_sinh(n, c)`: `x / sin x` (`x = atan2(sqrt n, c)`) for
///   `n = sin^2 x >= 0`, `x / sinh x` (`x = asinh(sqrt(-n))`) for `n < 0`, the factor of each
///   half of a double-angle logarithm whose angle may be imaginary;
/// - `exp_log_coefficients_of(s, q) -> [c1 c2, alpha, beta, s1 s2]`, the coefficients of
///   `exp_log_coefficients` from the invariants `s = <B B>_0`, `q = W W`: with real roots
///   (`s^2 >= q`) exactly that; with a complex pair `l = a ± i b` (`a = s/2`,
///   `b = sqrt(q - s^2)/2`), `c1 c2 = |c(l)|^2`, `s1 s2 = |s(l)|^2`,
///   `alpha = Im(l s(l) conj c(l)) / b` and `beta = Im(c(l) conj s(l)) / b`, where
///   `c(l) = cosh(sqrt l)` and `s(l) = sinh(sqrt l)/sqrt l` are taken in complex arithmetic:
///   by their Taylor series in `l` for `|l| <= 1` (no cancellation of `sinh z / z` at small
///   `z`), else from `z = sqrt(l) = u + i v` (`cosh z = cosh u cos v + i sinh u sin v`, ...).
///   When `2b` is within the cube root of the precision of `|l|` the equal-squares limit at `a`
///   is used, as for real squares.
pub fn complex_helpers(scalar: ScalarType) -> TokenStream {
    let s = scalar.tokens();
    let tol = equal_squares_tolerance(scalar);
    let fact = |n: u32| -> f64 { (1..=n).map(f64::from).product() };
    let cosh_terms: Vec<TokenStream> = (0..SERIES_TERMS)
        .rev()
        .map(|k| constant(scalar, 1.0 / fact(2 * k)))
        .collect();
    let sinhc_terms: Vec<TokenStream> = (0..SERIES_TERMS)
        .rev()
        .map(|k| constant(scalar, 1.0 / fact(2 * k + 1)))
        .collect();
    quote! {
        /// `[c1 c2, alpha, beta, s1 s2]` with `exp(B) = c1 c2 + alpha B + beta (W B)/2 +
        /// s1 s2 W/2`, from `s = <B B>_0` and `q = W W`: [`exp_log_coefficients`] of the real
        /// roots of `l^2 - s l + q/4`, or, for a complex pair `l = a ± i b`, the same symmetric
        /// functions in complex arithmetic (`c = cosh(sqrt l)`, `sn = sinh(sqrt l)/sqrt l`):
        /// `|c|^2`, `Im(l sn conj c)/b`, `Im(c conj sn)/b`, `|sn|^2`. By the series in `l` for
        /// `|l| <= 1`; the equal-squares limit when `2 b` is within the cube root of the
        /// precision of `|l|`.
        /// `x / sin x` for `x = atan2(sqrt(n), c)` when `n = sin^2 x >= 0`, or `x / sinh x`
        /// for `x = asinh(sqrt(-n))` when `n = -sinh^2 x < 0` (an imaginary angle): the factor
        /// of the logarithm's part along the sum or difference of two angles. `1` at `n = 0`
        /// from both sides.
        #[inline]
        #[allow(dead_code)]
        fn exp_log_x_over_sin_or_sinh(n: #s, c: #s) -> #s {
            if n >= 0.0 {
                let sn = n.sqrt();
                exp_log_x_over_sin(exp_log_atan2(sn, c), sn)
            } else {
                let sh = (-n).sqrt();
                if sh < 1e-4 {
                    let x2 = sh * sh;
                    1.0 - x2 * (1.0 / 6.0 - x2 * (3.0 / 40.0))
                } else {
                    sh.asinh() / sh
                }
            }
        }

        #[inline]
        #[allow(dead_code)]
        fn exp_log_coefficients_of(s: #s, q: #s) -> [#s; 4] {
            let disc = s * s - q;
            if disc >= 0.0 {
                let (l1, l2) = exp_log_squares(s, q);
                return exp_log_coefficients(l1, l2);
            }
            let a = 0.5 * s;
            let b = 0.5 * (-disc).sqrt();
            let m = a.hypot(b);
            if 2.0 * b <= #tol * m {
                return exp_log_coefficients(a, a);
            }
            let ((cr, ci), (sr, si)) = if m <= 1.0 {
                // Horner's rule in complex arithmetic on the Taylor series in `l`.
                let series = |terms: &[#s]| {
                    let (mut xr, mut xi): (#s, #s) = (0.0, 0.0);
                    for &t in terms {
                        let r = xr * a - xi * b + t;
                        xi = xr * b + xi * a;
                        xr = r;
                    }
                    (xr, xi)
                };
                (series(&[#(#cosh_terms),*]), series(&[#(#sinhc_terms),*]))
            } else {
                // z = sqrt(l) = u + i v (v > 0), each part without cancellation.
                let (u, v) = if a >= 0.0 {
                    let u = (0.5 * (m + a)).sqrt();
                    (u, 0.5 * b / u)
                } else {
                    let v = (0.5 * (m - a)).sqrt();
                    (0.5 * b / v, v)
                };
                let (sv, cv) = exp_log_sin_cos(v);
                let (ch, sh) = (u.cosh(), u.sinh());
                let (hr, hi) = (sh * cv, ch * sv);
                // sinh(z) / z = sinh(z) conj(z) / |z|^2, |z|^2 = |l|.
                ((ch * cv, sh * sv), ((hr * u + hi * v) / m, (hi * u - hr * v) / m))
            };
            let (lr, li) = (a * sr - b * si, a * si + b * sr);
            [
                cr * cr + ci * ci,
                (li * cr - lr * ci) / b,
                (ci * sr - cr * si) / b,
                sr * sr + si * si,
            ]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generator::spec::Spec;

    fn signature(p: usize, q: usize, r: usize) -> Metric {
        Spec::for_signature(p, q, r).expect("spec").metric
    }

    #[test]
    fn inertia_of_known_metrics() {
        assert_eq!(inertia(&[vec![0.0, -1.0], vec![-1.0, 0.0]]), (1, 1, 0));
        assert_eq!(inertia(&[vec![1.0, 0.0], vec![0.0, 0.0]]), (1, 0, 1));
        assert_eq!(inertia(&[vec![2.0, 1.0], vec![1.0, 2.0]]), (2, 0, 0));
    }

    #[test]
    fn spans_refused_and_accepted() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../algebras/cga.toml");
        let cga = Spec::from_file(&path).expect("cga.toml").metric;
        let k = classify(&cga, 0b11111).expect("G(4,1) is closed form");
        assert_eq!(k.inertia, (4, 1, 0));
        assert!(k.double_rotation());
        let e3 = classify(&cga, 0b01110).expect("Euclidean 3D");
        assert!(!e3.double_rotation());
        let g6 = signature(6, 0, 0);
        assert_eq!(classify(&g6, 0b111111), Err(Refusal::TooManyDimensions(6)));
        assert!(classify(&g6, 0b011111).is_ok());
        let g22 = signature(2, 2, 0);
        let k = classify(&g22, 0b1111).expect("G(2,2) is closed form");
        assert!(k.complex_squares());
        assert!(!classify(&g22, 0b0111).expect("G(2,1)").complex_squares());
        assert!(!classify(&cga, 0b11111).expect("CGA").complex_squares());
        let pga = signature(3, 0, 1);
        assert_eq!(classify(&pga, 0b1111).expect("PGA").inertia, (3, 0, 1));
    }
}
