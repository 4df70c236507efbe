//! The generated WGSL against the generated Rust f32 products on random inputs: each kernel
//! runs the WGSL functions on the device and the same generated functions on the CPU, and the
//! two must agree to f32 rounding.

use super::*;

/// The generated WGSL (`cga::f32::WGSL`, the same spec as `cga::f32`) run on the GPU agrees
/// with the generated Rust f32 functions on random inputs: the geometric product of motors,
/// the fused sandwich of points and its matrix form.
#[test]
fn generated_wgsl_agrees_with_generated_rust() {
    use cga::f32::{Motor, Point, Sandwich};
    let Some(ctx) = context() else { return };
    let n = 4096usize;
    // A small deterministic generator of values in [-1, 1).
    let mut next = uniform(0x9e37_79b9_7f4a_7c15u64);
    // Unit motors: a normalised rotor part, and the `e123i` that the versor condition
    // `M ~M = 1` asks for (`s e123i = e12 e3i - e13 e2i + e23 e1i`).
    let mut motor = || {
        let m = Motor::new(next(), next(), next(), next(), next(), next(), next(), 0.0);
        let r = 1.0 / (m.s * m.s + m.e12 * m.e12 + m.e13 * m.e13 + m.e23 * m.e23).sqrt();
        let m = Motor::from_array(m.to_array().map(|c| c * r));
        let e123i = (m.e12 * m.e3i - m.e13 * m.e2i + m.e23 * m.e1i) / m.s;
        Motor { e123i, ..m }
    };
    let a: Vec<Motor> = (0..n).map(|_| motor()).collect();
    let b: Vec<Motor> = (0..n).map(|_| motor()).collect();
    let mut point = || {
        let (x, y, z) = (next(), next(), next());
        Point::new(x, y, z, 0.5 * (x * x + y * y + z * z))
    };
    let p: Vec<Point> = (0..n).map(|_| point()).collect();
    let floats = |v: Vec<[f32; 8]>| -> Vec<u8> {
        v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect()
    };
    let pts: Vec<u8> = p
        .iter()
        .flat_map(|q| [q.e1, q.e2, q.e3, q.ei])
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let shader = r#"
@group(0) @binding(0) var<storage, read> ma: array<Motor>;
@group(0) @binding(1) var<storage, read> mb: array<Motor>;
@group(0) @binding(2) var<storage, read> pts: array<Point>;
@group(0) @binding(3) var<storage, read_write> out_m: array<Motor>;
@group(0) @binding(4) var<storage, read_write> out_p: array<Point>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&ma) {
        return;
    }
    out_m[i] = motor_gp_motor(ma[i], mb[i]);
    out_p[2u * i] = motor_sandwich_point(ma[i], pts[i]);
    out_p[2u * i + 1u] = motor_point_matrix_apply(motor_point_matrix(ma[i]), pts[i]);
}
"#;
    let inputs = [
        floats(a.iter().map(|m| m.to_array()).collect()),
        floats(b.iter().map(|m| m.to_array()).collect()),
        pts,
    ];
    let out = run_kernel(&ctx, shader, &inputs, &[n * 32, 2 * n * 16], n as u32);
    let (gm, gp) = (&out[0], &out[1]);
    let close = |what: &str, i: usize, got: &[f32], want: &[f32]| {
        for (g, w) in got.iter().zip(want) {
            assert!(
                (g - w).abs() <= 1e-5 * (1.0 + w.abs()),
                "{what} {i}: WGSL {got:?}, Rust {want:?}"
            );
        }
    };
    for i in 0..n {
        close(
            "motor_gp_motor",
            i,
            &gm[8 * i..8 * i + 8],
            &(a[i] * b[i]).to_array(),
        );
        let s: Point = a[i].sandwich(p[i]);
        let want = [s.e1, s.e2, s.e3, s.ei];
        close("motor_sandwich_point", i, &gp[8 * i..8 * i + 4], &want);
        close(
            "motor_point_matrix_apply",
            i,
            &gp[8 * i + 4..8 * i + 8],
            &want,
        );
    }
}

/// A deterministic generator of `f32`s in `[-1, 1)` (a linear congruential one).
fn uniform(seed: u64) -> impl FnMut() -> f32 {
    let mut state = seed;
    move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 40) as f32 / (1u64 << 24) as f32) * 2.0 - 1.0
    }
}

/// Run `main` of `shader` (the generated CGA WGSL prepended) once per element over storage
/// buffers: `inputs` at bindings 0.., then one output of each size in bytes; the outputs read
/// back as `f32`s.
fn run_kernel(
    ctx: &GpuContext,
    shader: &str,
    inputs: &[Vec<u8>],
    outputs: &[usize],
    n: u32,
) -> Vec<Vec<f32>> {
    use wgpu::util::DeviceExt as _;
    let device = ctx.device();
    let source = format!("{}\n{shader}", cga::f32::WGSL);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: None,
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: None,
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let mut buffers: Vec<wgpu::Buffer> = inputs
        .iter()
        .map(|b| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: None,
                contents: b,
                usage: wgpu::BufferUsages::STORAGE,
            })
        })
        .collect();
    let make = |size: usize, usage| {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: size as u64,
            usage,
            mapped_at_creation: false,
        })
    };
    let read = wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST;
    let back: Vec<wgpu::Buffer> = outputs.iter().map(|&s| make(s, read)).collect();
    for &s in outputs {
        buffers.push(make(
            s,
            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        ));
    }
    let layout = pipeline.get_bind_group_layout(0);
    let entries: Vec<wgpu::BindGroupEntry> = buffers
        .iter()
        .enumerate()
        .map(|(i, b)| wgpu::BindGroupEntry {
            binding: i as u32,
            resource: b.as_entire_binding(),
        })
        .collect();
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout,
        entries: &entries,
    });
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.dispatch_workgroups(n.div_ceil(64), 1, 1);
    }
    for (k, &s) in outputs.iter().enumerate() {
        enc.copy_buffer_to_buffer(&buffers[inputs.len() + k], 0, &back[k], 0, s as u64);
    }
    ctx.queue().submit([enc.finish()]);
    for b in &back {
        b.slice(..)
            .map_async(wgpu::MapMode::Read, |r| r.expect("map"));
    }
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("poll");
    back.iter()
        .map(|b| {
            let data = b.slice(..).get_mapped_range().expect("mapped");
            data.chunks_exact(4)
                .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                .collect()
        })
        .collect()
}

/// The generated closed-form exponentials in WGSL against the generated Rust f32 ones, on
/// random bivectors over every scale from 1e-6 to 1 (small angles and dilations are where a
/// GPU's `sin` and `sinh` lose their relative precision; the WGSL helpers use series there).
#[test]
fn generated_wgsl_exp_agrees_with_generated_rust() {
    use cga::f32::{Bivector, Exp, Motor, ScaledMotor};
    let Some(ctx) = context() else { return };
    let n = 2048usize;
    let mut next = uniform(0x51f1_5eed_u64);
    let b: Vec<Bivector> = (0..n)
        .map(|i| {
            let scale = 10f32.powf(-6.0 * (i % 7) as f32 / 6.0);
            // Similarity generators: rotation, translation, dilation (no transversion).
            let mut v = Bivector::default();
            (v.e12, v.e13, v.e23) = (next() * scale, next() * scale, next() * scale);
            (v.e1i, v.e2i, v.e3i) = (next(), next(), next());
            v.eoi = next() * scale;
            v
        })
        .collect();
    let input: Vec<u8> = b
        .iter()
        .flat_map(|v| v.to_array())
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let shader = r#"
@group(0) @binding(0) var<storage, read> bv: array<Bivector>;
@group(0) @binding(1) var<storage, read_write> out_s: array<ScaledMotor>;
@group(0) @binding(2) var<storage, read_write> out_m: array<Motor>;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&bv) {
        return;
    }
    out_s[i] = bivector_exp_scaled_motor(bv[i]);
    out_m[i] = bivector_exp_motor(bv[i]);
}
"#;
    let out = run_kernel(&ctx, shader, &[input], &[n * 48, n * 32], n as u32);
    for (i, v) in b.iter().enumerate() {
        let s: ScaledMotor = v.exp();
        let m: Motor = v.exp();
        for (what, got, want) in [
            ("scaled", &out[0][12 * i..12 * i + 12], &s.to_array()[..]),
            ("motor", &out[1][8 * i..8 * i + 8], &m.to_array()[..]),
        ] {
            for (g, w) in got.iter().zip(want) {
                assert!(
                    (g - w).abs() <= 2e-6 * (1.0 + w.abs()),
                    "{what} exp {i} of {v:?}: WGSL {got:?}, Rust {want:?}"
                );
            }
        }
    }
}
