//! The nearest similarity (rotation, uniform scale, translation) to an affine map, by polar
//! decomposition, and how far the map is from it.
//!
//! glTF skinning is a weighted sum of 4x4 matrices `global * inverse_bind`, any affine map.
//! Motors, dual quaternions and equation (17) carry similarities only. Exporters that work in
//! single precision leave maps that are similarities up to rounding (singular values such as
//! 1.0000194, 1.0000005, 1); scenes may also hold real non-uniform scale (a shield scaled 1.24,
//! 1.0008, 1.24) or mirrored joints. [`nearest_similarity`] gives the similarity `s R` nearest to
//! the linear part `A` in the spectral norm (`A = U S V^T`, `R = U D V^T` with
//! `D = diag(1, 1, det(U V^T))`, `s` the midpoint of the largest and smallest of `D S`) and the
//! map's relative deviation from it, `||A - s R||_2 / s`, which is then
//! `(max - min) / (max + min)` of the singular values: within [`SIMILARITY_NOISE`] the map is a
//! similarity up to single-precision rounding.

use glam::{DAffine3, DMat3, DQuat, DVec3};
use nalgebra::Matrix3;

/// Relative deviation from a similarity up to which a map counts as one rounded to single
/// precision. glTF files store `f32` and exporters compose their matrices in `f32`: rounding
/// the stored values alone deviates by about 1e-7; the worst Blender 1.8-era inverse bind
/// matrix of issue 45 (singular values 1.0000194, 1.0000005, 1) by 0.97e-5.
pub const SIMILARITY_NOISE: f64 = 1e-5;

/// The similarity nearest to an affine map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NearestSimilarity {
    /// The uniform scale `s > 0`.
    pub scale: f64,
    /// The rotation `R` (proper: a mirroring map's nearest similarity is a rotation, far away).
    pub rotation: DQuat,
    /// The translation (the map's own).
    pub translation: DVec3,
    /// `||A - s R||_2 / s`: 0 for a similarity, about 1e-7 for one stored in `f32`, 2 or more
    /// for a mirror.
    pub deviation: f64,
}

impl NearestSimilarity {
    /// The similarity as an affine map.
    pub fn affine(&self) -> DAffine3 {
        DAffine3::from_scale_rotation_translation(
            DVec3::splat(self.scale),
            self.rotation,
            self.translation,
        )
    }
}

/// The similarity nearest to `map` (see the module docs); `None` for a map that is not finite
/// or whose linear part is singular.
pub fn nearest_similarity(map: &DAffine3) -> Option<NearestSimilarity> {
    if !map.is_finite() {
        return None;
    }
    let a = map.matrix3;
    // Scaled by the largest entry first, so that scales near the ends of the f64 range are
    // measured, not overflowed or flushed.
    let big = a.to_cols_array().iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if big == 0.0 || !big.is_finite() {
        return None;
    }
    let n = Matrix3::from_column_slice(&(a * (1.0 / big)).to_cols_array());
    let svd = n.svd(true, true);
    let (u, v_t) = (svd.u?, svd.v_t?);
    let sigma = svd.singular_values;
    let det = (u * v_t).determinant().signum();
    let d = [1.0, 1.0, det];
    // nalgebra sorts the singular values in decreasing order: the flip goes to the smallest.
    let order = sorted_desc(&[sigma[0], sigma[1], sigma[2]]);
    let mut signs = [1.0; 3];
    signs[order[2]] = d[2];
    let signed = [0, 1, 2].map(|i| signs[i] * sigma[i]);
    let (hi, lo) = (signed[order[0]], signed[order[2]]);
    // A mirror's smallest signed value is negative: then the mean of the magnitudes (the
    // deviation is 1 or more either way).
    let s = if lo > 0.0 {
        0.5 * (hi + lo)
    } else {
        (sigma[0] + sigma[1] + sigma[2]) / 3.0
    };
    if s.partial_cmp(&(f64::MIN_POSITIVE * 4.0)) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let deviation = (0..3)
        .map(|i| (signs[i] * sigma[i] - s).abs())
        .fold(0.0f64, f64::max)
        / s;
    let flip = Matrix3::from_diagonal(&nalgebra::Vector3::new(signs[0], signs[1], signs[2]));
    let r = u * flip * v_t;
    let r = DMat3::from_cols_slice(r.as_slice());
    let rotation = DQuat::from_mat3(&r).normalize();
    let scale = s * big;
    if !(scale.is_finite() && scale > 0.0 && rotation.is_finite()) {
        return None;
    }
    Some(NearestSimilarity {
        scale,
        rotation,
        translation: map.translation,
        deviation,
    })
}

/// The indices of `x` in decreasing order of their values.
fn sorted_desc(x: &[f64; 3]) -> [usize; 3] {
    let mut i = [0, 1, 2];
    i.sort_by(|&a, &b| x[b].total_cmp(&x[a]));
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    fn similarity(s: f64) -> DAffine3 {
        DAffine3::from_scale_rotation_translation(
            DVec3::splat(s),
            DQuat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0),
            DVec3::new(1.0, -2.0, 3.0),
        )
    }

    #[test]
    fn a_similarity_is_its_own_nearest() {
        for s in [1.0, 0.01, 100.0, 1e-200, 1e200] {
            let m = similarity(s);
            let n = nearest_similarity(&m).unwrap();
            assert!(n.deviation < 1e-14, "{s}: {}", n.deviation);
            assert!((n.scale - s).abs() <= 1e-14 * s, "{s}: {}", n.scale);
            let back = n.affine();
            let err = (back.matrix3 - m.matrix3).abs().to_cols_array();
            assert!(err.iter().all(|e| *e <= 1e-14 * s), "{s}: {err:?}");
        }
    }

    #[test]
    fn rounding_is_noise_and_real_scale_is_not() {
        // Issue 45's inverse bind matrix: singular values 1.0000194, 1.0000005, 1.
        let noisy =
            DAffine3::from_mat3(DMat3::from_diagonal(DVec3::new(1.0000194, 1.0000005, 1.0)))
                * similarity(1.0);
        let n = nearest_similarity(&noisy).unwrap();
        assert!(n.deviation < SIMILARITY_NOISE, "{}", n.deviation);
        assert!(n.deviation > 9e-6, "{}", n.deviation);
        // The shield: 1.24, 1.0008, 1.24.
        let shield = DAffine3::from_scale_rotation_translation(
            DVec3::new(1.24, 1.0008, 1.24),
            DQuat::from_rotation_y(0.4),
            DVec3::X,
        );
        let n = nearest_similarity(&shield).unwrap();
        let s = (1.24 + 1.0008) / 2.0;
        assert!((n.scale - s).abs() < 1e-12, "{}", n.scale);
        assert!(
            (n.deviation - (1.24 - s) / s).abs() < 1e-12,
            "{}",
            n.deviation
        );
        assert!(n.rotation.angle_between(DQuat::from_rotation_y(0.4)) < 1e-12);
    }

    #[test]
    fn a_mirror_is_far_and_singular_maps_have_none() {
        let mirror = DAffine3::from_scale(DVec3::new(-1.0, 1.0, 1.0));
        let n = nearest_similarity(&mirror).unwrap();
        assert!(n.deviation >= 1.0, "{}", n.deviation);
        let flat = DAffine3::from_scale(DVec3::new(1.0, 1.0, 0.0));
        assert!(nearest_similarity(&flat).is_none_or(|n| n.deviation >= 1.0));
        assert!(nearest_similarity(&DAffine3::from_scale(DVec3::ZERO)).is_none());
        let mut nan = similarity(1.0);
        nan.translation.x = f64::NAN;
        assert!(nearest_similarity(&nan).is_none());
    }
}
