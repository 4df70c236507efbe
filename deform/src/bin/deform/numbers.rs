//! Numeric flags parsed into values the commands can use: NaN and infinities never reach a
//! command, radii and tolerances are positive, distances are not negative.

/// A finite number.
pub fn finite(s: &str) -> Result<f64, String> {
    let x: f64 = s.trim().parse().map_err(|e| format!("{s:?}: {e}"))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("{s:?}: expected a finite number"))
    }
}

/// A finite number `>= 0`.
pub fn non_negative(s: &str) -> Result<f64, String> {
    match finite(s)? {
        x if x >= 0.0 => Ok(x),
        _ => Err(format!("{s:?}: expected a number >= 0")),
    }
}

/// A finite number `> 0`.
pub fn positive(s: &str) -> Result<f64, String> {
    match finite(s)? {
        x if x > 0.0 => Ok(x),
        _ => Err(format!("{s:?}: expected a number > 0")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_nan_infinities_and_out_of_range_values() {
        for bad in ["nan", "NaN", "inf", "-inf", "1e999", "x", ""] {
            assert!(finite(bad).is_err(), "{bad}");
        }
        assert_eq!(finite(" -2.5 "), Ok(-2.5));
        assert!(non_negative("-1").is_err());
        assert_eq!(non_negative("0"), Ok(0.0));
        assert!(positive("0").is_err());
        assert_eq!(positive("1e-3"), Ok(1e-3));
    }
}
