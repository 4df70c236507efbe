//! `bytemuck` support (feature `bytemuck`): the generated types are `#[repr(C)]` structs of
//! one float type only (no padding, every bit pattern valid), so they are `Pod`.

macro_rules! pod {
    ($m:ident: $($t:ident),*) => {$(
        // SAFETY: `#[repr(C)]`, `Copy`, all fields the same float type: no padding, no invalid
        // bit patterns, zero is a valid value.
        unsafe impl bytemuck::Zeroable for crate::$m::$t {}
        // SAFETY: as above.
        unsafe impl bytemuck::Pod for crate::$m::$t {}
        const _: () = assert!(
            core::mem::size_of::<crate::$m::$t>()
                == crate::$m::$t::LEN * core::mem::size_of::<crate::$m::Scalar>()
        );
    )*};
}

pod!(f64: Vector, Point, Bivector, Trivector, Quadvector, Pseudoscalar, Rotor, Translator,
    Dilator, Motor, ScaledMotor, Even, Odd, Mv);
pod!(f32: Vector, Point, Bivector, Trivector, Quadvector, Pseudoscalar, Rotor, Translator,
    Dilator, Motor, ScaledMotor, Even, Odd, Mv);
