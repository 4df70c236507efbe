//! Characters from the wild (issue 45), as generated fixtures: each reproduces one property
//! that real exporters leave in skinned glTF files (f32 noise in inverse binds, non-uniform and
//! mirrored joint scale, meshopt compression, quantised positions, a thousand primitives,
//! skins shared and several, no animation, a centimetre Z-up armature, sparse accessors, morph
//! targets, Draco). Each
//! is loaded by `parse_gltf` and skinned with the exact matrices (`lbs`) against an
//! independent evaluator of glTF's skinning formula written here on the JSON (three.js's
//! `boneMatrices = world * inverse bind`, weights normalised, morph targets at their default
//! weights applied first); written back as `.glb` for the
//! validator, and cut, with the cut rig still posed finite.

mod encoded;
mod properties;

use crate::gltf_out;
use deform::skinning::{glb_bytes, parse_gltf, GlbOptions, Rig, Skinning};
use deform::surgery::{CutOptions, Frame, Surgery};
use deform::BlendMethod;
use glam::{DMat4, DQuat, DVec3};
use serde_json::{json, Value};

/// A fixture: the glTF JSON and its binary buffer, assembled into a `.glb`.
struct Fixture {
    json: Value,
    bin: Vec<u8>,
}

impl Fixture {
    fn new() -> Fixture {
        Fixture {
            json: json!({"asset": {"version": "2.0"}, "buffers": [], "bufferViews": [],
                         "accessors": [], "nodes": [], "meshes": [], "skins": [],
                         "scenes": [{"nodes": [0]}], "scene": 0}),
            bin: Vec::new(),
        }
    }

    /// Append `bytes` as a buffer view; its index.
    fn view(&mut self, bytes: &[u8], stride: Option<usize>) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let mut v = json!({"buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len()});
        if let Some(s) = stride {
            v["byteStride"] = json!(s);
        }
        self.bin.extend_from_slice(bytes);
        push(&mut self.json["bufferViews"], v)
    }

    /// An accessor over a new view of `bytes`.
    fn accessor(&mut self, bytes: &[u8], component: u32, kind: &str, count: usize) -> usize {
        let view = self.view(bytes, None);
        let a = json!({"bufferView": view, "componentType": component, "type": kind,
                       "count": count});
        push(&mut self.json["accessors"], a)
    }

    fn floats(&mut self, v: &[f32], kind: &str, count: usize) -> usize {
        let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
        let a = self.accessor(&bytes, 5126, kind, count);
        if kind == "VEC3" {
            let (lo, hi) = bounds(v);
            self.json["accessors"][a]["min"] = json!(lo);
            self.json["accessors"][a]["max"] = json!(hi);
        }
        a
    }

    fn node(&mut self, n: Value) -> usize {
        push(&mut self.json["nodes"], n)
    }

    fn glb(&self) -> Vec<u8> {
        let mut json = self.json.clone();
        json["buffers"] = json!([{"byteLength": self.bin.len()}]);
        let mut text = serde_json::to_vec(&json).unwrap();
        while !text.len().is_multiple_of(4) {
            text.push(b' ');
        }
        let mut bin = self.bin.clone();
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let total = 12 + 8 + text.len() + 8 + bin.len();
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(text.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&text);
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
        out
    }
}

fn push(list: &mut Value, v: Value) -> usize {
    let a = list.as_array_mut().unwrap();
    a.push(v);
    a.len() - 1
}

fn bounds(v: &[f32]) -> ([f32; 3], [f32; 3]) {
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for p in v.chunks_exact(3) {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}

/// A bar along y (rings of 4 vertices at `rings` heights, from 0 to 2), closed at both ends:
/// positions and triangles.
fn bar(rings: usize) -> (Vec<f32>, Vec<u16>) {
    let mut p = Vec::new();
    for r in 0..rings {
        let y = 2.0 * r as f32 / (rings - 1) as f32;
        for (x, z) in [(0.2, 0.2), (-0.2, 0.2), (-0.2, -0.2), (0.2, -0.2)] {
            p.extend_from_slice(&[x, y, z]);
        }
    }
    let mut t = Vec::new();
    for r in 0..rings - 1 {
        for k in 0..4 {
            let (a, b) = ((r * 4 + k) as u16, (r * 4 + (k + 1) % 4) as u16);
            let (c, d) = (a + 4, b + 4);
            t.extend_from_slice(&[a, b, d, a, d, c]);
        }
    }
    let top = (4 * (rings - 1)) as u16;
    t.extend_from_slice(&[
        0,
        2,
        1,
        0,
        3,
        2,
        top,
        top + 1,
        top + 2,
        top,
        top + 2,
        top + 3,
    ]);
    (p, t)
}

/// Joints and weights of the bar for two joints: weight of the second = height / 2.
fn bar_influences(positions: &[f32]) -> (Vec<u8>, Vec<f32>) {
    let mut j = Vec::new();
    let mut w = Vec::new();
    for p in positions.chunks_exact(3) {
        let a = (p[1] / 2.0).clamp(0.0, 1.0);
        j.extend_from_slice(&[0, 1, 0, 0]);
        w.extend_from_slice(&[1.0 - a, a, 0.0, 0.0]);
    }
    (j, w)
}

/// Options of [`two_joint_bar`].
#[derive(Clone, Copy)]
struct Bar {
    /// The armature node's transform (scale, rotation).
    armature: (f64, DQuat),
    /// The second joint's local scale and rotation.
    joint_scale: [f32; 3],
    joint_turn: DQuat,
    /// Multiply the second joint's inverse bind matrix by this (noise, mirror).
    ibm_factor: DMat4,
    /// Copies of the mesh's primitive.
    primitives: usize,
    /// A second mesh node sharing the skin.
    shared: bool,
    /// An animation (a STEP rotation of the second joint).
    animated: bool,
}

impl Default for Bar {
    fn default() -> Bar {
        Bar {
            armature: (1.0, DQuat::IDENTITY),
            joint_scale: [1.0; 3],
            joint_turn: DQuat::IDENTITY,
            ibm_factor: DMat4::IDENTITY,
            primitives: 1,
            shared: false,
            animated: true,
        }
    }
}

/// A bar skinned to two joints under an armature node: root 0 (armature) -> joint 1 -> joint
/// 2 (at height 1); the mesh node 3 under the armature.
fn two_joint_bar(o: Bar) -> Fixture {
    let mut f = Fixture::new();
    let (pos, tri) = bar(9);
    let n = pos.len() / 3;
    let (joints, weights) = bar_influences(&pos);
    let p = f.floats(&pos, "VEC3", n);
    let idx: Vec<u8> = tri.iter().flat_map(|x| x.to_le_bytes()).collect();
    let i = f.accessor(&idx, 5123, "SCALAR", tri.len());
    let j = f.accessor(&joints, 5121, "VEC4", n);
    let w = f.floats(&weights, "VEC4", n);
    let prim = json!({"attributes": {"POSITION": p, "JOINTS_0": j, "WEIGHTS_0": w},
                      "indices": i});
    let prims: Vec<Value> = (0..o.primitives).map(|_| prim.clone()).collect();
    f.json["meshes"] = json!([{"primitives": prims}]);
    let (s, q) = o.armature;
    f.node(json!({"name": "Armature", "children": [1, 3],
                  "scale": [s, s, s], "rotation": [q.x, q.y, q.z, q.w]}));
    f.node(json!({"name": "hip", "children": [2]}));
    let t = o.joint_turn;
    f.node(json!({"name": "knee", "translation": [0.0, 1.0, 0.0],
                  "rotation": [t.x, t.y, t.z, t.w], "scale": o.joint_scale}));
    f.node(json!({"name": "body", "mesh": 0, "skin": 0}));
    if o.shared {
        f.json["nodes"][0]["children"] = json!([1, 3, 4]);
        f.node(json!({"name": "body copy", "mesh": 0, "skin": 0}));
    }
    // Inverse bind matrices: the inverse of each joint's bind-time world matrix (in the
    // armature's frame, as exporters write them), the second times `ibm_factor`.
    let armature = DMat4::from_scale_rotation_translation(DVec3::splat(s), q, DVec3::ZERO);
    let knee = DMat4::from_scale_rotation_translation(
        DVec3::from(o.joint_scale.map(f64::from)),
        t,
        DVec3::Y,
    );
    // In the mesh node's frame (under the armature too): the hip's is the identity.
    let _ = armature;
    let ibm = [DMat4::IDENTITY, knee.inverse() * o.ibm_factor];
    let values: Vec<f32> = ibm
        .iter()
        .flat_map(|m| m.to_cols_array().map(|x| x as f32))
        .collect();
    let ib = f.floats(&values, "MAT4", 2);
    f.json["skins"] = json!([{"joints": [1, 2], "inverseBindMatrices": ib}]);
    if o.animated {
        let times = f.floats(&[0.0, 1.0], "SCALAR", 2);
        let bend = DQuat::from_rotation_z(0.8);
        let keys = [t, t * bend];
        let v: Vec<f32> = keys
            .iter()
            .flat_map(|k| [k.x, k.y, k.z, k.w].map(|x| x as f32))
            .collect();
        let out = f.floats(&v, "VEC4", 2);
        f.json["animations"] = json!([{"name": "bend",
            "samplers": [{"input": times, "output": out, "interpolation": "STEP"}],
            "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]}]);
    }
    f
}

/// Accessor `a` of the fixture read as f64s (floats, unsigned shorts or bytes; no sparse).
fn read_accessor(f: &Fixture, a: usize) -> Vec<f64> {
    let j = &f.json;
    let acc = &j["accessors"][a];
    let view = &j["bufferViews"][acc["bufferView"].as_u64().unwrap() as usize];
    let off = view["byteOffset"].as_u64().unwrap() as usize;
    let len = view["byteLength"].as_u64().unwrap() as usize;
    let b = &f.bin[off..off + len];
    match acc["componentType"].as_u64().unwrap() {
        5126 => b
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
            .collect(),
        5123 => b
            .chunks_exact(2)
            .map(|c| u16::from_le_bytes([c[0], c[1]]) as f64)
            .collect(),
        5121 => b.iter().map(|&x| x as f64).collect(),
        t => panic!("component type {t}"),
    }
}

/// Each node's local matrix from its translation, rotation and scale (glTF's defaults).
fn local_matrices(nodes: &[Value]) -> Vec<DMat4> {
    nodes
        .iter()
        .map(|n| {
            let v = |k: &str, d: &[f64]| -> Vec<f64> {
                n.get(k).map_or(d.to_vec(), |a| {
                    a.as_array()
                        .unwrap()
                        .iter()
                        .map(|x| x.as_f64().unwrap())
                        .collect()
                })
            };
            let t = v("translation", &[0.0; 3]);
            let r = v("rotation", &[0.0, 0.0, 0.0, 1.0]);
            let s = v("scale", &[1.0; 3]);
            DMat4::from_scale_rotation_translation(
                DVec3::new(s[0], s[1], s[2]),
                DQuat::from_xyzw(r[0], r[1], r[2], r[3]).normalize(),
                DVec3::new(t[0], t[1], t[2]),
            )
        })
        .collect()
}

/// The first animation's rotation keys at `t` (STEP: the last key at or before `t`) set into
/// the animated nodes' local matrices.
fn apply_rotation_keys(f: &Fixture, animations: &Value, t: f64, local: &mut [DMat4]) {
    let a = animations;
    for c in a[0]["channels"].as_array().unwrap() {
        let s = &a[0]["samplers"][c["sampler"].as_u64().unwrap() as usize];
        let times = read_accessor(f, s["input"].as_u64().unwrap() as usize);
        let values = read_accessor(f, s["output"].as_u64().unwrap() as usize);
        let k = times.iter().rposition(|&x| x <= t).unwrap_or(0);
        let node = c["target"]["node"].as_u64().unwrap() as usize;
        let q = &values[4 * k..4 * k + 4];
        let (sc, _, tr) = local[node].to_scale_rotation_translation();
        let q = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).normalize();
        local[node] = DMat4::from_scale_rotation_translation(sc, q, tr);
    }
}

/// Each node's world matrix: its local matrix after its ancestors'.
fn world_matrices(nodes: &[Value], local: &[DMat4]) -> Vec<DMat4> {
    let mut parent = vec![None; nodes.len()];
    for (i, n) in nodes.iter().enumerate() {
        for c in n
            .get("children")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            parent[c.as_u64().unwrap() as usize] = Some(i);
        }
    }
    (0..nodes.len())
        .map(|mut i| {
            let mut m = local[i];
            while let Some(p) = parent[i] {
                m = local[p] * m;
                i = p;
            }
            m
        })
        .collect()
}

/// One primitive of `mesh` on `node` skinned by the `bone` matrices: morph targets at the
/// default weights (the node's, else the mesh's) first, then `sum w bone p` with the weights
/// normalised; the vertices pushed to `out`.
fn skin_primitive(
    f: &Fixture,
    (mesh, node): (usize, &Value),
    prim: &Value,
    bone: &[DMat4],
    out: &mut Vec<DVec3>,
) {
    let at = |k: &str| prim["attributes"][k].as_u64().unwrap() as usize;
    let mut p = read_accessor(f, at("POSITION"));
    let weights = node
        .get("weights")
        .or_else(|| f.json["meshes"][mesh].get("weights"));
    for (t, target) in prim
        .get("targets")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
        .enumerate()
    {
        let w = weights.map_or(0.0, |w| w[t].as_f64().unwrap());
        let d = read_accessor(f, target["POSITION"].as_u64().unwrap() as usize);
        p.iter_mut().zip(&d).for_each(|(x, d)| *x += w * d);
    }
    let jj = read_accessor(f, at("JOINTS_0"));
    let ww = read_accessor(f, at("WEIGHTS_0"));
    for v in 0..p.len() / 3 {
        let x = DVec3::new(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
        let sum: f64 = ww[4 * v..4 * v + 4].iter().sum();
        let mut y = DVec3::ZERO;
        for k in 0..4 {
            let w = ww[4 * v + k] / sum;
            y += w * bone[jj[4 * v + k] as usize].transform_point3(x);
        }
        out.push(y);
    }
}

/// glTF's skinning formula on the fixture's own JSON and buffer, independent of the
/// crate's reader: per skinned mesh node, per primitive in document order, per vertex
/// `sum w (world(joint) * inverse_bind) p` with the weights normalised (three.js's
/// `SkinnedMesh`), at the rest pose or with the animation's keys at `time` (STEP only).
fn reference_skinning(f: &Fixture, time: Option<f64>) -> Vec<DVec3> {
    let j = &f.json;
    let nodes = j["nodes"].as_array().unwrap();
    let mut local = local_matrices(nodes);
    if let (Some(t), Some(a)) = (time, j.get("animations")) {
        apply_rotation_keys(f, a, t, &mut local);
    }
    let world = world_matrices(nodes, &local);
    let mut out = Vec::new();
    let mut instances: Vec<(usize, usize)> = nodes
        .iter()
        .enumerate()
        .filter_map(|(i, n)| Some((n.get("mesh")?.as_u64()? as usize, i)))
        .collect();
    instances.sort();
    for (mesh, node) in instances {
        let skin = &j["skins"][nodes[node]["skin"].as_u64().unwrap() as usize];
        let joints: Vec<usize> = skin["joints"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as usize)
            .collect();
        let ibm = read_accessor(f, skin["inverseBindMatrices"].as_u64().unwrap() as usize);
        let bone: Vec<DMat4> = joints
            .iter()
            .enumerate()
            .map(|(k, &n)| world[n] * DMat4::from_cols_slice(&ibm[16 * k..16 * k + 16]))
            .collect();
        for prim in j["meshes"][mesh]["primitives"].as_array().unwrap() {
            skin_primitive(f, (mesh, &nodes[node]), prim, &bone, &mut out);
        }
    }
    out
}

fn diagonal(p: &[DVec3]) -> f64 {
    let lo = p.iter().fold(DVec3::INFINITY, |a, b| a.min(*b));
    let hi = p.iter().fold(DVec3::NEG_INFINITY, |a, b| a.max(*b));
    (hi - lo).length()
}

/// `rig` skinned by `method` at the rest pose or the animation's `time`.
fn skin_rig(rig: &Rig, method: BlendMethod, time: Option<f64>) -> Vec<DVec3> {
    let pose = rig.pose(time.map(|_| 0), time.unwrap_or(0.0), &[]).unwrap();
    let skin = Skinning::bind(rig, method).unwrap();
    let mut out = vec![DVec3::ZERO; rig.mesh.vertex_count()];
    skin.pose_rig(&pose, &mut skin.blend().scratch(), &mut out)
        .unwrap();
    out
}

/// Load `f`, check `lbs` against the reference at rest and at t = 1, write it back for the
/// validator, cut it through the middle at the bind pose and pose the cut rig.
fn check(name: &str, f: &Fixture) -> Rig {
    let bytes = f.glb();
    let rig = parse_gltf(&bytes, name, None).unwrap_or_else(|e| panic!("{name}: {e}"));
    let animated = !rig.animations.is_empty();
    let times = if animated {
        vec![None, Some(1.0)]
    } else {
        vec![None]
    };
    for time in times {
        let want = reference_skinning(f, time);
        let diag = diagonal(&want);
        for method in [BlendMethod::Matrix, BlendMethod::MatrixF32] {
            let got = skin_rig(&rig, method, time);
            assert_eq!(got.len(), want.len(), "{name}");
            let err = got
                .iter()
                .zip(&want)
                .map(|(a, b)| a.distance(*b))
                .fold(0.0, f64::max)
                / diag;
            let tol = if method == BlendMethod::Matrix {
                1e-6
            } else {
                1e-5
            };
            assert!(err < tol, "{name} {time:?} {}: {err:e}", method.name());
        }
    }
    let out = glb_bytes(&rig, &GlbOptions::default()).unwrap();
    std::fs::write(gltf_out().join(format!("wild-{name}.glb")), &out).unwrap();
    let back = parse_gltf(&out, name, None).unwrap();
    assert_eq!(back.mesh.vertex_count(), rig.mesh.vertex_count(), "{name}");
    // A cut at the bind pose, in world space: half the bar's height.
    let world = rig.bind_pose_positions().unwrap();
    let pose = rig.rest_pose().unwrap();
    let lo = world.iter().fold(DVec3::INFINITY, |a, b| a.min(*b));
    let hi = world.iter().fold(DVec3::NEG_INFINITY, |a, b| a.max(*b));
    let axis = (hi - lo).normalize();
    let plane = cga::Plane::from_normal_distance(axis, axis.dot(0.5 * (lo + hi)));
    let surgery = Surgery::new(&rig.mesh, &rig.influences).unwrap();
    let frame = Frame::Posed {
        positions: &world,
        skin: &pose.skin_matrices,
    };
    let cut = surgery
        .cut(&plane, frame, &CutOptions::default())
        .unwrap_or_else(|e| panic!("{name}: cut: {e}"));
    assert!(cut.pieces.len() >= 2, "{name}: pieces on both sides");
    let parts: Vec<_> = cut.pieces.iter().map(|p| p.mesh.part()).collect();
    let cut_rig = rig.with_parts(&parts).unwrap();
    assert_eq!(cut_rig.look.morph_weights, rig.look.morph_weights, "{name}");
    let posed = skin_rig(&cut_rig, BlendMethod::Matrix, animated.then_some(1.0));
    assert!(posed.iter().all(|p| p.is_finite()), "{name}");
    let out = glb_bytes(&cut_rig, &GlbOptions::default()).unwrap();
    std::fs::write(gltf_out().join(format!("wild-{name}-cut.glb")), &out).unwrap();
    rig
}
