//! A mesh bound by a [`MethodSettings`]: bind once from the mesh and its handle groups (or a
//! cage), then pose from one motor per key as often as wanted; the bound method keeps its own
//! scratch, so a pose after the first allocates nothing. What the editor drives, and what a
//! library caller who picks the method at run time uses.

use super::budget::WorkBudget;
use super::error::MethodError;
use super::error::MethodsError;
use super::harmonic_cache::HarmonicCache;
use super::kind::{BindInput, ControlPoints, PoseMethod};
use super::settings::MethodSettings;
use crate::blend::BlendMethod;

type Result<T> = std::result::Result<T, MethodsError>;
use crate::mesh::Mesh;
use cga::ScaledMotor;
use glam::DVec3;

/// The bound method of a mesh: the rest pose until it is bound, then the method's own
/// [`PoseMethod`].
pub enum BoundMethod {
    /// Not bound (too few groups, or nothing to bind to yet): the rest pose, one motor per
    /// group.
    Rest {
        /// The groups a pose takes motors for.
        groups: usize,
    },
    /// Bound by its method.
    Bound(Box<dyn PoseMethod>),
}

impl BoundMethod {
    /// Bind `mesh` by `settings` to `groups` (or to the lattice over its box, or to `cage`);
    /// with fewer groups than the method needs, [`MethodError::TooFewGroups`]. The handle
    /// groups are checked against `budget` first (a weight per vertex and group);
    /// `cache` keeps the harmonic analysis for the next selection.
    pub fn bind(
        mesh: &Mesh,
        groups: &[Vec<u32>],
        cage: Option<&Mesh>,
        settings: &MethodSettings,
        budget: &WorkBudget,
        cache: &mut HarmonicCache,
    ) -> Result<BoundMethod> {
        let kind = settings.method.kind();
        let need = kind.groups_needed();
        if groups.len() < need {
            let (method, have) = (kind.name(), groups.len());
            return Err(MethodError::TooFewGroups { method, need, have }.into());
        }
        let input = BindInput {
            mesh,
            groups,
            cage,
            budget,
            cache,
        };
        Ok(BoundMethod::Bound(kind.bind(input, &settings.values)?))
    }

    /// The motors a pose takes: one per control point of a lattice or cage, else one per
    /// group.
    pub fn key_count(&self) -> usize {
        match self {
            BoundMethod::Rest { groups } => *groups,
            BoundMethod::Bound(b) => b.key_count(),
        }
    }

    /// The control points of a lattice or cage.
    pub fn controls(&self) -> Option<&ControlPoints> {
        match self {
            BoundMethod::Rest { .. } => None,
            BoundMethod::Bound(b) => b.controls(),
        }
    }

    /// Another blend method with the same weights, where the method keeps them apart
    /// (handles); `false` where it must be bound again.
    pub fn reblend(&mut self, positions: &[DVec3], method: BlendMethod) -> Result<bool> {
        match self {
            BoundMethod::Rest { .. } => Ok(false),
            BoundMethod::Bound(b) => b.reblend(positions, method),
        }
    }

    /// The fields of the bound method's own the mesh can be coloured by.
    pub fn fields(&self) -> &'static [&'static str] {
        match self {
            BoundMethod::Rest { .. } => &[],
            BoundMethod::Bound(b) => b.fields(),
        }
    }

    /// One value per vertex of the bound method's field `name` (`group` for a per-group
    /// field).
    pub fn field(&self, name: &str, group: usize) -> Option<Vec<f64>> {
        match self {
            BoundMethod::Rest { .. } => None,
            BoundMethod::Bound(b) => b.field(name, group),
        }
    }

    /// Pose by one motor per key into `out` (`rest`, the mesh's positions, for
    /// [`BoundMethod::Rest`]); a method that minimises an energy (ARAP, from its last pose)
    /// returns its value.
    pub fn pose(
        &mut self,
        motors: &[ScaledMotor],
        rest: &[DVec3],
        out: &mut [DVec3],
    ) -> Result<Option<f64>> {
        let expected = self.key_count();
        if motors.len() != expected {
            let keys = if self.controls().is_some() {
                "control points"
            } else {
                "groups"
            };
            let given = motors.len();
            return Err(MethodError::KeyCount {
                given,
                expected,
                keys,
            }
            .into());
        }
        match self {
            BoundMethod::Rest { .. } => {
                out.copy_from_slice(rest);
                Ok(None)
            }
            BoundMethod::Bound(b) => b.pose(motors, out),
        }
    }
}
