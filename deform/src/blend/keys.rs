//! The keys of one pose, prepared in the form a blend method needs.

use super::{BlendMethod, Row};
use crate::blend::KeyError;
use crate::blend::Result;
use cga::wide::{F64x4, Lane};
use cga::{Bivector, Motor, ScaledMotor};
use glam::{Affine3A, DAffine3, DMat3, DQuat, DVec3, Vec3A};

/// `a.0[0] b.0[0] + ... + a.0[3] b.0[3]`, summed left to right: the hemisphere test of two
/// rotor (or quaternion) rows, here and in the batch kernels.
#[inline(always)]
pub(super) fn dot(a: F64x4, b: F64x4) -> f64 {
    let p = a * b;
    p.0[0] + p.0[1] + p.0[2] + p.0[3]
}

/// Key counts up to which the hemisphere-aligned rows are tabulated per pose (64 keys: a
/// 512 KiB table, cheap next to any mesh such rigs skin).
const ALIGNED_MAX_KEYS: usize = 64;

/// The keys in the form one blend method needs. Reused from pose to pose (its buffers keep
/// their capacity), so posing does not allocate.
#[derive(Clone, Debug, Default)]
pub struct PreparedKeys {
    method: BlendMethod,
    /// The number of keys prepared.
    count: usize,
    /// Whether any key scales (otherwise the cheaper rigid paths are taken).
    pub(super) scaled: bool,
    pub(super) logs: Vec<Bivector>,
    pub(super) motors: Vec<Motor>,
    pub(super) log_scales: Vec<f64>,
    pub(super) quats: Vec<(DQuat, DQuat)>,
    pub(super) affines: Vec<DAffine3>,
    pub(super) affines_f32: Vec<Affine3A>,
    /// Equation (17): per key the rows `e1, e2, e3` (columns `e1, e2, e3, 1`) of the point
    /// matrix of `M X ~M`, and its constant `eo` coefficient.
    pub(super) conformal: Vec<ConformalKey>,
    /// The keys as four [`F64x4`] rows each, for the batch kernels (`kernels.rs`, which says
    /// what each method keeps in them).
    pub(super) rows: Vec<[F64x4; 4]>,
}

/// The part of a scaled motor's point matrix ([`ScaledMotor::point_matrix`]) that
/// down-projection needs: `X' = M up(x) ~M` has `e1, e2, e3` coefficients `rows * (x, 1)` and
/// `eo` coefficient `eo` (independent of `x`), and `down(X') = rows * (x, 1) / eo`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ConformalKey {
    /// Rows `e1, e2, e3`; columns `e1, e2, e3, 1`.
    pub rows: [[f64; 4]; 3],
    /// The `eo` coefficient.
    pub eo: f64,
}

impl ConformalKey {
    /// From the generated point matrix of `m` (rows `eo, e1, e2, e3, ei`; columns
    /// `e1, e2, e3, ei, 1`). The `e1..e3` rows have no `ei` column and the `eo` row only a
    /// constant: the sandwich of a similarity keeps points finite. That constant is taken from
    /// [`ScaledMotor::origin_weight`], its factored form. `m` may be any non-zero multiple of a
    /// scaled motor (it is normalised first).
    pub fn new(m: &ScaledMotor) -> ConformalKey {
        // The point matrix's formulas hold for `S ~S = 1`; a multiple (which every other
        // method accepts as the same motion) is brought back to it first.
        let m = m.normalize_similarity();
        let p = m.point_matrix().rows();
        debug_assert!((1..4).all(|r| p[r][3] == 0.0) && p[0][..4].iter().all(|&x| x == 0.0));
        let row = |r: usize| [p[r][0], p[r][1], p[r][2], p[r][4]];
        ConformalKey {
            rows: [row(1), row(2), row(3)],
            // `p[0][4]` in factored form: the expanded one loses eps * scale^2.
            eo: m.origin_weight(),
        }
    }

    /// The same image as a normalised conformal point (`eo` coefficient 1): the form in which
    /// equation (17) adds its terms. The sandwich of a dilator of scale `s` gives `up(s x) / s`;
    /// summed unnormalised, each term would weigh `w / s` instead of `w` and the two evaluation
    /// orders of the paper (add then down-project, down-project then add), which it calls two
    /// ways of computing the same sum, would differ under dilation.
    pub fn normalised(&self) -> ConformalKey {
        let s = 1.0 / self.eo;
        ConformalKey {
            rows: self.rows.map(|r| r.map(|x| x * s)),
            eo: 1.0,
        }
    }

    /// `w * self + acc`.
    #[inline(always)]
    fn mul_add(&self, w: f64, acc: ConformalKey) -> ConformalKey {
        let r = |i: usize| {
            let (a, b) = (self.rows[i], acc.rows[i]);
            [
                b[0] + w * a[0],
                b[1] + w * a[1],
                b[2] + w * a[2],
                b[3] + w * a[3],
            ]
        };
        ConformalKey {
            rows: [r(0), r(1), r(2)],
            eo: acc.eo + w * self.eo,
        }
    }

    /// The `e1, e2, e3` coefficients of the image of `up(p)`.
    #[inline(always)]
    fn euclidean(&self, p: DVec3) -> DVec3 {
        let r = |i: usize| {
            let a = self.rows[i];
            a[0] * p.x + a[1] * p.y + a[2] * p.z + a[3]
        };
        DVec3::new(r(0), r(1), r(2))
    }

    /// `down(M up(p) ~M)`.
    #[inline(always)]
    pub fn transform_point(&self, p: DVec3) -> DVec3 {
        self.euclidean(p) / self.eo
    }

    /// The affine map `p -> down(...)`.
    fn affine(&self) -> DAffine3 {
        let s = 1.0 / self.eo;
        let c = |j: usize| DVec3::new(self.rows[0][j], self.rows[1][j], self.rows[2][j]) * s;
        DAffine3::from_cols(c(0), c(1), c(2), c(3))
    }
}

impl PreparedKeys {
    /// Check the keys and prepare them for `method` (allocates; see [`PreparedKeys::prepare`]).
    ///
    /// # Errors
    /// As [`PreparedKeys::prepare`].
    pub fn new(keys: &[ScaledMotor], method: BlendMethod) -> Result<Self> {
        let mut p = PreparedKeys::default();
        p.prepare(keys, method)?;
        Ok(p)
    }

    /// Check the keys and prepare them for `method`, reusing this value's buffers.
    ///
    /// # Errors
    /// [`KeyError::TooMany`], or [`KeyError::Invalid`] naming the first key that is not a
    /// finite scaled motor.
    pub fn prepare(&mut self, keys: &[ScaledMotor], method: BlendMethod) -> Result<()> {
        KeyError::check_count("keys", keys.len())?;
        self.reset(method, false);
        for (j, k) in keys.iter().enumerate() {
            let log = k
                .try_log()
                .map_err(|source| KeyError::Invalid { index: j, source })?;
            self.logs.push(log);
            self.log_scales.push(2.0 * log.eoi);
            self.scaled |= log.eoi != 0.0;
            match method {
                BlendMethod::Conformal | BlendMethod::ConformalProjected => {
                    self.conformal.push(ConformalKey::new(k).normalised());
                    continue;
                }
                BlendMethod::MatrixF32 => {
                    let (s, q, t) = k.to_scale_rotation_translation();
                    self.affines_f32
                        .push(Affine3A::from_scale_rotation_translation(
                            glam::Vec3::splat(s as f32),
                            q.normalize().as_quat(),
                            t.as_vec3(),
                        ));
                    continue;
                }
                _ => {}
            }
            if method != BlendMethod::MotorLog {
                let (s, q, t) = k.to_scale_rotation_translation();
                let q = q.normalize();
                self.motors.push(Motor::from_rotation_translation(q, t));
                let d = DQuat::from_vec4((0.5 * t).extend(0.0)) * q;
                self.quats.push((q, d));
                self.affines.push(DAffine3::from_scale_rotation_translation(
                    DVec3::splat(s),
                    q,
                    t,
                ));
            }
        }
        self.fill_rows();
        self.count = keys.len();
        Ok(())
    }

    /// Empty every buffer (keeping its capacity) for a new pose by `method`.
    fn reset(&mut self, method: BlendMethod, scaled: bool) {
        self.method = method;
        self.count = 0;
        self.scaled = scaled;
        self.logs.clear();
        self.log_scales.clear();
        self.motors.clear();
        self.quats.clear();
        self.affines.clear();
        self.affines_f32.clear();
        self.conformal.clear();
        self.rows.clear();
    }

    /// Prepare any affine maps (not only similarities: glTF's skin matrices, `global * inverse
    /// bind`, may scale non-uniformly or shear) as the keys of a matrix method,
    /// [`BlendMethod::Matrix`] or [`BlendMethod::MatrixF32`], reusing this value's buffers.
    ///
    /// # Errors
    /// [`KeyError::TooMany`]; [`KeyError::Affine`] for another method or a map that is not
    /// finite.
    pub fn prepare_affine(&mut self, maps: &[DAffine3], method: BlendMethod) -> Result<()> {
        KeyError::check_count("keys", maps.len())?;
        if !matches!(method, BlendMethod::Matrix | BlendMethod::MatrixF32) {
            return Err(KeyError::Affine(format!(
                "affine keys are blended by matrix skinning only, not by {}",
                method.name()
            ))
            .into());
        }
        if let Some(j) = maps.iter().position(|m| !m.is_finite()) {
            return Err(KeyError::Affine(format!("key {j}: the affine map is not finite")).into());
        }
        self.reset(method, true);
        if method == BlendMethod::MatrixF32 {
            self.affines_f32.extend(maps.iter().map(|m| Affine3A {
                matrix3: m.matrix3.as_mat3().into(),
                translation: m.translation.as_vec3a(),
            }));
        } else {
            self.affines.extend_from_slice(maps);
        }
        self.fill_rows();
        self.count = maps.len();
        Ok(())
    }

    /// The prepared keys as 16 `f32`s each, in the layout of the GPU shader's entry point for
    /// the method (`deform::gpu`): logarithms (10 bivector coefficients), motors (8
    /// coefficients), dual quaternions (`q.xyzw`, `d.xyzw`), each of the last two with its
    /// log-scale at 8; affine maps (columns `x, y, z, t`); the equation (17) rows and `eo` at
    /// 12.
    pub fn pack_f32(&self, out: &mut Vec<f32>) {
        out.clear();
        let mut put = |v: &[f64], log_scale: Option<f64>| {
            let mut a = [0.0f32; 16];
            for (x, y) in a.iter_mut().zip(v) {
                *x = *y as f32;
            }
            if let Some(l) = log_scale {
                a[8] = l as f32;
            }
            out.extend_from_slice(&a);
        };
        match self.method {
            BlendMethod::MotorLog => {
                for b in &self.logs {
                    put(&b.to_array(), None);
                }
            }
            BlendMethod::MotorLinear => {
                for (m, l) in self.motors.iter().zip(&self.log_scales) {
                    put(&m.to_array(), Some(*l));
                }
            }
            BlendMethod::DualQuaternion => {
                for ((q, d), l) in self.quats.iter().zip(&self.log_scales) {
                    put(&[q.x, q.y, q.z, q.w, d.x, d.y, d.z, d.w], Some(*l));
                }
            }
            BlendMethod::Matrix => {
                for a in &self.affines {
                    let (m, t) = (a.matrix3, a.translation);
                    put(
                        &[
                            m.x_axis.x, m.x_axis.y, m.x_axis.z, m.y_axis.x, m.y_axis.y, m.y_axis.z,
                            m.z_axis.x, m.z_axis.y, m.z_axis.z, t.x, t.y, t.z,
                        ],
                        None,
                    );
                }
            }
            BlendMethod::MatrixF32 => {
                for a in &self.affines_f32 {
                    let (m, t) = (a.matrix3, a.translation);
                    let v = [
                        m.x_axis.x, m.x_axis.y, m.x_axis.z, m.y_axis.x, m.y_axis.y, m.y_axis.z,
                        m.z_axis.x, m.z_axis.y, m.z_axis.z, t.x, t.y, t.z,
                    ];
                    put(&v.map(f64::from), None);
                }
            }
            BlendMethod::Conformal | BlendMethod::ConformalProjected => {
                for c in &self.conformal {
                    let r = c.rows;
                    let mut v = [0.0; 13];
                    v[..4].copy_from_slice(&r[0]);
                    v[4..8].copy_from_slice(&r[1]);
                    v[8..12].copy_from_slice(&r[2]);
                    v[12] = c.eo;
                    put(&v, None);
                }
            }
        }
    }

    /// The rows of the batch kernels: motors as (rotor part, dual part), dual quaternions as
    /// (`q.xyzw`, `d.xyzw`), affine maps and equation (17) keys as columns `x, y, z, 1` of the
    /// 3x4 map (the `eo` coefficient in lane 3 of the last), logarithms as their 7
    /// similarity coefficients in 8 lanes.
    fn fill_rows(&mut self) {
        let z = F64x4::splat(0.0);
        let v = |a: [f64; 4]| F64x4(a);
        match self.method {
            BlendMethod::MotorLinear => {
                self.rows.extend(self.motors.iter().map(|m| {
                    let c = m.to_array();
                    [
                        v([c[0], c[1], c[2], c[3]]),
                        v([c[4], c[5], c[6], c[7]]),
                        z,
                        z,
                    ]
                }));
                self.align_rows();
            }
            BlendMethod::DualQuaternion => {
                self.rows.extend(
                    self.quats
                        .iter()
                        .map(|(q, d)| [v(q.to_array()), v(d.to_array()), z, z]),
                );
                self.align_rows();
            }
            BlendMethod::Matrix => self.rows.extend(self.affines.iter().map(|a| {
                let c = |x: DVec3| v([x.x, x.y, x.z, 0.0]);
                let m = a.matrix3;
                let t = a.translation;
                [
                    c(m.x_axis),
                    c(m.y_axis),
                    c(m.z_axis),
                    v([t.x, t.y, t.z, 1.0]),
                ]
            })),
            BlendMethod::Conformal | BlendMethod::ConformalProjected => {
                self.rows.extend(self.conformal.iter().map(|k| {
                    let r = k.rows;
                    let c = |j: usize| v([r[0][j], r[1][j], r[2][j], 0.0]);
                    [c(0), c(1), c(2), v([r[0][3], r[1][3], r[2][3], k.eo])]
                }));
            }
            // The generator's `e12, e13, e23, e1i` and `e2i, e3i, eoi`; a similarity's
            // logarithm has no `eo1, eo2, eo3` part (and `exp` ignores it).
            BlendMethod::MotorLog => self.rows.extend(self.logs.iter().map(|b| {
                [
                    v([b.e12, b.e13, b.e23, b.e1i]),
                    v([b.e2i, b.e3i, b.eoi, 0.0]),
                    z,
                    z,
                ]
            })),
            BlendMethod::MatrixF32 => {}
        }
    }

    /// For the hemisphere-aligned methods with at most [`ALIGNED_MAX_KEYS`] keys, append to
    /// the `K` rows (rotor or real quaternion part in the first) the `K x K` table whose entry
    /// `K + a K + b` is row `b` in the hemisphere of row `a` (negated when their first parts
    /// have a negative dot product, as the per-vertex blend negates the weight), so that the
    /// batch kernels add rows without testing signs.
    fn align_rows(&mut self) {
        let k = self.rows.len();
        if k > ALIGNED_MAX_KEYS {
            return;
        }
        for a in 0..k {
            let r0 = self.rows[a][0];
            for b in 0..k {
                let row = self.rows[b];
                let d = dot(row[0], r0);
                self.rows.push(if d < 0.0 { row.map(|x| -x) } else { row });
            }
        }
    }

    /// The key count `K` when the rows hold the aligned table of [`PreparedKeys::align_rows`].
    pub(super) fn aligned(&self) -> Option<usize> {
        let k = match self.method {
            BlendMethod::MotorLinear => self.motors.len(),
            BlendMethod::DualQuaternion => self.quats.len(),
            _ => return None,
        };
        (k <= ALIGNED_MAX_KEYS && self.rows.len() == k + k * k).then_some(k)
    }

    /// Whether any key scales.
    pub fn scaled(&self) -> bool {
        self.scaled
    }

    /// The blend method.
    pub fn method(&self) -> BlendMethod {
        self.method
    }

    /// How many keys were prepared (0 after a failed [`PreparedKeys::prepare`]).
    pub fn key_count(&self) -> usize {
        self.count
    }

    /// Apply the blend of the row's keys to the point `p`.
    #[inline]
    pub fn transform(&self, row: Row, p: DVec3) -> DVec3 {
        match self.method {
            BlendMethod::MotorLog => {
                // exp of the blended generator, applied in its quaternion form (the motor's
                // action `M X ~M` without building M).
                self.log_blend(row).exp_similarity().transform_point(p)
            }
            BlendMethod::MotorLinear => {
                // Only the rotor norm is divided out: the point action is the same as that
                // of the exactly renormalised motor (see `Motor::normalize_for_points`).
                let m = self.linear_sum(row);
                let m = if m.norm_squared() > f64::MIN_POSITIVE {
                    m.normalize_for_points()
                } else {
                    Motor::IDENTITY
                };
                m.transform_point(self.scale_of(row) * p)
            }
            BlendMethod::DualQuaternion => {
                let (q, t) = self.dual_quaternion_blend(row);
                q * (self.scale_of(row) * p) + t
            }
            BlendMethod::Matrix => self.affine_blend(row).transform_point3(p),
            BlendMethod::MatrixF32 => self.transform_f32(row, p.as_vec3a()).as_dvec3(),
            BlendMethod::Conformal => self.conformal_blend(row).transform_point(p),
            BlendMethod::ConformalProjected => row.fold(DVec3::ZERO, |acc, k, w| {
                acc + w * self.conformal[k].transform_point(p)
            }),
        }
    }

    /// [`BlendMethod::MatrixF32`] in single precision: `sum w A` applied to `p`.
    #[inline]
    pub fn transform_f32(&self, row: Row, p: Vec3A) -> Vec3A {
        let a = row.fold(Affine3A::ZERO, |acc, k, w| {
            let a = &self.affines_f32[k];
            let w = w as f32;
            Affine3A {
                matrix3: acc.matrix3 + a.matrix3 * w,
                translation: acc.translation + a.translation * w,
            }
        });
        a.transform_point3a(p)
    }

    /// Equation (17), adding first: `sum w (M up(x) ~M)` is linear in the point matrices,
    /// so they are blended and applied once.
    #[inline]
    fn conformal_blend(&self, row: Row) -> ConformalKey {
        row.fold(ConformalKey::default(), |acc, k, w| {
            self.conformal[k].mul_add(w, acc)
        })
    }

    /// The blended transform of the row's keys as an affine map (for the bind, which applies
    /// its inverse).
    pub fn affine(&self, row: Row) -> DAffine3 {
        let (s, q, t) = match self.method {
            BlendMethod::MotorLog => {
                let sim = self.log_blend(row).exp_similarity();
                (sim.scale, sim.rotation, sim.translation)
            }
            BlendMethod::MotorLinear => {
                let (q, t) = self.linear_blend(row).to_rotation_translation();
                (self.scale_of(row), q.normalize(), t)
            }
            BlendMethod::DualQuaternion => {
                let (q, t) = self.dual_quaternion_blend(row);
                (self.scale_of(row), q, t)
            }
            BlendMethod::Matrix => return self.affine_blend(row),
            BlendMethod::MatrixF32 => {
                let a = row.fold(DAffine3::ZERO, |acc, k, w| {
                    let a = &self.affines_f32[k];
                    DAffine3 {
                        matrix3: acc.matrix3 + a.matrix3.as_dmat3() * w,
                        translation: acc.translation + a.translation.as_dvec3() * w,
                    }
                });
                return a;
            }
            BlendMethod::Conformal => return self.conformal_blend(row).affine(),
            BlendMethod::ConformalProjected => {
                return row.fold(DAffine3::ZERO, |acc, k, w| {
                    let a = self.conformal[k].affine();
                    DAffine3 {
                        matrix3: acc.matrix3 + a.matrix3 * w,
                        translation: acc.translation + a.translation * w,
                    }
                })
            }
        };
        DAffine3::from_scale_rotation_translation(DVec3::splat(s), q, t)
    }

    /// `sum w log R` over the row.
    #[inline]
    fn log_blend(&self, row: Row) -> Bivector {
        match row.keys {
            None => Bivector::weighted_sum(self.logs[row.first..].iter().copied(), row.weights),
            Some(k) => {
                Bivector::weighted_sum(k.iter().map(|&k| self.logs[k as usize]), row.weights)
            }
        }
    }

    /// `normalise(sum w R)` over the row, in the hemisphere of its first key (the loop of
    /// [`Motor::blend_linear_pairs`], written over the row so that it compiles to straight
    /// multiply-adds; a sum with a vanishing rotor part gives the identity, as there).
    #[inline]
    fn linear_blend(&self, row: Row) -> Motor {
        let acc = self.linear_sum(row);
        if acc.norm_squared() > f64::MIN_POSITIVE {
            acc.normalize_rigid()
        } else {
            Motor::IDENTITY
        }
    }

    /// `sum w M` over the row, each key in the hemisphere of the row's first key.
    #[inline]
    fn linear_sum(&self, row: Row) -> Motor {
        let m0 = self.motors[row.key(0)];
        row.fold(Motor::default(), |acc, k, w| {
            let m = self.motors[k];
            let d = m.s * m0.s + m.e12 * m0.e12 + m.e13 * m0.e13 + m.e23 * m0.e23;
            acc + m * if d < 0.0 { -w } else { w }
        })
    }

    /// `exp(sum w ln s)`: the geometric blend of the key scales.
    #[inline]
    fn scale_of(&self, row: Row) -> f64 {
        if !self.scaled {
            return 1.0;
        }
        row.fold(0.0, |a, k, w| a + w * self.log_scales[k]).exp()
    }

    /// Kavan's dual-quaternion linear blend: `(rotation, translation)`.
    #[inline]
    fn dual_quaternion_blend(&self, row: Row) -> (DQuat, DVec3) {
        let q0 = self.quats[row.key(0)].0;
        let (r, d) = row.fold((r0(), r0()), |(r, d), k, wk| {
            let (q, dq) = self.quats[k];
            let wk = if q.dot(q0) < 0.0 { -wk } else { wk };
            (r + q * wk, d + dq * wk)
        });
        let n = r.length();
        let (r, d) = (r * (1.0 / n), d * (1.0 / n));
        let t = d * r.conjugate();
        (r, 2.0 * DVec3::new(t.x, t.y, t.z))
    }

    /// `sum w A`.
    #[inline]
    fn affine_blend(&self, row: Row) -> DAffine3 {
        let (m, t) = row.fold((DMat3::ZERO, DVec3::ZERO), |(m, t), k, wk| {
            let a = &self.affines[k];
            (m + a.matrix3 * wk, t + a.translation * wk)
        });
        DAffine3::from_mat3_translation(m, t)
    }
}

/// The zero quaternion.
#[inline]
fn r0() -> DQuat {
    DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)
}
