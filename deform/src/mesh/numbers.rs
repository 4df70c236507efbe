//! Numbers for people: messages and labels print them short.

/// A number in at most about four significant digits (scientific beyond `1e-3..1e5`).
#[must_use]
pub fn short_number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor();
    if !(-3.0..5.0).contains(&magnitude) {
        return format!("{v:.2e}");
    }
    let decimals = (3.0 - magnitude).clamp(0.0, 6.0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// A point as `(x, y, z)`, each coordinate a [`short_number`].
#[must_use]
pub fn short_point(v: glam::DVec3) -> String {
    let [x, y, z] = v.to_array().map(short_number);
    format!("({x}, {y}, {z})")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(short_number(0.0), "0");
        assert_eq!(short_number(1.0), "1");
        assert_eq!(short_number(4.123_456), "4.123");
        assert_eq!(short_number(-12.5), "-12.5");
        assert_eq!(short_number(0.012_345_6), "0.01235");
        assert_eq!(short_number(123_456.0), "1.23e5");
        assert_eq!(short_number(2e-7), "2.00e-7");
        assert_eq!(
            short_point(glam::DVec3::new(2.0, -1e-5, 0.5)),
            "(2, -1.00e-5, 0.5)"
        );
    }
}
