//! The knobs that trade time for accuracy, as a procedure declares them
//! ([`Procedure::sweeps`](super::Procedure::sweeps)): each setting a closure that constructs
//! the problem so set, times it, and gives its error against the exact value. The helpers
//! here time a run and make a sweep's points; [`sweeps`](super::sweeps) runs them.

use crate::protocol::{Board, BoardConfig, ConstructionError};
use serde::Serialize;
use std::time::Instant;

/// One knob swept: a curve of the accuracy plot.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sweep {
    /// The knob ("crank divisions").
    pub knob: String,
    /// What its error is measured on ("mean tangential force T_m").
    pub quantity: String,
    /// The unit of the error.
    pub unit: String,
    /// The exact value it is measured against, where there is one number.
    pub exact: Option<f64>,
    /// The magnitude the errors are relative to (the exact value, the largest moment; 1 for
    /// an error that is relative already).
    pub scale: f64,
    /// The settings, in the order swept.
    pub points: Vec<SweepPoint>,
}

impl Sweep {
    /// The error of a point relative to the sweep's scale.
    pub fn relative(&self, p: &SweepPoint) -> f64 {
        if self.scale > 0.0 {
            p.error / self.scale
        } else {
            p.error
        }
    }
}

/// One setting of a knob.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepPoint {
    /// The setting ("36", "f64").
    pub setting: String,
    /// The value found.
    pub value: f64,
    /// |value − exact|.
    pub error: f64,
    /// Median seconds of one run (construction, recording and checks).
    pub seconds: f64,
}

/// Median seconds of `f` after one warm-up run, run at least three times and for at least 20 ms (at most 200
/// times), with its last result.
pub(super) fn timed<R>(mut f: impl FnMut() -> R) -> (R, f64) {
    // One run first, so that the timed runs find the caches and the allocator warm.
    let _ = f();
    let (mut times, start) = (Vec::new(), Instant::now());
    loop {
        let t = Instant::now();
        let r = f();
        times.push(t.elapsed().as_secs_f64());
        let spent = start.elapsed().as_secs_f64();
        if (times.len() >= 3 && spent >= 0.02) || times.len() >= 200 {
            times.sort_by(f64::total_cmp);
            return (r, times[times.len() / 2]);
        }
    }
}

/// The most steps a setting of the accuracy sweep draws: eight figures' worth
/// ([`super::MAX_FIGURE_STEPS`]), since a sweep goes past the scene's own divisions on
/// purpose (the bundled sweeps draw at most 345,680 steps, KG Abb. 1056's four cylinders at
/// 3,600 shaft divisions: 475 MB at the peak of its `accuracy`).
pub const MAX_SWEEP_STEPS: usize = 8 * super::MAX_FIGURE_STEPS;

/// A setting's construction timed as [`timed`] times it, on a drawing board held to
/// [`MAX_SWEEP_STEPS`]: the first construction counts the setting's steps, and a setting
/// past the limit is refused, naming it, before it is timed (it costs the limit's memory and
/// one construction's time, not a drawing's memory many times over).
pub(super) fn timed_drawing<R>(
    setting: &dyn std::fmt::Display,
    construct: impl Fn(BoardConfig) -> Result<(Board, R), ConstructionError>,
) -> (Result<(Board, R), ConstructionError>, f64) {
    let most = MAX_SWEEP_STEPS;
    let config = BoardConfig::DRAWING.keeping_at_most(most as u32);
    match construct(config) {
        Ok((b, _)) if b.spilled() => {
            let steps = b.step_count();
            let e = ConstructionError::unsupported(
                "sweep",
                format!(
                    "the accuracy sweep's setting {setting} draws {steps} steps, more than the \
                     {most} a setting may draw: accuracy takes a scene whose every setting fits \
                     (fewer cylinders, loads or members)"
                ),
            );
            (Err(e), 0.0)
        }
        Err(e) => (Err(e), 0.0),
        Ok(_) => timed(|| construct(config)),
    }
}

/// One setting of a knob, to be run: it constructs the problem so set and gives the sweeps'
/// points it measured (one per quantity).
pub type Setting<'a> = Box<dyn Fn() -> Result<Vec<Sweep>, ConstructionError> + 'a>;

/// The crank divisions every crank-like procedure sweeps.
pub(super) const CRANK_DIVISIONS: [usize; 10] = [4, 8, 12, 24, 36, 72, 180, 360, 1200, 3600];

/// The mean of |value| over a revolution that [`mean_over_divisions`] holds against its
/// exact value.
pub(super) struct MeanOf {
    pub(super) quantity: &'static str,
    pub(super) unit: &'static str,
    pub(super) exact: f64,
}

/// One setting per entry of [`CRANK_DIVISIONS`]: `run(n)` constructs at n equal divisions and
/// gives the values read at them with the seconds a run took; their mean |value| is the
/// setting's value.
pub(super) fn mean_over_divisions<'a>(
    what: MeanOf,
    run: impl Fn(usize) -> Result<(Vec<f64>, f64), ConstructionError> + Clone + 'a,
) -> Vec<Setting<'a>> {
    CRANK_DIVISIONS
        .iter()
        .map(|&n| -> Setting<'a> {
            let (run, q, u, exact) = (run.clone(), what.quantity, what.unit, what.exact);
            Box::new(move || {
                let (sample, secs) = run(n)?;
                let value =
                    sample.iter().map(|x| x.abs()).sum::<f64>() / sample.len().max(1) as f64;
                Ok(vec![one(
                    "crank divisions",
                    q,
                    u,
                    Some(exact),
                    n.to_string(),
                    value,
                    secs,
                )])
            })
        })
        .collect()
}

/// A sweep of one point.
#[allow(clippy::too_many_arguments)]
pub(super) fn one(
    knob: &str,
    quantity: &str,
    unit: &str,
    exact: Option<f64>,
    setting: String,
    value: f64,
    seconds: f64,
) -> Sweep {
    Sweep {
        knob: knob.into(),
        quantity: quantity.into(),
        unit: unit.into(),
        exact,
        scale: exact.map_or(1.0, f64::abs),
        points: vec![SweepPoint {
            setting,
            value,
            error: exact.map_or(value, |e| (value - e).abs()),
            seconds,
        }],
    }
}
