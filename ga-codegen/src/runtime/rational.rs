//! Exact rational numbers for metric entries and product coefficients.
//!
//! The generator never rounds: a metric such as the CGA null basis (`eo.ei = -1`) gives
//! coefficients that are small rationals, and terms that cancel cancel exactly.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact rational number `num / den` with `den > 0`, `gcd(num, den) = 1` and
/// `num != i128::MIN` (so negation and absolute values never overflow).
///
/// Every operation is checked: the `checked_*` methods return `None` on overflow, and the
/// operators panic with a message instead of wrapping (which would silently give a wrong
/// product). Specs are checked up front (`spec::exact`) so that generation never reaches
/// that panic.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Rational {
    num: i128,
    den: i128,
}

/// What the operators say when exact arithmetic leaves 128 bits.
const OVERFLOW: &str =
    "exact rational arithmetic overflowed 128 bits (specs are checked for this up front)";

fn gcd(a: i128, b: i128) -> u128 {
    let (mut a, mut b) = (a.unsigned_abs(), b.unsigned_abs());
    if a == 1 || b == 1 {
        return 1;
    }
    if let (Ok(x), Ok(y)) = (u64::try_from(a), u64::try_from(b)) {
        // The same Euclid in 64 bits: one machine division a step instead of a 128-bit call.
        let (mut x, mut y) = (x, y);
        while y != 0 {
            (x, y) = (y, x % y);
        }
        return x.into();
    }
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

/// `n / d` correctly rounded to `f64`, for `n, d < 2^127`, `d > 0`: the quotient's leading 64
/// bits `q` with `n / d = (q + f) 2^e`, `0 <= f < 1`; a non-zero `f` sets `q`'s lowest bit
/// (below the 53 kept, so it only breaks what would read as a tie), and the conversion of `q`
/// rounds to nearest even. The quotient lies in `[2^-127, 2^127]`, so scaling by `2^e` is exact.
fn quotient_f64(n: u128, d: u128) -> f64 {
    if n == 0 {
        return 0.0;
    }
    let (mut q, mut r) = (n / d, n % d);
    let mut e: i32 = 0;
    let bits = 128 - q.leading_zeros();
    if bits > 64 {
        let shift = bits - 64;
        let dropped = q & ((1u128 << shift) - 1);
        q >>= shift;
        e = shift as i32;
        if dropped != 0 {
            r = 1;
        }
    } else {
        // The next bits of the fraction, one at a time (r < d < 2^127, so 2r fits).
        while q < (1u128 << 63) {
            r <<= 1;
            q <<= 1;
            if r >= d {
                r -= d;
                q |= 1;
            }
            e -= 1;
        }
    }
    let sticky = u64::from(r != 0);
    (q as u64 | sticky) as f64 * 2f64.powi(e)
}

/// `a / b` compared with `c / d` for positive denominators, by continued fractions (no
/// product can overflow).
fn cmp_fractions(mut a: u128, mut b: u128, mut c: u128, mut d: u128) -> Ordering {
    loop {
        let (q1, r1) = (a / b, a % b);
        let (q2, r2) = (c / d, c % d);
        if q1 != q2 {
            return q1.cmp(&q2);
        }
        match (r1 == 0, r2 == 0) {
            (true, true) => return Ordering::Equal,
            (true, false) => return Ordering::Less,
            (false, true) => return Ordering::Greater,
            (false, false) => {}
        }
        // r1/b < r2/d  <=>  d/r2 < b/r1
        (a, b, c, d) = (d, r2, b, r1);
    }
}

impl Rational {
    /// Zero.
    pub const ZERO: Rational = Rational { num: 0, den: 1 };
    /// One.
    pub const ONE: Rational = Rational { num: 1, den: 1 };

    /// The `n x n` identity matrix, row by row.
    pub fn identity_matrix(n: usize) -> Vec<Vec<Rational>> {
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        if i == j {
                            Rational::ONE
                        } else {
                            Rational::ZERO
                        }
                    })
                    .collect()
            })
            .collect()
    }

    /// The integer `num` (what `checked_new(num, 1)` gives, without its gcd); `None` for
    /// `i128::MIN`, whose negation does not fit.
    fn integer(num: i128) -> Option<Rational> {
        (num != i128::MIN).then_some(Rational { num, den: 1 })
    }

    /// `num / den`, reduced; `None` when `den == 0` or the value does not fit.
    pub fn checked_new(num: i128, den: i128) -> Option<Rational> {
        if den == 0 {
            return None;
        }
        let Ok(g) = i128::try_from(gcd(num, den).max(1)) else {
            // gcd = 2^127: den is i128::MIN and num is 0 or i128::MIN.
            return Some(if num == 0 {
                Rational::ZERO
            } else {
                Rational::ONE
            });
        };
        let (mut num, mut den) = (num / g, den / g);
        if den < 0 {
            num = num.checked_neg()?;
            den = den.checked_neg()?;
        }
        if num == i128::MIN {
            return None;
        }
        Some(Rational { num, den })
    }

    /// `num / den`, reduced. Panics if `den == 0` or on overflow (never reached from user
    /// input: callers construct denominators from non-zero pivots of checked specs only).
    pub fn new(num: i128, den: i128) -> Rational {
        assert!(den != 0, "rational with zero denominator");
        Rational::checked_new(num, den).expect(OVERFLOW)
    }

    /// An integer.
    pub fn int(n: i64) -> Rational {
        Rational {
            num: n as i128,
            den: 1,
        }
    }

    /// The decimal an `f64` prints as, exactly: its shortest round-trip form (`0.1` is
    /// 1/10, not the nearest double; `0.5`, `-3`, `1e20` are what they say). This is what a
    /// user wrote in a spec whenever the literal has at most 15 significant digits. `None` for
    /// NaN, infinities and values whose numerator or denominator do not fit in 127 bits
    /// (`1e300`, `1e-320`). `-0.0` is zero.
    pub fn from_f64(x: f64) -> Option<Rational> {
        if !x.is_finite() {
            return None;
        }
        if x == 0.0 {
            return Some(Rational::ZERO);
        }
        Rational::from_decimal(&format!("{x:e}"))
    }

    /// A decimal in scientific or plain notation (`-1.25e-3`, `12`, `0.5`), exactly; `None`
    /// when it is malformed or does not fit.
    pub fn from_decimal(text: &str) -> Option<Rational> {
        let (mantissa, exp) = match text.find(['e', 'E']) {
            Some(i) => (&text[..i], text[i + 1..].parse::<i32>().ok()?),
            None => (text, 0),
        };
        let (neg, mantissa) = match mantissa.strip_prefix('-') {
            Some(m) => (true, m),
            None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
        };
        let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        if int.is_empty() && frac.is_empty()
            || !int.bytes().chain(frac.bytes()).all(|b| b.is_ascii_digit())
        {
            return None;
        }
        let mut num: i128 = 0;
        for b in int.bytes().chain(frac.bytes()) {
            num = num.checked_mul(10)?.checked_add(i128::from(b - b'0'))?;
        }
        let exp = i64::from(exp) - frac.len() as i64;
        let pow = 10i128.checked_pow(u32::try_from(exp.unsigned_abs()).ok()?)?;
        let (num, den) = if exp >= 0 {
            (num.checked_mul(pow)?, 1)
        } else {
            (num, pow)
        };
        Rational::checked_new(if neg { -num } else { num }, den)
    }

    /// Numerator.
    pub fn numer(self) -> i128 {
        self.num
    }

    /// Denominator (positive).
    pub fn denom(self) -> i128 {
        self.den
    }

    /// `|self|`.
    #[must_use]
    pub fn abs(self) -> Rational {
        if self < Rational::ZERO {
            -self
        } else {
            self
        }
    }

    /// True for zero.
    pub fn is_zero(self) -> bool {
        self.num == 0
    }

    /// The nearest `f64` (correctly rounded, ties to even). Where numerator and denominator
    /// are both at most 2^53 this is one division; beyond, the quotient's leading 64 bits
    /// come from a long division, so the numerator and the denominator are not rounded first
    /// (which could land one unit in the last place off).
    pub fn to_f64(self) -> f64 {
        const EXACT: u128 = 1 << 53;
        let (n, d) = (self.num.unsigned_abs(), self.den.unsigned_abs());
        let magnitude = if n <= EXACT && d <= EXACT {
            n as f64 / d as f64
        } else {
            quotient_f64(n, d)
        };
        if self.num < 0 {
            -magnitude
        } else {
            magnitude
        }
    }

    /// `1 / self`; `None` for zero.
    pub fn recip(self) -> Option<Rational> {
        if self.num == 0 {
            None
        } else {
            Rational::checked_new(self.den, self.num)
        }
    }

    /// `self + o`, or `None` on overflow.
    pub fn checked_add(self, o: Rational) -> Option<Rational> {
        if self.den == 1 && o.den == 1 {
            return Rational::integer(self.num.checked_add(o.num)?);
        }
        let g = i128::try_from(gcd(self.den, o.den)).ok()?;
        let (da, db) = (self.den / g, o.den / g);
        let num = self
            .num
            .checked_mul(db)?
            .checked_add(o.num.checked_mul(da)?)?;
        Rational::checked_new(num, da.checked_mul(o.den)?)
    }

    /// `self - o`, or `None` on overflow.
    pub fn checked_sub(self, o: Rational) -> Option<Rational> {
        self.checked_add(-o)
    }

    /// `self * o`, or `None` on overflow (cross-reduced first, so a product that fits is
    /// always found).
    pub fn checked_mul(self, o: Rational) -> Option<Rational> {
        if self.den == 1 && o.den == 1 {
            return Rational::integer(self.num.checked_mul(o.num)?);
        }
        if let (Ok(a), Ok(b), Ok(c), Ok(d)) = (
            i64::try_from(self.num),
            i64::try_from(self.den),
            i64::try_from(o.num),
            i64::try_from(o.den),
        ) {
            // The same cross-reduction in 64 bits; the result is then already reduced, with
            // a positive denominator (what `checked_new` would return).
            let g1 = (gcd(a.into(), d.into()).max(1)) as i64;
            let g2 = (gcd(c.into(), b.into()).max(1)) as i64;
            let num = i128::from(a / g1) * i128::from(c / g2);
            let den = i128::from(b / g2) * i128::from(d / g1);
            return (num != i128::MIN).then_some(Rational { num, den });
        }
        let g1 = i128::try_from(gcd(self.num, o.den).max(1)).ok()?;
        let g2 = i128::try_from(gcd(o.num, self.den).max(1)).ok()?;
        let num = (self.num / g1).checked_mul(o.num / g2)?;
        let den = (self.den / g2).checked_mul(o.den / g1)?;
        Rational::checked_new(num, den)
    }

    /// `self / o`, or `None` when `o` is zero or on overflow.
    pub fn checked_div(self, o: Rational) -> Option<Rational> {
        self.checked_mul(o.recip()?)
    }

    /// Number of bits of the larger of `|numerator|` and the denominator: a product of
    /// values of heights `h1`, `h2` has height at most `h1 + h2`.
    pub fn height(self) -> u32 {
        128 - self
            .num
            .unsigned_abs()
            .max(self.den as u128)
            .leading_zeros()
    }
}

impl From<i64> for Rational {
    fn from(n: i64) -> Rational {
        Rational::int(n)
    }
}

impl Add for Rational {
    type Output = Rational;
    fn add(self, o: Rational) -> Rational {
        self.checked_add(o).expect(OVERFLOW)
    }
}

impl Sub for Rational {
    type Output = Rational;
    fn sub(self, o: Rational) -> Rational {
        self.checked_sub(o).expect(OVERFLOW)
    }
}

impl Mul for Rational {
    type Output = Rational;
    fn mul(self, o: Rational) -> Rational {
        self.checked_mul(o).expect(OVERFLOW)
    }
}

impl Div for Rational {
    type Output = Rational;
    fn div(self, o: Rational) -> Rational {
        assert!(!o.is_zero(), "division by zero rational");
        self.checked_div(o).expect(OVERFLOW)
    }
}

impl Neg for Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        // num != i128::MIN by construction.
        Rational {
            num: -self.num,
            den: self.den,
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, o: &Rational) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for Rational {
    fn cmp(&self, o: &Rational) -> Ordering {
        let by_sign = self.num.signum().cmp(&o.num.signum());
        if by_sign != Ordering::Equal || self.num == 0 {
            return by_sign;
        }
        let mag = cmp_fractions(
            self.num.unsigned_abs(),
            self.den as u128,
            o.num.unsigned_abs(),
            o.den as u128,
        );
        if self.num < 0 {
            mag.reverse()
        } else {
            mag
        }
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_exact() {
        let a = Rational::new(1, 3);
        let b = Rational::new(1, 6);
        assert_eq!(a + b, Rational::new(1, 2));
        assert_eq!(a - a, Rational::ZERO);
        assert_eq!(a * b, Rational::new(1, 18));
        assert_eq!(a / b, Rational::int(2));
        assert_eq!(Rational::new(2, -4), Rational::new(-1, 2));
    }

    /// The integer and 64-bit routes of `checked_mul` and `checked_add` (and of `gcd`) give
    /// what the general 128-bit route gives: `checked_new` of the plain cross products.
    #[test]
    fn fast_paths_match_the_general_route() {
        let big = 1i128 << 70;
        let values: Vec<Rational> = [
            (0, 1),
            (1, 1),
            (-1, 1),
            (7, 1),
            (-12, 1),
            (1, 2),
            (-3, 2),
            (5, 6),
            (-14, 15),
            (i64::MAX as i128, 1),
            (i64::MIN as i128 + 1, 3),
            (big + 1, 1),
            (-big, 3),
            (3, big + 1),
            (1, (1 << 62) + 1),
        ]
        .iter()
        .map(|&(n, d)| Rational::new(n, d))
        .collect();
        for &a in &values {
            for &b in &values {
                let mul = a
                    .num
                    .checked_mul(b.num)
                    .zip(a.den.checked_mul(b.den))
                    .and_then(|(n, d)| Rational::checked_new(n, d));
                if let Some(m) = mul {
                    assert_eq!(a.checked_mul(b), Some(m), "{a:?} * {b:?}");
                }
                let add = a
                    .num
                    .checked_mul(b.den)
                    .zip(b.num.checked_mul(a.den))
                    .and_then(|(x, y)| x.checked_add(y))
                    .zip(a.den.checked_mul(b.den))
                    .and_then(|(n, d)| Rational::checked_new(n, d));
                if let Some(s) = add {
                    assert_eq!(a.checked_add(b), Some(s), "{a:?} + {b:?}");
                }
            }
        }
        assert_eq!(gcd(12, 18), 6);
        assert_eq!(gcd(big * 6, big * 4), (big * 2) as u128);
        assert_eq!(gcd(0, 5), 5);
        assert_eq!(gcd(1, 0), 1);
    }

    #[test]
    fn to_f64_rounds_once() {
        // Expected values from Python's `float(Fraction(n, d))` (correctly rounded). Rounding
        // the numerator and the denominator before dividing is one unit off on two of them.
        let cases: [(i128, i128, f64); 10] = [
            ((1 << 53) + 1, 1, 9007199254740992.0),
            ((1 << 54) + 3, 2, 9007199254740994.0),
            (-((1 << 53) + 1), 3, -3002399751580331.0),
            ((1 << 53) + 3, (1 << 53) + 1, 1.0000000000000002),
            ((1 << 60) + 1, (1 << 58) + 3, 4.0),
            (i128::MAX, 3, 5.671372782015641e37),
            (1, i128::MAX, 5.877471754111438e-39),
            (-7, (1 << 100) + 1, -5.5220263365470826e-30),
            (1, 3, 0.3333333333333333),
            (-2, 7, -0.2857142857142857),
        ];
        for (n, d, want) in cases {
            let got = Rational::new(n, d).to_f64();
            assert_eq!(
                got.to_bits(),
                want.to_bits(),
                "{n} / {d}: {got:e} against {want:e}"
            );
        }
    }

    #[test]
    fn from_f64_is_exact_for_dyadics() {
        assert_eq!(Rational::from_f64(0.5), Some(Rational::new(1, 2)));
        assert_eq!(Rational::from_f64(-3.0), Some(Rational::int(-3)));
        assert_eq!(Rational::from_f64(f64::NAN), None);
        assert_eq!(Rational::from_f64(f64::INFINITY), None);
        assert_eq!(Rational::from_f64(f64::NEG_INFINITY), None);
        assert_eq!(Rational::from_f64(-0.0), Some(Rational::ZERO));
        assert_eq!(Rational::from_f64(0.1).map(|r| r.to_f64()), Some(0.1));
    }

    #[test]
    fn from_f64_reads_the_decimal_written() {
        assert_eq!(Rational::from_f64(0.1), Some(Rational::new(1, 10)));
        assert_eq!(Rational::from_f64(0.3), Some(Rational::new(3, 10)));
        assert_eq!(Rational::from_f64(-0.7), Some(Rational::new(-7, 10)));
        assert_eq!(
            Rational::from_f64(0.3333333333333333),
            Some(Rational::new(3333333333333333, 10i128.pow(16)))
        );
        assert_eq!(
            Rational::from_f64(1e13),
            Some(Rational::new(10i128.pow(13), 1))
        );
        assert_eq!(Rational::from_f64(1.5e-3), Some(Rational::new(3, 2000)));
        // Too large or too small to hold in 127 bits.
        assert_eq!(Rational::from_f64(1e300), None);
        assert_eq!(Rational::from_f64(1e-320), None);
        assert_eq!(Rational::from_f64(f64::MAX), None);
        // Round trip for every decimal with few digits.
        for x in [
            0.1,
            0.2,
            0.3,
            0.7,
            1e-7,
            123.456,
            -2.5e10,
            0.3333333333333333,
        ] {
            assert_eq!(Rational::from_f64(x).unwrap().to_f64(), x);
        }
    }

    #[test]
    fn from_decimal_rejects_malformed_text() {
        for bad in ["", ".", "-", "1e", "e5", "1.2.3", "0x10", "1e99999999999"] {
            assert_eq!(Rational::from_decimal(bad), None, "{bad}");
        }
        assert_eq!(Rational::from_decimal("+2.50"), Some(Rational::new(5, 2)));
    }

    #[test]
    fn checked_arithmetic_reports_overflow() {
        let big = Rational::new(i128::MAX, 1);
        assert_eq!(big.checked_add(Rational::ONE), None);
        assert_eq!(big.checked_mul(Rational::int(2)), None);
        assert_eq!((-big).checked_sub(Rational::int(2)), None);
        assert_eq!(Rational::ONE.checked_div(Rational::ZERO), None);
        let tiny = Rational::new(1, i128::MAX);
        assert_eq!(tiny.checked_mul(Rational::new(1, 3)), None);
        // Cross-reduction finds products that fit.
        assert_eq!(tiny.checked_mul(big), Some(Rational::ONE));
        assert_eq!(Rational::checked_new(i128::MIN, 1), None);
        assert_eq!(
            Rational::checked_new(i128::MIN, i128::MIN),
            Some(Rational::ONE)
        );
        assert_eq!(Rational::checked_new(1, 0), None);
    }

    #[test]
    #[should_panic(expected = "overflowed 128 bits")]
    fn operators_panic_instead_of_wrapping() {
        let _ = Rational::new(i128::MAX, 1) + Rational::ONE;
    }

    #[test]
    fn order_is_exact_without_overflow() {
        let a = Rational::new(i128::MAX, i128::MAX - 1);
        let b = Rational::new(i128::MAX - 1, i128::MAX - 2);
        // a = 1 + 1/(M-1) < b = 1 + 1/(M-2)
        assert!(a < b);
        assert!(-a > -b);
        assert!(Rational::new(-1, 3) < Rational::ZERO);
        assert_eq!(
            Rational::new(2, 6).cmp(&Rational::new(1, 3)),
            Ordering::Equal
        );
        assert!(Rational::new(1, 3) < Rational::new(1, 2));
        assert!(Rational::int(7) > Rational::new(13, 2));
    }

    #[test]
    fn height_bounds_products() {
        assert_eq!(Rational::ONE.height(), 1);
        assert_eq!(Rational::new(1, 1000).height(), 10);
        assert_eq!(Rational::new(-255, 2).height(), 8);
    }
}
