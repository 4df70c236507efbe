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
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
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

    /// True for zero.
    pub fn is_zero(self) -> bool {
        self.num == 0
    }

    /// Nearest `f64` (exact when numerator and denominator are at most 2^53, as for every
    /// decimal with up to 15 significant digits and a small exponent).
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
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
