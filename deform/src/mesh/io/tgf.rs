//! libigl's Trivial Graph Format skeletons (`.tgf`).

use super::{read_text, Ctx};
use crate::mesh::Result;
use glam::DVec3;
use std::path::Path;

/// A skeleton: joint positions and bones joining two joints.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Skeleton {
    /// Joint positions.
    pub joints: Vec<DVec3>,
    /// Bones as 0-based joint pairs `[parent, child]`.
    pub bones: Vec<[u32; 2]>,
}

/// Reads a TGF file; see [`parse_tgf`].
pub fn read_tgf(path: impl AsRef<Path>) -> Result<Skeleton> {
    let path = path.as_ref();
    parse_tgf(&read_text(path)?, &path.display().to_string())
}

/// Parses TGF: joint lines `index x y z ...` (1-based index, extra columns ignored), a `#`
/// line, then bone lines `a b ...` (1-based joints), optionally ended by another `#`.
/// Coordinates must be finite and bones must join existing joints.
///
/// ```
/// let s = deform::mesh::io::parse_tgf("1 0 0 0\n2 0 1 0\n#\n1 2\n#\n", "s").unwrap();
/// assert_eq!(s.bones, vec![[0, 1]]);
/// ```
pub fn parse_tgf(text: &str, name: &str) -> Result<Skeleton> {
    let mut sk = Skeleton::default();
    let mut section = 0;
    for (ln, line) in text.lines().enumerate() {
        let ctx = Ctx { name, line: ln + 1 };
        let line = line.trim();
        if line.starts_with('#') {
            section += 1;
            continue;
        }
        if line.is_empty() {
            continue;
        }
        let mut t = line.split_ascii_whitespace();
        match section {
            0 => {
                let idx = ctx.index1(t.next(), "joint index")?;
                if idx as usize != sk.joints.len() {
                    return Err(ctx.err(format!(
                        "joint {} listed out of order (expected {})",
                        idx + 1,
                        sk.joints.len() + 1
                    )));
                }
                let x = ctx.f64(t.next(), "x coordinate")?;
                let y = ctx.f64(t.next(), "y coordinate")?;
                let z = ctx.f64(t.next(), "z coordinate")?;
                sk.joints.push(DVec3::new(x, y, z));
            }
            1 => {
                let a = ctx.index1(t.next(), "bone start")?;
                let b = ctx.index1(t.next(), "bone end")?;
                let n = sk.joints.len() as u32;
                if a >= n || b >= n {
                    return Err(ctx.err(format!("bone refers to a joint beyond {n}")));
                }
                sk.bones.push([a, b]);
            }
            _ => {}
        }
    }
    Ok(sk)
}
