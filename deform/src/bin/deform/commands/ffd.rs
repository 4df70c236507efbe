//! `deform ffd`: free-form deformation by a lattice of control points over the mesh's box,
//! one motor per control point, in motor or positional form: read, bind, pose (timed),
//! write, report.

use crate::finish::pose_control_and_finish;
use crate::input_files::{read_mesh_checked, read_text};
use crate::report::Report;
use crate::shared_args::{named, FormArgs, OutputArgs};
use crate::timing::ms;
use anyhow::{Context, Result};
use clap::Args;
use deform::deformers::ffd::{Ffd, FfdOptions, LatticeBasis};
use deform::input::parse_group_motors;
use deform::methods::kinds::ffd::{BASIS, LATTICE};
use deform::render::preview::{Look, POSED_INK, REST_INK};
use deform::render::tools::{lattice, moved};
use glam::DVec3;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct FfdArgs {
    /// The mesh (OBJ, OFF or MEDIT).
    pub mesh: PathBuf,
    #[arg(long = LATTICE.name, help = LATTICE.help,
          value_parser = crate::numbers::dims)]
    pub lattice: [usize; 3],
    #[arg(long = BASIS.name, help = BASIS.help,
          value_parser = named::<LatticeBasis>(), default_value = "bernstein")]
    pub basis: LatticeBasis,
    /// The lattice box MINX,MINY,MINZ,MAXX,MAXY,MAXZ (default: the mesh's bounding box).
    #[arg(long = "box", value_parser = crate::numbers::bounds, allow_hyphen_values = true)]
    pub bounds: Option<[f64; 6]>,
    /// Per-control-point motors: JSON {"index": motor, "*": motor for the rest}.
    #[arg(long)]
    pub motors: PathBuf,
    #[command(flatten)]
    pub form: FormArgs,
    #[command(flatten)]
    pub out: OutputArgs,
}

pub fn run(a: &FfdArgs) -> Result<()> {
    // The lattice's own limits first: the budget's hint to raise --max-work cannot help there.
    deform::deformers::ffd::Lattice::check_dims(a.lattice).context("--lattice")?;
    let mesh = read_mesh_checked(&a.mesh, &[a.motors.as_path()], &a.out)?;
    crate::budget::get().ffd_lattice("--lattice", a.lattice, a.basis, mesh.vertex_count())?;
    let count: usize = a.lattice.iter().product();
    let name = a.motors.display().to_string();
    let motors = parse_group_motors(&read_text(&a.motors)?, &name, count)?;
    let options = FfdOptions {
        basis: a.basis,
        form: a.form.form(),
    };
    let bounds = a
        .bounds
        .map(|b| (DVec3::new(b[0], b[1], b[2]), DVec3::new(b[3], b[4], b[5])));
    let t = Instant::now();
    let d = Ffd::bind(&mesh, a.lattice, bounds, options)
        .with_context(|| format!("{}: cannot bind to the lattice", a.mesh.display()))?;
    let basis = options.basis.name();
    let mut report = Report::new("ffd", &mesh);
    report.add("bind_ms", ms(t));
    report.add(
        "lattice",
        format!("{}x{}x{}", a.lattice[0], a.lattice[1], a.lattice[2]),
    );
    report.add("basis", basis.as_str());
    report.add("form", options.form.name());
    let title = format!(
        "ffd  {}x{}x{} {basis}  {}",
        a.lattice[0],
        a.lattice[1],
        a.lattice[2],
        options.form.name()
    );
    let mut look = Look::new(title, "displacement");
    // The lattice at rest and moved by its motors.
    let points = d.lattice().rest_points();
    lattice(&mut look.rest, &points, a.lattice, REST_INK);
    lattice(
        &mut look.posed,
        &moved(&points, &motors),
        a.lattice,
        POSED_INK,
    );
    let (binding, gpu) = (d.binding(), a.form.gpu);
    pose_control_and_finish(&d, binding, gpu, (&mesh, &motors), look, &a.out, report)
}
