//! `deform pose METHOD MESH`: any method of the library's catalogue by its name, bound and
//! posed as the editor does (`deform::methods::BoundMethod`); its option flags are made from
//! the library's description ([`deform::methods::settings::all_options`]) and parsed by it
//! ([`MethodSettings::set`]), so a method added to the library is a method here too.

use crate::finish::{displacement, finish};
use crate::input_files::{read_mesh, read_mesh_checked, read_selection, read_text};
use crate::report::Report;
use crate::shared_args::{named, OutputArgs};
use crate::timing::ms;
use anyhow::{Context, Result};
use clap::builder::PossibleValuesParser;
use clap::{Arg, ArgAction, ArgMatches, Args, Command, FromArgMatches};
use deform::input::parse_group_motors;
use deform::methods::bound::BoundMethod;
use deform::methods::harmonic_cache::HarmonicCache;
use deform::methods::named::Named;
use deform::methods::option::OptionKind;
use deform::methods::settings::all_options;
use deform::methods::{Method, MethodSettings};
use deform::render::preview::{Look, POSED_INK, REST_INK};
use deform::render::tools::{edges, moved};
use std::path::PathBuf;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct PoseArgs {
    /// The method, by the library's name.
    #[arg(value_parser = named::<Method>())]
    pub method: Method,
    /// The mesh (OBJ, OFF or MEDIT).
    pub mesh: PathBuf,
    /// Handle groups (handles, arap, spline): a libigl DMAT or JSON {"k": [vertices]}.
    #[arg(long)]
    pub select: Option<PathBuf>,
    /// One motor per key: per group, or per control point of a lattice or cage; JSON
    /// {"index": motor, "*": motor for the rest}. A spline's keys follow a translation to
    /// each group's centre, as in the editor.
    #[arg(long)]
    pub motors: PathBuf,
    /// The closed cage around the mesh (cage).
    #[arg(long)]
    pub cage: Option<PathBuf>,
    #[command(flatten)]
    pub options: MethodFlags,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The method options given, by name, as the library's description makes the flags.
#[derive(Debug, Clone, Default)]
pub struct MethodFlags(pub Vec<(&'static str, String)>);

impl FromArgMatches for MethodFlags {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut given = Vec::new();
        for o in all_options() {
            let name = o.spec.name;
            if let OptionKind::Switch = o.spec.kind {
                if m.get_flag(name) {
                    given.push((name, "true".to_string()));
                }
            } else if let Some(v) = m.get_one::<String>(name) {
                given.push((name, v.clone()));
            }
        }
        Ok(MethodFlags(given))
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
}

impl Args for MethodFlags {
    fn augment_args(mut cmd: Command) -> Command {
        for o in all_options() {
            let methods: Vec<&str> = o.methods.iter().map(|m| m.name()).collect();
            let (name, spec) = (o.spec.name, o.spec);
            let help = format!("{} ({})", spec.help, methods.join(", "));
            let arg = Arg::new(name).long(name).help(help);
            cmd = cmd.arg(match &spec.kind {
                OptionKind::Switch => arg.action(ArgAction::SetTrue),
                OptionKind::Choice { names, .. } => {
                    arg.value_parser(PossibleValuesParser::new(names()))
                }
                OptionKind::Number(_) => arg.value_name("N"),
                OptionKind::Dims(_) => arg.value_name("LxMxN"),
            });
        }
        cmd
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// The settings the flags give (each checked by the library), for `method`.
pub fn settings_of(method: Method, flags: &MethodFlags) -> Result<MethodSettings> {
    let mut s = MethodSettings::default();
    s.set_method(method);
    let all = all_options();
    for (name, value) in &flags.0 {
        let info = all.iter().find(|o| o.spec.name == *name);
        let methods = info.map_or(&[][..], |o| &o.methods[..]);
        if !methods.contains(&method) {
            let methods: Vec<&str> = methods.iter().map(|m| m.name()).collect();
            let (methods, this) = (methods.join(", "), method.name());
            anyhow::bail!("--{name} is for {methods}, not {this}");
        }
        s.set(name, value).with_context(|| format!("--{name}"))?;
    }
    Ok(s)
}

pub fn run(a: &PoseArgs) -> Result<()> {
    let method = a.method;
    let settings = settings_of(method, &a.options)?;
    if method.reads("cage") && a.cage.is_none() {
        anyhow::bail!("cage: give the cage with --cage CAGE.obj");
    }
    if method.groups_needed() > 0 && a.select.is_none() {
        anyhow::bail!("{}: give the handle groups with --select", method.name());
    }
    let mut extra: Vec<&std::path::Path> = vec![a.motors.as_path()];
    extra.extend(a.select.as_deref());
    extra.extend(a.cage.as_deref());
    let mesh = read_mesh_checked(&a.mesh, &extra, &a.out)?;
    let groups = match &a.select {
        Some(s) => read_selection(s, mesh.vertex_count())?.groups,
        None => Vec::new(),
    };
    let cage = a.cage.as_deref().map(read_mesh).transpose()?;
    let budget = crate::budget::get();
    if let Some(c) = &cage {
        budget.cage_pairs("--cage", mesh.vertex_count(), c.vertex_count())?;
    }
    let t = Instant::now();
    let mut bound = BoundMethod::bind(
        &mesh,
        &groups,
        cage.as_ref(),
        &settings,
        &budget,
        &mut HarmonicCache::default(),
    )
    .with_context(|| format!("{}: cannot bind {}", a.mesh.display(), method.name()))?;
    let bind_ms = ms(t);
    let name = a.motors.display().to_string();
    let motors = parse_group_motors(&read_text(&a.motors)?, &name, bound.key_count())?;
    let mut posed = mesh.positions.clone();
    let t = Instant::now();
    let energy = bound.pose(&motors, &mesh.positions, &mut posed)?;
    let pose_ms = ms(t);
    let mut report = Report::new("pose", &mesh);
    report.add("method", method.name());
    report.add("flags", settings.args().join(" "));
    report.add("keys", bound.key_count());
    report.add("bind_ms", bind_ms);
    report.add("pose_ms", pose_ms);
    if let Some(e) = energy {
        report.add("energy", e);
    }
    let title = format!("pose {}  {}", method.name(), settings.args().join(" "));
    let mut look = Look::new(title, "displacement");
    if let Some(c) = bound.controls() {
        // The lattice or cage at rest and moved by its motors.
        edges(&mut look.rest, &c.points, &c.edges, REST_INK);
        edges(
            &mut look.posed,
            &moved(&c.points, &motors),
            &c.edges,
            POSED_INK,
        );
    }
    let scalar = displacement(&mesh, &posed);
    finish(&mesh, posed, &scalar, look, &a.out, &mut report)
}
