//! The command line (clap): the program, its global options and its subcommands, each with
//! its arguments in its own file under `commands/` (the groups they share are in
//! `shared_args.rs`). Every subcommand shares the motor JSON format, the selection format,
//! `-o`, `--png`, `--json` and `--quiet`.

use crate::commands::{
    arap, cage, cut, demo, drill, fabrik, ffd, handles, pose, skin, spline, tear, view,
};
use clap::{Parser, Subcommand};

/// Mesh deformation with conformal geometric algebra motors.
#[derive(Parser, Debug)]
#[command(name = "deform", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// The work budget: the most elements (f64s of a buffer, grid nodes, vertices times frames
    /// or iterations) any size asked for may come to; larger requests are refused up front.
    #[arg(
        long,
        global = true,
        default_value_t = crate::budget::DEFAULT_MAX_WORK,
        value_parser = clap::value_parser!(u64).range(1..)
    )]
    pub max_work: u64,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Every method on procedural meshes (no downloads): bend, twist and stretch bars with
    /// every spline scheme, fit a spline to a FABRIK chain, twist by FFD, bend by a cage, move
    /// motor handles, pose an ARAP beam, animate a rigged arm and cut, tear and drill it; write
    /// OBJ files, PNG previews, a .glb per rig and a contact sheet, and print a table of bind
    /// (or tool) and pose times.
    Demo(demo::DemoArgs),
    /// Spline-aligned deformation: group 0 of the selection is H_1 (lambda = 0), the highest
    /// group H_n (lambda = 1); keys are posed relative to the rest pose (rest keys are the
    /// identity unless --rest-keys is given).
    Spline(spline::SplineArgs),
    /// Motor handles: one harmonic field per selection group, one motor per group.
    Handles(handles::HandlesArgs),
    /// Inverse kinematics driving a spline: a chain of joints (JSON array of [x, y, z],
    /// root first; default: a straight chain of --joints joints from the centroid of group 0
    /// to the centroid of the highest group) is solved by FABRIK for its end effector to reach
    /// --target; its joint frames are fitted by a cubic B-spline of --controls motors, which
    /// deforms the mesh (the first paper's Fig. 5). An unreachable target stretches the chain
    /// towards it and says so.
    Fabrik(fabrik::FabrikArgs),
    /// Free-form deformation: a lattice of L x M x N control points over the mesh's box (or
    /// --box), one motor per control point (index u + L*(v + M*w), "*" the rest); motor FFD
    /// (the paper's equations (7)-(8)) or classic positional FFD (--positional).
    Ffd(ffd::FfdArgs),
    /// Cage deformation: mean value or harmonic coordinates of the mesh in a closed cage, one
    /// motor per cage vertex ("*" the rest); motor-valued or positional (--positional). A cage
    /// that does not enclose the mesh is an error (exit code 2).
    Cage(cage::CageArgs),
    /// As-rigid-as-possible deformation (the paper's rotors): selection groups with a motor
    /// in --motors are handles moved rigidly by it, the other groups stay fixed; iterates
    /// from the rest pose and prints the energy after each iteration.
    Arap(arap::ArapArgs),
    /// Any method of the library's catalogue by name (handles, arap, spline, ffd, cage),
    /// bound and posed as the editor does, with the option flags the library describes: one
    /// motor per group (or per control point of a lattice or cage). ARAP runs --iterations
    /// (1 to 50) from the rest pose.
    Pose(pose::PoseArgs),
    /// Skinning: pose a rigged model (glTF, or a mesh with --skeleton TGF and --weights DMAT)
    /// at --time of --animation, with joint edits, by any --backend; write OBJ (world space by
    /// the glTF skinning formula, one vertex per glTF vertex, primitives concatenated in
    /// document order), an OBJ sequence (--range, --in-betweens) or the whole rig as .glb.
    Skin(skin::SkinArgs),
    /// Cut a rigged model by the plane n.x = d (the second paper's Algorithm 1): both pieces
    /// stay skinned and animatable; .glb keeps the rig (one primitive per piece), OBJ writes
    /// the rest mesh. Coordinates are rest-pose mesh space unless --time is given.
    #[command(after_long_help = CUT_COUNTS)]
    Cut(cut::CutArgs),
    /// Drill a hole with a finite cylinder from --tip to --end of --radius (Algorithm 3);
    /// the result stays skinned and animatable.
    #[command(after_long_help = DRILL_COUNTS)]
    Drill(drill::DrillArgs),
    /// Tear the skin with a scalpel given at successive time steps (Algorithm 2): the
    /// incision opens (--open pulls its lips apart); the result stays skinned and animatable.
    #[command(after_long_help = TEAR_COUNTS)]
    Tear(tear::TearArgs),
    /// The interactive editor: serve a page on this machine (loopback unless --host) that
    /// deforms the model (or the demo's scenes) by hand, live; prints the address to open.
    View(view::ViewArgs),
}

impl Command {
    /// Runs the subcommand.
    pub fn run(&self) -> anyhow::Result<()> {
        match self {
            Command::Demo(a) => demo::run(a),
            Command::Spline(a) => spline::run(a),
            Command::Handles(a) => handles::run(a),
            Command::Fabrik(a) => fabrik::run(a),
            Command::Ffd(a) => ffd::run(a),
            Command::Cage(a) => cage::run(a),
            Command::Arap(a) => arap::run(a),
            Command::Pose(a) => pose::run(a),
            Command::Skin(a) => skin::run(a),
            Command::Cut(a) => cut::run(a),
            Command::Drill(a) => drill::run(a),
            Command::Tear(a) => tear::run(a),
            Command::View(a) => view::run(a),
        }
    }
}

/// What `cut --json` reports.
const CUT_COUNTS: &str = "Reported counts (--json): new_vertices: vertices made on crossing \
edges (each appears in both pieces); split_faces: input triangles removed and \
re-triangulated; snapped_vertices: input vertices closer to the plane than --snap of a \
crossing edge, treated as on it; per piece (piece_positive, piece_negative): vertices, \
triangles, cap_triangles, and boundary_loops: the closed chains of boundary edges of the \
piece after capping, counted over the welded surface (vertices at bit-identical positions, \
such as glTF's copies along UV seams, are one vertex), so an uncapped cut through a closed \
limb reports 1 per piece and a capped one 0.";

/// What `tear --json` reports.
const TEAR_COUNTS: &str = "Reported counts (--json): steps: scalpel positions minus one; \
incision_vertices: points of the incision, from the first scalpel point to the last, each \
counted once (a scalpel that goes back along its incision passes points twice and opens them \
once); new_vertices: vertices added (incision points, their copies on the far side of UV \
seams, and the lips' copies); duplicated: inner incision points split into two lips; changed_faces: \
input triangles re-triangulated; boundary_loops: closed chains of boundary edges through the \
changed region, counted over the welded surface as for cut (glTF's seam copies are one \
vertex), so a slit through a closed surface is 1, on the rest pose and on a posed frame \
alike. Between two scalpel positions the incision follows the surface along the plane \
swept by the blade, however far apart they are; two positions whose entry points that \
curve does not join (say one blade enters another limb) are refused, saying where.";

/// What `drill --json` reports.
const DRILL_COUNTS: &str = "Reported counts (--json): new_vertices: points made where the \
cylinder crosses edges; removed_faces: input triangles removed or re-triangulated; \
refined_faces: triangles replaced by refinement where the drill is thinner than the \
triangles; boundary_loops: closed chains of boundary edges through the drilled region, \
counted over the welded surface as for cut (glTF's seam copies are one vertex), or over the \
whole result's own vertices after refinement; holes: boundary_loops minus the boundary \
loops the whole input had (over the same vertices), exact on a closed surface (a \
through-drill of a closed limb makes 2) and an undercount where the input has open \
boundaries of its own near the drill.";

#[cfg(test)]
mod method_flags {
    //! The contract between the library's method settings and the flags: what
    //! `MethodSettings::args` prints (the editor's replay command), clap parses back into
    //! the same settings.
    use super::{Cli, Command};
    use clap::Parser;
    use deform::methods::named::Named;
    use deform::methods::{Method, MethodSettings};
    use deform::BlendMethod;

    /// The settings a parsed command binds by (the options its method uses).
    fn settings_of(c: &Command) -> MethodSettings {
        let mut s = MethodSettings::default();
        match c {
            Command::Handles(a) => s.blend = a.blending.blend,
            Command::Spline(a) => {
                s.set_method(Method::Spline);
                s.blend = a.blending.blend;
            }
            Command::Arap(a) => {
                s.set_method(Method::Arap);
                let step = a.local_step.name();
                s.set_all(&[("energy", a.energy.name()), ("local-step", step)])
                    .unwrap();
                // The replayed run from rest: more iterations than the editor's per frame.
                assert_eq!(a.iterations, Some(1000));
            }
            Command::Ffd(a) => {
                s.set_method(Method::Ffd);
                let [l, m, n] = a.lattice;
                let lattice = format!("{l}x{m}x{n}");
                s.set_all(&[("lattice", &lattice), ("basis", Named::name(a.basis))])
                    .unwrap();
                (s.blend, s.positional) = (a.form.blend, a.form.positional);
            }
            Command::Cage(a) => {
                s.set_method(Method::Cage);
                let (coordinates, grid) = (a.coordinates.name(), a.grid.to_string());
                s.set_all(&[("coordinates", coordinates), ("grid", &grid)])
                    .unwrap();
                (s.blend, s.positional) = (a.form.blend, a.form.positional);
            }
            Command::Pose(a) => {
                return crate::commands::pose::settings_of(a.method, &a.options).unwrap()
            }
            other => panic!("not a method: {other:?}"),
        }
        s
    }

    #[test]
    fn the_printed_flags_parse_back_into_the_same_settings() {
        let mut cases = 0;
        for &method in Method::ALL {
            for blend in BlendMethod::ALL {
                for variant in 0..4 {
                    let mut s = MethodSettings::default();
                    s.set_method(method);
                    s.blend = blend;
                    if method.controls() && variant == 1 {
                        s.set_positional(true).unwrap();
                    }
                    if variant == 2 {
                        s.set("energy", "spokes").unwrap();
                        s.set("local-step", "svd").unwrap();
                        s.set("coordinates", "harmonic").unwrap();
                        s.set("grid", "24").unwrap();
                        s.set_all(&[("lattice", "5x3x2"), ("basis", "bspline-2")])
                            .unwrap();
                    }
                    if variant == 3 {
                        s.set_all(&[("lattice", "2x3x4"), ("basis", "bernstein")])
                            .unwrap();
                    }
                    let mut argv = vec!["deform".to_string()];
                    argv.extend(method.command().into_iter().map(String::from));
                    argv.push("m.obj".into());
                    for (flag, what) in method.inputs() {
                        argv.extend([format!("--{flag}"), format!("{what}.json")]);
                    }
                    argv.extend(s.args());
                    argv.extend(["-o".into(), "out.obj".into()]);
                    let cli = Cli::try_parse_from(&argv)
                        .unwrap_or_else(|e| panic!("{}: {e}", argv.join(" ")));
                    // What the method uses, printed: the same settings both ways.
                    assert_eq!(settings_of(&cli.command).args(), s.args(), "{argv:?}");
                    cases += 1;
                }
            }
        }
        assert_eq!(cases, Method::ALL.len() * BlendMethod::ALL.len() * 4);
    }
}
