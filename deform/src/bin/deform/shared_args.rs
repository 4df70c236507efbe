//! The argument groups several subcommands share: the mesh and its selection, the rigged
//! model, where a surgery tool is given, how weights are computed and motors blended, and
//! `-o`, `--png`, `--json`, `--quiet`.

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Args, ValueEnum};
use deform::blend::control::ControlForm;
use deform::methods::named::Named;
use deform::methods::settings;
use deform::operators::harmonic::HarmonicOptions;
use deform::operators::laplacian::LaplacianKind;
use deform::BlendMethod;
use std::path::{Path, PathBuf};

/// Options every command that writes files shares.
#[derive(Args, Debug, Clone)]
pub struct OutputArgs {
    /// The result, by extension: `.obj`, `.ply` (binary) or `.glb` (for `skin`, `cut`, `tear`
    /// and `drill` the whole rig, for the deformers a static mesh with smooth normals); any
    /// other extension is refused before any work. The deformers and `skin` keep the input's
    /// vertex order and count; `cut`, `tear` and `drill` change them.
    #[arg(short = 'o', long = "output")]
    pub output: PathBuf,
    /// A PNG preview: the rest mesh beside the deformed one, titled, with the colour legend
    /// and the tools (handles, cage, lattice, chain, target, plane, scalpel, drill) drawn over
    /// them.
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// The preview's view YAW,PITCH in degrees (yaw 0 looks along -Z, at the model's front
    /// when it faces +Z; pitch raises the eye; +Y is up).
    #[arg(long, value_parser = parse_view, allow_hyphen_values = true, default_value = "30,20")]
    pub view: (f64, f64),
    /// Print timings and counts as one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
    /// What an OBJ input had beside positions and faces, kept for an OBJ output (set when the
    /// input is read).
    #[arg(skip)]
    pub input_extras: std::cell::OnceCell<deform::mesh::io::ObjInputExtras>,
}

/// `YAW,PITCH`, finite degrees.
fn parse_view(s: &str) -> Result<(f64, f64), String> {
    let bad = || format!("{s:?}: expected YAW,PITCH in degrees");
    let (y, p) = s.split_once(',').ok_or_else(bad)?;
    let y: f64 = y.trim().parse().map_err(|_| bad())?;
    let p: f64 = p.trim().parse().map_err(|_| bad())?;
    if !(y.is_finite() && p.is_finite()) {
        return Err(bad());
    }
    Ok((y, p))
}

impl OutputArgs {
    /// The preview's yaw and pitch.
    pub fn view(&self) -> (f64, f64) {
        self.view
    }

    /// The files this run writes: `-o` and `--png`.
    pub fn paths(&self) -> Vec<&Path> {
        let mut outputs = vec![self.output.as_path()];
        outputs.extend(self.png.as_deref());
        outputs
    }
}

/// The mesh and its handle groups, read by every subcommand.
#[derive(Args, Debug)]
pub struct MeshInput {
    /// The mesh (OBJ, OFF or MEDIT).
    pub mesh: PathBuf,
    /// Handle groups: a libigl DMAT (-1 free, k >= 0 group) or JSON {"k": [vertices]}.
    #[arg(long)]
    pub select: PathBuf,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum LaplacianArg {
    MeanValue,
    Cotangent,
}

/// A choice by its library name ([`Named`]: the names the editor and the replayed command
/// use too), parsed by the library; the names are clap's possible values (listed in the help
/// and in the error for any other).
pub fn named<T: Named + Clone + Send + Sync>() -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(T::names()).try_map(|name| T::from_name(&name))
}

/// A blend method by its library name.
pub fn blend_method() -> impl TypedValueParser<Value = BlendMethod> {
    named::<BlendMethod>()
}

/// How weights are computed and motors blended.
#[derive(Args, Debug)]
pub struct BlendingArgs {
    /// The Laplacian of the harmonic fields.
    #[arg(long, value_enum, default_value = "mean-value")]
    pub laplacian: LaplacianArg,
    #[arg(long = settings::BLEND.name, help = settings::BLEND.help,
          value_parser = blend_method(), default_value = "motor-log")]
    pub blend: BlendMethod,
}

impl BlendingArgs {
    /// The harmonic fields' options for `--laplacian`.
    pub fn harmonic(&self) -> HarmonicOptions {
        HarmonicOptions {
            laplacian: match self.laplacian {
                LaplacianArg::MeanValue => LaplacianKind::MeanValue,
                LaplacianArg::Cotangent => LaplacianKind::Default,
            },
            ..HarmonicOptions::default()
        }
    }
}

/// Positional or motor-valued posing of control points.
#[derive(Args, Debug)]
pub struct FormArgs {
    #[arg(long = settings::POSITIONAL.name, help = settings::POSITIONAL.help)]
    pub positional: bool,
    #[arg(long = settings::BLEND.name, help = settings::BLEND.help,
          value_parser = blend_method(), default_value = "motor-log")]
    pub blend: BlendMethod,
    /// Pose on the GPU (wgpu), in f32: needs a program built with `--features gpu`, and a GPU
    /// or Mesa's lavapipe (otherwise exit code 2); `--gpu=auto` poses on the CPU instead,
    /// with a note, where there is none.
    #[arg(long, value_enum, num_args = 0..=1, require_equals = true, default_value = "off",
          default_missing_value = "on", value_name = "WHEN")]
    pub gpu: GpuChoice,
}

/// Where `--gpu` poses.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum GpuChoice {
    /// On the CPU (no `--gpu`).
    Off,
    /// On the GPU, or exit code 2 when there is none (`--gpu`).
    On,
    /// On the GPU when there is one, else on the CPU with a note (`--gpu=auto`).
    Auto,
}

impl FormArgs {
    /// The form the flags select.
    pub fn form(&self) -> ControlForm {
        if self.positional {
            ControlForm::Positional
        } else {
            ControlForm::Motor(self.blend)
        }
    }
}

/// A rigged model on the command line.
#[derive(Args, Debug)]
pub struct RigInput {
    /// The rigged model: glTF 2.0 (.gltf, .glb), or a mesh (OBJ, OFF) with --skeleton and
    /// --weights.
    pub model: PathBuf,
    /// libigl skeleton (TGF) of a mesh model.
    #[arg(long, requires = "weights")]
    pub skeleton: Option<PathBuf>,
    /// libigl weights (DMAT, vertices x bones) of a mesh model.
    #[arg(long, requires = "skeleton")]
    pub weights: Option<PathBuf>,
    /// Follow glTF buffer URIs that leave the model's folder (refused by default).
    #[arg(long)]
    pub allow_external: bool,
}

impl RigInput {
    /// The input files: the model (with the buffer and image files a glTF model names), the
    /// skeleton and the weights.
    pub fn paths(&self) -> Vec<PathBuf> {
        let mut v = vec![self.model.clone()];
        v.extend(deform::skinning::gltf_external_files(&self.model));
        v.extend(self.skeleton.clone());
        v.extend(self.weights.clone());
        v
    }
}

/// Where the tool's coordinates are given.
#[derive(Args, Debug)]
pub struct ToolFrame {
    /// Give the tool in the posed world space at this time in seconds (clamped to the
    /// animation's keys) instead of the world space at the bind pose; as for `skin`,
    /// --animation alone means time 0.
    #[arg(long, value_parser = crate::numbers::finite, allow_hyphen_values = true)]
    pub time: Option<f64>,
    /// The animation, by name or index (default: the first when --time is given, as for
    /// `skin`; without either, the rest pose).
    #[arg(long)]
    pub animation: Option<String>,
    /// Give the tool in the rest mesh's own coordinates (the vertex space of the glTF mesh,
    /// before the armature's transforms, unit scale and up axis) instead of the scene's world
    /// space at the bind pose.
    #[arg(long, conflicts_with_all = ["time", "animation"])]
    pub mesh_space: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_blend_parser_lists_every_name() {
        let names: Vec<String> = blend_method()
            .possible_values()
            .into_iter()
            .flatten()
            .map(|v| v.get_name().to_string())
            .collect();
        assert_eq!(names, BlendMethod::ALL.map(|m| m.name().to_string()));
    }
}
