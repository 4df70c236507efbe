//! What a method is to the program, the editor and a library caller: [`MethodKind`] describes
//! it (its name, the groups and files it needs, its options) and binds a mesh;
//! [`PoseMethod`] is the bound mesh. A method reads its options' values from
//! [`OptionValues`] (what [`super::MethodSettings`] holds besides the method), posed from one motor per key. Each method is one file
//! in [`super::kinds`] implementing both; [`super::Method`] names it.

use super::budget::WorkBudget;
use super::error::{MethodError, MethodsError};
use super::harmonic_cache::HarmonicCache;
use super::option::OptionSpec;
use super::values::OptionValues;
use crate::blend::BlendMethod;
use crate::mesh::Mesh;
use cga::ScaledMotor;
use glam::DVec3;

/// A lattice's or cage's control points at rest and the pairs joined by a line (the lattice's
/// grid, the cage's edges).
#[derive(Clone, Debug, PartialEq)]
pub struct ControlPoints {
    /// The points at rest.
    pub points: Vec<DVec3>,
    /// Pairs of point indices.
    pub edges: Vec<[u32; 2]>,
}

/// What a method binds: the mesh, its handle groups, the cage where the scene has one, the
/// work budget that refuses oversized requests and the harmonic analysis kept between binds.
pub struct BindInput<'a> {
    /// The mesh at rest.
    pub mesh: &'a Mesh,
    /// The handle groups (vertex indices), at least [`MethodKind::groups_needed`].
    pub groups: &'a [Vec<u32>],
    /// The scene's cage.
    pub cage: Option<&'a Mesh>,
    /// The work budget.
    pub budget: &'a WorkBudget,
    /// The harmonic analysis of the mesh, kept for the next bind.
    pub cache: &'a mut HarmonicCache,
}

/// A deformation method: its description and its bind.
pub trait MethodKind: Sync {
    /// Its name, which is also the program's subcommand (`deform pose NAME`).
    fn name(&self) -> &'static str;

    /// The fewest handle groups it binds to.
    fn groups_needed(&self) -> usize {
        1
    }

    /// The files its command reads besides the mesh, in order: each flag's name and what the
    /// file holds (`selection`: the handle groups; `motors`: a motor per key; `keys` and
    /// `rest-keys`: posed and rest keys; `cage`: the cage mesh).
    fn inputs(&self) -> &'static [(&'static str, &'static str)];

    /// The program's words that pose it from files, before the mesh: `pose NAME` (the
    /// command every method has), or its own subcommand where it has one.
    fn command(&self) -> Vec<&'static str> {
        vec!["pose", self.name()]
    }

    /// Whether its keys are control points (a lattice's or a cage's), not handle groups.
    fn controls(&self) -> bool {
        false
    }

    /// Whether it blends key motors by a [`BlendMethod`] (ARAP solves instead).
    fn blends(&self) -> bool {
        true
    }

    /// Its own options (the program's flags and the editor's panel are made from them).
    fn options(&self) -> &'static [OptionSpec] {
        &[]
    }

    /// The checks its options need together (each alone is checked by its [`OptionSpec`]).
    fn check(&self, _settings: &OptionValues) -> Result<(), MethodError> {
        Ok(())
    }

    /// Bind `input` by `settings` (the method is this one; the groups are enough).
    fn bind(
        &self,
        input: BindInput<'_>,
        settings: &OptionValues,
    ) -> Result<Box<dyn PoseMethod>, MethodsError>;
}

/// A mesh bound by a method, posed from one motor per key as often as wanted; it keeps its
/// own scratch, so a pose after the first allocates nothing.
pub trait PoseMethod: Send {
    /// The motors a pose takes.
    fn key_count(&self) -> usize;

    /// The control points of a lattice or cage.
    fn controls(&self) -> Option<&ControlPoints> {
        None
    }

    /// Another blend method with the same weights, where the method keeps them apart;
    /// `false` where it must be bound again.
    fn reblend(&mut self, _positions: &[DVec3], _blend: BlendMethod) -> Result<bool, MethodsError> {
        Ok(false)
    }

    /// Pose by `motors` (as many as [`PoseMethod::key_count`]) into `out`; a method that
    /// minimises an energy returns its value.
    fn pose(
        &mut self,
        motors: &[ScaledMotor],
        out: &mut [DVec3],
    ) -> Result<Option<f64>, MethodsError>;

    /// The fields of its own the mesh can be coloured by.
    fn fields(&self) -> &'static [&'static str] {
        &[]
    }

    /// One value per vertex of the field `name` (`group` for a per-group field).
    fn field(&self, _name: &str, _group: usize) -> Option<Vec<f64>> {
        None
    }
}
