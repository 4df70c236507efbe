//! libigl rigs: a mesh, a TGF skeleton, DMAT weights (one column per bone), and DMAT
//! animations (per frame, per bone, the 4x3 block `[A^T; t^T]` that `igl::lbs_matrix` uses).

use super::influences::Influences;
use super::rig::{LoadReport, PrimitiveInfo, Rig, RigNode};
use super::SkinError;
use super::Trs;
use crate::mesh::io::{Dmat, Skeleton};
use crate::mesh::Mesh;
use cga::ScaledMotor;
use glam::{DAffine3, DMat3, DMat4, DVec3};

/// Build a rig from a libigl mesh, skeleton and weights. Each bone becomes a joint whose rest
/// frame is a translation to the bone's first joint position, parented to the bone ending
/// where it starts (libigl's `directed_edge_parents`); inverse bind matrices undo the rest
/// frames, so the rest pose is the identity on every vertex. The weights' columns are the
/// bones, in the TGF's bone order.
///
/// # Errors
/// [`SkinError::NoSkin`] when the weights do not have one row per vertex and one column per
/// bone, there are no bones, or a bone names a joint the skeleton does not have; the checks
/// of [`Rig::new`].
pub fn libigl_rig(mesh: Mesh, skeleton: &Skeleton, weights: &Dmat) -> Result<Rig, SkinError> {
    let bones = &skeleton.bones;
    if bones.is_empty() {
        return Err(SkinError::NoSkin("the skeleton has no bones".into()));
    }
    let joints = skeleton.joints.len();
    if let Some(b) = bones
        .iter()
        .position(|e| e.iter().any(|&j| j as usize >= joints))
    {
        return Err(SkinError::NoSkin(format!(
            "bone {b} joins joints {} and {}, past the skeleton's {joints}",
            bones[b][0], bones[b][1]
        )));
    }
    if weights.rows != mesh.vertex_count() || weights.cols != bones.len() {
        return Err(SkinError::NoSkin(format!(
            "weights are {}x{}, expected {}x{} (vertices x bones)",
            weights.rows,
            weights.cols,
            mesh.vertex_count(),
            bones.len()
        )));
    }
    let at = |b: usize| skeleton.joints[bones[b][0] as usize];
    let nodes: Vec<RigNode> = (0..bones.len())
        .map(|b| {
            let parent = bones.iter().position(|e| e[1] == bones[b][0]);
            let origin = parent.map_or(DVec3::ZERO, at);
            RigNode {
                name: format!("bone {b}"),
                parent,
                rest: Trs {
                    translation: at(b) - origin,
                    ..Trs::IDENTITY
                },
            }
        })
        .collect();
    let inverse_bind = (0..bones.len())
        .map(|b| DMat4::from_translation(-at(b)))
        .collect();
    let m = bones.len();
    let n = mesh.vertex_count();
    let mut influences = Influences {
        width: m,
        joints: Vec::with_capacity(n * m),
        weights: Vec::with_capacity(n * m),
    };
    for i in 0..n {
        for b in 0..m {
            influences.joints.push(b as u32);
            influences.weights.push(weights.get(i, b));
        }
    }
    let primitives = vec![PrimitiveInfo::whole(&mesh)];
    Rig::new(
        nodes,
        (0..m).collect(),
        inverse_bind,
        mesh,
        influences,
        primitives,
        Vec::new(),
        LoadReport::default(),
    )
}

/// A libigl animation: per frame, one skin transform per bone.
#[derive(Clone, Debug, PartialEq)]
pub struct LibiglAnimation {
    /// `frames[f][b]`: bone `b`'s transform at frame `f`.
    pub frames: Vec<Vec<DAffine3>>,
}

impl LibiglAnimation {
    /// The skin motors of frame `f`.
    ///
    /// # Errors
    /// [`SkinError::NoAnimation`] for a frame past the last; [`SkinError::NotSimilarity`]
    /// for a transform that is not a similarity; [`SkinError::BadTransform`] for one beyond a
    /// scaled motor's range.
    pub fn skin_motors(&self, f: usize) -> Result<Vec<ScaledMotor>, SkinError> {
        let frame = self
            .frames
            .get(f)
            .ok_or_else(|| SkinError::NoAnimation(format!("frame {f}")))?;
        frame
            .iter()
            .enumerate()
            .map(|(b, a)| {
                let what = format!("frame {f} bone {b}");
                Trs::from_matrix(&DMat4::from(*a), &what)?.motor(&what)
            })
            .collect()
    }
}

/// Read a libigl animation DMAT: one column per frame, `bones * 12` rows holding each bone's
/// 4x3 block `[A^T; t^T]` column-major (the layout `igl::lbs_matrix` multiplies).
///
/// # Errors
/// [`SkinError::Data`] when the row count is not `12 * bones`;
/// [`SkinError::BadTransform`] for a non-finite entry.
pub fn read_libigl_animation(m: &Dmat, bones: usize) -> Result<LibiglAnimation, SkinError> {
    if bones == 0 || Some(m.rows) != bones.checked_mul(12) {
        return Err(SkinError::Data {
            name: "libigl animation".into(),
            message: format!(
                "{} rows for {bones} bones (expected 12 a bone, {})",
                m.rows,
                bones.saturating_mul(12)
            ),
        });
    }
    let mut frames = Vec::with_capacity(m.cols);
    for f in 0..m.cols {
        let col = m.column(f);
        if col.iter().any(|x| !x.is_finite()) {
            return Err(SkinError::BadTransform {
                what: format!("frame {f}"),
                message: "not finite".into(),
            });
        }
        // T is (4 bones) x 3, column-major: T[b * 4 + r][c] = col[c * 4 * bones + b * 4 + r].
        let t = |b: usize, r: usize, c: usize| col[c * 4 * bones + b * 4 + r];
        frames.push(
            (0..bones)
                .map(|b| {
                    let a = DMat3::from_cols(
                        DVec3::new(t(b, 0, 0), t(b, 0, 1), t(b, 0, 2)),
                        DVec3::new(t(b, 1, 0), t(b, 1, 1), t(b, 1, 2)),
                        DVec3::new(t(b, 2, 0), t(b, 2, 1), t(b, 2, 2)),
                    );
                    DAffine3::from_mat3_translation(
                        a,
                        DVec3::new(t(b, 3, 0), t(b, 3, 1), t(b, 3, 2)),
                    )
                })
                .collect(),
        );
    }
    Ok(LibiglAnimation { frames })
}
