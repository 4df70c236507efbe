//! ga-benchmark's binary operation set for 3D CGA f64 (a subset: the products of grade pairs
//! (1,1), (1,2), (2,2), (1,4) on blades), ours against GATL's `gatl_ops.hpp`.
//!
//! Each row times `o[i] = a[i] op b[i]` over the N operands; its outputs, for the first
//! [`CHECKED`] operands, are written as all 32 coefficients in `Mv` blade order (GATL maps its
//! blades to those names as for the other CGA rows). A product that is identically zero for a
//! pair (the regressive product below grade 5, right contractions and scalar products of
//! unequal grades) is not generated, and has no row.

use crate::{each2, time_pass, Record, N};
use cga::f64::{
    CommutatorProduct, DotProduct, HestenesInnerProduct, InverseGeometricProduct,
    RegressiveProduct, RightContraction, ScalarProduct,
};
use cga::{Bivector, Even, Mv, Odd, Pseudoscalar, Quadvector, Trivector, Vector};
use std::collections::BTreeMap;
use std::hint::black_box;

/// Operands whose outputs are compared (all N are timed).
pub(crate) const CHECKED: usize = 1000;

/// The grade pairs and their products, as `(pair key, product keys)`: what the rows and the
/// report's table are made of.
pub(crate) const PAIRS: [(&str, &[&str]); 4] = [
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
pub(crate) fn product_name(key: &str) -> &'static str {
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
    Bivector,
    Trivector,
    Quadvector,
    Pseudoscalar,
    Even,
    Odd
);

/// Times one product over the operands and records it.
fn row<A: Copy, B: Copy, T: AsMv>(
    rec: &mut Record,
    key: &str,
    (a, b): (&[A], &[B]),
    f: impl Fn(A, B) -> T,
) {
    let mut out = vec![T::default(); N];
    let ns = time_pass(&mut out, |o| {
        let (a, b) = black_box((a, b));
        each2(o, a, b, &f);
    });
    rec.add(key, ns, &out[..CHECKED], T::mv);
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

/// Every operation row (keys `ops.PAIR.PRODUCT`).
pub(crate) fn op_rows(inp: &BTreeMap<&str, Vec<f64>>, rec: &mut Record) {
    let typed = |name: &str| -> Vec<Vec<f64>> {
        let w = crate::SECTIONS.iter().find(|s| s.0 == name).unwrap().1;
        inp[name].chunks_exact(w).map(<[f64]>::to_vec).collect()
    };
    let v = |name| -> Vec<Vector> {
        typed(name)
            .iter()
            .map(|c| Vector::from_array(c[..].try_into().unwrap()))
            .collect()
    };
    let (va, vb) = (v("cga.vector_a"), v("cga.vector_b"));
    let b2 = |name| -> Vec<Bivector> {
        typed(name)
            .iter()
            .map(|c| Bivector::from_array(c[..].try_into().unwrap()))
            .collect()
    };
    let (ba, bb) = (b2("cga.blade2_a"), b2("cga.blade2_b"));
    let q4: Vec<Quadvector> = typed("cga.blade4")
        .iter()
        .map(|c| Quadvector::from_array(c[..].try_into().unwrap()))
        .collect();
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
}

/// A blade operand of grade 2 or 4: the outer product of random vectors (ga-benchmark's
/// `MakeRandomBlade`), in our blade order.
pub(crate) fn blade(grade: usize, rng: &mut benches::timing::Lcg) -> Vec<f64> {
    let mut vec = || Vector::from_array(rng.array::<5>());
    match grade {
        2 => (vec() ^ vec()).to_array().to_vec(),
        4 => (((vec() ^ vec()) ^ vec()) ^ vec()).to_array().to_vec(),
        _ => unreachable!("grade {grade}"),
    }
}
