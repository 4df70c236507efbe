//! The triangle mesh type and its per-element geometry.

use glam::DVec3;

/// A triangle mesh: vertex positions and triangles as triples of vertex indices.
///
/// Nothing is cached: adjacency ([`Mesh::edges`], [`Mesh::one_rings`],
/// [`Mesh::boundary_loops`], ...) is built on demand, so the public fields can be edited freely.
///
/// Nothing is checked either: [`Mesh::new`] takes any triangles, and the methods that read
/// them (areas, normals, volume, subdivision, adjacency, components) index the positions
/// directly and panic on a triangle index past the last vertex. Check a mesh from outside
/// with [`crate::mesh::validate::check_elements`] or [`crate::mesh::validate::validate()`] first; every
/// operator, deformer and reader of this crate does.
///
/// ```
/// use deform::Mesh;
/// use glam::DVec3;
/// let m = Mesh::new(
///     vec![DVec3::ZERO, DVec3::X, DVec3::Y],
///     vec![[0, 1, 2]],
/// );
/// assert_eq!(m.face_areas(), vec![0.5]);
/// assert_eq!(m.face_normals()[0], DVec3::Z);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

/// An axis-aligned bounding box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Smallest coordinates.
    pub min: DVec3,
    /// Largest coordinates.
    pub max: DVec3,
}

impl Aabb {
    /// The box's extent `max - min`.
    pub fn size(&self) -> DVec3 {
        self.max - self.min
    }

    /// The box's centre.
    pub fn center(&self) -> DVec3 {
        0.5 * (self.min + self.max)
    }

    /// Length of the diagonal.
    pub fn diagonal(&self) -> f64 {
        self.size().length()
    }
}

impl Mesh {
    /// A mesh from positions and triangles (not validated; see [`crate::mesh::validate::validate()`]).
    pub fn new(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Self {
        Mesh {
            positions,
            triangles,
        }
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// True when the mesh has no vertices or no triangles.
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty() || self.triangles.is_empty()
    }

    /// The corners of triangle `f`.
    ///
    /// # Panics
    /// If `f` or one of its indices is out of range (validate user meshes first).
    pub fn corners(&self, f: usize) -> [DVec3; 3] {
        let [a, b, c] = self.triangles[f];
        [
            self.positions[a as usize],
            self.positions[b as usize],
            self.positions[c as usize],
        ]
    }

    /// The bounding box of all vertices, or `None` for a mesh without vertices.
    pub fn bounding_box(&self) -> Option<Aabb> {
        let first = *self.positions.first()?;
        let mut bb = Aabb {
            min: first,
            max: first,
        };
        for &p in &self.positions[1..] {
            bb.min = bb.min.min(p);
            bb.max = bb.max.max(p);
        }
        Some(bb)
    }

    /// Unnormalised face normals `(b - a) x (c - a)`, whose length is twice the area.
    pub fn face_area_vectors(&self) -> Vec<DVec3> {
        (0..self.triangles.len())
            .map(|f| {
                let [a, b, c] = self.corners(f);
                (b - a).cross(c - a)
            })
            .collect()
    }

    /// Triangle areas.
    pub fn face_areas(&self) -> Vec<f64> {
        self.face_area_vectors()
            .into_iter()
            .map(|n| 0.5 * n.length())
            .collect()
    }

    /// Total surface area.
    pub fn area(&self) -> f64 {
        self.face_areas().iter().sum()
    }

    /// Unit face normals (zero for degenerate triangles).
    pub fn face_normals(&self) -> Vec<DVec3> {
        self.face_area_vectors()
            .into_iter()
            .map(|n| n.normalize_or_zero())
            .collect()
    }

    /// Unit vertex normals: area-weighted average of the incident face normals (zero for
    /// unreferenced vertices).
    pub fn vertex_normals(&self) -> Vec<DVec3> {
        let mut acc = vec![DVec3::ZERO; self.positions.len()];
        for (t, n) in self.triangles.iter().zip(self.face_area_vectors()) {
            for &v in t {
                acc[v as usize] += n;
            }
        }
        acc.into_iter().map(|n| n.normalize_or_zero()).collect()
    }

    /// [`Mesh::vertex_normals`] with the normals of vertices at bit-identical positions summed
    /// (the copies glTF makes along UV seams), so shading shows no seam.
    pub fn seamless_vertex_normals(&self) -> Vec<DVec3> {
        let mut acc = vec![DVec3::ZERO; self.positions.len()];
        for (t, n) in self.triangles.iter().zip(self.face_area_vectors()) {
            for &v in t {
                acc[v as usize] += n;
            }
        }
        let key = |p: DVec3| p.to_array().map(f64::to_bits);
        let mut at: std::collections::HashMap<[u64; 3], DVec3> = std::collections::HashMap::new();
        for (p, n) in self.positions.iter().zip(&acc) {
            *at.entry(key(*p)).or_insert(DVec3::ZERO) += *n;
        }
        self.positions
            .iter()
            .map(|p| at[&key(*p)].normalize_or_zero())
            .collect()
    }

    /// Signed volume enclosed by a closed, consistently oriented mesh.
    pub fn volume(&self) -> f64 {
        (0..self.triangles.len())
            .map(|f| {
                let [a, b, c] = self.corners(f);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    /// Vertices whose coordinate `axis` (0: x, 1: y, 2: z) lies in the slab
    /// `[min + lo * h, min + hi * h]`, where `min` and `h` are the bounding box's minimum and
    /// extent along that axis. `vertices_in_slab(1, 0.0, 0.05)` is "the lowest 5% by y", the
    /// handle convention of the libigl timings in the data README.
    ///
    /// # Panics
    /// If `axis > 2`.
    pub fn vertices_in_slab(&self, axis: usize, lo: f64, hi: f64) -> Vec<u32> {
        let Some(bb) = self.bounding_box() else {
            return Vec::new();
        };
        let (min, h) = (bb.min[axis], bb.size()[axis]);
        let (a, b) = (min + lo * h, min + hi * h);
        (0..self.positions.len() as u32)
            .filter(|&v| {
                let c = self.positions[v as usize][axis];
                c >= a && c <= b
            })
            .collect()
    }

    /// Midpoint subdivision: every triangle is split into four through its edge midpoints.
    /// Vertex `i < n` keeps its index; edge midpoints are appended.
    pub fn subdivide_midpoint(&self) -> Mesh {
        let edges = self.edges();
        let n = self.positions.len() as u32;
        let mut positions = self.positions.clone();
        positions.extend(
            edges
                .edges
                .iter()
                .map(|&[a, b]| 0.5 * (self.positions[a as usize] + self.positions[b as usize])),
        );
        let mut triangles = Vec::with_capacity(4 * self.triangles.len());
        for (f, t) in self.triangles.iter().enumerate() {
            // `edges.face_edges[f][k]` is the edge opposite corner k.
            let m = edges.face_edges[f].map(|e| n + e);
            triangles.push([t[0], m[2], m[1]]);
            triangles.push([t[1], m[0], m[2]]);
            triangles.push([t[2], m[1], m[0]]);
            triangles.push([m[0], m[1], m[2]]);
        }
        Mesh {
            positions,
            triangles,
        }
    }
}
