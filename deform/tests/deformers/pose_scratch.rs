//! Explicit pose scratch: a bound deformer is shared by threads that each pose it
//! with their own scratch, and a warm scratch makes `pose` allocation-free.

use cga::ScaledMotor;
use deform::blend::control::ControlForm;
use deform::deformers::arap::{Arap, ArapOptions};
use deform::deformers::ffd::{Ffd, FfdOptions, LatticeBasis};
use deform::mesh::shapes::{tube, tube_ring};
use deform::skinning::{procedural_arm, Skinning};
use deform::{BlendMethod, Deformer, Mesh, MotorHandles, Poser};
use glam::{DQuat, DVec3};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// Counts the allocations of the current thread (so tests running at the same time on other
/// threads do not count).
struct CountingAllocator;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.with(|c| c.set(c.get() + 1));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

const SIDES: usize = 12;
const RINGS: usize = 24;

fn bar() -> Mesh {
    tube(1.0, 10.0, SIDES, RINGS)
}

/// A twist of `angle` about the bar's axis, lifted along `z`.
fn twist(angle: f64) -> ScaledMotor {
    ScaledMotor::from_scale_rotation_translation(
        1.0,
        DQuat::from_rotation_x(angle),
        DVec3::new(0.0, 0.0, 0.3 * angle),
    )
}

/// Every kind of bound deformer, by name, each with a key list maker.
type Keys = Box<dyn Fn(f64) -> Vec<ScaledMotor> + Sync>;

/// A pose loop: a deformer's [`Poser`] (the deformer and a scratch of its own type).
type PoseLoop<'a> = Box<dyn FnMut(&[ScaledMotor], &mut [DVec3]) + Send + 'a>;

/// What these tests need of a deformer, whatever its scratch type.
trait Posable: Sync {
    fn vertices(&self) -> usize;
    /// One pose with a fresh scratch.
    fn pose_once(&self, keys: &[ScaledMotor], out: &mut [DVec3]);
    fn pose_loop(&self) -> PoseLoop<'_>;
}

impl<D: Deformer> Posable for D {
    fn vertices(&self) -> usize {
        self.vertex_count()
    }

    fn pose_once(&self, keys: &[ScaledMotor], out: &mut [DVec3]) {
        self.pose(keys, out).expect("pose");
    }

    fn pose_loop(&self) -> PoseLoop<'_> {
        let mut poser = Poser::new(self);
        Box::new(move |keys, out| poser.pose(keys, out).expect("pose"))
    }
}

fn deformers() -> Vec<(String, Box<dyn Posable>, Keys)> {
    let mesh = bar();
    let first = tube_ring(SIDES, 0);
    let last = tube_ring(SIDES, RINGS - 1);
    let mut all: Vec<(String, Box<dyn Posable>, Keys)> = Vec::new();
    let two: Keys = Box::new(|t| vec![ScaledMotor::IDENTITY, twist(t)]);
    let handles = MotorHandles::bind(&mesh, &[&first, &last], Default::default()).expect("bind");
    all.push(("motor handles".into(), Box::new(handles), two));
    let arap = Arap::bind(&mesh, &first, &[&last], ArapOptions::default()).expect("bind");
    all.push(("arap".into(), Box::new(arap), Box::new(|t| vec![twist(t)])));
    for (name, form) in [
        ("ffd positional", ControlForm::Positional),
        ("ffd motor-log", ControlForm::Motor(BlendMethod::MotorLog)),
    ] {
        let options = FfdOptions {
            basis: LatticeBasis::BSpline(2),
            form,
        };
        let ffd = Ffd::bind(&mesh, [4, 3, 3], None, options).expect("bind");
        let n = ffd.key_count();
        all.push((
            name.into(),
            Box::new(ffd),
            Box::new(move |t| (0..n).map(|k| twist(t * k as f64 / n as f64)).collect()),
        ));
    }
    let rig = procedural_arm(8, 12);
    for method in BlendMethod::ALL {
        let skin = Skinning::bind(&rig, method).expect("bind");
        let rig = rig.clone();
        all.push((
            format!("skinning {}", method.name()),
            Box::new(skin),
            Box::new(move |t| {
                let pose = rig.pose(Some(0), t.abs().min(2.0), &[]).expect("pose");
                pose.skin_motors().expect("motors").to_vec()
            }),
        ));
    }
    all
}

#[test]
fn one_bound_deformer_poses_from_several_threads_at_once() {
    for (name, d, keys) in deformers() {
        let times: Vec<f64> = (0..8).map(|k| 0.1 + 0.2 * k as f64).collect();
        // The truth: one thread, one fresh scratch per pose.
        let expected: Vec<Vec<DVec3>> = times
            .iter()
            .map(|&t| {
                let mut out = vec![DVec3::ZERO; d.vertices()];
                d.pose_once(&keys(t), &mut out);
                out
            })
            .collect();
        let start = std::sync::Barrier::new(4);
        std::thread::scope(|s| {
            for thread in 0..4 {
                let (d, keys, times, expected, start) = (&*d, &keys, &times, &expected, &start);
                let name = &name;
                s.spawn(move || {
                    let mut pose = d.pose_loop();
                    let mut out = vec![DVec3::ZERO; d.vertices()];
                    start.wait();
                    for round in 0..3 {
                        for k in 0..times.len() {
                            // Each thread walks the poses in its own order.
                            let k = (k * (thread + 1) + round) % times.len();
                            pose(&keys(times[k]), &mut out);
                            let worst = out
                                .iter()
                                .zip(&expected[k])
                                .map(|(a, b)| (*a - *b).length())
                                .fold(0.0, f64::max);
                            assert!(
                                worst <= 1e-12,
                                "{name}: thread {thread}, pose {k}: off by {worst:e}"
                            );
                        }
                    }
                });
            }
        });
    }
}

#[test]
fn a_warm_scratch_poses_without_allocating() {
    // One worker thread, so every allocation of a pose happens on the thread that counts.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    for (name, d, keys) in deformers() {
        let key_lists: Vec<Vec<ScaledMotor>> = (0..3).map(|k| keys(0.3 + 0.4 * k as f64)).collect();
        let counted = pool.install(|| {
            let mut pose = d.pose_loop();
            let mut out = vec![DVec3::ZERO; d.vertices()];
            pose(&key_lists[0], &mut out);
            let before = allocations();
            for k in &key_lists {
                pose(k, &mut out);
            }
            allocations() - before
        });
        assert_eq!(counted, 0, "{name}: {counted} allocations in 3 warm poses");
    }
}

#[test]
fn the_counter_counts() {
    let before = allocations();
    let v: Vec<u64> = std::hint::black_box(vec![1, 2, 3]);
    assert!(allocations() > before, "{v:?}");
}

/// The scratch of another kind of deformer does not compile (the `compile_fail` example of
/// `deform::Deformer`); the scratch of another deformer of the same kind (another mesh) is
/// replaced, never misread.
#[test]
fn a_scratch_of_another_arap_is_replaced_not_misread() {
    let mesh = bar();
    let first = tube_ring(SIDES, 0);
    let last = tube_ring(SIDES, RINGS - 1);
    let arap = Arap::bind(&mesh, &first, &[&last], ArapOptions::default()).expect("bind");
    let keys = [twist(0.5)];
    let mut expected = vec![DVec3::ZERO; arap.vertex_count()];
    Deformer::pose(&arap, &keys, &mut expected).expect("pose");
    let other_mesh = tube(1.0, 5.0, 8, 10);
    let other = Arap::bind(
        &other_mesh,
        &tube_ring(8, 0),
        &[&tube_ring(8, 9)],
        ArapOptions::default(),
    )
    .expect("bind");
    let mut foreign = Deformer::scratch(&other);
    let mut out = vec![DVec3::ZERO; other.vertex_count()];
    Deformer::pose_using(&other, &[twist(0.2)], &mut foreign, &mut out).expect("pose");
    let mut posed = vec![DVec3::ZERO; arap.vertex_count()];
    Deformer::pose_using(&arap, &keys, &mut foreign, &mut posed).expect("pose");
    assert_eq!(posed, expected);
    // And the scratch now serves this ARAP: a warm second pose agrees to rounding (the same
    // 1e-12 as the threads above; a warm scratch is not bit-for-bit a fresh one).
    Deformer::pose_using(&arap, &keys, &mut foreign, &mut posed).expect("pose");
    let worst = posed
        .iter()
        .zip(&expected)
        .map(|(a, b)| (*a - *b).length())
        .fold(0.0, f64::max);
    assert!(worst <= 1e-12, "off by {worst:e}");
}

/// FABRIK + B-spline (the first paper's Fig. 5): a warm `ChainScratch` poses the chain
/// towards new targets without allocating, agrees with the one-off `pose_to_target`, and a
/// scratch of a chain with other joint and control counts is resized, not misread.
#[test]
fn a_warm_chain_scratch_poses_to_targets_without_allocating() {
    use deform::deformers::fabrik::{straight_chain, FabrikOptions};
    use deform::deformers::spline::SplineOptions;
    let mesh = bar();
    let (first, last) = (tube_ring(SIDES, 0), tube_ring(SIDES, RINGS - 1));
    let bind = |joints: usize, controls: usize| {
        let chain = straight_chain(&mesh, &first, &last, joints);
        let options = SplineOptions::default();
        deform::ChainDeformer::bind(&mesh, &first, &last, &chain, controls, options).expect("bind")
    };
    let d = bind(7, 4);
    let options = FabrikOptions::default();
    let targets = [
        DVec3::new(8.0, 3.0, 0.0),
        DVec3::new(6.0, -2.0, 4.0),
        DVec3::new(30.0, 0.0, 0.0), // out of reach: the chain stretches towards it
    ];
    // A scratch warmed by a chain of other counts first.
    let other = bind(4, 3);
    let mut scratch = other.chain_scratch();
    let mut out = vec![DVec3::ZERO; mesh.positions.len()];
    other
        .pose_to_target_using(targets[0], &options, &mut scratch, &mut out)
        .expect("pose");
    d.pose_to_target_using(targets[0], &options, &mut scratch, &mut out)
        .expect("pose");
    let mut summaries = Vec::with_capacity(targets.len());
    let mut posed = vec![vec![DVec3::ZERO; out.len()]; targets.len()];
    // One worker thread, so every allocation of a pose happens on the thread that counts.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    let counted = pool.install(|| {
        let before = allocations();
        for (t, p) in targets.iter().zip(&mut posed) {
            let summary = d
                .pose_to_target_using(*t, &options, &mut scratch, p)
                .expect("pose");
            summaries.push(summary);
        }
        allocations() - before
    });
    assert_eq!(
        counted,
        0,
        "{counted} allocations in {} warm poses",
        targets.len()
    );
    for ((t, p), summary) in targets.iter().zip(&posed).zip(&summaries) {
        let r = d.pose_to_target(*t, &options, &mut out).expect("pose");
        assert_eq!(r.solution.status, summary.status);
        assert_eq!(r.fit.max_residual, summary.max_residual);
        let worst = out
            .iter()
            .zip(p)
            .map(|(a, b)| (*a - *b).length())
            .fold(0.0, f64::max);
        assert!(worst <= 1e-12, "target {t}: off by {worst:e}");
    }
    // The last pose's joints and controls stay in the scratch: the stretched chain points at
    // the unreachable target.
    let joints = scratch.joints();
    let dir = (joints[joints.len() - 1] - joints[0]).normalize();
    assert!((dir - (targets[2] - joints[0]).normalize()).length() < 1e-9);
    assert_eq!(scratch.controls().len(), 4);
}
