//! Quick report of cut, tear and drill speed (medians of repeated runs, the face index built
//! once) on libigl's arm and CesiumMan, and the ratio to the paper's Python timings on its
//! 5k-face arm. The criterion bench `surgery` measures the same.
//!
//! `cargo run --release -p deform --example surgery_report`

#[path = "../benches/surgery_scenes.rs"]
mod surgery_scenes;

use surgery_scenes::measure::median_ms;

use deform::surgery::{CutOptions, DrillOptions, Frame, Surgery, TearOptions};

fn main() {
    for s in surgery_scenes::all() {
        let rig = &s.rig;
        println!(
            "{} ({} vertices, {} faces)",
            s.name,
            rig.mesh.vertex_count(),
            rig.mesh.triangle_count()
        );
        let index = median_ms(21, || {
            std::hint::black_box(Surgery::new(&rig.mesh, &rig.influences).expect("index"));
        });
        let surgery = Surgery::new(&rig.mesh, &rig.influences).expect("index");
        let cut = median_ms(201, || {
            std::hint::black_box(
                surgery
                    .cut(&s.plane, Frame::Rest, &CutOptions::default())
                    .expect("cut"),
            );
        });
        let tear = median_ms(201, || {
            std::hint::black_box(
                surgery
                    .tear(&s.scalpel, Frame::Rest, &TearOptions::default())
                    .expect("tear"),
            );
        });
        let drill = median_ms(201, || {
            std::hint::black_box(
                surgery
                    .drill(&s.drill, Frame::Rest, &DrillOptions::default())
                    .expect("drill"),
            );
        });
        println!("  {:<28} {:>9.3} ms", "index (BVH + topology)", index);
        for (name, ms) in [("cut", cut), ("tear step", tear), ("drill", drill)] {
            let paper = surgery_scenes::PAPER_MS
                .iter()
                .find(|p| name.starts_with(p.0))
                .map_or(f64::NAN, |p| p.1);
            println!("  {name:<28} {ms:>9.3} ms   paper (Python, 5k faces) {paper:>7.0} ms: {:>8.0}x faster", paper / ms);
        }
    }
}
