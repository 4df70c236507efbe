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

/// Call `$m!` with every type of `algebras/cga.toml` (one list for the tests below).
#[allow(unused_macros)]
macro_rules! every_type {
    ($m:ident) => {
        $m!(
            Vector,
            Point,
            Bivector,
            Trivector,
            Quadvector,
            Pseudoscalar,
            Rotor,
            Translator,
            Dilator,
            Motor,
            ScaledMotor,
            Even,
            Odd,
            Mv
        )
    };
}

/// Every generated type (not only those a hand-written list once named) serialises as its
/// coefficient array in storage order and reads back.
#[cfg(feature = "serde")]
#[test]
fn serde_every_generated_type() {
    fn round_trip<T>(x: T, len: usize)
    where
        T: serde::Serialize + serde::de::DeserializeOwned + PartialEq + std::fmt::Debug,
    {
        let s = serde_json::to_string(&x).unwrap();
        let v: Vec<f64> = serde_json::from_str(&s).unwrap();
        assert_eq!(v.len(), len, "{s}");
        assert_eq!(serde_json::from_str::<T>(&s).unwrap(), x);
    }
    macro_rules! each {
        ($($t:ident),*) => {$(
            let x = cga::$t::from_array(std::array::from_fn(|i| i as f64 + 0.5));
            round_trip(x, cga::$t::LEN);
            let y = cga::f32::$t::from_array(std::array::from_fn(|i| i as f32 - 0.25));
            round_trip(y, cga::f32::$t::LEN);
        )*};
    }
    every_type!(each);
}

/// Every generated type is `Pod`: a slice of any of them casts to bytes and back.
#[cfg(feature = "bytemuck")]
#[test]
fn pod_every_generated_type() {
    macro_rules! each {
        ($($t:ident),*) => {$(
            let xs = [cga::$t::from_array(std::array::from_fn(|i| i as f64)); 2];
            let bytes: &[u8] = bytemuck::cast_slice(&xs);
            assert_eq!(bytes.len(), 2 * cga::$t::LEN * 8);
            assert_eq!(bytemuck::cast_slice::<u8, cga::$t>(bytes), &xs);
            let z: cga::f32::$t = bytemuck::Zeroable::zeroed();
            assert_eq!(z, cga::f32::$t::default());
        )*};
    }
    every_type!(each);
}
