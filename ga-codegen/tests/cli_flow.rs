//! The CLI flow of the README ("Use it in your crate", `ga-codegen`), done as a new user does
//! it: a fresh crate outside the workspace that depends only on the `ga-codegen` runtime
//! (`default-features = false`), PGA and STA modules written into its `src/` by the CLI
//! (`algebras/pga3d.toml -o src/pga3d.rs`, `algebras/sta.toml --library --wide -o src/sta.rs`),
//! declared with `pub mod pga3d;` in its `lib.rs` and used by a `main` that asserts its numbers. The crate must
//! build without a warning (`-D warnings`): the `--library` impls are behind `serde` and
//! `bytemuck` features this crate does not declare, which once warned once per impl.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

mod fresh_crate;

/// The crate's library: the generated modules, public (in a binary's private module every
/// generated item the program does not use would be dead code, warned about).
const LIB: &str = "pub mod pga3d;\npub mod sta;\n";

const MAIN: &str = r#"
use cli_flow::{pga3d, sta};
use pga3d::Sandwich as _;
use sta::Sandwich as _;

fn main() {
    // PGA: points x e032 + y e013 + z e021 + w e123; `1 + 0.5 e01` moves the origin to x = -1.
    let origin = pga3d::Point::new(0.0, 0.0, 0.0, 1.0);
    let p = pga3d::Translator::new(1.0, 0.5, 0.0, 0.0).sandwich(origin);
    println!("pga: (1 + 0.5 e01) moves the origin to x = {}", p.e032 / p.e123);
    assert!((p.e032 / p.e123 + 1.0).abs() < 1e-15);
    // A motor `T * R`: turn 90 degrees about z (cos - sin e12), then move by (1, 2, 3).
    let h = std::f64::consts::FRAC_PI_4;
    let r = pga3d::Rotor::new(h.cos(), 0.0, 0.0, -h.sin());
    let t = pga3d::Translator::new(1.0, -0.5, -1.0, -1.5);
    let m: pga3d::Motor = t * r;
    let q = m.sandwich(pga3d::Point::new(1.0, 0.0, 0.0, 1.0));
    let got = [q.e032 / q.e123, q.e013 / q.e123, q.e021 / q.e123];
    println!("pga: motor moves (1, 0, 0) to {got:?}");
    let want = [1.0, 3.0, 3.0];
    assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-14));

    // STA: cosh(phi/2) - sinh(phi/2) e01 boosts a particle at rest to velocity +tanh(phi).
    let phi = 0.5f64;
    let b = sta::Rotor::new((phi / 2.0).cosh(), -(phi / 2.0).sinh(), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    let v = b.sandwich(sta::Vector::new(1.0, 0.0, 0.0, 0.0));
    println!("sta: velocity {} (tanh: {})", v.e1 / v.e0, phi.tanh());
    assert!((v.e1 / v.e0 - phi.tanh()).abs() < 1e-15);
    // The wide twin moves four vectors at once, lane for lane as the scalar sandwich.
    let vs = [0.0, 1.0, 2.0, 3.0].map(|x| sta::Vector::new(1.0 + x, x, -x, 0.5));
    let wb = sta::wide::Rotor::<sta::wide::F64x4>::splat(b);
    let wide = wb.sandwich(sta::wide::Vector::<sta::wide::F64x4>::gather(&vs));
    for (i, v) in vs.iter().enumerate() {
        assert_eq!(wide.lane(i), b.sandwich(*v));
    }
    println!("ok");
}
"#;

#[test]
fn a_new_crate_builds_and_runs_modules_the_cli_wrote() {
    let manifest_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let workspace = manifest_dir.join("..");
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("ga-codegen-cli-flow");
    let src = fresh_crate::write(&root, "cli-flow", 0, LIB, MAIN);
    for (spec, flags, out) in [
        ("algebras/pga3d.toml", &[][..], "pga3d.rs"),
        ("algebras/sta.toml", &["--library", "--wide"][..], "sta.rs"),
    ] {
        let out = src.join(out);
        let run = Command::new(env!("CARGO_BIN_EXE_ga-codegen"))
            .arg(spec)
            .args(flags)
            .arg("-o")
            .arg(&out)
            .current_dir(&workspace)
            .stdin(Stdio::null())
            .output()
            .unwrap();
        assert!(
            run.status.success(),
            "ga-codegen {spec} failed: {}",
            String::from_utf8_lossy(&run.stderr)
        );
    }
    fresh_crate::run(&src, &root);
}
