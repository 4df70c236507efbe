//! Skinned, animated models (second paper, sections 2-4.1): rigs read from glTF 2.0 or
//! libigl files, sampled animations, joint transforms as motors with dilators, and skinning
//! by any [`crate::blend::BlendMethod`] (matrix LBS, dual quaternions, the paper's equation (17) in
//! both evaluation orders, motor blending).
//!
//! * [`Rig`]: the node hierarchy, the skin (joints and inverse bind matrices), the rest mesh
//!   with its per-vertex influences, and the animations; read by [`read_gltf`] /
//!   [`parse_gltf`] or built from libigl files by [`libigl_rig`].
//! * [`Rig::pose`] samples an animation at a time into a [`RigPose`]: local transforms, global
//!   transforms (walking the hierarchy, as matrices and as motors) and the skin motors
//!   `M_n B_n` of equation (17).
//! * [`Skinning`]: the bound deformer; its keys are the skin motors, one per joint.
//! * [`write_glb`]: the rig back out as binary glTF (mesh, skin, hierarchy, animations).
//!
//! **May use**: mesh, operators, blend, deformers. **Must not use**: surgery, render, input,
//! or the crate-level `Error`; its error is [`SkinError`] (binding reports
//! [`crate::deformers::DeformError`]).
//!
//! ```
//! use deform::skinning::{procedural_arm, Skinning};
//! use deform::{BlendMethod, Deformer};
//! let rig = procedural_arm(12, 8);
//! let skin = Skinning::bind(&rig, BlendMethod::MotorLinear).unwrap();
//! let pose = rig.pose(Some(0), 0.5, &[]).unwrap();
//! let mut out = vec![glam::DVec3::ZERO; rig.mesh.vertex_count()];
//! skin.pose(&pose.skin_motors().unwrap(), &mut out).unwrap();
//! assert!(out.iter().all(|p| p.is_finite()));
//! ```

mod accessor;
mod animation;
mod approximation;
mod bake;
mod compressed;
mod edit;
mod glb_container;
mod glb_write;
mod gltf_read;
mod index_check;
mod influences;
mod libigl_rig;
mod look;
mod look_read;
mod morph;
mod parts;
mod pose;
mod primitive_read;
mod procedural;
mod rig;
mod rig_files;
mod similarity;
mod skin;
mod trs;

pub use accessor::GltfReadOptions;
pub use animation::{Animation, Channel, Interpolation, KeyframeBlend, Property};
pub use approximation::Approximation;
pub use bake::bake_edits;
pub use edit::{in_betweens, JointEdit};
pub use glb_write::{glb_bytes, write_glb, GlbOptions};
pub use gltf_read::{gltf_external_files, parse_gltf, parse_gltf_with, read_gltf, read_gltf_with};
pub use influences::Influences;
pub use libigl_rig::{libigl_rig, read_libigl_animation, LibiglAnimation};
pub use look::{planar_uvs, Look, LookImage, VertexAttribute};
pub use parts::RigPart;
pub use pose::RigPose;
pub use procedural::procedural_arm;
pub use rig::{LoadReport, PrimitiveInfo, Rig, RigNode};
pub use rig_files::read_rig;
pub use similarity::{nearest_similarity, NearestSimilarity, SIMILARITY_NOISE};
pub use skin::Skinning;
pub use trs::Trs;

/// What is wrong with a rig file, a rig or an animation request.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SkinError {
    /// The file could not be read or written.
    #[error("{}: {message}", path.display())]
    Io {
        /// The file.
        path: std::path::PathBuf,
        /// What the system said.
        message: String,
    },
    /// A value that cannot be written (not finite in single precision, too many joints).
    #[error("invalid argument: {0}")]
    InvalidArgument(String),
    /// The file is not valid glTF (truncated, corrupt, or failing the glTF schema checks).
    #[error("{name}: not a valid glTF file: {message}")]
    Gltf {
        /// The file.
        name: String,
        /// What the parser said.
        message: String,
    },
    /// Buffer data that is missing, too short, or an accessor reaching past its buffer.
    #[error("{name}: {message}")]
    Data {
        /// The file.
        name: String,
        /// What is wrong.
        message: String,
    },
    /// A feature this crate does not read (documented at [`parse_gltf`]).
    #[error("{name}: unsupported: {message}")]
    Unsupported {
        /// The file.
        name: String,
        /// The feature.
        message: String,
    },
    /// A vertex influenced by a joint index past the skin's joints.
    #[error("vertex {vertex}: joint index {joint} is past the skin's {joints} joints")]
    JointOutOfRange {
        /// The vertex (index into the concatenated primitives).
        vertex: usize,
        /// The joint index.
        joint: u32,
        /// The number of joints.
        joints: usize,
    },
    /// A negative or non-finite weight.
    #[error("vertex {vertex}: weight {weight} is negative or not finite")]
    BadWeight {
        /// The vertex.
        vertex: usize,
        /// The weight.
        weight: f64,
    },
    /// A node transform, inverse bind matrix or keyframe value that is not finite or not
    /// usable.
    #[error("{what}: {message}")]
    BadTransform {
        /// Which node, joint or channel.
        what: String,
        /// What is wrong.
        message: String,
    },
    /// A transform that motors cannot represent (non-uniform scale or shear), asked for in
    /// motor form.
    #[error("{what} is not a similarity (rotation, translation, uniform scale): {message}")]
    NotSimilarity {
        /// Which node or joint.
        what: String,
        /// Why.
        message: String,
    },
    /// An animation index or name that the rig does not have.
    #[error("no animation {0}")]
    NoAnimation(String),
    /// A joint name or index that the rig does not have.
    #[error("no joint {0} in this rig")]
    NoJoint(String),
    /// A rig without a skin or a skinned triangle mesh.
    #[error("{0}")]
    NoSkin(String),
    /// Skinning a pose failed (a pose of another rig, positions leaving the `f64` range).
    #[error("skinning the pose: {0}")]
    Pose(String),
}
