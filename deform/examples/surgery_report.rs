//! Quick report of cut, tear and drill speed (medians of repeated runs with their range, the
//! face index built once) on libigl's arm and CesiumMan, graded against the targets of
//! `deform/BENCH.md` (cut < 1 ms, tear step and drill < 0.5 ms), and the ratio to the paper's
//! Python timings on its 5k-face arm. The criterion bench `surgery` measures the same.
//!
//! `cargo run --release -p deform --example surgery_report`

#[path = "../benches/support/surgery_scenes.rs"]
mod surgery_scenes;

use devkit::grade::{Tally, Target};
use devkit::measure::spread_ms;

use deform::surgery::{CutOptions, DrillOptions, Frame, Surgery, TearOptions};

fn main() {
    let mut tally = Tally::default();
    for s in surgery_scenes::all() {
        let rig = &s.rig;
        println!(
            "{} ({} vertices, {} faces)",
            s.name,
            rig.mesh.vertex_count(),
            rig.mesh.triangle_count()
        );
        let index = spread_ms(21, || {
            std::hint::black_box(Surgery::new(&rig.mesh, &rig.influences).expect("index"));
        });
        let surgery = Surgery::new(&rig.mesh, &rig.influences).expect("index");
        let cut = spread_ms(201, || {
            std::hint::black_box(
                surgery
                    .cut(&s.plane, Frame::Rest, &CutOptions::default())
                    .expect("cut"),
            );
        });
        let tear = spread_ms(201, || {
            std::hint::black_box(
                surgery
                    .tear(&s.scalpel, Frame::Rest, &TearOptions::default())
                    .expect("tear"),
            );
        });
        let drill = spread_ms(201, || {
            std::hint::black_box(
                surgery
                    .drill(&s.drill, Frame::Rest, &DrillOptions::default())
                    .expect("drill"),
            );
        });
        println!(
            "{}",
            tally.row("  index (BVH + topology)", index, "ms", None)
        );
        for (name, ms, target) in [
            ("cut", cut, 1.0),
            ("tear step", tear, 0.5),
            ("drill", drill, 0.5),
        ] {
            let paper = surgery_scenes::PAPER_MS
                .iter()
                .find(|p| name.starts_with(p.0))
                .map_or(f64::NAN, |p| p.1);
            let label = format!("  {} {name}", s.name);
            println!(
                "{}",
                tally.row(&label, ms, "ms", Some(Target::Below(target)))
            );
            println!(
                "  {:<42} {:.0}x faster than the paper's Python ({paper:.0} ms, 5k faces)",
                "",
                paper / ms.value
            );
        }
    }
    println!("{}", tally.summary());
}
