//! Hostile rig inputs (issue 20): non-finite times, frame counts past the budget, openings
//! and drills far beyond the model, scalpels that return, missing accessors and frame
//! sequences over an input exit with code 2 before any work, or succeed, never a panic.

use super::refusals::refused;
use super::{read_obj, run, stderr, Scene};
use crate::common;

/// The shared data folder and CesiumMan's path in it (`None`: skipped, see `common`).
pub(super) fn cesium_man() -> Option<(std::path::PathBuf, String)> {
    let data = common::data_dir()?;
    let man = data
        .join("gltf/CesiumMan.glb")
        .to_string_lossy()
        .into_owned();
    Some((data, man))
}

/// CesiumMan (see `cesium_man`), a scratch scene named `name` and its output `o.obj`.
fn rig_scene(name: &str) -> Option<(std::path::PathBuf, String, Scene, String)> {
    let (data, man) = cesium_man()?;
    let s = Scene::new(name);
    let out = s.p("o.obj");
    Some((data, man, s, out))
}

/// Issue 20's reproducers on the shared rigs: `--time nan` for every tool and frame counts
/// past the budget (files or work) exit 2 before any work.
#[test]
fn non_finite_times_and_huge_frame_counts_on_rigs_are_refused() {
    let Some((data, man, s, out)) = rig_scene("rigs-times") else {
        return;
    };
    std::fs::write(s.p("edit.json"), "{}").unwrap();
    let edit = format!("0={}", s.p("edit.json"));
    refused(&["skin", &man, "--time", "nan", "-o", &out], "finite", &out);
    // A file per frame: a 10-vertex rig kept vertices x frames under the budget, and a million
    // in-betweens (or 100,000 frames) ran past 20 s writing files. Each file counts now.
    let simple_path = data.join("gltf/SimpleSkin.gltf");
    let simple_path = simple_path.to_string_lossy().into_owned();
    refused(
        &["skin", &simple_path, "--in-betweens", "1000000", "-o", &out],
        "--in-betweens: 1000000 files",
        &out,
    );
    refused(
        &["skin", &simple_path, "--range", "0:1:100000", "-o", &out],
        "--range: 100000 files",
        &out,
    );
    for tool in [
        vec!["cut", &man, "--plane", "0,0,1,1"],
        vec![
            "drill", &man, "--tip", "0,0,0", "--end", "0,0,1", "--radius", "0.1",
        ],
        vec![
            "tear",
            &man,
            "--scalpel",
            "0.3,0,1.05:0,0,1.05",
            "--scalpel",
            "0.3,0.03,1.05:0,0.03,1.05",
        ],
    ] {
        let mut args = tool.clone();
        args.extend(["--time", "nan", "-o", &out]);
        refused(&args, "finite", &out);
    }
    let args = [
        "skin",
        &man,
        "--edit",
        &edit,
        "--in-betweens=18446744073709551615",
        "-o",
        &out,
    ];
    refused(&args, "--in-betweens", &out);
    refused(
        &["skin", &man, "--range", "0:1:100000", "-o", &out],
        "--max-work",
        &out,
    );
}

/// An opening or a drill far beyond the model is refused; a scalpel that returns to an
/// earlier blade does not panic.
#[test]
fn far_openings_and_drills_are_refused_and_a_returning_scalpel_does_not_panic() {
    let Some((_, man, _s, out)) = rig_scene("rigs-far") else {
        return;
    };
    let (a, b) = ("0.3,0,1.05:0,0,1.05", "0.3,0.03,1.05:0,0.03,1.05");
    let args = [
        "tear",
        &man,
        "--scalpel",
        a,
        "--scalpel",
        b,
        "--open",
        "1e308",
        "-o",
        &out,
    ];
    refused(&args, "model's size", &out);
    let args = [
        "drill", &man, "--tip", "0,0,-10", "--end", "0,0,10", "--radius", "100", "-o", &out,
    ];
    refused(&args, "whole mesh", &out);

    // A scalpel that comes back to an earlier blade: no panic; a finite result or a message.
    let o = run(&[
        "tear",
        &man,
        "--scalpel",
        a,
        "--scalpel",
        b,
        "--scalpel",
        a,
        "-o",
        &out,
        "--quiet",
    ]);
    let err = stderr(&o);
    assert!(
        matches!(o.status.code(), Some(0 | 2)) && !err.contains("panicked"),
        "{err}"
    );
    if o.status.success() {
        let m = read_obj(&out);
        assert!(m.positions.iter().all(|p| p.is_finite()));
        std::fs::remove_file(&out).unwrap();
    }
}

/// An ordinary straight 4-blade scalpel along libigl's arm: a finite, opened tear.
#[test]
fn a_straight_scalpel_along_libigls_arm_tears_finitely() {
    let Some((data, _, _s, out)) = rig_scene("rigs-arm") else {
        return;
    };
    let libigl = data.join("meshes/libigl");
    let lib = |n: &str| libigl.join(n).to_string_lossy().into_owned();
    let (arm, tgf, dmat) = (lib("arm.obj"), lib("arm.tgf"), lib("arm-weights.dmat"));
    let mut args = vec![
        "tear".to_string(),
        arm,
        "--skeleton".into(),
        tgf,
        "--weights".into(),
        dmat,
    ];
    for (x, y) in [(-0.6, 0.215), (-0.3, 0.227), (0.0, 0.183), (0.3, 0.097)] {
        args.push("--scalpel".into());
        args.push(format!("{x},{y},0.6:{x},{y},-0.03"));
    }
    args.extend(["--open", "0.01", "-o", &out, "--quiet"].map(String::from));
    let o = run(&args.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(read_obj(&out).positions.iter().all(|p| p.is_finite()));
    std::fs::remove_file(&out).unwrap();
}

/// A glTF naming a missing accessor, and a frame sequence whose generated names include an
/// input, are refused before anything is written.
#[test]
fn a_missing_accessor_and_a_sequence_over_an_input_are_refused() {
    let Some((data, _, s, out)) = rig_scene("rigs-gltf") else {
        return;
    };
    let simple = data.join("gltf/SimpleSkin.gltf");
    // POSITION names an accessor that does not exist (the gltf crate's validation panicked).
    let mut json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&simple).unwrap()).unwrap();
    json["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 99.into();
    std::fs::write(s.p("bad.gltf"), json.to_string()).unwrap();
    refused(
        &["skin", &s.p("bad.gltf"), "-o", &out],
        "refers to index 99",
        &out,
    );

    // A sequence whose generated names include an input (the edit motor file) is refused
    // before anything is written, and the input is left as it was.
    std::fs::write(s.p("seq_0001.obj"), "{}").unwrap();
    let edit = format!("0={}", s.p("seq_0001.obj"));
    let simple = simple.to_string_lossy().into_owned();
    let seq = s.p("seq.obj");
    let args = [
        "skin", &simple, "--edit", &edit, "--range", "0:1:3", "-o", &seq,
    ];
    refused(
        &args,
        "refusing to overwrite an input",
        &s.p("seq_0000.obj"),
    );
    assert_eq!(std::fs::read_to_string(s.p("seq_0001.obj")).unwrap(), "{}");
}
