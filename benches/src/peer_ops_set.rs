//! ga-benchmark's binary operation set for 3D CGA f64: every product it times for every pair of
//! grades 0..=5 on blades, our side of the peer harness's operation rows
//! (`benches/examples/peer_ops/`, GATL's side `benches/peers/gatl_ops.hpp`). The unary set is
//! in [`crate::peer_ops_unary`].
//!
//! It lives in the library, compiled apart from the example: in the example crate its
//! instantiated loops changed LLVM's inlining there (the `bivector * bivector` row's
//! `Bivector * Bivector` went out of line, 14 ns to 38), and passing the closures by
//! reference instead kept a call per operand in these rows.
//!
//! Each row times `o[i] = a[i] op b[i]` over the N operands; its outputs, for the first
//! [`CHECKED`] operands, are written as all 32 coefficients in `Mv` blade order (GATL maps its
//! blades to those names as for the other CGA rows). Operands of grade 0..=5 are `f64`,
//! `Vector`, `Bivector`, `Trivector`, `Quadvector`, `Pseudoscalar`; the grade-(0, 0) rows are
//! plain `f64` arithmetic. A product that is identically zero for a pair (see [`products`]) is
//! not generated, and has no row.

use crate::grade::Spread;
use cga::f64::{
    CommutatorProduct, DotProduct, HestenesInnerProduct, InverseGeometricProduct,
    RegressiveProduct, RightContraction, ScalarProduct,
};
use cga::{
    Bivector, Even, Mv, Odd, Pseudoscalar, Quadvector, ScalarBivector, Trivector,
    TrivectorPseudoscalar, Vector,
};
use std::hint::black_box;
use std::time::Instant;

/// Operands per row (the harness's N).
pub const N: usize = 10_000;
/// Timed passes per row (the harness's PASSES).
const PASSES: usize = 41;

/// Operands whose outputs are compared (all N are timed).
pub const CHECKED: usize = 1000;

/// The highest grade (3D CGA: 5 basis vectors).
pub const MAX_GRADE: usize = 5;

/// The products of ga-benchmark's set that are not identically zero on blades of grades `ga`,
/// `gb` (keys, in row order): the outer product needs `ga + gb <= 5`, the left contraction
/// `ga <= gb`, the right one `ga >= gb`, the scalar product `ga = gb`, the Hestenes inner product
/// two non-scalars, the commutator product two grades in 1..=4 (a scalar and the
/// pseudoscalar of an odd dimension commute with everything), the regressive product
/// `ga + gb >= 5`.
pub fn products(ga: usize, gb: usize) -> Vec<&'static str> {
    let mut v = vec!["gp"];
    let mut add = |on: bool, key| on.then(|| v.push(key));
    add(ga + gb <= MAX_GRADE, "op");
    add(ga <= gb, "lc");
    add(ga >= gb, "rc");
    add(ga == gb, "sp");
    add(true, "dot");
    add(ga > 0 && gb > 0, "hip");
    let inner = 1..MAX_GRADE;
    add(inner.contains(&ga) && inner.contains(&gb), "cp");
    add(ga + gb >= MAX_GRADE, "rp");
    add(true, "igp");
    v
}

/// Every grade pair ga-benchmark times, `(ga, gb)` for `ga, gb` in `0..=5`, with its key
/// (`"23"`).
pub fn pairs() -> Vec<(usize, usize, String)> {
    (0..=MAX_GRADE)
        .flat_map(|a| (0..=MAX_GRADE).map(move |b| (a, b, format!("{a}{b}"))))
        .collect()
}

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
pub(crate) trait AsMv: Copy + Default {
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
    TrivectorPseudoscalar,
    Quadvector,
    Pseudoscalar,
    Even,
    Odd,
    Mv
);

/// One row: key, ns per op, the first [`CHECKED`] outputs as 32 coefficients each.
pub type Row = (String, f64, Vec<f64>);

/// The harness's timer: the median over [`PASSES`] of one pass (after 3 warm-up passes), in ns
/// per operand, `o[i] = f(a[i], b[i])` by iterators.
pub(crate) fn time_pass<A: Copy, B: Copy, T>(
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

/// The rows of one pair: every product the pair has, in [`products`] order.
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

/// The rows of many pairs: `[a b: products]` for operands `a`, `b` (slices).
macro_rules! all_pairs {
    ($rec:expr, $($pair:literal $a:ident $b:ident: [$($op:ident)*])*) => {
        $(pair_rows!($rec, $pair, (&$a[..], &$b[..]), [$($op),*]);)*
    };
}

/// The typed operands of one side: grade 0 as `f64`, 1..=5 as the generated blade types.
struct Operands {
    s: Vec<f64>,
    v: Vec<Vector>,
    b: Vec<Bivector>,
    t: Vec<Trivector>,
    q: Vec<Quadvector>,
    p: Vec<Pseudoscalar>,
}

impl Operands {
    /// From the coefficients of blades of grade 0..=5 (our blade order).
    fn new(c: [&[f64]; 6]) -> Operands {
        fn typed<T, const K: usize>(v: &[f64], from: fn([f64; K]) -> T) -> Vec<T> {
            v.chunks_exact(K)
                .map(|c| from(c.try_into().unwrap()))
                .collect()
        }
        Operands {
            s: c[0].to_vec(),
            v: typed(c[1], Vector::from_array),
            b: typed(c[2], Bivector::from_array),
            t: typed(c[3], Trivector::from_array),
            q: typed(c[4], Quadvector::from_array),
            p: typed(c[5], Pseudoscalar::from_array),
        }
    }
}

/// Every binary operation row (keys `ops.PAIR.PRODUCT`, [`pairs`] and [`products`] in order),
/// from the coefficients of blades of grade 0..=5, left operands `l` and right ones `r`.
pub fn op_rows(l: [&[f64]; 6], r: [&[f64]; 6]) -> Vec<Row> {
    let (l, r) = (Operands::new(l), Operands::new(r));
    let (s0, v1, b2, t3, q4, p5) = (&l.s, &l.v, &l.b, &l.t, &l.q, &l.p);
    let (s0r, v1r, b2r, t3r, q4r, p5r) = (&r.s, &r.v, &r.b, &r.t, &r.q, &r.p);
    let rec = &mut Vec::new();
    // Two scalars: `f64` arithmetic (the inverse geometric product is the quotient).
    let ss = (&s0[..], &s0r[..]);
    for key in ["gp", "op", "lc", "rc", "sp", "dot"] {
        row(rec, &format!("ops.00.{key}"), ss, |x: f64, y: f64| x * y);
    }
    row(rec, "ops.00.igp", ss, |x: f64, y: f64| x / y);
    all_pairs!(rec,
        "01" s0 v1r: [gp op lc dot igp]
        "02" s0 b2r: [gp op lc dot igp]
        "03" s0 t3r: [gp op lc dot igp]
        "04" s0 q4r: [gp op lc dot igp]
        "05" s0 p5r: [gp op lc dot rp igp]
        "10" v1 s0r: [gp op rc dot igp]
        "11" v1 v1r: [gp op lc rc sp dot hip cp igp]
        "12" v1 b2r: [gp op lc dot hip cp igp]
        "13" v1 t3r: [gp op lc dot hip cp igp]
        "14" v1 q4r: [gp op lc dot hip cp rp igp]
        "15" v1 p5r: [gp lc dot hip rp igp]
        "20" b2 s0r: [gp op rc dot igp]
        "21" b2 v1r: [gp op rc dot hip cp igp]
        "22" b2 b2r: [gp op lc rc sp dot hip cp igp]
        "23" b2 t3r: [gp op lc dot hip cp rp igp]
        "24" b2 q4r: [gp lc dot hip cp rp igp]
        "25" b2 p5r: [gp lc dot hip rp igp]
        "30" t3 s0r: [gp op rc dot igp]
        "31" t3 v1r: [gp op rc dot hip cp igp]
        "32" t3 b2r: [gp op rc dot hip cp rp igp]
        "33" t3 t3r: [gp lc rc sp dot hip cp rp igp]
        "34" t3 q4r: [gp lc dot hip cp rp igp]
        "35" t3 p5r: [gp lc dot hip rp igp]
        "40" q4 s0r: [gp op rc dot igp]
        "41" q4 v1r: [gp op rc dot hip cp rp igp]
        "42" q4 b2r: [gp rc dot hip cp rp igp]
        "43" q4 t3r: [gp rc dot hip cp rp igp]
        "44" q4 q4r: [gp lc rc sp dot hip cp rp igp]
        "45" q4 p5r: [gp lc dot hip rp igp]
        "50" p5 s0r: [gp op rc dot rp igp]
        "51" p5 v1r: [gp rc dot hip rp igp]
        "52" p5 b2r: [gp rc dot hip rp igp]
        "53" p5 t3r: [gp rc dot hip rp igp]
        "54" p5 q4r: [gp rc dot hip rp igp]
        "55" p5 p5r: [gp lc rc sp dot hip rp igp]
    );
    std::mem::take(rec)
}

/// A blade operand of grade `grade` in `0..=5`: a random scalar times the outer product of
/// `grade` random vectors (ga-benchmark's `MakeRandomBlade`, with the vectors' coordinates all
/// random), in our blade order, drawn again until `|<x ~x>_0|` is at least 1/20 of the sum of
/// the squared coefficients (ga-benchmark's `MakeRandomInvertibleBlade` asks a non-zero norm;
/// this also keeps inverses and quotients well conditioned, so that two implementations agree
/// to rounding).
pub fn blade(grade: usize, rng: &mut crate::timing::Lcg) -> Vec<f64> {
    let c = blade_mv(grade, rng).to_array();
    let at = |name: &&str| Mv::BLADES.iter().position(|b| b == name).unwrap();
    let pick = |blades: &[&str]| blades.iter().map(|n| c[at(n)]).collect();
    match grade {
        0 => vec![c[0]],
        1 => pick(&Vector::BLADES),
        2 => pick(&Bivector::BLADES),
        3 => pick(&Trivector::BLADES),
        4 => pick(&Quadvector::BLADES),
        5 => pick(&Pseudoscalar::BLADES),
        _ => unreachable!("grade {grade}"),
    }
}

/// The blade of [`blade`] as a multivector.
fn blade_mv(grade: usize, rng: &mut crate::timing::Lcg) -> Mv {
    loop {
        let s = rng.uniform();
        let mut m = Mv::from_array(std::array::from_fn(|i| if i == 0 { s } else { 0.0 }));
        for _ in 0..grade {
            m = m ^ Vector::from_array(rng.array::<5>());
        }
        let squares: f64 = m.to_array().iter().map(|x| x * x).sum();
        if m.norm_squared().abs() >= squares / 20.0 {
            return m;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ga_codegen::runtime::derived::DerivedProducts as _;

    /// [`products`] against the generic multivector: a product of ga-benchmark's set has a row
    /// for a pair of grades exactly when it is not zero on random blades of those grades.
    #[test]
    fn the_rows_are_the_products_not_identically_zero() {
        let mut rng = crate::timing::Lcg(0x0b5e7);
        for (ga, gb, _) in pairs() {
            let mut nonzero = Vec::new();
            for _ in 0..3 {
                let a = blade_mv(ga, &mut rng).to_multivector();
                let b = blade_mv(gb, &mut rng).to_multivector();
                let alg = a.algebra().clone();
                let scalar = |x: f64| ga_codegen::Multivector::scalar(&alg, x);
                let all = [
                    ("gp", a.gp(&b)),
                    ("op", a.outer(&b)),
                    ("lc", a.left_contraction(&b)),
                    ("rc", a.right_contraction(&b)),
                    ("sp", scalar(a.scalar_product(&b))),
                    ("dot", a.dot_product(&b)),
                    ("hip", a.hestenes_inner_product(&b)),
                    ("cp", a.commutator_product(&b)),
                    ("rp", a.regressive_product(&b)),
                    (
                        "igp",
                        a.inverse_geometric_product(&b)
                            .expect("an invertible blade"),
                    ),
                ];
                for (key, m) in all {
                    if m.max_abs() > 1e-12 && !nonzero.contains(&key) {
                        nonzero.push(key);
                    }
                }
            }
            let mut want = products(ga, gb);
            want.sort_unstable();
            nonzero.sort_unstable();
            assert_eq!(nonzero, want, "grades ({ga}, {gb})");
        }
    }

    /// Blades are blades of their grade, normalisable: `|<x ~x>_0|` computed by the generic
    /// multivector is not small against the sum of the squared coefficients (the operands of
    /// the rows are scaled as drawn, so the bound is relative).
    #[test]
    fn blades_have_their_grade_and_a_norm() {
        let mut rng = crate::timing::Lcg(3);
        for g in 0..=MAX_GRADE {
            for _ in 0..20 {
                let m = blade_mv(g, &mut rng).to_multivector();
                assert!((m.max_diff(&m.grade(g as u32))) == 0.0, "grade {g}");
                let squares: f64 = m.coeffs().iter().map(|x| x * x).sum();
                assert!(squares > 0.0, "grade {g}: zero");
                assert!(m.norm_squared().abs() >= squares / 20.0, "grade {g}");
            }
        }
    }
}
