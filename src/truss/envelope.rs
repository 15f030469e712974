//! Sums of load cases and the envelope of member forces (LH B.5, Aufgabe 4 "Gesamtbelastung",
//! Aufgabe 5 "maximale Stabbelastung", T6).
//!
//! The envelope of a member is the range of its force (most tension, most compression) under every
//! admissible combination of the load cases. A rule names the **permanent** cases (always
//! present: dead load) and **groups of exclusive** cases (wind from the left or from the
//! right; the positions of one moving load): from each group at most one case acts, and only
//! if it makes the extreme worse. Every case in neither list is a group of its own.
//! Without a rule, each case is taken alone.

use super::cremona::CaseResult;
use crate::kernel::Vector;
use serde::Serialize;

/// A named sum of load cases.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Combination {
    /// Its name ("total").
    pub name: String,
    /// Indices of the cases added.
    pub cases: Vec<usize>,
}

impl Combination {
    /// The force of member `m` under the sum (kg).
    pub fn force(&self, results: &[CaseResult], m: usize) -> f64 {
        self.cases
            .iter()
            .map(|&i| results[i].members[m].force)
            .sum()
    }

    /// The reaction of support `k` under the sum (kg, x and y).
    pub fn reaction(&self, results: &[CaseResult], k: usize) -> Vector {
        self.cases.iter().fold(Vector::zeros(), |acc, &i| {
            let f = results[i].reactions[k].force;
            Vector::new(acc.x + f.x, acc.y + f.y)
        })
    }
}

/// Which cases are permanent and which exclude each other (indices into the cases).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct EnvelopeRule {
    /// Cases always present.
    pub permanent: Vec<usize>,
    /// Groups of which at most one case acts at a time.
    pub exclusive: Vec<Vec<usize>>,
}

/// The extremes of one member.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Extremes {
    /// Member name.
    pub member: String,
    /// The largest force (kg: the most tension, or with permanent loads the least
    /// compression) and the cases that give it ("-" for none).
    pub max: (f64, String),
    /// The smallest force (kg: the most compression) and the cases that give it.
    pub min: (f64, String),
}

/// The envelope of every member under `rule` (or each case alone).
///
/// ```
/// use graphostatik::truss::envelope::*;
/// use graphostatik::truss::cremona::CaseResult;
/// use graphostatik::truss::MemberForce;
/// let case = |name: &str, f: f64| CaseResult { case: name.into(), reactions: vec![],
///     members: vec![MemberForce { member: "1".into(), plan_mm: 0.0, force: f, matrix: None }],
///     plan_residual: 0.0, matrix_residual: None };
/// let r = [case("dead", 100.0), case("wind left", -300.0), case("wind right", 50.0)];
/// let rule = EnvelopeRule { permanent: vec![0], exclusive: vec![vec![1, 2]] };
/// let e = &envelope(&r, Some(&rule))[0];
/// assert_eq!(e.max.0, 150.0); // dead + wind right
/// assert_eq!(e.min.0, -200.0); // dead + wind left
/// ```
pub fn envelope(results: &[CaseResult], rule: Option<&EnvelopeRule>) -> Vec<Extremes> {
    let n = results.first().map_or(0, |r| r.members.len());
    let single;
    let rule = match rule {
        Some(r) => r,
        None => {
            single = EnvelopeRule::default();
            &single
        }
    };
    // Every case in neither list is a group of its own.
    let mut groups = rule.exclusive.clone();
    let listed =
        |c: usize| rule.permanent.contains(&c) || rule.exclusive.iter().any(|g| g.contains(&c));
    groups.extend((0..results.len()).filter(|&c| !listed(c)).map(|c| vec![c]));
    let alone = rule.permanent.is_empty() && rule.exclusive.is_empty();
    (0..n)
        .map(|m| {
            let f = |c: usize| results[c].members[m].force;
            let base: f64 = rule.permanent.iter().map(|&c| f(c)).sum();
            let names: Vec<&str> = rule
                .permanent
                .iter()
                .map(|&c| results[c].case.as_str())
                .collect();
            let extreme = |better: &dyn Fn(f64, f64) -> bool| -> (f64, String) {
                let mut total = base;
                let mut used = names.clone();
                if alone {
                    // Each case alone: the single worst one.
                    let mut best: Option<usize> = None;
                    for c in 0..results.len() {
                        if better(f(c), best.map_or(0.0, f)) {
                            best = Some(c);
                        }
                    }
                    return match best {
                        Some(c) => (f(c), results[c].case.clone()),
                        None => (0.0, "-".into()),
                    };
                }
                for g in &groups {
                    let mut best: Option<usize> = None;
                    for &c in g {
                        if better(f(c), best.map_or(0.0, f)) {
                            best = Some(c);
                        }
                    }
                    if let Some(c) = best {
                        total += f(c);
                        used.push(results[c].case.as_str());
                    }
                }
                if used.is_empty() {
                    (0.0, "-".into())
                } else {
                    (total, used.join(" + "))
                }
            };
            Extremes {
                member: results[0].members[m].member.as_str().to_owned(),
                max: extreme(&|a, b| a > b),
                min: extreme(&|a, b| a < b),
            }
        })
        .collect()
}
