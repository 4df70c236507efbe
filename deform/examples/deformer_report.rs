//! Quick report of the deformers' speed on armadillo-50k and its 200k-vertex subdivision:
//! bind time (harmonic fields and rest points), pose time per frame with both cores, and ns
//! per vertex of the four blend methods on the same weights (4 cubic B-spline keys), and the
//! speed-up of the batch pose loop over the vertex-by-vertex loop (same run), for the
//! spline, the handles and a positional lattice.
//! Medians of repeated runs with their range `[fastest, slowest]`; rows with a target (the
//! armadillo-50k rows of `deform/BENCH.md`) say `met` or `MISSED`. The criterion bench
//! `deformers` measures the same.
//!
//! `cargo run --release -p deform --example deformer_report`

#[path = "../benches/support/limits.rs"]
mod limits;
#[path = "../benches/support/scenes.rs"]
mod scenes;

use cga::ScaledMotor;
use devkit::grade::{Spread, Tally, Target};
use devkit::measure::spread_ms;

use deform::{BlendMethod, Deformer, Mesh, MotorHandles, SplineDeformer};
use glam::DVec3;

/// The targets of issue 10, set for armadillo-50k; the subdivision is reported for scaling.
struct Targets {
    bind_ms: Option<Target>,
    pose_ms: Option<Target>,
}

/// Pose times of the spline and the handles, ms per frame: the batch loop and the
/// vertex-by-vertex loop it replaced.
struct PoseTimes {
    spline: Spread,
    handles: Spread,
    spline_vertex: Spread,
    handles_vertex: Spread,
}

/// Times and prints every row of one mesh: binds, poses, the lattice and the blend methods.
fn report(name: &str, mesh: &Mesh, targets: &Targets, tally: &mut Tally) {
    let n = mesh.vertex_count();
    let (bind_spline, bind_handles) = time_binds(mesh);
    let spline = scenes::bind_spline(mesh);
    let handles = scenes::bind_handles(mesh);
    let keys = scenes::keys(mesh, 4);
    let mut out = vec![DVec3::ZERO; n];
    let poses = time_poses(&spline, &handles, &keys, &mut out);
    println!(
        "{name} ({n} vertices, {} threads)",
        rayon::current_num_threads()
    );
    print_deformer_rows(bind_spline, bind_handles, &poses, targets, tally);
    lattice_rows(mesh, &mut out, tally);
    blend_rows(mesh, &spline, &keys, &mut out, tally);
}

/// Bind times of the spline and of the 4 handles (harmonic fields and rest points), ms.
fn time_binds(mesh: &Mesh) -> (Spread, Spread) {
    let bind_spline = spread_ms(3, || {
        std::hint::black_box(scenes::bind_spline(mesh));
    });
    let bind_handles = spread_ms(3, || {
        std::hint::black_box(scenes::bind_handles(mesh));
    });
    (bind_spline, bind_handles)
}

/// Warms up, then times posing the spline and the handles with `keys` into `out`, with the
/// batch loop and then with the vertex-by-vertex loop.
fn time_poses(
    spline: &SplineDeformer,
    handles: &MotorHandles,
    keys: &[ScaledMotor],
    out: &mut [DVec3],
) -> PoseTimes {
    // Warm up (page in the output, wake the thread pool) before measuring.
    let (mut spline_poser, mut handles_poser) = (spline.poser(), handles.poser());
    for _ in 0..20 {
        spline_poser.pose(keys, out).expect("pose");
        handles_poser.pose(keys, out).expect("pose");
    }
    let pose_spline = spread_ms(31, || spline_poser.pose(keys, out).expect("pose"));
    let pose_handles = spread_ms(31, || handles_poser.pose(keys, out).expect("pose"));
    // The vertex-by-vertex loop the batch loop replaced, in the same run (issue 23: at least
    // 2x per vertex on both cores).
    let mut prepared = spline.blend().scratch();
    let spline_vertex = spread_ms(31, || {
        spline
            .blend()
            .pose_vertex_by_vertex(keys, &mut prepared, out)
            .expect("pose")
    });
    let handles_vertex = spread_ms(31, || {
        handles
            .blend()
            .pose_vertex_by_vertex(keys, &mut prepared, out)
            .expect("pose")
    });
    PoseTimes {
        spline: pose_spline,
        handles: pose_handles,
        spline_vertex,
        handles_vertex,
    }
}

/// Prints the graded bind and pose rows, then the speed-up of the batch loop over the
/// vertex-by-vertex loop (graded where the pose has a target).
fn print_deformer_rows(
    bind_spline: Spread,
    bind_handles: Spread,
    poses: &PoseTimes,
    targets: &Targets,
    tally: &mut Tally,
) {
    let rows = [
        (
            "bind spline (field + rest points)",
            bind_spline,
            "ms",
            targets.bind_ms,
        ),
        (
            "bind 4 handles (fields + rest)",
            bind_handles,
            "ms",
            targets.bind_ms,
        ),
        (
            "pose spline, 4 B-spline keys",
            poses.spline,
            "ms/frame",
            targets.pose_ms,
        ),
        (
            "pose 4 motor handles",
            poses.handles,
            "ms/frame",
            targets.pose_ms,
        ),
    ];
    for (label, s, unit, target) in rows {
        println!("{}", tally.row(&format!("  {label}"), s, unit, target));
    }
    let gain = targets.pose_ms.map(|_| Target::AtLeast(2.0));
    for (label, batch, vertex) in [
        ("spline", poses.spline, poses.spline_vertex),
        ("handles", poses.handles, poses.handles_vertex),
    ] {
        println!(
            "{}",
            tally.row(
                &format!("  pose {label}: batch loop over vertex by vertex"),
                batch.speedup_over(vertex),
                "x",
                gain
            )
        );
    }
}

/// Binds the positional form of a lattice (4 x 3 x 3 points, cubic: 64 weights per vertex) and
/// prints its pose time and the speed-up of the batch loop over the per-vertex sum it replaced,
/// both on both cores.
fn lattice_rows(mesh: &Mesh, out: &mut [DVec3], tally: &mut Tally) {
    let ffd = deform::deformers::ffd::Ffd::bind(
        mesh,
        [4, 3, 3],
        None,
        deform::deformers::ffd::FfdOptions {
            form: deform::blend::control::ControlForm::Positional,
            ..Default::default()
        },
    )
    .expect("lattice");
    let binding = ffd.binding();
    let control: Vec<DVec3> = binding
        .rest_points()
        .iter()
        .map(|p| *p * 1.1 + DVec3::Y)
        .collect();
    let ffd_batch = spread_ms(31, || binding.pose_points(&control, out).expect("pose"));
    let ffd_vertex = spread_ms(31, || {
        use rayon::prelude::*;
        let w = binding.weights();
        out.par_iter_mut()
            .enumerate()
            .with_min_len(1024)
            .for_each(|(i, o)| *o = w.row(i).fold(DVec3::ZERO, |a, k, x| a + x * control[k]));
    });
    println!(
        "{}",
        tally.row(
            "  pose lattice 4x3x3, positional",
            ffd_batch,
            "ms/frame",
            None
        )
    );
    println!(
        "{}",
        tally.row(
            "  pose lattice: batch loop over vertex by vertex",
            ffd_batch.speedup_over(ffd_vertex),
            "x",
            None
        )
    );
}

/// Per blend method: prints its estimated limit (4 keys per vertex, both cores), then rebinds
/// the spline with it and prints ns per vertex with rigid keys and with the scaled `keys`.
fn blend_rows(
    mesh: &Mesh,
    spline: &SplineDeformer,
    keys: &[ScaledMotor],
    out: &mut [DVec3],
    tally: &mut Tally,
) {
    let n = mesh.vertex_count();
    let rigid = scenes::rigid_keys(mesh, 4);
    let per_vertex = 1e6 / n as f64;
    // The limits of the blend rows (4 keys per vertex, both cores).
    let threads = rayon::current_num_threads();
    let ns_per_byte = limits::stream_ns_per_byte(limits::bytes(4) as usize * n, threads);
    let clock = limits::ghz();
    for method in BlendMethod::ALL {
        let compute = limits::operations(method, 4) / (16.0 * clock * threads as f64);
        let memory = limits::bytes(4) * ns_per_byte;
        println!(
            "  {} limit: {:.1} ns/vertex (compute {compute:.1} for {:.0} operations, memory {memory:.1} for {:.0} bytes)",
            method.name(),
            compute.max(memory),
            limits::operations(method, 4),
            limits::bytes(4)
        );
        let d = scenes::rebind_spline(mesh, spline, method);
        let mut poser = d.poser();
        let rigid_ns = spread_ms(31, || poser.pose(&rigid, out).expect("pose")).scale(per_vertex);
        let scaled_ns = spread_ms(31, || poser.pose(keys, out).expect("pose")).scale(per_vertex);
        let label = format!("  blend {}, rigid keys", method.name());
        println!("{}", tally.row(&label, rigid_ns, "ns/vertex", None));
        let label = format!("  blend {}, scaled keys", method.name());
        println!("{}", tally.row(&label, scaled_ns, "ns/vertex", None));
    }
}

fn main() {
    let Some(arma) = scenes::armadillo() else {
        return;
    };
    let mut tally = Tally::default();
    let set = Targets {
        bind_ms: Some(Target::AtMost(150.0)),
        pose_ms: Some(Target::AtMost(2.0)),
    };
    report("armadillo-50k", &arma, &set, &mut tally);
    let scaling = Targets {
        bind_ms: None,
        pose_ms: None,
    };
    report(
        "armadillo-50k subdivided (no targets: scaling)",
        &arma.subdivide_midpoint(),
        &scaling,
        &mut tally,
    );
    println!("{}", tally.summary());
}
