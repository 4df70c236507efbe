//! Cage coordinates (first paper, section VI): every model vertex is a combination of the
//! vertices `P_j` of a closed cage around it, `p_i = sum_j lambda_j^i P_j`, with generalised
//! barycentric coordinates `lambda_j^i`:
//!
//! * mean value coordinates ([`mvc`], Ju, Schaefer and Warren 2005), closed form;
//! * harmonic coordinates ([`harmonic`], Joshi et al. 2007): one Laplace solve per cage vertex
//!   on a voxel grid inside the cage, looked up trilinearly at the model's vertices.
//!
//! Posed positionally (each cage vertex moved by its motor, `P_j = R_j(P_j^rest)`) or
//! motor-valued (`M_i = exp(sum_j lambda_j^i log R_j)`), so cage vertices can rotate as well as
//! move (Fig. 8). Binding checks the cage ([`check_cage`]) and that it encloses the model
//! ([`check_encloses`]).
//!
//! ```
//! use deform::deformers::cage::{CageDeformer, CageOptions};
//! use deform::mesh::shapes;
//! use deform::Deformer;
//! let cage = shapes::icosphere(2.0, 1);
//! let model = shapes::icosphere(1.0, 1);
//! let d = CageDeformer::bind(&model, &cage, CageOptions::default()).unwrap();
//! let keys = vec![cga::ScaledMotor::IDENTITY; cage.vertex_count()];
//! let mut out = vec![glam::DVec3::ZERO; model.vertex_count()];
//! d.pose(&keys, &mut out).unwrap();
//! assert!(out.iter().zip(&model.positions).all(|(a, b)| a.distance(*b) < 1e-12));
//! ```

mod check;
mod containment;
pub mod harmonic;
pub mod intersect;
pub mod mvc;

pub use check::{check_cage, check_cage_with, DEGENERATE_AREA};
pub use containment::{
    check_encloses, check_winding, orientation, winding_number, winding_numbers, ENCLOSED,
};
pub use harmonic::{harmonic_cage_coordinates, HarmonicGrid};
pub use mvc::{coordinates_and_winding, mean_value_coordinates};

use crate::blend::control::{ControlBinding, ControlForm};
use crate::blend::KeyWeights;
pub use crate::deformers::error::CageError;
use crate::deformers::Result;
use crate::mesh::Mesh;

/// Which coordinates bind the model to the cage.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum CageCoordinates {
    /// Mean value coordinates (the default).
    #[default]
    MeanValue,
    /// Harmonic coordinates on a voxel grid.
    Harmonic(HarmonicGrid),
}

/// Options of [`CageDeformer::bind`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CageOptions {
    /// Which coordinates.
    pub coordinates: CageCoordinates,
    /// Positional or motor-valued (default: the motor log blend).
    pub form: ControlForm,
    /// Accept a cage whose faces cross (mean value coordinates are still defined; harmonic
    /// ones see the union of its inside). Default `false`: refused.
    pub allow_self_intersecting: bool,
}

/// A model bound to a cage: one key per cage vertex.
#[derive(Clone, Debug)]
pub struct CageDeformer {
    cage: Mesh,
    binding: ControlBinding,
}

impl CageDeformer {
    /// Check `cage`, check that it encloses `model`, compute the coordinates and bind.
    ///
    /// # Errors
    /// The [`CageError`]s (wrapped in [`crate::Error::Cage`]).
    pub fn bind(model: &Mesh, cage: &Mesh, options: CageOptions) -> Result<Self> {
        check_cage_with(cage, options.allow_self_intersecting)?;
        let m = cage.vertex_count();
        let n = model.vertex_count();
        let weights = match options.coordinates {
            CageCoordinates::MeanValue => {
                // The winding numbers come with the coordinates, from the same unit vectors.
                let (w, winding) = match coordinates_and_winding(cage, &model.positions) {
                    Ok(x) => x,
                    Err(e) => {
                        // A point outside is the likelier cause: report it as such.
                        check_encloses(cage, &model.positions)?;
                        return Err(e);
                    }
                };
                check_winding(orientation(cage), &winding)?;
                w
            }
            CageCoordinates::Harmonic(grid) => {
                check_encloses(cage, &model.positions)?;
                harmonic_cage_coordinates(cage, &model.positions, grid)?
            }
        };
        let weights = KeyWeights::new(m, m, vec![0; n], weights)?;
        let binding = ControlBinding::bind(
            &model.positions,
            cage.positions.clone(),
            weights,
            options.form,
        )?;
        Ok(CageDeformer {
            cage: cage.clone(),
            binding,
        })
    }

    /// The rest cage.
    pub fn cage(&self) -> &Mesh {
        &self.cage
    }

    /// The coordinate of cage vertex `j` at model vertex `i`.
    pub fn coordinate(&self, i: usize, j: usize) -> f64 {
        self.binding.weights().row(i).weights[j]
    }

    /// The binding (weights, positional posing by cage points).
    pub fn binding(&self) -> &ControlBinding {
        &self.binding
    }
}

crate::deformers::deformer::deformer_via_blend!(
    CageDeformer,
    binding,
    crate::blend::control::ControlScratch
);
