//! Adjacency built on demand: edges, vertex one-rings, vertex-face incidence, boundary loops,
//! connected components and the fans around each vertex.
//!
//! Every function takes index slices (`triangles` and `vertex_count`), so callers such as
//! [`crate::mesh::validate::validate()`] need no [`Mesh`]; the `Mesh` methods of the same names forward here.
//! All of them assume the triangle indices are in range (check with [`crate::mesh::validate::validate()`]
//! first); they panic otherwise.

pub use crate::mesh::union_find::Components;
use crate::mesh::union_find::UnionFind;
use crate::mesh::Mesh;

/// Compressed rows of `u32` items (one row per vertex).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Csr {
    /// Row `i` is `items[offsets[i]..offsets[i + 1]]`.
    pub offsets: Vec<usize>,
    /// The concatenated rows.
    pub items: Vec<u32>,
}

impl Csr {
    /// Number of rows.
    pub fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// True when there are no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Row `i`.
    pub fn row(&self, i: usize) -> &[u32] {
        &self.items[self.offsets[i]..self.offsets[i + 1]]
    }

    /// Builds rows from `(row, item)` pairs given by `pairs`, preserving their order within a row.
    pub(crate) fn from_pairs(rows: usize, pairs: impl Iterator<Item = (u32, u32)> + Clone) -> Csr {
        let mut offsets = vec![0usize; rows + 1];
        for (r, _) in pairs.clone() {
            offsets[r as usize + 1] += 1;
        }
        for i in 0..rows {
            offsets[i + 1] += offsets[i];
        }
        let mut fill = offsets.clone();
        let mut items = vec![0u32; offsets[rows]];
        for (r, x) in pairs {
            items[fill[r as usize]] = x;
            fill[r as usize] += 1;
        }
        Csr { offsets, items }
    }
}

/// The unique undirected edges of a mesh.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Edges {
    /// Edges `[a, b]` with `a < b`, sorted lexicographically.
    pub edges: Vec<[u32; 2]>,
    /// Number of triangles incident to each edge (1: boundary, 2: interior, more: non-manifold).
    pub face_count: Vec<u32>,
    /// For each triangle, the index (into `edges`) of the edge opposite each corner.
    pub face_edges: Vec<[u32; 3]>,
}

impl Edges {
    /// Indices of the boundary edges (exactly one incident triangle).
    pub fn boundary(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.edges.len()).filter(|&e| self.face_count[e] == 1)
    }

    /// Indices of the non-manifold edges (more than two incident triangles).
    pub fn non_manifold(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.edges.len()).filter(|&e| self.face_count[e] > 2)
    }
}

/// The unique edges with their triangle counts and the triangle-to-edge map.
///
/// Linear time (bucketed by the smaller endpoint, sorted within a bucket).
pub fn edges(triangles: &[[u32; 3]], vertex_count: usize) -> Edges {
    let n = vertex_count;
    let corners = triangles.len() * 3;
    // Bucket half-edges (opposite corner id) by their smaller endpoint.
    let key = |c: usize| -> (u32, u32) {
        let t = triangles[c / 3];
        let k = c % 3;
        let (a, b) = (t[(k + 1) % 3], t[(k + 2) % 3]);
        if a < b {
            (a, b)
        } else {
            (b, a)
        }
    };
    let mut offsets = vec![0usize; n + 1];
    for c in 0..corners {
        offsets[key(c).0 as usize + 1] += 1;
    }
    for i in 0..n {
        offsets[i + 1] += offsets[i];
    }
    let mut fill = offsets.clone();
    let mut bucket = vec![(0u32, 0u32); corners];
    for c in 0..corners {
        let (a, b) = key(c);
        bucket[fill[a as usize]] = (b, c as u32);
        fill[a as usize] += 1;
    }
    let mut edges = Vec::with_capacity(corners / 2 + 1);
    let mut face_count = Vec::with_capacity(corners / 2 + 1);
    let mut face_edges = vec![[0u32; 3]; triangles.len()];
    for a in 0..n {
        let row = &mut bucket[offsets[a]..offsets[a + 1]];
        row.sort_unstable();
        let mut prev = u32::MAX;
        for &(b, c) in row.iter() {
            if b != prev {
                edges.push([a as u32, b]);
                face_count.push(0);
                prev = b;
            }
            let e = edges.len() - 1;
            face_count[e] += 1;
            face_edges[c as usize / 3][c as usize % 3] = e as u32;
        }
    }
    Edges {
        edges,
        face_count,
        face_edges,
    }
}

/// One-rings (neighbours of each vertex, sorted increasingly) from already computed edges.
pub fn rings_from_edges(vertex_count: usize, edges: &Edges) -> Csr {
    // Edges are sorted by (min, max): filling in edge order keeps every row sorted.
    Csr::from_pairs(
        vertex_count,
        edges
            .edges
            .iter()
            .flat_map(|&[a, b]| [(a, b), (b, a)].into_iter()),
    )
}

/// The triangles incident to each vertex, in increasing order.
pub fn vertex_faces(triangles: &[[u32; 3]], vertex_count: usize) -> Csr {
    Csr::from_pairs(
        vertex_count,
        triangles
            .iter()
            .enumerate()
            .flat_map(|(f, t)| t.iter().map(move |&v| (v, f as u32))),
    )
}

/// Closed boundary loops as vertex sequences that follow the triangles' orientation.
///
/// Each boundary edge is used once; at a vertex with several outgoing boundary edges
/// (non-manifold) the loop continues with the first unused one.
pub fn boundary_loops(triangles: &[[u32; 3]], vertex_count: usize) -> Vec<Vec<u32>> {
    let edges = edges(triangles, vertex_count);
    // Oriented boundary half-edges a -> b.
    let pairs: Vec<(u32, u32)> = triangles
        .iter()
        .enumerate()
        .flat_map(|(f, t)| {
            let fe = edges.face_edges[f];
            let counts = &edges.face_count;
            (0..3).filter_map(move |k| {
                (counts[fe[k] as usize] == 1).then_some((t[(k + 1) % 3], t[(k + 2) % 3]))
            })
        })
        .collect();
    let next = Csr::from_pairs(vertex_count, pairs.iter().copied());
    // Each vertex's half-edges are taken in order: `cursor[v]` is the first one not yet
    // taken, so a vertex on many boundary edges is not scanned from its start at every visit.
    let mut cursor: Vec<usize> = next.offsets[..vertex_count].to_vec();
    let mut loops = Vec::new();
    for &(start, _) in &pairs {
        let mut lp = Vec::new();
        let mut v = start;
        loop {
            let slot = cursor[v as usize];
            if slot == next.offsets[v as usize + 1] {
                break;
            }
            cursor[v as usize] += 1;
            lp.push(v);
            v = next.items[slot];
            if v == start {
                break;
            }
        }
        if !lp.is_empty() {
            loops.push(lp);
        }
    }
    loops
}

/// Connected components through triangle edges; unreferenced vertices are singletons.
pub fn components(triangles: &[[u32; 3]], vertex_count: usize) -> Components {
    let mut uf = UnionFind::new(vertex_count);
    for t in triangles {
        uf.union(t[0], t[1]);
        uf.union(t[1], t[2]);
    }
    uf.labels()
}

/// Which vertices are used by at least one triangle.
pub fn referenced(triangles: &[[u32; 3]], vertex_count: usize) -> Vec<bool> {
    let mut r = vec![false; vertex_count];
    for t in triangles {
        for &v in t {
            r[v as usize] = true;
        }
    }
    r
}

/// For each vertex, the number of fans its triangles form: triangles sharing an edge at the
/// vertex are in one fan. 0 for an unreferenced vertex, 1 for a manifold vertex, more for a
/// bow-tie. `edges` must be [`edges()`] of the same triangles, whose three indices must be
/// distinct. Linear time: one union-find over the triangle corners.
pub fn fan_counts(triangles: &[[u32; 3]], vertex_count: usize, edges: &Edges) -> Vec<u32> {
    let corners = triangles.len() * 3;
    let mut uf = UnionFind::new(corners);
    // The first corner (3 f + k, k opposite the edge) seen for each edge.
    let mut first = vec![u32::MAX; edges.edges.len()];
    for (g, tg) in triangles.iter().enumerate() {
        for m in 0..3 {
            let e = edges.face_edges[g][m] as usize;
            if first[e] == u32::MAX {
                first[e] = (3 * g + m) as u32;
                continue;
            }
            let (f, k) = (first[e] as usize / 3, first[e] as usize % 3);
            let tf = triangles[f];
            let (ka, kb) = ((k + 1) % 3, (k + 2) % 3);
            let (ma, mb) = if tg[(m + 1) % 3] == tf[ka] {
                ((m + 1) % 3, (m + 2) % 3)
            } else {
                ((m + 2) % 3, (m + 1) % 3)
            };
            uf.union((3 * f + ka) as u32, (3 * g + ma) as u32);
            uf.union((3 * f + kb) as u32, (3 * g + mb) as u32);
        }
    }
    let mut fans = vec![0u32; vertex_count];
    for c in 0..corners as u32 {
        if uf.find(c) == c {
            fans[triangles[c as usize / 3][c as usize % 3] as usize] += 1;
        }
    }
    fans
}

impl Mesh {
    /// The unique edges; see [`edges()`].
    pub fn edges(&self) -> Edges {
        edges(&self.triangles, self.positions.len())
    }

    /// The neighbours of each vertex (its one-ring), sorted increasingly.
    pub fn one_rings(&self) -> Csr {
        rings_from_edges(self.positions.len(), &self.edges())
    }

    /// One-rings from already computed edges; see [`rings_from_edges()`].
    pub fn rings_from_edges(n: usize, edges: &Edges) -> Csr {
        rings_from_edges(n, edges)
    }

    /// The triangles incident to each vertex; see [`vertex_faces()`].
    pub fn vertex_faces(&self) -> Csr {
        vertex_faces(&self.triangles, self.positions.len())
    }

    /// Closed boundary loops; see [`boundary_loops()`].
    pub fn boundary_loops(&self) -> Vec<Vec<u32>> {
        boundary_loops(&self.triangles, self.positions.len())
    }

    /// Connected components; see [`components()`].
    pub fn components(&self) -> Components {
        components(&self.triangles, self.positions.len())
    }

    /// Which vertices are used by at least one triangle.
    pub fn referenced(&self) -> Vec<bool> {
        referenced(&self.triangles, self.positions.len())
    }
}
