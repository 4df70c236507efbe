//! The optional `serde` and `bytemuck` features.

#[cfg(feature = "serde")]
#[test]
fn serde_round_trip() {
    let m =
        cga::Motor::from_rotation_translation(glam::DQuat::from_rotation_x(0.3), glam::DVec3::X);
    let s = serde_json::to_string(&m).unwrap();
    assert_eq!(serde_json::from_str::<cga::Motor>(&s).unwrap(), m);
    let p = cga::Plane::from_normal_distance(glam::DVec3::Z, 2.0);
    let s = serde_json::to_string(&p).unwrap();
    assert_eq!(serde_json::from_str::<cga::Plane>(&s).unwrap(), p);
    let d = cga::f32::DualQuat::from(cga::f32::Motor::IDENTITY);
    let s = serde_json::to_string(&d).unwrap();
    assert_eq!(serde_json::from_str::<cga::f32::DualQuat>(&s).unwrap(), d);
}

#[cfg(feature = "bytemuck")]
#[test]
fn pod_cast() {
    let ms = [cga::f32::Motor::IDENTITY; 3];
    let bytes: &[u8] = bytemuck::cast_slice(&ms);
    assert_eq!(bytes.len(), 3 * 8 * 4);
    let back: &[cga::f32::Motor] = bytemuck::cast_slice(bytes);
    assert_eq!(back, &ms);
}
