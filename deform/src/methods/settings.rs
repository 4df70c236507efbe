//! A method with every option it binds by, each option named once: [`OPTIONS`] lists the
//! names, the program's flags are `--` and the name, the editor's messages carry the same
//! names, and [`MethodSettings::args`] prints the flags that bind the same way (the editor's
//! replay command). The checks of each option's value live here too.

use super::error::MethodError;
use super::method::Method;
use super::named::{Coordinates, Named};
use crate::blend::control::ControlForm;
use crate::blend::BlendMethod;
use crate::deformers::arap::ArapOptions;
use crate::deformers::cage::{CageCoordinates, HarmonicGrid};
use crate::deformers::ffd::LatticeBasis;
use std::ops::RangeInclusive;

/// One option: its name (the flag is `--name`) and what it does, for help texts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OptionInfo {
    /// The name.
    pub name: &'static str,
    /// One line of help.
    pub help: &'static str,
    /// The methods it applies to.
    pub methods: &'static [Method],
}

/// How key motors are blended ([`BlendMethod`]'s names).
pub const BLEND: OptionInfo = OptionInfo {
    name: "blend",
    help: "How the key motors are blended.",
    methods: &[Method::Handles, Method::Spline, Method::Ffd, Method::Cage],
};
/// Lattices and cages: the classic positional form instead of blended motors.
pub const POSITIONAL: OptionInfo = OptionInfo {
    name: "positional",
    help: "Classic positional form: each control point moves by its motor, vertices follow the \
           weighted sum of the points.",
    methods: &[Method::Ffd, Method::Cage],
};
/// ARAP iterations.
pub const ITERATIONS: OptionInfo = OptionInfo {
    name: "iterations",
    help: "ARAP iterations (local and global steps).",
    methods: &[Method::Arap],
};
/// ARAP's rigidity energy.
pub const ENERGY: OptionInfo = OptionInfo {
    name: "energy",
    help: "The rigidity energy: each cell a vertex's spokes (the paper's) or its triangles' \
           spokes and rims (libigl's default).",
    methods: &[Method::Arap],
};
/// ARAP's local fit.
pub const LOCAL_STEP: OptionInfo = OptionInfo {
    name: "local-step",
    help: "The local fit: the paper's rotor or Sorkine and Alexa's SVD.",
    methods: &[Method::Arap],
};
/// Control points per axis of an FFD lattice.
pub const LATTICE: OptionInfo = OptionInfo {
    name: "lattice",
    help: "Control points per axis: LxMxN (each at least 2).",
    methods: &[Method::Ffd],
};
/// The lattice's basis.
pub const BASIS: OptionInfo = OptionInfo {
    name: "basis",
    help: "The lattice's basis: Bernstein polynomials of degree L-1, M-1, N-1, or clamped \
           uniform B-splines of degree 1 to 3.",
    methods: &[Method::Ffd],
};
/// A cage's coordinates.
pub const COORDINATES: OptionInfo = OptionInfo {
    name: "coordinates",
    help: "The cage's coordinates: mean value or harmonic.",
    methods: &[Method::Cage],
};
/// Harmonic coordinates' grid.
pub const GRID: OptionInfo = OptionInfo {
    name: "grid",
    help: "Grid nodes along the cage's longest side (harmonic coordinates).",
    methods: &[Method::Cage],
};

/// Every option, in the order help lists them.
pub const OPTIONS: [OptionInfo; 9] = [
    BLEND,
    POSITIONAL,
    ITERATIONS,
    ENERGY,
    LOCAL_STEP,
    LATTICE,
    BASIS,
    COORDINATES,
    GRID,
];

/// The names an option takes, for the choices among named values (`None` for numbers, the
/// lattice's `LxMxN` and the `positional` switch).
pub fn option_values(name: &str) -> Option<Vec<&'static str>> {
    use crate::deformers::arap::{ArapEnergy, LocalStep};
    match name {
        "blend" => Some(BlendMethod::names()),
        "energy" => Some(ArapEnergy::names()),
        "local-step" => Some(LocalStep::names()),
        "basis" => Some(LatticeBasis::names()),
        "coordinates" => Some(Coordinates::names()),
        _ => None,
    }
}

/// ARAP iterations per pose the editor runs (from the last pose, once per frame).
pub const ITERATIONS_PER_POSE: RangeInclusive<usize> = 1..=50;
/// Control points per axis of an interactive lattice.
pub const LATTICE_AXIS: RangeInclusive<usize> = 2..=8;
/// At most this many control points in an interactive Bernstein lattice, where every point
/// moves every vertex (B-splines blend at most `(degree + 1)^3` per vertex).
pub const MAX_BERNSTEIN_POINTS: usize = 64;
/// Harmonic grid nodes of an interactive cage.
pub const GRID_NODES: RangeInclusive<usize> = 16..=64;
/// ARAP iterations [`MethodSettings::args`] asks for: the editor iterates a few times per
/// frame from the last frame and comes to rest once the drag stops, where a run from the rest
/// pose needs many (ARAP's energy flattens long before its positions settle).
pub const REPLAY_ARAP_ITERATIONS: usize = 1000;

/// A method and every option it binds by. The interactive limits (the ranges above) are
/// checked by the setters; [`Default`] is handles with the paper's log blend.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MethodSettings {
    /// The method.
    pub method: Method,
    /// How motors are blended (not ARAP's).
    pub blend: BlendMethod,
    /// Lattices and cages: the positional form instead of `blend`.
    pub positional: bool,
    /// ARAP iterations per pose.
    pub iterations: usize,
    /// ARAP's energy, local step and solver.
    pub arap: ArapOptions,
    /// Control points per axis of an FFD lattice.
    pub lattice: [usize; 3],
    /// The lattice's basis.
    pub basis: LatticeBasis,
    /// The cage's coordinates.
    pub coordinates: Coordinates,
    /// Harmonic coordinates' grid nodes along the cage's longest side.
    pub grid: usize,
}

impl Default for MethodSettings {
    fn default() -> Self {
        MethodSettings {
            method: Method::Handles,
            blend: BlendMethod::MotorLog,
            positional: false,
            iterations: 2,
            arap: ArapOptions::default(),
            lattice: [4, 3, 3],
            basis: LatticeBasis::Bernstein,
            coordinates: Coordinates::MeanValue,
            grid: 32,
        }
    }
}

fn in_range(
    option: &'static str,
    value: usize,
    range: &RangeInclusive<usize>,
) -> Result<(), MethodError> {
    if range.contains(&value) {
        return Ok(());
    }
    Err(MethodError::OutOfRange {
        option,
        value: value.to_string(),
        range: format!("{}..={}", range.start(), range.end()),
    })
}

impl MethodSettings {
    /// Choose `method` (the positional form kept only where it applies).
    pub fn set_method(&mut self, method: Method) {
        self.method = method;
        self.positional &= method.controls();
    }

    /// Set the option `name` from its text, as the program and the editor give it: a name
    /// for the choices, a number, `LxMxN` for the lattice, `true`/`false` for `positional`.
    /// Unchanged on an error.
    pub fn set(&mut self, name: &str, value: &str) -> Result<(), MethodError> {
        let number = |option: &'static str| {
            value.parse::<usize>().map_err(|_| MethodError::OutOfRange {
                option,
                value: value.to_string(),
                range: "the whole numbers".into(),
            })
        };
        match name {
            "blend" => self.blend = BlendMethod::from_name(value)?,
            "positional" => match value {
                "true" | "false" => self.set_positional(value == "true")?,
                _ => {
                    return Err(MethodError::UnknownName {
                        what: "positional switch",
                        given: value.to_string(),
                        expected: "true, false".into(),
                    })
                }
            },
            "iterations" => self.set_iterations(number("iterations")?)?,
            "energy" => self.arap.energy = Named::from_name(value)?,
            "local-step" => self.arap.local_step = Named::from_name(value)?,
            "lattice" => {
                let dims: Vec<usize> = value
                    .split('x')
                    .map(|n| n.parse().map_err(|_| ()))
                    .collect::<Result<_, ()>>()
                    .unwrap_or_default();
                let dims: [usize; 3] = dims.try_into().map_err(|_| MethodError::OutOfRange {
                    option: "lattice",
                    value: value.to_string(),
                    range: "LxMxN".into(),
                })?;
                self.set_lattice(dims, self.basis)?
            }
            "basis" => self.set_lattice(self.lattice, Named::from_name(value)?)?,
            "coordinates" => self.coordinates = Named::from_name(value)?,
            "grid" => self.set_grid(number("grid")?)?,
            _ => {
                return Err(MethodError::UnknownName {
                    what: "option",
                    given: name.to_string(),
                    expected: OPTIONS.map(|o| o.name).join(", "),
                })
            }
        }
        Ok(())
    }

    /// The positional form (lattices and cages only).
    pub fn set_positional(&mut self, positional: bool) -> Result<(), MethodError> {
        if positional && !self.method.controls() {
            return Err(MethodError::PositionalWithoutControls {
                method: self.method.name(),
            });
        }
        self.positional = positional;
        Ok(())
    }

    /// ARAP iterations per pose, in [`ITERATIONS_PER_POSE`].
    pub fn set_iterations(&mut self, k: usize) -> Result<(), MethodError> {
        in_range("iterations per pose", k, &ITERATIONS_PER_POSE)?;
        self.iterations = k;
        Ok(())
    }

    /// The lattice and its basis: each axis in [`LATTICE_AXIS`], a Bernstein lattice of at
    /// most [`MAX_BERNSTEIN_POINTS`].
    pub fn set_lattice(
        &mut self,
        dims: [usize; 3],
        basis: LatticeBasis,
    ) -> Result<(), MethodError> {
        for n in dims {
            in_range("control points on a lattice axis", n, &LATTICE_AXIS)?;
        }
        let points: usize = dims.iter().product();
        if basis == LatticeBasis::Bernstein && points > MAX_BERNSTEIN_POINTS {
            return Err(MethodError::BernsteinTooLarge {
                dims,
                points,
                max: MAX_BERNSTEIN_POINTS,
            });
        }
        (self.lattice, self.basis) = (dims, basis);
        Ok(())
    }

    /// Harmonic grid nodes, in [`GRID_NODES`].
    pub fn set_grid(&mut self, nodes: usize) -> Result<(), MethodError> {
        in_range("harmonic grid nodes per side", nodes, &GRID_NODES)?;
        self.grid = nodes;
        Ok(())
    }

    /// The form lattices and cages pose in.
    pub fn form(&self) -> ControlForm {
        if self.positional {
            ControlForm::Positional
        } else {
            ControlForm::Motor(self.blend)
        }
    }

    /// The cage coordinates these settings name.
    pub fn cage_coordinates(&self) -> CageCoordinates {
        match self.coordinates {
            Coordinates::MeanValue => CageCoordinates::MeanValue,
            Coordinates::Harmonic => CageCoordinates::Harmonic(HarmonicGrid {
                resolution: self.grid,
            }),
        }
    }

    /// Whether going from `self` to `next` needs the weights bound again; `false` where only
    /// the blend changed (or an option the method does not use).
    pub fn rebinds_for(&self, next: &MethodSettings) -> bool {
        let m = next.method;
        m != self.method
            || next.positional != self.positional
            || m == Method::Arap && (next.iterations != self.iterations || next.arap != self.arap)
            || m == Method::Ffd && (next.lattice, next.basis) != (self.lattice, self.basis)
            || m == Method::Cage && (next.coordinates, next.grid) != (self.coordinates, self.grid)
    }

    /// The program's flags that bind this method the same way (the subcommand is
    /// [`Method`]'s name), each option printed by its name from [`OPTIONS`]. ARAP asks for
    /// [`REPLAY_ARAP_ITERATIONS`]; options at their defaults are printed too, except a lattice's
    /// Bernstein basis and a cage's mean value coordinates.
    pub fn args(&self) -> Vec<String> {
        let mut a: Vec<String> = Vec::new();
        let mut flag = |o: OptionInfo, v: String| {
            a.push(format!("--{}", o.name));
            if !v.is_empty() {
                a.push(v);
            }
        };
        match self.method {
            Method::Arap => {
                flag(ENERGY, self.arap.energy.name().into());
                flag(LOCAL_STEP, self.arap.local_step.name().into());
                flag(ITERATIONS, REPLAY_ARAP_ITERATIONS.to_string());
            }
            Method::Ffd => {
                let [l, m, n] = self.lattice;
                flag(LATTICE, format!("{l}x{m}x{n}"));
                if self.basis != LatticeBasis::Bernstein {
                    flag(BASIS, Named::name(self.basis).into());
                }
            }
            Method::Cage => {
                if self.coordinates != Coordinates::MeanValue {
                    flag(COORDINATES, self.coordinates.name().into());
                    flag(GRID, self.grid.to_string());
                }
            }
            Method::Handles | Method::Spline => {}
        }
        if self.positional {
            flag(POSITIONAL, String::new());
        } else if self.method.blends() {
            flag(BLEND, self.blend.name().into());
        }
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_option_name_is_set_by_name() {
        let mut s = MethodSettings {
            method: Method::Cage,
            ..MethodSettings::default()
        };
        for (name, value) in [
            ("blend", "dual-quaternion"),
            ("positional", "true"),
            ("iterations", "7"),
            ("energy", "spokes"),
            ("local-step", "svd"),
            ("lattice", "3x3x3"),
            ("basis", "bspline-2"),
            ("coordinates", "harmonic"),
            ("grid", "20"),
        ] {
            s.set(name, value).unwrap();
        }
        assert_eq!(OPTIONS.len(), 9);
        assert_eq!(s.blend, BlendMethod::DualQuaternion);
        assert!(s.positional);
        assert_eq!((s.iterations, s.grid, s.lattice), (7, 20, [3, 3, 3]));
        assert_eq!(s.basis, LatticeBasis::BSpline(2));
        assert_eq!(s.coordinates, Coordinates::Harmonic);
    }

    #[test]
    fn bad_values_leave_the_settings_as_they_were() {
        let s0 = MethodSettings::default();
        let mut s = s0;
        for (name, value) in [
            ("iterations", "0"),
            ("iterations", "51"),
            ("lattice", "9x2x2"),
            ("lattice", "2x2"),
            ("lattice", "5x5x5"),
            ("grid", "8"),
            ("energy", "rims"),
            ("positional", "true"),
            ("positional", "yes"),
            ("no-such-option", "1"),
        ] {
            assert!(s.set(name, value).is_err(), "{name} {value}");
            assert_eq!(s, s0);
        }
        // A B-spline basis takes the 125 points a Bernstein lattice may not.
        s.set("basis", "bspline-3").unwrap();
        s.set("lattice", "5x5x5").unwrap();
    }

    #[test]
    fn only_options_the_method_uses_rebind() {
        let s = MethodSettings::default();
        let mut blend = s;
        blend.blend = BlendMethod::Matrix;
        assert!(!s.rebinds_for(&blend));
        let mut energy = s;
        energy.arap.energy = crate::deformers::arap::ArapEnergy::Spokes;
        assert!(!s.rebinds_for(&energy), "handles do not use ARAP's energy");
        energy.method = Method::Arap;
        assert!(s.rebinds_for(&energy));
    }
}
