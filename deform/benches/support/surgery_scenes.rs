//! The surgery scenes shared by the criterion bench (`benches/surgery.rs`) and the quick
//! report (`examples/surgery_report.rs`): libigl's arm (8,311 vertices, 16,618 faces) and
//! CesiumMan (3,273 vertices, 4,672 faces), each with a cut through the middle of its longest
//! axis, one tear step (two scalpel positions 1% of the diagonal apart, along the normal of
//! the vertex nearest the box's centre) and a drill along that normal (radius 1% of the
//! diagonal).
#![allow(dead_code)]

use cga::Plane;
use deform::skinning::{libigl_rig, read_gltf, Rig};
use deform::surgery::{Drill, Scalpel};
use glam::DVec3;

use devkit::shared::data_file;

/// A rig and its three tools.
pub struct SurgeryScene {
    pub name: &'static str,
    pub rig: Rig,
    pub plane: Plane,
    pub scalpel: [Scalpel; 2],
    pub drill: Drill,
}

fn scene(name: &'static str, rig: Rig) -> SurgeryScene {
    let m = &rig.mesh;
    let b = m.bounding_box().expect("a mesh");
    let (c, size, diag) = (b.center(), b.size(), b.diagonal());
    let axis = if size.x >= size.y && size.x >= size.z {
        DVec3::X
    } else if size.y >= size.z {
        DVec3::Y
    } else {
        DVec3::Z
    };
    let v = (0..m.vertex_count())
        .min_by(|&i, &j| {
            m.positions[i]
                .distance(c)
                .total_cmp(&m.positions[j].distance(c))
        })
        .expect("a vertex");
    let (p, n) = (m.positions[v], m.vertex_normals()[v]);
    let along = n.any_orthonormal_vector();
    let blade = |q: DVec3| Scalpel {
        a: q + n * 0.05 * diag,
        b: q - n * 0.05 * diag,
    };
    SurgeryScene {
        name,
        plane: Plane::from_point_normal(c, axis + 0.1 * axis.any_orthonormal_vector()),
        scalpel: [
            blade(p + along * 0.002 * diag),
            blade(p + along * 0.012 * diag),
        ],
        drill: Drill {
            tip: p - n * 0.3 * diag,
            end: p + n * 0.02 * diag,
            radius: 0.01 * diag,
        },
        rig,
    }
}

/// libigl's arm with its skeleton and weights.
pub fn arm() -> Option<SurgeryScene> {
    let lib = "meshes/libigl/";
    let mesh = deform::mesh::io::read_mesh(data_file(&format!("{lib}arm.obj"))?).expect("mesh");
    let sk = deform::mesh::io::read_tgf(data_file(&format!("{lib}arm.tgf"))?).expect("skeleton");
    let w = deform::mesh::io::read_dmat(data_file(&format!("{lib}arm-weights.dmat"))?)
        .expect("weights");
    Some(scene("arm", libigl_rig(mesh, &sk, &w).expect("rig")))
}

/// CesiumMan.
pub fn cesium_man() -> Option<SurgeryScene> {
    Some(scene(
        "CesiumMan",
        read_gltf(data_file("gltf/CesiumMan.glb")?).expect("CesiumMan loads"),
    ))
}

/// Every scene with its data.
pub fn all() -> Vec<SurgeryScene> {
    [arm(), cesium_man()].into_iter().flatten().collect()
}

/// The paper's Python timings on its 5,037-face arm (Table 1 and section 4.3): cut, tear,
/// drill, in milliseconds.
pub const PAPER_MS: [(&str, f64); 3] = [("cut", 4666.0), ("tear", 2437.0), ("drill", 274.0)];
