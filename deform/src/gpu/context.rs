//! The GPU device: one adapter (the first wgpu offers, preferring a real GPU) and its queue.

use super::GpuError;

/// A wgpu device and queue, made once and shared by every bound blend.
pub struct GpuContext {
    pub(super) device: wgpu::Device,
    pub(super) queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    /// Whether the device writes timestamps around compute passes.
    pub(super) timestamps: bool,
}

impl std::fmt::Debug for GpuContext {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GpuContext")
            .field("adapter", &self.info.name)
            .field("backend", &self.info.backend)
            .finish()
    }
}

impl GpuContext {
    /// The high-performance adapter wgpu finds (Vulkan, Metal, DX12 or GL), or a software one
    /// (Mesa's lavapipe) when there is no GPU.
    ///
    /// # Errors
    /// [`GpuError::NoAdapter`] when there is none, [`GpuError::Device`] when it refuses.
    pub fn new() -> Result<GpuContext, GpuError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|e| GpuError::NoAdapter(e.to_string()))?;
        let info = adapter.get_info();
        // The adapter's own limits: the shader binds five storage buffers, above the
        // downlevel default of four, and large meshes need its buffer sizes.
        let limits = adapter.limits();
        if limits.max_storage_buffers_per_shader_stage < 5 {
            return Err(GpuError::Device(format!(
                "{}: binds {} storage buffers per shader stage, the skinning shader needs 5",
                info.name, limits.max_storage_buffers_per_shader_stage
            )));
        }
        // Timestamps around compute passes where the adapter has them (for
        // `GpuBlend::run_timed`: the pass alone, without the submit and wait).
        let timestamps = adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("deform"),
            required_limits: limits,
            required_features: if timestamps {
                wgpu::Features::TIMESTAMP_QUERY
            } else {
                wgpu::Features::empty()
            },
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(e.to_string()))?;
        Ok(GpuContext {
            device,
            queue,
            info,
            timestamps,
        })
    }

    /// The adapter's name and backend (`llvmpipe (LLVM 15.0.6, 256 bits) on Vulkan`).
    pub fn adapter(&self) -> String {
        format!("{} on {:?}", self.info.name, self.info.backend)
    }

    /// The device, to run other shaders (the generated WGSL of [`cga::f32::WGSL`]) on it.
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The device's queue.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// Whether the device times compute passes (`GpuBlend::run_timed`).
    pub fn has_timestamps(&self) -> bool {
        self.timestamps
    }

    /// Whether the adapter is a software rasteriser (lavapipe, WARP) rather than a GPU.
    pub fn is_software(&self) -> bool {
        self.info.device_type == wgpu::DeviceType::Cpu
    }
}
