//! Quick report of the deformers' speed on armadillo-50k and its 200k-vertex subdivision:
//! bind time (harmonic fields and rest points), pose time per frame with both cores, and ns
//! per vertex of the four blend methods on the same weights (4 cubic B-spline keys).
//! Medians of repeated runs; the criterion bench `deformers` measures the same.
//!
//! `cargo run --release -p deform --example deformer_report`

#[path = "../benches/scenes.rs"]
mod scenes;

use scenes::measure::median_ms;

use deform::{BlendMethod, Deformer, Mesh};
use glam::DVec3;

fn report(name: &str, mesh: &Mesh) {
    let n = mesh.vertex_count();
    let bind_spline = median_ms(3, || {
        std::hint::black_box(scenes::bind_spline(mesh));
    });
    let bind_handles = median_ms(3, || {
        std::hint::black_box(scenes::bind_handles(mesh));
    });
    let spline = scenes::bind_spline(mesh);
    let handles = scenes::bind_handles(mesh);
    let keys = scenes::keys(mesh, 4);
    let mut out = vec![DVec3::ZERO; n];
    // Warm up (page in the output, wake the thread pool) before measuring.
    for _ in 0..20 {
        spline.pose(&keys, &mut out).expect("pose");
    }
    let pose_spline = median_ms(31, || spline.pose(&keys, &mut out).expect("pose"));
    let pose_handles = median_ms(31, || handles.pose(&keys, &mut out).expect("pose"));
    println!(
        "{name} ({n} vertices, {} threads)",
        rayon::current_num_threads()
    );
    println!(
        "  {:<34} {:>9.1} ms",
        "bind spline (field + rest points)", bind_spline
    );
    println!(
        "  {:<34} {:>9.1} ms",
        "bind 4 handles (fields + rest)", bind_handles
    );
    println!(
        "  {:<34} {:>9.3} ms/frame",
        "pose spline, 4 B-spline keys", pose_spline
    );
    println!(
        "  {:<34} {:>9.3} ms/frame",
        "pose 4 motor handles", pose_handles
    );
    let rigid = scenes::rigid_keys(mesh, 4);
    let mut base = 0.0;
    for method in BlendMethod::ALL {
        let d = scenes::rebind_spline(mesh, &spline, method);
        let rigid_ms = median_ms(31, || d.pose(&rigid, &mut out).expect("pose"));
        let scaled_ms = median_ms(31, || d.pose(&keys, &mut out).expect("pose"));
        if method == BlendMethod::Matrix {
            base = rigid_ms;
        }
        println!(
            "  blend {:<16} rigid keys {:>7.1} ns/vertex   scaled keys {:>7.1} ns/vertex",
            method.name(),
            rigid_ms * 1e6 / n as f64,
            scaled_ms * 1e6 / n as f64
        );
        let _ = base;
    }
}

fn main() {
    let Some(arma) = scenes::armadillo() else {
        return;
    };
    report("armadillo-50k", &arma);
    report("armadillo-50k subdivided", &arma.subdivide_midpoint());
}
