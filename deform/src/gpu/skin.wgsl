// Skinning and key blending on the GPU, one invocation per vertex. Written once against the
// generated CGA functions (`cga::f32::WGSL`, prepended): `motor_gp_motor`, `motor_rev`, the
// fused `motor_sandwich_point` and `scaled_motor_sandwich_point` and the closed-form
// `bivector_exp_scaled_motor` are the generator's, not copies.
//
// Buffers (filled by `deform::gpu::GpuBlend`): per vertex its rest point in the frame of its
// rest transform (3 floats) and `width` (key, weight) pairs; per key 16 floats packed by
// `PreparedKeys::pack_f32` (the layout of each method is written at its entry point).

struct Params {
    n: u32,
    width: u32,
    // Invocations per row of the dispatch grid (x groups times 64).
    row: u32,
    // Whether any key scales (motor and dual-quaternion blending blend the log-scales).
    scaled: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> rest: array<f32>;
@group(0) @binding(2) var<storage, read> joints: array<u32>;
@group(0) @binding(3) var<storage, read> weights: array<f32>;
@group(0) @binding(4) var<storage, read> keys: array<f32>;
@group(0) @binding(5) var<storage, read_write> out: array<f32>;

fn vertex_index(id: vec3<u32>) -> u32 {
    return id.y * params.row + id.x;
}

fn rest_point(i: u32) -> vec3<f32> {
    return vec3<f32>(rest[3u * i], rest[3u * i + 1u], rest[3u * i + 2u]);
}

fn key(k: u32, c: u32) -> f32 {
    return keys[16u * k + c];
}

fn store(i: u32, p: vec3<f32>) {
    out[3u * i] = p.x;
    out[3u * i + 1u] = p.y;
    out[3u * i + 2u] = p.z;
}

// exp(sum w log s): the geometric blend of the key scales (log-scale at float 8).
fn blended_scale(base: u32) -> f32 {
    if params.scaled == 0u {
        return 1.0;
    }
    var ls = 0.0;
    for (var j = 0u; j < params.width; j++) {
        ls += weights[base + j] * key(joints[base + j], 8u);
    }
    return exp(ls);
}

// The weight of pair `j`, negated when its key (floats 0..3) is in the other hemisphere from
// the row's first key.
fn aligned_weight(base: u32, j: u32) -> f32 {
    let k = joints[base + j];
    let k0 = joints[base];
    let d = key(k, 0u) * key(k0, 0u) + key(k, 1u) * key(k0, 1u) + key(k, 2u) * key(k0, 2u)
        + key(k, 3u) * key(k0, 3u);
    let w = weights[base + j];
    return select(w, -w, d < 0.0);
}

// Log blending, the papers' equation (1): keys are the logarithms of the (scaled) motors
// (bivectors: eo1, eo2, eo3, eoi, e12, e13, e23, e1i, e2i, e3i); exp(sum w log M) by the
// generated closed-form exponential, applied by the generated fused sandwich, down-projected.
@compute @workgroup_size(64)
fn skin_log(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = vertex_index(id);
    if i >= params.n {
        return;
    }
    let base = i * params.width;
    var b: array<f32, 10>;
    for (var j = 0u; j < params.width; j++) {
        let w = weights[base + j];
        let k = joints[base + j];
        for (var c = 0u; c < 10u; c++) {
            b[c] += w * key(k, c);
        }
    }
    let m = bivector_exp_scaled_motor(
        Bivector(b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], b[8], b[9]),
    );
    let p = rest_point(i);
    let x = scaled_motor_sandwich_point(m, Point(p.x, p.y, p.z, 0.5 * dot(p, p)));
    store(i, vec3<f32>(x.e1, x.e2, x.e3) / x.eo);
}

// Motor blending: keys are motors (s, e12, e13, e23, e1i, e2i, e3i, e123i; log-scale at 8);
// normalise(sum w M) (divided by the rotor norm, as `Motor::normalize_for_points`), then the
// generated fused sandwich of the (scaled) conformal point.
@compute @workgroup_size(64)
fn skin_motor(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = vertex_index(id);
    if i >= params.n {
        return;
    }
    let base = i * params.width;
    var m: array<f32, 8>;
    for (var j = 0u; j < params.width; j++) {
        let w = aligned_weight(base, j);
        let k = joints[base + j];
        for (var c = 0u; c < 8u; c++) {
            m[c] += w * key(k, c);
        }
    }
    var mot = Motor(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7]);
    let n2 = motor_gp_motor(mot, motor_rev(mot)).s;
    if n2 > 1e-30 {
        let r = inverseSqrt(n2);
        mot = Motor(m[0] * r, m[1] * r, m[2] * r, m[3] * r, m[4] * r, m[5] * r, m[6] * r, m[7] * r);
    } else {
        mot = Motor(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    }
    let p = blended_scale(base) * rest_point(i);
    let x = motor_sandwich_point(mot, Point(p.x, p.y, p.z, 0.5 * dot(p, p)));
    store(i, vec3<f32>(x.e1, x.e2, x.e3));
}

fn qmul(a: vec4<f32>, b: vec4<f32>) -> vec4<f32> {
    return vec4<f32>(
        a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz),
        a.w * b.w - dot(a.xyz, b.xyz),
    );
}

// Kavan's dual-quaternion blending: keys are (q.xyzw, d.xyzw; log-scale at 8).
@compute @workgroup_size(64)
fn skin_dual_quaternion(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = vertex_index(id);
    if i >= params.n {
        return;
    }
    let base = i * params.width;
    var r = vec4<f32>(0.0);
    var d = vec4<f32>(0.0);
    for (var j = 0u; j < params.width; j++) {
        let w = aligned_weight(base, j);
        let k = joints[base + j];
        r += w * vec4<f32>(key(k, 0u), key(k, 1u), key(k, 2u), key(k, 3u));
        d += w * vec4<f32>(key(k, 4u), key(k, 5u), key(k, 6u), key(k, 7u));
    }
    let n = 1.0 / length(r);
    r *= n;
    d *= n;
    let t = 2.0 * qmul(d, vec4<f32>(-r.xyz, r.w)).xyz;
    let p = blended_scale(base) * rest_point(i);
    let u = cross(r.xyz, p);
    store(i, p + 2.0 * (r.w * u + cross(r.xyz, u)) + t);
}

// Matrix LBS: keys are 3x4 affine maps (columns x, y, z, translation).
@compute @workgroup_size(64)
fn skin_matrix(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = vertex_index(id);
    if i >= params.n {
        return;
    }
    let base = i * params.width;
    var a: array<f32, 12>;
    for (var j = 0u; j < params.width; j++) {
        let w = weights[base + j];
        let k = joints[base + j];
        for (var c = 0u; c < 12u; c++) {
            a[c] += w * key(k, c);
        }
    }
    let p = rest_point(i);
    store(i, vec3<f32>(a[0], a[1], a[2]) * p.x + vec3<f32>(a[3], a[4], a[5]) * p.y
        + vec3<f32>(a[6], a[7], a[8]) * p.z + vec3<f32>(a[9], a[10], a[11]));
}

// Equation (17), adding first: keys are the rows e1, e2, e3 (columns x, y, z, 1) of the
// sandwich's point matrix and its constant eo coefficient (float 12).
@compute @workgroup_size(64)
fn skin_conformal(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = vertex_index(id);
    if i >= params.n {
        return;
    }
    let base = i * params.width;
    var a: array<f32, 13>;
    for (var j = 0u; j < params.width; j++) {
        let w = weights[base + j];
        let k = joints[base + j];
        for (var c = 0u; c < 13u; c++) {
            a[c] += w * key(k, c);
        }
    }
    let p = vec4<f32>(rest_point(i), 1.0);
    let e = vec3<f32>(
        dot(vec4<f32>(a[0], a[1], a[2], a[3]), p),
        dot(vec4<f32>(a[4], a[5], a[6], a[7]), p),
        dot(vec4<f32>(a[8], a[9], a[10], a[11]), p),
    );
    store(i, e / a[12]);
}

// Equation (17), down-projecting each term first (same keys as `skin_conformal`).
@compute @workgroup_size(64)
fn skin_conformal_projected(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = vertex_index(id);
    if i >= params.n {
        return;
    }
    let base = i * params.width;
    let p = vec4<f32>(rest_point(i), 1.0);
    var acc = vec3<f32>(0.0);
    for (var j = 0u; j < params.width; j++) {
        let w = weights[base + j];
        let k = joints[base + j];
        let e = vec3<f32>(
            dot(vec4<f32>(key(k, 0u), key(k, 1u), key(k, 2u), key(k, 3u)), p),
            dot(vec4<f32>(key(k, 4u), key(k, 5u), key(k, 6u), key(k, 7u)), p),
            dot(vec4<f32>(key(k, 8u), key(k, 9u), key(k, 10u), key(k, 11u)), p),
        );
        acc += w * e / key(k, 12u);
    }
    store(i, acc);
}

// Positional lattices and cages: the control points (floats 0..2 of each key) summed with the
// vertex's weights, `p = sum w P` (the classic FFD and cage deformers).
@compute @workgroup_size(64)
fn control_positional(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = vertex_index(id);
    if i >= params.n {
        return;
    }
    let base = i * params.width;
    var p = vec3<f32>(0.0, 0.0, 0.0);
    for (var j = 0u; j < params.width; j++) {
        let k = joints[base + j];
        p += weights[base + j] * vec3<f32>(key(k, 0u), key(k, 1u), key(k, 2u));
    }
    store(i, p);
}
