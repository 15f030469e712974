//! The checks of a large construction summed up: per kind of check (its quantity and unit)
//! how many were made, how many failed and the worst of them, and every failed check.
//!
//! A 100,000-load beam makes 300,000 checks and a 100,000-joint girder 200,000: a table of
//! every one is some 45 MB that nobody reads, and keeping them took more memory than the
//! scene. A board that keeps only its checks ([`Mode::Checks`](super::Mode::Checks)) files
//! each check here as it is made; it keeps the checks themselves only while there are at
//! most [`LISTED_CHECKS`] (what the check table then lists row by row, as before) or when
//! every one was asked for (its `every`, `check --all`). Every
//! check is still made and counted: a failure is never summed away, it is kept whole, the
//! first [`LISTED_FAILURES`] of them.
//!
//! ```
//! use graphostatik::prelude::*;
//! use graphostatik::protocol::{BoardConfig, LISTED_CHECKS};
//! let mut b = Board::new(BoardConfig::CHECKS);
//! let n = Note::new("lengths", Topic::Custom("demo"));
//! let o = b.point(Point::new(0.0, 0.0), Role::Given.named("O"), n.clone());
//! for i in 1..=LISTED_CHECKS + 1 {
//!     let a = b.point(Point::new(3.0 * i as f64, 4.0 * i as f64), Role::Given, n.clone());
//!     let x = b.line_through(&o, &a, Role::Construction, n.clone())?;
//!     let d = b.measure(&o, &a, &x, Scale::new(1.0, "mm"), Label::NONE, n.clone());
//!     b.check(&d, "OA", "mm", "Pythagoras", 5.0, || 5.0 * i as f64);
//! }
//! let s = b.check_summary().expect("more checks than are listed");
//! assert_eq!((s.total, s.failed, s.kinds.len()), (LISTED_CHECKS as u64 + 1, 0, 1));
//! assert_eq!(s.kinds[0].count, LISTED_CHECKS as u64 + 1);
//! assert!(b.all_passed());
//! # Ok::<(), ConstructionError>(())
//! ```

use super::step::{Check, StepId, Text};

/// A board that keeps only its checks keeps each of them while it has made at most this many;
/// past it, their [`CheckSummary`] (a row per kind of check, and every failure).
pub const LISTED_CHECKS: usize = 1_000;

/// The failed checks a summary keeps whole; the rest are counted.
pub const LISTED_FAILURES: usize = 1_000;

/// The checks of one kind: one quantity in one unit ("member force (tension +)", kg).
#[derive(Debug, Clone, PartialEq)]
pub struct CheckKind {
    /// The quantity.
    pub quantity: Text,
    /// Its unit.
    pub unit: Text,
    /// How many checks of this kind were made.
    pub count: u64,
    /// How many of them failed.
    pub failed: u64,
    /// How many depend on a glancing cut.
    pub glancing: u64,
    /// The step of the first check of this kind (the kinds are listed in its order).
    pub first_step: StepId,
    /// The step of the worst check.
    pub worst_step: StepId,
    /// The worst check: the largest error against its tolerance (the earliest of equals).
    pub worst: Check,
}

/// Every check of a board counted, per kind, with the worst of each kind and every failure
/// (up to [`LISTED_FAILURES`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CheckSummary {
    /// Checks made.
    pub total: u64,
    /// Checks failed.
    pub failed: u64,
    /// Checks depending on a glancing cut.
    pub glancing: u64,
    /// Checks not failed whose bound exceeds their tolerance ([`Check::judged`]).
    pub unjudged: u64,
    /// One per kind, in the order of their first steps.
    pub kinds: Vec<CheckKind>,
    /// The first [`LISTED_FAILURES`] failed checks with their steps, in the order filed.
    pub failures: Vec<(StepId, Check)>,
}

/// How far a check is from failing: its error against its tolerance (1 is the limit).
fn badness(c: &Check) -> f64 {
    if c.tolerance > 0.0 {
        c.error / c.tolerance
    } else if c.error == 0.0 {
        0.0
    } else {
        f64::INFINITY
    }
}

/// Whether `a` (made at step `sa`) is worse than `b` (at `sb`): larger badness, and for
/// equals the earlier step.
fn worse(a: &Check, sa: StepId, b: &Check, sb: StepId) -> bool {
    match badness(a).total_cmp(&badness(b)) {
        std::cmp::Ordering::Equal => sa < sb,
        o => o.is_gt(),
    }
}

impl CheckSummary {
    /// Counts a check made at `step`.
    pub(crate) fn add(&mut self, step: StepId, c: &Check) {
        self.total += 1;
        self.failed += u64::from(!c.passed);
        self.unjudged += u64::from(c.passed && !c.judged());
        let glancing = u64::from(c.glancing());
        self.glancing += glancing;
        if !c.passed && self.failures.len() < LISTED_FAILURES {
            self.failures.push((step, c.clone()));
        }
        let kind = self
            .kinds
            .iter()
            .rposition(|k| k.quantity == c.quantity && k.unit == c.unit);
        let Some(i) = kind else {
            let at = self.kinds.partition_point(|k| k.first_step <= step);
            self.kinds.insert(
                at,
                CheckKind {
                    quantity: c.quantity.clone(),
                    unit: c.unit.clone(),
                    count: 1,
                    failed: u64::from(!c.passed),
                    glancing,
                    first_step: step,
                    worst_step: step,
                    worst: c.clone(),
                },
            );
            return;
        };
        let k = &mut self.kinds[i];
        k.count += 1;
        k.failed += u64::from(!c.passed);
        k.glancing += glancing;
        if worse(c, step, &k.worst, k.worst_step) {
            k.worst_step = step;
            k.worst = c.clone();
        }
        // Checks are filed in the order made, not always in step order: a kind whose first
        // step moves earlier moves up the list.
        if step < k.first_step {
            let mut k = self.kinds.remove(i);
            k.first_step = step;
            let at = self.kinds.partition_point(|o| o.first_step <= step);
            self.kinds.insert(at, k);
        }
    }

    /// Failed checks counted but not kept whole.
    pub fn failures_not_listed(&self) -> u64 {
        self.failed - self.failures.len() as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::borrow::Cow;

    fn check(quantity: &'static str, error: f64, passed: bool) -> Check {
        Check {
            object: None,
            quantity: Cow::Borrowed(quantity),
            unit: Cow::Borrowed("kg"),
            constructed: 1.0 + error,
            closed_form: 1.0,
            formula: Cow::Borrowed("test"),
            error,
            tolerance: 1e-6,
            reference: 1.0,
            passed,
            bound: 1e-15,
            worst_cut: None,
        }
    }

    #[test]
    fn kinds_keep_their_worst_and_every_failure() {
        let mut s = CheckSummary::default();
        s.add(StepId(9), &check("moment", 1e-9, true));
        s.add(StepId(3), &check("reaction", 0.0, true));
        s.add(StepId(12), &check("moment", 2e-9, true));
        s.add(StepId(15), &check("moment", 2e-9, true));
        s.add(StepId(20), &check("moment", 1e-3, false));
        s.add(StepId(21), &check("reaction", 0.0, true));
        assert_eq!((s.total, s.failed), (6, 1));
        // In the order of their first steps, whatever the order filed.
        let names: Vec<&str> = s.kinds.iter().map(|k| &*k.quantity).collect();
        assert_eq!(names, ["reaction", "moment"]);
        assert_eq!((s.kinds[1].count, s.kinds[1].failed), (4, 1));
        assert_eq!(s.kinds[1].worst_step, StepId(20));
        // Of equals, the earliest.
        assert_eq!(s.kinds[0].worst_step, StepId(3));
        assert_eq!(s.failures.len(), 1);
        assert_eq!(s.failures_not_listed(), 0);
        let mut t = CheckSummary::default();
        t.add(StepId(1), &check("moment", 1e-9, true));
        t.add(StepId(2), &check("moment", 3e-9, true));
        t.add(StepId(3), &check("moment", 3e-9, true));
        assert_eq!(t.kinds[0].worst_step, StepId(2));
        // A kind filed late for an earlier step moves ahead of the kinds it now precedes.
        let mut u = CheckSummary::default();
        u.add(StepId(5), &check("reaction", 0.0, true));
        u.add(StepId(8), &check("moment", 0.0, true));
        u.add(StepId(2), &check("moment", 0.0, true));
        let names: Vec<&str> = u.kinds.iter().map(|k| &*k.quantity).collect();
        assert_eq!(names, ["moment", "reaction"]);
        assert_eq!(u.kinds[0].first_step, StepId(2));
    }

    #[test]
    fn failures_past_the_limit_are_counted() {
        let mut s = CheckSummary::default();
        for i in 0..LISTED_FAILURES + 7 {
            s.add(StepId(i as u32 + 1), &check("moment", 1.0, false));
        }
        assert_eq!(s.failures.len(), LISTED_FAILURES);
        assert_eq!(s.failures_not_listed(), 7);
        assert_eq!(s.kinds[0].failed, LISTED_FAILURES as u64 + 7);
    }
}
