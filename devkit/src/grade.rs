//! Targets that grade themselves: each quick report prints, for every row that has a target, the
//! target, `met` or `MISSED`, and the spread of the runs behind the figure, then a tally.
//!
//! Shared by the `benches` crate's `bench-report` and the `deform` examples.

use std::fmt;

/// Repeated measurements of one quantity: the figure reported (`value`, a median or a best run)
/// and the range the runs spanned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    /// The figure the report uses and grades.
    pub value: f64,
    /// The lowest run.
    pub low: f64,
    /// The highest run.
    pub high: f64,
}

impl Spread {
    /// The median of `samples` with their minimum and maximum; NaN when there are none.
    pub fn median_of(samples: &mut [f64]) -> Spread {
        samples.sort_by(f64::total_cmp);
        match samples {
            [] => Spread::exact(f64::NAN),
            s => Spread {
                value: s[s.len() / 2],
                low: s[0],
                high: s[s.len() - 1],
            },
        }
    }

    /// The lowest of `samples` (the usual figure for short loops) with the range of all.
    pub fn best_of(samples: &mut [f64]) -> Spread {
        let s = Spread::median_of(samples);
        Spread { value: s.low, ..s }
    }

    /// One exact figure (a count, a size): no spread.
    pub fn exact(value: f64) -> Spread {
        Spread {
            value,
            low: value,
            high: value,
        }
    }

    /// Every figure multiplied by `k > 0` (unit changes, per-item figures).
    pub fn scale(self, k: f64) -> Spread {
        Spread {
            value: self.value * k,
            low: self.low * k,
            high: self.high * k,
        }
    }

    /// `self / base` for two positive quantities measured in the same run: the ratio of the
    /// values, and the extreme ratios the runs allow (`low / base.high`, `high / base.low`).
    pub fn ratio(self, base: Spread) -> Spread {
        Spread {
            value: self.value / base.value,
            low: self.low / base.high,
            high: self.high / base.low,
        }
    }

    /// `base / self`: how many times faster than `base` this is, with its extremes.
    pub fn speedup_over(self, base: Spread) -> Spread {
        base.ratio(self)
    }
}

/// Digits after the point that keep about four significant figures.
fn decimals(x: f64) -> usize {
    match x.abs() {
        a if a >= 1000.0 => 0,
        a if a >= 100.0 => 1,
        a if a >= 10.0 => 2,
        _ => 3,
    }
}

impl fmt::Display for Spread {
    /// `value [low, high]`, or `value` alone when the runs did not vary.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let d = decimals(self.value);
        if self.low == self.high {
            write!(f, "{:.*}", d, self.value)
        } else {
            write!(
                f,
                "{:.*} [{:.*}, {:.*}]",
                d, self.value, d, self.low, d, self.high
            )
        }
    }
}

/// What a figure must reach, in the unit the report prints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Target {
    /// Strictly below.
    Below(f64),
    /// At most.
    AtMost(f64),
    /// At least (speedups).
    AtLeast(f64),
}

/// How a figure fared against its target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The figure and every run reach the target.
    Met,
    /// The figure reaches the target, but the worst run did not.
    MetNotEveryRun,
    /// The figure does not reach the target.
    Missed,
}

impl Target {
    /// Whether `x` reaches the target (NaN never does).
    pub fn reached_by(self, x: f64) -> bool {
        match self {
            Target::Below(t) => x < t,
            Target::AtMost(t) => x <= t,
            Target::AtLeast(t) => x >= t,
        }
    }

    /// Grades `s`: its value decides, its worst run qualifies.
    pub fn grade(self, s: Spread) -> Verdict {
        let worst = match self {
            Target::Below(_) | Target::AtMost(_) => s.high,
            Target::AtLeast(_) => s.low,
        };
        match (self.reached_by(s.value), self.reached_by(worst)) {
            (false, _) => Verdict::Missed,
            (true, false) => Verdict::MetNotEveryRun,
            (true, true) => Verdict::Met,
        }
    }
}

impl fmt::Display for Target {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Target::Below(t) => write!(f, "< {t}"),
            Target::AtMost(t) => write!(f, "<= {t}"),
            Target::AtLeast(t) => write!(f, ">= {t}"),
        }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Verdict::Met => "met",
            Verdict::MetNotEveryRun => "met (not in every run)",
            Verdict::Missed => "MISSED",
        })
    }
}

/// The verdicts of one report, for the closing tally.
#[derive(Debug, Default)]
pub struct Tally {
    met: usize,
    missed: Vec<String>,
}

impl Tally {
    /// One graded row: `label  value [low, high] unit  target <= t unit: met`. Rows without a
    /// target print the figure alone and are not counted.
    pub fn row(&mut self, label: &str, s: Spread, unit: &str, target: Option<Target>) -> String {
        let figure = format!("{s} {unit}");
        match target {
            None => format!("{label:<48} {figure}"),
            Some(t) => {
                let v = t.grade(s);
                match v {
                    Verdict::Missed => self.missed.push(label.trim().to_string()),
                    _ => self.met += 1,
                }
                format!("{label:<48} {figure:<34} target {t} {unit}: {v}")
            }
        }
    }

    /// `targets: N met, M MISSED (which)`.
    pub fn summary(&self) -> String {
        if self.missed.is_empty() {
            format!("targets: {} met, 0 MISSED", self.met)
        } else {
            format!(
                "targets: {} met, {} MISSED ({})",
                self.met,
                self.missed.len(),
                self.missed.join("; ")
            )
        }
    }

    /// How many rows missed their target.
    pub fn missed(&self) -> usize {
        self.missed.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spreads_take_the_median_or_the_best_run_with_the_range() {
        let s = Spread::median_of(&mut [3.0, 1.0, 2.0]);
        assert_eq!((s.value, s.low, s.high), (2.0, 1.0, 3.0));
        assert_eq!(Spread::best_of(&mut [3.0, 1.0, 2.0]).value, 1.0);
        assert!(Spread::median_of(&mut []).value.is_nan());
        let r = Spread::exact(4.0).ratio(Spread::median_of(&mut [1.0, 2.0, 4.0]));
        assert_eq!((r.value, r.low, r.high), (2.0, 1.0, 4.0));
        assert_eq!(format!("{}", Spread::exact(1.5)), "1.500");
        assert_eq!(format!("{s}"), "2.000 [1.000, 3.000]");
    }

    #[test]
    fn the_tally_counts_met_and_names_missed_rows() {
        let mut t = Tally::default();
        t.row("fast", Spread::exact(1.0), "ms", Some(Target::Below(2.0)));
        t.row("slow", Spread::exact(3.0), "ms", Some(Target::AtMost(2.0)));
        t.row("untargeted", Spread::exact(3.0), "ms", None);
        assert_eq!(t.missed(), 1);
        assert_eq!(t.summary(), "targets: 1 met, 1 MISSED (slow)");
    }
}
