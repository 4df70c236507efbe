//! Cross-crate integration tests (in `tests/tests/`) and the generated algebras they check.
//!
//! Every spec in `algebras/` is generated here (f64 and f32) together with a check harness that compares
//! each generated product and method with the generic [`ga_codegen::Multivector`].

macro_rules! algebra_module {
    ($name:ident, $file:literal, $checks:literal, $doc:literal) => {
        #[doc = $doc]
        #[allow(unused_variables, clippy::all, clippy::pedantic, missing_docs)]
        pub mod $name {
            include!(concat!(env!("OUT_DIR"), "/", $file));
            /// The check harness for this algebra.
            #[allow(unused_variables, clippy::all, clippy::pedantic, missing_docs)]
            pub mod checks {
                include!(concat!(env!("OUT_DIR"), "/", $checks));
            }
        }
    };
}

algebra_module!(
    cga,
    "cga.rs",
    "cga_checks.rs",
    "G(4,1) from `algebras/cga.toml`."
);
algebra_module!(
    cga_f32,
    "cga_f32.rs",
    "cga_f32_checks.rs",
    "G(4,1) from `algebras/cga.toml`, f32 (4-lane products)."
);
algebra_module!(
    pga3d,
    "pga3d.rs",
    "pga3d_checks.rs",
    "G(3,0,1) from `algebras/pga3d.toml`."
);
algebra_module!(g3, "g3.rs", "g3_checks.rs", "G(3) from `algebras/g3.toml`.");
algebra_module!(
    sta,
    "sta.rs",
    "sta_checks.rs",
    "G(1,3) from `algebras/sta.toml`."
);
algebra_module!(
    sig201,
    "sig201.rs",
    "sig201_checks.rs",
    "G(2,0,1) from `--signature 2,0,1`."
);
algebra_module!(
    sig400,
    "sig400.rs",
    "sig400_checks.rs",
    "G(4) from `--signature 4,0,0` (double rotations)."
);
algebra_module!(
    sig400_f32,
    "sig400_f32.rs",
    "sig400_f32_checks.rs",
    "G(4) from `--signature 4,0,0`, f32."
);
algebra_module!(
    sig220,
    "sig220.rs",
    "sig220_checks.rs",
    "G(2,2) from `--signature 2,2,0` (complex squares)."
);
algebra_module!(
    sig220_f32,
    "sig220_f32.rs",
    "sig220_f32_checks.rs",
    "G(2,2) from `--signature 2,2,0`, f32."
);
algebra_module!(
    sig320,
    "sig320.rs",
    "sig320_checks.rs",
    "G(3,2) from `--signature 3,2,0` (complex squares)."
);
algebra_module!(
    pga3d_f32,
    "pga3d_f32.rs",
    "pga3d_f32_checks.rs",
    "G(3,0,1) from `algebras/pga3d.toml`, f32."
);
algebra_module!(
    g3_f32,
    "g3_f32.rs",
    "g3_f32_checks.rs",
    "G(3) from `algebras/g3.toml`, f32."
);
algebra_module!(
    sta_f32,
    "sta_f32.rs",
    "sta_f32_checks.rs",
    "G(1,3) from `algebras/sta.toml`, f32."
);
algebra_module!(
    sig201_f32,
    "sig201_f32.rs",
    "sig201_f32_checks.rs",
    "G(2,0,1) from `--signature 2,0,1`, f32."
);
