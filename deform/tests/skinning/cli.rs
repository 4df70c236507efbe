//! `deform skin` end to end.

use crate::common::data_dir;
use crate::gltf_out;
use deform::skinning::read_gltf;
use std::path::Path;
use std::process::{Command, Output};

/// `deform ARGS`.
fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_deform"))
        .args(args)
        .output()
        .unwrap()
}

/// The CLI on glTF: an edit of CesiumMan written to .glb (validated in CI) keeps its animation.
#[test]
fn skin_cli_writes_an_edited_glb_with_its_animation() {
    let Some(dir) = data_dir() else { return };
    let out = gltf_out();
    let edit = out.join("neck.json");
    std::fs::write(
        &edit,
        r#"{"rotate": {"axis": [1, 0, 0], "degrees": 20}, "scale": 1.1}"#,
    )
    .unwrap();
    let man = dir.join("gltf/CesiumMan.glb");
    let glb = out.join("cesium-edited.glb");
    let o = run(&[
        "skin",
        man.to_str().unwrap(),
        "--edit",
        &format!("Skeleton_neck_joint_1={}", edit.display()),
        "-o",
        glb.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let back = read_gltf(&glb).unwrap();
    assert_eq!(back.animations.len(), 1);
}

/// The Fox posed to OBJ keeps its vertex count and its UVs as `vt`.
#[test]
fn skin_cli_writes_the_fox_to_obj_with_its_uvs() {
    let Some(dir) = data_dir() else { return };
    let out = gltf_out();
    let obj = out.join("fox.obj");
    let o = run(&[
        "skin",
        dir.join("gltf/Fox.glb").to_str().unwrap(),
        "--animation",
        "Walk",
        "--time",
        "0.35",
        "--backend",
        "dqs",
        "-o",
        obj.to_str().unwrap(),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let m = deform::mesh::io::read_obj(&obj).unwrap();
    assert_eq!(m.vertex_count(), 1728);
    // The Fox's UVs as `vt` (V flipped for OBJ), one per vertex, used by every face corner;
    // no `vn`, since the Fox has no normals.
    let text = std::fs::read_to_string(&obj).unwrap();
    let vt: Vec<[f32; 2]> = text
        .lines()
        .filter_map(|l| l.strip_prefix("vt "))
        .map(|l| {
            let mut it = l.split(' ').map(|x| x.parse::<f32>().unwrap());
            [it.next().unwrap(), it.next().unwrap()]
        })
        .collect();
    let fox = read_gltf(dir.join("gltf/Fox.glb")).unwrap();
    let uv = fox.look.attribute("TEXCOORD_0").unwrap();
    assert_eq!(vt.len(), uv.vertex_count());
    for (v, t) in vt.iter().enumerate() {
        assert_eq!(*t, [uv.row(v)[0], 1.0 - uv.row(v)[1]], "vertex {v}");
    }
    assert!(!text.contains("\nvn "));
    assert!(text.lines().any(|l| l == "f 1/1 2/2 3/3") || text.contains(" 1/1"));
}

/// libigl's elephant: its OBJ, TGF skeleton, DMAT weights and DMAT animation, as paths.
fn elephant_files(dir: &Path) -> [String; 4] {
    let lib = dir.join("meshes/libigl");
    [
        "elephant.obj",
        "elephant.tgf",
        "elephant-weights.dmat",
        "elephant-anim.dmat",
    ]
    .map(|f| lib.join(f).to_string_lossy().into_owned())
}

/// A libigl rig with its DMAT animation: frame 100.
#[test]
fn skin_cli_poses_a_libigl_rig_at_a_dmat_frame() {
    let Some(dir) = data_dir() else { return };
    let out = gltf_out();
    let [mesh, tgf, weights, anim] = elephant_files(&dir);
    let ele = out.join("elephant-100.obj");
    let o = run(&[
        "skin",
        &mesh,
        "--skeleton",
        &tgf,
        "--weights",
        &weights,
        "--dmat-animation",
        &anim,
        "--time",
        "100",
        "--backend",
        "lbs",
        "-o",
        ele.to_str().unwrap(),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        deform::mesh::io::read_obj(&ele).unwrap().vertex_count(),
        6034
    );
}

/// A frame past the animation's 457 (1e300 read "no animation frame 18446744073709551615"),
/// and a --range whose frames are not indices: exit code 2 naming the flag and the frames
/// there are.
#[test]
fn skin_cli_names_the_dmat_frames_when_a_time_is_not_one() {
    let Some(dir) = data_dir() else { return };
    let files = elephant_files(&dir);
    for (when, flag, frame) in [
        (["--time", "1e300"], "--time", "frame 1.00e300"),
        (["--range", "0:5:3"], "--range", "frame 2.5"),
    ] {
        let mut args = vec![
            "skin",
            &files[0],
            "--skeleton",
            &files[1],
            "--weights",
            &files[2],
            "--dmat-animation",
            &files[3],
            "-o",
            "/tmp/never.obj",
        ];
        args.extend(when);
        let o = run(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        let want =
            format!("{flag}: {frame}: with --dmat-animation times are frame indices, 0 to 456");
        assert!(err.contains(&want), "{err}");
    }
}

/// Bad input: a truncated file, an unknown animation or joint, an output over the input: exit
/// code 2 with a message.
#[test]
fn skin_cli_bad_input_exits_2_with_a_message() {
    let Some(dir) = data_dir() else { return };
    let out = gltf_out();
    let man = dir.join("gltf/CesiumMan.glb");
    let trunc = out.join("truncated.bin");
    std::fs::write(&trunc, &std::fs::read(&man).unwrap()[..500]).unwrap();
    let trunc_glb = out.join("truncated-input.glb.bin");
    std::fs::rename(&trunc, &trunc_glb).unwrap();
    for args in [
        vec!["skin", trunc_glb.to_str().unwrap(), "-o", "/tmp/never.obj"],
        vec![
            "skin",
            man.to_str().unwrap(),
            "--animation",
            "nope",
            "-o",
            "/tmp/never.obj",
        ],
        vec![
            "skin",
            man.to_str().unwrap(),
            "--edit",
            "nobody=x.json",
            "-o",
            "/tmp/never.obj",
        ],
        vec!["skin", man.to_str().unwrap(), "-o", man.to_str().unwrap()],
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!o.stderr.is_empty());
    }
}

/// `skin --edit ... -o x.glb` writes the edit into the animation (issue 21): the written file,
/// sampled at several times as a viewer samples it, gives what `skin --edit ... --time t
/// -o x.obj` gives at those times.
#[test]
fn an_edit_written_to_glb_plays_like_the_obj_of_each_frame() {
    use deform::skinning::{read_gltf, KeyframeBlend, RigPose};
    use std::process::Command;
    let Some(dir) = data_dir() else { return };
    let out = gltf_out();
    let exe = env!("CARGO_BIN_EXE_deform");
    let edit = out.join("neck-plays.json");
    std::fs::write(
        &edit,
        r#"{"rotate": {"axis": [1, 0, 0], "degrees": 25}, "scale": 1.2}"#,
    )
    .unwrap();
    let man = dir.join("gltf/CesiumMan.glb");
    let edit_arg = format!("Skeleton_neck_joint_1={}", edit.display());
    let run = |extra: &[&str]| {
        let mut args = vec!["skin", man.to_str().unwrap(), "--edit", &edit_arg, "-q"];
        args.extend(extra);
        let o = Command::new(exe).args(&args).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    let glb = out.join("cesium-neck-plays.glb");
    run(&["-o", glb.to_str().unwrap()]);
    let written = read_gltf(&glb).unwrap();
    let diag = written.mesh.bounding_box().unwrap().diagonal();
    for t in ["0.4", "1.25"] {
        let obj = out.join(format!("cesium-neck-{t}.obj"));
        run(&[
            "--animation",
            "0",
            "--time",
            t,
            "--backend",
            "lbs",
            "-o",
            obj.to_str().unwrap(),
        ]);
        let want = deform::mesh::io::read_obj(&obj).unwrap().positions;
        let mut pose = RigPose::default();
        written
            .pose_into(
                Some(0),
                t.parse().unwrap(),
                KeyframeBlend::Gltf,
                &[],
                &mut pose,
            )
            .unwrap();
        let got: Vec<glam::DVec3> = (0..written.mesh.vertex_count())
            .map(|v| {
                let p = written.mesh.positions[v];
                written
                    .influences
                    .row(v)
                    .map(|(j, w)| w * pose.skin_matrices[j as usize].transform_point3(p))
                    .sum()
            })
            .collect();
        let worst = want
            .iter()
            .zip(&got)
            .map(|(a, b)| (*a - *b).length())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-6 * diag,
            "t {t}: {:e} of the diagonal",
            worst / diag
        );
    }
}

/// `skin --time` without `--animation` samples the first animation, as `cut`, `tear` and
/// `drill` do (issue 21); without a time it is the rest pose.
#[test]
fn skin_time_defaults_to_the_first_animation() {
    use std::process::Command;
    let Some(dir) = data_dir() else { return };
    let out = gltf_out();
    let man = dir.join("gltf/CesiumMan.glb");
    let run = |name: &str, extra: &[&str]| {
        let obj = out.join(name);
        let mut args = vec![
            "skin",
            man.to_str().unwrap(),
            "-q",
            "-o",
            obj.to_str().unwrap(),
        ];
        args.extend(extra);
        let o = Command::new(env!("CARGO_BIN_EXE_deform"))
            .args(&args)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        deform::mesh::io::read_obj(&obj).unwrap().positions
    };
    let implicit = run("time-implicit.obj", &["--time", "0.5"]);
    let explicit = run("time-explicit.obj", &["--time", "0.5", "--animation", "0"]);
    let rest = run("time-rest.obj", &[]);
    assert_eq!(implicit, explicit);
    assert_ne!(implicit, rest);
}
