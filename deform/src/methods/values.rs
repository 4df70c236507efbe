//! The values a method binds by besides the method itself: the blend, the positional form
//! and each option's value by name (its default where none was set). What a method's file
//! reads ([`super::MethodKind::bind`]); [`super::MethodSettings`] holds it with the method and
//! checks every value it takes.

use super::named::Named;
use super::option::{OptionSpec, OptionValue};
use crate::blend::control::ControlForm;
use crate::blend::BlendMethod;
use std::collections::BTreeMap;

/// The blend, the positional form and the options' values. [`Default`]: the paper's log
/// blend, no option set.
#[derive(Clone, Debug, PartialEq)]
pub struct OptionValues {
    /// How motors are blended (not ARAP's).
    pub blend: BlendMethod,
    /// Lattices and cages: the positional form instead of `blend`.
    pub positional: bool,
    /// The options set, by name (any method's: they are kept when the method changes).
    values: BTreeMap<&'static str, OptionValue>,
}

impl Default for OptionValues {
    fn default() -> Self {
        OptionValues {
            blend: BlendMethod::MotorLog,
            positional: false,
            values: BTreeMap::new(),
        }
    }
}

impl OptionValues {
    /// Take `value` for the option `name` (checked by the caller).
    pub(super) fn insert(&mut self, name: &'static str, value: OptionValue) {
        self.values.insert(name, value);
    }

    /// The value of `option` (its default where none was set).
    pub fn value(&self, option: &OptionSpec) -> OptionValue {
        self.values
            .get(option.name)
            .copied()
            .unwrap_or(option.default)
    }

    /// The choice `option` names, as its type `T`.
    pub fn choice<T: Named>(&self, option: &OptionSpec) -> T {
        let named = |v: OptionValue| match v {
            OptionValue::Name(n) => T::from_name(n).ok(),
            _ => None,
        };
        named(self.value(option))
            .or_else(|| named(option.default))
            .unwrap_or(T::ALL[0])
    }

    /// The number `option` holds.
    pub fn number(&self, option: &OptionSpec) -> usize {
        match (self.value(option), option.default) {
            (OptionValue::Number(n), _) | (_, OptionValue::Number(n)) => n,
            _ => 0,
        }
    }

    /// The points per axis `option` holds.
    pub fn dims(&self, option: &OptionSpec) -> [usize; 3] {
        match (self.value(option), option.default) {
            (OptionValue::Dims(d), _) | (_, OptionValue::Dims(d)) => d,
            _ => [0; 3],
        }
    }

    /// The form lattices and cages pose in.
    pub fn form(&self) -> ControlForm {
        if self.positional {
            ControlForm::Positional
        } else {
            ControlForm::Motor(self.blend)
        }
    }
}
