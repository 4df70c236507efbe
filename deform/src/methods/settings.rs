//! A method with every option it binds by, each option described once ([`OptionSpec`]): the
//! blend and the positional form here, every other in its method's file
//! ([`super::MethodKind::options`]). The program's flags are `--` and the name, the editor's
//! messages carry the same names, and [`MethodSettings::args`] prints the flags that bind the
//! same way (the editor's replay command).

use super::error::MethodError;
use super::method::Method;
use super::named::Named;
use super::option::{OptionKind, OptionSpec, OptionValue};
use super::values::OptionValues;
use crate::blend::BlendMethod;

/// How key motors are blended ([`BlendMethod`]'s names; methods that blend).
pub const BLEND: OptionSpec = OptionSpec {
    name: "blend",
    help: "How the key motors are blended.",
    kind: OptionKind::choice::<BlendMethod>(),
    default: OptionValue::Name("motor-log"),
    replay: None,
};
/// Lattices and cages: the classic positional form instead of blended motors.
pub const POSITIONAL: OptionSpec = OptionSpec {
    name: "positional",
    help: "Classic positional form: each control point moves by its motor, vertices follow the \
           weighted sum of the points.",
    kind: OptionKind::Switch,
    default: OptionValue::Switch(false),
    replay: None,
};

/// One option and the methods it applies to.
#[derive(Clone, Debug)]
pub struct OptionInfo {
    /// The option.
    pub spec: &'static OptionSpec,
    /// The methods it applies to.
    pub methods: Vec<Method>,
}

/// Every option: the blend, the positional form, then each method's own in [`Named::ALL`]'s
/// order (an option two methods share is listed once, with both).
pub fn all_options() -> Vec<OptionInfo> {
    let methods = |f: fn(Method) -> bool| Method::ALL.iter().copied().filter(|m| f(*m)).collect();
    let mut all = vec![
        OptionInfo {
            spec: &BLEND,
            methods: methods(Method::blends),
        },
        OptionInfo {
            spec: &POSITIONAL,
            methods: methods(Method::controls),
        },
    ];
    for &m in Method::ALL {
        for spec in m.options() {
            match all.iter_mut().find(|o| o.spec.name == spec.name) {
                Some(o) => o.methods.push(m),
                None => all.push(OptionInfo {
                    spec,
                    methods: vec![m],
                }),
            }
        }
    }
    all
}

/// The option of some method named `name` (not the blend or the positional form).
fn method_option(name: &str) -> Option<&'static OptionSpec> {
    Method::ALL
        .iter()
        .flat_map(|m| m.options())
        .find(|o| o.name == name)
}

/// A method and every value it binds by ([`OptionValues`], which it derefs to: `blend`,
/// `positional`, each option's value). Each value is checked when it is set, alone by its
/// [`OptionSpec`] and together by its method's [`super::MethodKind::check`]; an option not
/// set has its default. [`Default`] is handles with the paper's log blend.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MethodSettings {
    /// The method.
    pub method: Method,
    /// Its blend, positional form and options' values.
    pub values: OptionValues,
}

impl std::ops::Deref for MethodSettings {
    type Target = OptionValues;
    fn deref(&self) -> &OptionValues {
        &self.values
    }
}

impl std::ops::DerefMut for MethodSettings {
    fn deref_mut(&mut self) -> &mut OptionValues {
        &mut self.values
    }
}

impl MethodSettings {
    /// Choose `method` (the positional form kept only where it applies).
    pub fn set_method(&mut self, method: Method) {
        self.method = method;
        self.positional &= method.controls();
    }

    /// Set the option `name` from its text, as the program and the editor give it: a name
    /// for the choices, a number, `LxMxN` for a lattice, `true`/`false` for `positional`.
    /// Unchanged on an error.
    pub fn set(&mut self, name: &str, value: &str) -> Result<(), MethodError> {
        self.set_all(&[(name, value)])
    }

    /// Set several options at once, checked together (a lattice's size and basis):
    /// unchanged when any is refused.
    pub fn set_all(&mut self, options: &[(&str, &str)]) -> Result<(), MethodError> {
        let mut next = self.clone();
        for &(name, text) in options {
            match name {
                "blend" => next.blend = BlendMethod::from_name(text)?,
                "positional" => match POSITIONAL.parse(text)? {
                    OptionValue::Switch(on) => next.set_positional(on)?,
                    _ => unreachable!("a switch parses to a switch"),
                },
                _ => {
                    let spec = method_option(name).ok_or_else(|| MethodError::UnknownName {
                        what: "option",
                        given: name.to_string(),
                        expected: all_options()
                            .iter()
                            .map(|o| o.spec.name)
                            .collect::<Vec<_>>()
                            .join(", "),
                    })?;
                    next.values.insert(spec.name, spec.parse(text)?);
                }
            }
        }
        for &m in Method::ALL {
            if m.options()
                .iter()
                .any(|o| options.iter().any(|(n, _)| *n == o.name))
            {
                m.kind().check(&next.values)?;
            }
        }
        *self = next;
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

    /// Every option of every method with its value, in [`all_options`]' order (the blend and
    /// the positional form left out: they are fields).
    pub fn values(&self) -> Vec<(&'static str, OptionValue)> {
        let own = all_options().into_iter().skip(2);
        own.map(|o| (o.spec.name, self.value(o.spec))).collect()
    }

    /// Whether going from `self` to `next` needs the weights bound again; `false` where only
    /// the blend changed (or an option the method does not use).
    pub fn rebinds_for(&self, next: &MethodSettings) -> bool {
        let m = next.method;
        m != self.method
            || next.positional != self.positional
            || m.options().iter().any(|o| next.value(o) != self.value(o))
    }

    /// The program's flags that bind this method the same way (after
    /// [`Method::command`] and the files): every option of the method by its name and value (its
    /// [`OptionSpec::replay`] value where it has one), then the positional form or the blend.
    pub fn args(&self) -> Vec<String> {
        let mut a: Vec<String> = Vec::new();
        for o in self.method.options() {
            let value = o.replay.unwrap_or(self.value(o));
            a.push(format!("--{}", o.name));
            a.push(value.to_string());
        }
        if self.positional {
            a.push(format!("--{}", POSITIONAL.name));
        } else if self.method.blends() {
            a.push(format!("--{}", BLEND.name));
            a.push(self.blend.name().into());
        }
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deformers::arap::{ArapEnergy, ArapOptions, LocalStep};
    use crate::deformers::ffd::LatticeBasis;
    use crate::methods::kinds::{arap, cage, ffd};
    use crate::methods::named::Coordinates;

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
        assert_eq!(all_options().len(), 11);
        assert_eq!(s.blend, BlendMethod::DualQuaternion);
        assert!(s.positional);
        let (iterations, grid) = (s.number(&arap::ITERATIONS), s.number(&cage::GRID));
        assert_eq!(
            (iterations, grid, s.dims(&ffd::LATTICE)),
            (7, 20, [3, 3, 3])
        );
        assert_eq!(
            s.choice::<LatticeBasis>(&ffd::BASIS),
            LatticeBasis::BSpline(2)
        );
        assert_eq!(
            s.choice::<Coordinates>(&cage::COORDINATES),
            Coordinates::Harmonic
        );
        assert_eq!(s.choice::<ArapEnergy>(&arap::ENERGY), ArapEnergy::Spokes);
        assert_eq!(s.choice::<LocalStep>(&arap::LOCAL_STEP), LocalStep::Svd);
    }

    #[test]
    fn every_default_is_a_value_its_option_takes() {
        for o in all_options() {
            let d = o.spec.default;
            assert_eq!(o.spec.parse(&d.to_string()).unwrap(), d, "{}", o.spec.name);
            assert!(!o.methods.is_empty(), "{}", o.spec.name);
        }
        // The defaults are the library's own.
        let s = MethodSettings::default();
        let library = ArapOptions::default();
        assert_eq!(s.choice::<ArapEnergy>(&arap::ENERGY), library.energy);
        assert_eq!(s.choice::<LocalStep>(&arap::LOCAL_STEP), library.local_step);
        assert_eq!(
            BlendMethod::from_name(&BLEND.default.to_string()).unwrap(),
            s.blend
        );
    }

    #[test]
    fn bad_values_leave_the_settings_as_they_were() {
        let s0 = MethodSettings::default();
        let mut s = s0.clone();
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
        // A B-spline basis takes the 125 points a Bernstein lattice may not, set together or
        // one after the other; back to Bernstein is refused.
        s.set_all(&[("lattice", "5x5x5"), ("basis", "bspline-3")])
            .unwrap();
        let s1 = s.clone();
        assert!(s.set("basis", "bernstein").is_err());
        assert_eq!(s, s1);
        s.set("lattice", "4x4x4").unwrap();
        s.set("basis", "bernstein").unwrap();
    }

    #[test]
    fn only_options_the_method_uses_rebind() {
        let s = MethodSettings::default();
        let mut blend = s.clone();
        blend.blend = BlendMethod::Matrix;
        assert!(!s.rebinds_for(&blend));
        let mut energy = s.clone();
        energy.set("energy", "spokes").unwrap();
        assert!(!s.rebinds_for(&energy), "handles do not use ARAP's energy");
        energy.method = Method::Arap;
        assert!(s.rebinds_for(&energy));
    }

    #[test]
    fn args_print_every_option_of_the_method() {
        let mut s = MethodSettings::default();
        s.set_method(Method::Ffd);
        s.set("lattice", "5x3x2").unwrap();
        assert_eq!(
            s.args().join(" "),
            "--lattice 5x3x2 --basis bernstein --blend motor-log"
        );
        s.set_method(Method::Arap);
        let replayed = "--iterations 1000 --energy spokes-and-rims --local-step rotor";
        assert_eq!(s.args().join(" "), replayed);
        s.set_method(Method::Cage);
        s.set_positional(true).unwrap();
        assert_eq!(
            s.args().join(" "),
            "--coordinates mean-value --grid 32 --positional"
        );
    }
}
