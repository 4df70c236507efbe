//! Numeric flags parsed into values the commands can use: NaN and infinities never reach a
//! command, radii and tolerances are positive, distances are not negative. One parser of
//! separated number lists ([`list`]) with a thin wrapper per flag format, each keeping its
//! own message.

use glam::DVec3;
use std::str::FromStr;

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

/// Why [`list`] refused its input.
#[derive(Debug, PartialEq)]
pub enum ListError<E> {
    /// The first item that is not a `T` (as given, untrimmed), and why.
    Item(String, E),
    /// Not `N` items, or (of [`finite_list`]) one that is not finite.
    Shape,
}

/// Exactly `N` items separated by any of `separators`, each trimmed and parsed as a `T`.
pub fn list<T: FromStr, const N: usize>(
    s: &str,
    separators: &[char],
) -> Result<[T; N], ListError<T::Err>> {
    let items: Vec<T> = s
        .split(separators)
        .map(|x| {
            x.trim()
                .parse::<T>()
                .map_err(|e| ListError::Item(x.into(), e))
        })
        .collect::<Result<_, _>>()?;
    <[T; N]>::try_from(items).map_err(|_| ListError::Shape)
}

/// Exactly `N` finite comma-separated numbers.
pub fn finite_list<const N: usize>(
    s: &str,
) -> Result<[f64; N], ListError<std::num::ParseFloatError>> {
    match list::<f64, N>(s, &[',']) {
        Ok(v) if v.iter().all(|x| x.is_finite()) => Ok(v),
        Ok(_) => Err(ListError::Shape),
        Err(e) => Err(e),
    }
}

/// `X,Y,Z` as three finite numbers (fabrik's `--target`).
pub fn xyz(s: &str) -> Result<[f64; 3], String> {
    finite_list(s).map_err(|e| match e {
        ListError::Item(x, e) => format!("{x:?}: {e}"),
        ListError::Shape => format!("expected three finite numbers X,Y,Z, got {s:?}"),
    })
}

/// `X,Y,Z` as a vector (the surgery tools' points).
pub fn point(s: &str) -> Result<DVec3, String> {
    match finite_list(s) {
        Ok(p) => Ok(DVec3::from_array(p)),
        Err(ListError::Item(..)) => Err(format!("{s:?}: expected X,Y,Z")),
        Err(ListError::Shape) => Err(format!("{s:?}: expected three finite numbers X,Y,Z")),
    }
}

/// `NX,NY,NZ,D`: a plane as four finite numbers.
pub fn plane(s: &str) -> Result<[f64; 4], String> {
    finite_list(s).map_err(|e| match e {
        ListError::Item(..) => format!("{s:?}: expected NX,NY,NZ,D"),
        ListError::Shape => format!("{s:?}: expected four finite numbers NX,NY,NZ,D"),
    })
}

/// `MINX,MINY,MINZ,MAXX,MAXY,MAXZ`: a box as six finite numbers.
pub fn bounds(s: &str) -> Result<[f64; 6], String> {
    finite_list(s).map_err(|e| match e {
        ListError::Item(x, e) => format!("{x:?}: {e}"),
        ListError::Shape => {
            format!("expected six finite numbers MINX,MINY,MINZ,MAXX,MAXY,MAXZ, got {s:?}")
        }
    })
}

/// `LxMxN` as three counts, read as the methods' lattice option reads it
/// ([`deform::methods::option::parse_dims`]).
pub fn dims(s: &str) -> Result<[usize; 3], String> {
    deform::methods::option::parse_dims(s)
        .ok_or_else(|| format!("expected LxMxN (three whole numbers), got {s:?}"))
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

    #[test]
    fn lists_have_exactly_n_finite_items() {
        assert_eq!(xyz(" 1, -2 ,3e0"), Ok([1.0, -2.0, 3.0]));
        assert_eq!(point("1,2,3"), Ok(DVec3::new(1.0, 2.0, 3.0)));
        assert_eq!(plane("0,0,1,-2"), Ok([0.0, 0.0, 1.0, -2.0]));
        assert_eq!(bounds("0,0,0,1,1,1"), Ok([0.0, 0.0, 0.0, 1.0, 1.0, 1.0]));
        assert_eq!(dims("2x3X4"), Ok([2, 3, 4]));
        assert_eq!(
            xyz("1,2"),
            Err("expected three finite numbers X,Y,Z, got \"1,2\"".into())
        );
        assert_eq!(
            xyz("1,nan,2"),
            Err("expected three finite numbers X,Y,Z, got \"1,nan,2\"".into())
        );
        assert_eq!(xyz("1, x,2"), Err("\" x\": invalid float literal".into()));
        assert_eq!(point("1,x,2"), Err("\"1,x,2\": expected X,Y,Z".into()));
        assert_eq!(
            point("1,inf,2"),
            Err("\"1,inf,2\": expected three finite numbers X,Y,Z".into())
        );
        assert_eq!(
            plane("1,2,3"),
            Err("\"1,2,3\": expected four finite numbers NX,NY,NZ,D".into())
        );
        assert!(bounds("1,2,3,4,5,inf").is_err());
        assert_eq!(
            dims("2x2"),
            Err("expected LxMxN (three whole numbers), got \"2x2\"".into())
        );
        assert!(dims("2x-1x2").is_err());
    }
}
