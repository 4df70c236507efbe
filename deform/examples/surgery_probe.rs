use deform::surgery::{CutOptions, Drill, DrillOptions, Frame, Surgery};
use std::time::Instant;
fn main() {
    let lib = std::path::Path::new("../shared/data/meshes/libigl");
    let mesh = deform::io::read_obj(lib.join("arm.obj")).unwrap();
    let sk = deform::io::read_tgf(lib.join("arm.tgf")).unwrap();
    let w = deform::io::read_dmat(lib.join("arm-weights.dmat")).unwrap();
    let rig = deform::skinning::libigl_rig(mesh, &sk, &w).unwrap();
    let t = Instant::now();
    let s = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    println!("index {:.3} ms", t.elapsed().as_secs_f64() * 1e3);
    let d = Drill {
        tip: glam::DVec3::new(0.1, 0.17, -1.0),
        end: glam::DVec3::new(0.1, 0.17, 1.0),
        radius: 0.04,
    };
    let t = Instant::now();
    for _ in 0..2000 {
        std::hint::black_box(s.drill(&d, Frame::Rest, &DrillOptions::default()).unwrap());
    }
    println!("drill {:.3} ms", t.elapsed().as_secs_f64() * 1e3 / 2000.0);
    let p = cga::Plane::from_normal_distance(glam::DVec3::new(1.0, 0.1, 0.0).normalize(), 0.0);
    let t = Instant::now();
    for _ in 0..20 {
        std::hint::black_box(s.cut(&p, Frame::Rest, &CutOptions::default()).unwrap());
    }
    println!("cut {:.3} ms", t.elapsed().as_secs_f64() * 1e3 / 20.0);
}
