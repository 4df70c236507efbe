//! 3D projective geometric algebra G(3,0,1) from a spec written inline with `algebra!`: points,
//! planes, rotors, translators and motors, checked against plain coordinates and against the
//! slow generic `Multivector` of `ga-codegen`.
//!
//! ```text
//! cargo run -p ga-macros --example pga
//! ```
//!
//! A crate of your own that calls `algebra!` depends on `ga-macros` and on the runtime,
//! `ga-codegen = { version = "0.1", default-features = false }`: the expansion names
//! `::ga_codegen` (this example gets it as `ga-macros`' own dependency).
//!
//! Sign conventions (as in `algebras/pga3d.toml`, klein's naming): a point is
//! `x e032 + y e013 + z e021 + w e123`, and the sandwich is `M X ~M`. With these point blades
//! the translator `1 + (d/2) e01` moves a point by `-d` along x (`1 + 0.5 e01` takes the
//! origin to x = -1), because `e01 e123 = e023 = -e032`: translate by `+t` with
//! `1 - (t/2)(tx e01 + ty e02 + tz e03)`. Rotations follow the same rule as in G(3):
//! `exp(-(a/2) e12) = cos(a/2) - sin(a/2) e12` turns a point about the z axis by `+a` (x
//! towards y). So both motions are `exp(-B/2)`, with `B = a e12` or `B = t e01`.

mod pga {
    ga_macros::algebra! {
        //! 3D projective geometric algebra G(3,0,1), with the degenerate vector e0.
        name = "pga3d";
        basis = [e0, e1, e2, e3];
        diagonal = [0, 1, 1, 1];
        /// A plane `a e1 + b e2 + c e3 + d e0`: the points with `a x + b y + c z + d = 0`.
        type Plane { blades = [e0, e1, e2, e3] }
        /// A point `x e032 + y e013 + z e021 + w e123` (normalised when w = 1).
        type Point { blades = [e032, e013, e021, e123] }
        /// A rotation about a line through the origin: `cos(a/2) - sin(a/2) e12` turns x
        /// towards y by `a`.
        type Rotor { blades = [s, e23, e31, e12], versor = true, unit = true }
        /// A translation: `1 - (t/2)(tx e01 + ty e02 + tz e03)` moves points by `+t`.
        type Translator { blades = [s, e01, e02, e03], versor = true, unit = true }
        /// A rigid motion: rotor and translator combined.
        type Motor { blades = [s, e23, e31, e12, e01, e02, e03, e0123], versor = true, unit = true }
        sandwich Motor(Point) -> Point;
        sandwich Motor(Plane) -> Plane;
        sandwich Translator(Point) -> Point;
        sandwich Rotor(Point) -> Point;
    }
}

use pga::{Motor, Plane, Point, Rotor, Sandwich, Translator};

/// The point at `(x, y, z)`.
fn point(x: f64, y: f64, z: f64) -> Point {
    Point::new(x, y, z, 1.0)
}

/// The coordinates of a point (dividing by its weight).
fn coords(p: Point) -> [f64; 3] {
    [p.e032 / p.e123, p.e013 / p.e123, p.e021 / p.e123]
}

/// The translator that moves points by `+t`.
fn translator(t: [f64; 3]) -> Translator {
    Translator::new(1.0, -0.5 * t[0], -0.5 * t[1], -0.5 * t[2])
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

fn main() {
    // The convention, shown: `1 + 0.5 e01` takes the origin to x = -1.
    let origin = point(0.0, 0.0, 0.0);
    let moved = Translator::new(1.0, 0.5, 0.0, 0.0).sandwich(origin);
    println!("(1 + 0.5 e01) moves the origin to {:?}", coords(moved));
    assert!(dist(coords(moved), [-1.0, 0.0, 0.0]) < 1e-15);

    // So a translation by +t is `1 - t/2 e0t`.
    let t = [1.0, -2.0, 0.5];
    let p = [0.3, 0.4, -1.2];
    let q = coords(translator(t).sandwich(point(p[0], p[1], p[2])));
    println!("translate {p:?} by {t:?}: {q:?}");
    assert!(dist(q, [1.3, -1.6, -0.7]) < 1e-15);

    // A rotor `cos(a/2) - sin(a/2) e12` turns x towards y by `a`.
    let a = std::f64::consts::FRAC_PI_2;
    let r = Rotor::new((a / 2.0).cos(), 0.0, 0.0, -(a / 2.0).sin());
    let y = coords(r.sandwich(point(1.0, 0.0, 0.0)));
    println!("rotate (1, 0, 0) by 90 degrees with cos - sin e12: {y:?}");
    assert!(dist(y, [0.0, 1.0, 0.0]) < 1e-15);

    // A motor is the product: rotate, then translate (`T * R` applies R first).
    let m: Motor = translator(t) * r;
    let got = coords(m.sandwich(point(p[0], p[1], p[2])));
    let want = [-p[1] + t[0], p[0] + t[1], p[2] + t[2]];
    println!("motor on {p:?}: {got:?}");
    assert!(dist(got, want) < 1e-15);

    // Planes move with their points: the plane z = 1 (e3 - e0) through the moved point.
    let plane = Plane::new(-1.0, 0.0, 0.0, 1.0);
    let moved_plane = m.sandwich(plane);
    let on = coords(m.sandwich(point(5.0, -7.0, 1.0)));
    let [d, a1, b1, c1] = moved_plane.to_array();
    let residual = a1 * on[0] + b1 * on[1] + c1 * on[2] + d;
    println!("a point of the moved plane satisfies its equation to {residual:.1e}");
    assert!(residual.abs() < 1e-14);

    // Every generated product agrees with the generic multivector of `ga-codegen`.
    let x = point(p[0], p[1], p[2]);
    let slow = m
        .to_multivector()
        .gp(&x.to_multivector())
        .gp(&m.rev().to_multivector());
    let diff = m.sandwich(x).to_multivector().max_diff(&slow);
    println!("fused sandwich vs M * X * ~M on the generic multivector: {diff:.1e}");
    assert!(diff < 1e-15);
    println!("ok");
}
