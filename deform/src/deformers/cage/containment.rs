//! Does the cage enclose the model? The generalised winding number of a closed triangle mesh
//! at a point (the sum of the signed solid angles of its faces over `4 pi`, Van Oosterom and
//! Strackee's formula) is 1 inside, 0 outside (for a consistently oriented, outward cage).

use super::CageError;
use crate::deformers::Result;
use crate::mesh::Mesh;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;

/// A point counts as enclosed when its winding number is at least this (a point on the cage
/// surface has 1/2).
pub const ENCLOSED: f64 = 0.5;

/// The winding number of the closed triangle mesh `cage` at `x`.
pub fn winding_number(cage: &Mesh, x: DVec3) -> f64 {
    let mut sum = 0.0;
    for t in &cage.triangles {
        let a = cage.positions[t[0] as usize] - x;
        let b = cage.positions[t[1] as usize] - x;
        let c = cage.positions[t[2] as usize] - x;
        let (la, lb, lc) = (a.length(), b.length(), c.length());
        let num = a.dot(b.cross(c));
        let den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        sum += 2.0 * num.atan2(den);
    }
    sum / (4.0 * PI)
}

/// The winding numbers of `cage` at `points` (parallel).
pub fn winding_numbers(cage: &Mesh, points: &[DVec3]) -> Vec<f64> {
    points
        .par_iter()
        .with_min_len(256)
        .map(|&p| winding_number(cage, p))
        .collect()
}

/// The orientation sign of a closed cage: `1` when it faces outward, `-1` when inward (the
/// sign of its signed volume).
pub fn orientation(cage: &Mesh) -> f64 {
    if cage.volume() < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// Check that `cage` (closed, see [`super::check_cage`]) encloses every point: winding number
/// at least [`ENCLOSED`] (after correcting for an inward-facing cage).
///
/// # Errors
/// [`CageError::NotEnclosing`] naming the points outside.
pub fn check_encloses(cage: &Mesh, points: &[DVec3]) -> Result<()> {
    check_winding(orientation(cage), &winding_numbers(cage, points))
}

/// Check winding numbers `w` (of a cage of orientation `sign`) against [`ENCLOSED`].
///
/// # Errors
/// [`CageError::NotEnclosing`] naming the points outside.
pub fn check_winding(sign: f64, w: &[f64]) -> Result<()> {
    let outside: Vec<u32> = (0..w.len())
        .filter(|&i| (sign * w[i]).is_nan() || sign * w[i] < ENCLOSED)
        .map(|i| i as u32)
        .collect();
    if outside.is_empty() {
        return Ok(());
    }
    let lowest = outside
        .iter()
        .map(|&i| sign * w[i as usize])
        .fold(f64::INFINITY, f64::min);
    Err(CageError::NotEnclosing {
        count: outside.len(),
        vertices: outside.into(),
        lowest,
    }
    .into())
}
