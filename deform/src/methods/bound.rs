//! A mesh bound by a [`MethodSettings`]: bind once from the mesh and its handle groups (or a
//! cage), then pose from one motor per key as often as wanted; the bound method keeps its own
//! scratch, so a pose after the first allocates nothing. What the editor drives, and what a
//! library caller who picks the method at run time uses.

use super::budget::WorkBudget;
use super::error::MethodError;
use super::error::MethodsError;
use super::method::Method;
use super::settings::MethodSettings;
use crate::blend::control::ControlScratch;
use crate::blend::{BlendMethod, BoundBlend, PreparedKeys};
use crate::deformers::arap::{Arap, ArapScratch, Stop, Targets};
use crate::deformers::cage::{CageDeformer, CageOptions};
use crate::deformers::ffd::{Ffd, FfdOptions};
use crate::deformers::handles::HandleOptions;
use crate::deformers::handles::MotorHandles;
use crate::deformers::spline::SplineDeformer;
use crate::deformers::spline::SplineOptions;
use crate::deformers::Deformer;
use crate::operators::harmonic::{harmonic_system, HarmonicOptions};
use crate::operators::solve::SystemAnalysis;

type Result<T> = std::result::Result<T, MethodsError>;
use crate::mesh::Mesh;
use cga::{Motor, ScaledMotor};
use glam::DVec3;
use std::hash::{Hash, Hasher};

/// A lattice's or cage's control points at rest and the pairs joined by a line (the lattice's
/// grid, the cage's edges).
#[derive(Clone, Debug, PartialEq)]
pub struct ControlPoints {
    /// The points at rest.
    pub points: Vec<DVec3>,
    /// Pairs of point indices.
    pub edges: Vec<[u32; 2]>,
}

/// The bound method of a mesh.
pub enum BoundMethod {
    /// Not bound (too few groups, or nothing to bind to yet): the rest pose, one motor per
    /// group.
    Rest {
        /// The groups a pose takes motors for.
        groups: usize,
    },
    /// Motor handles: the blend is kept apart so another blend method reuses the weights.
    Handles {
        /// The bound handles (coordinates per group).
        handles: Box<MotorHandles>,
        /// The weights bound with the current blend method.
        blend: Box<BoundBlend>,
        /// The pose's scratch.
        scratch: PreparedKeys,
    },
    /// ARAP with the groups as handles.
    Arap {
        /// The bound ARAP.
        arap: Box<Arap>,
        /// The pose's scratch (it keeps the last pose: the next starts there).
        scratch: Box<ArapScratch>,
        /// Iterations per pose.
        iterations: usize,
        /// The handle groups.
        groups: usize,
    },
    /// The spline through the groups' centres.
    Spline {
        /// The bound spline.
        spline: Box<SplineDeformer>,
        /// The rest keys: a translation to each group's centre; a pose's motor follows it.
        rest: Vec<ScaledMotor>,
        /// The pose's scratch.
        scratch: PreparedKeys,
        /// The posed keys (each motor after its rest key), kept between poses.
        keys: Vec<ScaledMotor>,
    },
    /// An FFD lattice or a cage: one motor per control point.
    Control {
        /// The bound lattice or cage.
        deformer: Box<dyn Deformer<Scratch = ControlScratch>>,
        /// Its control points and lines.
        controls: ControlPoints,
        /// The pose's scratch.
        scratch: ControlScratch,
    },
}

/// The harmonic system's analysis of one mesh, kept while the mesh and options stay the same,
/// so that a new handle selection binds with the numeric factorisation and the solves only.
#[derive(Default)]
pub struct HarmonicCache {
    key: Option<u64>,
    analysis: Option<SystemAnalysis>,
}

impl HarmonicCache {
    /// The analysis of `mesh`'s harmonic system, made now if the mesh or options changed.
    pub fn of(&mut self, mesh: &Mesh, options: &HarmonicOptions) -> Result<&SystemAnalysis> {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        for p in &mesh.positions {
            p.to_array().map(f64::to_bits).hash(&mut h);
        }
        mesh.triangles.hash(&mut h);
        format!("{options:?}").hash(&mut h);
        let key = h.finish();
        if self.key != Some(key) || self.analysis.is_none() {
            self.analysis = None;
            let q = harmonic_system(mesh, options)?;
            self.analysis = Some(SystemAnalysis::new(&q)?);
            self.key = Some(key);
        }
        Ok(self.analysis.as_ref().expect("made above"))
    }
}

/// The centre of each group (the mean of its vertices).
pub fn group_centres(mesh: &Mesh, groups: &[Vec<u32>]) -> Vec<DVec3> {
    groups
        .iter()
        .map(|g| {
            let sum: DVec3 = g.iter().map(|&v| mesh.positions[v as usize]).sum();
            sum / g.len().max(1) as f64
        })
        .collect()
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
        let method = settings.method;
        let need = method.groups_needed();
        if groups.len() < need {
            let (method, have) = (super::named::Named::name(method), groups.len());
            return Err(MethodError::TooFewGroups { method, need, have }.into());
        }
        let sets: Vec<&[u32]> = groups.iter().map(Vec::as_slice).collect();
        Ok(match method {
            Method::Handles => {
                budget.handle_groups("the selection", sets.len(), mesh.vertex_count())?;
                let rest = vec![ScaledMotor::IDENTITY; sets.len()];
                let options = HandleOptions {
                    method: settings.blend,
                    ..HandleOptions::default()
                };
                let analysis = cache.of(mesh, &options.harmonic)?;
                let handles =
                    MotorHandles::bind_with_analysis(mesh, analysis, &sets, &rest, options)?;
                let blend = Box::new(handles.blend().clone());
                let scratch = blend.scratch();
                BoundMethod::Handles {
                    handles: Box::new(handles),
                    blend,
                    scratch,
                }
            }
            Method::Arap => {
                let arap = Arap::bind(mesh, &[], &sets, settings.arap)?;
                let scratch = Box::new(arap.scratch()?);
                BoundMethod::Arap {
                    arap: Box::new(arap),
                    scratch,
                    iterations: settings.iterations,
                    groups: sets.len(),
                }
            }
            Method::Spline => {
                let rest: Vec<ScaledMotor> = group_centres(mesh, groups)
                    .into_iter()
                    .map(|c| ScaledMotor::from_motor(Motor::from_translation(c)))
                    .collect();
                let options = SplineOptions {
                    method: settings.blend,
                    ..SplineOptions::default()
                };
                let (first, last) = (sets[0], sets[sets.len() - 1]);
                let spline = SplineDeformer::bind(mesh, first, last, &rest, options)?;
                let scratch = spline.scratch();
                BoundMethod::Spline {
                    spline: Box::new(spline),
                    keys: Vec::with_capacity(rest.len()),
                    rest,
                    scratch,
                }
            }
            Method::Ffd => {
                let options = FfdOptions {
                    form: settings.form(),
                    basis: settings.basis,
                };
                let ffd = Ffd::bind(mesh, settings.lattice, None, options)?;
                let controls = ControlPoints {
                    points: ffd.lattice().rest_points(),
                    edges: ffd.lattice().edges(),
                };
                BoundMethod::control(Box::new(ffd), controls)
            }
            Method::Cage => {
                let cage = cage.ok_or(MethodError::NoCage)?;
                let options = CageOptions {
                    form: settings.form(),
                    coordinates: settings.cage_coordinates(),
                    ..CageOptions::default()
                };
                let deformer = CageDeformer::bind(mesh, cage, options)?;
                let controls = ControlPoints {
                    points: cage.positions.clone(),
                    edges: cage.edges().edges,
                };
                BoundMethod::control(Box::new(deformer), controls)
            }
        })
    }

    fn control(
        deformer: Box<dyn Deformer<Scratch = ControlScratch>>,
        controls: ControlPoints,
    ) -> BoundMethod {
        let scratch = deformer.scratch();
        BoundMethod::Control {
            deformer,
            controls,
            scratch,
        }
    }

    /// The motors a pose takes: one per control point of a lattice or cage, else one per
    /// group.
    pub fn key_count(&self) -> usize {
        match self {
            BoundMethod::Control { controls, .. } => controls.points.len(),
            BoundMethod::Handles { blend, .. } => blend.key_count(),
            BoundMethod::Spline { rest, .. } => rest.len(),
            BoundMethod::Arap { groups, .. } | BoundMethod::Rest { groups } => *groups,
        }
    }

    /// The control points of a lattice or cage.
    pub fn controls(&self) -> Option<&ControlPoints> {
        match self {
            BoundMethod::Control { controls, .. } => Some(controls),
            _ => None,
        }
    }

    /// Another blend method with the same weights, where the method keeps them apart
    /// (handles); `false` where it must be bound again.
    pub fn reblend(&mut self, positions: &[DVec3], method: BlendMethod) -> Result<bool> {
        let BoundMethod::Handles { blend, scratch, .. } = self else {
            return Ok(false);
        };
        let rest = vec![ScaledMotor::IDENTITY; blend.key_count()];
        **blend = BoundBlend::bind(positions, blend.weights().clone(), &rest, method)?;
        *scratch = blend.scratch();
        Ok(true)
    }

    /// Pose by one motor per key into `out` (`rest`, the mesh's positions, for
    /// [`BoundMethod::Rest`]); ARAP runs its iterations from its last pose and returns its energy.
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
            BoundMethod::Rest { .. } => out.copy_from_slice(rest),
            BoundMethod::Handles { blend, scratch, .. } => {
                blend.pose_using(motors, scratch, out)?
            }
            BoundMethod::Arap {
                arap,
                scratch,
                iterations,
                ..
            } => {
                let mut last = f64::NAN;
                arap.pose_using(
                    &Targets::Motors(motors),
                    Stop::Iterations(*iterations),
                    scratch,
                    out,
                    |_, e| last = e,
                )?;
                return Ok(Some(last));
            }
            BoundMethod::Spline {
                spline,
                rest,
                scratch,
                keys,
            } => {
                keys.clear();
                keys.extend(rest.iter().zip(motors).map(|(r, m)| r.then(*m)));
                spline.pose_using(keys, scratch, out)?
            }
            BoundMethod::Control {
                deformer, scratch, ..
            } => deformer.pose_using(motors, scratch, out)?,
        }
        Ok(None)
    }
}
