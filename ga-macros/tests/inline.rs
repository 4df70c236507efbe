//! The inline form of `algebra!`: it behaves exactly like the file form of the same spec (the
//! exact token equality with `ga_codegen::generate` is checked by the crate's unit tests), and
//! doc comments, null metrics, constants and `runtime` work.

mod g3_file {
    ga_macros::algebra!(path = "../algebras/g3.toml");
}

/// `algebras/g3.toml`, written inline.
mod g3_inline {
    ga_macros::algebra! {
        //! The geometric algebra of Euclidean 3-space G(3,0,0).
        name = "g3";
        basis = [e1, e2, e3];
        diagonal = [1, 1, 1];
        type Vector { blades = [e1, e2, e3] }
        /// A bivector, written with e31 (not e13) as is usual for rotations.
        type Bivector { blades = [e23, e31, e12] }
        type Trivector { blades = [e123] }
        /// A rotor (a unit quaternion in disguise).
        type Rotor { blades = [s, e23, e31, e12], versor = true, unit = true }
        /// The odd part: vectors and the pseudoscalar.
        type Odd { blades = [e1, e2, e3, e123], versor = true }
        sandwich Rotor(Vector) -> Vector;
        sandwich Rotor(Bivector) -> Bivector;
        sandwich Odd(Vector);
    }
}

/// The crate documentation's example.
mod g2 {
    ga_macros::algebra! {
        //! The Euclidean plane G(2,0,0).
        name = "g2";
        basis = [e1, e2];
        diagonal = [1, 1];
        type Vector { blades = [e1, e2] }
        /// A rotor: a unit complex number in disguise.
        type Rotor { blades = [s, e12], versor = true, unit = true }
        sandwich Rotor(Vector) -> Vector;
    }
}

/// A conformal line G(2,1) in a null basis, with a normalised point (`eo = 1`, not stored).
mod c1 {
    ga_macros::algebra! {
        name = "c1";
        basis = [eo, e1, ei];
        metric = [[0, 0, -1], [0, 1, 0], [-1, 0, 0]];
        type Point { blades = [eo, e1, ei], constants = { eo = 1 } }
        type Translator { blades = [s, e1i], versor = true, unit = true }
        sandwich Translator(Point) -> Point;
        scalar = f32;
    }
}

/// The runtime crate under another path.
mod rt {
    pub use ga_codegen::{Algebra, Multivector};
}

mod g1 {
    ga_macros::algebra! {
        basis = [e1];
        diagonal = [-1];
        type Vector { blades = [e1] }
        runtime = crate::rt;
    }
}

#[test]
fn inline_and_file_forms_agree() {
    use g3_file::Sandwich as _;
    use g3_inline::Sandwich as _;
    let r = g3_file::Rotor::new(0.5, 0.5, -0.5, 0.5);
    let v = g3_file::Vector::new(1.0, 2.0, 3.0);
    let ri = g3_inline::Rotor::from_array(r.to_array());
    let vi = g3_inline::Vector::from_array(v.to_array());
    assert_eq!((r * v).to_array(), (ri * vi).to_array());
    assert_eq!(r.sandwich(v).to_array(), ri.sandwich(vi).to_array());
    assert_eq!(
        (v ^ g3_file::Vector::new(0.0, 1.0, 0.0)).to_array(),
        (vi ^ g3_inline::Vector::new(0.0, 1.0, 0.0)).to_array()
    );
    assert_eq!(g3_file::BASIS, g3_inline::BASIS);
    assert_eq!(g3_file::METRIC, g3_inline::METRIC);
    assert_eq!(g3_file::Bivector::BLADES, g3_inline::Bivector::BLADES);
}

#[test]
fn doc_example_rotates() {
    use g2::Sandwich;
    let r = g2::Rotor::new(0.6, 0.8); // unit: 0.6^2 + 0.8^2 = 1
    let v: g2::Vector = r.sandwich(g2::Vector::new(1.0, 0.0));
    let slow = r
        .to_multivector()
        .gp(&g2::Vector::new(1.0, 0.0).to_multivector())
        .gp(&r.rev().to_multivector());
    assert!(v.to_multivector().max_diff(&slow) < 1e-12);
    assert!((v.norm() - 1.0).abs() < 1e-12);
}

#[test]
fn null_metric_translator_moves_a_point() {
    use c1::Sandwich;
    // T = 1 - 0.5 t e1 ei translates by t.
    let t = 2.0f32;
    let tr = c1::Translator::new(1.0, -0.5 * t);
    // The point x = 1: x + 0.5 x^2 ei + eo (eo = 1 is not stored).
    let p = c1::Point::new(1.0, 0.5);
    let q: c1::Point = tr.sandwich(p);
    assert!((q.e1 - 3.0).abs() < 1e-6, "{q:?}");
    assert!((q.ei - 4.5).abs() < 1e-6, "{q:?}");
    let slow = tr
        .to_multivector()
        .gp(&p.to_multivector())
        .gp(&tr.rev().to_multivector());
    assert!(q.to_multivector().max_diff(&slow) < 1e-5);
}

#[test]
fn runtime_path_is_honoured() {
    let v = g1::Vector::new(2.0);
    let m: rt::Multivector = v.to_multivector();
    assert_eq!(m.gp(&m).get(0), -4.0);
    assert_eq!(g1::METRIC, [[-1.0]]);
}
