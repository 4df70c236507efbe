//! Estimates of the limits of a pose loop per vertex, shared by the quick reports: the
//! floating-point work of each batch kernel, the bytes it streams, the clock, and the
//! streaming rate of this machine for a working set of a given size. Included by path by the
//! quick reports (`examples/skinning_report.rs`, `deformer_report.rs`); no criterion bench uses it.

use deform::BlendMethod;
use devkit::measure::median_ms;

/// Floating-point operations per vertex of the batch kernel of `m` with `w` influences (a
/// count of the adds, multiplies, divisions and square roots written in `blend/kernels.rs`;
/// the hemisphere table and the key preparation are per pose, not per vertex).
pub fn flops(m: BlendMethod, w: usize) -> f64 {
    let w = w as f64;
    match m {
        // Row sums (8 per key), norm 7, 1/n 1, the fused sandwich 36 + 28, the rescale 9.
        BlendMethod::MotorLinear => 16.0 * w + 81.0,
        // Row sums, norm 7, 1/n 1, translation 24, rotation 27, add and rescale 6.
        BlendMethod::DualQuaternion => 16.0 * w + 65.0,
        // Row sums over 12 of the 16 lanes written, the 3x4 map 18.
        BlendMethod::Matrix => 24.0 * w + 18.0,
        BlendMethod::Conformal => 26.0 * w + 21.0,
        BlendMethod::ConformalProjected => (18.0 + 3.0 + 6.0) * w,
        // Row sums over 7 (8 lanes), three series of 13, 14 and 16 terms (2 each),
        // translation 30, rotation 30.
        BlendMethod::MotorLog => 16.0 * w + 86.0 + 60.0,
        // glam's f32 path: 12 multiply-adds per key and the map.
        BlendMethod::MatrixF32 => 24.0 * w + 18.0,
    }
}

/// Arithmetic operations per vertex of the batch kernel of `m` in the copy this process runs
/// (`deform::blend::simd_level`): the [`flops`], except where the AVX2 copy fuses a multiply and an
/// add into one instruction (the row sums of dual quaternions, matrix LBS, equation (17) and
/// log blending, half their flops; and log blending's three series, 43, and its exponential's
/// sums, 50), which is what the compute limit divides by the machine's operations per cycle.
pub fn operations(m: BlendMethod, w: usize) -> f64 {
    let fused_rows = |per_key: f64| per_key * w as f64;
    match m {
        _ if deform::blend::simd_level() != "avx2" => flops(m, w),
        BlendMethod::DualQuaternion => fused_rows(8.0) + 65.0,
        BlendMethod::Matrix => fused_rows(12.0) + 18.0,
        BlendMethod::Conformal => fused_rows(13.0) + 21.0,
        BlendMethod::MotorLog => fused_rows(8.0) + 43.0 + 50.0,
        _ => flops(m, w),
    }
}

/// Bytes per vertex streamed by a pose: the weight (8) and key index (4) of each influence,
/// the rest point (24) and the posed point (24). The key tables stay in cache.
pub fn bytes(w: usize) -> f64 {
    12.0 * w as f64 + 48.0
}

/// Nanoseconds per byte to read a buffer of `len` bytes and write one a third its size (about
/// the mix a pose streams), on `threads` threads: the memory limit at that working-set size.
pub fn stream_ns_per_byte(len: usize, threads: usize) -> f64 {
    let src = vec![1.0f64; len / 8];
    let mut dst = vec![0.0f64; len / 24];
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool");
    let ms = pool.install(|| {
        use rayon::prelude::*;
        median_ms(41, || {
            dst.par_chunks_mut(4096)
                .zip(src.par_chunks(3 * 4096))
                .for_each(|(d, s)| {
                    for (o, c) in d.iter_mut().zip(s.chunks_exact(3)) {
                        *o = c[0] + c[1] + c[2];
                    }
                });
            std::hint::black_box(&dst);
        })
    });
    ms * 1e6 / (len + len / 3) as f64
}

/// Clock of this machine in GHz (from /proc/cpuinfo; 2.5 if unknown).
pub fn ghz() -> f64 {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("cpu MHz"))
                .and_then(|l| l.split(':').nth(1))
                .and_then(|v| v.trim().parse::<f64>().ok())
        })
        .map_or(2.5, |mhz| mhz / 1000.0)
}
