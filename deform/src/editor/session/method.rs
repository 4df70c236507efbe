//! Choosing the method of a mesh scene: the method, its blend and its options, all checked
//! (by the library's [`MethodSettings`]) before any is taken; then a rebind, or only a
//! re-blend when the weights stay.

use super::{Out, Session};
use crate::blend::BlendMethod;
use crate::editor::error::{bail, Result};
use crate::methods::named::Named;
use crate::methods::{Method, MethodSettings};
use serde_json::Value;
use std::collections::BTreeMap;

/// An option's value as a request gives it, as the program's flag takes it: a name, a
/// number, `[l, m, n]` as `LxMxN`, a boolean.
fn option_text(name: &str, value: &Value) -> Result<String> {
    let dims = |v: &Vec<Value>| -> Option<String> {
        let n: Option<Vec<String>> = v
            .iter()
            .map(|x| x.as_u64().map(|n| n.to_string()))
            .collect();
        n.map(|n| n.join("x"))
    };
    Ok(match value {
        Value::String(s) => s.clone(),
        Value::Number(n) => n.to_string(),
        Value::Bool(b) => b.to_string(),
        Value::Array(v) => match dims(v) {
            Some(text) => text,
            None => bail!("{name}: [{}] is not whole numbers", v.len()),
        },
        _ => bail!("{name}: {value} is not a name, number or [l, m, n]"),
    })
}

impl Session {
    /// A new method, blend (or `positional` for lattices and cages) and `options`: rebinds
    /// when the weights change, else only re-blends. Nothing changes when any of them is
    /// refused.
    pub(super) fn set_method(
        &mut self,
        method: &str,
        blend: &str,
        options: &BTreeMap<String, Value>,
    ) -> Result<Vec<Out>> {
        let mut next: MethodSettings = self.settings.clone();
        next.set_method(Method::from_name(method)?);
        if next.method.reads("cage") && self.cage.is_none() {
            bail!("this scene has no cage (the demo's \"cage\" scene has one)");
        }
        if blend == "positional" {
            next.set_positional(true)?;
        } else {
            next.positional = false;
            next.blend = BlendMethod::from_name(blend)?;
        }
        let texts: Vec<(&str, String)> = options
            .iter()
            .map(|(name, v)| Ok((name.as_str(), option_text(name, v)?)))
            .collect::<Result<_>>()?;
        let pairs: Vec<(&str, &str)> = texts.iter().map(|(n, t)| (*n, t.as_str())).collect();
        next.set_all(&pairs)?;
        let rebind = self.settings.rebinds_for(&next);
        let reblend = next.blend != self.settings.blend;
        let blend = next.blend;
        self.settings = next;
        if !rebind && reblend {
            return self.reblend(blend);
        }
        self.bind()
    }
}
