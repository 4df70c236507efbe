//! `serde` support (feature `serde`): every generated type serialises as its coefficient array
//! in storage order (`Motor` as 8 numbers `s, e12, e13, e23, e1i, e2i, e3i, e123i`), the
//! dual quaternion as `[real xyzw, dual xyzw]`.

macro_rules! serde_arrays {
    ($m:ident, $s:ty: $($t:ident = $n:literal),*) => {$(
        impl serde::Serialize for crate::$m::$t {
            fn serialize<Z: serde::Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
                self.to_array().serialize(z)
            }
        }
        impl<'de> serde::Deserialize<'de> for crate::$m::$t {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                <[$s; $n]>::deserialize(d).map(crate::$m::$t::from_array)
            }
        }
    )*
        impl serde::Serialize for crate::$m::DualQuat {
            fn serialize<Z: serde::Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
                [self.real.to_array(), self.dual.to_array()].serialize(z)
            }
        }
        impl<'de> serde::Deserialize<'de> for crate::$m::DualQuat {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let [r, u] = <[[$s; 4]; 2]>::deserialize(d)?;
                Ok(crate::$m::DualQuat {
                    real: <glam_quat!($m)>::from_array(r),
                    dual: <glam_quat!($m)>::from_array(u),
                })
            }
        }
    };
}

macro_rules! glam_quat {
    (f64) => {
        glam::DQuat
    };
    (f32) => {
        glam::Quat
    };
}

serde_arrays!(f64, f64: Vector = 5, Point = 4, Bivector = 10, Trivector = 10, Quadvector = 5,
    Pseudoscalar = 1, Rotor = 4, Translator = 4, Dilator = 2, Motor = 8, ScaledMotor = 12,
    Even = 16, Odd = 16, Mv = 32);
serde_arrays!(f32, f32: Vector = 5, Point = 4, Bivector = 10, Trivector = 10, Quadvector = 5,
    Pseudoscalar = 1, Rotor = 4, Translator = 4, Dilator = 2, Motor = 8, ScaledMotor = 12,
    Even = 16, Odd = 16, Mv = 32);
