//! Benchmarks (criterion, in `benches/benches/`) and the quick bench report binary
//! (`cargo run --release -p benches --bin bench-report`).
pub mod cga_report;
pub mod codegen_report;
pub use devkit::grade;
pub mod peer_ops_set;
pub mod peer_ops_unary;
pub mod timing;

#[cfg(test)]
mod tests {
    use crate::grade::{Spread, Target, Verdict};

    #[test]
    fn grades_by_value_and_qualifies_by_the_worst_run() {
        let s = Spread {
            value: 0.4,
            low: 0.3,
            high: 0.6,
        };
        assert_eq!(Target::Below(0.5).grade(s), Verdict::MetNotEveryRun);
        assert_eq!(Target::Below(0.7).grade(s), Verdict::Met);
        assert_eq!(Target::Below(0.35).grade(s), Verdict::Missed);
        assert_eq!(Target::AtLeast(0.35).grade(s), Verdict::MetNotEveryRun);
        assert_eq!(
            Target::AtMost(0.4).grade(Spread::exact(f64::NAN)),
            Verdict::Missed
        );
    }
}
