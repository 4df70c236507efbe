//! The skinning scenes shared by the criterion bench (`benches/skinning.rs`) and the quick
//! report (`examples/skinning_report.rs`): libigl's armadillo (43,243 vertices) with its 5
//! skinning weights, libigl's arm (8,311 vertices, 4 bones), and CesiumMan (3,273 vertices,
//! 19 joints) at mid-animation. The armadillo and arm keys are rigid motions of each bone
//! (turns of 20-60 degrees about points of the mesh); CesiumMan's are its walk's skin motors.
#![allow(dead_code)]

use cga::ScaledMotor;
use deform::skinning::{read_gltf, Influences, Rig};
use glam::{DQuat, DVec3};

use devkit::shared::data_file;

/// A skinning scene: rest positions, influences, joint count, and the keys of one frame.
pub struct SkinScene {
    pub name: &'static str,
    pub positions: Vec<DVec3>,
    pub influences: Influences,
    pub joints: usize,
    pub keys: Vec<ScaledMotor>,
}

/// `m` rigid keys: bone `j` turns by `20 + 40 j / m` degrees about an axis through a point of
/// the box.
fn rigid_keys(positions: &[DVec3], m: usize) -> Vec<ScaledMotor> {
    let (lo, hi) = positions
        .iter()
        .fold((DVec3::MAX, DVec3::MIN), |(a, b), p| (a.min(*p), b.max(*p)));
    (0..m)
        .map(|j| {
            let f = j as f64 / m.max(2) as f64;
            let c = lo.lerp(hi, 0.3 + 0.4 * f);
            let q = DQuat::from_axis_angle(
                DVec3::new(0.3 + f, 1.0, 0.2 - f).normalize(),
                (20.0 + 40.0 * f).to_radians(),
            );
            ScaledMotor::from_scale_rotation_translation(1.0, q, c - q * c)
        })
        .collect()
}

/// Dense libigl weights as influences (`width` = the number of bones).
fn dense(w: &deform::mesh::io::Dmat) -> Influences {
    let (n, m) = (w.rows, w.cols);
    Influences {
        width: m,
        joints: (0..n).flat_map(|_| 0..m as u32).collect(),
        weights: (0..n)
            .flat_map(|i| (0..m).map(move |j| w.get(i, j)))
            .collect(),
    }
}

/// libigl's armadillo with its 5 weights.
pub fn armadillo() -> Option<SkinScene> {
    let mesh =
        deform::mesh::io::read_mesh(data_file("meshes/libigl/armadillo.obj")?).expect("mesh");
    let w = deform::mesh::io::read_dmat(data_file("meshes/libigl/armadillo-weights.dmat")?)
        .expect("weights");
    Some(SkinScene {
        name: "armadillo",
        keys: rigid_keys(&mesh.positions, w.cols),
        joints: w.cols,
        influences: dense(&w),
        positions: mesh.positions,
    })
}

/// libigl's arm with its 4 bone weights.
pub fn arm() -> Option<SkinScene> {
    let mesh = deform::mesh::io::read_mesh(data_file("meshes/libigl/arm.obj")?).expect("mesh");
    let w =
        deform::mesh::io::read_dmat(data_file("meshes/libigl/arm-weights.dmat")?).expect("weights");
    Some(SkinScene {
        name: "arm",
        keys: rigid_keys(&mesh.positions, w.cols),
        joints: w.cols,
        influences: dense(&w),
        positions: mesh.positions,
    })
}

/// CesiumMan.
pub fn cesium_rig() -> Option<Rig> {
    Some(read_gltf(data_file("gltf/CesiumMan.glb")?).expect("CesiumMan loads"))
}

/// CesiumMan at mid-walk.
pub fn cesium_man() -> Option<SkinScene> {
    let rig = cesium_rig()?;
    let (t0, t1) = rig.animations[0].range();
    let pose = rig.pose(Some(0), 0.5 * (t0 + t1), &[]).expect("pose");
    Some(SkinScene {
        name: "CesiumMan",
        keys: pose.skin_motors().expect("similarity rig").to_vec(),
        joints: rig.joints.len(),
        influences: rig.influences.clone(),
        positions: rig.mesh.positions.clone(),
    })
}

/// Every scene that has its data.
pub fn all() -> Vec<SkinScene> {
    [armadillo(), arm(), cesium_man()]
        .into_iter()
        .flatten()
        .collect()
}

/// The skinning backends compared (every blend method).
pub const BACKENDS: [deform::BlendMethod; 7] = deform::BlendMethod::ALL;

/// `n` points in a box, 4 influences among `bones` each (normalised weights), and one rigid
/// key per bone (the GPU report's and bench's 1M vertices and 64 bones: no file needed).
pub fn procedural(n: usize, bones: usize) -> SkinScene {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let positions: Vec<DVec3> = (0..n)
        .map(|_| DVec3::new(next(), next(), next()) * 2.0 - 1.0)
        .collect();
    let mut joints = Vec::with_capacity(4 * n);
    let mut weights = Vec::with_capacity(4 * n);
    for _ in 0..n {
        let w: [f64; 4] = std::array::from_fn(|_| 0.05 + next());
        let sum: f64 = w.iter().sum();
        for x in w {
            joints.push((next() * bones as f64) as u32 % bones as u32);
            weights.push(x / sum);
        }
    }
    let keys = (0..bones)
        .map(|j| {
            let f = j as f64 / bones as f64;
            let q = DQuat::from_axis_angle(DVec3::new(f, 1.0, 0.5 - f).normalize(), 0.2 + f);
            ScaledMotor::from_scale_rotation_translation(1.0, q, DVec3::new(f, -f, 0.3))
        })
        .collect();
    SkinScene {
        // Leaked once per scene made (a report or bench makes one or two).
        name: Box::leak(format!("procedural {n} vertices / {bones} bones").into_boxed_str()),
        positions,
        influences: Influences {
            width: 4,
            joints,
            weights,
        },
        joints: bones,
        keys,
    }
}
