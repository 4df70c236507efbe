//! The deformation methods a mesh and its handle groups (or control points) can be posed by.

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
