//! One work budget for every size a caller can ask for (handle groups, keys, lattice points,
//! grid nodes, cage pairs, iterations, joints, frames written): checked before anything is
//! allocated, so a huge count is a [`BudgetError`] naming it instead of an allocation failure
//! that kills the process or a run that writes files for minutes.
//!
//! The unit is one element of work or memory: one `f64` of a buffer, one grid node's share of a
//! factorisation, one vertex of one frame or one iteration. The default, 2^28 (2 GiB of `f64`s),
//! holds every size the README and the benchmarks use; the `deform` program's `--max-work N`
//! raises (or lowers) it.
//!
//! ```
//! use deform::methods::budget::WorkBudget;
//! let budget = WorkBudget::default();
//! assert!(budget.handle_groups("--select", 1000, 49_999).is_ok());
//! let e = budget.frames_written("--range", 100_000, 12).unwrap_err();
//! assert!(e.to_string().contains("100000 files"), "{e}");
//! ```

use crate::deformers::ffd::LatticeBasis;

/// A request over the budget, naming the option that asked for it, what it comes to and the
/// budget.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BudgetError {
    /// The work is a number over the budget.
    #[error(
        "{item}: {what} comes to {work} elements of work, over this run's budget of {limit} \
         (raise it with --max-work {work} if the machine has the memory and time)"
    )]
    Over {
        /// The option or input that asked (`--grid`, `the selection`).
        item: String,
        /// What was asked, in words.
        what: String,
        /// The work it comes to.
        work: u64,
        /// The budget.
        limit: u64,
    },
    /// The work does not fit in 64 bits.
    #[error(
        "{item}: {what} overflows 64 bits, far over this run's budget of {limit} (--max-work)"
    )]
    Overflow {
        /// The option or input that asked.
        item: String,
        /// What was asked, in words.
        what: String,
        /// The budget.
        limit: u64,
    },
}

/// `f64`s held per vertex and per handle group while a group's harmonic coordinates are bound
/// (the fields, their copy per group and the blend's weight rows): 2,000 groups on
/// armadillo-50k (100M vertex-group pairs) took 2.76 GB, about 3.5 `f64`s a pair.
pub const PER_COORDINATE: u64 = 4;

/// The work of one file written, besides its vertices: an OBJ frame of a 12-vertex rig took
/// 1.15 ms to write (2,000 frames of `SimpleSkin.gltf` in 2.3 s), so the default budget allows
/// 8,192 files, about ten seconds of writing.
pub const PER_FILE_WRITTEN: u64 = 1 << 15;

/// The work budget of one run: the most elements any size asked for may come to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WorkBudget {
    /// The most elements of work or memory.
    pub max_work: u64,
}

impl Default for WorkBudget {
    fn default() -> Self {
        WorkBudget {
            max_work: Self::DEFAULT_MAX_WORK,
        }
    }
}

/// The product of `factors`, `None` on overflow.
pub fn product(factors: &[u64]) -> Option<u64> {
    factors.iter().try_fold(1u64, |acc, &f| acc.checked_mul(f))
}

impl WorkBudget {
    /// The default budget, 2^28 elements.
    pub const DEFAULT_MAX_WORK: u64 = 1 << 28;

    /// Refuses `work` (the product of `factors`, described by `what`, asked for by `item`) when
    /// it exceeds the budget.
    ///
    /// # Errors
    /// [`BudgetError`] naming `item`, the figure and the budget.
    pub fn check(&self, item: &str, what: &str, factors: &[u64]) -> Result<(), BudgetError> {
        let limit = self.max_work;
        match product(factors) {
            Some(work) if work <= limit => Ok(()),
            Some(work) => Err(BudgetError::Over {
                item: item.to_string(),
                what: what.to_string(),
                work,
                limit,
            }),
            None => Err(BudgetError::Overflow {
                item: item.to_string(),
                what: what.to_string(),
                limit,
            }),
        }
    }

    /// Motor handles: `groups` groups (a harmonic coordinate each) on `vertices` vertices; a
    /// selection file with thousands of groups asks for tens of gigabytes.
    ///
    /// # Errors
    /// As [`WorkBudget::check`].
    pub fn handle_groups(
        &self,
        item: &str,
        groups: usize,
        vertices: usize,
    ) -> Result<(), BudgetError> {
        self.check(
            item,
            &format!("{groups} groups on {vertices} vertices (a weight per vertex and group)"),
            &[groups as u64, vertices as u64, PER_COORDINATE],
        )
    }

    /// Spline keys: every vertex weighed by the keys its `scheme` reaches (all `n` of them
    /// for Bezier keys, by de Casteljau's `n^2` steps).
    ///
    /// # Errors
    /// As [`WorkBudget::check`].
    pub fn spline_keys(
        &self,
        item: &str,
        keys: usize,
        scheme: crate::deformers::spline::WeightScheme,
        vertices: usize,
    ) -> Result<(), BudgetError> {
        use crate::deformers::spline::WeightScheme;
        let n = keys as u64;
        let per_vertex = match scheme {
            WeightScheme::Bezier => n.saturating_mul(n),
            scheme => scheme.width(keys) as u64,
        };
        let what = format!("{keys} {} keys over {vertices} vertices", scheme.name());
        self.check(item, &what, &[vertices as u64, per_vertex])
    }

    /// An FFD lattice of `dims` control points on `vertices` vertices: a weight per vertex and
    /// control point, and for Bernstein polynomials their evaluation, quadratic in the
    /// degree.
    ///
    /// # Errors
    /// As [`WorkBudget::check`].
    pub fn ffd_lattice(
        &self,
        item: &str,
        dims: [usize; 3],
        basis: LatticeBasis,
        vertices: usize,
    ) -> Result<(), BudgetError> {
        let [l, m, n] = dims.map(|c| c as u64);
        let squares = [l, m, n]
            .iter()
            .try_fold(0u64, |acc, &d| acc.checked_add(d.checked_mul(d)?));
        let per_vertex = product(&[l, m, n]).and_then(|points| match basis {
            LatticeBasis::Bernstein => points.checked_add(squares?),
            LatticeBasis::BSpline(_) => Some(points),
        });
        let what = format!("{l}x{m}x{n} control points for {vertices} vertices");
        self.check(
            item,
            &what,
            &[per_vertex.unwrap_or(u64::MAX), vertices as u64],
        )
    }

    /// A harmonic cage grid of `resolution` nodes a side. Measured on the knight in a cube:
    /// 0.30 GB at 64 nodes a side, 1.86 GB at 96, about 22 bytes (three `f64`s) per `g^4`: the
    /// budget counts three elements per `g^4`.
    ///
    /// # Errors
    /// As [`WorkBudget::check`].
    pub fn cage_grid(&self, item: &str, resolution: usize) -> Result<(), BudgetError> {
        let g = resolution as u64;
        let what = format!(
            "a harmonic grid of {g} nodes per side (its factorisation grows as the 4th power)"
        );
        self.check(item, &what, &[g, g, g, g, 3])
    }

    /// Cage coordinates: one per mesh vertex and cage vertex. A 2,562-vertex cage on
    /// armadillo-50k took 2.5 GB while binding, about 2.5 `f64`s a pair; the budget counts
    /// three.
    ///
    /// # Errors
    /// As [`WorkBudget::check`].
    pub fn cage_pairs(
        &self,
        item: &str,
        vertices: usize,
        cage_vertices: usize,
    ) -> Result<(), BudgetError> {
        let what = format!(
            "{vertices} mesh vertices by {cage_vertices} cage vertices (a coordinate per pair)"
        );
        self.check(item, &what, &[vertices as u64, cage_vertices as u64, 3])
    }

    /// `iterations` iterations over `vertices` vertices (ARAP).
    ///
    /// # Errors
    /// As [`WorkBudget::check`].
    pub fn iterations(
        &self,
        item: &str,
        iterations: usize,
        vertices: usize,
    ) -> Result<(), BudgetError> {
        let what = format!("{iterations} iterations over {vertices} vertices");
        self.check(item, &what, &[iterations as u64, vertices as u64])
    }

    /// `frames` posed frames of `vertices` vertices, each written to its own file: the
    /// vertices and [`PER_FILE_WRITTEN`] per file, so a tiny rig cannot ask for a million
    /// files.
    ///
    /// # Errors
    /// As [`WorkBudget::check`].
    pub fn frames_written(
        &self,
        item: &str,
        frames: usize,
        vertices: usize,
    ) -> Result<(), BudgetError> {
        let per_frame = (3 * vertices as u64).saturating_add(PER_FILE_WRITTEN);
        let what = format!("{frames} files of {vertices} vertices");
        self.check(item, &what, &[frames as u64, per_frame])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_work_over_the_budget_and_overflow() {
        let b = WorkBudget::default();
        assert!(b.check("--joints", "6 joints", &[6, 24]).is_ok());
        let e = b
            .check("--joints", "many joints", &[u64::MAX, 24])
            .unwrap_err();
        assert!(e.to_string().contains("overflows"), "{e}");
        let e = b
            .check("--grid", "a grid", &[1 << 20, 1 << 20])
            .unwrap_err();
        assert!(e.to_string().contains("--max-work"), "{e}");
        // The default budget holds a thousand groups on armadillo-50k, not 65,536.
        assert!(b.handle_groups("--select", 1000, 49_999).is_ok());
        let e = b.handle_groups("--select", 65_536, 49_999).unwrap_err();
        assert!(e.to_string().contains("65536 groups"), "{e}");
    }

    #[test]
    fn files_written_count_besides_their_vertices() {
        let b = WorkBudget::default();
        // 8,192 files of a 12-vertex rig fit; a million do not, whatever the rig's size.
        assert!(b.frames_written("--range", 8_000, 12).is_ok());
        assert!(b.frames_written("--in-betweens", 1_000_000, 1).is_err());
        assert!(b.frames_written("--range", 100_000, 12).is_err());
        let e = b.frames_written("--range", 100_000, 12).unwrap_err();
        assert!(matches!(e, BudgetError::Over { ref item, .. } if item == "--range"));
        // A larger budget lets them through.
        let big = WorkBudget { max_work: 1 << 40 };
        assert!(big.frames_written("--range", 100_000, 12).is_ok());
    }

    #[test]
    fn lattice_estimates_follow_the_basis() {
        let b = WorkBudget { max_work: 1000 };
        // 4x4x4 = 64 points on 10 vertices: B-splines 640, Bernstein 64 + 48 = 112 per vertex.
        assert!(b
            .ffd_lattice("--lattice", [4, 4, 4], LatticeBasis::BSpline(3), 10)
            .is_ok());
        assert!(b
            .ffd_lattice("--lattice", [4, 4, 4], LatticeBasis::Bernstein, 10)
            .is_err());
        assert!(b
            .ffd_lattice("--lattice", [usize::MAX, 2, 2], LatticeBasis::Bernstein, 10)
            .is_err());
    }
}
