//! GPU skinning report: every backend with a GPU form on a procedural rig of 1M vertices and
//! 64 bones (4 influences each) and on libigl's armadillo (43,243 vertices, 5 dense weights),
//! per frame: the pose on the device alone (keys uploaded, compute pass, wait) and with the
//! positions read back, medians of 21 frames; against the memory-bandwidth limit of the bytes
//! each pose moves (`GpuBlend::bytes_per_pose`, over `--bandwidth GB/s`, default 4800: an
//! H200's HBM3e), and the CPU's pose of the same rig for scale.
//!
//! `cargo run --release -p deform --features gpu --example gpu_report [-- --bandwidth 3350]`
//! (on a machine without a GPU, Mesa's lavapipe runs it on the CPU: correct, not fast).
//! `benches/gpu/run.sh` runs it on a lent GPU machine.

#[path = "../benches/support/skin_scenes.rs"]
mod skin_scenes;

use cga::ScaledMotor;
use deform::gpu::{GpuBlend, GpuContext};
use deform::skinning::{Influences, Skinning};
use deform::BlendMethod;
use glam::{DQuat, DVec3};
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// `n` points in a box, 4 influences among `bones` each (normalised weights), and one rigid
/// key per bone.
fn procedural(n: usize, bones: usize) -> skin_scenes::SkinScene {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let positions: Vec<DVec3> = (0..n)
        .map(|_| DVec3::new(next(), next(), next()) * 2.0 - 1.0)
        .collect();
    let mut joints = Vec::with_capacity(4 * n);
    let mut weights = Vec::with_capacity(4 * n);
    for _ in 0..n {
        let w: [f64; 4] = std::array::from_fn(|_| 0.05 + next());
        let sum: f64 = w.iter().sum();
        for x in w {
            joints.push((next() * bones as f64) as u32 % bones as u32);
            weights.push(x / sum);
        }
    }
    let keys = (0..bones)
        .map(|j| {
            let f = j as f64 / bones as f64;
            let q = DQuat::from_axis_angle(DVec3::new(f, 1.0, 0.5 - f).normalize(), 0.2 + f);
            ScaledMotor::from_scale_rotation_translation(1.0, q, DVec3::new(f, -f, 0.3))
        })
        .collect();
    skin_scenes::SkinScene {
        name: "procedural 1M / 64 bones",
        positions,
        influences: Influences {
            width: 4,
            joints,
            weights,
        },
        joints: bones,
        keys,
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let bandwidth = args
        .iter()
        .position(|a| a == "--bandwidth")
        .and_then(|i| args.get(i + 1))
        .map(|v| v.parse::<f64>().expect("--bandwidth GB/s"))
        .unwrap_or(4800.0);
    let ctx = match GpuContext::new() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    println!(
        "GPU: {}{}; limit at {bandwidth} GB/s",
        ctx.adapter(),
        if ctx.is_software() { " (software)" } else { "" }
    );
    let mut scenes = vec![procedural(1_000_000, 64)];
    scenes.extend(skin_scenes::armadillo());
    for s in &scenes {
        let n = s.positions.len();
        println!(
            "{} ({n} vertices, {} influences)",
            s.name, s.influences.width
        );
        println!(
            "  {:<20} {:>10} {:>12} {:>10} {:>10} {:>10}",
            "backend", "device ms", "+read ms", "limit ms", "x limit", "CPU ms"
        );
        let mut out = vec![DVec3::ZERO; n];
        for method in BlendMethod::ALL {
            let cpu = Skinning::bind_influences(&s.positions, &s.influences, s.joints, method)
                .expect("bind");
            let Ok(mut gpu) = GpuBlend::bind(&ctx, cpu.blend()) else {
                println!("  {:<20} no GPU form", method.name());
                continue;
            };
            let (mut device, mut total, mut host) = (Vec::new(), Vec::new(), Vec::new());
            for frame in 0..24 {
                let t = Instant::now();
                gpu.run(&ctx, &s.keys).expect("run");
                let d = t.elapsed().as_secs_f64() * 1e3;
                gpu.read_back(&ctx, &mut out).expect("read back");
                let a = t.elapsed().as_secs_f64() * 1e3;
                let t = Instant::now();
                cpu.blend().pose(&s.keys, &mut out).expect("cpu");
                let c = t.elapsed().as_secs_f64() * 1e3;
                if frame >= 3 {
                    device.push(d);
                    total.push(a);
                    host.push(c);
                }
            }
            let limit = gpu.bytes_per_pose() as f64 / (bandwidth * 1e9) * 1e3;
            let d = median(device);
            println!(
                "  {:<20} {:>10.3} {:>12.3} {:>10.4} {:>10.1} {:>10.3}",
                method.name(),
                d,
                median(total),
                limit,
                d / limit,
                median(host)
            );
        }
    }
    println!(
        "device ms: keys uploaded, one compute pass, waited for (includes the submit and wait \
         overhead); +read ms: with the positions copied back to the host."
    );
}
