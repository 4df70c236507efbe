//! The deformer scenes shared by the criterion bench (`benches/deformers.rs`) and the quick
//! report (`examples/deformer_report.rs`): armadillo-50k (and its 200k-vertex midpoint
//! subdivision) with spline-aligned deformation (4 cubic B-spline keys, lambda from the lowest
//! to the highest 5% of the box in y) and motor handles (4 handles: the lowest 5% in y, the
//! highest 5% in y, and the outer 5% in x on either side).
#![allow(dead_code)]

use cga::ScaledMotor;
use deform::deformers::handles::HandleOptions;
use deform::deformers::spline::{SplineOptions, WeightScheme};
use deform::{BlendMethod, Mesh, MotorHandles, SplineDeformer};
use devkit::shared::data_file;
use glam::{DQuat, DVec3};

/// A mesh of the data set, e.g. `mesh("large/armadillo-50k.obj")`, from `$CGA_DATA_DIR/meshes`
/// (else `../shared/data/meshes`); `None` when absent (a panic under `CI=true`).
pub fn mesh(rel: &str) -> Option<Mesh> {
    let path = data_file(&format!("meshes/{rel}"))?;
    Some(deform::mesh::io::read_mesh(&path).expect("mesh loads"))
}

/// armadillo-50k (see [`mesh`]).
pub fn armadillo() -> Option<Mesh> {
    mesh("large/armadillo-50k.obj")
}

/// The spline's end sets: the lowest and highest 5% of the box in y.
pub fn spline_ends(mesh: &Mesh) -> (Vec<u32>, Vec<u32>) {
    (
        mesh.vertices_in_slab(1, 0.0, 0.05),
        mesh.vertices_in_slab(1, 0.95, 1.0),
    )
}

/// Four handle sets: bottom, top, left and right 5%.
pub fn handle_sets(mesh: &Mesh) -> Vec<Vec<u32>> {
    vec![
        mesh.vertices_in_slab(1, 0.0, 0.05),
        mesh.vertices_in_slab(1, 0.95, 1.0),
        mesh.vertices_in_slab(0, 0.0, 0.05),
        mesh.vertices_in_slab(0, 0.95, 1.0),
    ]
}

/// Keys that bend, twist and grow (rigid and scaled motors about points of the mesh).
pub fn keys(mesh: &Mesh, n: usize) -> Vec<ScaledMotor> {
    let b = mesh.bounding_box().expect("box");
    let d = b.diagonal();
    (0..n)
        .map(|j| {
            let f = j as f64 / (n - 1).max(1) as f64;
            let c = b.min.lerp(b.max, f);
            let q = DQuat::from_axis_angle(DVec3::new(0.3, 1.0, 0.2).normalize(), 0.8 * f);
            let s = 1.0 + 0.2 * f;
            ScaledMotor::from_scale_rotation_translation(
                s,
                q,
                c - s * (q * c) + DVec3::X * (0.1 * d * f),
            )
        })
        .collect()
}

/// Rigid keys (the same motions without scale), for the methods compared rigidly.
pub fn rigid_keys(mesh: &Mesh, n: usize) -> Vec<ScaledMotor> {
    keys(mesh, n)
        .into_iter()
        .map(|k| ScaledMotor::from(k.rigid_part()))
        .collect()
}

/// Bind the spline deformer (4 cubic B-spline keys, rest at the identity).
pub fn bind_spline(mesh: &Mesh) -> SplineDeformer {
    let (a, b) = spline_ends(mesh);
    SplineDeformer::bind(
        mesh,
        &a,
        &b,
        &[ScaledMotor::IDENTITY; 4],
        SplineOptions::default(),
    )
    .expect("spline binds")
}

/// The same spline weights blended by `method`.
pub fn rebind_spline(mesh: &Mesh, spline: &SplineDeformer, method: BlendMethod) -> SplineDeformer {
    SplineDeformer::bind_with_lambda(
        &mesh.positions,
        spline.lambda().to_vec(),
        &[ScaledMotor::IDENTITY; 4],
        WeightScheme::BSpline,
        method,
    )
    .expect("rebind")
}

/// Bind 4 motor handles.
pub fn bind_handles(mesh: &Mesh) -> MotorHandles {
    let sets = handle_sets(mesh);
    let s: Vec<&[u32]> = sets.iter().map(Vec::as_slice).collect();
    MotorHandles::bind_with(
        mesh,
        &s,
        &[ScaledMotor::IDENTITY; 4],
        HandleOptions::default(),
    )
    .expect("handles bind")
}
