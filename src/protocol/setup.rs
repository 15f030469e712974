//! How the boards made during a call are set up: a reference replay beside f64, the error
//! model the bounds follow, or a draftsman's unsteady hand.
//!
//! The procedures make their own boards; a caller who wants the same construction replayed
//! differently sets the setup for the span of a call, as `tracing`'s `with_default` sets a
//! subscriber: [`with_setup`] holds for the current thread until the closure returns (or
//! panics), and the procedures stay as they are.
//!
//! ```
//! use graphostatik::prelude::*;
//! use graphostatik::protocol::{with_setup, Setup};
//! let b = with_setup(Setup { reference: true, ..Setup::default() }, Board::recording);
//! assert!(b.has_reference());
//! assert!(!Board::recording().has_reference());
//! ```

use super::accuracy::ErrorModel;
use crate::kernel::{Point, Vector};
use std::cell::Cell;

/// The setup of the boards made during a [`with_setup`] call.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Setup {
    /// Replay every step in double-double beside f64 (recording boards).
    pub reference: bool,
    /// The error model the propagated bounds follow; f64's rounding if `None`.
    pub model: Option<ErrorModel>,
    /// Draw with a draftsman's hand: every point, line, circle and reading perturbed at
    /// random by the hand's errors (the Monte Carlo replay of a drawing).
    pub hand: Option<Hand>,
    /// Keep the checks and not the drawing (recording boards): steps and objects are
    /// counted, every check is made and kept with its step and situation, and every bound
    /// is tracked, but captions, geometry and inputs are not filed. What `check` and
    /// `forces` use: the check table comes out the same, in memory of the order of the
    /// scene rather than of its protocol. No reference replay is made on such a board.
    pub checks_only: bool,
    /// On a board that keeps only its checks, keep every check however many (`check
    /// --all`): otherwise past [`LISTED_CHECKS`](super::LISTED_CHECKS) only their
    /// [`CheckSummary`](super::CheckSummary) is kept, a row per kind and every failure.
    pub every_check: bool,
}

/// A draftsman's hand: the errors of [`ErrorModel::drafting`] drawn at random (normally
/// distributed with those standard deviations), from a seed, so that a run is repeatable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hand {
    /// The standard deviations of the pencil, the set square and the scale rule.
    pub model: ErrorModel,
    /// The seed of this run.
    pub seed: u64,
}

thread_local! {
    static SETUP: Cell<Setup> = Cell::new(Setup::default());
}

/// Runs `f` with the boards it makes set up by `setup` (on this thread), and restores the
/// setup before, even if `f` panics.
pub fn with_setup<R>(setup: Setup, f: impl FnOnce() -> R) -> R {
    struct Restore(Setup);
    impl Drop for Restore {
        fn drop(&mut self) {
            SETUP.with(|s| s.set(self.0));
        }
    }
    let _restore = Restore(SETUP.with(|s| s.replace(setup)));
    f()
}

/// The setup in force on this thread.
pub(crate) fn current() -> Setup {
    SETUP.with(|s| s.get())
}

/// Whether the boards made now on this thread keep only their checks
/// ([`Setup::checks_only`]): a scene read for its checks may be larger than one read for
/// its figure, which must fit a sheet and a protocol of some 1 KB per step.
pub fn checks_only() -> bool {
    current().checks_only
}

/// The hand's random state on a board: SplitMix64, normal deviates by Box–Muller.
#[derive(Debug, Clone)]
pub(crate) struct Jitter {
    model: ErrorModel,
    state: u64,
    spare: Option<f64>,
}

impl Jitter {
    pub fn new(hand: Hand) -> Jitter {
        Jitter {
            model: hand.model,
            state: hand.seed ^ 0x9E37_79B9_7F4A_7C15,
            spare: None,
        }
    }

    fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A standard normal deviate.
    fn normal(&mut self) -> f64 {
        if let Some(s) = self.spare.take() {
            return s;
        }
        // Uniform in (0, 1]: never 0, so the logarithm is finite.
        let u1 = ((self.next_u64() >> 11) + 1) as f64 / (1u64 << 53) as f64;
        let u2 = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        let r = (-2.0 * u1.ln()).sqrt();
        let (s, c) = (std::f64::consts::TAU * u2).sin_cos();
        self.spare = Some(r * s);
        r * c
    }

    /// A point marked with the pencil.
    /// (A hand without that error leaves the value alone, bit for bit: adding 0.0 would turn
    /// a −0.0 into +0.0, and an angle taken of it by half a turn.)
    pub fn mark(&mut self, p: Point) -> Point {
        let m = self.model.mark_mm;
        if m == 0.0 {
            return p;
        }
        Point::new(p.x + m * self.normal(), p.y + m * self.normal())
    }

    /// A direction set with the set square or protractor (turned by a random angle).
    pub fn turn(&mut self, d: Vector) -> Vector {
        if self.model.angle_rad == 0.0 {
            return d;
        }
        let (s, c) = (self.model.angle_rad * self.normal()).sin_cos();
        Vector::new(d.x * c - d.y * s, d.x * s + d.y * c)
    }

    /// A length (mm) set on, or read off, the scale rule.
    pub fn read(&mut self, mm: f64) -> f64 {
        if self.model.read_mm == 0.0 {
            return mm;
        }
        mm + self.model.read_mm * self.normal()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hand_is_repeatable_and_has_the_spread_asked_for() {
        let hand = Hand {
            model: ErrorModel::drafting(0.1, 0.0, 0.0),
            seed: 7,
        };
        let (mut a, mut b) = (Jitter::new(hand), Jitter::new(hand));
        let xs: Vec<f64> = (0..20_000).map(|_| a.mark(Point::origin()).x).collect();
        let again: Vec<f64> = (0..20_000).map(|_| b.mark(Point::origin()).x).collect();
        assert_eq!(xs, again);
        let other = Jitter::new(Hand { seed: 8, ..hand })
            .mark(Point::origin())
            .x;
        assert_ne!(other, xs[0]);
        let mean = xs.iter().sum::<f64>() / xs.len() as f64;
        let sd = (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / xs.len() as f64).sqrt();
        assert!(
            mean.abs() < 0.003 && (sd - 0.1).abs() < 0.003,
            "{mean} {sd}"
        );
    }

    #[test]
    fn a_setup_holds_for_its_call_only() {
        let s = Setup {
            reference: true,
            ..Setup::default()
        };
        assert!(with_setup(s, || current().reference));
        assert!(!current().reference);
        let r = std::panic::catch_unwind(|| with_setup(s, || panic!("inside")));
        assert!(r.is_err() && !current().reference);
    }
}
