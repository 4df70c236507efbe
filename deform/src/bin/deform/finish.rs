//! The last steps of every mesh deformer command: pose and time, refuse a non-finite result,
//! write the mesh (OBJ, static `.glb` or PLY) and the preview, print the report.

use crate::output_files::{write_deformed, write_png};
use crate::report::Report;
use crate::shared_args::OutputArgs;
use anyhow::{bail, Context, Result};
use deform::render::preview::{self, Look};
use deform::{Deformer, Mesh, Poser};
use glam::DVec3;

/// Write the posed mesh and its preview (the posed mesh coloured by `scalar`, `look`'s title
/// followed by the largest displacement), then print the report.
pub fn finish(
    mesh: &Mesh,
    posed: Vec<DVec3>,
    scalar: &[f64],
    look: Look,
    out: &OutputArgs,
    report: &mut Report,
) -> Result<()> {
    if let Some(i) = posed.iter().position(|p| !p.is_finite()) {
        bail!("vertex {i}: the deformation produced a non-finite position");
    }
    let posed = Mesh::new(posed, mesh.triangles.clone());
    write_deformed(&out.output, &posed, out.input_extras.get())?;
    report.add("output", out.output.display().to_string());
    if let Some(png) = &out.png {
        let look = Look {
            title: format!(
                "{}  {}",
                look.title,
                preview::max_move(mesh, &posed.positions)
            ),
            view: out.view(),
            ..look
        };
        let image = preview::before_after(mesh, &posed, scalar, &look)?;
        write_png(png, &image)?;
        report.add("png", png.display().to_string());
    }
    report.print(out);
    Ok(())
}

/// How far each vertex moved from `rest` to `posed`.
pub fn displacement(rest: &Mesh, posed: &[DVec3]) -> Vec<f64> {
    posed
        .iter()
        .zip(&rest.positions)
        .map(|(p, q)| p.distance(*q))
        .collect()
}

/// [`pose_and_finish`] for a lattice or a cage, posed on the GPU as `gpu` chooses (its adapter
/// in the report).
pub fn pose_control_and_finish(
    d: &(impl Deformer + ?Sized),
    binding: &deform::blend::control::ControlBinding,
    gpu: crate::shared_args::GpuChoice,
    (mesh, motors): (&Mesh, &[cga::ScaledMotor]),
    look: Look,
    out: &OutputArgs,
    mut report: Report,
) -> Result<()> {
    let open = || crate::gpu_pose::GpuPoser::open_control(binding);
    let Some(mut g) = crate::gpu_pose::GpuPoser::choose(gpu, &mut report, out.quiet, open)? else {
        return pose_and_finish(d, mesh, motors, look, out, report);
    };
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    report.add("pose_ms", g.pose(motors, &mut posed)?);
    let moved = displacement(mesh, &posed);
    finish(mesh, posed, &moved, look, out, &mut report)
}

/// Pose, time, report and write, the preview coloured by displacement.
pub fn pose_and_finish(
    d: &(impl Deformer + ?Sized),
    mesh: &Mesh,
    motors: &[cga::ScaledMotor],
    look: Look,
    out: &OutputArgs,
    mut report: Report,
) -> Result<()> {
    let mut posed = vec![DVec3::ZERO; mesh.vertex_count()];
    let pose_ms = Poser::new(d)
        .best_time_ms(motors, &mut posed, 5)
        .context("cannot pose")?;
    report.add("pose_ms", pose_ms);
    let moved = displacement(mesh, &posed);
    finish(mesh, posed, &moved, look, out, &mut report)
}
