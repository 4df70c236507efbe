//! Motor handles on harmonic fields (first paper, section IV): `n` handle vertex sets `H_j`,
//! one harmonic field `lambda_j` per handle (1 on `H_j`, 0 on the others: harmonic
//! coordinates, a partition of unity), and `M_i = exp(sum_j lambda_j^i log R_j)`. Each handle
//! can rotate, translate and scale; its vertices follow its motor exactly.

use crate::blend::KeyError;
use crate::blend::{BlendMethod, BoundBlend, KeyWeights};
use crate::deformers::deformer::deformer_via_blend;
use crate::deformers::Result;
use crate::mesh::{Mesh, MeshError};
use crate::operators::harmonic::Harmonic;
use crate::operators::harmonic::HarmonicOptions;
use crate::operators::laplacian::LaplacianKind;
use crate::operators::solve::SystemAnalysis;
use cga::ScaledMotor;

/// Options of [`MotorHandles::bind_with`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HandleOptions {
    /// How the fields are computed (default: the paper's mean-value weights).
    pub harmonic: HarmonicOptions,
    /// How the handle motors are blended (default: the paper's log blend).
    pub method: BlendMethod,
}

impl Default for HandleOptions {
    fn default() -> Self {
        HandleOptions {
            harmonic: HarmonicOptions {
                laplacian: LaplacianKind::MeanValue,
                ..HarmonicOptions::default()
            },
            method: BlendMethod::MotorLog,
        }
    }
}

/// A mesh bound to motor handles.
#[derive(Clone, Debug)]
pub struct MotorHandles {
    blend: BoundBlend,
}

impl MotorHandles {
    /// Bind with the rest pose at the identity, the log blend and the given field options.
    ///
    /// # Errors
    /// As [`MotorHandles::bind_with`].
    pub fn bind(mesh: &Mesh, sets: &[&[u32]], harmonic: HarmonicOptions) -> Result<Self> {
        let rest = vec![ScaledMotor::IDENTITY; sets.len()];
        Self::bind_with(
            mesh,
            sets,
            &rest,
            HandleOptions {
                harmonic,
                method: BlendMethod::MotorLog,
            },
        )
    }

    /// Bind `mesh` to the handle `sets` with rest motors `rest` (one per set). The harmonic
    /// coordinates are dense: a weight per vertex and set, held several times over while
    /// binding (about 4 `f64`s a pair; thousands of sets on a large mesh take gigabytes).
    ///
    /// # Errors
    /// [`KeyError::EmptyHandle`], [`KeyError::WrongCount`] (no sets, or `rest` of another
    /// length), [`KeyError::TooMany`], and the mesh and constraint errors of
    /// [`Harmonic::new`] (overlapping sets, vertices out of range, a component without
    /// handles).
    pub fn bind_with(
        mesh: &Mesh,
        sets: &[&[u32]],
        rest: &[ScaledMotor],
        options: HandleOptions,
    ) -> Result<Self> {
        Self::check_sets(sets, rest)?;
        let coordinates = Harmonic::new(mesh, sets, options.harmonic)?.coordinates()?;
        let weights = KeyWeights::from_columns(&coordinates)?;
        let blend = BoundBlend::bind(&mesh.positions, weights, rest, options.method)?;
        Ok(MotorHandles { blend })
    }

    /// [`MotorHandles::bind_with`] on a mesh whose system matrix is already analysed
    /// (`SystemAnalysis::new(&harmonic_system(mesh, &options.harmonic)?)`, kept across
    /// selections): a new selection costs the numeric factorisation, the solves and the rest
    /// points, not the matrix and its ordering. What `deform view` does when handles change.
    ///
    /// # Errors
    /// As [`MotorHandles::bind_with`]; [`MeshError::DimensionMismatch`] when the analysis is
    /// of a matrix of another size than the mesh.
    pub fn bind_with_analysis(
        mesh: &Mesh,
        analysis: &SystemAnalysis,
        sets: &[&[u32]],
        rest: &[ScaledMotor],
        options: HandleOptions,
    ) -> Result<Self> {
        if analysis.len() != mesh.vertex_count() {
            return Err(MeshError::DimensionMismatch {
                what: "rows of the analysed system matrix",
                expected: mesh.vertex_count(),
                got: analysis.len(),
            }
            .into());
        }
        Self::check_sets(sets, rest)?;
        let coordinates =
            Harmonic::with_analysis(analysis, sets, options.harmonic.solver)?.coordinates()?;
        let weights = KeyWeights::from_columns(&coordinates)?;
        let blend = BoundBlend::bind(&mesh.positions, weights, rest, options.method)?;
        Ok(MotorHandles { blend })
    }

    /// The checks of the handle sets and rest motors shared by the binds.
    fn check_sets(sets: &[&[u32]], rest: &[ScaledMotor]) -> Result<()> {
        if sets.is_empty() || rest.len() != sets.len() {
            return Err(KeyError::WrongCount {
                what: "motor handles",
                expected: format!("one rest motor per handle set ({})", sets.len().max(1)),
                got: rest.len(),
            }
            .into());
        }
        KeyError::check_count("handle sets", sets.len())?;
        if let Some(set) = sets.iter().position(|s| s.is_empty()) {
            return Err(KeyError::EmptyHandle { set }.into());
        }
        Ok(())
    }

    /// The harmonic coordinate of handle `j` at vertex `i`.
    pub fn coordinate(&self, i: usize, j: usize) -> f64 {
        self.blend.weights().weight(i, j)
    }

    /// The bound blend (weights, method).
    pub fn blend(&self) -> &BoundBlend {
        &self.blend
    }
}

deformer_via_blend!(MotorHandles, blend, crate::blend::PreparedKeys);
