//! Disjoint sets over `0..n` (union-find with path halving), the one used for connected
//! components of meshes, of matrix graphs and of the fans around a vertex.

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

/// Union-find over `0..n`; every root is the smallest member of its set.
#[derive(Debug, Clone)]
pub(crate) struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    /// `n` singletons.
    pub(crate) fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n as u32).collect(),
        }
    }

    /// The root (smallest member) of `x`'s set.
    pub(crate) fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let g = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = g;
            x = g;
        }
        x
    }

    /// Merges the sets of `a` and `b`; true when they were different.
    pub(crate) fn union(&mut self, a: u32, b: u32) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        // Keep the smaller root so labels follow the smallest member.
        let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
        self.parent[hi as usize] = lo;
        true
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

#[cfg(test)]
mod tests {
    use super::UnionFind;

    #[test]
    fn unions_merge_and_label_by_smallest_member() {
        let mut uf = UnionFind::new(6);
        assert!(uf.union(4, 2));
        assert!(uf.union(5, 4));
        assert!(!uf.union(2, 5));
        assert!(uf.union(1, 3));
        assert_eq!(uf.find(5), 2);
        assert_eq!(uf.find(3), 1);
        let c = uf.labels();
        assert_eq!(c.count, 3);
        assert_eq!(c.labels, vec![0, 1, 2, 1, 2, 2]);
    }

    #[test]
    fn long_chains_stay_fast() {
        // Path halving keeps a 200,000-long chain cheap.
        let n = 200_000;
        let mut uf = UnionFind::new(n);
        for i in (1..n as u32).rev() {
            uf.union(i, i - 1);
        }
        assert_eq!(uf.labels().count, 1);
    }
}
