//! Trusses with more than 2k − 3 members (LH B.5, Abb. 19-20): parallel girders with two
//! diagonals in a panel.
//!
//! - **Split into two systems** ([`PairMode::SplitHalfLoads`]): each system keeps one
//!   diagonal of every pair, both carry half the loads, and the forces are added. Chords
//!   and posts get the sum of both plans, each diagonal the force of its own system.
//! - **Tension-only counter-diagonals** ([`PairMode::TensionOnly`], flat bars): per load
//!   case only one diagonal of a pair works, the one in tension. The plan is drawn with the
//!   first diagonal of each pair; every pair whose working diagonal comes out in compression
//!   is switched to the other, and the plan is drawn again, until all working diagonals pull.
//!   The book: "man verfährt so, als wenn die zweite Diagonale nicht vorhanden wäre".

use super::cremona::{
    case_heading, construct_plan, construct_truss_rows, CaseResult, Rows, SlackMember, TrussDrawing,
};
use super::plan::case_result;
use super::{LoadCase, Truss};
use crate::kernel::Vector;
use crate::protocol::{Board, ConstructionError};
use serde::Serialize;

/// How the pairs of diagonals are treated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PairMode {
    /// Two systems with half the loads each, added (Abb. 19 a, b).
    SplitHalfLoads,
    /// Flat bars that take tension only: per case the one in tension works.
    TensionOnly,
}

pub use crate::kernel::tolerance::SLACK_KG;

/// The truss without the members in `drop`, and the old index of every member kept (in
/// order). O(members + dropped).
pub fn without(t: &Truss, drop: &[usize]) -> (Truss, Vec<usize>) {
    let mut dropped = vec![false; t.members.len()];
    for &m in drop {
        if let Some(d) = dropped.get_mut(m) {
            *d = true;
        }
    }
    let keep: Vec<usize> = (0..t.members.len()).filter(|&m| !dropped[m]).collect();
    (
        Truss::new(
            t.joints.clone(),
            keep.iter().map(|&m| t.members[m].clone()).collect(),
            t.supports.clone(),
        ),
        keep,
    )
}

/// The slack diagonals of a case, for its name: every one up to [`SLACK_NAMED`], else the
/// first of them and how many ("14, 16, 19, 21 slack"; "1, 5, 9, …, 97, … 16000 slack"). A
/// book's girder (Aufgabe 5's crane bridge, 19 pairs) is named in full.
fn slack_names(t: &Truss, drop: &[usize]) -> String {
    let names: Vec<&str> = (drop.iter().take(SLACK_NAMED))
        .map(|&m| t.members[m].name.as_str())
        .collect();
    if drop.len() <= SLACK_NAMED {
        format!("{} slack", names.join(", "))
    } else {
        format!("{}, … {} slack", names.join(", "), drop.len())
    }
}

/// Trial plans of one case before the tension-only diagonals are given up: each plan
/// switches every pair that pushes, and the book's girders settle in two or three.
pub const MAX_TRIAL_PLANS: usize = 64;

/// The slack diagonals a case's name lists one by one (its name is the situation of every
/// step of its plan: a case of 16,000 pairs named all of them in 3.6 GB of situations).
pub const SLACK_NAMED: usize = 24;

/// Constructs every case for a truss with pairs of diagonals (indices into `t.members`).
///
/// # Errors
/// As [`construct_truss_rows`]; and a tension-only case that no choice of working diagonals
/// carries with all of them in tension.
pub fn construct_pairs(
    b: &mut Board,
    t: &Truss,
    pairs: &[[usize; 2]],
    mode: PairMode,
    cases: &[LoadCase],
    dr: &TrussDrawing,
) -> Result<Vec<CaseResult>, ConstructionError> {
    let mut row = Rows::default();
    let mut out = Vec::with_capacity(cases.len());
    let p = Pairs { t, pairs, dr };
    for case in cases {
        // Several cases: each row under its case's name, as `construct_truss` heads them.
        if cases.len() > 1 && case.drawn {
            let scale = case.force_scale.unwrap_or(dr.force_scale);
            row.heading = Some(case_heading(cases, case, scale));
        }
        out.push(match mode {
            PairMode::SplitHalfLoads => p.split_half_loads(b, case, &mut row)?,
            PairMode::TensionOnly => p.tension_only(b, case, &mut row)?,
        });
    }
    Ok(out)
}

/// A truss with pairs of diagonals, drawn case by case.
struct Pairs<'a> {
    t: &'a Truss,
    pairs: &'a [[usize; 2]],
    dr: &'a TrussDrawing,
}

impl Pairs<'_> {
    /// Two systems, each with one diagonal of every pair and half the loads, drawn one under
    /// the other; the member forces and reactions added (LH B.5, Abb. 20).
    fn split_half_loads(
        &self,
        b: &mut Board,
        case: &LoadCase,
        row: &mut Rows,
    ) -> Result<CaseResult, ConstructionError> {
        let (t, n) = (self.t, self.t.members.len());
        let mut forces = vec![0.0; n];
        let mut plan = vec![0.0; n];
        let mut reactions = vec![Vector::zeros(); t.supports.len()];
        for (s, system) in ["a", "b"].iter().enumerate() {
            let drop: Vec<usize> = self.pairs.iter().map(|p| p[1 - s]).collect();
            let (sub, keep) = without(t, &drop);
            let half = LoadCase {
                name: format!("{}, system {system} (half loads)", case.name),
                loads: case
                    .loads
                    .iter()
                    .map(|l| super::JointLoad {
                        joint: l.joint,
                        force: l.force * 0.5,
                    })
                    .collect(),
                force_scale: case.force_scale,
                drawn: case.drawn,
                book_name: case.book_name.clone(),
            };
            let r = construct_truss_rows(b, &sub, &[half], self.dr, row, &[])?;
            for (i, &m) in keep.iter().enumerate() {
                forces[m] += r[0].members[i].force;
                plan[m] += r[0].members[i].plan_mm;
            }
            for (sum, rv) in reactions.iter_mut().zip(&r[0].reactions) {
                *sum += rv.force;
            }
        }
        let none = vec![None; n];
        Ok(case_result(
            t, case, &forces, &plan, &none, &reactions, self.dr,
        ))
    }

    /// Tension-only counter-diagonals of flat bar: one diagonal of each pair works; every
    /// pair whose working diagonal comes out in compression is switched, and the plan drawn
    /// again until every working diagonal pulls (LH B.5, Abb. 19). The trial plans are
    /// drawn on a silent board; the final one on `b`, the slack diagonals dashed.
    fn tension_only(
        &self,
        b: &mut Board,
        case: &LoadCase,
        row: &mut Rows,
    ) -> Result<CaseResult, ConstructionError> {
        let working = self.working_diagonals(b, case)?;
        let (t, n) = (self.t, self.t.members.len());
        let drop: Vec<usize> = self
            .pairs
            .iter()
            .zip(&working)
            .map(|(p, &w)| p[1 - w])
            .collect();
        let (sub, keep) = without(t, &drop);
        let c = LoadCase {
            name: format!("{} ({})", case.name, slack_names(t, &drop)),
            loads: case.loads.clone(),
            force_scale: case.force_scale,
            drawn: case.drawn,
            book_name: case.book_name.clone(),
        };
        let ghosts: Vec<SlackMember> = (drop.iter())
            .map(|&m| SlackMember {
                name: &t.members[m].name,
                ends: t.members[m].ends,
            })
            .collect();
        let r = construct_truss_rows(b, &sub, std::slice::from_ref(&c), self.dr, row, &ghosts)?;
        let mut forces = vec![0.0; n];
        let mut plan = vec![0.0; n];
        let mut mat = vec![Some(0.0); n];
        for (i, &m) in keep.iter().enumerate() {
            forces[m] = r[0].members[i].force;
            plan[m] = r[0].members[i].plan_mm;
            mat[m] = r[0].members[i].matrix;
        }
        let reactions: Vec<Vector> = r[0].reactions.iter().map(|v| v.force).collect();
        Ok(case_result(
            t, case, &forces, &plan, &mat, &reactions, self.dr,
        ))
    }

    /// Which diagonal of each pair works (0 or 1) so that every working one pulls: switched
    /// pair by pair on trial plans until none pushes; a choice seen twice means there is none.
    fn working_diagonals(
        &self,
        b: &Board,
        case: &LoadCase,
    ) -> Result<Vec<usize>, ConstructionError> {
        let mut working: Vec<usize> = vec![0; self.pairs.len()];
        let mut tried = std::collections::BTreeSet::new();
        loop {
            if tried.len() == MAX_TRIAL_PLANS {
                return Err(ConstructionError::unsupported(
                    "diagonals",
                    format!(
                        "{}: the tension-only diagonals did not settle in {MAX_TRIAL_PLANS} trial plans",
                        case.name
                    ),
                ));
            }
            if !tried.insert(working.clone()) {
                return Err(ConstructionError::unsupported(
                    "diagonals",
                    format!(
                        "{}: no choice of the tension-only diagonals has them all in tension",
                        case.name
                    ),
                ));
            }
            let drop: Vec<usize> = self
                .pairs
                .iter()
                .zip(&working)
                .map(|(p, &w)| p[1 - w])
                .collect();
            let (sub, keep) = without(self.t, &drop);
            let mut scratch = b.scratch();
            let r = construct_plan(&mut scratch, &sub, std::slice::from_ref(case), self.dr)?;
            // `keep` is in order: a member's place in the trial truss by binary search.
            let force_of = |m: usize| {
                keep.binary_search(&m)
                    .map_or(0.0, |i| r[0].members[i].force)
            };
            let mut switched = false;
            for (p, w) in self.pairs.iter().zip(working.iter_mut()) {
                if force_of(p[*w]) < -SLACK_KG {
                    *w = 1 - *w;
                    switched = true;
                }
            }
            if !switched {
                return Ok(working);
            }
        }
    }
}
