//! What both quick reports share: a deterministic input generator and a best-of-rounds timer.

use crate::grade::Spread;
use std::time::{Duration, Instant};

/// A small deterministic generator (no dependency on `rand`).
pub struct Lcg(pub u64);

impl Lcg {
    /// Uniform in [-1, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64) / ((1u64 << 53) as f64) * 2.0 - 1.0
    }

    /// A point in the cube [-3, 3)^3.
    pub fn vec3(&mut self) -> glam::DVec3 {
        glam::DVec3::new(self.uniform(), self.uniform(), self.uniform()) * 3.0
    }

    /// A rotation by up to 3 radians about a random axis.
    pub fn quat(&mut self) -> glam::DQuat {
        let axis =
            glam::DVec3::new(self.uniform(), self.uniform(), self.uniform() + 1e-3).normalize();
        glam::DQuat::from_axis_angle(axis, 3.0 * self.uniform())
    }

    /// A random unit motor.
    pub fn motor(&mut self) -> cga::Motor {
        let q = self.quat();
        cga::Motor::from_rotation_translation(q, self.vec3())
    }

    /// `K` coefficients in [-1, 1).
    pub fn array<const K: usize>(&mut self) -> [f64; K] {
        std::array::from_fn(|_| self.uniform())
    }
}

/// Nanoseconds per item of `f`, which processes `per_call` items per call: the best of 5
/// rounds that share `budget` (each round runs `f` at least once), with the range of the rounds.
pub fn time_ns(per_call: usize, budget: Duration, mut f: impl FnMut()) -> Spread {
    f();
    let mut rounds = [0.0; 5];
    for round in &mut rounds {
        let start = Instant::now();
        let mut iters = 0u64;
        while iters == 0 || start.elapsed() < budget / 5 {
            f();
            iters += 1;
        }
        *round = start.elapsed().as_nanos() as f64 / (iters as f64 * per_call as f64);
    }
    Spread::best_of(&mut rounds)
}
