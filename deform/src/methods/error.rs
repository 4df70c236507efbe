//! What goes wrong choosing a method, setting an option or binding and posing one.

/// A method, option or pose request that cannot be taken; nothing changed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MethodError {
    /// A name that is none of the choice's.
    #[error("no {what} {given:?} ({expected})")]
    UnknownName {
        /// What was named ("ARAP energy").
        what: &'static str,
        /// The name given.
        given: String,
        /// Every name, comma-separated.
        expected: String,
    },
    /// A number outside the option's range.
    #[error("{option}: {value} is not in {range}")]
    OutOfRange {
        /// The option.
        option: &'static str,
        /// The value given.
        value: String,
        /// The range it must be in.
        range: String,
    },
    /// A Bernstein lattice too large for interactive posing.
    #[error(
        "a {}x{}x{} Bernstein lattice has {points} control points, each moving every vertex \
         (at most {max} here; a B-spline basis takes more)", dims[0], dims[1], dims[2]
    )]
    BernsteinTooLarge {
        /// Control points per axis.
        dims: [usize; 3],
        /// Their product.
        points: usize,
        /// The most allowed.
        max: usize,
    },
    /// The cage method on a scene without a cage.
    #[error("this mesh has no cage to bind to")]
    NoCage,
    /// The positional form for a method that has no control points.
    #[error("positional blending is for lattices and cages, not {method}")]
    PositionalWithoutControls {
        /// The method's name.
        method: &'static str,
    },
    /// A request that does not fit (a selection given with a rig).
    #[error("{0}")]
    Refused(String),
    /// Fewer handle groups than the method binds to.
    #[error("{method} needs {need} handle group(s) or more, got {have}")]
    TooFewGroups {
        /// The method's name.
        method: &'static str,
        /// The fewest it takes.
        need: usize,
        /// How many were given.
        have: usize,
    },
    /// A pose with the wrong number of motors.
    #[error("{given} motors for {expected} {keys} (one per key)")]
    KeyCount {
        /// Motors given.
        given: usize,
        /// Keys bound.
        expected: usize,
        /// What the keys are: "groups" or "control points".
        keys: &'static str,
    },
}

/// The methods layer's error: a refused choice or request, or what the layers below report
/// while binding and posing.
#[derive(Debug, thiserror::Error)]
pub enum MethodsError {
    /// A method, option or pose request that cannot be taken.
    #[error(transparent)]
    Method(#[from] MethodError),
    /// A request over the work budget.
    #[error(transparent)]
    Budget(#[from] crate::methods::budget::BudgetError),
    /// A deformer that cannot bind or pose.
    #[error(transparent)]
    Deform(#[from] crate::deformers::DeformError),
    /// A rig that cannot be posed.
    #[error(transparent)]
    Skin(#[from] crate::skinning::SkinError),
    /// A cut, tear or drill that cannot be made.
    #[error(transparent)]
    Surgery(#[from] crate::surgery::SurgeryError),
    /// A bad motor or selection file.
    #[error(transparent)]
    Input(#[from] crate::input::InputError),
}

impl From<crate::mesh::MeshError> for MethodsError {
    fn from(e: crate::mesh::MeshError) -> Self {
        MethodsError::Deform(e.into())
    }
}

impl From<crate::operators::SolveError> for MethodsError {
    fn from(e: crate::operators::SolveError) -> Self {
        MethodsError::Deform(e.into())
    }
}

impl From<crate::blend::BlendError> for MethodsError {
    fn from(e: crate::blend::BlendError) -> Self {
        MethodsError::Deform(e.into())
    }
}
