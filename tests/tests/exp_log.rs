//! The generated closed-form `exp`, `log`, `sqrt` and `normalize` (issue 26) of every algebra in
//! `algebras/` and of `--signature 2,0,1`, in f64 and f32, by property tests against the
//! generic multivector: `exp` against its scaling-and-squaring series, `log(exp(B)) = B` on the
//! principal branch, `exp(log(V)) = ±V`, `sqrt(V)^2 = V`, and `normalize(k V) = V` with a unit
//! result.

use ga_codegen::Multivector;
use proptest::prelude::*;

/// Relative tolerance: the one of the generated-vs-generic checks (1e-12 for f64, 1e-4 for f32).
fn tol(f32: bool) -> f64 {
    if f32 {
        1e-4
    } else {
        1e-12
    }
}

/// `|got - want| <= tol (1 + |want|)`, coefficientwise, and finite.
fn close(what: &str, got: &Multivector, want: &Multivector, tol: f64) -> Result<(), String> {
    let ok = got.coeffs().iter().all(|x| x.is_finite())
        && got.max_diff(want) <= tol * (1.0 + want.max_abs());
    if ok {
        Ok(())
    } else {
        Err(format!(
            "{what}: got {:?}\nwant {:?}\n(diff {:e})",
            got.coeffs(),
            want.coeffs(),
            got.max_diff(want)
        ))
    }
}

/// Equal up to sign.
fn close_up_to_sign(
    what: &str,
    got: &Multivector,
    want: &Multivector,
    tol: f64,
) -> Result<(), String> {
    close(what, got, want, tol).or_else(|_| close(what, &got.scale(-1.0), want, tol))
}

/// A multivector with coefficients `c[i] * scale` on the blades named `names` whose grade is in
/// `grades` (blade signs as named).
fn on_blades(
    alg: &std::sync::Arc<ga_codegen::Algebra>,
    names: &[&str],
    grades: &[u32],
    c: &[f64],
    scale: f64,
) -> Multivector {
    let mut m = Multivector::zero(alg);
    for (i, name) in names.iter().enumerate() {
        let (b, sign) = alg.parse_blade(name).expect("a blade of the algebra");
        if grades.contains(&alg.grade(b)) {
            m.set(b, m.get(b) + f64::from(sign) * c[i % c.len()] * scale);
        }
    }
    m
}

/// The property tests of one algebra module and its (bivector, versor) pairs.
macro_rules! suite {
    ($name:ident, $m:path, $f32:expr, [$(($b:ident, $v:ident)),* $(,)?]) => {
        mod $name {
            use super::*;
            use $m as m;
            use m::{EvenVersor, Exp, Log};

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(64))]

                #[test]
                fn exp_matches_series(c in prop::array::uniform16(-1.0f64..1.0), scale in 0.0f64..3.0) {
                    let alg = m::algebra();
                    $({
                        let b = m::$b::from_multivector(&on_blades(&alg, &m::$v::BLADES, &[2], &c, scale));
                        let v: m::$v = b.exp();
                        let want = b.to_multivector().exp();
                        close(concat!(stringify!($b), " -> ", stringify!($v)), &v.to_multivector(), &want, tol($f32))
                            .map_err(TestCaseError::fail)?;
                    })*
                }

                #[test]
                fn log_inverts_exp_on_the_principal_branch(c in prop::array::uniform16(-1.0f64..1.0), scale in 0.0f64..0.35) {
                    let alg = m::algebra();
                    $({
                        let b = m::$b::from_multivector(&on_blades(&alg, &m::$v::BLADES, &[2], &c, scale));
                        let v: m::$v = b.exp();
                        close(concat!("log exp ", stringify!($v)), &v.log().to_multivector(), &b.to_multivector(), tol($f32))
                            .map_err(TestCaseError::fail)?;
                    })*
                }

                #[test]
                fn exp_inverts_log_up_to_sign(c in prop::array::uniform16(-1.0f64..1.0), scale in 0.0f64..3.0) {
                    let alg = m::algebra();
                    $({
                        let b = m::$b::from_multivector(&on_blades(&alg, &m::$v::BLADES, &[2], &c, scale));
                        let v: m::$v = b.exp();
                        let back: m::$v = v.log().exp();
                        close_up_to_sign(concat!("exp log ", stringify!($v)), &back.to_multivector(), &v.to_multivector(), tol($f32))
                            .map_err(TestCaseError::fail)?;
                        // log(-v) = log(v): the same motion.
                        close(concat!("log -", stringify!($v)), &(-v).log().to_multivector(), &v.log().to_multivector(), tol($f32))
                            .map_err(TestCaseError::fail)?;
                    })*
                }

                #[test]
                fn sqrt_squares_back(c in prop::array::uniform16(-1.0f64..1.0), scale in 0.0f64..1.2) {
                    let alg = m::algebra();
                    $({
                        let b = m::$b::from_multivector(&on_blades(&alg, &m::$v::BLADES, &[2], &c, scale));
                        let v: m::$v = b.exp();
                        let r = v.sqrt().to_multivector();
                        close(concat!("sqrt ", stringify!($v)), &r.gp(&r), &v.to_multivector(), tol($f32))
                            .map_err(TestCaseError::fail)?;
                    })*
                }

                #[test]
                fn normalize_removes_scale_and_drift(
                    c in prop::array::uniform16(-1.0f64..1.0),
                    d in prop::array::uniform16(-1.0f64..1.0),
                    scale in 0.0f64..2.0,
                    k in -6.0f64..6.0,
                ) {
                    let alg = m::algebra();
                    let k = 10f64.powf(k);
                    $({
                        let b = m::$b::from_multivector(&on_blades(&alg, &m::$v::BLADES, &[2], &c, scale));
                        let v: m::$v = b.exp();
                        let vm = v.to_multivector();
                        let scaled = m::$v::from_multivector(&vm.scale(k));
                        // Normalising divides by `sqrt(v ~v)`, which cancels products of `v`'s
                        // coefficients: its relative error grows like `eps |v|^2`.
                        let size = 1.0 + vm.max_abs() * vm.max_abs();
                        close(concat!("normalize k ", stringify!($v)), &scaled.normalize().to_multivector(), &vm, tol($f32) * size)
                            .map_err(TestCaseError::fail)?;
                        // Drift off the versor manifold (every even blade of the type perturbed).
                        let drift = on_blades(&alg, &m::$v::BLADES, &[0, 2, 4], &d, 0.05);
                        let n = m::$v::from_multivector(&(&vm + &drift)).normalize().to_multivector();
                        // `n ~n = 1` cancels products of `n`'s coefficients: rounding `n` alone
                        // moves it by about `eps |n|^2` (boosts have coefficients of 10 and more).
                        let size = 1.0 + n.max_abs() * n.max_abs();
                        close(concat!("normalize drift ", stringify!($v)), &n.gp(&n.rev()), &Multivector::scalar(&alg, 1.0), tol($f32) * size)
                            .map_err(TestCaseError::fail)?;
                    })*
                }
            }
        }
    };
}

suite!(g3, tests::g3, false, [(Bivector, Rotor)]);
suite!(g3_f32, tests::g3_f32, true, [(Bivector, Rotor)]);
suite!(
    pga3d,
    tests::pga3d,
    false,
    [(Line, Motor), (Line, Rotor), (Line, Translator)]
);
suite!(
    pga3d_f32,
    tests::pga3d_f32,
    true,
    [(Line, Motor), (Line, Rotor), (Line, Translator)]
);
suite!(sta, tests::sta, false, [(Bivector, Rotor)]);
suite!(sta_f32, tests::sta_f32, true, [(Bivector, Rotor)]);
suite!(sig201, tests::sig201, false, [(Bivector, Even)]);
suite!(sig201_f32, tests::sig201_f32, true, [(Bivector, Even)]);
suite!(sig400, tests::sig400, false, [(Bivector, Even)]);
suite!(sig400_f32, tests::sig400_f32, true, [(Bivector, Even)]);
suite!(
    cga,
    tests::cga,
    false,
    [
        (Bivector, Rotor),
        (Bivector, Translator),
        (Bivector, Dilator),
        (Bivector, Motor),
        (Bivector, ScaledMotor),
        (Bivector, Even),
    ]
);
suite!(
    cga_f32,
    tests::cga_f32,
    true,
    [
        (Bivector, Rotor),
        (Bivector, Translator),
        (Bivector, Dilator),
        (Bivector, Motor),
        (Bivector, ScaledMotor),
        (Bivector, Even),
    ]
);

/// The branches that break elsewhere, on exact inputs.
mod edges {
    use super::*;
    use std::f64::consts::FRAC_PI_2;
    use tests::{cga, g3, pga3d, sta};

    fn near(what: &str, got: &Multivector, want: &Multivector, tol: f64) {
        if let Err(e) = close(what, got, want, tol) {
            panic!("{e}");
        }
    }

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

    #[test]
    fn zero_bivector_is_the_identity_both_ways() {
        use g3::{Exp as _, Log as _};
        let r: g3::Rotor = g3::Bivector::default().exp();
        assert_eq!(r, g3::Rotor::new(1.0, 0.0, 0.0, 0.0));
        assert_eq!(r.log(), g3::Bivector::default());
        use pga3d::{Exp as _, Log as _};
        let m: pga3d::Motor = pga3d::Line::default().exp();
        assert_eq!(m.s, 1.0);
        assert_eq!(m.to_array()[1..], [0.0; 7]);
        assert_eq!(m.log(), pga3d::Line::default());
        use sta::{Exp as _, Log as _};
        let l: sta::Rotor = sta::Bivector::default().exp();
        assert_eq!(l.s, 1.0);
        assert_eq!(l.log(), sta::Bivector::default());
        use cga::{Exp as _, Log as _};
        let e: cga::Even = cga::Bivector::default().exp();
        assert_eq!(e.s, 1.0);
        assert_eq!(e.log(), cga::Bivector::default());
    }

    #[test]
    fn pure_translations_are_one_plus_the_bivector() {
        use pga3d::{Exp as _, Log as _};
        let b = pga3d::Line::new(1.5, -2.0, 3.0, 0.0, 0.0, 0.0);
        let m: pga3d::Motor = b.exp();
        assert_eq!(
            m,
            pga3d::Motor::new(1.0, 0.0, 0.0, 0.0, 1.5, -2.0, 3.0, 0.0)
        );
        assert_eq!(m.log(), b);
        let t: pga3d::Translator = b.exp();
        assert_eq!(t.log(), b);
        use cga::{Exp as _, Log as _};
        let mut c = cga::Bivector::default();
        (c.e1i, c.e2i, c.e3i) = (0.25, -4.0, 1e-3);
        let m: cga::Motor = c.exp();
        assert_eq!(
            (m.s, m.e1i, m.e2i, m.e3i, m.e12, m.e123i),
            (1.0, 0.25, -4.0, 1e-3, 0.0, 0.0)
        );
        assert_eq!(m.log(), c);
        let e: cga::Even = c.exp();
        near(
            "cga even translation",
            &e.log().to_multivector(),
            &c.to_multivector(),
            1e-15,
        );
    }

    #[test]
    fn half_turns_at_and_near_pi() {
        use g3::{Exp as _, Log as _};
        // Exactly e12: a half-turn (rotation by pi), scalar part exactly zero.
        let r = g3::Rotor::new(0.0, 0.0, 0.0, 1.0);
        let want = g3::Bivector::new(0.0, 0.0, FRAC_PI_2);
        near(
            "log e12",
            &r.log().to_multivector(),
            &want.to_multivector(),
            1e-15,
        );
        // The rotation angle pi - 2e-9, and pi - 1e-15.
        for eps in [1e-9, 5e-16] {
            let b = g3::Bivector::new(0.6 * (FRAC_PI_2 - eps), 0.0, 0.8 * (FRAC_PI_2 - eps));
            let r: g3::Rotor = b.exp();
            near(
                "log near pi",
                &r.log().to_multivector(),
                &b.to_multivector(),
                1e-15,
            );
        }
        // Past the half turn: the log takes the short way round (the other sign).
        let b = g3::Bivector::new(0.0, 0.0, FRAC_PI_2 + 0.25);
        let r: g3::Rotor = b.exp();
        let short = g3::Bivector::new(0.0, 0.0, FRAC_PI_2 + 0.25 - std::f64::consts::PI);
        near(
            "short way",
            &r.log().to_multivector(),
            &short.to_multivector(),
            1e-15,
        );
        // A PGA screw motion with a half turn: rotation by pi about the z axis plus a
        // translation along it, and the same motor with a scalar part of exactly zero.
        use pga3d::{Exp as _, Log as _};
        let b = pga3d::Line::new(0.0, 0.0, 0.7, 0.0, 0.0, FRAC_PI_2);
        let m: pga3d::Motor = b.exp();
        near(
            "pga screw half turn",
            &m.log().to_multivector(),
            &b.to_multivector(),
            1e-15,
        );
        let mut exact = m;
        exact.s = 0.0;
        near(
            "pga exact half turn",
            &exact.log().to_multivector(),
            &b.to_multivector(),
            1e-15,
        );
        // An off-axis half turn: rotation by pi about a line through (1, 0, 0).
        let b = pga3d::Line::new(0.0, -FRAC_PI_2, 0.0, 0.0, 0.0, FRAC_PI_2);
        let m: pga3d::Motor = b.exp();
        near(
            "pga off-axis half turn",
            &m.log().to_multivector(),
            &b.to_multivector(),
            1e-15,
        );
    }

    #[test]
    fn tiny_angles() {
        use g3::{Exp as _, Log as _};
        let b = g3::Bivector::new(1e-300, -2e-300, 3e-300);
        let r: g3::Rotor = b.exp();
        assert_eq!(r, g3::Rotor::new(1.0, 1e-300, -2e-300, 3e-300));
        let back = r.log();
        for (x, y) in back.to_array().iter().zip(b.to_array()) {
            assert!((x - y).abs() <= 1e-15 * y.abs(), "{back:?}");
        }
        // A tiny rotation with a unit translation (PGA), and the same in CGA.
        use pga3d::{Exp as _, Log as _};
        let b = pga3d::Line::new(1.0, 0.5, -0.25, 1e-160, 0.0, 2e-160);
        let m: pga3d::Motor = b.exp();
        near(
            "pga tiny",
            &m.log().to_multivector(),
            &b.to_multivector(),
            1e-15,
        );
        let b = pga3d::Line::new(1.0, 0.5, -0.25, 1e-9, 0.0, 2e-9);
        let m: pga3d::Motor = b.exp();
        near(
            "pga small",
            &m.to_multivector(),
            &b.to_multivector().exp(),
            1e-15,
        );
        near(
            "pga small log",
            &m.log().to_multivector(),
            &b.to_multivector(),
            1e-15,
        );
        use cga::{Exp as _, Log as _};
        let mut c = cga::Bivector::default();
        (c.e12, c.e1i, c.e3i) = (1e-200, 1.0, -2.0);
        let m: cga::Motor = c.exp();
        near(
            "cga tiny",
            &m.log().to_multivector(),
            &c.to_multivector(),
            1e-15,
        );
    }

    /// A CGA `Even` whose grade-4 part is nearly null (a screw motion, perturbed: `<v>_4^2 =
    /// 3.7e-5` from terms of about 1.5): read as two rotations, its logarithm divided by
    /// `sqrt(3.7e-5)` and came back 2e-10 off in f64 (0.1 in f32); the split by the squares of
    /// the bivector part, which differ by far more, is exact to the precision. Found by
    /// `exp_inverts_log_up_to_sign`.
    #[test]
    fn nearly_null_four_vector_is_not_a_double_rotation() {
        use cga::{Exp as _, Log as _};
        let c = [
            0.0,
            0.5484113127473594,
            -0.6998074726588602,
            -0.10538637554802817,
            -0.3189749429318847,
            -0.8870899831501191,
            -0.4728025201250004,
            -0.7512948226609527,
            0.20229413691089634,
            0.3966802151832649,
            0.719364939533516,
        ];
        let alg = cga::algebra();
        let b = cga::Bivector::from_multivector(&on_blades(
            &alg,
            &cga::Even::BLADES,
            &[2],
            &c,
            1.3835437951184608,
        ));
        let v: cga::Even = b.exp();
        let r4 = [v.eo123, v.eo12i, v.eo13i, v.eo23i, v.e123i];
        let r4sq = 2.0 * r4[0] * r4[4] - r4[1] * r4[1] - r4[2] * r4[2] - r4[3] * r4[3];
        assert!(r4sq > 0.0 && r4sq < 1e-4, "the case under test: {r4sq}");
        let back: cga::Even = v.log().exp();
        if let Err(e) = close_up_to_sign(
            "nearly null grade 4",
            &back.to_multivector(),
            &v.to_multivector(),
            1e-14,
        ) {
            panic!("{e}");
        }
        use tests::cga_f32::{self, Exp as _};
        let vf = cga_f32::Even::from_array(v.to_array().map(|x| x as f32));
        let backf: cga_f32::Even = cga_f32::Log::log(vf).exp();
        if let Err(e) = close_up_to_sign(
            "nearly null grade 4, f32",
            &backf.to_multivector(),
            &vf.to_multivector(),
            1e-5,
        ) {
            panic!("{e}");
        }
    }

    #[test]
    fn huge_and_tiny_scales_normalise() {
        use pga3d::{EvenVersor as _, Exp as _};
        let b = pga3d::Line::new(0.3, -1.0, 2.0, 0.4, -0.2, 0.9);
        let m: pga3d::Motor = b.exp();
        for k in [1e200, 1e-200, 1e300, 1e-300] {
            let mk = pga3d::Motor::from_array(m.to_array().map(|x| x * k));
            near(
                "normalize scaled",
                &mk.normalize().to_multivector(),
                &m.to_multivector(),
                1e-15,
            );
        }
        // A huge translation stays finite and inverts.
        use pga3d::Log as _;
        let t = pga3d::Line::new(1e200, -3e199, 0.0, 0.0, 0.0, 0.0);
        let m: pga3d::Motor = t.exp();
        assert_eq!(m.log(), t);
        use cga::{EvenVersor as _, Exp as _};
        let mut c = cga::Bivector::default();
        (c.e12, c.e13, c.e1i, c.eoi) = (0.4, -0.3, 2.0, 0.2);
        let s: cga::ScaledMotor = c.exp();
        let sk = cga::ScaledMotor::from_array(s.to_array().map(|x| x * 1e250));
        near(
            "cga scaled normalize",
            &sk.normalize().to_multivector(),
            &s.to_multivector(),
            1e-14,
        );
    }

    /// Motors whose rotation part is tiny next to their translation (a turn of 0.28 rad with a
    /// shift of `1e6` to `1e11` units in f32, `1e60` and `1e100` in f64): `normalize` took
    /// `1 / sqrt(2 a N^2)` with `a ~ N ~ n0` (the squared rotation part over the largest
    /// coefficient squared), which underflowed to zero, so `inf` or `NaN`, once that ratio
    /// fell under about `3e-8` in f32 and `1e-54` in f64; `sqrt` of a motor within `1e-9` of
    /// a full turn went through it too. Below `1e-19` (f32) and `1e-154` (f64) `n0` itself
    /// underflows.
    #[test]
    fn motors_far_from_the_origin_normalise_finitely() {
        use tests::cga_f32;
        let unit = |w: Multivector, what: &str, tol: f64| {
            let one = Multivector::scalar(w.algebra(), 1.0);
            near(what, &w.gp(&w.rev()), &one, tol);
        };
        for (far, f32_too) in [
            (1e6, true),
            (1e7, true),
            (1e11, true),
            (1e60, false),
            (1e100, false),
        ] {
            let mut c = cga::Bivector::default();
            (c.e12, c.e13, c.e1i, c.e2i) = (0.1, -0.1, far, -0.5 * far);
            let m: cga::Motor = cga::Exp::exp(c);
            let drift = cga::Motor::from_array(m.to_array().map(|x| x * 1.001));
            let n = cga::EvenVersor::normalize(drift).to_multivector();
            near(
                &format!("f64 normalize, {far:e}"),
                &n,
                &m.to_multivector(),
                1e-13 * far,
            );
            unit(n, &format!("f64 normalize unit, {far:e}"), 1e-13 * far);
            if f32_too {
                let m32 = cga_f32::Motor::from_array(m.to_array().map(|x| x as f32));
                let drift = cga_f32::Motor::from_array(m32.to_array().map(|x| x * 1.001));
                let n = cga_f32::EvenVersor::normalize(drift);
                assert!(
                    n.to_array().iter().all(|x| x.is_finite()),
                    "f32 normalize, {far:e}: {:?}",
                    n.to_array()
                );
                near(
                    &format!("f32 normalize, {far:e}"),
                    &n.to_multivector(),
                    &m32.to_multivector(),
                    1e-6 * far,
                );
            }
        }
    }

    #[test]
    fn negative_scalar_versors_log_to_the_same_motion() {
        use sta::{Exp as _, Log as _};
        let b = sta::Bivector::new(0.3, -0.2, 0.5, 1.1, 0.4, -0.7);
        let r: sta::Rotor = b.exp();
        near(
            "log -R",
            &(-r).log().to_multivector(),
            &b.to_multivector(),
            1e-14,
        );
        near(
            "log R",
            &r.log().to_multivector(),
            &b.to_multivector(),
            1e-14,
        );
        use pga3d::{Exp as _, Log as _};
        let b = pga3d::Line::new(0.3, -1.0, 2.0, 0.4, -0.2, 0.9);
        let m: pga3d::Motor = b.exp();
        assert_eq!((-m).log(), m.log());
    }

    #[test]
    fn sign_conventions_of_each_algebra() {
        // G3: exp(-(t/2) e12) turns e1 towards e2 by t; the field e31 stores -e13.
        use g3::{Exp as _, Sandwich as _};
        let t = 0.7f64;
        let r: g3::Rotor = g3::Bivector::new(0.0, 0.0, -t / 2.0).exp();
        let v = r.sandwich(g3::Vector::new(1.0, 0.0, 0.0));
        near(
            "g3 rotation",
            &v.to_multivector(),
            &g3::Vector::new(t.cos(), t.sin(), 0.0).to_multivector(),
            1e-15,
        );
        let r31: g3::Rotor = g3::Bivector::new(0.0, -t / 2.0, 0.0).exp();
        let v = r31.sandwich(g3::Vector::new(0.0, 0.0, 1.0));
        near(
            "g3 e31",
            &v.to_multivector(),
            &g3::Vector::new(t.sin(), 0.0, t.cos()).to_multivector(),
            1e-15,
        );
        // STA: exp((p/2) e01) is a boost with rapidity p: e0 -> cosh(p) e0 - sinh(p) e1.
        use sta::{Exp as _, Sandwich as _};
        let p = 0.9f64;
        let r: sta::Rotor = sta::Bivector::new(p / 2.0, 0.0, 0.0, 0.0, 0.0, 0.0).exp();
        let v = r.sandwich(sta::Vector::new(1.0, 0.0, 0.0, 0.0));
        near(
            "sta boost",
            &v.to_multivector(),
            &sta::Vector::new(p.cosh(), -p.sinh(), 0.0, 0.0).to_multivector(),
            1e-15,
        );
    }
}

/// The README's PGA example (the generator section): klein-style motor interpolation through
/// `log` and `exp`, checked.
#[test]
fn readme_pga_motor_interpolation() {
    use tests::pga3d::{EvenVersor, Exp, Line, Log, Motor, Point, Sandwich};
    // Two poses: the identity and a screw motion (a quarter turn about the z axis with a lift
    // of 1 along it). A motor is exp of a line: e12 turns, e03 translates.
    let a: Motor = Line::default().exp();
    let b: Motor = Line::new(0.0, 0.0, -0.5, 0.0, 0.0, -std::f64::consts::FRAC_PI_4).exp();
    // The motion from a to b, as a line, then a * exp(t log(~a b)) for t in [0, 1].
    let d: Line = (a.rev() * b).log();
    let at = |t: f64| -> Motor {
        let step: Motor = (d * t).exp();
        a * step
    };
    let p = Point::new(1.0, 0.0, 0.0, 1.0); // x e032 + y e013 + z e021 + w e123
    let path: Vec<Point> = (0..=4)
        .map(|i| at(f64::from(i) / 4.0).sandwich(p))
        .collect();
    // Halfway is the square root of the whole motion.
    let half = at(0.5);
    let root = a * (a.rev() * b).sqrt();
    assert!(half
        .to_array()
        .iter()
        .zip(root.to_array())
        .all(|(x, y)| (x - y).abs() < 1e-15));
    // The end is b (up to sign: the same motion), and the point climbs a helix: radius 1,
    // height t.
    let end = at(1.0);
    let same = |m: &Motor, n: &Motor| {
        m.to_array()
            .iter()
            .zip(n.to_array())
            .all(|(x, y)| (x - y).abs() < 1e-15)
    };
    assert!(same(&end, &b) || same(&-end, &b));
    for (i, q) in path.iter().enumerate() {
        let (x, y, z) = (q.e032 / q.e123, q.e013 / q.e123, q.e021 / q.e123);
        assert!(
            ((x * x + y * y).sqrt() - 1.0).abs() < 1e-14,
            "radius at {i}: {q:?}"
        );
        assert!(
            (z.abs() - f64::from(i as u32) / 4.0).abs() < 1e-14,
            "height at {i}: {q:?}"
        );
    }
    let _ = EvenVersor::normalize(b);
}
