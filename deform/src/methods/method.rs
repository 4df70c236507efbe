//! The deformation methods a mesh and its handle groups (or control points) can be posed by,
//! and what goes wrong choosing or binding one.

use super::named::Named;

/// How a mesh is deformed from motors: one per handle group, or one per control point of a
/// lattice or cage. Adding a method is a variant here, its options in
/// [`super::settings::MethodSettings`] and its bind and pose in [`super::bound`]; the editor
/// and the program take every method from here.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// Motor handles on harmonic coordinates (the first paper's section V).
    Handles,
    /// ARAP with rotors, the groups as handles.
    Arap,
    /// Spline-aligned deformation, the groups as keys (the first and last bound the spine).
    Spline,
    /// Free-form deformation: a motor per point of a lattice over the mesh's box.
    Ffd,
    /// A motor per vertex of a closed cage around the mesh.
    Cage,
}

impl Named for Method {
    const ALL: &'static [Self] = &[
        Method::Handles,
        Method::Arap,
        Method::Spline,
        Method::Ffd,
        Method::Cage,
    ];
    const WHAT: &'static str = "method";
    /// The name, which is also the program's subcommand.
    fn name(self) -> &'static str {
        match self {
            Method::Handles => "handles",
            Method::Arap => "arap",
            Method::Spline => "spline",
            Method::Ffd => "ffd",
            Method::Cage => "cage",
        }
    }
}

impl Method {
    /// Whether its keys are control points (a lattice's or a cage's), not handle groups.
    pub fn controls(self) -> bool {
        matches!(self, Method::Ffd | Method::Cage)
    }

    /// The fewest handle groups it binds to (the spline needs its two ends).
    pub fn groups_needed(self) -> usize {
        match self {
            Method::Spline => 2,
            Method::Ffd | Method::Cage => 0,
            Method::Handles | Method::Arap => 1,
        }
    }

    /// The files its command reads besides the mesh, in order: each flag's name and what
    /// the file holds (`selection`: the handle groups; `motors`: a motor per key; `keys` and
    /// `rest-keys`: the spline's posed and rest keys; `cage`: the cage mesh).
    pub fn inputs(self) -> &'static [(&'static str, &'static str)] {
        match self {
            Method::Handles | Method::Arap => &[("select", "selection"), ("motors", "motors")],
            Method::Spline => &[
                ("select", "selection"),
                ("keys", "keys"),
                ("rest-keys", "rest-keys"),
            ],
            Method::Ffd => &[("motors", "motors")],
            Method::Cage => &[("cage", "cage"), ("motors", "motors")],
        }
    }

    /// Whether it blends key motors by a [`crate::BlendMethod`] (ARAP solves instead).
    pub fn blends(self) -> bool {
        self != Method::Arap
    }
}

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
