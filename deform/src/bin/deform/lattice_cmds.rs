//! The `ffd` and `cage` subcommands: read, bind, pose (both forms timed), write, report.

use crate::args::{CageArgs, CoordsArg, FfdArgs, FormArgs, OutputArgs};
use crate::commands::{blend, pose_and_finish, with_progress, Report};
use crate::output::{check_outputs, read_mesh, read_text};
use anyhow::{Context, Result};
use deform::cage::{CageCoordinates, CageDeformer, CageOptions, HarmonicGrid};
use deform::control::ControlForm;
use deform::ffd::{Ffd, FfdOptions, LatticeBasis};
use deform::input::parse_group_motors;
use deform::Mesh;
use glam::DVec3;
use std::path::Path;
use std::time::Instant;

fn form(f: &FormArgs) -> ControlForm {
    if f.positional {
        ControlForm::Positional
    } else {
        ControlForm::Motor(blend(f.blend))
    }
}

/// Refuse outputs that are inputs, then read the mesh.
fn read_checked(mesh: &Path, extra: &[&Path], out: &OutputArgs) -> Result<Mesh> {
    let mut inputs = vec![mesh];
    inputs.extend_from_slice(extra);
    let mut outputs = vec![out.output.as_path()];
    if let Some(p) = &out.png {
        outputs.push(p.as_path());
    }
    check_outputs(&inputs, &outputs)?;
    crate::output::check_formats(out, &["obj"])?;
    read_mesh(mesh)
}

pub fn ffd(a: &FfdArgs) -> Result<()> {
    let mesh = read_checked(&a.mesh, &[a.motors.as_path()], &a.out)?;
    // Per vertex: a weight per control point, and for Bernstein polynomials of degree L-1,
    // M-1, N-1 their evaluation (quadratic in the degree).
    let [l, m, n] = a.lattice.map(|c| c as u64);
    let squares = [l, m, n]
        .iter()
        .try_fold(0u64, |acc, &d| acc.checked_add(d.checked_mul(d)?));
    let per_vertex = crate::budget::product(&[l, m, n]).and_then(|points| match a.degree {
        None => points.checked_add(squares?),
        Some(_) => Some(points),
    });
    let what = format!(
        "{l}x{m}x{n} control points for {} vertices",
        mesh.vertex_count()
    );
    let factors = [per_vertex.unwrap_or(u64::MAX), mesh.vertex_count() as u64];
    crate::budget::check("--lattice", &what, &factors)?;
    let count: usize = a.lattice.iter().product();
    let name = a.motors.display().to_string();
    let motors = parse_group_motors(&read_text(&a.motors)?, &name, count)?;
    let options = FfdOptions {
        basis: a
            .degree
            .map_or(LatticeBasis::Bernstein, LatticeBasis::BSpline),
        form: form(&a.form),
    };
    let bounds = a
        .bounds
        .map(|b| (DVec3::new(b[0], b[1], b[2]), DVec3::new(b[3], b[4], b[5])));
    let t = Instant::now();
    let d = Ffd::bind(&mesh, a.lattice, bounds, options)
        .with_context(|| format!("{}: cannot bind to the lattice", a.mesh.display()))?;
    let mut report = Report::new("ffd", &mesh);
    report.add("bind_ms", t.elapsed().as_secs_f64() * 1e3);
    report.add(
        "lattice",
        format!("{}x{}x{}", a.lattice[0], a.lattice[1], a.lattice[2]),
    );
    report.add(
        "basis",
        match options.basis {
            LatticeBasis::Bernstein => "bernstein".to_string(),
            LatticeBasis::BSpline(p) => format!("bspline-{p}"),
        },
    );
    report.add("form", options.form.name());
    pose_and_finish(&d, &mesh, &motors, &a.out, report)
}

pub fn cage(a: &CageArgs) -> Result<()> {
    let mesh = read_checked(&a.mesh, &[a.cage.as_path(), a.motors.as_path()], &a.out)?;
    let cage = read_mesh(&a.cage)?;
    if a.coords == CoordsArg::Harmonic {
        let g = a.grid as u64;
        let what = format!(
            "a harmonic grid of {g} nodes per side (its factorisation grows as the 4th power)"
        );
        crate::budget::check("--grid", &what, &[g, g, g, g])?;
    }
    let name = a.motors.display().to_string();
    let motors = parse_group_motors(&read_text(&a.motors)?, &name, cage.vertex_count())?;
    let options = CageOptions {
        coordinates: match a.coords {
            CoordsArg::Mvc => CageCoordinates::MeanValue,
            CoordsArg::Harmonic => CageCoordinates::Harmonic(HarmonicGrid { resolution: a.grid }),
        },
        form: form(&a.form),
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
            deform::Error::Cage(deform::cage::CageError::SelfIntersecting { .. })
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
    report.add("bind_ms", t.elapsed().as_secs_f64() * 1e3);
    report.add("cage_vertices", cage.vertex_count());
    report.add(
        "coords",
        match a.coords {
            CoordsArg::Mvc => "mvc",
            CoordsArg::Harmonic => "harmonic",
        },
    );
    report.add("form", options.form.name());
    pose_and_finish(&d, &mesh, &motors, &a.out, report)
}
