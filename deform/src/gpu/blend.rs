//! A [`BoundBlend`] (or a lattice's or cage's [`ControlBinding`]) on the GPU: its rest points
//! and weights uploaded once, each pose uploads only the keys (or the control points) and reads
//! the positions back.

use super::{GpuContext, GpuError};
use crate::blend::control::{check_points, move_points, ControlBinding, ControlForm};
use crate::blend::{BlendMethod, BoundBlend, KeyWeights, PreparedKeys};
use cga::ScaledMotor;
use glam::DVec3;
use wgpu::util::DeviceExt as _;

/// Invocations per workgroup (the shader's `@workgroup_size`).
const GROUP: u32 = 64;
/// Workgroups per dispatch row (the guaranteed limit of one dimension).
const ROW_GROUPS: u32 = 65_535;

/// The shader entry point of a form.
fn entry_point(form: ControlForm) -> &'static str {
    let ControlForm::Motor(method) = form else {
        return "control_positional";
    };
    match method {
        BlendMethod::MotorLog => "skin_log",
        BlendMethod::MotorLinear => "skin_motor",
        BlendMethod::DualQuaternion => "skin_dual_quaternion",
        BlendMethod::Matrix | BlendMethod::MatrixF32 => "skin_matrix",
        BlendMethod::Conformal => "skin_conformal",
        BlendMethod::ConformalProjected => "skin_conformal_projected",
    }
}

/// A bound blend on the GPU ([`GpuBlend::bind`] once, [`GpuBlend::pose`] per frame). Same
/// results as [`BoundBlend::pose`] in `f32`; bound with [`GpuBlend::bind_control`], a
/// positional lattice or cage gives what [`ControlBinding::pose_using`] and
/// [`ControlBinding::pose_points`] give.
#[derive(Debug)]
pub struct GpuBlend {
    form: ControlForm,
    /// The rest control points of the positional form (empty otherwise).
    rest_points: Vec<DVec3>,
    /// The control points moved by the keys, reused from pose to pose.
    moved: Vec<DVec3>,
    vertices: usize,
    width: usize,
    key_count: usize,
    pipeline: wgpu::ComputePipeline,
    bind_group: wgpu::BindGroup,
    params: wgpu::Buffer,
    keys: wgpu::Buffer,
    out: wgpu::Buffer,
    staging: wgpu::Buffer,
    groups: (u32, u32),
    prepared: PreparedKeys,
    packed: Vec<f32>,
    /// `packed` as bytes, reused from pose to pose.
    packed_bytes: Vec<u8>,
    /// Two timestamps around the pass, where the device has them.
    timer: Option<Timer>,
}

/// A query set of two timestamps (start and end of the compute pass), the buffer they
/// resolve into and the buffer they are read back from.
#[derive(Debug)]
struct Timer {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    read: wgpu::Buffer,
}

impl Timer {
    fn new(device: &wgpu::Device) -> Timer {
        let buffer = |label, usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: 16,
                usage,
                mapped_at_creation: false,
            })
        };
        Timer {
            queries: device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("pass timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: 2,
            }),
            resolved: buffer(
                "timestamps",
                wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            ),
            read: buffer(
                "timestamps read back",
                wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            ),
        }
    }
}

/// Map the first `size` bytes of `buffer` (a `MAP_READ` buffer whose copy was submitted),
/// hand them to `read`, unmap.
fn read_mapped(
    device: &wgpu::Device,
    buffer: &wgpu::Buffer,
    size: u64,
    read: impl FnOnce(&[u8]),
) -> Result<(), GpuError> {
    let slice = buffer.slice(..size);
    let (tx, rx) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        let _ = tx.send(r);
    });
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    rx.recv()
        .map_err(|e| GpuError::Readback(e.to_string()))?
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    {
        let data = slice
            .get_mapped_range()
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        read(&data);
    }
    buffer.unmap();
    Ok(())
}

fn bytes_f32(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

fn bytes_u32(v: &[u32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

/// Refuses, before allocating, a buffer of `n` vertices with `width` influences or of
/// `key_count` keys larger than the device binds.
fn check_binding_sizes(
    ctx: &GpuContext,
    n: usize,
    width: usize,
    key_count: usize,
) -> Result<(), GpuError> {
    let limits = ctx.device.limits();
    let largest = (n * width * 4).max(n * 12).max(key_count * 64) as u64;
    if largest > limits.max_storage_buffer_binding_size {
        return Err(GpuError::TooLarge(format!(
            "a buffer of {largest} bytes, the device binds at most {}",
            limits.max_storage_buffer_binding_size
        )));
    }
    Ok(())
}

/// The skinning shader (the generated `f32` CGA in WGSL and `skin.wgsl`) compiled at `entry`.
fn skin_pipeline(device: &wgpu::Device, entry: &str) -> wgpu::ComputePipeline {
    let source = format!("{}\n{}", cga::f32::WGSL, include_str!("skin.wgsl"));
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("deform skinning"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: None,
        module: &module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    })
}

/// A storage buffer holding `contents` (16 zero bytes when empty: a zero-sized binding is
/// invalid).
fn storage_buffer(
    device: &wgpu::Device,
    label: &str,
    contents: &[u8],
    extra: wgpu::BufferUsages,
) -> wgpu::Buffer {
    let contents = if contents.is_empty() {
        &[0u8; 16][..]
    } else {
        contents
    };
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents,
        usage: wgpu::BufferUsages::STORAGE | extra,
    })
}

/// The skinning shader's buffers, in binding order.
struct SkinBuffers {
    params: wgpu::Buffer,
    rest: wgpu::Buffer,
    joints: wgpu::Buffer,
    weights: wgpu::Buffer,
    keys: wgpu::Buffer,
    out: wgpu::Buffer,
    /// `out` read back.
    staging: wgpu::Buffer,
}

impl SkinBuffers {
    /// `weights` and the rest points `local` uploaded; room for `key_count` keys and the
    /// posed positions.
    fn new(
        device: &wgpu::Device,
        weights: &KeyWeights,
        local: &[DVec3],
        key_count: usize,
    ) -> SkinBuffers {
        let (n, width) = (weights.vertex_count(), weights.width());
        let mut joints = Vec::with_capacity(n * width);
        let mut w = Vec::with_capacity(n * width);
        for i in 0..n {
            for (k, x) in weights.row(i).pairs() {
                joints.push(k as u32);
                w.push(x as f32);
            }
        }
        let rest: Vec<f32> = local
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        let none = wgpu::BufferUsages::empty();
        let out_size = (n * 12).max(16) as u64;
        let plain = |label, size, usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage,
                mapped_at_creation: false,
            })
        };
        use wgpu::BufferUsages as U;
        SkinBuffers {
            params: plain("params", 16, U::UNIFORM | U::COPY_DST),
            rest: storage_buffer(device, "rest", &bytes_f32(&rest), none),
            joints: storage_buffer(device, "joints", &bytes_u32(&joints), none),
            weights: storage_buffer(device, "weights", &bytes_f32(&w), none),
            keys: storage_buffer(
                device,
                "keys",
                &vec![0u8; (key_count * 64).max(16)],
                U::COPY_DST,
            ),
            out: plain("positions", out_size, U::STORAGE | U::COPY_SRC),
            staging: plain("positions read back", out_size, U::MAP_READ | U::COPY_DST),
        }
    }

    /// The bind group of `pipeline` over these buffers (the positional entry point reads no
    /// rest point, so its layout has no binding 1).
    fn bind_group(
        &self,
        device: &wgpu::Device,
        pipeline: &wgpu::ComputePipeline,
        form: ControlForm,
    ) -> wgpu::BindGroup {
        let layout = pipeline.get_bind_group_layout(0);
        let buffers = [
            &self.params,
            &self.rest,
            &self.joints,
            &self.weights,
            &self.keys,
            &self.out,
        ];
        let entries: Vec<wgpu::BindGroupEntry> = buffers
            .into_iter()
            .enumerate()
            .filter(|&(i, _)| i != 1 || form != ControlForm::Positional)
            .map(|(i, b)| wgpu::BindGroupEntry {
                binding: i as u32,
                resource: b.as_entire_binding(),
            })
            .collect();
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("skinning"),
            layout: &layout,
            entries: &entries,
        })
    }
}

impl GpuBlend {
    /// Upload `blend`'s rest points and weights and build its pipeline.
    ///
    /// # Errors
    /// [`GpuError::TooLarge`] when a buffer exceeds the device's limits.
    pub fn bind(ctx: &GpuContext, blend: &BoundBlend) -> Result<GpuBlend, GpuError> {
        let form = ControlForm::Motor(blend.method());
        Self::upload(ctx, form, blend.weights(), blend.local(), blend.key_count())
    }

    /// Upload a lattice's or cage's binding: its motor form as [`GpuBlend::bind`] does, its
    /// positional form as weights summing the control points.
    ///
    /// # Errors
    /// As [`GpuBlend::bind`].
    pub fn bind_control(ctx: &GpuContext, binding: &ControlBinding) -> Result<GpuBlend, GpuError> {
        if let Some(blend) = binding.motor_blend() {
            return Self::bind(ctx, blend);
        }
        let rest = binding.rest_points();
        let mut gpu = Self::upload(
            ctx,
            ControlForm::Positional,
            binding.weights(),
            &[],
            rest.len(),
        )?;
        gpu.rest_points = rest.to_vec();
        Ok(gpu)
    }

    /// The buffers and pipeline of `form` for `weights` (`key_count` keys) and the rest points
    /// `local` (none for the positional form).
    fn upload(
        ctx: &GpuContext,
        form: ControlForm,
        weights: &KeyWeights,
        local: &[DVec3],
        key_count: usize,
    ) -> Result<GpuBlend, GpuError> {
        let (n, width) = (weights.vertex_count(), weights.width());
        check_binding_sizes(ctx, n, width, key_count)?;
        let device = &ctx.device;
        let pipeline = skin_pipeline(device, entry_point(form));
        let buffers = SkinBuffers::new(device, weights, local, key_count);
        let bind_group = buffers.bind_group(device, &pipeline, form);
        let groups_total = (n as u32).div_ceil(GROUP).max(1);
        let groups = (
            groups_total.min(ROW_GROUPS),
            groups_total.div_ceil(ROW_GROUPS),
        );
        Ok(GpuBlend {
            form,
            rest_points: Vec::new(),
            moved: Vec::new(),
            vertices: n,
            width,
            key_count,
            pipeline,
            bind_group,
            params: buffers.params,
            keys: buffers.keys,
            out: buffers.out,
            staging: buffers.staging,
            groups,
            prepared: PreparedKeys::default(),
            packed: Vec::new(),
            packed_bytes: Vec::new(),
            timer: ctx.timestamps.then(|| Timer::new(device)),
        })
    }

    /// The form: the blend method of a [`BoundBlend`] or a lattice's or cage's motor form, or
    /// the positional form.
    pub fn form(&self) -> ControlForm {
        self.form
    }

    /// `out[i]` = vertex `i` posed by `keys`, computed on the GPU and read back
    /// ([`GpuBlend::run`] then [`GpuBlend::read_back`]).
    ///
    /// # Errors
    /// [`GpuError::Blend`] for keys that are not finite scaled motors, a key count or an `out`
    /// length that does not fit the bound blend (`out` is then untouched);
    /// [`GpuError::Readback`] when the device fails.
    pub fn pose(
        &mut self,
        ctx: &GpuContext,
        keys: &[ScaledMotor],
        out: &mut [DVec3],
    ) -> Result<(), GpuError> {
        crate::blend::check_positions(self.vertices, out.len())?;
        self.run(ctx, keys)?;
        self.read_back(ctx, out)
    }

    /// Upload `keys`, pose every vertex on the GPU and wait for it; the positions stay in
    /// [`GpuBlend::positions`] (three `f32` per vertex) for drawing or [`GpuBlend::read_back`].
    ///
    /// # Errors
    /// As [`GpuBlend::pose`].
    pub fn run(&mut self, ctx: &GpuContext, keys: &[ScaledMotor]) -> Result<(), GpuError> {
        self.pose_pass(ctx, keys, false).map(|_| ())
    }

    /// [`GpuBlend::run`], and the milliseconds the compute pass took on the device (between
    /// timestamps written at its start and end: no upload, submit or wait), or `None` where
    /// the device has no timestamps ([`GpuContext::has_timestamps`]).
    ///
    /// # Errors
    /// As [`GpuBlend::run`].
    pub fn run_timed(
        &mut self,
        ctx: &GpuContext,
        keys: &[ScaledMotor],
    ) -> Result<Option<f64>, GpuError> {
        self.pose_pass(ctx, keys, true)
    }

    /// Upload `keys` (or the control points they move), run the pass, timed if asked.
    fn pose_pass(
        &mut self,
        ctx: &GpuContext,
        keys: &[ScaledMotor],
        timed: bool,
    ) -> Result<Option<f64>, GpuError> {
        crate::blend::check_key_count("this deformer", self.key_count, keys.len())?;
        let ControlForm::Motor(method) = self.form else {
            let mut moved = std::mem::take(&mut self.moved);
            move_points(&self.rest_points, keys, &mut moved)?;
            let r = self.points_pass(ctx, &moved, timed);
            self.moved = moved;
            return r;
        };
        self.prepared.prepare(keys, method)?;
        self.prepared.pack_f32(&mut self.packed);
        self.dispatch(ctx, self.prepared.scaled(), timed)
    }

    /// The positional form with the control points given: `p_i = sum_j w_ij P_j` on the GPU
    /// (then [`GpuBlend::positions`] or [`GpuBlend::read_back`]).
    ///
    /// # Errors
    /// [`GpuError::Blend`] for a form other than positional, or control points of the wrong
    /// count or not finite.
    pub fn run_points(&mut self, ctx: &GpuContext, control: &[DVec3]) -> Result<(), GpuError> {
        self.points_pass(ctx, control, false).map(|_| ())
    }

    /// [`GpuBlend::run_points`], timed if asked (as [`GpuBlend::run_timed`]).
    fn points_pass(
        &mut self,
        ctx: &GpuContext,
        control: &[DVec3],
        timed: bool,
    ) -> Result<Option<f64>, GpuError> {
        if self.form != ControlForm::Positional {
            return Err(
                crate::blend::BlendError::Mesh(crate::mesh::MeshError::InvalidArgument(format!(
                    "control points given to the {} form",
                    self.form.name()
                )))
                .into(),
            );
        }
        check_points(self.key_count, control)?;
        // Each point in the 16 floats of a key (the shader reads the first three).
        self.packed.clear();
        for p in control {
            let mut a = [0.0f32; 16];
            a[..3].copy_from_slice(&[p.x as f32, p.y as f32, p.z as f32]);
            self.packed.extend_from_slice(&a);
        }
        self.dispatch(ctx, false, timed)
    }

    /// [`GpuBlend::run_points`] then [`GpuBlend::read_back`].
    ///
    /// # Errors
    /// As both.
    pub fn pose_points(
        &mut self,
        ctx: &GpuContext,
        control: &[DVec3],
        out: &mut [DVec3],
    ) -> Result<(), GpuError> {
        crate::blend::check_positions(self.vertices, out.len())?;
        self.run_points(ctx, control)?;
        self.read_back(ctx, out)
    }

    /// Upload the packed keys and the parameters, run the pass and wait for it; its device
    /// time when `timed` and the device has timestamps.
    fn dispatch(
        &mut self,
        ctx: &GpuContext,
        scaled: bool,
        timed: bool,
    ) -> Result<Option<f64>, GpuError> {
        let (queue, device) = (&ctx.queue, &ctx.device);
        if !self.packed.is_empty() {
            self.packed_bytes.clear();
            self.packed_bytes
                .extend(self.packed.iter().flat_map(|x| x.to_le_bytes()));
            queue.write_buffer(&self.keys, 0, &self.packed_bytes);
        }
        let params = [
            self.vertices as u32,
            self.width as u32,
            self.groups.0 * GROUP,
            u32::from(scaled),
        ];
        queue.write_buffer(&self.params, 0, &bytes_u32(&params));
        let timer = self.timer.as_ref().filter(|_| timed);
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("pose"),
                timestamp_writes: timer.map(|t| wgpu::ComputePassTimestampWrites {
                    query_set: &t.queries,
                    beginning_of_pass_write_index: Some(0),
                    end_of_pass_write_index: Some(1),
                }),
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &self.bind_group, &[]);
            pass.dispatch_workgroups(self.groups.0, self.groups.1, 1);
        }
        if let Some(t) = timer {
            encoder.resolve_query_set(&t.queries, 0..2, &t.resolved, 0);
            encoder.copy_buffer_to_buffer(&t.resolved, 0, &t.read, 0, 16);
        }
        queue.submit([encoder.finish()]);
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        let Some(t) = timer else {
            return Ok(None);
        };
        let mut ticks = [0u64; 2];
        read_mapped(device, &t.read, 16, |data| {
            for (x, c) in ticks.iter_mut().zip(data.chunks_exact(8)) {
                *x = u64::from_le_bytes(c.try_into().expect("8 bytes"));
            }
        })?;
        let ns = ticks[1].saturating_sub(ticks[0]) as f64 * f64::from(queue.get_timestamp_period());
        Ok(Some(ns * 1e-6))
    }

    /// The posed positions on the GPU (`x, y, z` as `f32` per vertex) after
    /// [`GpuBlend::run`].
    pub fn positions(&self) -> &wgpu::Buffer {
        &self.out
    }

    /// Copy the positions of the last [`GpuBlend::run`] into `out`.
    ///
    /// # Errors
    /// [`GpuError::Blend`] for an `out` of the wrong length (untouched then), or for a posed
    /// vertex that is not finite in single precision (as the CPU's poses, naming it);
    /// [`GpuError::Readback`] when the device fails.
    pub fn read_back(&self, ctx: &GpuContext, out: &mut [DVec3]) -> Result<(), GpuError> {
        crate::blend::check_positions(self.vertices, out.len())?;
        let size = (self.vertices * 12) as u64;
        if size == 0 {
            return Ok(());
        }
        let device = &ctx.device;
        let mut encoder = device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(&self.out, 0, &self.staging, 0, size);
        ctx.queue.submit([encoder.finish()]);
        read_mapped(device, &self.staging, size, |data| {
            for (o, c) in out.iter_mut().zip(data.chunks_exact(12)) {
                let f =
                    |k: usize| f64::from(f32::from_le_bytes([c[k], c[k + 1], c[k + 2], c[k + 3]]));
                *o = DVec3::new(f(0), f(4), f(8));
            }
        })?;
        Ok(crate::blend::finite_pose(
            crate::blend::all_finite(out),
            out,
        )?)
    }

    /// Bytes one pose reads and writes in device memory, not counting the keys (which stay in
    /// cache): per vertex its rest point (12), `width` joint indices and weights (8 each) and
    /// its result (12). Over the device's memory bandwidth this is the least time a pose can
    /// take.
    pub fn bytes_per_pose(&self) -> usize {
        self.vertices * (24 + 8 * self.width)
    }
}
