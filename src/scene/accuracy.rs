//! What accuracy costs in time: the knobs of a scene's procedure swept, each setting
//! constructed on the whole path `graphostatik check` runs (validation is done; the board
//! records every step and check), its error against the exact value set beside its time.
//!
//! The knobs (each only where the scene calls for what it trades):
//! - a crank: the number of crank angles (divisions), against the mean tangential force of a
//!   constant piston force (2P/π, whatever the rod), or else the mean piston speed (2v/π);
//! - an engine's dynamics: the divisions, each rule of the mean turning force (trapezoid,
//!   Simpson, 3/8, millimetre squares, planimeter) against the exact T_m;
//! - a beam with uniform loads: n point loads in place of each (the funicular polygon against
//!   the parabola), and the parabola by its tangents divided into d parts;
//! - every scene: f64 against the double-double replay of the same construction.
//!
//! Each procedure declares its own knobs ([`Procedure::sweeps`](super::Procedure::sweeps), in
//! its scene file); this module runs them and adds the precision every scene has.

use super::registry::AnyProblem;
use super::sweep::{timed, Setting, Sweep, SweepPoint};
use crate::protocol::{Board, BoardConfig, ConstructionError};

/// The knobs of the problem's procedure, swept. `progress(done, total)` is called after each
/// setting (for a progress bar).
///
/// # Errors
/// A construction error of a setting (a validated scene constructs at every setting the
/// sweep chooses; an error here is a defect).
pub fn sweeps(
    p: &AnyProblem,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Vec<Sweep>, ConstructionError> {
    // The scene's own figure first: one too large to draw is refused before any setting
    // is timed (the precision sweep draws it, with its double-double replay).
    p.construct(BoardConfig::DRAWING)?;
    let mut plan: Vec<Setting<'_>> = p.sweeps();
    plan.push(Box::new(move || precision(p).map(|s| vec![s])));
    let total = plan.len();
    let mut out: Vec<Sweep> = Vec::new();
    for (k, step) in plan.iter().enumerate() {
        for s in step()? {
            match out
                .iter_mut()
                .find(|o| o.knob == s.knob && o.quantity == s.quantity)
            {
                Some(o) => o.points.extend(s.points),
                None => out.push(s),
            }
        }
        progress(k + 1, total);
    }
    Ok(out)
}

/// f64 against the double-double replay: the largest relative error of any step's results
/// against the replay, and the time of each.
fn precision(p: &AnyProblem) -> Result<Sweep, ConstructionError> {
    let (plain, t64) = timed(|| p.construct(BoardConfig::DRAWING));
    plain?;
    let (b, tdd) = timed(|| p.construct(BoardConfig::DRAWING.with_reference()));
    let b: Board = b?;
    let worst = b
        .reference_report()
        .iter()
        .map(|r| r.observed / r.scale.max(f64::MIN_POSITIVE))
        .fold(0.0, f64::max);
    let points = vec![
        SweepPoint {
            setting: "f64".into(),
            value: worst,
            error: worst,
            seconds: t64,
        },
        SweepPoint {
            setting: "double-double replay".into(),
            value: 0.0,
            error: 0.0,
            seconds: tdd,
        },
    ];
    Ok(Sweep {
        knob: "precision".into(),
        quantity: "largest relative error of a step against the double-double replay".into(),
        unit: "relative".into(),
        exact: None,
        scale: 1.0,
        points,
    })
}
