//! The draftsman simulated: the same construction drawn many times by an unsteady hand
//! (every point marked within the pencil's width, every line ruled a little turned, every
//! length set and read on the scale rule a little off), across every core, and the spread
//! of every checked value set beside the error bound the board propagates for that hand.
//!
//! A book's printed numbers were read off drawings like these: the spread says which of
//! their disagreements with the closed form a drawing explains, and at what pencil and scale.

use super::registry::AnyProblem;
use crate::protocol::{Board, BoardConfig, ConstructionError, ErrorModel, Hand, WorstCut};
use serde::Serialize;
use std::collections::HashMap;

/// How the draftsman is simulated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DraftingOptions {
    /// The hand's standard deviations: pencil (mm), set square (rad), scale rule (mm).
    pub hand: ErrorModel,
    /// Drawings made.
    pub runs: usize,
    /// The seed of the first drawing (drawing k has seed + k).
    pub seed: u64,
    /// Threads drawing at once.
    pub jobs: usize,
}

/// One checked value, as the drawings came out.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DraftedValue {
    /// The step of the check.
    pub step: String,
    /// Its situation ("θ = 30°").
    pub context: String,
    /// The quantity.
    pub quantity: String,
    /// The name of the object the value was read as (a member's name), if it has one.
    pub object: String,
    /// Its unit.
    pub unit: String,
    /// The construction without a hand's errors.
    pub drawn_exactly: f64,
    /// The closed form.
    pub closed_form: f64,
    /// The natural magnitude of the quantity (the check's reference: the largest force of
    /// the case, the crank-pin speed), against which a relative spread is read.
    pub reference: f64,
    /// Mean of the drawings.
    pub mean: f64,
    /// Standard deviation of the drawings.
    pub sd: f64,
    /// The 2.5 % and 97.5 % points of the drawings.
    pub range: [f64; 2],
    /// The linear error bound the board propagates for a hand whose every error is one
    /// standard deviation (a worst case: the errors all adding up).
    pub bound: f64,
    /// The most glancing cut the value depends on.
    pub worst_cut: Option<WorstCut>,
    /// Drawings that gave this value.
    pub drawings: usize,
    /// The error budget: the standard deviation with only the pencil's, only the set
    /// square's, only the scale rule's errors (the same seeds).
    pub budget: [f64; 3],
}

/// The drawings, summed up.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DraftingReport {
    /// The options.
    pub options: DraftingOptions,
    /// Drawings that could not be finished (a cut the hand's errors made miss), and the first
    /// reason.
    pub failed: usize,
    /// Why the first of them failed.
    pub first_failure: Option<String>,
    /// Every checked value that some drawing gave.
    pub values: Vec<DraftedValue>,
    /// Checked values that no finished drawing gave (a branch the hand's errors switched).
    pub missing: usize,
}

/// A checked value across drawings: its quantity, the name of the object it was read as, and
/// its place among the values of that quantity and name. Not the step number: a drawing's
/// errors may switch a tension-only diagonal and with it the number of steps before.
type Key = (String, String, usize);

/// The name of the object a step made that a check was read as (a member's name).
fn object_of(b: &Board, s: &crate::protocol::Step) -> String {
    s.outputs
        .iter()
        .filter_map(|id| b.object(*id))
        .map(|o| o.label.to_string())
        .find(|l| !l.is_empty())
        .unwrap_or_default()
}

/// Every check of a board with its key, in step order.
fn keyed(b: &Board) -> Vec<(Key, &crate::protocol::Step, &crate::protocol::Check)> {
    let mut seen: HashMap<(String, String), usize> = HashMap::new();
    let mut out = Vec::new();
    for s in b.steps() {
        for c in &s.checks {
            let name = (c.quantity.to_string(), object_of(b, s));
            let k = seen.entry(name.clone()).or_default();
            out.push(((name.0, name.1, *k), s, c));
            *k += 1;
        }
    }
    out
}

/// The checked values of a board by key.
fn readings(b: &Board) -> HashMap<Key, f64> {
    keyed(b)
        .into_iter()
        .map(|(k, _, c)| (k, c.constructed))
        .collect()
}

/// Every drawing's readings gathered by key, with the count of drawings that failed and the
/// first reason.
fn sample(
    p: &AnyProblem,
    options: DraftingOptions,
    tick: &(dyn Fn() + Sync),
) -> (HashMap<Key, Vec<f64>>, usize, Option<String>) {
    let mut failed = 0;
    let mut first_failure = None;
    let mut samples: HashMap<Key, Vec<f64>> = HashMap::new();
    for r in draw_all(p, options, tick) {
        match r {
            Ok(m) => {
                for (k, v) in m {
                    samples.entry(k).or_default().push(v);
                }
            }
            Err(e) => {
                failed += 1;
                first_failure.get_or_insert(e);
            }
        }
    }
    (samples, failed, first_failure)
}

/// Mean and standard deviation, summed as offsets from the middle value: equal drawings give
/// their value exactly, and the spread does not drown in the value's own size.
fn spread(v: &[f64]) -> (f64, f64) {
    let n = v.len();
    if n == 0 {
        return (0.0, 0.0);
    }
    let mid = v[n / 2];
    let mean = mid + v.iter().map(|x| x - mid).sum::<f64>() / n as f64;
    let sd = if n > 1 {
        (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt()
    } else {
        0.0
    };
    (mean, sd)
}

/// Draws the problem `options.runs` times with the hand's errors, on `options.jobs` threads.
///
/// # Errors
/// The construction's error if it fails without a hand (a validated scene does not).
pub fn drafting(
    p: &AnyProblem,
    options: DraftingOptions,
) -> Result<DraftingReport, ConstructionError> {
    drafting_with_progress(p, options, &|_, _| {})
}

/// [`drafting`], calling `progress(done, total)` after each drawing (from the drawing
/// threads), for a progress bar: the report's drawings and the budget's, four times `runs`.
///
/// # Errors
/// As [`drafting`].
pub fn drafting_with_progress(
    p: &AnyProblem,
    options: DraftingOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<DraftingReport, ConstructionError> {
    let done = std::sync::atomic::AtomicUsize::new(0);
    let tick = || {
        let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        progress(k, 4 * options.runs);
    };
    let exact = p.construct(BoardConfig::DRAWING.with_model(options.hand))?;
    let (mut samples, failed, first_failure) = sample(p, options, &tick);
    // The budget: the same drawings by a hand with one kind of error only.
    let h = options.hand;
    let only = [
        ErrorModel::drafting(h.mark_mm, 0.0, 0.0),
        ErrorModel::drafting(0.0, h.angle_rad, 0.0),
        ErrorModel::drafting(0.0, 0.0, h.read_mm),
    ];
    let by_source: Vec<HashMap<Key, Vec<f64>>> = only
        .iter()
        .map(|m| {
            sample(
                p,
                DraftingOptions {
                    hand: *m,
                    ..options
                },
                &tick,
            )
            .0
        })
        .collect();
    let all: Vec<Option<DraftedValue>> = keyed(&exact)
        .into_iter()
        .map(|(key, s, c)| {
            let v = samples.remove(&key).unwrap_or_default();
            let budget = by_source
                .iter()
                .map(|m| {
                    let v: Vec<f64> = m
                        .get(&key)
                        .into_iter()
                        .flatten()
                        .copied()
                        .filter(|x| x.is_finite())
                        .collect();
                    let mut v = v;
                    v.sort_by(f64::total_cmp);
                    spread(&v).1
                })
                .collect::<Vec<_>>();
            summarise(s, c, v).map(|d| DraftedValue {
                object: key.1.clone(),
                budget: [budget[0], budget[1], budget[2]],
                ..d
            })
        })
        .collect();
    let missing = all.iter().filter(|v| v.is_none()).count();
    Ok(DraftingReport {
        options,
        failed,
        first_failure,
        values: all.into_iter().flatten().collect(),
        missing,
    })
}

/// Every drawing's readings (or why it failed), in the order of the seeds.
fn draw_all(
    p: &AnyProblem,
    o: DraftingOptions,
    tick: &(dyn Fn() + Sync),
) -> Vec<Result<HashMap<Key, f64>, String>> {
    let jobs = o.jobs.clamp(1, o.runs.max(1));
    let per = o.runs.div_ceil(jobs);
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..jobs)
            .map(|j| {
                scope.spawn(move || {
                    (j * per..((j + 1) * per).min(o.runs))
                        .map(|k| {
                            let hand = Hand {
                                model: o.hand,
                                seed: o.seed.wrapping_add(k as u64),
                            };
                            let r = p
                                .construct(BoardConfig::DRAWING.with_hand(hand))
                                .map(|b| readings(&b))
                                .map_err(|e| e.to_string());
                            tick();
                            r
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("a drawing thread does not panic"))
            .collect()
    })
}

/// The statistics of one value's drawings; `None` if no drawing gave it.
fn summarise(
    s: &crate::protocol::Step,
    c: &crate::protocol::Check,
    mut v: Vec<f64>,
) -> Option<DraftedValue> {
    v.retain(|x| x.is_finite());
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        return None;
    }
    let (mean, sd) = spread(&v);
    let at = |q: f64| v[((n - 1) as f64 * q).round() as usize];
    Some(DraftedValue {
        step: s.id.to_string(),
        context: s.context.as_deref().unwrap_or("").to_string(),
        quantity: c.quantity.to_string(),
        object: String::new(),
        unit: c.unit.to_string(),
        drawn_exactly: c.constructed,
        closed_form: c.closed_form,
        reference: c.reference.abs().max(c.closed_form.abs()),
        mean,
        sd,
        range: [at(0.025), at(0.975)],
        bound: c.bound,
        worst_cut: c.worst_cut,
        drawings: n,
        budget: [0.0; 3],
    })
}
