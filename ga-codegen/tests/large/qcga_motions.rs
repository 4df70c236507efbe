// QCGA versors, intersections and normals (included by `qcga_main.rs` as `mod motions`): the
// translator of `algebras/qcga.toml` on the generated types, rotation rotors (not declared:
// see the spec) on the sparse reference, the paper's intersection of two dual quadrics by
// their outer product, its line-quadric intersection and its normal, each against a closed
// form in plain f64.
use super::*;
use ga_codegen::runtime::sparse::multivector::SparseMultivector;

/// The basis blade `name` of the sparse reference, times `x`.
fn blade(name: &str, x: f64) -> SparseMultivector {
    let alg = qcga::algebra();
    let (b, sign) = alg.parse_blade(name).unwrap();
    SparseMultivector::blade(&alg, b, x * f64::from(sign))
}

fn scalar(x: f64) -> SparseMultivector {
    SparseMultivector::scalar(&qcga::algebra(), x)
}

/// `v x ~v` on the sparse reference.
fn sandwich(v: &SparseMultivector, x: &SparseMultivector) -> SparseMultivector {
    v.gp(x).gp(&v.rev())
}

/// The translator by `t` as the spec derives it: `(1 - e1 w1 / 2)(1 - e2 w2 / 2)(1 - e3 w3 / 2)`
/// with `wj` the derivatives of the points' `ei` monomials along `t`, read into `Translator`.
fn translator([t1, t2, t3]: [f64; 3]) -> Translator {
    let w = |terms: [(&str, f64); 3]| terms.iter().fold(scalar(0.0), |acc, &(n, c)| acc.add_scaled(&blade(n, 1.0), c));
    let factors = [
        ("e1", w([("ei1", t1), ("ei4", t2), ("ei5", t3)])),
        ("e2", w([("ei2", t2), ("ei4", t1), ("ei6", t3)])),
        ("e3", w([("ei3", t3), ("ei5", t1), ("ei6", t2)])),
    ];
    let t = factors.iter().fold(scalar(1.0), |acc, (e, wj)| acc.gp(&scalar(1.0).add_scaled(&blade(e, 1.0).gp(wj), -0.5)));
    let got = Translator::from_multivector(&t);
    assert!(got.to_multivector().max_diff(&t) < 1e-15, "the translator lies in `Translator`");
    assert!(t.gp(&t.rev()).max_diff(&scalar(1.0)) < 1e-12, "T ~T = 1");
    got
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// Points of the ellipsoid `(x - c)^T M (x - c) = 1` (M positive definite) and off it.
fn samples(m: M3, c: [f64; 3]) -> Vec<([f64; 3], f64)> {
    let coeffs = ellipsoid_coeffs(m, c);
    [[0.3, -1.2, 2.0], [1.5, 0.4, -0.7], [-2.0, 0.1, 0.9], [0.0, 2.5, -1.5]]
        .into_iter()
        .map(|p| (p, implicit(coeffs, p)))
        .collect()
}

/// The generated translator moves points to the points of `x + t`, and a dual quadric to
/// one that takes at `x + t` the value the first takes at `x` (the ellipsoid centred at
/// `c + t`); its `e` and `eo` parts are those of that ellipsoid's dual quadric.
pub fn translations(m: M3, centre: [f64; 3]) {
    let t = [0.8, -1.7, 0.45];
    let tr = translator(t);
    let q: Vector = tr.sandwich(dual_quadric(ellipsoid_coeffs(m, centre)));
    for (x, value) in samples(m, centre) {
        let moved: Point = tr.sandwich(point(x));
        assert!(moved.abs_diff_eq(point(add(x, t)), 1e-12), "{moved:?}");
        assert!(close(point(add(x, t)) | q, value, 1.0 + value.abs()), "{x:?}");
        let want = dual_quadric(ellipsoid_coeffs(m, add(centre, t)));
        let parts = |v: Vector| [v.e1, v.e2, v.e3, v.eo1, v.eo2, v.eo3, v.eo4, v.eo5, v.eo6, v.ei1 + v.ei2 + v.ei3];
        for (a, b) in parts(q).into_iter().zip(parts(Vector::from(want))) {
            assert!(close(a, b, 1.0), "{q:?} vs {want:?}");
        }
    }
}

/// The QCGA bivector of the rotation generator `omega` (skew, `x' = omega x`):
/// `1/2 sum omega_ij ej ^ ei` on e1 e2 e3 plus `sum M_ab eia ^ eob`, where `M` is the
/// generator's action on the points' monomials (x^2/2, y^2/2, z^2/2, xy, xz, yz), split into
/// the parts on disjoint basis vectors (they commute, and each has a cheap exponential).
fn rotation_parts(o: M3) -> Vec<SparseMultivector> {
    #[rustfmt::skip]
    let m = [
        [0.0, 0.0, 0.0, o[0][1], o[0][2], 0.0],
        [0.0, 0.0, 0.0, o[1][0], 0.0, o[1][2]],
        [0.0, 0.0, 0.0, 0.0, o[2][0], o[2][1]],
        [2.0 * o[1][0], 2.0 * o[0][1], 0.0, 0.0, o[1][2], o[0][2]],
        [2.0 * o[2][0], 0.0, 2.0 * o[0][2], o[2][1], 0.0, o[0][1]],
        [0.0, 2.0 * o[2][1], 2.0 * o[1][2], o[2][0], o[1][0], 0.0],
    ];
    let e = ["e1", "e2", "e3"];
    let mut euclid = scalar(0.0);
    for i in 0..3 {
        for j in 0..3 {
            euclid = euclid.add_scaled(&blade(e[j], 1.0).outer(&blade(e[i], 1.0)), 0.5 * o[i][j]);
        }
    }
    // Group the monomial indices the generator connects (union by smallest label).
    let mut label: Vec<usize> = (0..6).collect();
    for _ in 0..6 {
        for a in 0..6 {
            for b in 0..6 {
                if m[a][b] != 0.0 || m[b][a] != 0.0 {
                    let l = label[a].min(label[b]);
                    (label[a], label[b]) = (l, l);
                }
            }
        }
    }
    let mut parts = vec![euclid];
    for l in 0..6 {
        let mut part = scalar(0.0);
        for a in (0..6).filter(|&a| label[a] == l) {
            for b in 0..6 {
                let (ei, eo) = (blade(&format!("ei{}", a + 1), 1.0), blade(&format!("eo{}", b + 1), 1.0));
                part = part.add_scaled(&ei.outer(&eo), m[a][b]);
            }
        }
        if part.max_abs() > 0.0 {
            parts.push(part);
        }
    }
    parts
}

/// `exp(angle omega)` for a generator about a coordinate axis (`omega^3 = -omega`).
fn rotation_matrix(o: M3, angle: f64) -> M3 {
    let o2 = mul(o, o);
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| f64::from(u8::from(r == c)) + angle.sin() * o[r][c] + (1.0 - angle.cos()) * o2[r][c]))
}

/// Rotors in the published basis (on the sparse reference: the spec says why no type holds
/// them): `exp(-angle/2 B)` of the generator's bivector, applied factor by factor, moves a
/// point to the point of the rotated coordinates and the dual quadric exactly to the dual
/// quadric of the rotated ellipsoid (`M' = R M R^T`, centre `R c`), for a rotation about e1
/// followed by one about e3.
pub fn rotations(m: M3, centre: [f64; 3]) {
    let about_x = [[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
    let about_z = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]];
    let (ax, az) = (0.9, -0.6);
    let mut rotors = Vec::new();
    for (o, angle) in [(about_x, ax), (about_z, az)] {
        let parts = rotation_parts(o);
        assert_eq!(parts.len(), 3, "e_ij, and two blocks of monomials");
        rotors.extend(parts.iter().map(|b| b.scale(-angle / 2.0).exp()));
    }
    assert!(rotors.iter().all(|r| r.gp(&r.rev()).max_diff(&scalar(1.0)) < 1e-12), "R ~R = 1");
    let rotate = |x: SparseMultivector| rotors.iter().fold(x, |acc, r| sandwich(r, &acc));
    let r = mul(rotation_matrix(about_z, az), rotation_matrix(about_x, ax));
    for (x, _) in samples(m, centre) {
        let moved = rotate(point(x).to_multivector());
        let want = point(apply(r, x)).to_multivector();
        assert!(moved.max_diff(&want) < 1e-12, "{x:?}: {}", moved.max_diff(&want));
    }
    let q = rotate(dual_quadric(ellipsoid_coeffs(m, centre)).to_multivector());
    let want = dual_quadric(ellipsoid_coeffs(mul(mul(r, m), transpose(r)), apply(r, centre)));
    assert!(q.max_diff(&want.to_multivector()) < 1e-12, "{q:?} vs {want:?}");
    // A rotation about the wrong axis does not give that quadric.
    let wrong = dual_quadric(ellipsoid_coeffs(mul(mul(transpose(r), m), r), apply(transpose(r), centre)));
    assert!(q.max_diff(&wrong.to_multivector()) > 1e-3);
}

/// Two unit vectors orthogonal to `d` and to each other.
fn normals_to(d: [f64; 3]) -> [[f64; 3]; 2] {
    let cross = |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let unit = |a: [f64; 3]| {
        let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        a.map(|x| x / n)
    };
    let n1 = unit(cross(d, [0.3, 1.0, -0.2]));
    [n1, unit(cross(d, n1))]
}

/// The dual plane `n . x = n . p` (a dual quadric with only linear terms).
fn plane(n: [f64; 3], p: [f64; 3]) -> DualQuadric {
    dual_quadric([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, n[0], n[1], n[2], -(n[0] * p[0] + n[1] * p[1] + n[2] * p[2])])
}

/// The paper's intersections: `x | (Q1 ^ Q2)` is zero exactly on the points of both quadrics
/// (a sphere and a cylinder meeting in two circles); a line meets a quadric where the
/// paper's quadratic in the line parameter vanishes (against the same quadratic from the
/// implicit coefficients), and those points, and no other point of the line, satisfy
/// `x | (Q ^ pi1 ^ pi2)` = 0 for two planes through the line; the normal read from `x ^ Q`
/// is the gradient `2 M (x - c)`.
pub fn intersections(m: M3, centre: [f64; 3]) {
    let sphere = dual_quadric([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -4.0]);
    let cylinder = dual_quadric([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -3.0]);
    let curve: Bivector = sphere ^ cylinder;
    let s3 = 3f64.sqrt();
    for (u, z) in [(0.4, 1.0), (2.0, -1.0), (4.4, 1.0), (5.9, -1.0)] {
        let on_both: Vector = point([s3 * f64::cos(u), s3 * f64::sin(u), z]) | curve;
        assert!(on_both.abs_diff_eq(Vector::default(), 1e-12), "{on_both:?}");
    }
    for p in [[0.0, 0.0, 2.0], [2.0, 0.0, 0.0], [s3, 0.0, 0.5], [1.0, 1.0, 1.0]] {
        let x = point(p);
        let got: Vector = x | curve;
        let want = Vector::from(cylinder) * (x | sphere) - Vector::from(sphere) * (x | cylinder);
        assert!(got.abs_diff_eq(want, 1e-12), "{got:?} vs {want:?}");
        assert!(got.to_multivector().max_abs() > 0.1, "{p:?} is on one quadric at most");
    }

    let q = dual_quadric(ellipsoid_coeffs(m, centre));
    let (p, d) = (add(centre, [0.1, -0.2, 0.05]), [0.6, 0.0, 0.8]);
    // The paper's quadratic a s^2 + b s + c from the dual quadric's coefficients.
    let a = -0.5 * (d[0] * d[0] * q.eo1 + d[1] * d[1] * q.eo2 + d[2] * d[2] * q.eo3) - (d[0] * d[1] * q.eo4 + d[0] * d[2] * q.eo5 + d[1] * d[2] * q.eo6);
    let b = -(d[0] * p[0] * q.eo1 + d[1] * p[1] * q.eo2 + d[2] * p[2] * q.eo3)
        - ((d[0] * p[1] + d[1] * p[0]) * q.eo4 + (d[0] * p[2] + d[2] * p[0]) * q.eo5 + (d[1] * p[2] + d[2] * p[1]) * q.eo6)
        + (d[0] * q.e1 + d[1] * q.e2 + d[2] * q.e3);
    let c = point(p) | q;
    // The same from (p + s d - c)^T M (p + s d - c) - 1.
    let md = apply(m, d);
    let pc = [p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]];
    let dot = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let (a0, b0, c0) = (dot(d, md), 2.0 * dot(pc, md), dot(pc, apply(m, pc)) - 1.0);
    assert!(close(a, a0, 1.0) && close(b, b0, 1.0) && close(c, c0, 1.0), "{a} {b} {c} vs {a0} {b0} {c0}");
    let disc = (b0 * b0 - 4.0 * a0 * c0).sqrt();
    assert!(disc > 0.1, "the line crosses the ellipsoid");
    let [n1, n2] = normals_to(d);
    let line_quadric = q.to_multivector().outer(&plane(n1, p).to_multivector()).outer(&plane(n2, p).to_multivector());
    let along = |s: f64| add(p, d.map(|x| x * s));
    for s in [(-b0 + disc) / (2.0 * a0), (-b0 - disc) / (2.0 * a0)] {
        let x = point(along(s));
        assert!((x | q).abs() < 1e-12, "x . Q = {}", x | q);
        assert!(x.to_multivector().left_contraction(&line_quadric).max_abs() < 1e-12);
        // The paper's normal: n1 = -(e1o1 + e2o4 + e3o5) of x ^ Q, and likewise.
        let n: Bivector = x ^ q;
        let normal = [-(n.e1o1 + n.e2o4 + n.e3o5), -(n.e2o2 + n.e1o4 + n.e3o6), -(n.e3o3 + n.e1o5 + n.e2o6)];
        let xc = [along(s)[0] - centre[0], along(s)[1] - centre[1], along(s)[2] - centre[2]];
        let gradient = apply(m, xc).map(|g| 2.0 * g);
        for (got, want) in normal.into_iter().zip(gradient) {
            assert!(close(got, want, 1.0), "{normal:?} vs {gradient:?}");
        }
    }
    for s in [0.0, 0.37] {
        let off = point(along(s)).to_multivector().left_contraction(&line_quadric);
        assert!(off.max_abs() > 1e-3, "{s}: a point of the line inside the ellipsoid");
    }
}
