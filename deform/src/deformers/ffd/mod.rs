//! Free-form deformation (first paper, section V): a lattice of control points over the mesh,
//! in the classic positional form of Sederberg and Parry (equation (6),
//! `p_i = sum B_u B_v B_k P_uvk`) and the motor form (equations (7)-(8): every control point
//! carries a motor, `M_i = exp(sum w_uvk^i log R_uvk)`), which bends and twists where moving
//! control points alone shears and collapses (Fig. 7).
//!
//! Keys are one motor per control point, index `u + L * (v + M * w)`; in the positional form
//! each control point moves by its motor.
//!
//! ```
//! use deform::deformers::ffd::{Ffd, FfdOptions};
//! use deform::mesh::shapes;
//! use deform::Deformer;
//! use cga::ScaledMotor;
//! let bar = shapes::tube(1.0, 4.0, 8, 5);
//! let ffd = Ffd::bind(&bar, [2, 2, 2], None, FfdOptions::default()).unwrap();
//! let mut out = vec![glam::DVec3::ZERO; bar.vertex_count()];
//! ffd.pose(&vec![ScaledMotor::IDENTITY; 8], &mut out).unwrap();
//! assert!(out.iter().zip(&bar.positions).all(|(a, b)| a.distance(*b) < 1e-12));
//! ```

mod lattice;

pub use crate::deformers::bspline::bernstein;
pub use lattice::{Lattice, LatticeBasis, OUTSIDE_TOLERANCE};

use crate::blend::control::{ControlBinding, ControlForm};
pub use crate::deformers::error::FfdError;
use crate::deformers::Result;
use crate::mesh::Mesh;
use crate::mesh::MeshError;
use glam::DVec3;

/// Options of [`Ffd::bind`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FfdOptions {
    /// Bernstein (default) or B-spline basis.
    pub basis: LatticeBasis,
    /// Positional or motor form (default: the motor log blend).
    pub form: ControlForm,
}

/// A mesh bound to a lattice.
#[derive(Clone, Debug)]
pub struct Ffd {
    lattice: Lattice,
    binding: ControlBinding,
}

impl Ffd {
    /// Bind `mesh` to a lattice of `dims` control points over `bounds` (default: the mesh's
    /// bounding box).
    ///
    /// # Errors
    /// The [`FfdError`]s of [`Lattice::new`] and [`Lattice::local`] (wrapped in
    /// [`crate::Error::Ffd`]), [`MeshError::EmptyMesh`] for a mesh without vertices.
    pub fn bind(
        mesh: &Mesh,
        dims: [usize; 3],
        bounds: Option<(DVec3, DVec3)>,
        options: FfdOptions,
    ) -> Result<Self> {
        let (min, max) = match bounds {
            Some(b) => b,
            None => {
                let b = mesh.bounding_box().ok_or(MeshError::EmptyMesh {
                    vertices: 0,
                    triangles: mesh.triangle_count(),
                })?;
                (b.min, b.max)
            }
        };
        let lattice = Lattice::new(dims, min, max, options.basis)?;
        Self::bind_lattice(&mesh.positions, lattice, options.form)
    }

    /// Bind `positions` to `lattice` in `form`.
    ///
    /// # Errors
    /// [`FfdError::Outside`] for a vertex outside the lattice.
    pub fn bind_lattice(positions: &[DVec3], lattice: Lattice, form: ControlForm) -> Result<Self> {
        let weights = lattice.weights(positions)?;
        let binding = ControlBinding::bind(positions, lattice.rest_points(), weights, form)?;
        Ok(Ffd { lattice, binding })
    }

    /// The lattice.
    pub fn lattice(&self) -> &Lattice {
        &self.lattice
    }

    /// The binding (weights, rest points, positional posing by points).
    pub fn binding(&self) -> &ControlBinding {
        &self.binding
    }
}

crate::deformers::deformer::deformer_via_blend!(
    Ffd,
    binding,
    crate::blend::control::ControlScratch
);
