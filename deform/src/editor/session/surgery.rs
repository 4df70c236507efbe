//! Surgery from the page: a scalpel stroke (rays from the eye) tears the skin along the surface
//! it meets, a click drills where its ray meets it; both sized by the mesh, in the posed frame.

use super::{v3, Out, Session};
use crate::editor::error::{bail, refused, Result};
use crate::editor::protocol::Request;
use crate::surgery::{Drill, Scalpel};

impl Session {
    /// Tear along the surface under a stroke (rays from the eye), or drill where a ray meets it.
    pub(super) fn tool(&mut self, request: Request) -> Result<Vec<Out>> {
        if self.rig.is_none() {
            bail!("surgery needs a rig: open the arm or a .glb");
        }
        // The blade and the drill are sized by the mesh.
        let size = self
            .mesh
            .bounding_box()
            .map_or(1.0, |b| (b.max - b.min).length());
        match request {
            Request::Tear { rays, open } => {
                let mut blades = Vec::new();
                for [o, d] in rays {
                    let d = v3(d).normalize_or_zero();
                    if let Some(h) = self.hit(v3(o), d) {
                        blades.push(Scalpel {
                            a: h.point - 0.02 * size * d,
                            b: h.point + 0.08 * size * d,
                        });
                    }
                }
                if blades.len() < 2 {
                    bail!(
                        "tear: the stroke met the surface {} time(s); draw across it",
                        blades.len()
                    );
                }
                let rig = self.rig.as_mut().expect("checked");
                rig.tear(&blades, open, &self.posed)?;
            }
            Request::Drill {
                origin,
                direction,
                radius,
                depth,
            } => {
                if !(radius > 0.0 && radius.is_finite() && depth > 0.0 && depth.is_finite()) {
                    bail!("drill: radius {radius} and depth {depth} must be positive fractions");
                }
                let d = v3(direction).normalize_or_zero();
                let h = self
                    .hit(v3(origin), d)
                    .ok_or_else(|| refused!("drill: aim at the surface"))?;
                let drill = Drill {
                    tip: h.point - 0.25 * depth * size * d,
                    end: h.point + depth * size * d,
                    radius: radius * size,
                };
                let rig = self.rig.as_mut().expect("checked");
                rig.drill(&drill, &self.posed)?;
            }
            _ => unreachable!("tool() takes a tear or a drill"),
        }
        self.load_rig_mesh()
    }
}
