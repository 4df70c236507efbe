//! `serde` support (feature `serde`) for the hand-written dual quaternion, as
//! `[real xyzw, dual xyzw]`. The generated types get theirs from the generator (each
//! serialises as its coefficient array in storage order: `Motor` as 8 numbers
//! `s, e12, e13, e23, e1i, e2i, e3i, e123i`).

macro_rules! serde_dual_quat {
    ($m:ident, $s:ty, $quat:ty) => {
        impl serde::Serialize for crate::$m::DualQuat {
            fn serialize<Z: serde::Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
                [self.real.to_array(), self.dual.to_array()].serialize(z)
            }
        }
        impl<'de> serde::Deserialize<'de> for crate::$m::DualQuat {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let [r, u] = <[[$s; 4]; 2]>::deserialize(d)?;
                Ok(crate::$m::DualQuat {
                    real: <$quat>::from_array(r),
                    dual: <$quat>::from_array(u),
                })
            }
        }
    };
}

serde_dual_quat!(f64, f64, glam::DQuat);
serde_dual_quat!(f32, f32, glam::Quat);
