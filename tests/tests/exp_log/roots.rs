//! The square root near its cut: rounding off the commutant of `J`, two rotations across a
//! half turn, one near a full turn, and scaled versors.

use super::*;
use tests::{cga, g3, pga3d, sta};

/// A CGA `Even` near the cut (`<v>_0 - p = -0.99998`) whose bivector part, rounded, leaks
/// into bivectors that do not commute with `J`: divided by the small imaginary part, the
/// leak made the root's square 1.3e-12 off in f64 and 1e-3 in f32 until the unit imaginary
/// was projected on the commutant of `J` as well. Found by `sqrt_squares_back`.
#[test]
fn sqrt_near_the_cut_with_rounding_off_the_commutant() {
    use tests::cga_f32;
    let c = [
        0.0,
        0.9569863430254548,
        -0.7157255882611253,
        0.821289996219408,
        0.6839236889330607,
        -0.4866255120801515,
        0.6022356894744446,
        -0.8986633857523371,
        0.9489793439003248,
        -0.8105985922075651,
        0.9139748562125125,
    ];
    let alg = cga::algebra();
    let planes = on_blades(&alg, &cga::Even::BLADES, &[2], &c, 1.1975711592178102);
    let v: cga::Even = cga::Exp::exp(cga::Bivector::from_multivector(&planes));
    let u4 = [v.eo123, v.eo12i, v.eo13i, v.eo23i, v.e123i];
    let p = (2.0 * u4[0] * u4[4] - u4[1] * u4[1] - u4[2] * u4[2] - u4[3] * u4[3]).sqrt();
    let s1 = (1.0 + v.s) * (1.0 + v.s);
    assert!(
        s1 - p * p < p * s1 && v.s - p < -0.9999,
        "the case under test (the split root, near the cut)"
    );
    let w = cga::EvenVersor::sqrt(v).to_multivector();
    near("f64", &w.gp(&w), &v.to_multivector(), 1e-15);
    let vf = cga_f32::Even::from_array(v.to_array().map(|x| x as f32));
    let w = cga_f32::EvenVersor::sqrt(vf).to_multivector();
    near("f32", &w.gp(&w), &vf.to_multivector(), 1e-6);
}

/// `w` is a root of `v` (`w^2 = v`) and a unit (`w ~w = 1`), to `tol`.
fn root_of(what: &str, v: Multivector, w: Multivector, tol: f64) {
    near(&format!("{what}: w^2 = v"), &w.gp(&w), &v, tol);
    let one = Multivector::scalar(v.algebra(), 1.0);
    near(&format!("{what}: w ~w = 1"), &w.gp(&w.rev()), &one, tol);
}

/// Two commuting rotations whose angles sum to about a half turn, `a + b = pi - d`: there
/// `1 + v` is nearly a zero divisor (one on the cut), and `normalize(1 + v)` cancelled
/// (its square 1.6e-4 off `v` at `d = 1e-6` in f64, not finite at `d = 0`). The root taken
/// in the two halves of `J` squares back to `v` and is a unit, to rounding, on both sides
/// of the cut and on it, in G(4,0) (planes `e12`, `e34`) and CGA (`e12` and `e3 ^ e+`,
/// `e+ = eo - ei/2`), in f64 and f32. So it does with one of the two rotations near a full
/// turn (`<v>_0 < 0`, where CGA's `Even` keeps `normalize(1 + v)` and its cut form for two
/// rotations, not the screws' root beyond a half turn).
#[test]
fn sqrt_across_the_half_turn_cut() {
    use tests::{cga_f32, sig400, sig400_f32};
    let g4 = sig400::algebra();
    let c5 = cga::algebra();
    let pi = std::f64::consts::PI;
    let mut pairs = Vec::new();
    for a in [0.4, 1.0, 1.3] {
        for d in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 0.0, -1e-9, -1e-7, -1e-3] {
            pairs.push((a, pi - a - d, format!("a = {a}, d = {d:e}")));
        }
        // The other rotation within `2 d` of a full turn (its half-angle `pi - d`:
        // `<v>_0 < 0`, away from the cut).
        for d in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9] {
            pairs.push((
                a,
                pi - d,
                format!("a = {a}, the other {d:e} from a full turn"),
            ));
        }
    }
    for (a, b, what) in pairs {
        // The root of `exp(planes)` in an algebra and its f32 twin.
        macro_rules! case {
            ($m:ident, $m32:ident, $planes:expr, $label:expr) => {{
                let v: $m::Even = $m::Exp::exp($m::Bivector::from_multivector(&$planes));
                let w = $m::EvenVersor::sqrt(v).to_multivector();
                root_of(&format!("{} {what}", $label), v.to_multivector(), w, 1e-14);
                let v = $m32::Even::from_array(v.to_array().map(|x| x as f32));
                let w = $m32::EvenVersor::sqrt(v).to_multivector();
                root_of(
                    &format!("{} f32 {what}", $label),
                    v.to_multivector(),
                    w,
                    1e-6,
                );
            }};
        }
        case!(
            sig400,
            sig400_f32,
            on_blades(&g4, &["e12", "e34"], &[2], &[a, b], 1.0),
            "G(4,0)"
        );
        case!(
            cga,
            cga_f32,
            on_blades(&c5, &["e12", "eo3", "e3i"], &[2], &[a, -b, -0.5 * b], 1.0),
            "CGA"
        );
    }
}

/// Rotations within `d` of a full turn (`v` near `-1`): `1 + <v>_0` cancels there, and
/// until `sqrt` took it as `<y ~y>_0 / (|v| - <v>_0)` the root's square was off by about
/// `eps / d` (G(3) failed at `d = 1e-3` in f64). The root of a versor scaled by `k` is that
/// of the versor (it is `sqrt(v / |v|)`). Screws (CGA and PGA motors that also shift along
/// their axis) lost about `eps / d` there until their root beyond a half turn became
/// `exp(log / 2)` the long way round: `normalize(1 + v)` cancels terms of size `1 / d`
/// (f64 1.8e-13 off at `d = 1e-3` and 1.7e-7 at `1e-9`; f32 1.6e-4 at `1e-3`, 0.8 at `1e-7`
/// and 58 at `1e-9`); a CGA similarity with a dilation of 0.3 lost more (f64 1.7e-11 at
/// `1e-3`, 2e-4 at `1e-7`, not finite at `1e-9`), and gets the same root, in its own type
/// and in CGA's `Even` (where the grade-4 part does not square positive).
#[test]
fn sqrt_near_a_full_turn_and_of_a_scaled_versor() {
    use tests::{cga_f32, sig400};
    let (a3, a5, a4) = (g3::algebra(), cga::algebra(), sig400::algebra());
    let tau = std::f64::consts::TAU;
    for d in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9] {
        let t = tau - d;
        let what = format!("{d:e} from a full turn");
        // A bivector on the named planes with norm t / 2 (a turn by t).
        let turn = |alg: &std::sync::Arc<ga_codegen::Algebra>, names: &[&str], c: &[f64]| {
            let b = on_blades(alg, names, &[2], c, 1.0);
            b.scale(0.5 * t / b.gp(&b.rev()).get(0).sqrt())
        };
        let oblique = [0.3, -0.5, 0.8, 0.1];
        // G(3): a rotor about an oblique axis.
        let v: g3::Rotor = g3::Exp::exp(g3::Bivector::from_multivector(&turn(
            &a3,
            &["e12", "e13", "e23"],
            &oblique,
        )));
        assert!(v.s + 1.0 < 0.6 * d * d, "{what}: near -1");
        let w = g3::EvenVersor::sqrt(v).to_multivector();
        root_of(&format!("G(3) {what}"), v.to_multivector(), w, 1e-15);
        // CGA: a rotor and its f32 twin.
        let b5 = turn(&a5, &["e12", "e13", "e23"], &oblique);
        let r: cga::Rotor = cga::Exp::exp(cga::Bivector::from_multivector(&b5));
        let w = cga::EvenVersor::sqrt(r).to_multivector();
        root_of(&format!("CGA {what}"), r.to_multivector(), w, 1e-15);
        let r32 = cga_f32::Rotor::from_array(r.to_array().map(|x| x as f32));
        let w = cga_f32::EvenVersor::sqrt(r32).to_multivector();
        root_of(&format!("CGA f32 {what}"), r32.to_multivector(), w, 1e-6);
        // G(4,0): a simple rotation in the general `Even` type.
        let b4 = turn(&a4, &["e12", "e13", "e24", "e34"], &oblique);
        let v: sig400::Even = sig400::Exp::exp(sig400::Bivector::from_multivector(&b4));
        let w = sig400::EvenVersor::sqrt(v).to_multivector();
        root_of(&format!("G(4,0) {what}"), v.to_multivector(), w, 1e-14);
        // Screws in CGA and PGA, f64 and f32: the rotation and a shift along and across
        // its axis. (In f32 below `d = 1e-7` the motor's translation, rounded, no longer
        // fixes the axis: `eps |t| / d` exceeds its size.)
        // `exp` of a bivector of an algebra into a versor type, and its root to 1e-15.
        macro_rules! exp_and_root {
            ($m:ident, $b:ident, $t:ident, $biv:expr, $label:expr) => {{
                let v: $m::$t = $m::Exp::exp($m::$b::from_multivector(&$biv));
                let w = $m::EvenVersor::sqrt(v).to_multivector();
                root_of(&format!("{} {what}", $label), v.to_multivector(), w, 1e-15);
                v
            }};
        }
        let shift5 = on_blades(&a5, &["e1i", "e2i", "e3i"], &[2], &[0.7, -0.2, 0.4], 1.0);
        let m = exp_and_root!(cga, Bivector, Motor, &b5 + &shift5, "CGA motor");
        let ap = pga3d::algebra();
        let bp = &turn(&ap, &["e23", "e31", "e12"], &oblique)
            + &on_blades(&ap, &["e01", "e02", "e03"], &[2], &[0.7, -0.2, 0.4], 1.0);
        let mp = exp_and_root!(pga3d, Line, Motor, bp, "PGA motor");
        // A similarity (the screw and a dilation) and a Lorentz rotor (a rotation and a
        // boost along and across its axis): the other part is not null there.
        let dil = on_blades(&a5, &["eoi"], &[2], &[0.3], 1.0);
        let screw5 = &b5 + &shift5;
        let sm = exp_and_root!(
            cga,
            Bivector,
            ScaledMotor,
            &screw5 + &dil,
            "CGA scaled motor"
        );
        // The same in CGA's general `Even`, which may also hold two rotations.
        let ev = exp_and_root!(cga, Bivector, Even, &screw5 + &dil, "CGA even similarity");
        let a13 = sta::algebra();
        let bl = &turn(&a13, &["e23", "e31", "e12"], &oblique)
            + &on_blades(&a13, &["e01", "e02", "e03"], &[2], &[0.3, -0.1, 0.2], 1.0);
        let l = exp_and_root!(sta, Bivector, Rotor, bl, "STA rotor");
        if d >= 1e-7 {
            // The f32 twin of a versor roots to 1e-6.
            macro_rules! root_f32 {
                ($m:ident, $t:ident, $x:expr, $label:expr) => {{
                    let x = tests::$m::$t::from_array($x.to_array().map(|c| c as f32));
                    let w = tests::$m::EvenVersor::sqrt(x).to_multivector();
                    root_of(&format!("{} {what}", $label), x.to_multivector(), w, 1e-6);
                }};
            }
            root_f32!(cga_f32, ScaledMotor, sm, "CGA f32 scaled motor");
            root_f32!(cga_f32, Even, ev, "CGA f32 even similarity");
            root_f32!(sta_f32, Rotor, l, "STA f32 rotor");
            root_f32!(cga_f32, Motor, m, "CGA f32 motor");
            root_f32!(pga3d_f32, Motor, mp, "PGA f32 motor");
        }
        // Scaled: the same root (for a screw away from the full turn).
        for k in [1e-3, 2.5, 1e3] {
            let scaled = cga::Rotor::from_multivector(&r.to_multivector().scale(k));
            near(
                &format!("CGA {what}: sqrt({k} r) = sqrt(r)"),
                &cga::EvenVersor::sqrt(scaled).to_multivector(),
                &cga::EvenVersor::sqrt(r).to_multivector(),
                1e-15,
            );
            // A screw's root near the full turn is that of `m` to `eps |t| / d` only (the
            // axis, see above): compared away from it.
            if d == 1e-1 {
                let scaled = cga::Motor::from_multivector(&m.to_multivector().scale(k));
                near(
                    &format!("CGA {what}: sqrt({k} m) = sqrt(m)"),
                    &cga::EvenVersor::sqrt(scaled).to_multivector(),
                    &cga::EvenVersor::sqrt(m).to_multivector(),
                    1e-14,
                );
            }
        }
    }
}
