//! The one mapping between glam quaternions and CGA coefficients.
//!
//! A rotor `R = cos(a/2) - sin(a/2) n I3` is the unit quaternion `w + x i + y j + z k` with
//! `(s, e12, e13, e23) = (w, -z, y, -x)`. The same map takes a half rotation vector `u` (a pure
//! quaternion) to the Euclidean part `e12, e13, e23` of a generator. The dual part
//! `q_d = 0.5 t q_r` of a motor is stored as `(e1i, e2i, e3i, e123i) = -(x, y, z, w)`.
//! Every conversion in this crate goes through these four functions.

use super::*;

/// `(s, e12, e13, e23)` of the quaternion `q`.
#[inline]
#[must_use]
pub(crate) fn rotor_coeffs(q: Quat) -> [S; 4] {
    [q.w, -q.z, q.y, -q.x]
}

/// The quaternion of the coefficients `(s, e12, e13, e23)`.
#[inline]
#[must_use]
pub(crate) fn rotor_quat([s, e12, e13, e23]: [S; 4]) -> Quat {
    Quat::from_xyzw(-e23, e13, -e12, s)
}

/// `(e1i, e2i, e3i, e123i)` of the dual quaternion part `d`.
#[inline]
#[must_use]
pub(crate) fn dual_coeffs(d: Quat) -> [S; 4] {
    [-d.x, -d.y, -d.z, -d.w]
}

/// The dual quaternion part of the coefficients `(e1i, e2i, e3i, e123i)`.
#[inline]
#[must_use]
pub(crate) fn dual_quat([e1i, e2i, e3i, e123i]: [S; 4]) -> Quat {
    Quat::from_xyzw(-e1i, -e2i, -e3i, -e123i)
}

/// The `(e12, e13, e23)` coefficients of the half rotation vector `u` (a pure quaternion).
#[inline]
#[must_use]
pub(crate) fn rotation_plane(u: V3) -> [S; 3] {
    let [_, e12, e13, e23] = rotor_coeffs(Quat::from_xyzw(u.x, u.y, u.z, 0.0));
    [e12, e13, e23]
}

/// The half rotation vector `u` of the coefficients `(e12, e13, e23)`.
#[inline]
#[must_use]
pub(crate) fn rotation_vector([e12, e13, e23]: [S; 3]) -> V3 {
    let q = rotor_quat([0.0, e12, e13, e23]);
    V3::new(q.x, q.y, q.z)
}
