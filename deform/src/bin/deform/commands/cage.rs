//! `deform cage`: cage deformation by mean value or harmonic coordinates of the mesh in a
//! closed cage, one motor per cage vertex, in motor or positional form: read, bind, pose
//! (timed), write, report.

use crate::finish::pose_control_and_finish;
use crate::input_files::{read_mesh, read_mesh_checked, read_text};
use crate::progress::with_progress;
use crate::report::Report;
use crate::shared_args::{named, FormArgs, OutputArgs};
use crate::timing::ms;
use anyhow::{Context, Result};
use clap::Args;
use deform::deformers::cage::{CageCoordinates, CageDeformer, CageOptions, HarmonicGrid};
use deform::input::parse_group_motors;
use deform::methods::kinds::cage::{COORDINATES, GRID};
use deform::methods::named::{Coordinates, Named};
use deform::render::preview::{Look, POSED_INK, REST_INK};
use deform::render::tools::{mesh_edges, moved};
use std::path::PathBuf;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct CageArgs {
    /// The mesh (OBJ, OFF or MEDIT).
    pub mesh: PathBuf,
    /// The closed triangle cage around it.
    #[arg(long)]
    pub cage: PathBuf,
    #[arg(long = COORDINATES.name, help = COORDINATES.help,
          value_parser = named::<Coordinates>(), default_value = "mean-value")]
    pub coordinates: Coordinates,
    #[arg(long = GRID.name, help = GRID.help, default_value_t = 64)]
    pub grid: usize,
    /// Accept a cage whose faces cross each other (refused by default).
    #[arg(long)]
    pub allow_self_intersecting: bool,
    /// Per-cage-vertex motors: JSON {"index": motor, "*": motor for the rest}.
    #[arg(long)]
    pub motors: PathBuf,
    #[command(flatten)]
    pub form: FormArgs,
    #[command(flatten)]
    pub out: OutputArgs,
}

pub fn run(a: &CageArgs) -> Result<()> {
    if a.coordinates == Coordinates::Harmonic {
        // The grid's own limits first: the budget's hint to raise --max-work cannot help there.
        let grid = HarmonicGrid { resolution: a.grid };
        grid.check().context("--grid")?;
        crate::budget::get().cage_grid("--grid", a.grid)?;
    }
    let mesh = read_mesh_checked(&a.mesh, &[a.cage.as_path(), a.motors.as_path()], &a.out)?;
    let cage = read_mesh(&a.cage)?;
    crate::budget::get().cage_pairs("--cage", mesh.vertex_count(), cage.vertex_count())?;
    let name = a.motors.display().to_string();
    let motors = parse_group_motors(&read_text(&a.motors)?, &name, cage.vertex_count())?;
    let options = CageOptions {
        coordinates: match a.coordinates {
            Coordinates::MeanValue => CageCoordinates::MeanValue,
            Coordinates::Harmonic => CageCoordinates::Harmonic(HarmonicGrid { resolution: a.grid }),
        },
        form: a.form.form(),
        allow_self_intersecting: a.allow_self_intersecting,
    };
    let t = Instant::now();
    let d = with_progress(
        "binding (cage coordinates)",
        mesh.vertex_count() * cage.vertex_count() / 20,
        a.out.quiet,
        || CageDeformer::bind(&mesh, &cage, options),
    )
    .map_err(|e| {
        let hint = if matches!(
            e,
            deform::deformers::DeformError::Cage(
                deform::deformers::cage::CageError::SelfIntersecting { .. }
            )
        ) {
            " (--allow-self-intersecting accepts it)"
        } else {
            ""
        };
        anyhow::Error::new(e).context(format!(
            "{}: cannot bind to the cage {}{hint}",
            a.mesh.display(),
            a.cage.display()
        ))
    })?;
    let mut report = Report::new("cage", &mesh);
    report.add("bind_ms", ms(t));
    report.add("cage_vertices", cage.vertex_count());
    let coords = a.coordinates.name();
    report.add("coordinates", coords);
    report.add("form", options.form.name());
    let title = format!(
        "cage  {coords}  {}  {} cage vertices",
        options.form.name(),
        cage.vertex_count()
    );
    let mut look = Look::new(title, "displacement");
    // The cage at rest and moved by its motors.
    look.rest.line_width = 1;
    look.posed.line_width = 1;
    mesh_edges(&mut look.rest, &cage, &cage.positions, REST_INK);
    mesh_edges(
        &mut look.posed,
        &cage,
        &moved(&cage.positions, &motors),
        POSED_INK,
    );
    let (binding, gpu) = (d.binding(), a.form.gpu);
    pose_control_and_finish(&d, binding, gpu, (&mesh, &motors), look, &a.out, report)
}
