//! Inlined `f32` sine, cosine and arctangent, and the series of a simple bivector's
//! exponential, for the generated `exp` and `log`.
//!
//! The standard library's `sinf`/`cosf`/`atan2f` are calls into libm: every `xmm` register is
//! caller-saved, so an `exp` or `log` in a loop spills its live values around each call, and
//! the call dominates (issue 47: PGA `exp(line)` at 1.10x klein). These evaluate in `f64`
//! inside the caller: a range reduction and a Taylor polynomial whose truncation is below
//! `1e-10` relative, so the single rounding to `f32` at the end is within a hair of correct
//! rounding (tests: at most one ulp from the `f64` libm result rounded to `f32`). Arguments
//! outside the reduced range (`|x| > 1e5` for the sine and cosine, zeros and non-finite values
//! for the arctangent) go to libm, so every input gives libm's answer there.
//!
//! [`simple_exp_series_f32`] goes further for the exponential of a simple bivector `b` with
//! `b b = l`: its coefficients `cos t` and `sin(t)/t` (`t = sqrt(-l)`) are power series in `l`
//! itself, so for the principal range `|l| <= pi^2/4` (rotations up to a half turn each way,
//! every `exp(log(M))`) they need neither the square root, nor a range reduction, nor a
//! division.

use core::f64::consts::{FRAC_PI_2, FRAC_PI_6, PI};

/// Above this `|x|` the sine and cosine go to libm (the two-part `pi/2` below keeps
/// `k pi/2` exact only for `|k| < 2^20`).
const SIN_COS_REDUCED_MAX: f64 = 1.0e5;

/// `1.5 * 2^52`: adding and subtracting it rounds an `|x| < 2^51` to the nearest integer
/// (SSE2 has no rounding instruction).
const ROUND_SHIFT: f64 = 6_755_399_441_055_744.0;

/// `pi/2` to its first 33 bits (so `k * PIO2_HI` is exact for `|k| < 2^20`) ...
const PIO2_HI: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
/// ... and the rest of `pi/2`.
const PIO2_LO: f64 = f64::from_bits(0x3DD0_B461_1A62_6331);

/// `c[0] x^(N-1) + ... + c[N-1]` by Horner's rule (coefficients from the highest power).
#[inline]
fn horner<const N: usize>(c: &[f64; N], x: f64) -> f64 {
    c[1..].iter().fold(c[0], |p, &k| p * x + k)
}

/// `(sin r, cos r)` on `|r| <= pi/4`: the series of [`simple_exp_series_f32`] at `l = -r^2`
/// (`sin r = r sinc`, to `r^15`; `cos r` to `r^14`: truncations under `1e-15`).
#[inline]
fn sin_cos_reduced(r: f64) -> (f64, f64) {
    let l = -r * r;
    let l2 = l * l;
    let l4 = l2 * l2;
    (
        r * estrin7(&SINC_SERIES, l, l2, l4),
        estrin7(&COS_SERIES, l, l2, l4),
    )
}

/// `(sin x, cos x)` for an `f32`, inlined (evaluated in `f64`; libm for `|x| > 1e5`, zeros,
/// NaN and infinities).
///
/// ```
/// let (s, c) = ga_codegen::runtime::trig::sin_cos_f32(0.5);
/// assert!((s - 0.5f32.sin()).abs() <= f32::EPSILON && (c - 0.5f32.cos()).abs() <= f32::EPSILON);
/// ```
#[inline]
#[must_use]
pub fn sin_cos_f32(x: f32) -> (f32, f32) {
    let xd = f64::from(x);
    // Also NaN, and zeros (libm keeps the sign of -0).
    if xd.is_nan() || xd.abs() > SIN_COS_REDUCED_MAX || x == 0.0 {
        return x.sin_cos();
    }
    // x = k pi/2 + r, |r| <= pi/4 (to rounding).
    let k = (xd * (1.0 / FRAC_PI_2) + ROUND_SHIFT) - ROUND_SHIFT;
    let r = (xd - k * PIO2_HI) - k * PIO2_LO;
    let (s, c) = sin_cos_reduced(r);
    // |k| < 2^17 here, so the conversion is exact; `& 3` is k mod 4 for negative k too.
    let q = (k as i64) & 3;
    let (s, c) = if q & 1 == 0 { (s, c) } else { (c, s) };
    let s = if q & 2 == 0 { s } else { -s };
    let c = if (q + 1) & 2 == 0 { c } else { -c };
    (s as f32, c as f32)
}

/// `tan(pi/12)`: above it the arctangent's argument is moved by `pi/6`.
const TAN_PI_12: f64 = 0.267_949_192_431_122_7;
/// `sqrt(3)`.
const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// The Taylor coefficients of `(atan u - u) / u^3` in `u^2`, highest first: to `u^15`
/// (truncation `u^17/17 < 2e-11` on `|u| <= tan(pi/12)`).
const ATAN_SERIES: [f64; 7] = [
    -1.0 / 15.0,
    1.0 / 13.0,
    -1.0 / 11.0,
    1.0 / 9.0,
    -1.0 / 7.0,
    1.0 / 5.0,
    -1.0 / 3.0,
];

/// `atan u` on `|u| <= tan(pi/12)`.
#[inline]
fn atan_reduced(u: f64) -> f64 {
    let u2 = u * u;
    u + u * u2 * horner(&ATAN_SERIES, u2)
}

/// `atan2(y, x)` for `f32`s, inlined (evaluated in `f64` with one division; libm when either
/// is zero or not finite, where the signs of zeros and the infinities decide).
///
/// ```
/// let a = ga_codegen::runtime::trig::atan2_f32(1.0, -2.0);
/// assert!((a - 1.0f32.atan2(-2.0)).abs() <= f32::EPSILON);
/// ```
#[inline]
#[must_use]
pub fn atan2_f32(y: f32, x: f32) -> f32 {
    if !(y.is_finite() && x.is_finite()) || y == 0.0 || x == 0.0 {
        return y.atan2(x);
    }
    let (ay, ax) = (f64::from(y).abs(), f64::from(x).abs());
    // t = n / d in (0, 1]; the angle of (d, n) is atan t, swapped back below.
    let (n, d) = if ay > ax { (ax, ay) } else { (ay, ax) };
    // atan t = pi/6 + atan((t sqrt3 - 1) / (sqrt3 + t)) for t > tan(pi/12), in one division.
    let (base, u) = if n > TAN_PI_12 * d {
        (FRAC_PI_6, (n * SQRT_3 - d) / (d * SQRT_3 + n))
    } else {
        (0.0, n / d)
    };
    let a = base + atan_reduced(u);
    let a = if ay > ax { FRAC_PI_2 - a } else { a };
    let a = if x < 0.0 { PI - a } else { a };
    (a as f32).copysign(y)
}

/// `pi^2 / 4`, rounded down: the largest `|l|` that [`simple_exp_series_f32`] takes (`t =
/// sqrt(-l) <= pi/2`, a rotation by at most a half turn each way).
pub const SIMPLE_EXP_SERIES_MAX: f32 = 2.467_401;

/// `p(l) = c[0] + c[1] l + ... + c[7] l^7` by Estrin's scheme (three levels of products, not
/// seven dependent steps), with `l2 = l^2`, `l4 = l^4` shared by the three series.
#[inline]
fn estrin7(c: &[f64; 8], l: f64, l2: f64, l4: f64) -> f64 {
    let (p01, p23) = (c[0] + c[1] * l, c[2] + c[3] * l);
    let (p45, p67) = (c[4] + c[5] * l, c[6] + c[7] * l);
    (p01 + p23 * l2) + (p45 + p67 * l2) * l4
}

/// `1 / (2n)!`, `n = 0..8`: `cos t = sum l^n / (2n)!` with `l = -t^2` (`cosh` for `l > 0`).
const COS_SERIES: [f64; 8] = [
    1.0,
    1.0 / 2.0,
    1.0 / 24.0,
    1.0 / 720.0,
    1.0 / 40_320.0,
    1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    1.0 / 87_178_291_200.0,
];
/// `1 / (2n+1)!`, `n = 0..8`: `sin(t)/t = sum l^n / (2n+1)!`.
const SINC_SERIES: [f64; 8] = [
    1.0,
    1.0 / 6.0,
    1.0 / 120.0,
    1.0 / 5_040.0,
    1.0 / 362_880.0,
    1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    1.0 / 1_307_674_368_000.0,
];
/// `2(m+1) / (2m+3)!`, `m = 0..8`: `(cos t - sin(t)/t) / l = sum l^m 2(m+1)/(2m+3)!`.
const SLOPE_SERIES: [f64; 8] = [
    2.0 / 6.0,
    4.0 / 120.0,
    6.0 / 5_040.0,
    8.0 / 362_880.0,
    10.0 / 39_916_800.0,
    12.0 / 6_227_020_800.0,
    14.0 / 1_307_674_368_000.0,
    16.0 / 355_687_428_096_000.0,
];

/// `[c, s, d]` for a simple bivector `b` with `b b = l`, `|l| <= pi^2/4`
/// ([`SIMPLE_EXP_SERIES_MAX`]): `exp(b) = c + s b` with `c = cos t`, `s = sin(t)/t`, `t =
/// sqrt(-l)` (`cosh`, `sinh(t)/t` with `t = sqrt(l)` for `l > 0`), and `d = (c - s) / l` (`1/3`
/// at `l = 0`), each by its Taylor series in `l` to `l^7` in `f64` (truncation under `7e-11`),
/// rounded once to `f32`. The caller checks the range; outside it the series lose precision.
///
/// ```
/// let [c, s, d] = ga_codegen::runtime::trig::simple_exp_series_f32(-1.0);
/// assert!((c - 1.0f32.cos()).abs() < 1e-7 && (s - 1.0f32.sin()).abs() < 1e-7);
/// assert!((d - (c - s) / -1.0).abs() < 1e-6);
/// ```
#[inline]
#[must_use]
pub fn simple_exp_series_f32(l: f32) -> [f32; 3] {
    let l = f64::from(l);
    let l2 = l * l;
    let l4 = l2 * l2;
    [
        estrin7(&COS_SERIES, l, l2, l4) as f32,
        estrin7(&SINC_SERIES, l, l2, l4) as f32,
        estrin7(&SLOPE_SERIES, l, l2, l4) as f32,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The distance in `f32` ulps between `got` and the `f64` value `want` rounded to `f32`.
    fn ulps(got: f32, want: f64) -> u32 {
        let want = want as f32;
        if got == want {
            return 0;
        }
        let key = |v: f32| {
            let b = v.to_bits() as i32;
            if b < 0 {
                i32::MIN - b
            } else {
                b
            }
        };
        (i64::from(key(got)) - i64::from(key(want))).unsigned_abs() as u32
    }

    /// A deterministic spread of `f32`s: random bits of every exponent up to `max_exp`.
    fn samples(count: usize, max_abs: f32) -> Vec<f32> {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut out = Vec::with_capacity(count);
        while out.len() < count {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let v = f32::from_bits((state >> 32) as u32);
            if v.is_finite() && v.abs() <= max_abs {
                out.push(v);
            }
        }
        out
    }

    #[test]
    fn sine_and_cosine_are_within_one_ulp_of_the_correctly_rounded_values() {
        let mut xs = samples(400_000, 2.0e5);
        // Near multiples of pi/2 (where the reduction cancels) and the range's ends.
        for k in -2000i32..=2000 {
            let c = f64::from(k) * FRAC_PI_2;
            let x = c as f32;
            xs.extend([
                x,
                f32::from_bits(x.to_bits() + 1),
                f32::from_bits(x.to_bits().max(1) - 1),
            ]);
        }
        xs.extend([
            0.0, -0.0, 1.0e5, -1.0e5, 99_999.99, 1.0e-30, -1.0e-30, 1.0e-45,
        ]);
        let mut worst = 0;
        for &x in &xs {
            let (s, c) = sin_cos_f32(x);
            let (ws, wc) = (f64::from(x).sin(), f64::from(x).cos());
            worst = worst.max(ulps(s, ws)).max(ulps(c, wc));
            assert!(
                ulps(s, ws) <= 1 && ulps(c, wc) <= 1,
                "x = {x:e}: ({s:e}, {c:e}) against ({ws:e}, {wc:e})"
            );
        }
        assert!(worst <= 1, "worst {worst} ulps");
        assert_eq!(sin_cos_f32(-0.0).0.to_bits(), (-0.0f32).to_bits());
    }

    #[test]
    fn sine_and_cosine_outside_the_range_are_libm_s() {
        for x in [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            1.0e30,
            -3.0e6,
            100_001.0,
        ] {
            let (s, c) = sin_cos_f32(x);
            let (ls, lc) = x.sin_cos();
            assert!(
                s.to_bits() == ls.to_bits() || (s.is_nan() && ls.is_nan()),
                "{x}"
            );
            assert!(
                c.to_bits() == lc.to_bits() || (c.is_nan() && lc.is_nan()),
                "{x}"
            );
        }
    }

    #[test]
    fn arctangent_is_within_one_ulp_of_the_correctly_rounded_value_in_every_quadrant() {
        let ys = samples(300_000, f32::MAX);
        let xs = samples(300_001, f32::MAX);
        let mut pairs: Vec<(f32, f32)> = ys
            .iter()
            .zip(xs.iter().rev())
            .map(|(&y, &x)| (y, x))
            .collect();
        // Ratios near the reduction's switch points and the quadrant boundaries.
        for (y, x) in [
            (1.0f32, 1.0f32),
            (-1.0, 1.0),
            (1.0, -1.0),
            (-1.0, -1.0),
            (0.267_949_2, 1.0),
        ] {
            for i in 0..50u32 {
                let y = f32::from_bits(y.to_bits() + i);
                pairs.push((y, x));
                pairs.push((x, y));
            }
        }
        pairs.extend([
            (1.0e-38, 3.0e38),
            (3.0e38, 1.0e-38),
            (1.0e-45, -1.0),
            (-5.0, 1.0e-45),
        ]);
        for (y, x) in pairs {
            let a = atan2_f32(y, x);
            let want = f64::from(y).atan2(f64::from(x));
            assert!(
                ulps(a, want) <= 1,
                "atan2({y:e}, {x:e}) = {a:e}, want {want:e}"
            );
        }
    }

    #[test]
    fn the_series_of_a_simple_exponential_agree_with_the_closed_forms_over_the_principal_range() {
        let max = f64::from(SIMPLE_EXP_SERIES_MAX);
        assert!(max <= std::f64::consts::PI.powi(2) / 4.0);
        let mut ls: Vec<f64> = (0..=20_000)
            .map(|i| max * (f64::from(i) / 10_000.0 - 1.0))
            .collect();
        ls.extend([0.0, 1e-30, -1e-30, 1e-8, -1e-8, max, -max]);
        for l in ls {
            let [c, s, d] = simple_exp_series_f32(l as f32);
            let l = f64::from(l as f32);
            let (wc, ws) = if l < 0.0 {
                let t = (-l).sqrt();
                (t.cos(), t.sin() / t)
            } else if l > 0.0 {
                let t = l.sqrt();
                (t.cosh(), t.sinh() / t)
            } else {
                (1.0, 1.0)
            };
            // The quotient cancels in f64 too near zero: compare with its series' first terms.
            let wd = if l.abs() > 1e-2 {
                (wc - ws) / l
            } else {
                1.0 / 3.0 + l / 30.0 + l * l / 840.0
            };
            let close = |got: f32, want: f64| {
                let tol = f64::from(f32::EPSILON) * want.abs().max(1e-3);
                (f64::from(got) - want).abs() <= tol
            };
            assert!(
                close(c, wc) && close(s, ws) && close(d, wd),
                "l = {l:e}: [{c}, {s}, {d}] against [{wc}, {ws}, {wd}]"
            );
        }
        assert_eq!(simple_exp_series_f32(0.0), [1.0, 1.0, 1.0 / 3.0]);
    }

    #[test]
    fn arctangent_of_zeros_and_infinities_is_libm_s() {
        let special = [
            0.0f32,
            -0.0,
            1.0,
            -1.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        for &y in &special {
            for &x in &special {
                let (a, l) = (atan2_f32(y, x), y.atan2(x));
                if y.is_finite() && x.is_finite() && y != 0.0 && x != 0.0 {
                    assert!(ulps(a, f64::from(y).atan2(f64::from(x))) <= 1, "({y}, {x})");
                } else {
                    assert!(
                        a.to_bits() == l.to_bits() || (a.is_nan() && l.is_nan()),
                        "({y}, {x})"
                    );
                }
            }
        }
    }
}
