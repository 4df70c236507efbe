//! ga-benchmark's inverse-kinematics workload (`AlgorithmInverseKinematics.cpp`: a 5-joint arm
//! in 3D CGA, f64) on the generated `cga` types; GATL's side is `benches/peers/gatl_ik.hpp`.
//!
//! One solve takes five joint angles and returns `(R1, R2, R3, T2, R4, Rg, Jg_f)`: the joints'
//! rotors, the translator of the second joint and the moved gripper point. The steps, products
//! and their order are ga-benchmark's; [`Exponential`] picks the exponential: its 4th-order
//! Taylor series `expp` ([`Taylor`], the same products as GATL's) or our closed form
//! ([`Closed`], the generated `Exp` impls).
//!
//! Types: a line (the generator of a joint) is a [`DualLine`] (the six blades `e12 e13 e23 e1i
//! e2i e3i`), joint 1's generator a [`Rotor`], the translation generator a [`Translator`]. The
//! series takes `x^2` by the generated `square` (expanded in one set of coefficients, as GATL's
//! lazy `x * x`: a line's square keeps only its scalar and `e123i`, a [`DualNumber`]), `x^3` as
//! `x^2 x` and `x^4` as `(x^2)^2`: the same polynomial, its powers by fewer products. The series
//! versors are not unit (`R ~R != 1`), so there `apply_rotor(R, X) = R X ~R` is the two full
//! geometric products, as in GATL (of a line: its bivector part, the part GATL's lazy product
//! keeps, so a moved line is a `DualLine` again); the closed-form versors are unit, and
//! [`Closed`] moves points by the generated unit-reduced `sandwich` (lines still by the two
//! products, cheaper than the fused bivector sandwich; GATL's closed-form side keeps
//! ga-benchmark's `apply_rotor`).
//!
//! Blade order and signs against GATL: the same as the other CGA rows (GATL's basis `e1, e2,
//! e3, no, ni` against our `eo, e1, e2, e3, ei`, one sign per blade from sorting; for the
//! blades here `s e12 e13 e23 e1i e2i e3i e123i` and `eo e1 e2 e3 ei` it is +1). GATL's
//! `dual(x)` is `x ⌋ I⁻¹` with `I = e1^e2^e3^no^ni`, which is `-eo^e1^e2^e3^ei`, minus our
//! `dual` (`x I⁻¹` with `I = eo123i`): [`gatl_dual`].

use cga::f64::{Exp as _, Sandwich as _};
use cga::glam::DVec3;
use cga::{
    Bivector, DualLine, DualNumber, Motor, Odd, Point, Rotor, Translator, Trivector, Vector,
};

/// The outputs of one solve.
#[derive(Clone, Copy, Debug)]
pub struct Solve {
    pub r1: Rotor,
    pub r2: Motor,
    pub r3: Motor,
    pub t2: Translator,
    pub r4: Motor,
    pub rg: Motor,
    pub jg: Vector,
}

impl Solve {
    /// Values per solve in [`Solve::to_array`].
    pub const LEN: usize = 45;

    /// `r1 r2 r3 t2 r4 rg jg`, each in its type's blade order.
    pub fn to_array(self) -> [f64; Self::LEN] {
        let mut v = [0.0; Self::LEN];
        let parts: [&[f64]; 7] = [
            &self.r1.to_array(),
            &self.r2.to_array(),
            &self.r3.to_array(),
            &self.t2.to_array(),
            &self.r4.to_array(),
            &self.rg.to_array(),
            &self.jg.to_array(),
        ];
        let mut at = 0;
        for p in parts {
            v[at..at + p.len()].copy_from_slice(p);
            at += p.len();
        }
        v
    }

    /// A solve with every value zero (output buffers).
    pub fn zero() -> Solve {
        Solve {
            r1: Rotor::from_array([0.0; 4]),
            r2: Motor::from_array([0.0; 8]),
            r3: Motor::from_array([0.0; 8]),
            t2: Translator::from_array([0.0; 4]),
            r4: Motor::from_array([0.0; 8]),
            rg: Motor::from_array([0.0; 8]),
            jg: Vector::from_array([0.0; 5]),
        }
    }
}

/// The exponential a solve uses, for each of its three kinds of generator.
pub trait Exponential {
    /// `exp` of a generator on `e12 e13 e23`.
    fn rotor(x: Rotor) -> Rotor;
    /// `exp` of a generator on `e1i e2i e3i`.
    fn translator(x: Translator) -> Translator;
    /// `exp` of a line.
    fn motor(x: DualLine) -> Motor;
    /// `apply_rotor(v, x)` of a line: the full products (the series' versors are not unit).
    #[inline(always)]
    fn move_line<V: Versor>(v: V, x: DualLine) -> DualLine {
        v.line_full(x)
    }
    /// `apply_rotor(v, p)` of a point.
    #[inline(always)]
    fn move_point<V: Versor>(v: V, p: Point) -> Vector {
        v.point_full(p)
    }
}

/// ga-benchmark's `expp`: `1 + x + x^2/2 + x^3/6 + x^4/24`, summed left to right, with
/// `x^2 = x.square()`, `x^3 = x^2 x`, `x^4 = (x^2).square()`.
pub struct Taylor;

/// The generated closed-form exponentials (`Exp<Rotor>`, `Exp<Translator>`, `Exp<Motor>` of a
/// [`DualLine`]).
pub struct Closed;

/// The series `1 + x + x^2/2 + x^3/6 + x^4/24` of `$x`, with `1` given as `$one`, by the
/// generated `square` and products (each term in the smallest type that holds it).
macro_rules! expp {
    ($one:expr, $x:expr) => {{
        let x = $x;
        let x2 = x.square();
        let x3 = x2 * x;
        let x4 = x2.square();
        $one + x + x2 / 2.0 + x3 / 6.0 + x4 / 24.0
    }};
}

impl Exponential for Taylor {
    #[inline(always)]
    fn rotor(x: Rotor) -> Rotor {
        expp!(Rotor::new(1.0, 0.0, 0.0, 0.0), x)
    }
    #[inline(always)]
    fn translator(x: Translator) -> Translator {
        expp!(Translator::new(1.0, 0.0, 0.0, 0.0), x)
    }
    #[inline(always)]
    fn motor(x: DualLine) -> Motor {
        expp!(DualNumber::new(1.0, 0.0), x)
    }
}

impl Exponential for Closed {
    #[inline(always)]
    fn rotor(x: Rotor) -> Rotor {
        DualLine::new(x.e12, x.e13, x.e23, 0.0, 0.0, 0.0).exp()
    }
    #[inline(always)]
    fn translator(x: Translator) -> Translator {
        DualLine::new(0.0, 0.0, 0.0, x.e1i, x.e2i, x.e3i).exp()
    }
    #[inline(always)]
    fn motor(x: DualLine) -> Motor {
        x.exp()
    }
    /// Closed-form versors are unit: points move by the generated unit-reduced `sandwich`
    /// (lines by the full products, which cost less than the fused bivector sandwich).
    #[inline(always)]
    fn move_point<V: Versor>(v: V, p: Point) -> Vector {
        v.point_unit(p)
    }
}

/// GATL's `dual`: minus ours (see the module doc).
#[inline(always)]
fn gatl_dual(t: Trivector) -> Bivector {
    -t.dual()
}

/// A dual line as a [`DualLine`] (its `eo` blades are zero, so nothing is dropped but exact
/// zeros).
#[inline(always)]
fn line(b: Bivector) -> DualLine {
    DualLine::new(b.e12, b.e13, b.e23, b.e1i, b.e2i, b.e3i)
}

/// The bivector part of `v x ~v` for a line `x`: all there is of it up to rounding (`v x ~v`
/// changes sign under reversion, so it has no scalar or `e123i` part; a motor has no `eo`).
#[inline(always)]
fn line_part(m: Motor) -> DualLine {
    DualLine::new(m.e12, m.e13, m.e23, m.e1i, m.e2i, m.e3i)
}

/// The dual line through `a` and `b`: GATL's `dual(a ^ b ^ ni)`.
#[inline(always)]
fn line_through(a: Point, b: Point) -> Bivector {
    gatl_dual((a ^ b) ^ Vector::new(0.0, 0.0, 0.0, 0.0, 1.0))
}

/// What a solve does with a versor `v`: move a line or a point, `v x ~v`.
pub trait Versor: Copy {
    /// `v x ~v` by the two full geometric products (`v` need not be unit), its bivector part.
    fn line_full(self, x: DualLine) -> DualLine;
    /// `v p ~v` by the two full products, its vector part.
    fn point_full(self, p: Point) -> Vector;
    /// The generated unit-reduced `sandwich` of a point (exact for unit `v` only).
    fn point_unit(self, p: Point) -> Vector;
}

/// The vector part of an odd result.
#[inline(always)]
fn vector_part(o: Odd) -> Vector {
    Vector::new(o.eo, o.e1, o.e2, o.e3, o.ei)
}

/// The vector part of a product's result, whichever odd type holds it.
trait VectorPart {
    fn vector_part(self) -> Vector;
}

impl VectorPart for Odd {
    #[inline(always)]
    fn vector_part(self) -> Vector {
        vector_part(self)
    }
}

impl VectorPart for cga::TrivectorPseudoscalar {
    /// None: the type holds grades 3 and 5 only (`Pseudoscalar * Rotor`).
    #[inline(always)]
    fn vector_part(self) -> Vector {
        Vector::new(0.0, 0.0, 0.0, 0.0, 0.0)
    }
}

/// The vector part of `o r` for an odd `o` and a versor `r`, as the sum of the vector parts
/// of `o`'s grades times `r` (products small enough to be inlined, so only the vector part is
/// computed).
#[inline(always)]
fn vector_of_odd_times<R>(o: Odd, r: R) -> Vector
where
    R: Copy,
    Vector: std::ops::Mul<R, Output = Odd>,
    Trivector: std::ops::Mul<R, Output = Odd>,
    cga::Pseudoscalar: std::ops::Mul<R>,
    <cga::Pseudoscalar as std::ops::Mul<R>>::Output: VectorPart,
{
    let v = Vector::new(o.eo, o.e1, o.e2, o.e3, o.ei);
    let t = Trivector::new(
        o.eo12, o.eo13, o.eo1i, o.eo23, o.eo2i, o.eo3i, o.e123, o.e12i, o.e13i, o.e23i,
    );
    let (a, b) = (vector_part(v * r), vector_part(t * r));
    let c = (cga::Pseudoscalar::new(o.eo123i) * r).vector_part();
    Vector::new(
        a.eo + b.eo + c.eo,
        a.e1 + b.e1 + c.e1,
        a.e2 + b.e2 + c.e2,
        a.e3 + b.e3 + c.e3,
        a.ei + b.ei + c.ei,
    )
}

/// [`Versor`] for generated versor types: the same three calls on each.
macro_rules! versor {
    ($($t:ty),*) => {$(
        impl Versor for $t {
            #[inline(always)]
            fn line_full(self, x: DualLine) -> DualLine {
                line_part((self * x) * self.rev())
            }
            #[inline(always)]
            fn point_full(self, p: Point) -> Vector {
                vector_of_odd_times((self * p), self.rev())
            }
            #[inline(always)]
            fn point_unit(self, p: Point) -> Vector {
                self.sandwich(p).into()
            }
        }
    )*};
}

versor!(Rotor, Motor);

fn pt(x: f64, y: f64, z: f64) -> Point {
    Point::from_vec3(DVec3::new(x, y, z))
}

/// One solve for the joint angles `a` (radians).
#[inline(always)]
pub fn solve<E: Exponential>(a: [f64; 5]) -> Solve {
    let (d1, d2, d3, d4, d5) = (200.0, 680.0, 150.0, 140.0, 114.2);
    let (l12, l23) = (890.0, 880.0);
    let j1 = pt(d1, 0.0, d2);
    let j2 = pt(d1, 0.0, d2 + l12);
    let j3 = pt(d1 + l23, 0.0, d2 + l12 + d3);
    let jg = pt(d1 + l23 + d4 + d5, 0.0, d2 + l12 + d3);

    // Joint 1 turns about the z axis: dual(no ^ P_z ^ ni) is e12.
    let eo = pt(0.0, 0.0, 0.0);
    let lz = line_through(eo, pt(0.0, 0.0, 1.0));
    let r1 = E::rotor(Rotor::new(0.0, lz.e12, lz.e13, lz.e23) * (a[0] / 2.0));

    // Joint 2 about the line through J1 along y, carried by joint 1.
    let l2 = E::move_line(r1, line(line_through(j1, pt(d1, 1.0, d2))));
    let r2 = E::motor(l2 * (a[1] / 2.0));
    let r21 = r2 * r1;
    let j2_f = E::move_point(r21, j2);

    // Joint 3 about the line through J2 along y, carried by joints 1 and 2.
    let l3 = E::move_line(r21, line(line_through(j2, pt(d1, 1.0, d2 + l12))));
    let r3 = E::motor(l3 * (a[2] / 2.0));

    // The translation joint 2 gave J2 (`sp(X, e_k)` is X's e_k coefficient) as a translator.
    let j2_r1 = E::move_point(r1, j2);
    let t = DVec3::new(j2_f.e1 - j2_r1.e1, j2_f.e2 - j2_r1.e2, j2_f.e3 - j2_r1.e3);
    let t2 = E::translator(Translator::new(0.0, t.x, t.y, t.z) * -0.5);

    // Joint 4 about the unit line J3 Jg, joint 5 about the line through J3 along y.
    let m4 = r3 * t2 * r1;
    let l4 = E::move_line(m4, line(line_through(j3, jg).normalized()));
    let r4 = E::motor(l4 * (a[3] / 2.0));
    let mg = r4 * r3 * t2 * r1;
    let lg_init = line_through(j3, pt(d1 + l23, 1.0, d2 + l12 + d3));
    let lg = E::move_line(mg, line(lg_init));
    let rg = E::motor(lg * (a[4] / 2.0));
    let mf = rg * r3 * t2 * r1;
    let jg_f = E::move_point(mf, jg);
    Solve {
        r1,
        r2,
        r3,
        t2,
        r4,
        rg,
        jg: jg_f,
    }
}
