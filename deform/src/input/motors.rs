//! Key motors in JSON, shared by every subcommand of the `deform` program.
//!
//! A motor is an object with optional `rotate` (`axis` `[x, y, z]`, `degrees`, `center`
//! `[x, y, z]`, default the origin), `translate` `[x, y, z]` and `scale` (about the same
//! `center`), applied as scale, then rotate, then translate: `x -> c + s R (x - c) + t`.
//! `{}` is the identity. A key list is a JSON array of motors; per-group (or per-item) motors
//! are an object from the group number, as a string, to a motor, where `"*"` stands for every
//! group or item not listed.
//!
//! ```
//! use deform::input::parse_key_list;
//! let keys = parse_key_list(r#"[{}, {"rotate": {"axis": [0, 0, 1], "degrees": 90}, "translate": [1, 0, 0]}]"#, "keys.json").unwrap();
//! let p = keys[1].transform_point(glam::DVec3::X);
//! assert!((p - glam::DVec3::new(1.0, 1.0, 0.0)).length() < 1e-15);
//! ```

use super::InputError;
use cga::ScaledMotor;
use glam::{DQuat, DVec3};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A rotation as written: axis, angle in degrees, centre.
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RotateSpec {
    /// The axis direction (any non-zero length).
    pub axis: [f64; 3],
    /// The angle in degrees (right-hand rule).
    pub degrees: f64,
    /// A point on the axis (default the origin); also the centre of `scale`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub center: Option<[f64; 3]>,
}

/// A motor as written in JSON (and written back by [`serde_json::to_string`]).
#[derive(Clone, Debug, Default, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MotorSpec {
    /// Rotation about an axis through a centre.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotate: Option<RotateSpec>,
    /// Translation, applied last.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub translate: Option<[f64; 3]>,
    /// Uniform scale about the rotation's centre (or the origin), applied first.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale: Option<f64>,
    /// The centre of `scale` when there is no rotation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub center: Option<[f64; 3]>,
}

impl MotorSpec {
    /// The scaled motor `x -> c + s R (x - c) + t`.
    ///
    /// # Errors
    /// A message for a non-finite number, a zero axis, a scale that is not positive or one a
    /// scaled motor cannot hold.
    pub fn to_motor(&self) -> Result<ScaledMotor, String> {
        let v = |a: [f64; 3]| DVec3::from_array(a);
        let center = self
            .rotate
            .as_ref()
            .and_then(|r| r.center)
            .or(self.center)
            .map(v)
            .unwrap_or(DVec3::ZERO);
        let q = match &self.rotate {
            None => DQuat::IDENTITY,
            Some(r) => {
                if !r.degrees.is_finite() {
                    return Err("rotate.degrees is not finite".into());
                }
                cga::Rotor::try_from_axis_angle(v(r.axis), r.degrees.to_radians())
                    .map_err(|e| format!("rotate: {e}"))?
                    .to_quat()
            }
        };
        let s = self.scale.unwrap_or(1.0);
        let t = self.translate.map(v).unwrap_or(DVec3::ZERO);
        if !center.is_finite() || !t.is_finite() {
            return Err("centre or translation is not finite".into());
        }
        ScaledMotor::try_from_scale_rotation_translation(s, q, center - s * (q * center) + t)
            .map_err(|e| e.to_string())
    }
}

fn parse_value(text: &str, name: &str) -> Result<serde_json::Value, InputError> {
    super::json::parse_json(text, name)
}

fn motor_of(
    value: &serde_json::Value,
    name: &str,
    item: String,
) -> Result<ScaledMotor, InputError> {
    let spec: MotorSpec = serde_json::from_value(value.clone())
        .map_err(|e| InputError::new(name, item.clone(), e.to_string()))?;
    spec.to_motor().map_err(|m| InputError::new(name, item, m))
}

/// One motor: a JSON object (as in the module doc).
///
/// # Errors
/// [`InputError`] for JSON of the wrong shape or a motor that cannot be built.
pub fn parse_motor(text: &str, name: &str) -> Result<ScaledMotor, InputError> {
    let value = parse_value(text, name)?;
    motor_of(&value, name, "motor".to_string())
}

/// A key list: a JSON array of motors.
///
/// # Errors
/// [`InputError`] naming the key (`key 2`) or `JSON` for a file of the wrong shape.
pub fn parse_key_list(text: &str, name: &str) -> Result<Vec<ScaledMotor>, InputError> {
    let value = parse_value(text, name)?;
    let items = value
        .as_array()
        .ok_or_else(|| InputError::new(name, "JSON", "expected an array of motors"))?;
    items
        .iter()
        .enumerate()
        .map(|(k, m)| motor_of(m, name, format!("key {k}")))
        .collect()
}

/// Per-group motors: a JSON object from group numbers (`"0"`, `"1"`, ...) to motors, with
/// `"*"` for every group not listed (the identity when there is no `"*"`). Returns one motor
/// per group `0 .. groups`.
///
/// # Errors
/// [`InputError`] for a key that is not a group number below `groups` or `"*"`, a motor of
/// the wrong shape, or a file that is not an object.
pub fn parse_group_motors(
    text: &str,
    name: &str,
    groups: usize,
) -> Result<Vec<ScaledMotor>, InputError> {
    let value = parse_value(text, name)?;
    let object: BTreeMap<String, serde_json::Value> =
        serde_json::from_value(value).map_err(|_| {
            InputError::new(
                name,
                "JSON",
                "expected an object from group numbers to motors",
            )
        })?;
    let default = match object.get("*") {
        Some(m) => motor_of(m, name, "group \"*\"".into())?,
        None => ScaledMotor::IDENTITY,
    };
    let mut out = Vec::new();
    out.try_reserve_exact(groups).map_err(|_| {
        InputError::new(
            name,
            "JSON",
            format!("{groups} groups: more motors than memory holds"),
        )
    })?;
    out.resize(groups, default);
    for (key, m) in &object {
        if key == "*" {
            continue;
        }
        let item = format!("group {key:?}");
        let g: usize = key
            .parse()
            .map_err(|_| InputError::new(name, item.clone(), "not a group number or \"*\""))?;
        if g >= groups {
            return Err(InputError::new(
                name,
                item,
                format!("no such group (there are {groups})"),
            ));
        }
        out[g] = motor_of(m, name, item)?;
    }
    Ok(out)
}
