//! Compile-fail tests: spec errors in `algebra!` are reported at the offending token with a
//! message naming the type and the blade (hostile specs in `ui/hostile_specs.rs`: an
//! overflowing metric entry, colliding basis names, a reserved type name). Regenerate the
//! expected output with `TRYBUILD=overwrite cargo test -p ga-macros --test ui` and read it
//! before committing.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
