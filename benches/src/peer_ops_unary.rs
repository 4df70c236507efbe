//! ga-benchmark's unary operation set for 3D CGA f64 on blades of every grade 0..=5: reversion,
//! grade involution, Clifford conjugation, dual, undual, inverse, normalisation and squared
//! (reverse) norm. Our side of the peer harness's `un.GRADE.OP` rows (GATL's side
//! `benches/peers/gatl_ops.hpp`), timed and recorded as [`crate::peer_ops_set`]'s binary rows
//! (in the library for the same reason).
//!
//! Grade 0 is `f64`: its reversion, involution and conjugation are the identity, its inverse
//! `1 / x`, its normalisation `x / |x|` (GATL's `x |x|^-1`), its squared norm `x x`, and its
//! dual and undual the generated [`ScalarDual`].

use crate::peer_ops_set::{time_pass, AsMv, Row, CHECKED};
use cga::f64::ScalarDual;
use cga::{Bivector, Pseudoscalar, Quadvector, Trivector, Vector};

/// The unary operations (keys, in row order).
pub const UNARY: [&str; 8] = [
    "rev",
    "inv",
    "conj",
    "dual",
    "undual",
    "inverse",
    "normalize",
    "nsq",
];

/// An operation's name as printed.
pub fn unary_name(key: &str) -> &'static str {
    match key {
        "rev" => "reversion",
        "inv" => "grade involution",
        "conj" => "Clifford conjugation",
        "dual" => "dual",
        "undual" => "undual",
        "inverse" => "inverse",
        "normalize" => "normalisation",
        "nsq" => "squared norm",
        _ => unreachable!("{key}"),
    }
}

/// Times `o[i] = f(a[i])` (the binary timer with an unread right operand of size zero) and
/// records it.
fn row1<A: Copy, T: AsMv>(rows: &mut Vec<Row>, key: &str, a: &[A], f: impl Fn(A) -> T + Copy) {
    let mut out = vec![T::default(); a.len()];
    let none = vec![(); a.len()];
    let ns = time_pass(&mut out, a, &none, move |x, ()| f(x));
    rows.push((
        key.to_string(),
        ns,
        out[..CHECKED].iter().flat_map(T::mv).collect(),
    ));
}

/// The rows of the generated blade types: every operation of [`UNARY`] by its method.
macro_rules! typed_rows {
    ($rec:expr, $grade:literal, $a:expr) => {
        row1($rec, concat!("un.", $grade, ".rev"), $a, |x| x.rev());
        row1($rec, concat!("un.", $grade, ".inv"), $a, |x| x.involute());
        row1($rec, concat!("un.", $grade, ".conj"), $a, |x| x.conjugate());
        row1($rec, concat!("un.", $grade, ".dual"), $a, |x| x.dual());
        row1($rec, concat!("un.", $grade, ".undual"), $a, |x| x.undual());
        row1($rec, concat!("un.", $grade, ".inverse"), $a, |x| {
            x.inverse()
        });
        row1($rec, concat!("un.", $grade, ".normalize"), $a, |x| {
            x.normalized()
        });
        row1($rec, concat!("un.", $grade, ".nsq"), $a, |x| {
            x.norm_squared()
        });
    };
}

/// Every unary row (keys `un.GRADE.OP`), from the coefficients of blades of grade 0..=5 (our
/// blade order).
pub fn unary_rows(c: [&[f64]; 6]) -> Vec<Row> {
    fn typed<T, const K: usize>(v: &[f64], from: fn([f64; K]) -> T) -> Vec<T> {
        v.chunks_exact(K)
            .map(|c| from(c.try_into().unwrap()))
            .collect()
    }
    let rec = &mut Vec::new();
    let s = c[0];
    row1(rec, "un.0.rev", s, |x: f64| x);
    row1(rec, "un.0.inv", s, |x: f64| x);
    row1(rec, "un.0.conj", s, |x: f64| x);
    row1(rec, "un.0.dual", s, |x: f64| x.dual());
    row1(rec, "un.0.undual", s, |x: f64| x.undual());
    row1(rec, "un.0.inverse", s, |x: f64| 1.0 / x);
    row1(rec, "un.0.normalize", s, |x: f64| x / x.abs());
    row1(rec, "un.0.nsq", s, |x: f64| x * x);
    typed_rows!(rec, "1", &typed(c[1], Vector::from_array));
    typed_rows!(rec, "2", &typed(c[2], Bivector::from_array));
    typed_rows!(rec, "3", &typed(c[3], Trivector::from_array));
    typed_rows!(rec, "4", &typed(c[4], Quadvector::from_array));
    typed_rows!(rec, "5", &typed(c[5], Pseudoscalar::from_array));
    std::mem::take(rec)
}
