//! Adjacency built on demand: edges, vertex one-rings, vertex-face incidence, boundary loops
//! and connected components.
//!
//! All functions here assume the triangle indices are in range (check with
//! [`crate::validate()`] first); they panic otherwise.

use crate::Mesh;

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

/// Connected components of the vertices (through triangle edges).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Components {
    /// Component label of each vertex, `0..count`, numbered by their smallest vertex.
    pub labels: Vec<u32>,
    /// Number of components; each unreferenced vertex is a component of its own.
    pub count: usize,
}

impl Components {
    /// The vertices of each component, in increasing order.
    pub fn members(&self) -> Vec<Vec<u32>> {
        let mut out = vec![Vec::new(); self.count];
        for (v, &c) in self.labels.iter().enumerate() {
            out[c as usize].push(v as u32);
        }
        out
    }
}

/// Union-find with path halving.
pub(crate) struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    pub(crate) fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n as u32).collect(),
        }
    }

    pub(crate) fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let g = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = g;
            x = g;
        }
        x
    }

    pub(crate) fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            // Keep the smaller root so labels follow the smallest vertex.
            let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
            self.parent[hi as usize] = lo;
        }
    }

    /// Dense labels `0..count` in order of the smallest member.
    pub(crate) fn labels(mut self) -> Components {
        let n = self.parent.len();
        let mut labels = vec![u32::MAX; n];
        let mut count = 0u32;
        for v in 0..n as u32 {
            let r = self.find(v);
            if labels[r as usize] == u32::MAX {
                labels[r as usize] = count;
                count += 1;
            }
            labels[v as usize] = labels[r as usize];
        }
        Components {
            labels,
            count: count as usize,
        }
    }
}

impl Mesh {
    /// The unique edges with their triangle counts and the triangle-to-edge map.
    ///
    /// Linear time (bucketed by the smaller endpoint).
    pub fn edges(&self) -> Edges {
        let n = self.positions.len();
        let corners = self.triangles.len() * 3;
        // Bucket half-edges (opposite corner id) by their smaller endpoint.
        let key = |c: usize| -> (u32, u32) {
            let t = self.triangles[c / 3];
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
        let mut face_edges = vec![[0u32; 3]; self.triangles.len()];
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

    /// The neighbours of each vertex (its one-ring), sorted increasingly.
    pub fn one_rings(&self) -> Csr {
        Self::rings_from_edges(self.positions.len(), &self.edges())
    }

    /// One-rings from already computed edges.
    pub fn rings_from_edges(n: usize, edges: &Edges) -> Csr {
        // Edges are sorted by (min, max): filling in edge order keeps every row sorted.
        Csr::from_pairs(
            n,
            edges
                .edges
                .iter()
                .flat_map(|&[a, b]| [(a, b), (b, a)].into_iter()),
        )
    }

    /// The triangles incident to each vertex, in increasing order.
    pub fn vertex_faces(&self) -> Csr {
        Csr::from_pairs(
            self.positions.len(),
            self.triangles
                .iter()
                .enumerate()
                .flat_map(|(f, t)| t.iter().map(move |&v| (v, f as u32))),
        )
    }

    /// Closed boundary loops as vertex sequences that follow the triangles' orientation.
    ///
    /// Each boundary edge is used once; at a vertex with several outgoing boundary edges
    /// (non-manifold) the loop continues with the first unused one.
    pub fn boundary_loops(&self) -> Vec<Vec<u32>> {
        let edges = self.edges();
        // Oriented boundary half-edges a -> b.
        let pairs: Vec<(u32, u32)> = self
            .triangles
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
        let next = Csr::from_pairs(self.positions.len(), pairs.iter().copied());
        let mut used = vec![false; next.items.len()];
        let mut loops = Vec::new();
        for &(start, _) in &pairs {
            let mut lp = Vec::new();
            let mut v = start;
            loop {
                let (lo, hi) = (next.offsets[v as usize], next.offsets[v as usize + 1]);
                let Some(slot) = (lo..hi).find(|&s| !used[s]) else {
                    break;
                };
                used[slot] = true;
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
    pub fn components(&self) -> Components {
        let mut uf = UnionFind::new(self.positions.len());
        for t in &self.triangles {
            uf.union(t[0], t[1]);
            uf.union(t[1], t[2]);
        }
        uf.labels()
    }

    /// Which vertices are used by at least one triangle.
    pub fn referenced(&self) -> Vec<bool> {
        let mut r = vec![false; self.positions.len()];
        for t in &self.triangles {
            for &v in t {
                r[v as usize] = true;
            }
        }
        r
    }
}
