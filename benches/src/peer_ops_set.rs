//! ga-benchmark's binary operation set for 3D CGA f64 (a subset: the products of grade pairs
//! (1,1), (1,2), (2,2), (1,4) on blades): our side of the peer harness's operation rows
//! (`benches/examples/peer_ops/`, GATL's side `benches/peers/gatl_ops.hpp`).
//!
//! It lives in the library, compiled apart from the example: in the example crate its 33
//! instantiated loops changed LLVM's inlining there (the `bivector * bivector` row's
//! `Bivector * Bivector` went out of line, 14 ns to 38), and passing the closures by
//! reference instead kept a call per operand in these rows.
//!
//! Each row times `o[i] = a[i] op b[i]` over the N operands; its outputs, for the first
//! [`CHECKED`] operands, are written as all 32 coefficients in `Mv` blade order (GATL maps its
//! blades to those names as for the other CGA rows). A product that is identically zero for a
//! pair (the regressive product below grade 5, right contractions and scalar products of
//! unequal grades) is not generated, and has no row.

use crate::grade::Spread;
use cga::f64::{
    CommutatorProduct, DotProduct, HestenesInnerProduct, InverseGeometricProduct,
    RegressiveProduct, RightContraction, ScalarProduct,
};
use cga::{Bivector, Even, Mv, Odd, Pseudoscalar, Quadvector, ScalarBivector, Trivector, Vector};
use std::hint::black_box;
use std::time::Instant;

/// Operands per row (the harness's N).
pub const N: usize = 10_000;
/// Timed passes per row (the harness's PASSES).
const PASSES: usize = 41;

/// Operands whose outputs are compared (all N are timed).
pub const CHECKED: usize = 1000;

/// The grade pairs and their products, as `(pair key, product keys)`: what the rows and the
/// report's table are made of.
pub const PAIRS: [(&str, &[&str]); 4] = [
    (
        "11",
        &["gp", "op", "lc", "rc", "sp", "dot", "hip", "cp", "igp"],
    ),
    ("12", &["gp", "op", "lc", "dot", "hip", "cp", "igp"]),
    (
        "22",
        &["gp", "op", "lc", "rc", "sp", "dot", "hip", "cp", "igp"],
    ),
    ("14", &["gp", "op", "lc", "dot", "hip", "cp", "rp", "igp"]),
];

/// A product's name as printed.
pub fn product_name(key: &str) -> &'static str {
    match key {
        "gp" => "geometric",
        "op" => "outer",
        "lc" => "left contraction",
        "rc" => "right contraction",
        "sp" => "scalar",
        "dot" => "dot",
        "hip" => "Hestenes inner",
        "cp" => "commutator",
        "rp" => "regressive",
        "igp" => "inverse geometric",
        _ => unreachable!("{key}"),
    }
}

/// A result as its 32 coefficients in `Mv` blade order.
trait AsMv: Copy + Default {
    fn mv(&self) -> [f64; 32];
}

impl AsMv for f64 {
    fn mv(&self) -> [f64; 32] {
        let mut v = [0.0; 32];
        v[0] = *self;
        v
    }
}

macro_rules! as_mv {
    ($($t:ty),*) => {$(
        impl AsMv for $t {
            fn mv(&self) -> [f64; 32] {
                let mut v = [0.0; 32];
                for (name, x) in <$t>::BLADES.iter().zip(self.to_array()) {
                    let at = Mv::BLADES.iter().position(|b| b == name).expect("a blade of Mv");
                    v[at] = x;
                }
                v
            }
        }
    )*};
}
as_mv!(
    Vector,
    ScalarBivector,
    Bivector,
    Trivector,
    Quadvector,
    Pseudoscalar,
    Even,
    Odd
);

/// One row: key, ns per op, the first [`CHECKED`] outputs as 32 coefficients each.
pub type Row = (String, f64, Vec<f64>);

/// The harness's timer: the median over [`PASSES`] of one pass (after 3 warm-up passes), in ns
/// per operand, `o[i] = f(a[i], b[i])` by iterators.
fn time_pass<A: Copy, B: Copy, T>(
    o: &mut [T],
    a: &[A],
    b: &[B],
    f: impl Fn(A, B) -> T + Copy,
) -> f64 {
    let pass = |o: &mut [T]| {
        let (a, b) = black_box((a, b));
        for ((o, a), b) in o.iter_mut().zip(a).zip(b) {
            *o = f(*a, *b);
        }
    };
    for _ in 0..3 {
        pass(black_box(&mut *o));
    }
    let mut samples: Vec<f64> = (0..PASSES)
        .map(|_| {
            let start = Instant::now();
            pass(black_box(&mut *o));
            black_box(&mut *o);
            start.elapsed().as_nanos() as f64 / N as f64
        })
        .collect();
    Spread::median_of(&mut samples).value
}

/// Times one product over the operands and records it.
fn row<A: Copy, B: Copy, T: AsMv>(
    rows: &mut Vec<Row>,
    key: &str,
    (a, b): (&[A], &[B]),
    f: impl Fn(A, B) -> T + Copy,
) {
    let mut out = vec![T::default(); a.len()];
    let ns = time_pass(&mut out, a, b, f);
    rows.push((
        key.to_string(),
        ns,
        out[..CHECKED].iter().flat_map(T::mv).collect(),
    ));
}

/// The rows of one pair: every product the pair has, in [`PAIRS`] order.
macro_rules! pair_rows {
    ($rec:expr, $pair:literal, $ab:expr, [$($op:ident),*]) => {
        $(pair_rows!(@one $rec, $pair, $ab, $op);)*
    };
    (@one $rec:expr, $pair:literal, $ab:expr, gp) => { row($rec, concat!("ops.", $pair, ".gp"), $ab, |x, y| x * y) };
    (@one $rec:expr, $pair:literal, $ab:expr, op) => { row($rec, concat!("ops.", $pair, ".op"), $ab, |x, y| x ^ y) };
    (@one $rec:expr, $pair:literal, $ab:expr, lc) => { row($rec, concat!("ops.", $pair, ".lc"), $ab, |x, y| x | y) };
    (@one $rec:expr, $pair:literal, $ab:expr, rc) => { row($rec, concat!("ops.", $pair, ".rc"), $ab, |x, y| x.right_contraction(y)) };
    (@one $rec:expr, $pair:literal, $ab:expr, sp) => { row($rec, concat!("ops.", $pair, ".sp"), $ab, |x, y| x.scalar_product(y)) };
    (@one $rec:expr, $pair:literal, $ab:expr, dot) => { row($rec, concat!("ops.", $pair, ".dot"), $ab, |x, y| x.dot_product(y)) };
    (@one $rec:expr, $pair:literal, $ab:expr, hip) => { row($rec, concat!("ops.", $pair, ".hip"), $ab, |x, y| x.hestenes_inner_product(y)) };
    (@one $rec:expr, $pair:literal, $ab:expr, cp) => { row($rec, concat!("ops.", $pair, ".cp"), $ab, |x, y| x.commutator_product(y)) };
    (@one $rec:expr, $pair:literal, $ab:expr, rp) => { row($rec, concat!("ops.", $pair, ".rp"), $ab, |x, y| x.regressive_product(y)) };
    (@one $rec:expr, $pair:literal, $ab:expr, igp) => { row($rec, concat!("ops.", $pair, ".igp"), $ab, |x, y| x.inverse_geometric_product(y)) };
}

/// Every operation row (keys `ops.PAIR.PRODUCT`), from the coefficients of the operands (our
/// blade order): vectors `va`, `vb`, grade-2 blades `ba`, `bb`, grade-4 blades `q4`.
pub fn op_rows(va: &[f64], vb: &[f64], ba: &[f64], bb: &[f64], q4: &[f64]) -> Vec<Row> {
    fn typed<T, const K: usize>(v: &[f64], from: fn([f64; K]) -> T) -> Vec<T> {
        v.chunks_exact(K)
            .map(|c| from(c.try_into().unwrap()))
            .collect()
    }
    let (va, vb) = (typed(va, Vector::from_array), typed(vb, Vector::from_array));
    let (ba, bb) = (
        typed(ba, Bivector::from_array),
        typed(bb, Bivector::from_array),
    );
    let q4 = typed(q4, Quadvector::from_array);
    let rec = &mut Vec::new();
    pair_rows!(
        rec,
        "11",
        (&va[..], &vb[..]),
        [gp, op, lc, rc, sp, dot, hip, cp, igp]
    );
    pair_rows!(
        rec,
        "12",
        (&va[..], &ba[..]),
        [gp, op, lc, dot, hip, cp, igp]
    );
    pair_rows!(
        rec,
        "22",
        (&ba[..], &bb[..]),
        [gp, op, lc, rc, sp, dot, hip, cp, igp]
    );
    pair_rows!(
        rec,
        "14",
        (&va[..], &q4[..]),
        [gp, op, lc, dot, hip, cp, rp, igp]
    );
    std::mem::take(rec)
}

/// A blade operand of grade 2 or 4: the outer product of random vectors (ga-benchmark's
/// `MakeRandomBlade`), in our blade order.
pub fn blade(grade: usize, rng: &mut crate::timing::Lcg) -> Vec<f64> {
    let mut vec = || Vector::from_array(rng.array::<5>());
    match grade {
        2 => (vec() ^ vec()).to_array().to_vec(),
        4 => (((vec() ^ vec()) ^ vec()) ^ vec()).to_array().to_vec(),
        _ => unreachable!("grade {grade}"),
    }
}
