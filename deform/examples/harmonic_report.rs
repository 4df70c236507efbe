//! Quick report of the harmonic field end to end (`harmonic_field`, k = 1: mesh checks,
//! cotangent Laplacian, ordering, Cholesky factorisation, one solve) on libigl's armadillo
//! (43,243 vertices) and armadillo-50k, with the lowest 5% of the box in y fixed at 0 and the
//! highest 5% at 1, on one thread and on two. Medians of 15 runs with their range.
//!
//! Issue 23 asks for 2x over the code before it; to measure both in one window, build this
//! example in a worktree of the earlier commit too and run the two binaries one after the
//! other (see `deform/BENCH.md`).
//!
//! `cargo run --release -p deform --example harmonic_report`

#[path = "../benches/support/scenes.rs"]
mod scenes;

use devkit::grade::{Tally, Target};
use devkit::measure::spread_ms;

use deform::operators::harmonic::{harmonic_field, HarmonicOptions};

fn main() -> Result<(), deform::Error> {
    let mut tally = Tally::default();
    println!("harmonic field, k = 1 (ms)");
    for rel in ["libigl/armadillo.obj", "large/armadillo-50k.obj"] {
        let Some(mesh) = scenes::mesh(rel) else {
            continue;
        };
        let (fixed, moved) = scenes::spline_ends(&mesh);
        let opts = HarmonicOptions::default();
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("pool");
            let t = pool.install(|| {
                spread_ms(15, || {
                    std::hint::black_box(
                        harmonic_field(&mesh, &fixed, &moved, opts).expect("field"),
                    );
                })
            });
            let label = format!(
                "  {rel} ({} vertices, {} constrained), {threads} thread(s)",
                mesh.vertex_count(),
                fixed.len() + moved.len()
            );
            println!("{}", tally.row(&label, t, "ms", None::<Target>));
        }
    }
    Ok(())
}
