//! CGA objects and motors with glam: points, spheres, planes, lines and circles, their
//! meets, and rigid motions applied to them, checked against the same geometry done with
//! glam's vectors.
//!
//! ```text
//! cargo run -p cga --example objects_and_motors
//! ```
//!
//! Every number printed is also asserted, so this is a check as well as a demo.

use cga::glam::{DQuat, DVec3};
use cga::{CgaError, Line, Motor, Plane, Point, Rotor, Sphere, Translator};
use std::f64::consts::FRAC_PI_2;

fn close(a: DVec3, b: DVec3) -> f64 {
    (a - b).length()
}

fn main() -> Result<(), CgaError> {
    // Points are conformal vectors X = x + 0.5 |x|^2 ei + eo; -2 X.Y is the squared distance.
    let (p, q) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 6.0, 3.0));
    let d = Point::from_vec3(p).distance(Point::from_vec3(q));
    println!("distance {p} .. {q}: {d} (glam: {})", p.distance(q));
    assert!((d - p.distance(q)).abs() < 1e-14);

    // Rotors, translators and motors: `t * r` rotates, then translates.
    let r = Rotor::from_axis_angle(DVec3::Z, FRAC_PI_2);
    let t = Translator::from_translation(DVec3::new(0.0, 0.0, 2.0));
    let m: Motor = t * r;
    let x = m.transform_point(DVec3::X);
    println!("rotate X by 90 degrees about z, lift by 2: {x}");
    assert!(close(x, DVec3::new(0.0, 1.0, 2.0)) < 1e-15);
    let glam_way = DQuat::from_rotation_z(FRAC_PI_2) * DVec3::X + DVec3::new(0.0, 0.0, 2.0);
    assert!(close(x, glam_way) < 1e-15);

    // A sphere through four points; its centre and radius, and who is inside.
    let sphere = Sphere::through_points(
        DVec3::new(3.0, 0.0, 0.0),
        DVec3::new(1.0, 2.0, 0.0),
        DVec3::new(1.0, 0.0, 2.0),
        DVec3::new(-1.0, 0.0, 0.0),
    )?;
    println!(
        "sphere: centre {}, radius {} (dual vector {:?})",
        sphere.center(),
        sphere.radius(),
        sphere.dual_vector.to_array()
    );
    assert!(close(sphere.center(), DVec3::new(1.0, 0.0, 0.0)) < 1e-14);
    assert!((sphere.radius() - 2.0).abs() < 1e-14);
    assert!(sphere.contains(DVec3::new(1.0, 1.0, 1.0)) && !sphere.contains(DVec3::splat(3.0)));
    // The direct (outer product) form is the algebraic dual of the dual vector.
    let direct = sphere.direct();
    assert_eq!(direct, sphere.dual_vector.dual());

    // The plane z = 0.5 cuts it in a circle of radius sqrt(4 - 0.25).
    let plane = Plane::from_normal_distance(DVec3::Z, 0.5);
    let circle = sphere.meet_plane(&plane).expect("they meet");
    println!(
        "circle: centre {}, radius {}",
        circle.center(),
        circle.radius()
    );
    assert!(close(circle.center(), DVec3::new(1.0, 0.0, 0.5)) < 1e-14);
    assert!((circle.radius() - 3.75f64.sqrt()).abs() < 1e-14);

    // A line along x through (0, 0, 0.5) lies in the plane; one along z meets it in a point.
    let line = Line::through_points(DVec3::new(2.0, 1.0, -1.0), DVec3::new(2.0, 1.0, 4.0))?;
    let hit = plane.meet_line(&line).expect("not parallel").point();
    println!("line x = 2, y = 1 meets z = 0.5 at {hit}");
    assert!(close(hit, DVec3::new(2.0, 1.0, 0.5)) < 1e-14);
    let pair = sphere.meet_line(&line).expect("meets");
    let (a, b) = pair.points().expect("two real points");
    // (x - 1)^2 + 1 + z^2 = 4 at x = 2: z = +-sqrt(2).
    println!("the same line meets the sphere at {a} and {b}");
    for z in [a.z, b.z] {
        assert!((z.abs() - 2f64.sqrt()).abs() < 1e-14);
    }

    // Move every object by one motor: the objects follow the points.
    let m = Motor::from_rotation_translation(
        DQuat::from_axis_angle(DVec3::new(1.0, 1.0, 0.0).normalize(), 0.8),
        DVec3::new(-2.0, 0.5, 3.0),
    );
    let moved = sphere.transformed(m);
    let err = close(moved.center(), m.transform_point(sphere.center()));
    println!("moved sphere: centre {} (error {err:.1e})", moved.center());
    assert!(err < 1e-14 && (moved.radius() - 2.0).abs() < 1e-14);
    let moved_plane = plane.transformed(m);
    let on_plane = m.transform_point(DVec3::new(7.0, -3.0, 0.5));
    let off = moved_plane.signed_distance(on_plane);
    println!("a moved point of the plane is {off:.1e} from the moved plane");
    assert!(off.abs() < 1e-14);
    let moved_line = line.transformed(m);
    let err = moved_line.distance_to_point(m.transform_point(DVec3::new(2.0, 1.0, 10.0)));
    assert!(err < 1e-13);
    println!("ok");
    Ok(())
}
