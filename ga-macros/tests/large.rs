//! `algebra!(path = ..)` on the large specs: double conformal G(8,2) (10 basis vectors) and
//! quadric conformal G(9,6) (15) expand (no general multivector, the sparse reference), their
//! products agree with the sparse reference, and the papers' quadrics hold with the macro's
//! types; the mother algebra G(4,4) (8, all null) moves points as its translator's matrix
//! does, by the macro's types and by the generic multivector.

mod dcga {
    ga_macros::algebra!(path = "../algebras/dcga.toml");
}

mod qcga {
    ga_macros::algebra!(path = "../algebras/qcga.toml");
}

mod mother {
    ga_macros::algebra!(path = "../algebras/mother.toml");
}

use dcga::{CgaPoint1, CgaPoint2, Point, Rotor, Sandwich as _, Surface};

/// The CGA points of `x` in DCGA's two copies.
fn cga_points(x: [f64; 3]) -> (CgaPoint1, CgaPoint2) {
    let h = 0.5 * x.iter().map(|v| v * v).sum::<f64>();
    let p1 = CgaPoint1 {
        e1: x[0],
        e2: x[1],
        e3: x[2],
        ei1: h,
    };
    let p2 = CgaPoint2 {
        e4: x[0],
        e5: x[1],
        e6: x[2],
        ei2: h,
    };
    (p1, p2)
}

/// The DCGA point `P1 ^ P2` of `x`.
fn point(x: [f64; 3]) -> Point {
    let (p1, p2) = cga_points(x);
    p1 ^ p2
}

#[test]
fn dcga_from_the_macro_agrees_with_the_sparse_reference() {
    assert!(
        !dcga::SKIPPED.is_empty(),
        "no general multivector above 6 basis vectors"
    );
    let x = [0.3, -1.1, 2.0];
    let (p1, p2) = cga_points(x);
    let slow = p1.to_multivector().outer(&p2.to_multivector());
    assert!((p1 ^ p2).to_multivector().max_diff(&slow) < 1e-12);
    let (c, s) = (0.35f64.cos(), 0.35f64.sin());
    let r = Rotor {
        s: c,
        e12: -s,
        ..Rotor::default()
    } * Rotor {
        s: c,
        e45: -s,
        ..Rotor::default()
    };
    let p = point(x);
    let (rm, pm) = (r.to_multivector(), p.to_multivector());
    let slow = rm.gp(&pm).gp(&rm.rev());
    assert!(r.sandwich(p).to_multivector().max_diff(&slow) < 1e-12);
}

#[test]
fn a_point_on_an_ellipsoid_satisfies_its_inner_product_equation() {
    let axes = [2.0, 3.0, 0.5];
    // x^2/a^2 + y^2/b^2 + z^2/c^2 - 1 = T_x^2 / a^2 + ... - T_1, T_x^2 = -e14, T_1 = -ei1 ^ ei2.
    let e = Surface {
        e14: -1.0 / (axes[0] * axes[0]),
        e25: -1.0 / (axes[1] * axes[1]),
        e36: -1.0 / (axes[2] * axes[2]),
        ei1i2: 1.0,
        ..Surface::default()
    };
    let implicit = |x: [f64; 3]| -> f64 {
        x.iter()
            .zip(axes)
            .map(|(v, a)| v * v / (a * a))
            .sum::<f64>()
            - 1.0
    };
    for (u, v) in [(0.3f64, 0.4f64), (1.9, 2.2), (4.0, 1.0)] {
        let on = [
            axes[0] * u.cos() * v.sin(),
            axes[1] * u.sin() * v.sin(),
            axes[2] * v.cos(),
        ];
        assert!((point(on) | e).abs() < 1e-12, "{on:?}");
        let off = [on[0] * 1.3, on[1] - 0.2, on[2] + 0.1];
        assert!(((point(off) | e) - implicit(off)).abs() < 1e-12 * (1.0 + implicit(off).abs()));
    }
}

/// QCGA: the dual quadric of `a x^2 + b y^2 + c z^2 + d xy + e xz + f yz + g x + h y + i z + j`
/// (Breuils et al.) against a point is that polynomial.
#[test]
fn a_qcga_point_against_a_dual_quadric_is_its_implicit_polynomial() {
    use qcga::{DualQuadric, Point};
    let point = |[x, y, z]: [f64; 3]| Point {
        e1: x,
        e2: y,
        e3: z,
        ei1: 0.5 * x * x,
        ei2: 0.5 * y * y,
        ei3: 0.5 * z * z,
        ei4: x * y,
        ei5: x * z,
        ei6: y * z,
    };
    let k = [1.5, -0.7, 2.0, 0.3, -1.1, 0.4, 0.9, -2.2, 0.6, -1.3];
    let [a, b, c, d, e, f, g, h, i, j] = k;
    let q = DualQuadric {
        e1: g,
        e2: h,
        e3: i,
        eo1: -2.0 * a,
        eo2: -2.0 * b,
        eo3: -2.0 * c,
        eo4: -d,
        eo5: -e,
        eo6: -f,
        ei1: -j / 3.0,
        ei2: -j / 3.0,
        ei3: -j / 3.0,
    };
    for x in [[0.3, -1.1, 2.0], [1.0, 0.0, -0.5], [-2.0, 0.7, 0.1]] {
        let [px, py, pz] = x;
        let want = a * px * px
            + b * py * py
            + c * pz * pz
            + d * px * py
            + e * px * pz
            + f * py * pz
            + g * px
            + h * py
            + i * pz
            + j;
        let got = point(x) | q;
        assert!(
            (got - want).abs() < 1e-12 * (1.0 + want.abs()),
            "{x:?}: {got} vs {want}"
        );
        let slow = point(x)
            .to_multivector()
            .left_contraction(&q.to_multivector())
            .get(0);
        assert!((got - slow).abs() < 1e-12 * (1.0 + want.abs()));
    }
}

#[test]
fn mother_algebra_from_the_macro_translates_points() {
    use mother::{Point, Sandwich as _, Translator};
    let t = [0.4, -1.2, 2.5];
    let tr = Translator {
        s: 1.0,
        e1dw: t[0],
        e2dw: t[1],
        e3dw: t[2],
    };
    let x = [0.3, -0.7, 1.9];
    let p = Point {
        ew: 1.0,
        e1: x[0],
        e2: x[1],
        e3: x[2],
    };
    let q = tr.sandwich(p);
    let got = [q.ew, q.e1, q.e2, q.e3];
    let want = [1.0, x[0] + t[0], x[1] + t[1], x[2] + t[2]];
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-12, "{got:?} vs {want:?}");
    }
    let v = tr.to_multivector();
    let slow = v.gp(&p.to_multivector()).gp(&v.rev());
    assert!(q.to_multivector().max_diff(&slow) < 1e-12);
}
