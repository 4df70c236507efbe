//! The metric: a symmetric matrix of exact inner products between named basis vectors.

use crate::runtime::blade::suffix;
use crate::runtime::rational::Rational;
use std::fmt;

/// Largest supported number of basis vectors (2^16 = 65,536 blades; the dense
/// [`Algebra`](crate::runtime::algebra::Algebra) table of that many is too large to build: large
/// algebras use the sparse reference, [`crate::runtime::sparse`]).
pub const MAX_DIMENSION: usize = 16;

/// Inner products `g[i][j] = v_i . v_j` of the basis vectors, exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct Metric {
    names: Vec<String>,
    g: Vec<Vec<Rational>>,
}

/// Why a metric was rejected.
#[derive(Clone, Debug, PartialEq)]
pub enum MetricError {
    /// No basis vectors, or more than [`MAX_DIMENSION`].
    Dimension(usize),
    /// A row of the matrix has the wrong length, or there are too few or too many rows.
    Size {
        /// Number of basis vectors.
        expected: usize,
        /// Rows given, or the length of row `row`.
        got: usize,
        /// The offending row, if one row is wrong.
        row: Option<usize>,
    },
    /// `g[i][j] != g[j][i]`.
    NotSymmetric {
        /// Row.
        i: usize,
        /// Column.
        j: usize,
    },
    /// An entry is NaN or infinite, or too small/large to hold exactly.
    NotExact {
        /// Row.
        i: usize,
        /// Column.
        j: usize,
    },
    /// Two basis vectors share a name.
    DuplicateName(String),
    /// The suffix of one basis name starts with the suffix of another (`e1`, `e12`), so blade
    /// names could be read in two ways (`e12` is `e1^e2` or the basis vector `e12`). Basis
    /// suffixes must be prefix-free; blade names are then read in one left-to-right pass.
    PrefixName {
        /// The shorter name.
        name: String,
        /// The name that starts with its suffix.
        longer: String,
    },
    /// A basis name that is a Rust keyword (`enum`, `else`, `extern`): blade names become
    /// field names.
    KeywordName(String),
    /// Exact products of the metric do not fit in 128-bit rationals (entries such as `1e13`
    /// on three vectors give a pseudoscalar square of `1e39`, or `1e-9` entries give
    /// denominators beyond `2^127`).
    Overflow {
        /// Row of the entry with the largest numerator or denominator.
        i: usize,
        /// Column of that entry.
        j: usize,
        /// Its value.
        value: f64,
    },
    /// A basis name is not `e` followed by a non-empty suffix of letters or digits.
    BadName(String),
}

impl fmt::Display for MetricError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetricError::Dimension(n) => {
                write!(f, "{n} basis vectors: need between 1 and {MAX_DIMENSION}")
            }
            MetricError::Size {
                expected,
                got,
                row: Some(r),
            } => write!(f, "metric row {r} has {got} entries, expected {expected}"),
            MetricError::Size { expected, got, .. } => {
                write!(f, "metric has {got} rows, expected {expected}")
            }
            MetricError::NotSymmetric { i, j } => {
                write!(f, "metric is not symmetric: entry [{i}][{j}] differs from [{j}][{i}]")
            }
            MetricError::NotExact { i, j } => {
                write!(
                    f,
                    "metric entry [{i}][{j}] is not a finite number that can be held exactly \
                     (a decimal whose digits fit in 127 bits)"
                )
            }
            MetricError::DuplicateName(n) => write!(f, "basis vector `{n}` is named twice"),
            MetricError::PrefixName { name, longer } => write!(
                f,
                "basis vector `{longer}`: its suffix starts with the suffix of `{name}`, so blade \
                 names would be ambiguous (basis suffixes must be prefix-free)"
            ),
            MetricError::KeywordName(n) => {
                write!(f, "basis vector `{n}`: a Rust keyword cannot name a blade")
            }
            MetricError::Overflow { i, j, value } => write!(
                f,
                "metric entry [{i}][{j}] = {value}: exact products of the metric do not fit in \
                 128-bit rationals; use entries with fewer digits or a rescaled basis"
            ),
            MetricError::BadName(n) => write!(
                f,
                "basis vector name `{n}` must be `e` followed by letters or digits (e.g. e1, eo, ei)"
            ),
        }
    }
}

impl std::error::Error for MetricError {}

fn check_names(names: &[String]) -> Result<(), MetricError> {
    if names.is_empty() || names.len() > MAX_DIMENSION {
        return Err(MetricError::Dimension(names.len()));
    }
    for (i, n) in names.iter().enumerate() {
        let ok =
            n.len() > 1 && n.starts_with('e') && n[1..].chars().all(|c| c.is_ascii_alphanumeric());
        if !ok {
            return Err(MetricError::BadName(n.clone()));
        }
        if names[..i].contains(n) {
            return Err(MetricError::DuplicateName(n.clone()));
        }
        if crate::runtime::ident::is_keyword(n) {
            return Err(MetricError::KeywordName(n.clone()));
        }
    }
    for a in names {
        for b in names {
            if a != b && suffix(b).starts_with(suffix(a)) {
                return Err(MetricError::PrefixName {
                    name: a.clone(),
                    longer: b.clone(),
                });
            }
        }
    }
    Ok(())
}

impl Metric {
    /// A metric from basis names and a full symmetric matrix of exact entries.
    pub fn new(names: Vec<String>, g: Vec<Vec<Rational>>) -> Result<Metric, MetricError> {
        check_names(&names)?;
        let n = names.len();
        if g.len() != n {
            return Err(MetricError::Size {
                expected: n,
                got: g.len(),
                row: None,
            });
        }
        for (r, row) in g.iter().enumerate() {
            if row.len() != n {
                return Err(MetricError::Size {
                    expected: n,
                    got: row.len(),
                    row: Some(r),
                });
            }
        }
        for i in 0..n {
            for j in (i + 1)..n {
                if g[i][j] != g[j][i] {
                    return Err(MetricError::NotSymmetric { i, j });
                }
            }
        }
        Ok(Metric { names, g })
    }

    /// A metric from `f64` entries, each read as the decimal it prints as (`0.1` is 1/10, see
    /// [`Rational::from_f64`]); NaN, infinities and entries of more than 127 bits are
    /// [`MetricError::NotExact`].
    pub fn from_f64(names: Vec<String>, g: &[Vec<f64>]) -> Result<Metric, MetricError> {
        let mut rows = Vec::with_capacity(g.len());
        for (i, row) in g.iter().enumerate() {
            let mut r = Vec::with_capacity(row.len());
            for (j, &x) in row.iter().enumerate() {
                r.push(Rational::from_f64(x).ok_or(MetricError::NotExact { i, j })?);
            }
            rows.push(r);
        }
        Metric::new(names, rows)
    }

    /// A diagonal metric with the given squares.
    pub fn diagonal(names: Vec<String>, squares: &[Rational]) -> Result<Metric, MetricError> {
        let n = squares.len();
        let g = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| if i == j { squares[i] } else { Rational::ZERO })
                    .collect()
            })
            .collect();
        Metric::new(names, g)
    }

    /// The diagonal signature G(p, q, r): `p` vectors squaring to +1, then `q` to -1, then `r`
    /// to 0, named `e1 .. en` (or `e0` first for the degenerate ones when `r == 1`, as PGA does).
    pub fn signature(p: usize, q: usize, r: usize) -> Result<Metric, MetricError> {
        let n = p.saturating_add(q).saturating_add(r);
        if n == 0 || n > MAX_DIMENSION {
            return Err(MetricError::Dimension(n));
        }
        let mut names = Vec::new();
        let mut squares = Vec::new();
        if r == 1 {
            names.push("e0".to_string());
            squares.push(Rational::ZERO);
            for i in 0..(p + q) {
                names.push(format!("e{}", i + 1));
                squares.push(if i < p { Rational::ONE } else { -Rational::ONE });
            }
        } else {
            for i in 0..n {
                names.push(if n < 10 {
                    format!("e{}", i + 1)
                } else {
                    format!("e{}", (b'a' + i as u8) as char)
                });
                squares.push(if i < p {
                    Rational::ONE
                } else if i < p + q {
                    -Rational::ONE
                } else {
                    Rational::ZERO
                });
            }
        }
        Metric::diagonal(names, &squares)
    }

    /// The error for a metric whose exact products overflow: it names the entry with the
    /// most digits (the largest [`Rational::height`]), the likely culprit.
    pub fn overflow_error(&self) -> MetricError {
        let n = self.dim();
        let (mut i, mut j) = (0, 0);
        for r in 0..n {
            for c in r..n {
                if self.g[r][c].height() > self.g[i][j].height() {
                    (i, j) = (r, c);
                }
            }
        }
        MetricError::Overflow {
            i,
            j,
            value: self.g[i][j].to_f64(),
        }
    }

    /// Number of basis vectors.
    pub fn dim(&self) -> usize {
        self.names.len()
    }

    /// Basis names in order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// `v_i . v_j`.
    ///
    /// # Panics
    /// When `i` or `j` is not below [`Metric::dim`].
    pub fn get(&self, i: usize, j: usize) -> Rational {
        self.g[i][j]
    }

    /// True when no off-diagonal entry is non-zero.
    pub fn is_diagonal(&self) -> bool {
        (0..self.dim()).all(|i| (0..self.dim()).all(|j| i == j || self.g[i][j].is_zero()))
    }

    /// Entries as `f64`.
    pub fn to_f64(&self) -> Vec<Vec<f64>> {
        self.g
            .iter()
            .map(|r| r.iter().map(|x| x.to_f64()).collect())
            .collect()
    }

    /// Inner product of two vectors given by coordinates.
    ///
    /// # Panics
    /// When `u` or `v` does not have one coordinate per basis vector, or on overflow (see
    /// [`Metric::checked_inner`]).
    pub fn inner(&self, u: &[Rational], v: &[Rational]) -> Rational {
        assert!(
            u.len() == self.dim() && v.len() == self.dim(),
            "inner product of vectors of {} and {} coordinates in a {}-dimensional metric",
            u.len(),
            v.len(),
            self.dim()
        );
        self.checked_inner(u, v)
            .expect("exact rational arithmetic overflowed 128 bits")
    }

    /// Inner product of two vectors given by coordinates; `None` on overflow, or when `u` or
    /// `v` does not have one coordinate per basis vector.
    pub fn checked_inner(&self, u: &[Rational], v: &[Rational]) -> Option<Rational> {
        if u.len() != self.dim() || v.len() != self.dim() {
            return None;
        }
        let mut s = Rational::ZERO;
        for i in 0..self.dim() {
            if u[i].is_zero() {
                continue;
            }
            for j in 0..self.dim() {
                if !v[j].is_zero() && !self.g[i][j].is_zero() {
                    s = s.checked_add(u[i].checked_mul(self.g[i][j])?.checked_mul(v[j])?)?;
                }
            }
        }
        Some(s)
    }

    /// Diagonalise by congruence, exactly: returns rows `P` and squares `d` such that the
    /// vectors `f_k = sum_i P[k][i] v_i` are mutually orthogonal with `f_k . f_k = d[k]`.
    /// Panics on overflow, which a metric of a validated spec never reaches (see
    /// [`Metric::checked_orthogonal_basis`]).
    pub fn orthogonal_basis(&self) -> (Vec<Vec<Rational>>, Vec<Rational>) {
        self.checked_orthogonal_basis()
            .expect("exact rational arithmetic overflowed 128 bits")
    }

    /// [`Metric::orthogonal_basis`], or `None` when exact arithmetic overflows.
    ///
    /// Symmetric Gram-Schmidt with pivoting: a remaining vector of non-zero square is the next
    /// pivot; if all remaining vectors are null but two are not orthogonal, their sum is used
    /// (for CGA this turns `eo, ei` into `-(eo + ei)`-like combinations of square +-1... all
    /// rational); if all remaining vectors are null and mutually orthogonal they are the
    /// degenerate directions (square 0). No square roots, so every coefficient stays rational.
    pub fn checked_orthogonal_basis(&self) -> Option<(Vec<Vec<Rational>>, Vec<Rational>)> {
        let n = self.dim();
        let mut remaining = Rational::identity_matrix(n);
        let mut rows = Vec::new();
        let mut squares = Vec::new();
        while !remaining.is_empty() {
            let mut pivot = None;
            for (k, r) in remaining.iter().enumerate() {
                if !self.checked_inner(r, r)?.is_zero() {
                    pivot = Some(k);
                    break;
                }
            }
            if pivot.is_none() {
                'outer: for a in 0..remaining.len() {
                    for b in (a + 1)..remaining.len() {
                        if !self.checked_inner(&remaining[a], &remaining[b])?.is_zero() {
                            let mut sum = Vec::with_capacity(n);
                            for (x, y) in remaining[a].iter().zip(&remaining[b]) {
                                sum.push(x.checked_add(*y)?);
                            }
                            remaining[a] = sum;
                            pivot = Some(a);
                            break 'outer;
                        }
                    }
                }
            }
            let Some(p) = pivot else {
                for r in remaining.drain(..) {
                    rows.push(r);
                    squares.push(Rational::ZERO);
                }
                break;
            };
            let pv = remaining.remove(p);
            let pp = self.checked_inner(&pv, &pv)?;
            for r in remaining.iter_mut() {
                let c = self.checked_inner(r, &pv)?.checked_div(pp)?;
                if !c.is_zero() {
                    for k in 0..n {
                        r[k] = r[k].checked_sub(c.checked_mul(pv[k])?)?;
                    }
                }
            }
            rows.push(pv);
            squares.push(pp);
        }
        Some((rows, squares))
    }
}

/// G(4,1) in the null basis `eo, e1, e2, e3, ei` (`eo . ei = -1`), the metric of
/// `algebras/cga.toml`, for the unit tests of this crate.
#[cfg(test)]
impl Metric {
    pub(crate) fn cga_null_basis() -> Metric {
        let names = ["eo", "e1", "e2", "e3", "ei"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let z = 0.0;
        Metric::from_f64(
            names,
            &[
                vec![z, z, z, z, -1.0],
                vec![z, 1.0, z, z, z],
                vec![z, z, 1.0, z, z],
                vec![z, z, z, 1.0, z],
                vec![-1.0, z, z, z, z],
            ],
        )
        .unwrap()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cga() -> Metric {
        Metric::cga_null_basis()
    }

    #[test]
    fn congruence_diagonalises_null_basis() {
        let m = cga();
        let (p, d) = m.orthogonal_basis();
        for a in 0..5 {
            for b in 0..5 {
                let ip = m.inner(&p[a], &p[b]);
                if a == b {
                    assert_eq!(ip, d[a]);
                } else {
                    assert!(ip.is_zero());
                }
            }
        }
        let pos = d.iter().filter(|x| **x > Rational::ZERO).count();
        let neg = d.iter().filter(|x| **x < Rational::ZERO).count();
        assert_eq!((pos, neg), (4, 1));
    }

    #[test]
    fn rejects_bad_metrics() {
        let names: Vec<String> = vec!["e1".into(), "e2".into()];
        assert_eq!(
            Metric::from_f64(names.clone(), &[vec![1.0, 2.0], vec![0.0, 1.0]]),
            Err(MetricError::NotSymmetric { i: 0, j: 1 })
        );
        assert!(matches!(
            Metric::from_f64(names.clone(), &[vec![1.0, 0.0]]),
            Err(MetricError::Size { .. })
        ));
        assert!(matches!(
            Metric::from_f64(vec!["x".into()], &[vec![1.0]]),
            Err(MetricError::BadName(_))
        ));
    }

    #[test]
    fn degenerate_signature() {
        let m = Metric::signature(3, 0, 1).unwrap();
        assert_eq!(m.names()[0], "e0");
        let (_, d) = m.orthogonal_basis();
        assert_eq!(d.iter().filter(|x| x.is_zero()).count(), 1);
    }

    fn names(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn rejects_prefix_and_keyword_names() {
        let one = |n: &[&str]| {
            let k = n.len();
            let sq = vec![Rational::ONE; k];
            Metric::diagonal(names(n), &sq)
        };
        assert_eq!(
            one(&["e1", "e11"]),
            Err(MetricError::PrefixName {
                name: "e1".into(),
                longer: "e11".into()
            })
        );
        assert!(matches!(
            one(&["e1", "e2", "e12"]),
            Err(MetricError::PrefixName { .. })
        ));
        assert_eq!(
            one(&["e1", "enum"]),
            Err(MetricError::KeywordName("enum".into()))
        );
        assert!(one(&["eo", "e1", "e2", "e3", "ei"]).is_ok());
        assert!(one(&["ex", "ey", "ez"]).is_ok());
    }

    #[test]
    fn signature_sizes_do_not_wrap() {
        assert_eq!(
            Metric::signature(usize::MAX, 2, 0),
            Err(MetricError::Dimension(usize::MAX))
        );
        assert_eq!(Metric::signature(0, 0, 0), Err(MetricError::Dimension(0)));
        assert_eq!(Metric::signature(17, 0, 0), Err(MetricError::Dimension(17)));
        assert_eq!(Metric::signature(16, 0, 0).map(|m| m.dim()), Ok(16));
    }

    #[test]
    fn congruence_reports_overflow() {
        let big = Rational::new(i128::MAX / 3, 1);
        let m = Metric::new(
            names(&["e1", "e2"]),
            vec![vec![big, big], vec![big, Rational::new(1, 7)]],
        )
        .unwrap();
        assert!(m.checked_orthogonal_basis().is_none());
        assert!(cga().checked_orthogonal_basis().is_some());
    }
}
