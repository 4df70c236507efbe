//! The generated closed-form `exp` on spans with two or more directions of each sign (G(2,2)
//! and G(3,2) from `--signature`), where the squares of a bivector's two commuting parts can be
//! a complex-conjugate pair: against the generic multivector's scaling-and-squaring series, on
//! random bivectors (a share of them with complex squares, counted), on each branch of
//! `exp_log_coefficients_of` (the series in `l`, `z = sqrt(l)`, the equal-squares limit) and
//! across the boundary between real and complex squares, in f64 and f32; and `exp(B) ~exp(B) =
//! 1`; `log(exp(B)) = B` on the principal branch and `exp(log(V)) = ±V` beyond it, for the
//! complex pair, two boosts, two rotations and a rotation with a boost; the square root on
//! split-complex halves. (`exp_log/main.rs` runs its whole property suite on both algebras too.)

use ga_codegen::Multivector;
use proptest::prelude::*;
use std::sync::Arc;
use tests::{close, sig220, sig220_f32, sig320};

/// The roots' discriminant `s^2 - q` of `B` (`s = <B B>_0`, `q = W W`, `W = <B B>_4`), and
/// `|l|` (the larger root's magnitude): negative for a complex pair.
fn discriminant(b: &Multivector) -> (f64, f64) {
    let bb = b.gp(b);
    let s = bb.grade(0).get(0);
    let w = bb.grade(4);
    let q = w.gp(&w).get(0);
    (s * s - q, q.abs().sqrt().max(s.abs()))
}

/// A bivector of `alg` with coefficients `c` (cycled) on its bivector blades, times `scale`.
fn bivector(alg: &Arc<ga_codegen::Algebra>, c: &[f64], scale: f64) -> Multivector {
    let mut m = Multivector::zero(alg);
    let blades: Vec<usize> = (0..1usize << alg.dim())
        .filter(|&b| b.count_ones() == 2)
        .collect();
    for (i, b) in blades.into_iter().enumerate() {
        m.set(b as _, c[i % c.len()] * scale);
    }
    m
}

/// The generated `exp` of `b` (f64 and f32 G(2,2), f64 G(3,2)) against the series, and a unit.
fn exp_checks(b: &Multivector, tol64: f64, tol32: f64) -> Result<(), String> {
    let want = b.exp();
    let one = Multivector::scalar(b.algebra(), 1.0);
    let (got, got32) = if b.algebra().dim() == 4 {
        use sig220::Exp as _;
        use sig220_f32::Exp as _;
        let e: sig220::Even = sig220::Bivector::from_multivector(b).exp();
        let b32 = sig220_f32::Bivector::from_multivector(b);
        let e32: sig220_f32::Even = b32.exp();
        (e.to_multivector(), Some(e32.to_multivector()))
    } else {
        use sig320::Exp as _;
        let e: sig320::Even = sig320::Bivector::from_multivector(b).exp();
        (e.to_multivector(), None)
    };
    close("exp", &got, &want, tol64)?;
    // A unit: the size of the coefficients multiplies the rounding of `e ~e`.
    let size = 1.0 + want.max_abs() * want.max_abs();
    close("exp ~exp", &got.gp(&got.rev()), &one, tol64 * size)?;
    if let Some(g32) = got32 {
        close("exp f32", &g32, &want, tol32)?;
    }
    Ok(())
}

/// `log` of the generated `exp(b)`: back to `b` when `principal`, else `exp(log(v)) = ±v`;
/// and `log(-v) = log(v)`. G(2,2) in f64 and f32, G(3,2) in f64.
fn log_checks(b: &Multivector, principal: bool, tol64: f64, tol32: f64) -> Result<(), String> {
    let bm = b.clone();
    // (v, log v, log -v, exp log v) as multivectors, from the generated functions.
    let (v, lv, lmv, back, f32s) = if b.algebra().dim() == 4 {
        use sig220::{Exp as _, Log as _};
        use sig220_f32::{Exp as _, Log as _};
        let v: sig220::Even = sig220::Bivector::from_multivector(b).exp();
        let l = v.log();
        let back: sig220::Even = l.exp();
        let v32: sig220_f32::Even = sig220_f32::Bivector::from_multivector(b).exp();
        let l32 = v32.log();
        let back32: sig220_f32::Even = l32.exp();
        (
            v.to_multivector(),
            l.to_multivector(),
            (-v).log().to_multivector(),
            back.to_multivector(),
            Some((
                v32.to_multivector(),
                l32.to_multivector(),
                back32.to_multivector(),
            )),
        )
    } else {
        use sig320::{Exp as _, Log as _};
        let v: sig320::Even = sig320::Bivector::from_multivector(b).exp();
        let l = v.log();
        let back: sig320::Even = l.exp();
        (
            v.to_multivector(),
            l.to_multivector(),
            (-v).log().to_multivector(),
            back.to_multivector(),
            None,
        )
    };
    // The log's error is the rounding of `v` over the conditioning of the map back: it grows
    // with the size of `v`'s coefficients, and near a half turn of the sum of the two angles
    // with `1 / sin S` (where the logarithm stops being unique).
    let size = (1.0 + v.max_abs()) * tests::half_turn_conditioning(&v);
    if principal {
        close("log exp", &lv, &bm, tol64 * size)?;
    }
    let sign = |got: &Multivector, want: &Multivector, tol: f64| {
        close("exp log", got, want, tol).or_else(|_| close("exp log", &got.scale(-1.0), want, tol))
    };
    sign(&back, &v, tol64 * size)?;
    close("log -v", &lmv, &lv, tol64 * size)?;
    if let Some((v32, l32, back32)) = f32s {
        if principal {
            close("log exp f32", &l32, &bm, tol32 * size)?;
        }
        sign(&back32, &v32, tol32 * size)?;
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn log_inverts_exp_in_g22(c in prop::array::uniform6(-1.0f64..1.0), scale in 0.0f64..0.35) {
        let b = bivector(&sig220::algebra(), &c, scale);
        log_checks(&b, true, 1e-12, 1e-4).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn exp_inverts_log_in_g22(c in prop::array::uniform6(-1.0f64..1.0), scale in 0.0f64..3.0) {
        let b = bivector(&sig220::algebra(), &c, scale);
        log_checks(&b, false, 1e-12, 1e-4).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn log_inverts_exp_in_g32(c in prop::array::uniform10(-1.0f64..1.0), scale in 0.0f64..0.25) {
        let b = bivector(&sig320::algebra(), &c, scale);
        log_checks(&b, true, 1e-12, 1e-4).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn exp_inverts_log_in_g32(c in prop::array::uniform10(-1.0f64..1.0), scale in 0.0f64..2.0) {
        let b = bivector(&sig320::algebra(), &c, scale);
        log_checks(&b, false, 1e-12, 1e-4).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn exp_matches_series_in_g22(c in prop::array::uniform6(-1.0f64..1.0), scale in 0.0f64..3.0) {
        let b = bivector(&sig220::algebra(), &c, scale);
        exp_checks(&b, 1e-12, 1e-4).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn exp_matches_series_in_g32(c in prop::array::uniform10(-1.0f64..1.0), scale in 0.0f64..2.0) {
        let b = bivector(&sig320::algebra(), &c, scale);
        exp_checks(&b, 1e-12, 1e-4).map_err(TestCaseError::fail)?;
    }
}

/// The random bivectors above are not all real-squared: about a third of them in G(2,2) (and
/// of G(3,2)'s) have complex squares, so the property tests cover that branch.
#[test]
fn a_share_of_random_bivectors_have_complex_squares() {
    // Uniform in [-1, 1), as the property tests draw them (a fixed linear congruential
    // sequence).
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut uniform = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    };
    for (alg, n) in [(sig220::algebra(), 6), (sig320::algebra(), 10)] {
        let mut complex = 0;
        for _ in 0..400 {
            let c: Vec<f64> = (0..n).map(|_| uniform()).collect();
            if discriminant(&bivector(&alg, &c, 1.0)).0 < 0.0 {
                complex += 1;
            }
        }
        assert!(
            complex > 60,
            "{complex} of 400 complex in G({},..)",
            alg.dim()
        );
    }
}

/// `x e12 + y e34 + z (e13 + e24)` in G(2,2) (`e1, e2` positive, `e3, e4` negative): two
/// rotations at `z = 0`, a complex pair once `z` passes a threshold.
fn family(x: f64, y: f64, z: f64) -> Multivector {
    let alg = sig220::algebra();
    let mut m = Multivector::zero(&alg);
    m.set(0b0011, x);
    m.set(0b1100, y);
    m.set(0b0101, z);
    m.set(0b1010, z);
    m
}

/// Each branch of the complex coefficients: small and large `|l|` (the series in `l`, and
/// `z = sqrt(l)` with `Re l` of either sign), and the complex pair within the cube root of the
/// precision of equal squares (the limit), down to `b = 0`.
#[test]
fn every_branch_of_the_complex_coefficients() {
    let mut seen = [0; 3];
    for scale in [1e-6, 1e-3, 0.1, 0.5, 0.99, 1.5, 3.0, 6.0] {
        for (x, y, z) in [
            (0.3, 0.2, 1.0),
            (1.0, -1.0, 1.0),
            (0.1, 0.9, 0.7),
            (0.5, 0.0, 1.0),
        ] {
            let b = family(x * scale, y * scale, z * scale);
            let (d, m) = discriminant(&b);
            assert!(d < 0.0, "{x} {y} {z} at {scale}: not complex ({d})");
            seen[if m <= 1.0 { 0 } else { 1 }] += 1;
            exp_checks(&b, 1e-12, 1e-4).unwrap_or_else(|e| panic!("{x} {y} {z} at {scale}: {e}"));
        }
    }
    // Near equal squares: `z` just past the threshold where the pair turns complex, found by
    // bisection on the discriminant of `e12 + 0.5 e34 + z (e13 + e24)`.
    let (mut lo, mut hi) = (0.0, 2.0);
    assert!(discriminant(&family(1.0, 0.5, lo)).0 > 0.0);
    assert!(discriminant(&family(1.0, 0.5, hi)).0 < 0.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if discriminant(&family(1.0, 0.5, mid)).0 < 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    for dz in [0.0, 1e-15, 1e-12, 1e-9, 1e-6, 1e-4, 1e-2] {
        for z in [hi + dz, lo - dz] {
            let b = family(1.0, 0.5, z);
            let (d, m) = discriminant(&b);
            if d < 0.0 && (-d).sqrt() <= 6e-6 * m {
                seen[2] += 1;
            }
            exp_checks(&b, 1e-12, 1e-4).unwrap_or_else(|e| panic!("z = {z}: {e}"));
        }
    }
    assert!(seen.iter().all(|&n| n > 0), "branches seen: {seen:?}");
}

/// Along a path from real to complex squares and back, `exp` agrees with the series at every
/// step (no jump where the discriminant changes sign).
#[test]
fn exp_is_continuous_across_the_real_complex_boundary() {
    for i in 0..=400 {
        let z = 0.5 + f64::from(i) / 400.0;
        let b = family(1.0, 0.5, z);
        exp_checks(&b, 1e-12, 1e-4).unwrap_or_else(|e| panic!("z = {z}: {e}"));
    }
}

/// The logarithm of each kind of pair G(2,2) holds, on exact inputs: a complex pair (near the
/// identity, at moderate angles, near the real boundary on both sides), two boosts (equal and
/// unequal), two rotations, one rotation, one boost and a null bivector. (G(2,2) has no
/// rotation with a boost: the plane orthogonal to a rotation's is a rotation's too; G(3,2)'s
/// random bivectors have them.)
#[test]
fn log_of_each_kind_of_pair() {
    let alg = sig220::algebra();
    let blade = |x: [f64; 6]| bivector(&alg, &x, 1.0);
    // Blades in order e12, e13, e14, e23, e24, e34 (e1, e2 positive; e3, e4 negative).
    let cases: Vec<(&str, Multivector)> = vec![
        ("complex, tiny", family(1e-9, 2e-9, 3e-9)),
        ("complex", family(0.3, 0.2, 0.5)),
        ("complex, larger", family(0.9, -0.4, 0.8)),
        ("two boosts", blade([0.0, 0.4, 0.0, 0.0, 0.7, 0.0])),
        ("two equal boosts", blade([0.0, 0.6, 0.0, 0.0, 0.6, 0.0])),
        ("two rotations", blade([0.7, 0.0, 0.0, 0.0, 0.0, 0.3])),
        ("one rotation", blade([0.5, 0.0, 0.0, 0.0, 0.0, 0.0])),
        ("one boost", blade([0.0, 0.5, 0.0, 0.0, 0.0, 0.0])),
        // `(e1 + e3) ^ e2 = e12 - e23`, on a null direction: squares to zero.
        ("null", blade([0.5, 0.0, 0.0, -0.5, 0.0, 0.0])),
    ];
    let (lo, hi) = {
        let (mut lo, mut hi) = (0.0, 2.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if discriminant(&family(0.4, 0.2, mid)).0 < 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        (lo, hi)
    };
    let mut all = cases;
    for dz in [0.0, 1e-12, 1e-8, 1e-4] {
        all.push(("boundary, complex side", family(0.4, 0.2, hi + dz)));
        all.push(("boundary, real side", family(0.4, 0.2, lo - dz)));
    }
    for (what, b) in all {
        log_checks(&b, true, 1e-12, 1e-4).unwrap_or_else(|e| panic!("{what}: {e}"));
    }
}

/// Every closed form is emitted where the squares can be complex, and `--exp-log` accepts
/// the spec.
#[test]
fn every_closed_form_is_emitted_there() {
    let spec = ga_codegen::Spec::for_signature(2, 2, 0).expect("spec");
    let opts = ga_codegen::EmitOptions {
        require_exp_log: true,
        ..Default::default()
    };
    let generated = ga_codegen::generate(&spec, &opts).expect("generates");
    let code = generated.code().expect("formats");
    for item in [
        "impl Exp<Even> for Bivector",
        "impl Log for Even",
        "impl EvenVersor for Even",
    ] {
        assert!(code.contains(item), "{item}");
    }
    assert!(ga_codegen::generator::emit::refusals(&spec).is_empty());
}
