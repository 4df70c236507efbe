//! The deformation methods a mesh and its handle groups (or control points) can be posed by.

use super::kind::MethodKind;
use super::kinds::{arap, cage, fabrik, ffd, handles, spline};
use super::named::Named;
use super::option::OptionSpec;

/// How a mesh is deformed from motors: one per handle group, or one per control point of a
/// lattice or cage. Each variant names a [`MethodKind`], one file in [`super::kinds`] that
/// describes, binds and poses it; adding a method is that file, a variant here and its line in
/// [`Method::kind`] and [`Named::ALL`]. The editor and the program take every method from here.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Method {
    /// Motor handles on harmonic coordinates (the first paper's section V).
    #[default]
    Handles,
    /// ARAP with rotors, the groups as handles.
    Arap,
    /// Spline-aligned deformation, the groups as keys (the first and last bound the spine).
    Spline,
    /// Free-form deformation: a motor per point of a lattice over the mesh's box.
    Ffd,
    /// A motor per vertex of a closed cage around the mesh.
    Cage,
    /// B-spline + FABRIK: the last group's motor moves a chain's end effector.
    Fabrik,
}

impl Method {
    /// The method's description and bind.
    pub fn kind(self) -> &'static dyn MethodKind {
        match self {
            Method::Handles => &handles::HandlesMethod,
            Method::Arap => &arap::ArapMethod,
            Method::Spline => &spline::SplineMethod,
            Method::Ffd => &ffd::FfdMethod,
            Method::Cage => &cage::CageMethod,
            Method::Fabrik => &fabrik::FabrikMethod,
        }
    }

    /// Whether its keys are control points (a lattice's or a cage's), not handle groups.
    pub fn controls(self) -> bool {
        self.kind().controls()
    }

    /// The fewest handle groups it binds to (the spline needs its two ends).
    pub fn groups_needed(self) -> usize {
        self.kind().groups_needed()
    }

    /// The files its command reads besides the mesh ([`MethodKind::inputs`]).
    pub fn inputs(self) -> &'static [(&'static str, &'static str)] {
        self.kind().inputs()
    }

    /// The program's words that pose it from files, before the mesh ([`MethodKind::command`]).
    pub fn command(self) -> Vec<&'static str> {
        self.kind().command()
    }

    /// Whether its command reads a file holding `what` (`selection`, `keys`, `cage`, ...).
    pub fn reads(self, what: &str) -> bool {
        self.inputs().iter().any(|(_, w)| *w == what)
    }

    /// Whether it blends key motors by a [`crate::BlendMethod`] (ARAP solves instead).
    pub fn blends(self) -> bool {
        self.kind().blends()
    }

    /// Its own options.
    pub fn options(self) -> &'static [OptionSpec] {
        self.kind().options()
    }
}

impl Named for Method {
    const ALL: &'static [Self] = &[
        Method::Handles,
        Method::Arap,
        Method::Spline,
        Method::Ffd,
        Method::Cage,
        Method::Fabrik,
    ];
    const WHAT: &'static str = "method";
    /// The name, which is also the program's subcommand.
    fn name(self) -> &'static str {
        self.kind().name()
    }
}
