//! The cells of the ARAP energy and the per-cell sums every step shares: the one-ring
//! (spokes) or spokes-and-rims data fixed at bind, and the covariance of a cell at the
//! current positions.

use glam::{DMat3, DVec3};

/// Vertices (or triangles) per parallel task.
pub(crate) const CHUNK: usize = 512;

/// One-ring (spokes) data: CSR rows of the Laplacian without the diagonal.
#[derive(Debug, Clone)]
pub(crate) struct Spokes {
    /// Row `i` is `ptr[i]..ptr[i + 1]`.
    pub ptr: Vec<usize>,
    /// Neighbour `j` of each entry.
    pub col: Vec<u32>,
    /// Weight `w_ij`.
    pub w: Vec<f64>,
    /// `w_ij (p_i - p_j)` at rest.
    pub we: Vec<DVec3>,
}

/// Spokes-and-rims data: per-triangle weights and edges, and the triangles around each vertex.
#[derive(Debug, Clone)]
pub(crate) struct Rims {
    /// The mesh's triangles.
    pub tris: Vec<[u32; 3]>,
    /// `c[t][k]`: the (half-cotangent) weight of the edge opposite corner `k`.
    pub c: Vec<[f64; 3]>,
    /// `c[t][k] * e[t][k]` with `e[t][k] = p[k + 2] - p[k + 1]` at rest.
    pub ce: Vec<[DVec3; 3]>,
    /// Incident triangles of vertex `i`: `inc[ptr[i]..ptr[i + 1]]`.
    pub ptr: Vec<usize>,
    /// The triangle of each incidence.
    pub inc: Vec<u32>,
}

/// The cells' data for the chosen energy.
#[derive(Debug, Clone)]
pub(crate) enum Cells {
    Spokes(Spokes),
    Rims(Rims),
}

/// A cell's covariance and the sums the energy and the eigenvalue bound need.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Covariance {
    /// `s[3 r + c] = sum_j w_j e_j[r] e'_j[c]`.
    pub s: [f64; 9],
    /// `sum_j w_j |e'_j|^2`.
    pub a: f64,
    /// `sum_j |w_j| |e'_j|^2`.
    pub a_abs: f64,
}

impl Covariance {
    /// Adds `w e e'^T` (`we = w e`).
    #[inline(always)]
    pub fn add(&mut self, w: f64, we: DVec3, e1: DVec3) {
        let s = &mut self.s;
        s[0] += we.x * e1.x;
        s[1] += we.x * e1.y;
        s[2] += we.x * e1.z;
        s[3] += we.y * e1.x;
        s[4] += we.y * e1.y;
        s[5] += we.y * e1.z;
        s[6] += we.z * e1.x;
        s[7] += we.z * e1.y;
        s[8] += we.z * e1.z;
        let l2 = e1.length_squared();
        self.a += w * l2;
        self.a_abs += w.abs() * l2;
    }

    /// Adds another covariance.
    #[inline(always)]
    pub fn add_cov(&mut self, o: &Covariance) {
        for (a, b) in self.s.iter_mut().zip(&o.s) {
            *a += b;
        }
        self.a += o.a;
        self.a_abs += o.a_abs;
    }

    /// `tr(R S)`.
    #[inline]
    pub fn trace_with(&self, r: &DMat3) -> f64 {
        // tr(R S) = sum_{r,c} R[r][c] S[c][r]; glam stores columns: R[r][c] = r.col(c)[r].
        let s = &self.s;
        let (c0, c1, c2) = (r.x_axis, r.y_axis, r.z_axis);
        c0.x * s[0]
            + c1.x * s[3]
            + c2.x * s[6]
            + c0.y * s[1]
            + c1.y * s[4]
            + c2.y * s[7]
            + c0.z * s[2]
            + c1.z * s[5]
            + c2.z * s[8]
    }
}
