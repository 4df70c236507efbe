//! Our side of the peer harness `benches/peers/run.sh` (klein for PGA f32, GATL for CGA f64):
//! writes the one input file both sides read, times our rows on it, and reads every side's
//! timings and outputs back to print the graded table.
//!
//! ```text
//! peer_ops gen INPUT                 # the operands, from a fixed seed
//! peer_ops run INPUT OUT_PREFIX      # our rows: OUT_PREFIX.times (ns per op) and OUT_PREFIX.out
//! peer_ops report DIR ROUNDS         # DIR/{ours,klein,gatl}.R.times and .out -> the table
//! ```
//!
//! Files (all little-endian). INPUT: `GAPEERS1`, `n: u64`, then the sections of [`SECTIONS`] in
//! order, each `n * width` f64 (the PGA ones hold values that are exact f32). OUT_PREFIX.out:
//! records `name_len: u32, name, count: u64, count f64`, every output in OUR blade order (the
//! peers map theirs before writing). OUT_PREFIX.times: lines `key ns_per_op`.
//!
//! Blade order and signs. PGA: klein names its blades as `algebras/pga3d.toml` does (`e23, e31,
//! e12, e01, e02, e03, e0123`; points `e032, e013, e021, e123`), with the same product and the same
//! sandwich `m x ~m`, so the mapping is the identity on names (klein keeps them in other lanes:
//! a point's `p3_` is `(e123, e032, e013, e021)`, a motor's `p1_ = (s, e23, e31, e12)`,
//! `p2_ = (e0123, e01, e02, e03)`); klein's `mat4x4` column `c`, lane `r` is our
//! `point_matrix().rows()[r][c]`. CGA: GATL's `ga3c` has the same metric (`no . ni = -1`) with basis
//! order `e1, e2, e3, no, ni` where ours is `eo, e1, e2, e3, ei`: our blade `eo12i` is
//! `no ^ e1 ^ e2 ^ ni = -(e1 ^ e2 ^ no ^ ni)`, i.e. the sign of the permutation that sorts our
//! basis order into GATL's (`gatl.cpp` computes it for every blade).
//!
//! Built at the x86-64 baseline (no `-C target-cpu`): `cargo build --release -p benches
//! --example peer_ops`.

mod ik;
mod ops;
mod pga_rows;
mod report;

mod pga {
    ga_macros::algebra!(path = "../algebras/pga3d.toml", scalar = f32);
}

use benches::grade::Spread;
use benches::timing::Lcg;
use cga::f64::Sandwich as _;
use std::collections::BTreeMap;
use std::hint::black_box;
use std::io::Write;
use std::path::Path;
use std::time::Instant;

/// Operands per row.
const N: usize = 10_000;
/// Timed passes over the N operands per row and run (the median is the run's figure).
const PASSES: usize = 41;

/// The input file's sections: name and f64 values per operand, in file order.
const SECTIONS: [(&str, usize); 26] = [
    ("pga.motor_a", 8),  // s e23 e31 e12 e01 e02 e03 e0123 (unit)
    ("pga.motor_b", 8),  // the same
    ("pga.point", 4),    // e032 e013 e021 e123 (e123 = 1)
    ("pga.rotor_a", 4),  // s e23 e31 e12 (unit)
    ("pga.rotor_b", 4),  // the same
    ("pga.line", 6),     // e01 e02 e03 e23 e31 e12
    ("cga.vector_a", 5), // eo e1 e2 e3 ei
    ("cga.vector_b", 5),
    ("cga.bivector_a", 10), // eo1 eo2 eo3 eoi e12 e13 e23 e1i e2i e3i
    ("cga.bivector_b", 10),
    ("cga.motor_a", 8), // s e12 e13 e23 e1i e2i e3i e123i (unit)
    ("cga.motor_b", 8),
    ("cga.point", 4),     // e1 e2 e3 ei (eo = 1, not stored)
    ("cga.ik_angles", 5), // ga-benchmark's inverse kinematics: 5 joint angles
    ("cga.blade2_a", 10), // blades for the operation rows (`ops.rs`): outer products of vectors
    ("cga.blade2_b", 10),
    ("cga.blade4_a", 5),
    ("cga.blade0_a", 1), // the rest of the blades of grade 0..=5, left (a) and right (b) operands
    ("cga.blade0_b", 1),
    ("cga.blade1_a", 5),
    ("cga.blade1_b", 5),
    ("cga.blade3_a", 10),
    ("cga.blade3_b", 10),
    ("cga.blade4_b", 5),
    ("cga.blade5_a", 1),
    ("cga.blade5_b", 1),
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    match args.as_slice() {
        ["gen", input] => write_input(Path::new(input)),
        ["run", input, prefix] => run(Path::new(input), prefix),
        ["report", dir, rounds] => {
            let rounds = rounds.parse().expect("ROUNDS: a number");
            std::process::exit(report::report(Path::new(dir), rounds));
        }
        _ => {
            eprintln!("usage: peer_ops gen INPUT | run INPUT OUT_PREFIX | report DIR ROUNDS");
            std::process::exit(2);
        }
    }
}

// ---------------------------------------------------------------------------------- the input

/// PGA f32 operands from f64 ones: rounded once, so both sides read the same floats.
fn f32_exact(v: &[f64]) -> Vec<f64> {
    v.iter().map(|&x| f64::from(x as f32)).collect()
}

fn write_input(path: &Path) {
    let mut rng = Lcg(0x5eed_2047);
    let mut sections: BTreeMap<&str, Vec<f64>> = BTreeMap::new();
    for &(name, _) in &SECTIONS {
        let mut v = Vec::new();
        for _ in 0..N {
            v.extend(operand(name, &mut rng));
        }
        sections.insert(name, v);
    }
    let mut bytes = b"GAPEERS1".to_vec();
    bytes.extend((N as u64).to_le_bytes());
    for &(name, width) in &SECTIONS {
        let v = &sections[name];
        assert_eq!(v.len(), N * width, "{name}");
        bytes.extend(v.iter().flat_map(|x| x.to_le_bytes()));
    }
    std::fs::write(path, bytes).expect("write INPUT");
}

/// One random operand of a section, in our blade order.
fn operand(name: &str, rng: &mut Lcg) -> Vec<f64> {
    let unit_rotor = |rng: &mut Lcg| {
        let q = rng.quat(); // turn by up to 3 rad
                            // The rotor of that turn is `cos(a/2) - sin(a/2) (nx e23 + ny e31 + nz e12)`.
        [q.w, -q.x, -q.y, -q.z]
    };
    match name {
        "pga.motor_a" | "pga.motor_b" => {
            // T R with T = 1 - (t/2)(tx e01 + ty e02 + tz e03): rotate, then move by t
            // (the product in f32, by the generated code: both sides read its floats).
            let r = f32s(unit_rotor(rng));
            let t = rng.vec3() * -0.5;
            let t = pga::Translator::new(1.0, t.x as f32, t.y as f32, t.z as f32);
            let m = t * pga::Rotor::from_array(r);
            m.to_array().map(f64::from).to_vec()
        }
        "pga.point" => {
            let p = rng.vec3();
            f32_exact(&[p.x, p.y, p.z, 1.0])
        }
        "pga.rotor_a" | "pga.rotor_b" => f32_exact(&unit_rotor(rng)),
        "pga.line" => {
            let d = rng.array::<3>();
            let m = rng.vec3();
            f32_exact(&[m.x, m.y, m.z, d[0], d[1], d[2]])
        }
        "cga.vector_a" | "cga.vector_b" => rng.array::<5>().to_vec(),
        "cga.bivector_a" | "cga.bivector_b" => rng.array::<10>().to_vec(),
        "cga.motor_a" | "cga.motor_b" => rng.motor().to_array().to_vec(),
        "cga.point" => {
            let x = rng.vec3();
            vec![x.x, x.y, x.z, 0.5 * x.length_squared()]
        }
        // Uniform in [-pi/2, pi/2). ga-benchmark's `MakeRandomAngle` draws [0, 2 pi): at
        // half-angles near pi the series versors are far from unit, the chained sandwiches
        // reach 1e124 and no comparison of outputs means anything. The series has no branch,
        // so its time does not depend on the values.
        "cga.ik_angles" => (0..5)
            .map(|_| rng.uniform() * std::f64::consts::FRAC_PI_2)
            .collect(),
        _ if name.starts_with("cga.blade") => {
            ops::blade(usize::from(name.as_bytes()[9] - b'0'), rng)
        }
        _ => unreachable!("{name}"),
    }
}

fn read_input(path: &Path) -> BTreeMap<&'static str, Vec<f64>> {
    let bytes = std::fs::read(path).expect("read INPUT");
    assert!(
        bytes.len() >= 16 && &bytes[..8] == b"GAPEERS1",
        "not a peer input file"
    );
    let n = u64::from_le_bytes(bytes[8..16].try_into().unwrap()) as usize;
    assert_eq!(n, N, "operand count");
    let mut at = 16;
    let mut out = BTreeMap::new();
    for &(name, width) in &SECTIONS {
        let len = n * width * 8;
        let v = bytes[at..at + len]
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
            .collect();
        out.insert(name, v);
        at += len;
    }
    out
}

// ------------------------------------------------------------------------------ our side, timed

/// The median over [`PASSES`] of one pass over the operands, in ns per operand.
fn time_pass<T>(out: &mut [T], mut pass: impl FnMut(&mut [T])) -> f64 {
    for _ in 0..3 {
        pass(black_box(&mut *out));
    }
    let mut samples: Vec<f64> = (0..PASSES)
        .map(|_| {
            let start = Instant::now();
            pass(black_box(&mut *out));
            black_box(&mut *out);
            start.elapsed().as_nanos() as f64 / N as f64
        })
        .collect();
    Spread::median_of(&mut samples).value
}

/// `o[i] = f(a[i], b[i])`, by iterators (no bounds checks in the loop).
#[inline(always)]
fn each2<A: Copy, B: Copy, T>(o: &mut [T], a: &[A], b: &[B], f: impl Fn(A, B) -> T) {
    for ((o, a), b) in o.iter_mut().zip(a).zip(b) {
        *o = f(*a, *b);
    }
}

/// `o[i] = f(a[i])`, by iterators.
#[inline(always)]
fn each1<A: Copy, T>(o: &mut [T], a: &[A], f: impl Fn(A) -> T) {
    for (o, a) in o.iter_mut().zip(a) {
        *o = f(*a);
    }
}

/// Operands of a section as `T`, through its `from_array`.
fn typed<T, const K: usize>(v: &[f64], from: impl Fn([f64; K]) -> T) -> Vec<T> {
    v.chunks_exact(K)
        .map(|c| from(std::array::from_fn(|i| c[i])))
        .collect()
}

fn f32s<const K: usize>(a: [f64; K]) -> [f32; K] {
    a.map(|x| x as f32)
}

/// What one run records: ns per op by key, and the outputs by key (our blade order, f64).
#[derive(Default)]
struct Record {
    times: Vec<(String, f64)>,
    outputs: Vec<(String, Vec<f64>)>,
}

impl Record {
    fn add<T, const K: usize>(
        &mut self,
        key: &str,
        ns: f64,
        out: &[T],
        coeffs: impl Fn(&T) -> [f64; K],
    ) {
        self.times.push((key.to_string(), ns));
        self.outputs
            .push((key.to_string(), out.iter().flat_map(coeffs).collect()));
    }
}

fn run(input: &Path, prefix: &str) {
    let inp = read_input(input);
    let mut rec = Record::default();
    pga_rows::pga_rows(&inp, &mut rec);
    pga_rows::pga64_rows(&inp, &mut rec);
    cga_rows(&inp, &mut rec);
    ik_rows(&inp, &mut rec);
    ops::op_rows(&inp, &mut rec);
    let times: String = rec
        .times
        .iter()
        .map(|(k, ns)| format!("{k} {ns:.4}\n"))
        .collect();
    std::fs::write(format!("{prefix}.times"), times).expect("write times");
    write_outputs(&format!("{prefix}.out"), &rec.outputs);
}

fn cga_rows(inp: &BTreeMap<&str, Vec<f64>>, rec: &mut Record) {
    use cga::{Bivector, Even, Motor, Point, ScalarBivector, Vector};
    let va = typed(&inp["cga.vector_a"], Vector::from_array);
    let vb = typed(&inp["cga.vector_b"], Vector::from_array);
    let ba = typed(&inp["cga.bivector_a"], Bivector::from_array);
    let bb = typed(&inp["cga.bivector_b"], Bivector::from_array);
    let ma = typed(&inp["cga.motor_a"], Motor::from_array);
    let mb = typed(&inp["cga.motor_b"], Motor::from_array);
    let pts = typed(&inp["cga.point"], Point::from_array);

    // A scalar plus a bivector (`ScalarBivector`, 11 fields), as GATL's result.
    let mut sb = vec![ScalarBivector::from_array([0.0; 11]); N];
    let ns = time_pass(&mut sb, |o| {
        let (a, b) = black_box((&va, &vb));
        each2(o, a, b, |a, b| a * b);
    });
    rec.add("cga.vector_vector", ns, &sb, |e| e.to_array());

    let mut out = vec![Even::from_array([0.0; 16]); N];

    let ns = time_pass(&mut out, |o| {
        let (a, b) = black_box((&ba, &bb));
        each2(o, a, b, |a, b| a * b);
    });
    rec.add("cga.bivector_bivector", ns, &out, |e| e.to_array());

    let mut mout = vec![Motor::from_array([0.0; 8]); N];
    let ns = time_pass(&mut mout, |o| {
        let (a, b) = black_box((&ma, &mb));
        each2(o, a, b, |a, b| a * b);
    });
    rec.add("cga.motor_motor", ns, &mout, |m| m.to_array());

    let mut pout = vec![Point::from_array([0.0; 4]); N];
    let ns = time_pass(&mut pout, |o| {
        let (m, p) = black_box((&ma, &pts));
        each2(o, m, p, |m, p| m.sandwich(p));
    });
    // eo first (the constant 1 of a normalised point), then e1 e2 e3 ei.
    rec.add("cga.motor_point", ns, &pout, |p| {
        let [a, b, c, d] = p.to_array();
        [1.0, a, b, c, d]
    });
}

/// ga-benchmark's inverse kinematics (`ik.rs`), one solve per 5 angles: the Taylor series row and
/// the closed-form row.
fn ik_rows(inp: &BTreeMap<&str, Vec<f64>>, rec: &mut Record) {
    let angles = typed(&inp["cga.ik_angles"], |a: [f64; 5]| a);
    let mut out = vec![ik::Solve::zero(); N];
    let ns = time_pass(&mut out, |o| {
        each1(o, black_box(&angles), ik::solve::<ik::Taylor>);
    });
    rec.add("cga.ik_taylor", ns, &out, |s| s.to_array());
    let ns = time_pass(&mut out, |o| {
        each1(o, black_box(&angles), ik::solve::<ik::Closed>);
    });
    rec.add("cga.ik_exp", ns, &out, |s| s.to_array());
}

fn write_outputs(path: &str, outputs: &[(String, Vec<f64>)]) {
    let mut f = std::io::BufWriter::new(std::fs::File::create(path).expect("create outputs"));
    for (key, v) in outputs {
        f.write_all(&(key.len() as u32).to_le_bytes()).unwrap();
        f.write_all(key.as_bytes()).unwrap();
        f.write_all(&(v.len() as u64).to_le_bytes()).unwrap();
        for x in v {
            f.write_all(&x.to_le_bytes()).unwrap();
        }
    }
    f.flush().unwrap();
}
