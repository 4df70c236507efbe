//! `--gpu`: posing through `deform::gpu` when the program is built with the `gpu` feature.

use crate::report::Report;
use crate::shared_args::GpuChoice;
use anyhow::Result;
use glam::DVec3;

impl GpuPoser {
    /// The poser `choice` asks for: none for [`GpuChoice::Off`]; `open()` or its error for
    /// [`GpuChoice::On`]; for [`GpuChoice::Auto`], `open()`, else none with the reason as a
    /// note (on stderr unless `quiet`, and in the report). The device is added to `report`.
    pub fn choose(
        choice: GpuChoice,
        report: &mut Report,
        quiet: bool,
        open: impl FnOnce() -> Result<GpuPoser>,
    ) -> Result<Option<GpuPoser>> {
        let opened = match choice {
            GpuChoice::Off => return Ok(None),
            GpuChoice::On => open()?,
            GpuChoice::Auto => match open() {
                Ok(g) => g,
                Err(e) => {
                    let note = format!("{e:#}; posing on the CPU (--gpu=auto)");
                    if !quiet {
                        eprintln!("note: {note}");
                    }
                    report.add("device", "cpu");
                    report.add("note", note.as_str());
                    return Ok(None);
                }
            },
        };
        report.add("device", opened.adapter());
        Ok(Some(opened))
    }
}

/// A bound blend on the GPU, with its device.
#[cfg(feature = "gpu")]
pub struct GpuPoser {
    ctx: deform::gpu::GpuContext,
    blend: deform::gpu::GpuBlend,
}

/// The first adapter's device, or why there is none (no adapter: exit code 2).
#[cfg(feature = "gpu")]
fn context() -> Result<deform::gpu::GpuContext> {
    deform::gpu::GpuContext::new()
        .map_err(|e| anyhow::anyhow!("--gpu: {e} (install a GPU driver, or Mesa's lavapipe)"))
}

#[cfg(feature = "gpu")]
impl GpuPoser {
    /// Upload `blend` to the first adapter, or say why not (no adapter: exit code 2).
    pub fn open(blend: &deform::blend::BoundBlend) -> Result<GpuPoser> {
        let ctx = context()?;
        let blend =
            deform::gpu::GpuBlend::bind(&ctx, blend).map_err(|e| anyhow::anyhow!("--gpu: {e}"))?;
        Ok(GpuPoser { ctx, blend })
    }

    /// Upload a lattice's or cage's binding (either form), as [`GpuPoser::open`].
    pub fn open_control(binding: &deform::blend::control::ControlBinding) -> Result<GpuPoser> {
        let ctx = context()?;
        let blend = deform::gpu::GpuBlend::bind_control(&ctx, binding)
            .map_err(|e| anyhow::anyhow!("--gpu: {e}"))?;
        Ok(GpuPoser { ctx, blend })
    }

    /// The adapter, for the report.
    pub fn adapter(&self) -> String {
        self.ctx.adapter()
    }

    /// Pose on the GPU and read back; the milliseconds it took.
    pub fn pose(&mut self, keys: &[cga::ScaledMotor], out: &mut [DVec3]) -> Result<f64> {
        let t = std::time::Instant::now();
        self.blend.pose(&self.ctx, keys, out)?;
        Ok(t.elapsed().as_secs_f64() * 1e3)
    }
}

/// Why `--gpu` is refused without the `gpu` feature, and how to build with it.
#[cfg(not(feature = "gpu"))]
fn no_gpu_feature() -> anyhow::Error {
    anyhow::anyhow!(
        "--gpu: this deform was built without the `gpu` feature (cargo run --release -p deform \
         --features gpu -- skin|ffd|cage ... --gpu)"
    )
}

/// Without the `gpu` feature `--gpu` is refused.
#[cfg(not(feature = "gpu"))]
pub struct GpuPoser(std::convert::Infallible);

#[cfg(not(feature = "gpu"))]
impl GpuPoser {
    /// Always the error that says how to build with the GPU.
    pub fn open(_: &deform::blend::BoundBlend) -> Result<GpuPoser> {
        Err(no_gpu_feature())
    }

    /// Always the error that says how to build with the GPU.
    pub fn open_control(_: &deform::blend::control::ControlBinding) -> Result<GpuPoser> {
        Err(no_gpu_feature())
    }

    /// Never called: no value exists.
    pub fn adapter(&self) -> String {
        match self.0 {}
    }

    /// Never called: no value exists.
    pub fn pose(&mut self, _: &[cga::ScaledMotor], _: &mut [DVec3]) -> Result<f64> {
        match self.0 {}
    }
}
