//! Quick report of skinning speed: every backend on libigl's armadillo (5 weights), arm and
//! CesiumMan, ms per frame (both cores) and ns per vertex, medians of repeated runs with their
//! range; the targets of `deform/BENCH.md` graded (`met` / `MISSED`): motor blending <= 1 ms on
//! the armadillo and no slower than our dual quaternions, equation (17) within 1.2x of matrix
//! LBS; and the time to sample CesiumMan's animation and build its motors. The criterion bench
//! `skinning` measures the same.
//!
//! `cargo run --release -p deform --example skinning_report`

#[path = "../benches/support/skin_scenes.rs"]
mod skin_scenes;

use devkit::grade::{Spread, Tally, Target};
use devkit::measure::{median_ms, spread_ms};

use deform::skinning::{KeyframeBlend, RigPose, Skinning};
use deform::Deformer;
use glam::DVec3;

fn main() {
    println!("skinning, {} threads", rayon::current_num_threads());
    let mut tally = Tally::default();
    for s in skin_scenes::all() {
        let n = s.positions.len();
        println!(
            "{} ({n} vertices, {} joints, {} influences per vertex)",
            s.name, s.joints, s.influences.width
        );
        let mut out = vec![DVec3::ZERO; n];
        let mut times = Vec::new();
        for method in skin_scenes::BACKENDS {
            let d = Skinning::bind_influences(&s.positions, &s.influences, s.joints, method)
                .expect("bind");
            let mut poser = d.poser();
            for _ in 0..20 {
                poser.pose(&s.keys, &mut out).expect("pose");
            }
            let ms = spread_ms(101, || poser.pose(&s.keys, &mut out).expect("pose"));
            times.push((method, ms));
            let target = (s.name == "armadillo" && method == deform::BlendMethod::MotorLinear)
                .then_some(Target::AtMost(1.0));
            let label = format!("  {}", method.name());
            println!("{}", tally.row(&label, ms, "ms/frame", target));
            println!("  {:<42} {:.1} ns/vertex", "", ms.value * 1e6 / n as f64);
        }
        let get = |m| {
            times
                .iter()
                .find(|(k, _)| *k == m)
                .map(|t| t.1)
                .unwrap_or(Spread::exact(f64::NAN))
        };
        use deform::BlendMethod::*;
        let ratios = [
            (
                "motor-linear / dual-quaternion",
                get(MotorLinear).ratio(get(DualQuaternion)),
                Some(Target::AtMost(1.0)),
            ),
            (
                "conformal / matrix",
                get(Conformal).ratio(get(Matrix)),
                Some(Target::AtMost(1.2)),
            ),
            (
                "conformal-projected / conformal",
                get(ConformalProjected).ratio(get(Conformal)),
                None,
            ),
        ];
        for (label, r, target) in ratios {
            println!(
                "{}",
                tally.row(&format!("  {} {label}", s.name), r, "x", target)
            );
        }
    }
    if let Some(rig) = skin_scenes::cesium_rig() {
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
    println!("{}", tally.summary());
}
