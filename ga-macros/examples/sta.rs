//! The spacetime algebra G(1,3) from a spec written inline with `algebra!`: Lorentz rotors
//! (boosts and rotations) acting on four-vectors, checked against the Lorentz transformation
//! in coordinates, the invariant interval, and relativistic velocity addition.
//!
//! ```text
//! cargo run -p ga-macros --example sta
//! ```
//!
//! A crate of your own that calls `algebra!` depends on `ga-macros` and on the runtime,
//! `ga-codegen = { version = "0.1", default-features = false }`.
//!
//! Sign conventions (as in `algebras/sta.toml`): `e0` is time-like (`e0^2 = +1`), `e1, e2, e3`
//! space-like (`-1`), the sandwich is `R v ~R`. `e01` squares to `+1`, so
//! `exp(-(phi/2) e01) = cosh(phi/2) - sinh(phi/2) e01` is the boost with rapidity `phi`
//! towards `+x` (a particle at rest gets velocity `+tanh phi`); the rotor `+sinh` boosts
//! towards `-x`. `e12` squares to `-1`, and because the space-like vectors square to `-1`
//! `cos(a/2) + sin(a/2) e12` turns `e1` towards `+e2` by `a` (in G(3) with `+1` squares
//! the same rotor turns the other way).

mod sta {
    ga_macros::algebra! {
        //! The spacetime algebra G(1,3).
        name = "sta";
        basis = [e0, e1, e2, e3];
        diagonal = [1, -1, -1, -1];
        /// A four-vector `t e0 + x e1 + y e2 + z e3`.
        type Vector { blades = [e0, e1, e2, e3] }
        /// A bivector: boosts `e01, e02, e03` (square +1) and rotations `e23, e31, e12`
        /// (square -1).
        type Bivector { blades = [e01, e02, e03, e23, e31, e12] }
        /// A Lorentz rotor: `cosh(phi/2) - sinh(phi/2) e01` boosts towards +x with rapidity
        /// `phi`; `cos(a/2) + sin(a/2) e12` turns x towards y by `a`.
        type Rotor { blades = [s, e01, e02, e03, e23, e31, e12, e0123], versor = true, unit = true }
        sandwich Rotor(Vector) -> Vector;
        sandwich Rotor(Bivector) -> Bivector;
    }
}

use sta::{Rotor, Sandwich, Vector};

/// The boost with rapidity `phi` towards +x.
fn boost_x(phi: f64) -> Rotor {
    Rotor::new(
        (phi / 2.0).cosh(),
        -(phi / 2.0).sinh(),
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    )
}

/// `t^2 - x^2 - y^2 - z^2`, the vector's square.
fn interval(v: Vector) -> f64 {
    let [t, x, y, z] = v.to_array();
    t * t - x * x - y * y - z * z
}

fn main() {
    // A particle at rest, boosted with rapidity phi: gamma (1, beta, 0, 0).
    let phi = 0.8f64;
    let rest = Vector::new(1.0, 0.0, 0.0, 0.0);
    let moving = boost_x(phi).sandwich(rest);
    let (gamma, beta) = (phi.cosh(), phi.tanh());
    println!(
        "boost e0 by rapidity {phi}: {:?} (gamma {gamma:.6}, velocity {beta:.6})",
        moving.to_array()
    );
    let want = [gamma, gamma * beta, 0.0, 0.0];
    for (g, w) in moving.to_array().iter().zip(want) {
        assert!((g - w).abs() < 1e-15);
    }

    // Any event: the boost is the Lorentz transformation t' = gamma (t + beta x),
    // x' = gamma (x + beta t), and the interval is kept.
    let event = Vector::new(2.0, -0.5, 3.0, 1.0);
    let [t, x, y, z] = event.to_array();
    let got = boost_x(phi).sandwich(event).to_array();
    let lorentz = [gamma * (t + beta * x), gamma * (x + beta * t), y, z];
    let err = got
        .iter()
        .zip(lorentz)
        .map(|(g, w)| (g - w).abs())
        .fold(0.0, f64::max);
    println!("boost of an event vs the Lorentz matrix: {err:.1e}");
    assert!(err < 1e-14);
    let kept = (interval(boost_x(phi).sandwich(event)) - interval(event)).abs();
    println!(
        "interval before and after: {} and the change {kept:.1e}",
        interval(event)
    );
    assert!(kept < 1e-13);

    // Rapidities add, so velocities add relativistically: (u + v) / (1 + u v).
    let (u, v) = (0.6f64, 0.7f64);
    let twice = boost_x(v.atanh()) * boost_x(u.atanh());
    let w = twice.sandwich(rest).to_array();
    let velocity = w[1] / w[0];
    println!("0.6 c then 0.7 c: {velocity:.12} c");
    assert!((velocity - (u + v) / (1.0 + u * v)).abs() < 1e-15);

    // A rotation: `cos(a/2) + sin(a/2) e12` turns e1 towards +e2 here.
    let a = 0.5f64;
    let r = Rotor::new(
        (a / 2.0).cos(),
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        (a / 2.0).sin(),
        0.0,
    );
    let e1 = r.sandwich(Vector::new(0.0, 1.0, 0.0, 0.0)).to_array();
    println!("e1 turned by {a}: {e1:?}");
    assert!((e1[1] - a.cos()).abs() < 1e-15 && (e1[2] - a.sin()).abs() < 1e-15);

    // The generated sandwich agrees with the generic multivector.
    let m = twice * r;
    let slow = m
        .to_multivector()
        .gp(&event.to_multivector())
        .gp(&m.rev().to_multivector());
    let diff = m.sandwich(event).to_multivector().max_diff(&slow);
    println!("fused sandwich vs R * v * ~R on the generic multivector: {diff:.1e}");
    assert!(diff < 1e-13);
    println!("ok");
}
