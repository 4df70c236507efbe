//! The closed-form exponential of similarity generators over lanes: [`Bivector::exp_similarity`]
//! applied to points, for `W::LANES` generators and points at once (log blending moves every
//! vertex by the exponential of its own blended generator).
//!
//! The scalar form needs `sin_cos`, a division by the angle and a guarded quotient for the
//! translation. Over lanes the three functions of the half-angle `phi` that it uses are
//! power series in `phi^2` (Horner, no division, no special case at `phi = 0`):
//!
//! * `sinc(phi) = sin(phi) / phi`,
//! * `cos(phi)`,
//! * `k(phi) = (1 - sinc(phi) cos(phi)) / phi^2 = (1 - sinc(2 phi)) / phi^2`, the
//!   coefficient of `(u . v) u` in the translation, which the scalar form computes with a
//!   cancellation for small angles.
//!
//! Each series is summed to rounding for `phi <= 2` (principal logarithms and their convex
//! blends have `phi <= pi / 2`); a lane with a larger half-angle (a blend with weights outside
//! `[0, 1]` can make one) makes [`ExpLanes::exp_transform`] decline, and callers use the
//! scalar form for those. Each batch sums only the terms its largest half-angle needs (cuts
//! for `phi <= 1/4`, `1/2` and `1`, [`CUTS`]): blends mostly turn by far less than the range
//! allows, and the shorter sums made log blending 10-20% faster on the skinning rigs.
//! Generators with a dilation part add, per lane, the one `exp` of the scalar form and its
//! guarded quotients.

use crate::ext64::exp_log::exp_pair;
use crate::f64::wide::{Bivector, Lane};

/// The largest half-angle the series serve: principal logarithms have `phi <= pi / 2`, and
/// so have their blends with weights in `[0, 1]`; past 2 the alternating sums would lose
/// digits to their largest terms.
const MAX_PHI: f64 = 2.0;

/// `c[n]`, `n = 0..N`, with `f(phi) = sum c[n] phi^(2n)`: `c[0] = first` and
/// `c[n] = c[n-1] m / ((2n + a)(2n + b))`. Each series below is cut where its next term is
/// under `1e-18` at `phi = 2`.
const fn series<const N: usize>(first: f64, m: f64, a: i64, b: i64) -> [f64; N] {
    let mut c = [0.0; N];
    c[0] = first;
    let mut n = 1;
    while n < N {
        let k = 2 * n as i64;
        c[n] = c[n - 1] * m / ((k + a) as f64 * (k + b) as f64);
        n += 1;
    }
    c
}

/// `sinc`: `(-1)^n / (2n+1)!`.
const SINC: [f64; 13] = series(1.0, -1.0, 0, 1);
/// `cos`: `(-1)^n / (2n)!`.
const COS: [f64; 14] = series(1.0, -1.0, -1, 0);
/// `k`: `(-1)^n 4^(n+1) / (2n+3)!`.
const K: [f64; 16] = series(4.0 / 6.0, -4.0, 2, 3);

/// `sum c[n] x^n` by Horner's rule (the full series: what the tests compare the cuts with).
#[cfg(test)]
#[inline(always)]
fn horner<W: Lane<Scalar = f64>, const N: usize>(c: &[f64; N], x: W) -> W {
    horner_first::<W, N, N, false>(c, x)
}

/// `sum c[n] x^n` over the first `M` coefficients of `c` (each step fused when `FMA`).
#[inline(always)]
fn horner_first<W: Lane<Scalar = f64>, const M: usize, const N: usize, const FMA: bool>(
    c: &[f64; N],
    x: W,
) -> W {
    let mut acc = W::splat(c[M - 1]);
    let mut n = M - 1;
    while n > 0 {
        n -= 1;
        acc = acc.mul_add_if::<FMA>(x, W::splat(c[n]));
    }
    acc
}

/// The exponential of similarity generators applied to points, over lanes.
pub trait ExpLanes<W> {
    /// Lane by lane `self.lane(i).exp_similarity().transform_point(p_i)` for generators with
    /// a half rotation angle of at most 2 (principal logarithms and their convex blends have
    /// at most `pi / 2`); `None` when some lane is outside that range (nothing is computed).
    /// Rigid generators (`eoi = 0` in every lane) take the series alone; a dilation part adds
    /// one `exp` per lane and the scalar form's guarded quotients, lane by lane. The result
    /// agrees with the scalar closed form to rounding.
    fn exp_transform(self, p: [W; 3]) -> Option<[W; 3]>;

    /// [`ExpLanes::exp_transform`] with its series and its final sums written as fused
    /// multiply-adds when `FMA` (call it with `true` only from code compiled with the `fma`
    /// target feature: elsewhere each is a call into the C library). Fused, a lane agrees
    /// with the scalar closed form to rounding as before, not to the unfused bits.
    fn exp_transform_with<const FMA: bool>(self, p: [W; 3]) -> Option<[W; 3]>;
}

impl<W: Lane<Scalar = f64>> ExpLanes<W> for Bivector<W> {
    #[inline(always)]
    fn exp_transform(self, p: [W; 3]) -> Option<[W; 3]> {
        self.exp_transform_with::<false>(p)
    }

    #[inline(always)]
    fn exp_transform_with<const FMA: bool>(self, p: [W; 3]) -> Option<[W; 3]> {
        // The half rotation vector u and the translation part v (see `quat_map`).
        let (ux, uy, uz) = (-self.e23, self.e13, -self.e12);
        let two = W::splat(2.0);
        let (vx, vy, vz) = (-two * self.e1i, -two * self.e2i, -two * self.e3i);
        let phi2 = ux * ux + uy * uy + uz * uz;
        if !(0..W::LANES).all(|i| phi2.lane(i) <= MAX_PHI * MAX_PHI) {
            return None;
        }
        let rigid = (0..W::LANES).all(|i| self.eoi.lane(i) == 0.0);
        // The series cut for the largest half-angle of the batch: most blends turn by much
        // less than the range allows.
        let (sc, c, k_series) = match tier_of(phi2) {
            0 => series_cut::<W, { CUTS[0][0] }, { CUTS[0][1] }, { CUTS[0][2] }, FMA>(phi2),
            1 => series_cut::<W, { CUTS[1][0] }, { CUTS[1][1] }, { CUTS[1][2] }, FMA>(phi2),
            2 => series_cut::<W, { CUTS[2][0] }, { CUTS[2][1] }, { CUTS[2][2] }, FMA>(phi2),
            _ => series_cut::<W, 13, 14, 16, FMA>(phi2),
        };
        // The translation is t = zr v + k (u . v) u + zi (u x v) with `(zr, k, zi)` below, and
        // the rotation by the rotor (sinc u, cos) moves p to
        // (cos^2 - |sinc u|^2) p + 2 sinc^2 (p . u) u + 2 sinc cos (u x p).
        // Summed, the two terms along u and the two cross products each share one product:
        // p' = k0 p + zr v + (2 a (p . u) + k (u . v)) u + u x (2 b p + zi v),
        // with a = sinc^2 and b = sinc cos (the rigid case's zi and zr).
        let a = sc * sc;
        let b = sc * c;
        let (zr, k, zi, p) = if rigid {
            (b, k_series, a, p)
        } else {
            let (zr, k, zi, s) = dilation_terms(self.eoi, phi2, sc, c);
            (zr, k, zi, [s * p[0], s * p[1], s * p[2]])
        };
        let [px, py, pz] = p;
        let b2 = two * b;
        // `m(a, b, c) = a b + c`, one instruction where fused.
        let m = |a: W, b: W, c: W| a.mul_add_if::<FMA>(b, c);
        let along = m(
            two * a,
            m(px, ux, m(py, uy, pz * uz)),
            k * m(ux, vx, m(uy, vy, uz * vz)),
        );
        let (wx, wy, wz) = (m(b2, px, zi * vx), m(b2, py, zi * vy), m(b2, pz, zi * vz));
        let k0 = m(c, c, -(a * phi2));
        Some([
            m(k0, px, m(zr, vx, m(along, ux, m(uy, wz, -(uz * wy))))),
            m(k0, py, m(zr, vy, m(along, uy, m(uz, wx, -(ux * wz))))),
            m(k0, pz, m(zr, vz, m(along, uz, m(ux, wy, -(uy * wx))))),
        ])
    }
}

/// The half-angle bounds of the shorter series cuts.
const TIERS: [f64; 3] = [0.25, 0.5, 1.0];

/// The terms of `SINC`, `COS` and `K` kept for half-angles up to each bound of [`TIERS`]:
/// each series is cut where its next term is under `1e-18` at the bound (a test checks it).
const CUTS: [[usize; 3]; 3] = [[7, 7, 7], [8, 8, 9], [10, 10, 12]];

/// The first tier whose bound holds for every lane's `phi^2` (`TIERS.len()` for the full
/// series).
#[inline(always)]
fn tier_of<W: Lane<Scalar = f64>>(phi2: W) -> usize {
    let mut most = 0.0f64;
    for i in 0..W::LANES {
        most = most.max(phi2.lane(i));
    }
    let mut t = 0;
    while t < TIERS.len() && most > TIERS[t] * TIERS[t] {
        t += 1;
    }
    t
}

/// `(sinc, cos, k)` of `phi2` from the first `A`, `B` and `C` terms of their series.
#[inline(always)]
fn series_cut<
    W: Lane<Scalar = f64>,
    const A: usize,
    const B: usize,
    const C: usize,
    const FMA: bool,
>(
    phi2: W,
) -> (W, W, W) {
    (
        horner_first::<W, A, 13, FMA>(&SINC, phi2),
        horner_first::<W, B, 14, FMA>(&COS, phi2),
        horner_first::<W, C, 16, FMA>(&K, phi2),
    )
}

/// The scalar form's translation coefficients `(zr, k, zi / phi)` and scale `e^(2 l)` for
/// log-scales `l`, lane by lane with the same guards (`Bivector::exp_parts`).
#[inline(always)]
fn dilation_terms<W: Lane<Scalar = f64>>(l: W, phi2: W, sc: W, c: W) -> (W, W, W, W) {
    let (one, two, zero) = (W::splat(1.0), W::splat(2.0), W::splat(0.0));
    // e = exp(l) and em = exp(l) - 1, lane by lane (the scalar form's helper).
    // One call per lane (at most 8 lanes), then the two values as lanes.
    let mut pairs = [(1.0, 0.0); 8];
    for (i, p) in pairs.iter_mut().enumerate().take(W::LANES) {
        *p = exp_pair(l.lane(i));
    }
    let e = W::from_fn(|i| pairs[i].0);
    let em = W::from_fn(|i| pairs[i].1);
    let sg = two * l;
    let eg = e * e;
    let egm1 = em * (one + e);
    let ax = (sg * sg).gt_select(zero, egm1 / sg, one);
    let phi = phi2.sqrt();
    let sn = sc * phi;
    let er = egm1 * (c * c - sn * sn) - two * sn * sn;
    let theta = two * phi;
    let w2 = sg * sg + theta * theta;
    let ei_phi = two * eg * sc * c;
    let tiny = W::splat(f64::MIN_POSITIVE);
    let zr = w2.gt_select(tiny, (er * sg + eg * two * sn * c * theta) / w2, one);
    let zi = w2.gt_select(tiny, (ei_phi * sg - two * er) / w2, one);
    let k = phi2.gt_select(tiny, (ax - zr) / phi2, zero);
    (zr, k, zi, eg)
}

/// Rotate points by unit quaternions `(x, y, z, w)` lane by lane, as glam's `DQuat * DVec3`
/// writes it (`p (w^2 - |q|^2) + q 2 (p . q) + (q x p) 2 w`), so that a lane gives glam's
/// bits.
#[inline(always)]
pub fn rotate_lanes<W: Lane>(q: [W; 4], p: [W; 3]) -> [W; 3] {
    let [qx, qy, qz, w] = q;
    let [x, y, z] = p;
    let two = W::constant(2.0);
    let b2 = qx * qx + qy * qy + qz * qz;
    let k0 = w * w - b2;
    let k1 = (x * qx + y * qy + z * qz) * two;
    let k2 = w * two;
    let (rx, ry, rz) = (qy * z - qz * y, qz * x - qx * z, qx * y - qy * x);
    [
        x * k0 + qx * k1 + rx * k2,
        y * k0 + qy * k1 + ry * k2,
        z * k0 + qz * k1 + rz * k2,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::f64::Bivector as ScalarBivector;

    /// The scalar form.
    fn scalar(b: ScalarBivector, p: glam::DVec3) -> glam::DVec3 {
        b.exp_similarity().transform_point(p)
    }
    use crate::wide::F64x4;
    use glam::DVec3;

    #[test]
    fn series_match_the_functions() {
        for i in 0..=200 {
            let phi = MAX_PHI * i as f64 / 200.0;
            let x = phi * phi;
            let (s, c) = phi.sin_cos();
            let sinc = if phi == 0.0 { 1.0 } else { s / phi };
            assert!((horner(&SINC, x) - sinc).abs() < 4e-16, "sinc {phi}");
            assert!((horner(&COS, x) - c).abs() < 4e-16, "cos {phi}");
            if phi > 0.1 {
                let k = (1.0 - sinc * c) / x;
                assert!((horner(&K, x) - k).abs() < 1e-14 * k.max(1.0), "k {phi}");
            }
        }
        assert!((horner(&K, 0.0f64) - 2.0 / 3.0).abs() < 1e-16);
    }

    /// Each tier keeps the terms the cut rule asks for at its bound (the next term under
    /// 1e-18, the one before not), and its sums agree with the functions over the tier.
    #[test]
    fn tiers_cut_each_series_where_its_terms_vanish() {
        fn terms(c: &[f64], bound: f64) -> usize {
            (0..c.len())
                .find(|&n| c[n].abs() * bound.powi(2 * n as i32) < 1e-18)
                .unwrap_or(c.len())
        }
        for (t, &b) in TIERS.iter().enumerate() {
            assert_eq!(
                CUTS[t],
                [terms(&SINC, b), terms(&COS, b), terms(&K, b)],
                "tier {b}"
            );
        }
        // The full series keep at least as many at MAX_PHI.
        assert!(SINC.len() >= terms(&SINC, MAX_PHI));
        assert!(COS.len() >= terms(&COS, MAX_PHI));
        assert!(K.len() >= terms(&K, MAX_PHI));
        let cut = |t: usize, x: f64| match t {
            0 => series_cut::<f64, { CUTS[0][0] }, { CUTS[0][1] }, { CUTS[0][2] }, false>(x),
            1 => series_cut::<f64, { CUTS[1][0] }, { CUTS[1][1] }, { CUTS[1][2] }, false>(x),
            _ => series_cut::<f64, { CUTS[2][0] }, { CUTS[2][1] }, { CUTS[2][2] }, false>(x),
        };
        for (t, &b) in TIERS.iter().enumerate() {
            for i in 0..=100 {
                let phi = b * i as f64 / 100.0;
                let x = phi * phi;
                let (s, c, k) = cut(t, x);
                assert!((s - horner(&SINC, x)).abs() < 2e-16, "sinc {phi}");
                assert!((c - horner(&COS, x)).abs() < 2e-16, "cos {phi}");
                assert!((k - horner(&K, x)).abs() < 2e-16, "k {phi}");
            }
        }
        let four = |x: [f64; 4]| tier_of(F64x4(x));
        assert_eq!(four([0.0, 0.01, 0.0625, 0.0]), 0);
        assert_eq!(four([0.0, 0.07, 0.0625, 0.0]), 1);
        assert_eq!(four([0.9, 0.07, 1.0, 0.0]), 2);
        assert_eq!(four([0.9, 1.01, 1.0, 0.0]), 3);
    }

    #[test]
    fn lanes_agree_with_the_scalar_exponential() {
        let gens = [
            ScalarBivector::from_array([0.0, 0.0, 0.0, 0.0, 0.3, -1.2, 0.7, 0.5, -2.0, 1.0]),
            ScalarBivector::from_array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.5, 0.25, -3.0]),
            ScalarBivector::from_array([0.0, 0.0, 0.0, 0.0, 1e-9, 0.0, -2e-9, 0.1, 0.2, 0.3]),
            ScalarBivector::from_array([0.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.6, -0.4, 0.0, 0.9]),
        ];
        let pts = [
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(-4.0, 0.5, 0.0),
            DVec3::ZERO,
            DVec3::new(10.0, -7.0, 2.5),
        ];
        let p = [
            F64x4::from_fn(|i| pts[i].x),
            F64x4::from_fn(|i| pts[i].y),
            F64x4::from_fn(|i| pts[i].z),
        ];
        // Every lane of `g`'s batch against the scalar form, unfused and fused (here the C
        // library's `fma`: the same values as the instruction).
        let check = |g: &[ScalarBivector; 4], what: &str| {
            let w = Bivector::<F64x4>::gather(g);
            let plain = w.exp_transform(p).expect("in range");
            let fused = w.exp_transform_with::<true>(p).expect("in range");
            assert_ne!(
                plain, fused,
                "{what}: fused sums round differently somewhere"
            );
            for (q, i) in [plain, fused]
                .into_iter()
                .flat_map(|q| (0..4).map(move |i| (q, i)))
            {
                let want = scalar(g[i], pts[i]);
                let got = DVec3::new(q[0].lane(i), q[1].lane(i), q[2].lane(i));
                assert!(
                    (got - want).abs().max_element() < 1e-13 * want.length().max(1.0),
                    "{what}, lane {i}: {got} vs {want}"
                );
            }
        };
        check(&gens, "as given");
        // The same generators scaled down into each shorter series' tier.
        for f in [0.6, 0.3, 0.15, 0.05] {
            let small = gens.map(|g| ScalarBivector::from_array(g.to_array().map(|c| c * f)));
            check(&small, &format!("scaled by {f}"));
        }
        // Dilation parts, small, large and none, in one batch.
        let mut d = gens;
        d[0].eoi = 0.3;
        d[2].eoi = -0.8;
        d[3].eoi = 1e-12;
        check(&d, "dilated");
        // A pure dilation (no rotation), then a half-angle past the range.
        let mut z = d;
        z[1] = ScalarBivector::from_array([0.0, 0.0, 0.0, 0.4, 0.0, 0.0, 0.0, 0.2, 0.0, 0.0]);
        check(&z, "a pure dilation in lane 1");
        z[1].e12 = 2.5;
        assert!(Bivector::<F64x4>::gather(&z).exp_transform(p).is_none());
    }
}
