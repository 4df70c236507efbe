//! Choosing the method of a mesh scene: the method, its blend, ARAP's options and the lattice
//! and cage options, all checked (by the library's [`MethodSettings`]) before any is taken;
//! then a rebind, or only a re-blend when the weights stay.

use super::{Out, Session};
use crate::blend::BlendMethod;
use crate::editor::error::{bail, Result};
use crate::editor::protocol::ControlRequest;
use crate::methods::named::Named;
use crate::methods::{Method, MethodSettings};

/// ARAP's energy and local step, and the lattice and cage options, as a request gives them.
pub(in crate::editor) type MethodOptions<'a> =
    (Option<&'a str>, Option<&'a str>, Option<&'a ControlRequest>);

impl Session {
    /// A new method, blend (or `positional` for lattices and cages), ARAP iterations per frame
    /// and `options`: rebinds when the weights change, else only re-blends. Nothing changes
    /// when any of them is refused.
    pub(super) fn set_method(
        &mut self,
        method: &str,
        blend: &str,
        iterations: Option<usize>,
        (energy, local_step, controls): MethodOptions,
    ) -> Result<Vec<Out>> {
        let mut next: MethodSettings = self.settings;
        next.set_method(Method::from_name(method)?);
        if next.method == Method::Cage && self.cage.is_none() {
            bail!("this scene has no cage (the demo's \"cage\" scene has one)");
        }
        if blend == "positional" {
            next.set_positional(true)?;
        } else {
            next.positional = false;
            next.blend = BlendMethod::from_name(blend)?;
        }
        if let Some(k) = iterations {
            next.set_iterations(k)?;
        }
        for (name, value) in [("energy", energy), ("local-step", local_step)] {
            if let Some(v) = value {
                next.set(name, v)?;
            }
        }
        if let Some(r) = controls {
            let basis = match &r.basis {
                Some(b) => Named::from_name(b)?,
                None => next.basis,
            };
            next.set_lattice(r.lattice.unwrap_or(next.lattice), basis)?;
            if let Some(c) = &r.coordinates {
                next.set("coordinates", c)?;
            }
            if let Some(g) = r.grid {
                next.set_grid(g)?;
            }
        }
        let rebind = self.settings.rebinds_for(&next);
        let reblend = next.blend != self.settings.blend;
        self.settings = next;
        if !rebind && reblend {
            return self.reblend(next.blend);
        }
        self.bind()
    }
}
