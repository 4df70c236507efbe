//! Quick report of skinning speed: every backend on libigl's armadillo (5 weights), arm and
//! CesiumMan, on 1 and 2 threads: ms per frame and ns per vertex of the batch loop and of the
//! vertex-by-vertex loop it replaced (`BoundBlend::pose_vertex_by_vertex`), alternated in the
//! same run; per backend an estimate of the compute limit (operations per vertex at 16 per cycle
//! per core; a fused multiply-add is one) and of the memory limit (bytes per vertex at the
//! streaming rate measured here for the same working set) and the ratio to the larger.
//! Graded (`met` / `MISSED`): motor blending <= 1 ms on the armadillo and no slower than dual
//! quaternions, equation (17) within 1.1x of matrix LBS, log blending within 1.5x of motor
//! blending, and on one thread the speed-ups of issue 23 (dual quaternions 2x, motor blending
//! 3x, matrix 1.25x); and the time to sample
//! CesiumMan's animation and build its motors. The criterion bench `skinning` measures the same.
//!
//! `cargo run --release -p deform --example skinning_report [BACKEND..]`
//! (`DEFORM_SIMD=baseline` measures the baseline copy of the batch loop.)

#[path = "../benches/support/limits.rs"]
mod limits;
#[path = "../benches/support/skin_scenes.rs"]
mod skin_scenes;

use limits::{bytes, flops, ghz, operations, stream_ns_per_byte};

use devkit::grade::{Spread, Tally, Target};
use devkit::measure::{median_ms, spread_ms};

use deform::skinning::{KeyframeBlend, RigPose, Skinning};
use deform::BlendMethod::{self, *};
use deform::Deformer;
use glam::DVec3;

/// One backend's pose times on one scene: the batch loop and the vertex-by-vertex loop, ms.
struct Times {
    batch: Spread,
    vertex: Spread,
}

fn measure(s: &skin_scenes::SkinScene, method: BlendMethod) -> Times {
    let n = s.positions.len();
    let d = Skinning::bind_influences(&s.positions, &s.influences, s.joints, method).expect("bind");
    let mut out = vec![DVec3::ZERO; n];
    let mut prepared = d.blend().scratch();
    let mut poser = d.poser();
    for _ in 0..20 {
        poser.pose(&s.keys, &mut out).expect("pose");
    }
    // Alternate the two loops so that both see the same machine.
    let (mut b, mut v) = (Vec::new(), Vec::new());
    for _ in 0..15 {
        b.push(spread_ms(7, || poser.pose(&s.keys, &mut out).expect("pose")).value);
        v.push(
            spread_ms(7, || {
                d.blend()
                    .pose_vertex_by_vertex(&s.keys, &mut prepared, &mut out)
                    .expect("pose")
            })
            .value,
        );
    }
    Times {
        batch: Spread::median_of(&mut b),
        vertex: Spread::median_of(&mut v),
    }
}

fn main() {
    // `skinning_report [BACKEND..]`: only those backends (all by default).
    let only: Vec<String> = std::env::args().skip(1).collect();
    let clock = ghz();
    println!(
        "skinning: the batch loop ({} lanes) against the vertex-by-vertex loop in the same run; \
         limits: {clock:.2} GHz x 16 operations/cycle/core (two 4-wide adds and two multiplies; a fused multiply-add counts once), and streaming \
         the bytes at the rate measured here for the same working set",
        deform::blend::simd_level()
    );
    let mut tally = Tally::default();
    for s in skin_scenes::all() {
        scene_rows(&s, &only, clock, &mut tally);
    }
    cesium_rows();
    println!("{}", tally.summary());
}

/// One scene: its heading, then on 1 and then 2 threads every selected backend's rows and
/// the graded comparisons between backends.
fn scene_rows(s: &skin_scenes::SkinScene, only: &[String], clock: f64, tally: &mut Tally) {
    let n = s.positions.len();
    let w = s.influences.width;
    println!(
        "{} ({n} vertices, {} joints, {w} influences per vertex)",
        s.name, s.joints
    );
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        let ns_per_byte = stream_ns_per_byte(bytes(w) as usize * n, threads);
        println!("  {threads} thread(s)");
        let mut got: Vec<(BlendMethod, Times)> = Vec::new();
        for method in skin_scenes::BACKENDS {
            if !only.is_empty() && !only.iter().any(|o| o == method.name()) {
                continue;
            }
            let t = pool.install(|| measure(s, method));
            let limit = Limit::new(method, w, threads, clock, ns_per_byte);
            print_backend(s, method, &t, &limit, tally);
            got.push((method, t));
        }
        comparison_rows(s, threads, &got, tally);
    }
}

/// A backend's estimated limit on one scene, ns per vertex.
struct Limit {
    /// Operations per vertex at 16 per cycle per core.
    compute: f64,
    /// Bytes per vertex at the measured streaming rate.
    memory: f64,
}

impl Limit {
    /// The limit of `method` with `w` influences per vertex on `threads` cores at `clock` GHz,
    /// streaming at `ns_per_byte`.
    fn new(method: BlendMethod, w: usize, threads: usize, clock: f64, ns_per_byte: f64) -> Limit {
        Limit {
            compute: operations(method, w) / (16.0 * clock * threads as f64),
            memory: bytes(w) * ns_per_byte,
        }
    }
}

/// Prints a backend's graded ms per frame, then ns per vertex of both loops, the speed-up,
/// the limit and the ratio to it.
fn print_backend(
    s: &skin_scenes::SkinScene,
    method: BlendMethod,
    t: &Times,
    limit: &Limit,
    tally: &mut Tally,
) {
    let n = s.positions.len();
    let w = s.influences.width;
    let per_vertex = |ms: Spread| ms.scale(1e6 / n as f64);
    let Limit { compute, memory } = *limit;
    let limit = compute.max(memory);
    let target = (s.name == "armadillo" && method == BlendMethod::MotorLinear)
        .then_some(Target::AtMost(1.0));
    println!(
        "{}",
        tally.row(
            &format!("    {}", method.name()),
            t.batch,
            "ms/frame",
            target
        )
    );
    println!(
        "      {:.1} ns/vertex (vertex by vertex {:.1}, x{:.2}); limit {:.1} ns \
         (compute {:.1} for {:.0} flops in {:.0} operations, memory {:.1} for {:.0} bytes): {:.1}x the limit",
        per_vertex(t.batch).value,
        per_vertex(t.vertex).value,
        t.vertex.value / t.batch.value,
        limit,
        compute,
        flops(method, w),
        operations(method, w),
        memory,
        bytes(w),
        per_vertex(t.batch).value / limit
    );
}

/// The graded ratios between backends (when all five were measured) and, on one thread on the
/// armadillo, issue 23's speed-ups over the per-vertex loop.
fn comparison_rows(
    s: &skin_scenes::SkinScene,
    threads: usize,
    got: &[(BlendMethod, Times)],
    tally: &mut Tally,
) {
    let get = |m: BlendMethod| got.iter().find(|(k, _)| *k == m).map(|(_, t)| t);
    let (Some(dq), Some(ml), Some(mx), Some(cf), Some(lg)) = (
        get(DualQuaternion),
        get(MotorLinear),
        get(Matrix),
        get(Conformal),
        get(MotorLog),
    ) else {
        return;
    };
    let mut rows = vec![
        (
            "motor-linear / dual-quaternion",
            ml.batch.ratio(dq.batch),
            Some(Target::AtMost(1.0)),
        ),
        (
            "conformal / matrix",
            cf.batch.ratio(mx.batch),
            Some(Target::AtMost(1.1)),
        ),
        (
            "motor-log / motor-linear",
            lg.batch.ratio(ml.batch),
            Some(Target::AtMost(1.5)),
        ),
    ];
    // Issue 23's speed-ups are measured on one thread, against the per-vertex loop.
    let gain = |t: &Times, x: f64| (t.batch.speedup_over(t.vertex), Some(Target::AtLeast(x)));
    if threads == 1 && s.name == "armadillo" {
        for (label, t, x) in [
            ("dual-quaternion speed-up", dq, 2.0),
            ("motor-linear speed-up", ml, 3.0),
            ("matrix speed-up", mx, 1.25),
        ] {
            let (r, target) = gain(t, x);
            rows.push((label, r, target));
        }
    }
    for (label, r, target) in rows {
        println!(
            "{}",
            tally.row(&format!("    {} {label}", s.name), r, "x", target)
        );
    }
}

/// Times sampling CesiumMan's animation and building its skin motors, with glTF samplers and
/// with motor log blending (when the rig is present).
fn cesium_rows() {
    let Some(rig) = skin_scenes::cesium_rig() else {
        return;
    };
    let (t0, t1) = rig.animations[0].range();
    let mut pose = RigPose::default();
    for (name, blend) in [
        ("glTF samplers", KeyframeBlend::Gltf),
        ("motor log blending", KeyframeBlend::MotorLog),
    ] {
        let mut t = t0;
        let ms = median_ms(1001, || {
            t = if t > t1 { t0 } else { t + 0.013 };
            rig.pose_into(Some(0), t, blend, &[], &mut pose)
                .expect("pose");
            std::hint::black_box(pose.skin_motors().expect("motors").len());
        });
        println!(
            "CesiumMan: sample + global and skin motors ({name}): {:.2} us/frame",
            ms * 1e3
        );
    }
}
