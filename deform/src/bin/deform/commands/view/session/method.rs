//! Choosing the method of a mesh scene: the method, its blend, ARAP's options and the lattice
//! and cage options, all checked before any is taken; then a rebind, or only a re-blend when
//! the weights stay.

use super::{Out, Session};
use crate::commands::view::controls::ControlRequest;
use crate::commands::view::scenes::Method;
use anyhow::{anyhow, bail, Result};
use deform::deformers::arap::{ArapEnergy, LocalStep};
use deform::BlendMethod;

/// ARAP's energy and local step, and the lattice and cage options, as a request gives them.
pub(in crate::commands::view) type MethodOptions<'a> =
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
        let m = Method::parse(method).ok_or_else(|| anyhow!("no method {method:?}"))?;
        if m == Method::Cage && self.cage.is_none() {
            bail!("this scene has no cage (the demo's \"cage\" scene has one)");
        }
        let positional = blend == "positional";
        if positional && !m.controls() {
            bail!("positional blending is for lattices and cages");
        }
        let b: BlendMethod = if positional {
            self.blend
        } else {
            blend.parse()?
        };
        let k = iterations.unwrap_or(self.iterations);
        if !(1..=50).contains(&k) {
            bail!("iterations per frame: {k} is not in 1..=50");
        }
        let mut arap = self.arap;
        if let Some(e) = energy {
            arap.energy = match e {
                "spokes" => ArapEnergy::Spokes,
                "spokes-and-rims" => ArapEnergy::SpokesAndRims,
                _ => bail!("no ARAP energy {e:?} (spokes, spokes-and-rims)"),
            };
        }
        if let Some(l) = local_step {
            arap.local_step = match l {
                "rotor" => LocalStep::Rotor,
                "svd" => LocalStep::Svd,
                _ => bail!("no ARAP local step {l:?} (rotor, svd)"),
            };
        }
        let control = match controls {
            Some(r) => self.control.with(r)?,
            None => self.control,
        };
        let rebind = m != self.method
            || positional != self.positional
            || (k != self.iterations || arap != self.arap) && m == Method::Arap
            || control != self.control && m.controls();
        (self.iterations, self.arap, self.control) = (k, arap, control);
        if !rebind && b != self.blend {
            return self.reblend(b);
        }
        self.method = m;
        self.blend = b;
        self.positional = positional;
        self.bind()
    }
}
