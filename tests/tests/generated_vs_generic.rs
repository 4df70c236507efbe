//! Every generated product, method, sandwich, matrix form and conversion, for every type pair of
//! every algebra (f64, and f32 where the crate generates it), against the slow generic
//! multivector on 200 seeded random inputs.

fn run(name: &str, (count, fails): (usize, Vec<String>)) {
    println!("{name}: {count} comparisons");
    assert!(count > 0, "{name}: no comparisons made");
    assert!(
        fails.is_empty(),
        "{name}: {} failures:\n{}",
        fails.len(),
        fails.join("\n")
    );
}

#[test]
fn cga_generated_matches_generic() {
    run("cga", tests::cga::checks::check_all(200, 1));
}

#[test]
fn cga_f32_generated_matches_generic() {
    run("cga_f32", tests::cga_f32::checks::check_all(200, 6));
}

#[test]
fn pga3d_generated_matches_generic() {
    run("pga3d", tests::pga3d::checks::check_all(200, 2));
}

#[test]
fn pga3d_f32_generated_matches_generic() {
    run("pga3d_f32", tests::pga3d_f32::checks::check_all(200, 9));
}

#[test]
fn g3_f32_generated_matches_generic() {
    run("g3_f32", tests::g3_f32::checks::check_all(200, 10));
}

#[test]
fn g3_generated_matches_generic() {
    run("g3", tests::g3::checks::check_all(200, 3));
}

#[test]
fn sta_generated_matches_generic() {
    run("sta", tests::sta::checks::check_all(200, 4));
}

#[test]
fn signature_201_generated_matches_generic() {
    run("sig201", tests::sig201::checks::check_all(200, 5));
}

#[test]
fn signature_400_generated_matches_generic() {
    run("sig400", tests::sig400::checks::check_all(200, 6));
}

#[test]
fn signature_220_generated_matches_generic() {
    run("sig220", tests::sig220::checks::check_all(200, 7));
}

#[test]
fn signature_320_generated_matches_generic() {
    run("sig320", tests::sig320::checks::check_all(200, 8));
}

#[test]
fn sta_f32_generated_matches_generic() {
    run("sta_f32", tests::sta_f32::checks::check_all(200, 11));
}

#[test]
fn sig201_f32_generated_matches_generic() {
    run("sig201_f32", tests::sig201_f32::checks::check_all(200, 12));
}

#[test]
fn sig400_f32_generated_matches_generic() {
    run("sig400_f32", tests::sig400_f32::checks::check_all(200, 13));
}

#[test]
fn sig220_f32_generated_matches_generic() {
    run("sig220_f32", tests::sig220_f32::checks::check_all(200, 14));
}

#[test]
fn skew_metric_generated_matches_generic() {
    run("skew", tests::skew::checks::check_all(200, 16));
}

#[test]
fn skew_metric_f32_generated_matches_generic() {
    run("skew_f32", tests::skew_f32::checks::check_all(200, 17));
}
