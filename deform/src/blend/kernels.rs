//! One batch kernel per blend method: the keys of each slot gathered into the generated wide
//! twins (`cga::wide`) or lane arrays, blended lane by lane, applied to four points.
//!
//! Each kernel is the per-vertex method of `keys.rs` written over four lanes, so a lane gives
//! what [`PreparedKeys::transform`] gives for its vertex to rounding (tested to 1e-13): matrix
//! LBS (in f64, and in f32 with glam's `Affine3A`) with the same operations in the same
//! order; motor and dual-quaternion blending without the square root (the sandwich and the rotation are quadratic, divided by the squared norm
//! once); equation (17) with one division by the blended `eo`; log blending by the series of
//! `cga::ExpLanes`. The hemisphere choice of the linear methods comes from a per-pose aligned
//! table, or a branch-free sign flip per term above 64 keys. A batch whose blend degenerates
//! (a vanishing rotor sum) is declined and posed vertex by vertex, as before.
//!
//! In the batch loop's AVX2+FMA copy, dual quaternions, matrix LBS and equation (17) sum their
//! rows with fused multiply-adds, and log blending fuses its series and sums too (8-10% and
//! 20-25% faster; `Kernel::batch_fused`). Motor blending does not: fusing its row sums made it
//! 15% slower on this machine.

use super::batch::{Batches, Kernel, Points4, LANES};
use super::keys::{dot, PreparedKeys};
use super::BlendMethod;
use cga::wide::{Bivector as WBivector, F64x4, Lane, Motor as WMotor, Point as WPoint};
use cga::{rotate_lanes, ExpLanes, Sandwich};
use glam::{Affine3A, DVec3, Vec3A};

/// `&table[k]` without a bounds check.
///
/// Every key index of a [`Batches`] is below the deformer's key count (checked when its
/// [`super::KeyWeights`] were built), and [`super::BoundBlend::pose_using`] prepares exactly
/// that many keys before running a kernel (as `ControlBinding::pose_points` checks that many
/// control points), so the index is in range.
#[inline(always)]
fn at<T>(table: &[T], k: u32) -> &T {
    debug_assert!((k as usize) < table.len());
    // SAFETY: see above: `k < key_count == table.len()`.
    unsafe { table.get_unchecked(k as usize) }
}

/// `[e(0), e(1), .., e(n - 1)]` with `i` bound in `e`: `std::array::from_fn` as a loop written
/// in place. A closure would be a function of its own, compiled for the baseline and called
/// out of the AVX2 loop, which costs more than the work.
macro_rules! each {
    ($n:expr, $i:ident => $e:expr) => {{
        let mut r = [Default::default(); $n];
        for $i in 0..$n {
            r[$i] = $e;
        }
        r
    }};
}

/// `impl Kernel` for a kernel whose `blend::<FMA>` is its batch: unfused in the baseline copy,
/// with fused multiply-adds in the AVX2+FMA copy (`Kernel::batch_fused`).
macro_rules! fused_kernel {
    ($t:ident) => {
        fused_kernel!($t, true);
    };
    ($t:ident, $probe:expr) => {
        impl Kernel for $t<'_> {
            const PROBE: bool = $probe;

            #[inline(always)]
            fn batch(
                &self,
                keys: &[[u32; LANES]],
                weights: &[F64x4],
                p: &Points4,
            ) -> Option<Points4> {
                self.blend::<false>(keys, weights, p)
            }

            #[inline(always)]
            fn batch_fused(
                &self,
                keys: &[[u32; LANES]],
                weights: &[F64x4],
                p: &Points4,
            ) -> Option<Points4> {
                self.blend::<true>(keys, weights, p)
            }
        }
    };
}

/// The key rows of a kernel (see `PreparedKeys::fill_rows`).
type Rows<'a> = &'a [[F64x4; 4]];

/// `sum_j w_j rows[k_j][..N]` for lane (vertex) `l` of a batch, each weight first passed
/// through `weight(row, w)` (the hemisphere sign): the accumulation runs along a key's row,
/// four coefficients per operation.
///
/// `index(k)` is the row of key `k` (`k` itself, or its entry in the aligned table).
#[inline(always)]
fn accumulate<const N: usize, const FMA: bool>(
    rows: Rows,
    keys: &[[u32; LANES]],
    weights: &[F64x4],
    l: usize,
    index: impl Fn(u32) -> u32,
    weight: impl Fn(&[F64x4; 4], f64) -> f64,
) -> [F64x4; N] {
    let mut acc = [F64x4::splat(0.0); N];
    for (k, w) in keys.iter().zip(weights) {
        let row = at(rows, index(k[l]));
        let w = F64x4::splat(weight(row, w.0[l]));
        for (a, r) in acc.iter_mut().zip(row) {
            *a = r.mul_add_if::<FMA>(w, *a);
        }
    }
    acc
}

/// `exp(sum w log s)` per lane: the geometric blend of the key scales, when any key scales.
#[inline(always)]
fn scales(log_scales: Option<&[f64]>, keys: &[[u32; LANES]], weights: &[F64x4]) -> Option<F64x4> {
    let ls = log_scales?;
    let mut acc = F64x4::splat(0.0);
    for (k, &w) in keys.iter().zip(weights) {
        acc += w * F64x4::from_fn(|l| *at(ls, k[l]));
    }
    Some(F64x4::from_fn(|l| acc.0[l].exp()))
}

/// The points times the blended scales, if any.
#[inline(always)]
fn scaled(
    log_scales: Option<&[f64]>,
    keys: &[[u32; LANES]],
    weights: &[F64x4],
    p: &Points4,
) -> Points4 {
    match scales(log_scales, keys, weights) {
        Some(s) => [s * p[0], s * p[1], s * p[2]],
        None => *p,
    }
}

/// Row `i` of the four vertices' sums, transposed: lane `l` of result `c` is lane `c` of
/// vertex `l`'s `v[l][i]`. Written as two rounds of two-source shuffles (interleave the low
/// and high lanes of pairs, then swap halves), which compile to a few vector shuffles where a
/// four-source gather per lane would be scalarised.
#[inline(always)]
fn transpose<const N: usize>(v: &[[F64x4; N]; LANES], i: usize) -> [F64x4; 4] {
    let [a, b, c, d] = [v[0][i].0, v[1][i].0, v[2][i].0, v[3][i].0];
    let (t0, t1) = ([a[0], b[0], a[2], b[2]], [a[1], b[1], a[3], b[3]]);
    let (t2, t3) = ([c[0], d[0], c[2], d[2]], [c[1], d[1], c[3], d[3]]);
    [
        F64x4([t0[0], t0[1], t2[0], t2[1]]),
        F64x4([t1[0], t1[1], t3[0], t3[1]]),
        F64x4([t0[2], t0[3], t2[2], t2[3]]),
        F64x4([t1[2], t1[3], t3[2], t3[3]]),
    ]
}

/// Motor blending: `normalise(sum w M)` in the hemisphere of the first key, times the blended
/// scale; the four blended motors are turned into one generated `wide::Motor` and applied by
/// its fused sandwich.
struct MotorLinear<'a> {
    rows: Rows<'a>,
    /// The key count when `rows` holds the aligned table.
    aligned: Option<u32>,
    log_scales: Option<&'a [f64]>,
}

/// `sum w row` over the keys of vertex `l`, in the hemisphere of its first key: from the
/// aligned table when there is one (no sign to find), else with a sign per term.
#[inline(always)]
fn hemisphere_sum<const FMA: bool>(
    rows: Rows,
    aligned: Option<u32>,
    keys: &[[u32; LANES]],
    weights: &[F64x4],
    l: usize,
) -> [F64x4; 2] {
    let k0 = keys[0][l];
    match aligned {
        Some(n) => accumulate::<2, FMA>(rows, keys, weights, l, |k| n + k0 * n + k, |_, w| w),
        None => {
            let r0 = at(rows, k0)[0];
            accumulate::<2, FMA>(
                rows,
                keys,
                weights,
                l,
                |k| k,
                |row, w| dot(row[0], r0).flip_sign_if_negative(w),
            )
        }
    }
}

// Unfused: fusing its row sums made it 15% slower on this machine (0.32 -> 0.37 ms on the
// armadillo, one thread), where the other kernels gained or held (see the module's docs).
impl Kernel for MotorLinear<'_> {
    #[inline(always)]
    fn batch(&self, keys: &[[u32; LANES]], weights: &[F64x4], p: &Points4) -> Option<Points4> {
        let sums: [[F64x4; 2]; LANES] =
            each!(LANES, l => hemisphere_sum::<false>(self.rows, self.aligned, keys, weights, l));
        let (r, d) = (transpose(&sums, 0), transpose(&sums, 1));
        let acc = WMotor::<F64x4> {
            s: r[0],
            e12: r[1],
            e13: r[2],
            e23: r[3],
            e1i: d[0],
            e2i: d[1],
            e3i: d[2],
            e123i: d[3],
        };
        let n2 = acc.s * acc.s + acc.e12 * acc.e12 + acc.e13 * acc.e13 + acc.e23 * acc.e23;
        if !n2.0.iter().all(|&x| x > f64::MIN_POSITIVE) {
            return None;
        }
        // The fused sandwich of a unit motor is `x + Q(M, x)` with `Q` quadratic in `M`: for
        // the unnormalised sum, `x + Q(acc, x) / |acc|^2` (no square root).
        let inv = F64x4::splat(1.0) / n2;
        let p = scaled(self.log_scales, keys, weights, p);
        let q = acc.sandwich(up(&p));
        Some([
            p[0] + (q.e1 - p[0]) * inv,
            p[1] + (q.e2 - p[1]) * inv,
            p[2] + (q.e3 - p[2]) * inv,
        ])
    }
}

/// Four conformal points `up(p)` (the `ei` coefficient is read by no kernel that moves only
/// `e1, e2, e3`, and is then compiled away).
#[inline(always)]
fn up(p: &Points4) -> WPoint<F64x4> {
    let [x, y, z] = *p;
    WPoint {
        e1: x,
        e2: y,
        e3: z,
        ei: F64x4::splat(0.5) * (x * x + y * y + z * z),
    }
}

/// Kavan's dual-quaternion blending: the sums along the key rows, the normalisation and the
/// rotation over four lanes.
struct DualQuaternion<'a> {
    rows: Rows<'a>,
    aligned: Option<u32>,
    log_scales: Option<&'a [f64]>,
}

// The finite check after the loop, not in it: the probe's additions in the loop made this
// kernel 28% slower on an EPYC host (0.46 -> 0.59 ms on the armadillo, one thread) where they
// made the motor kernels 8-13% faster (deform/BENCH.md, thirteenth session).
fused_kernel!(DualQuaternion, false);

impl DualQuaternion<'_> {
    /// The batch; the row sums fused when `FMA`.
    #[inline(always)]
    fn blend<const FMA: bool>(
        &self,
        keys: &[[u32; LANES]],
        weights: &[F64x4],
        p: &Points4,
    ) -> Option<Points4> {
        let sums: [[F64x4; 2]; LANES] =
            each!(LANES, l => hemisphere_sum::<FMA>(self.rows, self.aligned, keys, weights, l));
        let (r, d) = (transpose(&sums, 0), transpose(&sums, 1));
        let n2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3];
        if !n2.0.iter().all(|&x| x > 0.0) {
            return None;
        }
        // Both the rotation and `t = 2 vec(d ~r)` are quadratic in (r, d): computed with the
        // unnormalised sums and divided by |r|^2 once (no square root).
        let inv = F64x4::splat(1.0) / n2;
        let [ax, ay, az, aw] = d;
        let [bx, by, bz, bw] = [-r[0], -r[1], -r[2], r[3]];
        let two = F64x4::splat(2.0);
        let tx = two * (aw * bx + ax * bw + ay * bz - az * by);
        let ty = two * (aw * by - ax * bz + ay * bw + az * bx);
        let tz = two * (aw * bz + ax * by - ay * bx + az * bw);
        let q = rotate_lanes(r, scaled(self.log_scales, keys, weights, p));
        Some([(q[0] + tx) * inv, (q[1] + ty) * inv, (q[2] + tz) * inv])
    }
}

/// `c0 x + c1 y + c2 z + c3` for one vertex: the 3x4 map of a row set applied to its point.
#[inline(always)]
fn apply(c: &[F64x4; 4], p: &Points4, l: usize) -> F64x4 {
    let s = |i: usize| F64x4::splat(p[i].0[l]);
    c[0] * s(0) + c[1] * s(1) + c[2] * s(2) + c[3]
}

/// Linear blend skinning (`sum w A` applied to the point) and equation (17) adding the
/// conformal points first (the same, then divided by the blended `eo`). The division is done
/// per vertex, before the lanes are transposed: gathering the four `eo` into one vector first
/// made the compiler reload them across two stores (a store-forwarding stall that cost equation
/// (17) 35-45% over matrix LBS).
struct Affine<'a> {
    rows: Rows<'a>,
    /// Divide by lane 3 (the blended `eo` of equation (17)).
    project: bool,
}

// The finite check after the loop, as for dual quaternions: 6-7% faster than the probe on the
// armadillo (deform/BENCH.md, thirteenth session).
fused_kernel!(Affine, false);

impl Affine<'_> {
    /// The batch; the row sums fused when `FMA`.
    #[inline(always)]
    fn blend<const FMA: bool>(
        &self,
        keys: &[[u32; LANES]],
        weights: &[F64x4],
        p: &Points4,
    ) -> Option<Points4> {
        let q: [[F64x4; 1]; LANES] = each!(LANES, l => {
            let a: [F64x4; 4] = accumulate::<4, FMA>(self.rows, keys, weights, l, |k| k, |_, w| w);
            let e = apply(&a, p, l);
            // `1 / eo` is exact for the rigid keys' `eo = 1`.
            [if self.project { e * F64x4::splat(1.0 / e.0[3]) } else { e }]
        });
        let [x, y, z, _] = transpose(&q, 0);
        Some([x, y, z])
    }
}

/// Linear blend skinning in single precision: the operations of
/// `PreparedKeys::transform_f32` (glam's `Affine3A`) lane by lane, so each vertex gets the
/// bits of the per-vertex path, with the rows streamed from the batch layout.
struct AffineF32<'a> {
    affines: &'a [Affine3A],
}

impl Kernel for AffineF32<'_> {
    // The finite check after the loop (5% faster than the probe, as for `Affine`).
    const PROBE: bool = false;

    #[inline(always)]
    fn batch(&self, keys: &[[u32; LANES]], weights: &[F64x4], p: &Points4) -> Option<Points4> {
        let q: [Vec3A; LANES] = each!(LANES, l => {
            let mut m = Affine3A::ZERO;
            for (k, w) in keys.iter().zip(weights) {
                let a = at(self.affines, k[l]);
                let w = w.0[l] as f32;
                m = Affine3A {
                    matrix3: m.matrix3 + a.matrix3 * w,
                    translation: m.translation + a.translation * w,
                };
            }
            let x = DVec3::new(p[0].0[l], p[1].0[l], p[2].0[l]);
            m.transform_point3a(x.as_vec3a())
        });
        Some([
            F64x4([q[0].x, q[1].x, q[2].x, q[3].x].map(f64::from)),
            F64x4([q[0].y, q[1].y, q[2].y, q[3].y].map(f64::from)),
            F64x4([q[0].z, q[1].z, q[2].z, q[3].z].map(f64::from)),
        ])
    }
}

/// The positional form of lattices and cages: `sum w P` of the control points, lane by lane in
/// the per-vertex path's order (so its bits).
struct Positional<'a> {
    control: &'a [DVec3],
}

impl Kernel for Positional<'_> {
    #[inline(always)]
    fn batch(&self, keys: &[[u32; LANES]], weights: &[F64x4], _: &Points4) -> Option<Points4> {
        let zero = F64x4::splat(0.0);
        let (mut x, mut y, mut z) = (zero, zero, zero);
        for (k, w) in keys.iter().zip(weights) {
            let (c0, c1, c2, c3) = (
                at(self.control, k[0]),
                at(self.control, k[1]),
                at(self.control, k[2]),
                at(self.control, k[3]),
            );
            x += *w * F64x4([c0.x, c1.x, c2.x, c3.x]);
            y += *w * F64x4([c0.y, c1.y, c2.y, c3.y]);
            z += *w * F64x4([c0.z, c1.z, c2.z, c3.z]);
        }
        Some([x, y, z])
    }
}

/// `out[i] = sum_j w_ij control[k_ij]` for every vertex of `batches`, whose key indices must
/// be below `control.len()`.
pub(super) fn run_positional(
    batches: &Batches,
    control: &[DVec3],
    single: &(impl Fn(usize) -> DVec3 + Sync),
    out: &mut [DVec3],
) -> bool {
    batches.run(&Positional { control }, single, out)
}

/// Equation (17), down-projecting each term first.
struct ConformalProjected<'a> {
    rows: Rows<'a>,
}

impl Kernel for ConformalProjected<'_> {
    #[inline(always)]
    fn batch(&self, keys: &[[u32; LANES]], weights: &[F64x4], p: &Points4) -> Option<Points4> {
        let q: [[F64x4; 1]; LANES] = each!(LANES, l => {
            let mut acc = F64x4::splat(0.0);
            for (k, w) in keys.iter().zip(weights) {
                let e = apply(at(self.rows, k[l]), p, l);
                acc += F64x4::splat(w.0[l]) * (e / F64x4::splat(e.0[3]));
            }
            [acc]
        });
        let [x, y, z, _] = transpose(&q, 0);
        Some([x, y, z])
    }
}

/// Log blending: `exp(sum w log M)`; the sums along the key rows, the closed-form exponential
/// over four lanes (`cga::ExpLanes`), vertex by vertex for a batch with a half-angle past the
/// lanes' range.
struct MotorLog<'a> {
    rows: Rows<'a>,
}

fused_kernel!(MotorLog);

impl MotorLog<'_> {
    /// `exp(sum w log M)` applied to the four points; the series and the sums of the
    /// exponential fused when `FMA` (`ExpLanes::exp_transform_with`).
    #[inline(always)]
    fn blend<const FMA: bool>(
        &self,
        keys: &[[u32; LANES]],
        weights: &[F64x4],
        p: &Points4,
    ) -> Option<Points4> {
        let sums: [[F64x4; 2]; LANES] =
            each!(LANES, l => accumulate::<2, FMA>(self.rows, keys, weights, l, |k| k, |_, w| w));
        let (a, b) = (transpose(&sums, 0), transpose(&sums, 1));
        let zero = F64x4::splat(0.0);
        let log = WBivector::<F64x4> {
            eo1: zero,
            eo2: zero,
            eo3: zero,
            eoi: b[2],
            e12: a[0],
            e13: a[1],
            e23: a[2],
            e1i: a[3],
            e2i: b[0],
            e3i: b[1],
        };
        if let Some(q) = log.exp_transform_with::<FMA>(*p) {
            return Some(q);
        }
        let q: [DVec3; LANES] = each!(LANES, l => log
            .lane(l)
            .exp_similarity()
            .transform_point(DVec3::new(p[0].0[l], p[1].0[l], p[2].0[l])));
        Some([
            F64x4::from_fn(|l| q[l].x),
            F64x4::from_fn(|l| q[l].y),
            F64x4::from_fn(|l| q[l].z),
        ])
    }
}

/// Pose every vertex of `batches` with the kernel of the prepared keys' method (`single(i)`
/// for the vertices of declined batches).
pub(super) fn run(
    prepared: &PreparedKeys,
    batches: &Batches,
    single: &(impl Fn(usize) -> DVec3 + Sync),
    out: &mut [DVec3],
) -> bool {
    let log_scales = prepared.scaled().then_some(&prepared.log_scales[..]);
    let rows = &prepared.rows[..];
    // At most 64 keys when aligned: the table index fits a u32.
    let aligned = prepared.aligned().map(|k| k as u32);
    match prepared.method() {
        BlendMethod::MotorLinear => batches.run(
            &MotorLinear {
                rows,
                aligned,
                log_scales,
            },
            single,
            out,
        ),
        BlendMethod::DualQuaternion => batches.run(
            &DualQuaternion {
                rows,
                aligned,
                log_scales,
            },
            single,
            out,
        ),
        BlendMethod::Matrix => batches.run(
            &Affine {
                rows,
                project: false,
            },
            single,
            out,
        ),
        BlendMethod::Conformal => batches.run(
            &Affine {
                rows,
                project: true,
            },
            single,
            out,
        ),
        BlendMethod::ConformalProjected => batches.run(&ConformalProjected { rows }, single, out),
        BlendMethod::MotorLog => batches.run(&MotorLog { rows }, single, out),
        BlendMethod::MatrixF32 => batches.run(
            &AffineF32 {
                affines: &prepared.affines_f32,
            },
            single,
            out,
        ),
    }
}
