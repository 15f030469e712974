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
    /// The estimate the board propagates for a hand whose every error is one standard
    /// deviation, all adding up: the linear sum of the errors' standard deviations, weighted
    /// by how each step amplifies them. Not a bound: a hand's errors are not limited to one
    /// standard deviation, and `outside` says how many drawings fell beyond it.
    pub bound: f64,
    /// The share of the drawings farther than `bound` from the construction drawn without
    /// error (about 5 % for the late members of LH Aufgabe 3, 0 for most values: there it
    /// is some two standard deviations of the drawings).
    pub outside: f64,
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

/// A drawing's checked values in the order of the keys (NaN where it gave none: a branch
/// its errors switched).
fn readings(b: &Board, index: &HashMap<Key, usize>) -> Vec<f64> {
    let mut out = vec![f64::NAN; index.len()];
    for (k, _, c) in keyed(b) {
        if let Some(&i) = index.get(&k) {
            out[i] = c.constructed;
        }
    }
    out
}

/// An f64 ordered by `total_cmp`, for the heaps of the tails.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Ordered(f64);

impl Eq for Ordered {}

impl PartialOrd for Ordered {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Ordered {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// The range the report gives: the 2.5 % and 97.5 % points of the drawings.
const RANGE: [f64; 2] = [0.025, 0.975];

/// One checked value's drawings, summed up as they come, in the order of the seeds: the
/// count, the sums of the offsets from the first drawing and of their squares (equal
/// drawings give their value exactly, and the spread does not drown in the value's size),
/// and the `keep` smallest and largest values, which hold the 2.5 % and 97.5 % points
/// exactly. Its memory is fixed by the runs asked for, not by the drawings kept: 2 × (2.5 %
/// of the runs + 2) values, where every drawing was kept whole before (0.2 MB a drawing).
#[derive(Debug, Clone)]
struct Stats {
    n: usize,
    shift: f64,
    sum: f64,
    sum_sq: f64,
    keep: usize,
    low: std::collections::BinaryHeap<Ordered>,
    high: std::collections::BinaryHeap<std::cmp::Reverse<Ordered>>,
    /// Drawings farther from the construction drawn without error than its propagated
    /// estimate, and that construction and estimate.
    outside: usize,
    exact: f64,
    estimate: f64,
}

impl Stats {
    fn new(runs: usize, tails: bool, (exact, estimate): (f64, f64)) -> Stats {
        let keep = if tails {
            (runs as f64 * RANGE[0]).ceil() as usize + 2
        } else {
            0
        };
        Stats {
            n: 0,
            shift: f64::NAN,
            sum: 0.0,
            sum_sq: 0.0,
            keep,
            low: std::collections::BinaryHeap::with_capacity(keep + 1),
            high: std::collections::BinaryHeap::with_capacity(keep + 1),
            outside: 0,
            exact,
            estimate,
        }
    }

    fn push(&mut self, x: f64) {
        if !x.is_finite() {
            return;
        }
        if self.n == 0 {
            self.shift = x;
        }
        self.n += 1;
        let d = x - self.shift;
        self.sum += d;
        self.sum_sq += d * d;
        if (x - self.exact).abs() > self.estimate {
            self.outside += 1;
        }
        if self.keep > 0 {
            self.low.push(Ordered(x));
            if self.low.len() > self.keep {
                self.low.pop();
            }
            self.high.push(std::cmp::Reverse(Ordered(x)));
            if self.high.len() > self.keep {
                self.high.pop();
            }
        }
    }

    /// Mean and standard deviation.
    fn spread(&self) -> (f64, f64) {
        if self.n == 0 {
            return (0.0, 0.0);
        }
        let n = self.n as f64;
        let mean = self.shift + self.sum / n;
        let sd = if self.n > 1 {
            ((self.sum_sq - self.sum * self.sum / n).max(0.0) / (n - 1.0)).sqrt()
        } else {
            0.0
        };
        (mean, sd)
    }

    /// The 2.5 % and 97.5 % points: the value of rank round((n − 1)·q) among the sorted
    /// drawings, read from the tail that holds it.
    fn range(&self) -> [f64; 2] {
        let last = self.n.saturating_sub(1);
        let lo = (last as f64 * RANGE[0]).round() as usize;
        let hi = last - (last as f64 * RANGE[1]).round() as usize;
        let mut low: Vec<f64> = self.low.iter().map(|o| o.0).collect();
        low.sort_by(f64::total_cmp);
        let mut high: Vec<f64> = self.high.iter().map(|o| o.0 .0).collect();
        high.sort_by(|a, b| b.total_cmp(a));
        [
            low.get(lo).copied().unwrap_or(f64::NAN),
            high.get(hi).copied().unwrap_or(f64::NAN),
        ]
    }
}

/// Every drawing of a hand summed up per checked value of `exact`, in the order of the
/// seeds whatever the threads: the statistics, the count of drawings that failed and the
/// first reason.
fn sample(
    p: &AnyProblem,
    options: DraftingOptions,
    (index, stats): (&HashMap<Key, usize>, &mut [Stats]),
    tick: &(dyn Fn() + Sync),
) -> (usize, Option<String>) {
    let mut failed = 0;
    let mut first_failure = None;
    let round = DRAWINGS_A_BATCH * options.jobs.clamp(1, options.runs.max(1));
    let mut from = 0;
    while from < options.runs {
        let to = (from + round).min(options.runs);
        for r in draw_all(p, options, (from, to), index, tick) {
            match r {
                Ok(values) => {
                    for (s, v) in stats.iter_mut().zip(values) {
                        s.push(v);
                    }
                }
                Err(e) => {
                    failed += 1;
                    first_failure.get_or_insert(e);
                }
            }
        }
        from = to;
    }
    (failed, first_failure)
}

/// Drawings a thread makes before their values are summed up: what is held at once is
/// this many drawings per thread, whatever the runs.
const DRAWINGS_A_BATCH: usize = 64;

/// Draws the problem `options.runs` times with the hand's errors, on `options.jobs` threads.
///
/// The most steps a drafting run draws in all (its drawings times their steps, four times
/// over): 200 runs, the default, of the largest figure ([`super::MAX_FIGURE_STEPS`]), some
/// 30-60 s on two cores at 0.8-1.5 µs a step.
pub const MAX_DRAFTING_STEPS: usize = 40_000_000;

/// # Errors
/// The construction's error if it fails without a hand (a validated scene does not); a
/// figure too large to draw, or more drawings than [`MAX_DRAFTING_STEPS`] allows (`runs`),
/// refused before the first run.
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
    // The cost, known from the exact drawing before the first run: four drawings a run
    // (the report's and the budget's three).
    let steps = exact.step_count();
    let work = 4 * options.runs.saturating_mul(steps);
    if work > MAX_DRAFTING_STEPS {
        let most = MAX_DRAFTING_STEPS / (4 * steps.max(1));
        return Err(ConstructionError::unsupported(
            "--runs",
            format!(
                "{} drawings of {steps} steps each, four times over, are {work} steps, more \
                 than the {MAX_DRAFTING_STEPS} drafting draws (about a minute on two cores): \
                 ask for at most {most} runs",
                options.runs
            ),
        ));
    }
    let checks = keyed(&exact);
    let index: HashMap<Key, usize> = (checks.iter().enumerate())
        .map(|(i, (k, _, _))| (k.clone(), i))
        .collect();
    let fresh = |runs: usize, tails: bool| -> Vec<Stats> {
        (checks.iter())
            .map(|(_, _, c)| Stats::new(runs, tails, (c.constructed, c.bound)))
            .collect()
    };
    let mut stats = fresh(options.runs, true);
    let (failed, first_failure) = sample(p, options, (&index, &mut stats), &tick);
    // The budget: the same drawings by a hand with one kind of error only.
    let h = options.hand;
    let only = [
        ErrorModel::drafting(h.mark_mm, 0.0, 0.0),
        ErrorModel::drafting(0.0, h.angle_rad, 0.0),
        ErrorModel::drafting(0.0, 0.0, h.read_mm),
    ];
    let by_source: Vec<Vec<Stats>> = only
        .iter()
        .map(|m| {
            let mut s = fresh(options.runs, false);
            let o = DraftingOptions {
                hand: *m,
                ..options
            };
            sample(p, o, (&index, &mut s), &tick);
            s
        })
        .collect();
    let all: Vec<Option<DraftedValue>> = (checks.iter().enumerate())
        .map(|(i, (key, s, c))| {
            let budget = [0, 1, 2].map(|k| by_source[k][i].spread().1);
            summarise(s, c, &stats[i]).map(|d| DraftedValue {
                object: key.1.clone(),
                budget,
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

/// The readings of drawings `from..to` (or why each failed), in the order of the seeds,
/// drawn on `o.jobs` threads.
fn draw_all(
    p: &AnyProblem,
    o: DraftingOptions,
    (from, to): (usize, usize),
    index: &HashMap<Key, usize>,
    tick: &(dyn Fn() + Sync),
) -> Vec<Result<Vec<f64>, String>> {
    let jobs = o.jobs.clamp(1, (to - from).max(1));
    let per = (to - from).div_ceil(jobs);
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..jobs)
            .map(|j| {
                scope.spawn(move || {
                    (from + j * per..(from + (j + 1) * per).min(to))
                        .map(|k| {
                            let hand = Hand {
                                model: o.hand,
                                seed: o.seed.wrapping_add(k as u64),
                            };
                            let r = p
                                .construct(BoardConfig::DRAWING.with_hand(hand))
                                .map(|b| readings(&b, index))
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
    stats: &Stats,
) -> Option<DraftedValue> {
    if stats.n == 0 {
        return None;
    }
    let (mean, sd) = stats.spread();
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
        range: stats.range(),
        bound: c.bound,
        outside: stats.outside as f64 / stats.n as f64,
        worst_cut: c.worst_cut,
        drawings: stats.n,
        budget: [0.0; 3],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The streamed statistics give what the whole sorted sample gives: the 2.5 % and
    /// 97.5 % points exactly, mean and standard deviation to rounding.
    #[test]
    fn streamed_statistics_match_the_whole_sample() {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for runs in [1usize, 2, 7, 40, 41, 999, 5000] {
            let mut all = Vec::new();
            let mut s = Stats::new(runs, true, (0.0, 1.5));
            for _ in 0..runs {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                let v = 1e6 + (x >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0;
                all.push(v);
                s.push(v);
            }
            s.push(f64::NAN);
            all.sort_by(f64::total_cmp);
            let n = all.len();
            let at = |q: f64| all[((n - 1) as f64 * q).round() as usize];
            assert_eq!(s.range(), [at(RANGE[0]), at(RANGE[1])], "{runs}");
            let mean = 1e6 + all.iter().map(|v| v - 1e6).sum::<f64>() / n as f64;
            let (m, sd) = s.spread();
            assert!((m - mean).abs() < 1e-9, "{runs}");
            if n > 1 {
                let var = all.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
                assert!(
                    (sd - var.sqrt()).abs() < 1e-9 * (1.0 + var.sqrt()),
                    "{runs}"
                );
            }
            let beyond = all.iter().filter(|v| v.abs() > 1.5).count();
            assert_eq!(s.outside, beyond);
        }
    }
}
