//! Motors against matrices: the same rigid motions as `cga` motors and as glam matrices,
//! applied to the same points, composed, inverted and interpolated, and checked to agree.
//!
//! ```text
//! cargo run -p cga --example motors_and_matrices
//! ```
//!
//! Every number printed is also asserted, so this is a check as well as a demo.

use cga::glam::{DAffine3, DMat4, DQuat, DVec3};
use cga::{Motor, Point, Sandwich};

/// A small deterministic generator (no `rand` needed): uniform in [-1, 1).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
    fn vec3(&mut self) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next())
    }
    fn quat(&mut self) -> DQuat {
        let axis = loop {
            let v = self.vec3();
            if v.length() > 0.1 {
                break v.normalize();
            }
        };
        DQuat::from_axis_angle(axis, 3.0 * self.next())
    }
}

/// The largest entry of `a - b`.
fn gap(a: DMat4, b: DMat4) -> f64 {
    (a - b)
        .to_cols_array()
        .iter()
        .fold(0.0, |m, x| m.max(x.abs()))
}

fn main() {
    let mut rng = Lcg(46);
    let points: Vec<DVec3> = (0..100).map(|_| 10.0 * rng.vec3()).collect();

    // 1. One motion, four ways: the motor's own transform, its fused sandwich on a conformal
    //    point, its 4x5 matrix form (the sandwich's outermorphism), and glam's affine matrix.
    let mut worst = [0.0f64; 4];
    for _ in 0..50 {
        let (q, t) = (rng.quat(), 5.0 * rng.vec3());
        let m = Motor::from_rotation_translation(q, t);
        let affine = DAffine3::from_rotation_translation(q, t);
        let matrix = m.point_matrix();
        for &x in &points {
            let want = affine.transform_point3(x);
            let by_motor = m.transform_point(x);
            let by_sandwich = m.sandwich(Point::from_vec3(x)).to_vec3();
            let by_matrix = matrix.apply(Point::from_vec3(x)).to_vec3();
            let by_mat4 = m.to_mat4().transform_point3(x);
            for (w, got) in worst
                .iter_mut()
                .zip([by_motor, by_sandwich, by_matrix, by_mat4])
            {
                *w = w.max((got - want).length() / (1.0 + want.length()));
            }
        }
    }
    println!("motor vs glam affine, 50 motions x 100 points (relative error):");
    for (name, w) in [
        "transform_point",
        "sandwich",
        "point_matrix().apply",
        "to_mat4()",
    ]
    .iter()
    .zip(worst)
    {
        println!("  {name:<22} {w:.1e}");
        assert!(w < 1e-14, "{name} disagrees with glam by {w:e}");
    }

    // 2. Composition is the geometric product, in matrix order: `b * a` applies `a` first.
    let (a, b) = (
        Motor::from_rotation_translation(rng.quat(), rng.vec3()),
        Motor::from_rotation_translation(rng.quat(), rng.vec3()),
    );
    let composed: DMat4 = b.to_mat4() * a.to_mat4();
    let err = gap((b * a).to_mat4(), composed);
    println!("(b * a).to_mat4() vs b.to_mat4() * a.to_mat4(): {err:.1e}");
    assert!(err < 1e-14);
    // The inverse motion is the reverse.
    let err = gap(a.inverse_motion().to_mat4(), a.to_mat4().inverse());
    println!("a.inverse_motion() vs the inverse matrix:        {err:.1e}");
    assert!(err < 1e-14);
    // And back: a rigid matrix to a motor.
    let back = Motor::try_from_mat4(composed).expect("a rigid matrix");
    let err = gap(back.to_mat4(), composed);
    println!("Motor::try_from_mat4 round trip:                  {err:.1e}");
    assert!(err < 1e-14);

    // 3. Interpolation: half of a screw motion is half the angle and half the translation
    //    along the axis, which glam's slerp and lerp give for a motion along its own axis.
    let axis = DVec3::new(1.0, 2.0, 2.0) / 3.0;
    let screw = Motor::from_rotation_translation(DQuat::from_axis_angle(axis, 2.0), 4.0 * axis);
    let half = Motor::interpolate(Motor::IDENTITY, screw, 0.5);
    let want = DAffine3::from_rotation_translation(DQuat::from_axis_angle(axis, 1.0), 2.0 * axis);
    let err = gap(half.to_mat4(), DMat4::from(want));
    println!("Motor::interpolate(1, screw, 0.5) vs half the screw: {err:.1e}");
    assert!(err < 1e-14);

    // 4. `blend_log` (the weighted mean of logarithms) equals `interpolate` only for motors
    //    that commute: two motions about one axis do; a rotation about z and a translation
    //    along x do not, and then the two paths differ.
    let along = |angle: f64, shift: f64| {
        Motor::from_rotation_translation(DQuat::from_axis_angle(axis, angle), shift * axis)
    };
    let (p, q) = (along(0.3, -1.0), along(1.7, 2.5));
    let err = gap(
        Motor::blend_log(&[p, q], &[0.7, 0.3]).to_mat4(),
        Motor::interpolate(p, q, 0.3).to_mat4(),
    );
    println!("commuting motors:     |blend_log - interpolate| = {err:.1e}");
    assert!(err < 1e-14);
    let (p, q) = (
        Motor::from_axis_angle(DVec3::Z, 1.5),
        Motor::from_translation(DVec3::new(3.0, 0.0, 0.0)),
    );
    let apart = gap(
        Motor::blend_log(&[p, q], &[0.5, 0.5]).to_mat4(),
        Motor::interpolate(p, q, 0.5).to_mat4(),
    );
    println!("non-commuting motors: |blend_log - interpolate| = {apart:.2}");
    assert!(apart > 0.1);
    // Both are exact at the keys.
    for (w, key) in [([1.0, 0.0], p), ([0.0, 1.0], q)] {
        let err = gap(Motor::blend_log(&[p, q], &w).to_mat4(), key.to_mat4());
        assert!(err < 1e-14);
    }
    println!("ok");
}
