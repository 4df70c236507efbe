//! Joint edits baked into a rig, so that the edit is part of the rig at every time: its rest
//! transform and every keyframe of its animation channels.
//!
//! An edit `E = T_e R_e D_e` (a similarity in the joint's own frame) turns the joint's local
//! transform `L = T R S` into `L E`. When `S` is a uniform scale `s` (or `R_e` is the
//! identity), `L E = T(T + R S t_e) (R R_e) (S d)`: the rotation keys are multiplied by `R_e` on
//! the right and the scale keys by `d` (tangents of `CUBICSPLINE` channels too), which glTF's
//! interpolations carry exactly to every time in between (`slerp(q_a R_e, q_b R_e) =
//! slerp(q_a, q_b) R_e`, and the Hermite spline is linear in its keys). The translation gains
//! `R S t_e`, which is exact only while `R` and `S` are not animated; an edit that translates a
//! joint whose rotation or scale is keyed is refused, as is a rotation of a joint with a
//! non-uniform scale (`L E` would shear; uniform means equal to single precision).

use super::animation::{Channel, Interpolation, Property};
use super::edit::JointEdit;
use super::rig::Rig;
use super::{SkinError, Trs};
use glam::{DQuat, DVec3, DVec4};

/// Relative tolerance for a zero translation or rotation of an edit.
const TOLERANCE: f64 = 1e-12;

/// Relative spread within which a keyed scale counts as uniform: single precision, the
/// precision of glTF files (CesiumMan's scale keys are uniform to about 2e-7).
const UNIFORM_SCALE: f64 = 1e-6;

/// `rig` with `edits` (applied in order, as [`Rig::pose`] applies them) baked into the rest
/// transforms and the animation channels of the edited joints. Posing the result without
/// edits gives, at every time and with every keyframe blend of glTF, what posing `rig` with
/// `edits` gives.
///
/// # Errors
/// [`SkinError::NoJoint`] for an edit of a joint past the skin; [`SkinError::BadTransform`]
/// naming the joint and animation when an edit cannot be baked exactly (see the module docs)
/// or makes the rest transform something other than translation, rotation and scale.
pub fn bake_edits(rig: &Rig, edits: &[JointEdit]) -> Result<Rig, SkinError> {
    let mut out = rig.clone();
    for e in edits {
        let node = *rig
            .joints
            .get(e.joint)
            .ok_or_else(|| SkinError::NoJoint(e.joint.to_string()))?;
        bake_one(&mut out, node, e)?;
    }
    Ok(out)
}

fn bake_one(rig: &mut Rig, node: usize, edit: &JointEdit) -> Result<(), SkinError> {
    let name = &rig.nodes[node].name;
    let bad = |message: String| SkinError::BadTransform {
        what: format!("joint {} ({name}) edit", edit.joint),
        message,
    };
    let (d, re, te) = edit.motor.to_scale_rotation_translation();
    let rest = rig.nodes[node].rest;
    let rotates = DVec3::new(re.x, re.y, re.z).length() > TOLERANCE;
    let translates = te.length() > TOLERANCE * (1.0 + rest.translation.length());
    let uniform = |s: DVec3| {
        (s.max_element() - s.min_element()).abs() <= UNIFORM_SCALE * s.abs().max_element()
    };
    // Which properties of the joint any animation keys.
    let keyed = |p: Property| {
        rig.animations
            .iter()
            .any(|a| a.channels.iter().any(|c| c.node == node && c.property == p))
    };
    if translates && (keyed(Property::Rotation) || keyed(Property::Scale)) {
        return Err(bad(
            "the edit translates a joint whose rotation or scale is animated: the moved pivot \
             would follow the animation, which glTF channels cannot hold exactly; edit by a \
             rotation or a dilation about the joint instead"
                .into(),
        ));
    }
    if rotates {
        let scales = std::iter::once(rest.scale).chain(
            rig.animations
                .iter()
                .flat_map(|a| a.channels.iter())
                .filter(|c| c.node == node && c.property == Property::Scale)
                .flat_map(|c| c.values.iter().map(|v| v.truncate())),
        );
        if let Some(s) = scales.into_iter().find(|&s| !uniform(s)) {
            return Err(bad(format!(
                "the joint has the non-uniform scale {s}: rotating it by the edit would shear"
            )));
        }
    }
    // The rest transform, as `Rig::pose` composes it.
    let m = rest.matrix() * edit.motor.to_mat4();
    rig.nodes[node].rest = Trs::from_matrix(&m, &format!("joint {} after its edit", edit.joint))?;
    let shift = rest.rotation * (rest.scale * te);
    for a in &mut rig.animations {
        for c in a.channels.iter_mut().filter(|c| c.node == node) {
            bake_channel(c, re, d, shift);
        }
    }
    Ok(())
}

/// One channel of the edited joint: rotations times `re` on the right, scales times `d`,
/// translations plus `shift` (values only; tangents are derivatives).
fn bake_channel(c: &mut Channel, re: DQuat, d: f64, shift: DVec3) {
    let cubic = c.interpolation == Interpolation::CubicSpline;
    for (k, v) in c.values.iter_mut().enumerate() {
        let is_value = !cubic || k % 3 == 1;
        *v = match c.property {
            Property::Rotation => {
                let q = DQuat::from_xyzw(v.x, v.y, v.z, v.w) * re;
                DVec4::new(q.x, q.y, q.z, q.w)
            }
            Property::Scale => *v * d,
            Property::Translation if is_value => *v + shift.extend(0.0),
            Property::Translation => *v,
        };
    }
}
