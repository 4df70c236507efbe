//! FABRIK inverse kinematics for one chain (Aristidou and Lasenby 2011), and the first
//! paper's Fig. 5 pipeline: the joint frames of the solved chain are key motors `Q_i`, a
//! cubic B-spline is fitted to them (section III.C) and drives a spline-aligned deformation.

use crate::blend::KeyError;
use crate::deformers::bspline::{BsplineFit, BsplineFitter, FitScratch, FitSolver};
use crate::deformers::deformer::{deformer_via_blend, Deformer};
use crate::deformers::spline::{SplineDeformer, SplineOptions, WeightScheme};
use crate::deformers::Result;
use crate::mesh::Mesh;
use cga::ScaledMotor;
use glam::{DQuat, DVec3};

/// Stop rule of [`fabrik`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FabrikOptions {
    /// The end effector is close enough when within this distance of the target.
    pub tolerance: f64,
    /// The most forward-and-backward passes.
    pub max_iterations: usize,
}

impl Default for FabrikOptions {
    fn default() -> Self {
        FabrikOptions {
            tolerance: 1e-6,
            max_iterations: 100,
        }
    }
}

/// How a FABRIK solve ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FabrikStatus {
    /// The end effector is within the tolerance of the target.
    Reached,
    /// The target is farther from the root than the chain is long: the chain is stretched
    /// straight towards it (the closest pose).
    Unreachable,
    /// Reachable, but the iteration cap came first.
    IterationLimit,
}

/// A solved chain.
#[derive(Clone, Debug, PartialEq)]
pub struct FabrikSolution {
    /// Joint positions, root first (the root does not move).
    pub joints: Vec<DVec3>,
    /// How the solve ended.
    pub status: FabrikStatus,
    /// Passes made.
    pub iterations: usize,
    /// Distance from the end effector to the target.
    pub distance: f64,
}

/// Check a chain: at least 2 joints, every joint finite, every bone of positive finite
/// length.
fn check_chain(joints: &[DVec3]) -> Result<()> {
    if joints.len() < 2 {
        return Err(KeyError::BadSetup(format!(
            "a chain needs at least 2 joints, got {}",
            joints.len()
        ))
        .into());
    }
    if let Some(i) = joints.iter().position(|p| !p.is_finite()) {
        return Err(KeyError::BadSetup(format!("joint {i} is not finite")).into());
    }
    for (i, w) in joints.windows(2).enumerate() {
        let l = w[0].distance(w[1]);
        if l.is_nan() || l <= 0.0 || !l.is_finite() {
            return Err(KeyError::BadSetup(format!(
                "bone {i} (joints {i} and {}) has length {l}",
                i + 1
            ))
            .into());
        }
    }
    Ok(())
}

/// Check a chain and return its bone lengths.
fn bone_lengths(joints: &[DVec3]) -> Result<Vec<f64>> {
    check_chain(joints)?;
    Ok(joints.windows(2).map(|w| w[0].distance(w[1])).collect())
}

/// `b` moved to distance `l` from `a` along `b - a` (or along `fallback` when they coincide).
#[inline]
fn place(a: DVec3, b: DVec3, l: f64, fallback: DVec3) -> DVec3 {
    a + l * direction(a, b).unwrap_or(fallback)
}

/// `b - a` and its largest component, from the halves (exact; no overflow for any finite
/// `a`, `b`).
fn half_difference(a: DVec3, b: DVec3) -> (DVec3, f64) {
    let v = 0.5 * b - 0.5 * a;
    (v, v.abs().max_element())
}

/// The unit direction from `a` to `b`, also where `|b - a|^2` overflows (a target 1e300 away
/// once left the chain at rest); `None` where they coincide.
fn direction(a: DVec3, b: DVec3) -> Option<DVec3> {
    let (v, m) = half_difference(a, b);
    (m > 0.0).then(|| (v / m).try_normalize()).flatten()
}

/// `|b - a|` without overflow where it is representable (a target 1e300 away is 1e300 short,
/// not infinitely).
fn distance(a: DVec3, b: DVec3) -> f64 {
    let (v, m) = half_difference(a, b);
    if m == 0.0 {
        0.0
    } else {
        2.0 * m * (v / m).length()
    }
}

/// Solve the chain `joints` (root first; its bone lengths are kept) for the end effector to
/// reach `target`, starting from the given pose (pass the previous solution to warm-start).
///
/// # Errors
/// [`KeyError::BadSetup`] for fewer than 2 joints, a non-finite joint, a zero-length bone, a
/// non-finite target or a tolerance that is not positive.
pub fn fabrik(joints: &[DVec3], target: DVec3, options: &FabrikOptions) -> Result<FabrikSolution> {
    let lengths = bone_lengths(joints)?;
    let mut p = joints.to_vec();
    let (status, iterations, distance) = solve_into(joints, &lengths, target, options, &mut p)?;
    Ok(FabrikSolution {
        joints: p,
        status,
        iterations,
        distance,
    })
}

/// [`fabrik`] from the checked chain `joints` with its bone `lengths`, solved in `p` (resized
/// to the chain): the status, the passes made and the end effector's distance to the target.
fn solve_into(
    joints: &[DVec3],
    lengths: &[f64],
    target: DVec3,
    options: &FabrikOptions,
    p: &mut Vec<DVec3>,
) -> Result<(FabrikStatus, usize, f64)> {
    if !target.is_finite() {
        return Err(KeyError::BadSetup("the target is not finite".into()).into());
    }
    if options.tolerance.is_nan() || options.tolerance <= 0.0 {
        return Err(KeyError::BadSetup("the tolerance must be positive".into()).into());
    }
    let n = joints.len();
    let root = joints[0];
    p.clear();
    p.extend_from_slice(joints);
    let total: f64 = lengths.iter().sum();
    let fallback = (joints[n - 1] - root).try_normalize().unwrap_or(DVec3::X);
    if distance(root, target) > total {
        for i in 0..n - 1 {
            p[i + 1] = place(p[i], target, lengths[i], fallback);
        }
        return Ok((FabrikStatus::Unreachable, 0, distance(p[n - 1], target)));
    }
    let mut iterations = 0;
    let mut distance = distance(p[n - 1], target);
    while distance > options.tolerance && iterations < options.max_iterations {
        // Forward: the end effector onto the target, back to the root.
        p[n - 1] = target;
        for i in (0..n - 1).rev() {
            p[i] = place(p[i + 1], p[i], lengths[i], -fallback);
        }
        // Backward: the root back in place, out to the end effector.
        p[0] = root;
        for i in 0..n - 1 {
            p[i + 1] = place(p[i], p[i + 1], lengths[i], fallback);
        }
        iterations += 1;
        distance = self::distance(p[n - 1], target);
    }
    let status = if distance <= options.tolerance {
        FabrikStatus::Reached
    } else {
        FabrikStatus::IterationLimit
    };
    Ok((status, iterations, distance))
}

/// The key motors `Q_i` of a posed chain relative to its rest pose: joint `i`'s frame turns
/// by the shortest rotation taking its rest bone direction to its posed one (the outgoing
/// bone; the last joint uses its incoming bone) and moves the rest joint onto the posed one:
/// `x -> R_i (x - rest_i) + posed_i`.
///
/// # Errors
/// [`KeyError::BadSetup`] when the chains differ in length or have a zero-length bone.
pub fn chain_key_motors(rest: &[DVec3], posed: &[DVec3]) -> Result<Vec<ScaledMotor>> {
    check_chain(rest)?;
    check_chain(posed)?;
    if rest.len() != posed.len() {
        return Err(KeyError::BadSetup(format!(
            "rest chain has {} joints, posed chain {}",
            rest.len(),
            posed.len()
        ))
        .into());
    }
    let mut keys = vec![ScaledMotor::IDENTITY; rest.len()];
    key_motors_into(rest, posed, &mut keys);
    Ok(keys)
}

/// [`chain_key_motors`] of two checked chains of the same length, into `keys` (one per joint).
fn key_motors_into(rest: &[DVec3], posed: &[DVec3], keys: &mut [ScaledMotor]) {
    let n = rest.len();
    for (i, key) in keys.iter_mut().enumerate() {
        let b = i.min(n - 2);
        let from = (rest[b + 1] - rest[b]).normalize();
        let to = (posed[b + 1] - posed[b]).normalize();
        let q = DQuat::from_rotation_arc(from, to);
        *key = ScaledMotor::from_scale_rotation_translation(1.0, q, posed[i] - q * rest[i]);
    }
}

/// The spline parameter of each joint: its distance from the root along the rest chain,
/// divided by the chain's length.
///
/// # Errors
/// As [`chain_key_motors`].
pub fn chain_parameters(rest: &[DVec3]) -> Result<Vec<f64>> {
    Ok(parameters_of(&bone_lengths(rest)?))
}

/// [`chain_parameters`] from the bone lengths of a checked chain.
fn parameters_of(lengths: &[f64]) -> Vec<f64> {
    let total: f64 = lengths.iter().sum();
    let mut acc = 0.0;
    let mut out = vec![0.0];
    for l in lengths {
        acc += l;
        out.push((acc / total).min(1.0));
    }
    out
}

/// The result of [`ChainDeformer::pose_to_target`].
#[derive(Clone, Debug)]
pub struct ChainPose {
    /// The solved chain.
    pub solution: FabrikSolution,
    /// The B-spline fitted to its joint frames (the keys the mesh was posed with).
    pub fit: BsplineFit,
}

/// What [`ChainDeformer::pose_to_target_using`] reports; the solved joints and the fitted
/// controls stay in its [`ChainScratch`] ([`ChainScratch::joints`], [`ChainScratch::controls`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChainPoseSummary {
    /// How the solve ended.
    pub status: FabrikStatus,
    /// FABRIK passes made.
    pub iterations: usize,
    /// Distance from the end effector to the target.
    pub distance: f64,
    /// The fit's largest residual (see [`BsplineFit::max_residual`]).
    pub max_residual: f64,
}

/// The working memory of [`ChainDeformer::pose_to_target_using`], owned by the caller: after
/// one pose, further poses allocate nothing.
#[derive(Clone, Debug)]
pub struct ChainScratch {
    joints: Vec<DVec3>,
    keys: Vec<ScaledMotor>,
    controls: Vec<ScaledMotor>,
    fit: FitScratch,
    spline: <SplineDeformer as Deformer>::Scratch,
}

impl ChainScratch {
    /// The solved joints of the last pose, root first.
    pub fn joints(&self) -> &[DVec3] {
        &self.joints
    }

    /// The control motors the last pose was posed with.
    pub fn controls(&self) -> &[ScaledMotor] {
        &self.controls
    }
}

/// A mesh bound to a kinematic chain (the paper's Fig. 5): moving the chain's end effector
/// solves the chain by FABRIK, fits a cubic B-spline of `control_count` motors to its joint
/// frames and poses the mesh by spline-aligned deformation. The fit's matrices are prepared at
/// bind; a pose with a warm [`ChainScratch`] allocates nothing.
#[derive(Clone, Debug)]
pub struct ChainDeformer {
    spline: SplineDeformer,
    rest: Vec<DVec3>,
    lengths: Vec<f64>,
    fitter: BsplineFitter,
}

impl ChainDeformer {
    /// Bind `mesh` to the chain `joints` (rest pose, root first): `lambda` is the harmonic
    /// field from `root_set` (0) to `tip_set` (1), and the mesh is posed by a cubic B-spline
    /// of `control_count` motors (at most the number of joints).
    ///
    /// # Errors
    /// The errors of [`SplineDeformer::bind`] and [`chain_parameters`];
    /// [`KeyError::BadSetup`] when `control_count` is below 2 or above the number of joints.
    pub fn bind(
        mesh: &Mesh,
        root_set: &[u32],
        tip_set: &[u32],
        joints: &[DVec3],
        control_count: usize,
        options: SplineOptions,
    ) -> Result<Self> {
        let lengths = bone_lengths(joints)?;
        let parameters = parameters_of(&lengths);
        if control_count < 2 || control_count > joints.len() {
            return Err(KeyError::BadSetup(format!(
                "{control_count} control motors for a chain of {} joints",
                joints.len()
            ))
            .into());
        }
        let fitter = BsplineFitter::new(&parameters, control_count)?;
        let options = SplineOptions {
            scheme: WeightScheme::BSpline,
            ..options
        };
        let rest = vec![ScaledMotor::IDENTITY; control_count];
        let spline = SplineDeformer::bind(mesh, root_set, tip_set, &rest, options)?;
        Ok(ChainDeformer {
            spline,
            lengths,
            rest: joints.to_vec(),
            fitter,
        })
    }

    /// The chain's rest joints.
    pub fn rest_joints(&self) -> &[DVec3] {
        &self.rest
    }

    /// The spline deformer underneath (its `lambda`, its blend).
    pub fn spline(&self) -> &SplineDeformer {
        &self.spline
    }

    /// How the fit's normal equations are solved (fixed at bind by the joints' parameters).
    pub fn fit_solver(&self) -> FitSolver {
        self.fitter.solver()
    }

    /// A scratch for [`ChainDeformer::pose_to_target_using`], sized for this chain and mesh.
    pub fn chain_scratch(&self) -> ChainScratch {
        let (n, m) = (self.rest.len(), self.spline.key_count());
        ChainScratch {
            joints: Vec::with_capacity(n),
            keys: vec![ScaledMotor::IDENTITY; n],
            controls: vec![ScaledMotor::IDENTITY; m],
            fit: FitScratch::default(),
            spline: self.spline.scratch(),
        }
    }

    /// Move the end effector towards `target` and pose the mesh, in one call: FABRIK from the
    /// rest chain, joint frames as key motors, B-spline fit, spline-aligned deformation.
    /// An unreachable target stretches the chain towards it (see [`FabrikStatus`]). For a pose
    /// loop, [`ChainDeformer::pose_to_target_using`] keeps the working memory.
    ///
    /// # Errors
    /// As [`fabrik`], [`BsplineFitter::fit_into`] and [`Deformer::pose`].
    pub fn pose_to_target(
        &self,
        target: DVec3,
        options: &FabrikOptions,
        positions: &mut [DVec3],
    ) -> Result<ChainPose> {
        let mut scratch = self.chain_scratch();
        let summary = self.pose_to_target_using(target, options, &mut scratch, positions)?;
        Ok(ChainPose {
            solution: FabrikSolution {
                joints: scratch.joints,
                status: summary.status,
                iterations: summary.iterations,
                distance: summary.distance,
            },
            fit: BsplineFit {
                controls: scratch.controls,
                max_residual: summary.max_residual,
                solver: self.fitter.solver(),
            },
        })
    }

    /// [`ChainDeformer::pose_to_target`] with the caller's scratch (from
    /// [`ChainDeformer::chain_scratch`]; one of another chain is resized): allocation-free
    /// once the scratch has served a pose of this chain.
    ///
    /// # Errors
    /// As [`ChainDeformer::pose_to_target`].
    pub fn pose_to_target_using(
        &self,
        target: DVec3,
        options: &FabrikOptions,
        scratch: &mut ChainScratch,
        positions: &mut [DVec3],
    ) -> Result<ChainPoseSummary> {
        let (status, iterations, distance) = solve_into(
            &self.rest,
            &self.lengths,
            target,
            options,
            &mut scratch.joints,
        )?;
        check_chain(&scratch.joints)?;
        let (n, m) = (self.rest.len(), self.spline.key_count());
        scratch.keys.resize(n, ScaledMotor::IDENTITY);
        scratch.controls.resize(m, ScaledMotor::IDENTITY);
        key_motors_into(&self.rest, &scratch.joints, &mut scratch.keys);
        let max_residual =
            self.fitter
                .fit_into(&scratch.keys, &mut scratch.fit, &mut scratch.controls)?;
        self.spline
            .pose_using(&scratch.controls, &mut scratch.spline, positions)?;
        Ok(ChainPoseSummary {
            status,
            iterations,
            distance,
            max_residual,
        })
    }
}

deformer_via_blend!(ChainDeformer, spline, crate::blend::PreparedKeys);

/// A straight chain of `n` joints (at least 2) from the centroid of vertices `a` of `mesh` to
/// the centroid of `b`: the chain a FABRIK deformer starts from when none is given.
///
/// ```
/// use deform::deformers::fabrik::straight_chain;
/// let bar = deform::mesh::shapes::tube(1.0, 10.0, 4, 3);
/// let (a, b) = (deform::mesh::shapes::tube_ring(4, 0), deform::mesh::shapes::tube_ring(4, 2));
/// let chain = straight_chain(&bar, &a, &b, 3);
/// assert!((chain[1] - glam::DVec3::new(5.0, 0.0, 0.0)).length() < 1e-12);
/// ```
pub fn straight_chain(mesh: &Mesh, a: &[u32], b: &[u32], n: usize) -> Vec<DVec3> {
    let centroid = |s: &[u32]| {
        s.iter().map(|&v| mesh.positions[v as usize]).sum::<DVec3>() / s.len().max(1) as f64
    };
    let (p, q) = (centroid(a), centroid(b));
    let n = n.max(2);
    (0..n)
        .map(|i| p.lerp(q, i as f64 / (n - 1) as f64))
        .collect()
}
