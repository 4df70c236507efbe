//! `DirichletSolver::solve_into` with a reused scratch: the allocating solve's result, and no
//! allocation at all (counted by a global allocator in this test binary only).

use crate::common;
use deform::mesh::MeshError;

use deform::operators::laplacian::cotangent_laplacian;
use deform::operators::solve::{DirichletSolver, SolverOptions};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// Counts allocations made by the current thread while `COUNTING` is set.
struct Counter;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counter {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.with(|c| c.get()) {
            ALLOCATIONS.with(|a| a.set(a.get() + 1));
        }
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if COUNTING.with(|c| c.get()) {
            ALLOCATIONS.with(|a| a.set(a.get() + 1));
        }
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counter = Counter;

/// Allocations made by `f` on this thread.
fn allocations(f: impl FnOnce()) -> usize {
    ALLOCATIONS.with(|a| a.set(0));
    COUNTING.with(|c| c.set(true));
    f();
    COUNTING.with(|c| c.set(false));
    ALLOCATIONS.with(|a| a.get())
}

fn solver() -> DirichletSolver {
    let m = common::grid(30, 30, true);
    let q = cotangent_laplacian(&m, Default::default())
        .expect("L")
        .map(|v| -v);
    let bnd: Vec<u32> = (0..900).filter(|v| v % 30 == 0 || v % 30 == 29).collect();
    DirichletSolver::new(&q, &bnd, SolverOptions::default()).expect("solver")
}

#[test]
fn reused_scratch_gives_the_allocating_result_without_allocating() {
    let s = solver();
    let (n, nc) = (s.len(), s.constrained().len());
    let mut scratch = s.scratch(3).expect("scratch");
    let mut out = vec![0.0; 3 * n];
    for frame in 0..5 {
        let bc: Vec<f64> = (0..3 * nc)
            .map(|k| ((k + 7 * frame) as f64 * 0.37).sin())
            .collect();
        let expect = s.solve(&bc, 3).expect("allocating solve");
        let count = allocations(|| {
            s.solve_into(None, &bc, 3, &mut out, &mut scratch)
                .expect("solve_into");
        });
        assert_eq!(count, 0, "frame {frame} allocated");
        // The counter does count: the allocating solve allocates.
        assert!(allocations(|| drop(s.solve(&bc, 3))) > 0);
        assert_eq!(out, expect, "frame {frame}");
        // Fewer columns with the same scratch.
        let expect1 = s.solve(&bc[..nc], 1).expect("one column");
        s.solve_into(None, &bc[..nc], 1, &mut out[..n], &mut scratch)
            .expect("one column into");
        assert_eq!(&out[..n], expect1.as_slice());
    }
}

#[test]
fn a_scratch_too_small_or_for_another_solver_is_refused() {
    let s = solver();
    let nc = s.constrained().len();
    let mut small = s.scratch(1).expect("scratch");
    let mut out = vec![0.0; 2 * s.len()];
    assert!(matches!(
        s.solve_into(None, &vec![0.0; 2 * nc], 2, &mut out, &mut small),
        Err(deform::operators::SolveError::Mesh(
            MeshError::DimensionMismatch { .. }
        ))
    ));
    let other = DirichletSolver::new(
        &cotangent_laplacian(&common::grid(4, 4, false), Default::default())
            .expect("L")
            .map(|v| -v),
        &[0, 15],
        SolverOptions::default(),
    )
    .expect("other");
    let mut foreign = other.scratch(1).expect("scratch");
    assert!(matches!(
        s.solve_into(None, &vec![0.0; nc], 1, &mut out[..s.len()], &mut foreign),
        Err(deform::operators::SolveError::Mesh(
            MeshError::DimensionMismatch { .. }
        ))
    ));
}
