//! Selecting handle groups: paint around where a ray meets the posed surface, or lasso the
//! vertices seen inside a screen polygon.

use super::{Out, Session, NONE};
use crate::editor::error::{bail, Result};
use crate::editor::protocol::Frame;
use crate::input::MotorSpec;
use crate::mesh::Mesh;
use glam::{DMat4, DVec3};

/// Whether `p` is inside `polygon` (even-odd rule).
fn contains(polygon: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut inside = false;
    let mut j = polygon.len() - 1;
    for i in 0..polygon.len() {
        let (a, b) = (polygon[i], polygon[j]);
        if (a[1] > p[1]) != (b[1] > p[1])
            && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]
        {
            inside = !inside;
        }
        j = i;
    }
    inside
}

/// The most selection changes kept for undo.
const HISTORY: usize = 100;

/// The vertex groups of a selection.
type Selection = Vec<Vec<u32>>;

/// Undo and redo of selection changes (paint strokes, lassos, clearing, loading), as the
/// groups before each. The motors stay with the group numbers, as the page's gizmos do.
#[derive(Debug, Default)]
pub(in crate::editor) struct SelectionHistory {
    undo: Vec<Selection>,
    redo: Vec<Selection>,
    /// Kept when a change begins, pushed once it changes something.
    pending: Option<Selection>,
}

impl SelectionHistory {
    pub(in crate::editor) fn undo_count(&self) -> usize {
        self.undo.len()
    }

    pub(in crate::editor) fn redo_count(&self) -> usize {
        self.redo.len()
    }
}

impl Session {
    /// A selection change begins: the current selection is what an undo returns to, once
    /// the change changes something ([`Session::changed`]).
    pub(super) fn begin_change(&mut self) {
        self.history.pending = Some(self.groups.clone());
    }

    /// The change begun last changed the selection: it becomes an undo step (once per
    /// stroke), and what was undone can no longer be redone.
    pub(super) fn changed(&mut self) {
        if let Some(s) = self.history.pending.take() {
            if self.history.undo.len() == HISTORY {
                self.history.undo.remove(0);
            }
            self.history.undo.push(s);
            self.history.redo.clear();
        }
    }

    /// Undo (or redo) the last surgery of a rig, or the last selection change of a mesh
    /// scene (then rebinds, each group keeping its motor).
    pub(super) fn undo_redo(&mut self, undo: bool) -> Result<Vec<Out>> {
        if let Some(rig) = self.rig.as_mut() {
            if undo {
                rig.undo()?;
            } else {
                rig.redo()?;
            }
            return self.load_rig_mesh();
        }
        let h = &mut self.history;
        let (from, word) = if undo {
            (&mut h.undo, "undo")
        } else {
            (&mut h.redo, "redo")
        };
        let Some(back) = from.pop() else {
            bail!("nothing to {word}");
        };
        h.pending = None;
        let now = self.groups.clone();
        if undo {
            self.history.redo.push(now);
        } else {
            self.history.undo.push(now);
        }
        // Group `g` keeps its motor (a new one starts at the identity), as in the page.
        let mut specs = std::mem::take(&mut self.specs);
        specs.resize(back.len(), MotorSpec::default());
        self.set_groups(back);
        self.specs = specs;
        self.bind()
    }

    /// Paint or erase around where the ray meets the posed surface.
    pub(super) fn paint(
        &mut self,
        origin: DVec3,
        direction: DVec3,
        radius: f64,
        group: usize,
        erase: bool,
    ) -> Result<Vec<Out>> {
        self.check_group(group)?;
        if !(radius.is_finite() && radius >= 0.0) {
            bail!("paint radius {radius} is not a finite length");
        }
        let Some(hit) = self.hit(origin, direction) else {
            return Ok(Vec::new());
        };
        let r2 = radius * radius;
        let near: Vec<usize> = (0..self.posed.len())
            .filter(|&v| (self.posed[v] - hit.point).length_squared() <= r2)
            .collect();
        self.assign(&near, group, erase)
    }

    /// Lasso: the vertices seen from `eye` (no surface in front of them) whose projection by
    /// `view_proj` (column-major, the page's) falls inside `polygon` (normalised device
    /// coordinates) join `group`, or leave it (`erase`).
    pub(super) fn lasso(
        &mut self,
        eye: DVec3,
        view_proj: [f64; 16],
        polygon: &[[f64; 2]],
        group: usize,
        erase: bool,
    ) -> Result<Vec<Out>> {
        self.check_group(group)?;
        if !(3..=10_000).contains(&polygon.len()) {
            bail!("a lasso has 3 to 10000 points, not {}", polygon.len());
        }
        let m = DMat4::from_cols_array(&view_proj);
        if !m.is_finite() || !eye.is_finite() || polygon.iter().flatten().any(|x| !x.is_finite()) {
            bail!("the lasso's camera or points are not finite");
        }
        self.begin_change();
        let inside: Vec<usize> = (0..self.posed.len())
            .filter(|&v| {
                let c = m * self.posed[v].extend(1.0);
                c.w > 0.0 && contains(polygon, [c.x / c.w, c.y / c.w])
            })
            .collect();
        // Seen: the first surface on the way from the eye is the vertex's own.
        let posed = Mesh::new(self.posed.clone(), self.mesh.triangles.clone());
        self.bvh.refit(&posed);
        let seen: Vec<usize> = inside
            .into_iter()
            .filter(|&v| {
                let hit = self.bvh.ray_hit(&posed, eye, self.posed[v] - eye);
                hit.is_none_or(|h| h.t >= 1.0 - 1e-6)
            })
            .collect();
        self.assign(&seen, group, erase)
    }

    /// `group` may be painted: an existing one or the next new one, on a handle method.
    fn check_group(&self, group: usize) -> Result<()> {
        self.mesh_only("select")?;
        if self.settings.method.controls() {
            bail!("paint groups for handles, ARAP or the spline; a lattice or cage moves by its points");
        }
        if group > self.groups.len() || group >= 250 {
            bail!(
                "group {group}: paint an existing group (0..{}) or the next new one",
                self.groups.len()
            );
        }
        Ok(())
    }

    /// Put `vertices` in `group` (or take them out of it), renumber the groups.
    fn assign(&mut self, vertices: &[usize], group: usize, erase: bool) -> Result<Vec<Out>> {
        let mut changed = false;
        for &v in vertices {
            let want = if erase {
                if self.owner[v] == group as u32 {
                    NONE
                } else {
                    self.owner[v]
                }
            } else {
                group as u32
            };
            changed |= want != self.owner[v];
            self.owner[v] = want;
        }
        if !changed {
            return Ok(Vec::new());
        }
        self.changed();
        // Groups from owners, renumbered without gaps (an emptied group disappears).
        let mut groups: Vec<Vec<u32>> = vec![Vec::new(); self.groups.len() + 1];
        for (v, &g) in self.owner.iter().enumerate() {
            if g != NONE {
                groups[g as usize].push(v as u32);
            }
        }
        let mut specs = std::mem::take(&mut self.specs);
        specs.push(MotorSpec::default());
        let (groups, specs): (Vec<_>, Vec<_>) = groups
            .into_iter()
            .zip(specs)
            .filter(|(g, _)| !g.is_empty())
            .unzip();
        let posed = std::mem::take(&mut self.posed);
        self.set_groups(groups);
        self.specs = specs;
        self.posed = posed;
        Ok(vec![Out::Binary(Frame::groups(&self.owner)), self.state()])
    }
}

#[cfg(test)]
mod tests {
    use super::contains;

    #[test]
    fn the_even_odd_rule_on_a_square_and_a_notch() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert!(contains(&square, [0.5, 0.5]));
        assert!(!contains(&square, [1.5, 0.5]));
        let notch = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 0.5], [0.0, 2.0]];
        assert!(contains(&notch, [0.5, 0.4]));
        assert!(!contains(&notch, [1.0, 1.5]));
    }
}
