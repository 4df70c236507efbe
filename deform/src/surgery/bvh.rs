//! A bounding-volume hierarchy over a mesh's triangles: the spatial index that lets cut, tear
//! and drill find the faces a plane, a blade or a cylinder reaches without scanning every face.

use crate::mesh::Aabb;
use crate::mesh::Mesh;
use glam::DVec3;

/// Triangles per leaf at most.
const LEAF: usize = 8;

/// One node: a box and either two children or a run of faces.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    bounds: Aabb,
    /// Children `first` and `first + 1` (inner node), or faces `order[first..first + count]`.
    first: u32,
    /// 0 for an inner node.
    count: u32,
}

/// A median-split AABB tree over the triangles of one mesh (built once, queried many times).
#[derive(Clone, Debug, PartialEq)]
pub struct FaceBvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

fn tri_box(mesh: &Mesh, f: usize) -> Aabb {
    let [a, b, c] = mesh.corners(f);
    Aabb {
        min: a.min(b).min(c),
        max: a.max(b).max(c),
    }
}

fn union(a: &Aabb, b: &Aabb) -> Aabb {
    Aabb {
        min: a.min.min(b.min),
        max: a.max.max(b.max),
    }
}

impl FaceBvh {
    /// Build the tree over `mesh`'s triangles (O(F log F)).
    pub fn new(mesh: &Mesh) -> FaceBvh {
        let n = mesh.triangle_count();
        let boxes: Vec<Aabb> = (0..n).map(|f| tri_box(mesh, f)).collect();
        let centers: Vec<DVec3> = boxes.iter().map(|b| 0.5 * (b.min + b.max)).collect();
        let mut order: Vec<u32> = (0..n as u32).collect();
        let empty = Aabb {
            min: DVec3::ZERO,
            max: DVec3::ZERO,
        };
        let mut nodes = vec![Node {
            bounds: empty,
            first: 0,
            count: 0,
        }];
        // (node, start, end) of faces still to place.
        let mut stack = vec![(0usize, 0usize, n)];
        while let Some((at, lo, hi)) = stack.pop() {
            let bounds = order[lo..hi]
                .iter()
                .map(|&f| boxes[f as usize])
                .reduce(|a, b| union(&a, &b))
                .unwrap_or(empty);
            if hi - lo <= LEAF {
                nodes[at] = Node {
                    bounds,
                    first: lo as u32,
                    count: (hi - lo) as u32,
                };
                continue;
            }
            let size = bounds.size();
            let axis = if size.x >= size.y && size.x >= size.z {
                0
            } else if size.y >= size.z {
                1
            } else {
                2
            };
            let mid = (lo + hi) / 2;
            order[lo..hi].select_nth_unstable_by(mid - lo, |&a, &b| {
                centers[a as usize][axis].total_cmp(&centers[b as usize][axis])
            });
            let first = nodes.len();
            nodes.push(nodes[at]);
            nodes.push(nodes[at]);
            nodes[at] = Node {
                bounds,
                first: first as u32,
                count: 0,
            };
            stack.push((first, lo, mid));
            stack.push((first + 1, mid, hi));
        }
        FaceBvh { nodes, order }
    }

    /// Recompute every box for new positions of the same mesh (a posed frame): O(F), the tree's
    /// shape kept.
    pub fn refit(&mut self, mesh: &Mesh) {
        if self.order.is_empty() {
            return;
        }
        // Children come after their parents: go backwards.
        for i in (0..self.nodes.len()).rev() {
            let node = self.nodes[i];
            let bounds = if node.count == 0 {
                union(
                    &self.nodes[node.first as usize].bounds,
                    &self.nodes[node.first as usize + 1].bounds,
                )
            } else {
                let r = node.first as usize..(node.first + node.count) as usize;
                self.order[r]
                    .iter()
                    .map(|&f| tri_box(mesh, f as usize))
                    .reduce(|a, b| union(&a, &b))
                    .expect("a leaf holds faces")
            };
            self.nodes[i].bounds = bounds;
        }
    }

    /// Call `visit(face)` for every face in a leaf whose box `hit` accepts (and whose
    /// ancestors' boxes it accepts).
    pub fn query(&self, hit: impl Fn(&Aabb) -> bool, mut visit: impl FnMut(u32)) {
        if self.order.is_empty() {
            return;
        }
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop() {
            let node = &self.nodes[i];
            if !hit(&node.bounds) {
                continue;
            }
            if node.count == 0 {
                stack.push(node.first as usize);
                stack.push(node.first as usize + 1);
            } else {
                let r = node.first as usize..(node.first + node.count) as usize;
                self.order[r].iter().for_each(|&f| visit(f));
            }
        }
    }

    /// The faces whose boxes straddle (or touch) the plane `x.n = d`, widened by `margin`.
    pub fn faces_near_plane(&self, n: DVec3, d: f64, margin: f64) -> Vec<u32> {
        let mut out = Vec::new();
        self.query(
            |b| {
                let c = 0.5 * (b.min + b.max);
                let h = 0.5 * (b.max - b.min);
                (n.dot(c) - d).abs() <= h.dot(n.abs()) + margin
            },
            |f| out.push(f),
        );
        out
    }
}
