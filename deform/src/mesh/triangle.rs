//! Per-triangle geometry, computed scale-invariantly: the one degenerate-triangle test and the
//! angle quantities (cotangents, tangents of half angles, Voronoi shares) every Laplacian and
//! mass matrix uses.
//!
//! A triangle's edge vectors are first multiplied by a power of two (exact in floating point)
//! so that their largest component lies in `[1, 2)`. Dimensionless results (cotangents,
//! tangents of half angles, the degenerate test) are therefore the same for a triangle scaled
//! by `1e-300` or `1e300` and never overflow; results with units (areas, lengths) are scaled
//! back by [`Frame::unscale`] and may leave the `f64` range, which callers report as
//! [`MeshError::Overflow`].

use glam::DVec3;

/// A non-degenerate triangle in normalised units (see the module docs).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    /// `e[k]` is the edge opposite corner `k` (`p[k+2] - p[k+1]`), times `2^-exp`.
    e: [DVec3; 3],
    /// Twice the area in normalised units, `|e2 x e1|`.
    dbl_area: f64,
    /// The power of two the edges were divided by.
    exp: i32,
}

/// `x * 2^k` without intermediate overflow (exact unless the result leaves the normal range).
pub(crate) fn ldexp(mut x: f64, mut k: i32) -> f64 {
    let big = 2f64.powi(1000);
    let small = 2f64.powi(-1000);
    while k > 1000 {
        x *= big;
        k -= 1000;
    }
    while k < -1000 {
        x *= small;
        k += 1000;
    }
    x * 2f64.powi(k)
}

/// `floor(log2(m))` of a finite `m > 0`: the exponent of its leading bit (subnormals
/// included).
fn binary_exponent(m: f64) -> i32 {
    let bits = m.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: the leading bit lies in the 52-bit fraction.
        let fraction = bits & ((1u64 << 52) - 1);
        -1074 + 63 - fraction.leading_zeros() as i32
    } else {
        biased - 1023
    }
}

impl Frame {
    /// The frame of the triangle `p`, or `None` when it is degenerate: an edge is not finite
    /// (NaN, infinite, or a difference that overflows), or twice its area is at most
    /// `f64::EPSILON` times its longest squared edge (the cross product is at rounding level).
    pub(crate) fn new(p: [DVec3; 3]) -> Option<Frame> {
        let raw = [p[2] - p[1], p[0] - p[2], p[1] - p[0]];
        if raw.iter().any(|e| !e.is_finite()) {
            return None;
        }
        let m = raw
            .iter()
            .map(|e| e.abs().max_element())
            .fold(0.0, f64::max);
        if m == 0.0 {
            return None;
        }
        let exp = binary_exponent(m);
        let e = if (-1000..=1000).contains(&exp) {
            // One exact multiplication by 2^-exp per component (the common case).
            let s = f64::from_bits(((1023 - exp) as u64) << 52);
            raw.map(|v| v * s)
        } else {
            raw.map(|v| DVec3::new(ldexp(v.x, -exp), ldexp(v.y, -exp), ldexp(v.z, -exp)))
        };
        let l2max = e.iter().map(|v| v.length_squared()).fold(0.0, f64::max);
        let dbl_area = e[2].cross(-e[1]).length();
        // Not strictly greater (NaN included) counts as degenerate.
        if dbl_area.partial_cmp(&(f64::EPSILON * l2max)) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        Some(Frame { e, dbl_area, exp })
    }

    /// Half cotangents of the angles, `[cot(A)/2, cot(B)/2, cot(C)/2]`; entry `k` belongs to
    /// the edge opposite corner `k`. Scale-invariant and finite.
    pub(crate) fn half_cotangents(&self) -> [f64; 3] {
        let [e0, e1, e2] = self.e;
        // cot at a corner = (dot of its two outgoing edges) / (2 area).
        let s = 0.5 / self.dbl_area;
        [-e2.dot(e1) * s, -e0.dot(e2) * s, -e1.dot(e0) * s]
    }

    /// Dot products of the two edges leaving each corner (negative at an obtuse corner),
    /// in normalised units.
    fn corner_dots(&self) -> [f64; 3] {
        let [e0, e1, e2] = self.e;
        [-e2.dot(e1), -e0.dot(e2), -e1.dot(e0)]
    }

    /// `tan(a_k / 2)` of the angle at each corner. Scale-invariant and finite; uses whichever
    /// of `|a x b| / (|a||b| + a.b)` and `(|a||b| - a.b) / |a x b|` does not cancel.
    pub(crate) fn tan_half_angles(&self) -> [f64; 3] {
        let dots = self.corner_dots();
        std::array::from_fn(|k| {
            let (a, b) = (self.e[(k + 2) % 3], self.e[(k + 1) % 3]);
            let ll = a.length() * b.length();
            if dots[k] >= 0.0 {
                self.dbl_area / (ll + dots[k])
            } else {
                (ll - dots[k]) / self.dbl_area
            }
        })
    }

    /// Length of the edge opposite corner `k`, in normalised units.
    pub(crate) fn edge_length(&self, k: usize) -> f64 {
        self.e[k].length()
    }

    /// Twice the area, in normalised units.
    pub(crate) fn double_area(&self) -> f64 {
        self.dbl_area
    }

    /// Mixed Voronoi area of each corner (Meyer et al. 2003), in normalised units: for an
    /// obtuse triangle half the area to the obtuse corner and a quarter to the others.
    pub(crate) fn voronoi_shares(&self) -> [f64; 3] {
        let area = 0.5 * self.dbl_area;
        let dots = self.corner_dots();
        if let Some(o) = (0..3).find(|&k| dots[k] < 0.0) {
            let mut s = [area / 4.0; 3];
            s[o] = area / 2.0;
            return s;
        }
        let cot = self.half_cotangents().map(|c| 2.0 * c);
        std::array::from_fn(|k| {
            let (j, l) = ((k + 1) % 3, (k + 2) % 3);
            // Edge k-j is opposite corner l; edge k-l is opposite corner j.
            (self.e[l].length_squared() * cot[l] + self.e[j].length_squared() * cot[j]) / 8.0
        })
    }

    /// A normalised quantity of dimension length^`power` in real units (may overflow to
    /// infinity or underflow to zero).
    pub(crate) fn unscale(&self, x: f64, power: i32) -> f64 {
        ldexp(x, power * self.exp)
    }
}

/// True when a triangle with these corners has (numerically) zero area: twice its area is at
/// most `f64::EPSILON` times its longest squared edge, i.e. the cross product is at rounding
/// level. Non-finite corners (or edges whose difference overflows) also count as degenerate.
/// Scale-invariant: the test is done after rescaling the edges by a power of two.
pub fn is_degenerate_triangle(a: DVec3, b: DVec3, c: DVec3) -> bool {
    Frame::new([a, b, c]).is_none()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scaled(s: f64) -> [DVec3; 3] {
        [
            DVec3::ZERO,
            DVec3::new(s, 0.0, 0.0),
            DVec3::new(0.3 * s, 0.7 * s, 0.1 * s),
        ]
    }

    #[test]
    fn angles_are_the_same_at_every_scale() {
        let unit = Frame::new(scaled(1.0)).expect("unit");
        // Powers of two scale every coordinate exactly.
        for k in [-1000, -300, -1, 1, 300, 1000] {
            let s = ldexp(1.0, k);
            let f = Frame::new(scaled(s)).expect("scaled");
            assert_eq!(f.half_cotangents(), unit.half_cotangents(), "scale 2^{k}");
            assert_eq!(f.tan_half_angles(), unit.tan_half_angles(), "scale 2^{k}");
        }
    }

    #[test]
    fn binary_exponent_brackets_the_value() {
        let mut values = vec![f64::MIN_POSITIVE, 5e-324, 1e-310, f64::MAX, 1.0, 0.75, 3.0];
        for k in [-1074, -1030, -1022, -1, 0, 1, 52, 1023] {
            let p = ldexp(1.0, k);
            values.extend([p, p * (1.0 + f64::EPSILON), p * (1.0 - f64::EPSILON / 2.0)]);
        }
        for m in values.into_iter().filter(|m| *m > 0.0 && m.is_finite()) {
            let e = binary_exponent(m);
            assert!(
                ldexp(1.0, e) <= m && (e == 1023 || m < ldexp(1.0, e + 1)),
                "{m:e}: {e}"
            );
        }
    }

    #[test]
    fn degenerate_cases() {
        assert!(is_degenerate_triangle(
            DVec3::ZERO,
            DVec3::X,
            2.0 * DVec3::X
        ));
        assert!(is_degenerate_triangle(
            DVec3::ZERO,
            DVec3::ZERO,
            DVec3::ZERO
        ));
        assert!(is_degenerate_triangle(DVec3::ZERO, DVec3::X, DVec3::NAN));
        let big = DVec3::new(f64::MAX, 0.0, 0.0);
        assert!(is_degenerate_triangle(-big, big, DVec3::Y));
        assert!(!is_degenerate_triangle(
            1e300 * DVec3::X,
            1e300 * DVec3::Y,
            DVec3::ZERO
        ));
        assert!(!is_degenerate_triangle(
            1e-310 * DVec3::X,
            1e-310 * DVec3::Y,
            DVec3::ZERO
        ));
    }

    #[test]
    fn tan_half_angle_matches_trigonometry() {
        // An obtuse corner (near pi) and an acute one.
        let (a, b) = (DVec3::X, DVec3::new(-3.0, 0.01, 0.0));
        let f = Frame::new([DVec3::ZERO, a, b]).expect("frame");
        let th = f.tan_half_angles();
        let at0 = a.y.atan2(a.x) - b.y.atan2(b.x);
        assert!(
            (th[0] - (at0.abs() / 2.0).tan()).abs() < 1e-9 * th[0],
            "{th:?}"
        );
        let (u, v) = (DVec3::new(-1.0, 0.0, 0.0), b - a);
        let at1 = (u.y.atan2(u.x) - v.y.atan2(v.x)).abs();
        assert!((th[1] - (at1 / 2.0).tan()).abs() < 1e-12, "{th:?}");
    }

    #[test]
    fn unscale_restores_units() {
        let f = Frame::new(scaled(1e100)).expect("frame");
        let area = f.unscale(0.5 * f.double_area(), 2);
        assert!(
            (area / (0.5 * 0.5f64.sqrt() * 1e200) - 1.0).abs() < 1e-12,
            "{area:e}"
        );
        let huge = Frame::new(scaled(1e200)).expect("frame");
        assert!(huge.unscale(huge.double_area(), 2).is_infinite());
    }
}
