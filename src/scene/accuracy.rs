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

use super::beam::BeamScene;
use super::crank_dynamics::DynamicsScene;
use super::procedure::Procedure;
use super::registry::AnyProblem;
use crate::crank::{Angles, PistonForce};
use crate::protocol::{Board, BoardConfig, ConstructionError};
use crate::statics::{Beam, PointLoad};
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
fn timed<R>(mut f: impl FnMut() -> R) -> (R, f64) {
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
    let mut plan: Vec<Setting<'_>> = Vec::new();
    if let Some(c) = p.get::<super::types::SliderCrankScene>() {
        plan.extend(crank_divisions(c));
    }
    if let Some(d) = p.get::<DynamicsScene>() {
        plan.extend(dynamics_divisions(d));
    }
    if let Some(b) = p.get::<BeamScene>() {
        plan.extend(beam_loads(b));
    }
    if let Some(y) = p.get::<super::scotch_yoke::YokeScene>() {
        plan.extend(yoke_divisions(y));
    }
    if let Some(g) = p.get::<super::combustion::CombustionScene>() {
        plan.extend(gas_divisions(g));
    }
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

type Setting<'a> = Box<dyn Fn() -> Result<Vec<Sweep>, ConstructionError> + 'a>;

const CRANK_DIVISIONS: [usize; 10] = [4, 8, 12, 24, 36, 72, 180, 360, 1200, 3600];

/// A combustion engine's shaft angles over the cycle swept, the mean of the drawn turning
/// force against the exact integral: the gas force jumps at the firing dead centre and at
/// the cut-off's corner, so the mean converges as n⁻¹ until the ordinates resolve the peak.
fn gas_divisions(g: &super::combustion::CombustionProblem) -> Vec<Setting<'_>> {
    [8, 12, 24, 48, 96, 180, 360, 720, 1440, 3600]
        .into_iter()
        .map(|n| -> Setting<'_> {
            Box::new(move || {
                let mut q = g.clone();
                q.divisions = n;
                let (r, secs) = timed(|| {
                    <super::combustion::CombustionScene as super::Procedure>::construct(
                        &q,
                        BoardConfig::DRAWING,
                    )
                });
                let res = r?.1;
                Ok(vec![one(
                    "shaft divisions over the cycle",
                    "mean turning force T_m (of the ordinates)",
                    "kg",
                    Some(res.t_m_exact),
                    n.to_string(),
                    res.t_m,
                    secs,
                )])
            })
        })
        .collect()
}

/// A scotch yoke's crank angles swept, against its mean speed 2v/π (velocity asked for):
/// |c′| = v·|sin φ| has kinks at the dead centres, so the mean of the divisions converges as
/// n⁻², as the slider-crank's does.
fn yoke_divisions(y: &super::scotch_yoke::YokeProblem) -> Vec<Setting<'_>> {
    if !y.request.velocity {
        return Vec::new();
    }
    let what = MeanOf {
        quantity: "mean yoke speed (of the divisions)",
        unit: "m/s",
        exact: 2.0 * y.yoke.crank_pin_speed / std::f64::consts::PI,
    };
    mean_over_divisions(what, move |n| {
        let mut q = y.clone();
        q.angles = Angles::Divisions(n);
        let (r, secs) =
            timed(|| super::scotch_yoke::YokeScene::construct(&q, BoardConfig::DRAWING));
        Ok((r?.1.rows.iter().filter_map(|r| r.c).collect(), secs))
    })
}

/// Crank angles swept, against 2P/π (constant piston force, tangential force asked for) or
/// 2v/π (the mean piston speed, velocity asked for).
fn crank_divisions(c: &super::slider_crank::SliderCrankProblem) -> Vec<Setting<'_>> {
    let by_t =
        c.request.tangential_force && matches!(c.drive.piston_force, PistonForce::Constant(_));
    let what = if by_t {
        MeanOf {
            quantity: "mean tangential force T_m (of the divisions)",
            unit: "kg",
            exact: 2.0 * c.drive.piston_force.max_abs() / std::f64::consts::PI,
        }
    } else if c.request.velocity_parallel || c.request.velocity_instant_centre {
        MeanOf {
            quantity: "mean piston speed (of the divisions)",
            unit: "m/s",
            exact: 2.0 * c.drive.crank_pin_speed / std::f64::consts::PI,
        }
    } else {
        return Vec::new();
    };
    mean_over_divisions(what, move |n| {
        let mut q = c.clone();
        q.angles = Angles::Divisions(n);
        let (r, secs) =
            timed(|| super::types::SliderCrankScene::construct(&q, BoardConfig::DRAWING));
        let rows = r?.1.rows;
        let sample = rows.iter().filter_map(|r| {
            if by_t {
                r.tangential_force
            } else {
                r.c_parallel.or(r.c_instant_centre)
            }
        });
        Ok((sample.collect(), secs))
    })
}

/// The mean of |value| over a revolution that [`mean_over_divisions`] holds against its
/// exact value.
struct MeanOf {
    quantity: &'static str,
    unit: &'static str,
    exact: f64,
}

/// One setting per entry of [`CRANK_DIVISIONS`]: `run(n)` constructs at n equal divisions and
/// gives the values read at them with the seconds a run took; their mean |value| is the
/// setting's value.
fn mean_over_divisions<'a>(
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

fn one(
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

const DYNAMICS_DIVISIONS: [usize; 6] = [12, 24, 60, 120, 360, 1200];

/// The engine's divisions swept; each rule of the mean turning force its own curve.
fn dynamics_divisions(d: &super::crank_dynamics::DynamicsProblem) -> Vec<Setting<'_>> {
    if !d.request.mean_height {
        return Vec::new();
    }
    DYNAMICS_DIVISIONS
        .iter()
        .map(|&n| -> Setting<'_> {
            Box::new(move || {
                let mut q = d.clone();
                q.rays = Angles::Divisions(n);
                let (r, secs) = timed(|| DynamicsScene::construct(&q, BoardConfig::DRAWING));
                let res = r?.1;
                let exact = res.t_m_exact;
                Ok(res
                    .mean_heights
                    .iter()
                    .map(|m| {
                        // m.error is m.t_m − exact: the error `one` finds.
                        one(
                            &format!("divisions, {}", m.rule),
                            "mean turning force T_m",
                            "kg",
                            exact,
                            n.to_string(),
                            m.t_m,
                            secs,
                        )
                    })
                    .collect())
            })
        })
        .collect()
}

const POINT_LOADS: [usize; 8] = [1, 2, 4, 8, 16, 32, 64, 128];
const TANGENT_PARTS: [usize; 5] = [2, 4, 8, 16, 64];

/// A beam's uniform loads as n point loads (strip centres), and the parabola by d tangent
/// parts: the largest moment error at the sections, against the uniform loads' exact moment.
fn beam_loads(b: &super::beam::BeamProblem) -> Vec<Setting<'_>> {
    if b.beam.uniform_loads.is_empty() || !b.request.moment_area {
        return Vec::new();
    }
    let mut out: Vec<Setting<'_>> = Vec::new();
    for &n in &POINT_LOADS {
        out.push(Box::new(move || {
            let mut q = b.clone();
            q.beam = as_point_loads(&b.beam, n);
            let s = moment_error(b, &q, "n point loads for each uniform load", n)?;
            Ok(vec![s])
        }));
    }
    for &d in &TANGENT_PARTS {
        out.push(Box::new(move || {
            let mut q = b.clone();
            q.drawing.parabola_divisions = d;
            Ok(vec![moment_error(
                b,
                &q,
                "parabola by its tangents, d parts",
                d,
            )?])
        }));
    }
    out
}

/// The beam with every uniform load replaced by `n` equal point loads at its strips' centres.
fn as_point_loads(beam: &Beam, n: usize) -> Beam {
    let mut out = beam.clone();
    out.uniform_loads.clear();
    for u in &beam.uniform_loads {
        let w = (u.to - u.from) / n as f64;
        out.point_loads.extend((0..n).map(|k| PointLoad {
            x: u.from + w * (k as f64 + 0.5),
            p: u.q * w,
        }));
    }
    out.point_loads.sort_by(|a, c| a.x.total_cmp(&c.x));
    out
}

/// The largest |M| error over the constructed sections, against the original beam's moment.
fn moment_error(
    orig: &super::beam::BeamProblem,
    q: &super::beam::BeamProblem,
    knob: &str,
    setting: usize,
) -> Result<Sweep, ConstructionError> {
    let (r, secs) = timed(|| BeamScene::construct(q, BoardConfig::DRAWING));
    let res = r?.1;
    let cf = crate::statics::closed_form::Sections::new(&orig.beam);
    let err = res
        .sections
        .iter()
        .map(|s| (s.moment - cf.moment(s.x)).abs())
        .fold(0.0, f64::max);
    // No single exact value: the setting's value is its error.
    let mut s = one(
        knob,
        "largest moment error at the sections",
        "kg·m",
        None,
        setting.to_string(),
        err,
        secs,
    );
    s.scale = crate::statics::closed_form::max_abs_moment(&orig.beam)
        .0
        .abs();
    Ok(s)
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
