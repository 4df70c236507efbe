//! The pose loop over batches of four vertices.
//!
//! At bind the weight rows are stored for streaming ([`Batches`]): per batch of four vertices
//! and per slot of the row, the four key indices and an [`F64x4`] of weights, then the four
//! rest points as three `F64x4`. Rows have the deformer's fixed width; the last batch is
//! padded with copies of the last vertex. At pose a [`Kernel`] (one per blend method, see
//! `kernels.rs`) gathers the keys of a slot into the generated wide twins (`cga::wide`),
//! blends them lane by lane and applies the result to the four points at once.
//!
//! The loop is compiled twice: for CPUs with AVX2 (256-bit lanes, chosen at run time with
//! `is_x86_feature_detected!`, so one binary runs everywhere) and for the x86-64 baseline
//! (SSE2; `DEFORM_SIMD=baseline` forces it). The AVX2 copy also needs FMA (every AVX2 CPU
//! made has it) and runs [`Kernel::batch_fused`], which is the same lane operations as
//! [`Kernel::batch`], so the same bits in both copies, except in the kernels that override it
//! with fused multiply-adds (the row sums of dual quaternions, matrix LBS and equation (17),
//! and all of log blending: each agreeing with the per-vertex path to rounding, as its unfused
//! form does).
//!
//! Every pose reports whether what it wrote is finite (a blend can leave the `f64` range): a
//! kernel either adds each batch's lanes into a probe inside the loop or has its task's
//! vertices scanned after it, whichever its code layout makes cheaper ([`Kernel::PROBE`]).

use super::PARALLEL_MIN;
use crate::blend::all_finite;
use crate::blend::KeyWeights;
use cga::wide::{F64x4, Lane};
use glam::DVec3;
use rayon::prelude::*;

/// Vertices per batch: the lanes of an [`F64x4`].
pub(crate) const LANES: usize = 4;

/// Vertices per parallel task (a multiple of [`LANES`]).
pub(super) const TASK: usize = 1024;

/// Four points, coordinate by coordinate.
pub(crate) type Points4 = [F64x4; 3];

/// Weight rows and rest points laid out for the batch loop.
#[derive(Clone, Debug, Default)]
pub(crate) struct Batches {
    width: usize,
    /// `keys[b * width + j]`: the keys of slot `j` of the four vertices of batch `b`.
    keys: Vec<[u32; LANES]>,
    /// `weights[b * width + j]`: their weights.
    weights: Vec<F64x4>,
    /// The four rest points of batch `b`.
    points: Vec<Points4>,
}

impl Batches {
    /// The streaming layout of `weights` and `points` (one point per row); empty when the
    /// rows have no slot.
    pub(crate) fn new(weights: &KeyWeights, points: &[DVec3]) -> Batches {
        let (n, width) = (points.len(), weights.width());
        if width == 0 || n == 0 {
            return Batches::default();
        }
        let count = n.div_ceil(LANES);
        let mut b = Batches {
            width,
            keys: Vec::with_capacity(count * width),
            weights: Vec::with_capacity(count * width),
            points: Vec::with_capacity(count),
        };
        for first in (0..n).step_by(LANES) {
            // Lanes past the last vertex repeat it (their results are dropped).
            let v = |l: usize| (first + l).min(n - 1);
            for j in 0..width {
                b.keys
                    .push(std::array::from_fn(|l| weights.row(v(l)).key(j) as u32));
                b.weights
                    .push(F64x4::from_fn(|l| weights.row(v(l)).weights[j]));
            }
            b.points.push([
                F64x4::from_fn(|l| points[v(l)].x),
                F64x4::from_fn(|l| points[v(l)].y),
                F64x4::from_fn(|l| points[v(l)].z),
            ]);
        }
        b
    }

    /// Whether there is nothing to run (no slot): callers pose vertex by vertex.
    pub(crate) fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// `out[i]` for every vertex: `kernel` on each batch, `single(i)` for the vertices of a
    /// batch the kernel declines (a degenerate blend it leaves to the per-vertex path).
    /// Parallel over tasks of [`TASK`] vertices when there are enough of them. Whether every
    /// vertex written is finite (each task checks its own while they are in cache).
    pub(crate) fn run<K: Kernel>(
        &self,
        kernel: &K,
        single: &(impl Fn(usize) -> DVec3 + Sync),
        out: &mut [DVec3],
    ) -> bool {
        debug_assert_eq!(out.len().div_ceil(LANES), self.points.len());
        let task = |(t, o): (usize, &mut [DVec3])| self.dispatch(kernel, single, t * TASK, o);
        if out.len() < PARALLEL_MIN {
            task((0, out))
        } else {
            out.par_chunks_mut(TASK)
                .enumerate()
                .map(task)
                .reduce(|| true, |a, b| a && b)
        }
    }

    /// The batches of `out` (vertices from `first`), with the widest lanes the CPU has;
    /// whether every vertex written is finite.
    fn dispatch<K: Kernel>(
        &self,
        kernel: &K,
        single: &(impl Fn(usize) -> DVec3 + Sync),
        first: usize,
        out: &mut [DVec3],
    ) -> bool {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: the CPU has AVX2 (checked at run time just above).
            return unsafe { self.range_avx2(kernel, single, first, out) };
        }
        self.range::<K, false>(kernel, single, first, out)
    }

    /// [`Batches::range`] compiled for AVX2 and FMA, with the fused kernels.
    ///
    /// # Safety
    /// The CPU must have AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn range_avx2<K: Kernel>(
        &self,
        kernel: &K,
        single: &(impl Fn(usize) -> DVec3 + Sync),
        first: usize,
        out: &mut [DVec3],
    ) -> bool {
        self.range::<K, true>(kernel, single, first, out)
    }

    /// The batch loop: `out` holds the vertices from `first` (a multiple of [`LANES`]);
    /// [`Kernel::batch_fused`] when `FMA` (only in a copy compiled with the `fma` feature).
    /// Whether every vertex written is finite. With [`Kernel::PROBE`] full batches add their
    /// lanes into one probe (not finite once a lane is not; three vector additions a batch,
    /// and a check point by point when the sum overflows) and the rest are checked as
    /// written; without, the task's vertices are checked once written, while in cache
    /// ([`all_finite`], a vectorised scan). Which is faster depends on the kernel's code
    /// layout, not on the work: each kernel says.
    #[inline(always)]
    fn range<K: Kernel, const FMA: bool>(
        &self,
        kernel: &K,
        single: &(impl Fn(usize) -> DVec3 + Sync),
        first: usize,
        out: &mut [DVec3],
    ) -> bool {
        let mut probe = F64x4::splat(0.0);
        let mut finite = true;
        let w = self.width;
        let b0 = first / LANES;
        let keys = &self.keys[b0 * w..];
        let weights = &self.weights[b0 * w..];
        for (i, (((o, p), k), wt)) in out
            .chunks_mut(LANES)
            .zip(&self.points[b0..])
            .zip(keys.chunks_exact(w))
            .zip(weights.chunks_exact(w))
            .enumerate()
        {
            let q = if FMA {
                kernel.batch_fused(k, wt, p)
            } else {
                kernel.batch(k, wt, p)
            };
            match q {
                Some(q) => {
                    for (l, o) in o.iter_mut().enumerate() {
                        *o = DVec3::new(q[0].lane(l), q[1].lane(l), q[2].lane(l));
                    }
                    if K::PROBE {
                        if o.len() == LANES {
                            probe += q[0] + q[1] + q[2];
                        } else {
                            // The last, partial batch: its padding lanes are not vertices.
                            finite &= all_finite(o);
                        }
                    }
                }
                None => {
                    let v0 = first + i * LANES;
                    for (l, o) in o.iter_mut().enumerate() {
                        *o = single(v0 + l);
                    }
                    if K::PROBE {
                        finite &= all_finite(o);
                    }
                }
            }
        }
        if !K::PROBE {
            return all_finite(out);
        }
        // A sum that overflowed from finite points is checked point by point (rare).
        finite && ((0..LANES).all(|l| probe.lane(l).is_finite()) || all_finite(out))
    }
}

/// Whether to run the AVX2 copy: the CPU has AVX2 and FMA and the environment variable
/// `DEFORM_SIMD` is not `baseline` (which benchmarks and CI use to measure and test the
/// baseline copy on the same machine). Decided once per process.
#[cfg(target_arch = "x86_64")]
#[inline]
fn avx2() -> bool {
    static AVX2: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *AVX2.get_or_init(|| {
        std::is_x86_feature_detected!("avx2")
            && std::is_x86_feature_detected!("fma")
            && std::env::var("DEFORM_SIMD").map_or(true, |v| v != "baseline")
    })
}

/// The lanes the batch loop runs on in this process: `"avx2"` or `"baseline"`.
pub fn simd_level() -> &'static str {
    #[cfg(target_arch = "x86_64")]
    if avx2() {
        return "avx2";
    }
    "baseline"
}

/// The blend of one method over a batch of four vertices.
pub(crate) trait Kernel: Sync {
    /// Whether the batch loop checks the written vertices by a probe inside the loop (true)
    /// or by a scan after it (false); see `Batches::range`.
    const PROBE: bool = true;

    /// The four posed points from the slots' `keys` and `weights` and the rest `points`;
    /// `None` declines the batch (the caller poses its vertices one by one).
    fn batch(&self, keys: &[[u32; LANES]], weights: &[F64x4], points: &Points4) -> Option<Points4>;

    /// [`Kernel::batch`] where the CPU fuses multiply-adds: the batch loop's AVX2 copy (compiled
    /// with the `fma` feature) calls this. The same operations unless a kernel says otherwise.
    #[inline(always)]
    fn batch_fused(
        &self,
        keys: &[[u32; LANES]],
        weights: &[F64x4],
        points: &Points4,
    ) -> Option<Points4> {
        self.batch(keys, weights, points)
    }
}

#[cfg(test)]
mod tests {
    use crate::blend::all_finite;
    use glam::DVec3;

    /// Every kind of non-finite coordinate, in every position, is seen; finite extremes are not.
    #[test]
    fn all_finite_sees_every_non_finite_coordinate() {
        let finite = [
            f64::MAX,
            -f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -0.0,
            0.0,
            1.0,
        ];
        let mut points: Vec<DVec3> = (0..7)
            .map(|i| DVec3::new(finite[i], finite[(i + 1) % 7], finite[(i + 2) % 7]))
            .collect();
        assert!(all_finite(&points));
        assert!(all_finite(&[]));
        for bad in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN, -f64::NAN] {
            for v in 0..points.len() {
                for c in 0..3 {
                    let keep = points[v][c];
                    points[v][c] = bad;
                    assert!(!all_finite(&points), "{bad} at {v}.{c}");
                    points[v][c] = keep;
                }
            }
        }
    }
}
