//! Shared helpers: the shared data and reference directories (located by `devkit`), libigl
//! references, small meshes and checks.
#![allow(dead_code)]

use std::path::PathBuf;

/// The shared data and reference folders (`devkit::shared`): `$CGA_DATA_DIR`, else
/// `../shared/data`; `$CGA_REFERENCE_DIR`, else `../shared/reference`. `None` (test skipped)
/// when absent, a panic under `CI=true`.
pub use devkit::shared::{data_dir, reference_dir};

/// A file of the mesh data set, e.g. `mesh("libigl/decimated-knight.off")`.
pub fn mesh_path(rel: &str) -> Option<PathBuf> {
    data_dir().map(|d| d.join("meshes").join(rel))
}

/// Reads a libigl reference JSON.
pub fn reference(name: &str) -> Option<serde_json::Value> {
    let path = reference_dir()?.join(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    Some(serde_json::from_str(&text).expect("reference JSON parses"))
}

/// Vertices and faces stored in a reference JSON.
pub fn reference_mesh(r: &serde_json::Value) -> deform::Mesh {
    let positions = r["V"]
        .as_array()
        .expect("V")
        .iter()
        .map(|p| {
            let c: Vec<f64> = p
                .as_array()
                .expect("vertex")
                .iter()
                .map(|x| x.as_f64().expect("coordinate"))
                .collect();
            glam::DVec3::new(c[0], c[1], c[2])
        })
        .collect();
    let triangles = r["F"]
        .as_array()
        .expect("F")
        .iter()
        .map(|t| {
            let c: Vec<u32> = t
                .as_array()
                .expect("face")
                .iter()
                .map(|x| x.as_u64().expect("index") as u32)
                .collect();
            [c[0], c[1], c[2]]
        })
        .collect();
    deform::Mesh::new(positions, triangles)
}

/// A JSON array of numbers.
pub fn f64s(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// A JSON array of indices.
pub fn u32s(v: &serde_json::Value) -> Vec<u32> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_u64().expect("index") as u32)
        .collect()
}

/// A planar `nx x ny`-vertex grid with unit spacing, triangulated with alternating diagonals.
/// With `jitter`, interior vertices move deterministically by up to 0.3 in x and y (the
/// triangulation stays valid).
pub fn grid(nx: u32, ny: u32, jitter: bool) -> deform::Mesh {
    let mut positions = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let mut p = glam::DVec3::new(i as f64, j as f64, 0.0);
            let interior = i > 0 && j > 0 && i + 1 < nx && j + 1 < ny;
            if jitter && interior {
                let s = (i * 7919 + j * 104729) as f64;
                p.x += 0.3 * (s * 0.37).sin();
                p.y += 0.3 * (s * 0.91).cos();
            }
            positions.push(p);
        }
    }
    let mut triangles = Vec::new();
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let (a, b, c, d) = (
                j * nx + i,
                j * nx + i + 1,
                (j + 1) * nx + i + 1,
                (j + 1) * nx + i,
            );
            if (i + j) % 2 == 0 {
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            } else {
                triangles.push([a, b, d]);
                triangles.push([b, c, d]);
            }
        }
    }
    deform::Mesh::new(positions, triangles)
}

/// `y = A x` for a CSR matrix.
pub fn mul(a: &sprs::CsMat<f64>, x: &[f64]) -> Vec<f64> {
    a.outer_iterator()
        .map(|row| row.iter().map(|(j, v)| v * x[j]).sum())
        .collect()
}

/// A libigl rig of the data set: `meshes/libigl/{name}.obj`, `{name}.tgf` and
/// `{name}-weights.dmat` (`arm`, `elephant`).
pub fn libigl_rig(name: &str) -> Option<deform::skinning::Rig> {
    let lib = data_dir()?.join("meshes/libigl");
    let mesh = deform::mesh::io::read_obj(lib.join(format!("{name}.obj"))).expect("mesh");
    let skeleton = deform::mesh::io::read_tgf(lib.join(format!("{name}.tgf"))).expect("skeleton");
    let weights =
        deform::mesh::io::read_dmat(lib.join(format!("{name}-weights.dmat"))).expect("weights");
    Some(deform::skinning::libigl_rig(mesh, &skeleton, &weights).expect("rig"))
}

/// Edge-manifold and consistently oriented: no edge has more than two triangles, no directed
/// edge appears twice, no triangle repeats a vertex.
pub fn assert_oriented_manifold(triangles: &[[u32; 3]], vertex_count: usize) {
    let e = deform::mesh::adjacency::edges(triangles, vertex_count);
    assert_eq!(e.non_manifold().count(), 0, "non-manifold edges");
    let mut directed: Vec<(u32, u32)> = triangles
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .collect();
    directed.sort_unstable();
    let n = directed.len();
    directed.dedup();
    assert_eq!(
        directed.len(),
        n,
        "a directed edge appears twice (flipped triangles)"
    );
    assert!(triangles
        .iter()
        .all(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2]));
}

/// A tiny deterministic generator for the mutation tests (Knuth's MMIX LCG constants).
pub struct Lcg(pub u64);

impl Lcg {
    /// The next 31 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }

    /// Uniform in `0..n` (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}
