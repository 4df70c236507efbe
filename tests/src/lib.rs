//! Cross-crate integration tests (in `tests/tests/`) and the generated algebras they check.
//!
//! Every small spec in `algebras/` (cga, pga3d, g3, sta: the list in `build.rs`) is generated here
//! (f64 and f32) together with a check harness that compares each generated product and method
//! with the generic [`ga_codegen::Multivector`]. The large ones (dcga, qcga, mother) are generated,
//! compiled and checked against the generic reference by `ga-codegen/tests/large_algebras.rs`,
//! whose `every_spec_in_algebras_is_checked_by_a_test` fails for a spec neither place names.

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

/// `|got - want| <= tol (1 + |want|)` coefficientwise, and `got` finite: the comparison of a
/// generated function with the generic multivector that the closed-form tests share; the
/// message shows both.
pub fn close(
    what: &str,
    got: &ga_codegen::Multivector,
    want: &ga_codegen::Multivector,
    tol: f64,
) -> Result<(), String> {
    let ok = got.coeffs().iter().all(|x| x.is_finite())
        && got.max_diff(want) <= tol * (1.0 + want.max_abs());
    if ok {
        Ok(())
    } else {
        Err(format!(
            "{what}: got {:?}\nwant {:?}\n(diff {:e})",
            got.coeffs(),
            want.coeffs(),
            got.max_diff(want)
        ))
    }
}

/// The conditioning of an even versor's logarithm near a half turn of the sum or difference of
/// its two angles: `1 / sin x` for the angle `x` with `cos x = |<v>_0| -+ sqrt(<v>_4^2)` (the
/// double-angle form divides the bivector part by it; at `x = pi` the logarithm is not
/// unique), floored at `1e-8`; `1` where `<v>_4` does not square positive. Measured: on a G(2,2)
/// versor with `cos S = -1 + 8.6e-10`, `exp(log(v))` is `4e-11` off `v`.
pub fn half_turn_conditioning(v: &ga_codegen::Multivector) -> f64 {
    let v4 = v.grade(4);
    let q = v4.gp(&v4).get(0);
    if q <= 0.0 {
        return 1.0;
    }
    let (r0, sig) = (v.get(0).abs(), q.sqrt());
    [r0 - sig, r0 + sig]
        .into_iter()
        .filter(|c| c.abs() <= 1.0)
        .map(|c| 1.0 / (1.0 - c * c).sqrt().max(1e-8))
        .fold(1.0, f64::max)
}
algebra_module!(
    skew,
    "skew.rs",
    "skew_checks.rs",
    "G(3,1) in a non-orthogonal basis (`SKEW` in `build.rs`)."
);
algebra_module!(
    skew_f32,
    "skew_f32.rs",
    "skew_f32_checks.rs",
    "G(3,1) in a non-orthogonal basis, f32."
);
