//! The generated exp/log of double rotations (two rotations in orthogonal planes: every rotor
//! of G(4), CGA's `Even`), where the split into the two planes is ill-conditioned: nearly equal
//! angles (isoclinic rotations), the double half turn (`v` a unit 4-blade, whose logarithm is
//! not unique) and the approach to it. Each is checked against the generic multivector's series.

use ga_codegen::Multivector;
use proptest::prelude::*;
use std::f64::consts::FRAC_PI_2;

/// The G(4) bivector with coefficients `c` on `e12, e13, e14, e23, e24, e34`.
fn bivector(c: &[f64; 6]) -> Multivector {
    let alg = tests::sig400::algebra();
    let mut m = Multivector::zero(&alg);
    for (i, name) in ["e12", "e13", "e14", "e23", "e24", "e34"]
        .iter()
        .enumerate()
    {
        let (bl, sign) = alg.parse_blade(name).expect("a G(4) blade");
        m.set(bl, f64::from(sign) * c[i]);
    }
    m
}

/// `theta1 e12 + theta2 e34` turned into general position by the rotor `exp(c)` (so that both
/// planes mix every blade), as a generic multivector of G(4).
fn double_rotation(theta1: f64, theta2: f64, c: &[f64; 6]) -> Multivector {
    let r = bivector(c).exp();
    let b0 = bivector(&[theta1, 0.0, 0.0, 0.0, 0.0, theta2]);
    r.gp(&b0).gp(&r.rev())
}

/// `max |got - want| <= tol (1 + max |want|)`, and finite.
fn close(what: &str, got: &Multivector, want: &Multivector, tol: f64) -> Result<(), TestCaseError> {
    let ok = got.coeffs().iter().all(|x| x.is_finite())
        && got.max_diff(want) <= tol * (1.0 + want.max_abs());
    prop_assert!(
        ok,
        "{what}: got {:?}\nwant {:?}\n(diff {:e})",
        got.coeffs(),
        want.coeffs(),
        got.max_diff(want)
    );
    Ok(())
}

fn close_up_to_sign(
    what: &str,
    got: &Multivector,
    want: &Multivector,
    tol: f64,
) -> Result<(), TestCaseError> {
    close(what, got, want, tol).or_else(|_| close(what, &got.scale(-1.0), want, tol))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Angles `theta` and `theta (1 - 10^-k)`, k up to 14: exp against the series and
    /// log(exp(B)) = B at the tolerance of every other generated-vs-generic check (1e-12); the
    /// split by the squares' difference lost up to 1e-5 here.
    #[test]
    fn nearly_isoclinic_double_rotations(
        theta in 0.01f64..1.5,
        k in 0.0f64..14.0,
        c in prop::array::uniform6(-1.0f64..1.0),
    ) {
        use tests::sig400::{Bivector, Even, Exp, Log};
        let bm = double_rotation(theta, theta * (1.0 - 10f64.powf(-k)), &c);
        let b = Bivector::from_multivector(&bm);
        let v: Even = b.exp();
        close("exp", &v.to_multivector(), &bm.exp(), 1e-12)?;
        close("log exp", &v.log().to_multivector(), &bm, 1e-12)?;
        // f32: the same at its precision.
        use tests::sig400_f32 as m32;
        use m32::{Exp as _, Log as _};
        let b32 = m32::Bivector::from_multivector(&bm);
        let v32: m32::Even = b32.exp();
        close("exp f32", &v32.to_multivector(), &bm.exp(), 1e-5)?;
        close("log exp f32", &v32.log().to_multivector(), &bm, 1e-4)?;
    }

    /// Up to the double half turn (both angles pi/2 - 10^-k): exp(log(v)) = ±v. The logarithm
    /// is ill-conditioned there (like a single half turn's), and within 1e-8 of the half turn
    /// one of its exact logarithms is returned, so the bound is 1e-8.
    #[test]
    fn towards_the_double_half_turn(
        ka in 1.0f64..16.0,
        kb in 1.0f64..16.0,
        c in prop::array::uniform6(-1.0f64..1.0),
    ) {
        use tests::sig400::{Bivector, Even, Exp, Log};
        let bm = double_rotation(FRAC_PI_2 - 10f64.powf(-ka), FRAC_PI_2 - 10f64.powf(-kb), &c);
        let v = Even::from_multivector(&bm.exp());
        let back: Even = v.log().exp();
        close_up_to_sign("exp log", &back.to_multivector(), &v.to_multivector(), 1e-8)?;
        // And the generated exp there agrees with the series.
        let e: Even = Bivector::from_multivector(&bm).exp();
        close("exp", &e.to_multivector(), &v.to_multivector(), 1e-12)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Square roots of double rotations in general position whose angles sum to within
    /// `10^-k` of a half turn (k up to 16, either side), where `normalize(1 + v)` cancelled
    /// (1.6e-4 off at `10^-6`, not finite on the cut): the root squares back to `v` and is a
    /// unit at the tolerance of every generated-vs-generic check (f64 1e-12; f32 1e-5). Both
    /// angles stay 0.2 or more from 0 and a half turn: near `v = -1` (a full turn, which has no
    /// unique half) the root still loses more (f32: 2e-5 at 0.06 from it), not addressed here.
    #[test]
    fn sqrt_near_the_half_turn_cut(
        theta in 0.3f64..2.84,
        k in 1.0f64..16.0,
        side in prop::bool::ANY,
        c in prop::array::uniform6(-1.0f64..1.0),
    ) {
        use tests::sig400::{Even, EvenVersor};
        let d = if side { 10f64.powf(-k) } else { -(10f64.powf(-k)) };
        let bm = double_rotation(theta, std::f64::consts::PI - theta - d, &c);
        let v = Even::from_multivector(&bm.exp());
        let one = Multivector::scalar(&tests::sig400::algebra(), 1.0);
        let w = v.sqrt().to_multivector();
        close("sqrt^2", &w.gp(&w), &v.to_multivector(), 1e-12)?;
        close("unit", &w.gp(&w.rev()), &one, 1e-12)?;
        use tests::sig400_f32 as m32;
        use m32::EvenVersor as _;
        let v32 = m32::Even::from_array(v.to_array().map(|x| x as f32));
        let w = v32.sqrt().to_multivector();
        close("sqrt^2 f32", &w.gp(&w), &v32.to_multivector(), 1e-5)?;
        close("unit f32", &w.gp(&w.rev()), &one, 1e-5)?;
    }
}

/// An f32 root on the cut to f32's precision (angles 2.0747 and pi - 2.0747 + 1e-10, planes in
/// general position), found by `sqrt_near_the_half_turn_cut`: the rounding that stood for the
/// small imaginary part kept little of itself on its half, and its direction, rescaled, gave
/// a root whose square was 1.37 off; it now takes a basis bivector's part of the half.
#[test]
fn sqrt_f32_on_the_cut_to_its_precision() {
    use tests::sig400_f32::{Even, EvenVersor};
    let c = [
        -0.38550345842063294,
        -0.15230866099951892,
        -0.5175253574927167,
        0.0,
        0.0,
        0.6260850408402142,
    ];
    let theta = 2.074703617665705;
    let bm = double_rotation(
        theta,
        std::f64::consts::PI - theta + 10f64.powf(-9.989113475538314),
        &c,
    );
    let v = Even::from_multivector(&bm.exp());
    let w = v.sqrt().to_multivector();
    let ok = close("sqrt^2 f32", &w.gp(&w), &v.to_multivector(), 1e-5);
    assert!(ok.is_ok(), "{ok:?}");
}

/// The exact double half turn, `v = ±e1234` and turned copies: a finite logarithm whose
/// exponential is `±v` (there are infinitely many; any is correct).
#[test]
fn exact_double_half_turn() {
    use tests::sig400::{Even, Exp, Log};
    let alg = tests::sig400::algebra();
    let (i4, sign) = alg.parse_blade("e1234").expect("pseudoscalar");
    for s in [1.0, -1.0] {
        for c in [[0.0; 6], [0.3, -0.2, 0.9, 0.1, -0.7, 0.4]] {
            let r = bivector(&c).exp();
            let mut p = Multivector::zero(&alg);
            p.set(i4, f64::from(sign) * s);
            let v = Even::from_multivector(&r.gp(&p).gp(&r.rev()));
            let l = v.log();
            assert!(l.to_array().iter().all(|x| x.is_finite()), "{l:?}");
            // Up to sign (`v` and `-v` are the same rotation; the sign of the rounding in the
            // scalar part picks the hemisphere).
            let back = l.exp().to_multivector();
            let vm = v.to_multivector();
            assert!(
                back.max_diff(&vm).min(back.max_diff(&vm.scale(-1.0))) < 1e-14,
                "{v:?}: exp(log) = {back:?}"
            );
            let _: Even = l.exp();
        }
    }
    // In CGA: e1 e2 e3 e4 with e4 = ei/2 - eo (squares to 1) is eo123 + e123i/2.
    use tests::cga::{Exp as _, Log as _};
    let mut v = tests::cga::Even::default();
    (v.eo123, v.e123i) = (1.0, 0.5);
    let back: tests::cga::Even = v.log().exp();
    assert!(
        back.to_multivector().max_diff(&v.to_multivector()) < 1e-14,
        "cga: exp(log) = {back:?}"
    );
}

/// Isoclinic and nearly isoclinic in CGA's `Even` (e12 and e3 ^ e4 with e4 = ei/2 - eo, which
/// squares to 1: two rotations by about the same angle), against the series.
#[test]
fn nearly_isoclinic_in_cga() {
    use tests::cga::{Bivector, Even, Exp, Log};
    for (t1, t2) in [
        (1.0, 1.0 + 1e-7),
        (0.5, 0.5 + 1e-4),
        (1.2, 1.2 - 1e-11),
        (0.3, 0.3),
        (1.2, 1.2),
        (1e-8, 1e-8),
    ] {
        let mut b = Bivector::default();
        (b.e12, b.e3i, b.eo3) = (t1, t2 / 2.0, t2);
        let v: Even = b.exp();
        let want = b.to_multivector().exp();
        let d = v.to_multivector().max_diff(&want);
        assert!(d < 1e-14, "exp ({t1}, {t2}): {d:e}");
        let d = v.log().to_multivector().max_diff(&b.to_multivector());
        assert!(d < 1e-14, "log ({t1}, {t2}): {d:e}");
    }
}

/// `exp(pi/2 (E1 + E2))` for the two rotation planes `planes` (name, coefficient pairs: a
/// double half turn, `v` a unit 4-blade) turned by `exp(c)` for a bivector `c` of the first
/// five basis vectors, as a generic multivector of `alg`.
fn turned_double_half_turn(
    alg: &std::sync::Arc<ga_codegen::Algebra>,
    planes: &[(&str, f64)],
    c: &[f64; 10],
) -> Multivector {
    let names = alg.metric().names();
    let mut b = Multivector::zero(alg);
    let mut h = Multivector::zero(alg);
    let pairs = (0..5).flat_map(|i| (i + 1..5).map(move |j| (i, j)));
    for ((i, j), x) in pairs.zip(c) {
        let (bl, sign) = alg
            .parse_blade(&format!("{}{}", names[i], &names[j][1..]))
            .expect("a bivector");
        b.set(bl, f64::from(sign) * x);
    }
    for (name, x) in planes {
        let (bl, sign) = alg.parse_blade(name).expect("a bivector");
        h.set(bl, f64::from(sign) * x * FRAC_PI_2);
    }
    let r = b.exp();
    r.gp(&h.exp()).gp(&r.rev())
}

/// `exp(log v) = ±v` within `tol (1 + |v|)^2` (the conditioning of a boosted versor).
fn back_up_to_sign(
    what: &str,
    v: &Multivector,
    back: &Multivector,
    tol: f64,
) -> Result<(), TestCaseError> {
    let d = back.max_diff(v).min(back.max_diff(&v.scale(-1.0)));
    prop_assert!(
        d <= tol * (1.0 + v.max_abs()).powi(2),
        "{what}: v {:?}\nexp(log v) {:?}\n(diff {d:e})",
        v.coeffs(),
        back.coeffs()
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The exact double half turn turned by a general versor, so that its 4-space is not a
    /// basis one: in CGA, `e12` and `e3 ^ (ei/2 - eo)` turned by boosts, translations and
    /// dilations too (coefficients up to 25 here); in G(3,2), `e12` and `e45`. The test that
    /// chose the double-rotation branch compared `<v_4 v_4>_0` with the sum of the squared
    /// coefficients, which a boost makes large while the square stays 1: these went to the
    /// single-rotation split, and exp(log v) was off by the size of `v` (most cases with
    /// coefficients past 0.5).
    #[test]
    fn turned_double_half_turns(c in prop::array::uniform10(-1.0f64..1.0)) {
        let cga = tests::cga::algebra();
        let v = turned_double_half_turn(&cga, &[("e12", 1.0), ("e3i", 0.5), ("eo3", 1.0)], &c);
        {
            use tests::cga::{Even, Exp, Log};
            let back: Even = Even::from_multivector(&v).log().exp();
            back_up_to_sign("cga", &v, &back.to_multivector(), 1e-11)?;
        }
        {
            use tests::cga_f32::{Even, Exp, Log};
            let back: Even = Even::from_multivector(&v).log().exp();
            back_up_to_sign("cga f32", &v, &back.to_multivector(), 1e-4)?;
        }
        let g32 = tests::sig320::algebra();
        let v = turned_double_half_turn(&g32, &[("e12", 1.0), ("e45", 1.0)], &c);
        use tests::sig320::{Even, Exp, Log};
        let back: Even = Even::from_multivector(&v).log().exp();
        back_up_to_sign("G(3,2)", &v, &back.to_multivector(), 1e-11)?;
    }
}
