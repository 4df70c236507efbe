//! Per-vertex joint influences.

/// Per-vertex joint influences: `width` (joint, weight) pairs per vertex, joints indexing the
/// skin's joint list. Weights are non-negative and sum to 1 ([`super::Rig::new`] reads weights in
/// `[-1e-6, 0)` as 0 and normalises).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Influences {
    /// Pairs per vertex (4, or 8 with a second joint/weight set).
    pub width: usize,
    /// Joint indices, vertex-major.
    pub joints: Vec<u32>,
    /// Weights, vertex-major.
    pub weights: Vec<f64>,
}

impl Influences {
    /// The influences of consecutive vertex ranges (the primitives of a rig), each padded with
    /// zero weights on its first joint to the widest.
    pub fn padded(parts: Vec<Influences>) -> Influences {
        let width = parts.iter().map(|p| p.width).max().unwrap_or(0);
        if parts.len() == 1 || parts.iter().all(|p| p.width == width) {
            let mut out = Influences {
                width,
                ..Influences::default()
            };
            for p in parts {
                out.joints.extend(p.joints);
                out.weights.extend(p.weights);
            }
            return out;
        }
        let mut out = Influences {
            width,
            ..Influences::default()
        };
        for p in &parts {
            for v in 0..p.vertex_count() {
                let row = v * p.width..(v + 1) * p.width;
                let first = p.joints[row.start];
                out.joints.extend_from_slice(&p.joints[row.clone()]);
                out.weights.extend_from_slice(&p.weights[row]);
                out.joints
                    .extend(std::iter::repeat_n(first, width - p.width));
                out.weights
                    .extend(std::iter::repeat_n(0.0, width - p.width));
            }
        }
        out
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.weights.len().checked_div(self.width).unwrap_or(0)
    }

    /// Normalise every vertex's weights to sum 1 (an all-zero vertex gets weight 1 on its first
    /// joint, as three.js does); returns how many vertices were off by more than `1e-5`.
    pub(crate) fn normalise(&mut self) -> usize {
        let mut changed = 0;
        let w = self.width.max(1);
        for row in self.weights.chunks_mut(w) {
            let sum: f64 = row.iter().sum();
            if (sum - 1.0).abs() > 1e-5 {
                changed += 1;
            }
            if sum > 0.0 {
                row.iter_mut().for_each(|x| *x /= sum);
            } else {
                row.iter_mut().for_each(|x| *x = 0.0);
                row[0] = 1.0;
            }
        }
        changed
    }

    /// Checks the layout for `vertex_count` vertices: a width of at least 1, one joint per
    /// weight, `vertex_count * width` of each, every weight finite. The reason, in words.
    pub fn check(&self, vertex_count: usize) -> Result<(), String> {
        if self.width == 0 {
            return Err("influences of width 0".into());
        }
        if self.joints.len() != self.weights.len() {
            return Err(format!(
                "{} influence joints for {} weights",
                self.joints.len(),
                self.weights.len()
            ));
        }
        if self.weights.len() != vertex_count.saturating_mul(self.width) {
            return Err(format!(
                "{} influence rows of width {} for {vertex_count} vertices",
                self.weights.len() / self.width,
                self.width
            ));
        }
        if let Some(i) = self.weights.iter().position(|w| !w.is_finite()) {
            return Err(format!(
                "vertex {}: influence weight {} is not finite",
                i / self.width,
                self.weights[i]
            ));
        }
        Ok(())
    }

    /// The `(joint, weight)` pairs of vertex `v`.
    ///
    /// # Panics
    /// When `v` is past the last vertex or the layout is not as [`Influences::check`] wants.
    pub fn row(&self, v: usize) -> impl Iterator<Item = (u32, f64)> + '_ {
        let r = v * self.width..(v + 1) * self.width;
        self.joints[r.clone()]
            .iter()
            .copied()
            .zip(self.weights[r].iter().copied())
    }
}
