//! The summary of a generated module: its types, then its product table (geometric products
//! and sandwiches, with result types and term counts), what was not emitted for want of a type
//! holding the result (large algebras only), then the closed-form exp/log impls, as printed by
//! `ga-codegen --summary`.

use super::{Generated, Op};
use std::fmt::Write;

impl Generated {
    /// A human-readable summary: types, then the product table.
    pub fn summary(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "types ({}):", self.types.len());
        for (n, f) in &self.types {
            let _ = writeln!(s, "  {n:<16} {f} fields");
        }
        let total: usize = self.ops.iter().map(|o| o.terms).sum();
        let _ = writeln!(
            s,
            "operations: {} emitted ({} multiply terms), {} identically zero and skipped",
            self.ops.len(),
            total,
            self.zero_ops
        );
        for o in self
            .ops
            .iter()
            .filter(|o| matches!(o.op, Op::Geometric | Op::Sandwich))
        {
            let form = o
                .matrix_form
                .map(|n| format!(" (matrix form: {n} multiplies)"))
                .unwrap_or_default();
            let _ = writeln!(
                s,
                "  {:<12} {:<9} {:<12} -> {:<12} {:>5} terms{form}",
                o.left,
                o.op.symbol(),
                o.right,
                o.output,
                o.terms
            );
        }
        if !self.skipped.is_empty() {
            let _ = writeln!(
                s,
                "not emitted ({}): no declared type holds the result (no general multivector \
                 above {} basis vectors)",
                self.skipped.len(),
                crate::generator::spec::MAX_GENERAL_DIMENSION
            );
            for x in &self.skipped {
                let _ = writeln!(s, "  {x}");
            }
        }
        let _ = writeln!(
            s,
            "closed forms ({}): exp, log, sqrt, normalize",
            self.closed_forms.len()
        );
        for c in &self.closed_forms {
            let _ = writeln!(s, "  {c}");
        }
        let _ = writeln!(s, "lines of code: {}", self.lines());
        s
    }
}
