//! How a board is set up, in one explicit value: what it keeps ([`Mode`]), the error model
//! its bounds follow, a draftsman's hand, and a double-double reference replay.
//!
//! A procedure is handed the [`BoardConfig`] its caller chose and makes its boards from it;
//! nothing else (no thread-local, no global) changes what a construction gives.
//!
//! ```
//! use graphostatik::prelude::*;
//! use graphostatik::protocol::BoardConfig;
//! let b = Board::new(BoardConfig::DRAWING.with_reference());
//! assert!(b.has_reference() && b.is_drawing());
//! assert!(!Board::new(BoardConfig::CHECKS).is_drawing());
//! assert!(!Board::silent().is_recording());
//! ```

use super::accuracy::ErrorModel;
use crate::kernel::{Point, Vector};

/// What a board keeps of a construction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// Computes only: no step, object, bound or check kept (the fast path of the same
    /// procedure code; steps are counted).
    Silent,
    /// Records every step, object, bound and check: what a figure, a protocol and a
    /// walk-through are drawn from.
    #[default]
    Drawing,
    /// Keeps the checks and not the drawing: steps and objects are counted, every check is
    /// made and kept with its step and situation, and every bound is tracked, but captions,
    /// geometry and inputs are not filed. What `check` and `forces` use: the check table
    /// comes out the same, in memory of the order of the scene rather than of its protocol.
    /// No reference replay is made on such a board.
    Checks {
        /// Keep every check however many (`check --all`): otherwise past
        /// [`LISTED_CHECKS`](super::LISTED_CHECKS) only their
        /// [`CheckSummary`](super::CheckSummary) is kept, a row per kind and every failure.
        every: bool,
    },
}

/// How a board is set up: passed to [`Board::new`](super::Board::new), and by a caller to a
/// procedure's construction, which makes its boards from it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoardConfig {
    /// What the board keeps.
    pub mode: Mode,
    /// The error model the propagated bounds follow (f64's rounding by default).
    pub model: ErrorModel,
    /// Draw with a draftsman's hand: every point, line, circle and reading perturbed at
    /// random by the hand's errors (the Monte Carlo replay of a drawing).
    pub hand: Option<Hand>,
    /// Replay every step in double-double beside f64 (a drawing board only).
    pub reference: bool,
    /// The most steps a drawing board keeps (`None`: no limit). Past it the board lets go
    /// of what it kept and only counts, as a silent board does, so that a figure too large
    /// to draw is found by its step count at the cost of the limit's memory, not the
    /// figure's ([`Board::spilled`](super::Board::spilled)).
    pub keep_steps: Option<u32>,
}

impl Default for BoardConfig {
    fn default() -> Self {
        BoardConfig::DRAWING
    }
}

impl BoardConfig {
    /// A board that records everything ([`Mode::Drawing`]), bounds after f64's rounding.
    pub const DRAWING: BoardConfig = BoardConfig {
        mode: Mode::Drawing,
        model: ErrorModel::ROUNDING,
        hand: None,
        reference: false,
        keep_steps: None,
    };
    /// A board that only computes ([`Mode::Silent`]).
    pub const SILENT: BoardConfig = BoardConfig {
        mode: Mode::Silent,
        ..BoardConfig::DRAWING
    };
    /// A board that keeps its checks and not its drawing ([`Mode::Checks`]), summing them up
    /// past [`LISTED_CHECKS`](super::LISTED_CHECKS).
    pub const CHECKS: BoardConfig = BoardConfig {
        mode: Mode::Checks { every: false },
        ..BoardConfig::DRAWING
    };

    /// [`BoardConfig::DRAWING`] or [`BoardConfig::SILENT`], by the flag.
    pub const fn recording(recording: bool) -> BoardConfig {
        if recording {
            BoardConfig::DRAWING
        } else {
            BoardConfig::SILENT
        }
    }

    /// This setup with a double-double reference replay (kept on a drawing board only):
    /// every step is evaluated a second time in double-double from its inputs' reference
    /// values, and [`Board::reference_report`](super::Board::reference_report) then sets
    /// what f64 lost beside what the propagated bound predicted.
    ///
    /// ```
    /// use graphostatik::prelude::*;
    /// use graphostatik::protocol::BoardConfig;
    /// let mut b = Board::new(BoardConfig::DRAWING.with_reference());
    /// let n = Note::new("a glancing cut", Topic::Custom("demo"));
    /// let o = b.point(Point::new(0.0, 0.0), Role::Given.named("O"), n.clone());
    /// let a = b.point(Point::new(0.0, 1.0), Role::Given.named("A"), n.clone());
    /// let x = b.line_dir(&o, Vector::new(1.0, 0.0), Role::Axis, n.clone())?;
    /// let y = b.line_dir(&a, Vector::new(1.0, -1e-6), Role::Construction, n.clone())?;
    /// let p = b.meet_point(&x, &y, Label::plain("P"), n)?;
    /// let row = b.reference_report().into_iter().find(|r| r.step == b.steps()[4].id).unwrap();
    /// assert!(row.observed <= row.bound);       // f64 kept within the bound ...
    /// assert!(row.bound > 1e5 * 1e6 * 1e-16);  // ... which the 1e-6 rad cut amplified
    /// # Ok::<(), ConstructionError>(())
    /// ```
    pub const fn with_reference(self) -> BoardConfig {
        BoardConfig {
            reference: true,
            ..self
        }
    }

    /// This setup, keeping at most `steps` steps ([`BoardConfig::keep_steps`]).
    ///
    /// ```
    /// use graphostatik::prelude::*;
    /// use graphostatik::protocol::BoardConfig;
    /// let mut b = Board::new(BoardConfig::DRAWING.keeping_at_most(2));
    /// let n = Note::new("three points", Topic::Custom("demo"));
    /// for x in [0.0, 1.0, 2.0] {
    ///     b.point(Point::new(x, 0.0), Role::Given.named("P"), n.clone());
    /// }
    /// // The third step went past the limit: counted, nothing kept.
    /// assert!(b.spilled() && b.step_count() == 3 && b.steps().is_empty());
    /// ```
    pub const fn keeping_at_most(self, steps: u32) -> BoardConfig {
        BoardConfig {
            keep_steps: Some(steps),
            ..self
        }
    }

    /// This setup, its bounds following `model` (a draftsman's pencil and set squares:
    /// [`ErrorModel::drafting`]).
    pub const fn with_model(self, model: ErrorModel) -> BoardConfig {
        BoardConfig { model, ..self }
    }

    /// This setup, drawn by a draftsman's `hand`.
    pub const fn with_hand(self, hand: Hand) -> BoardConfig {
        BoardConfig {
            hand: Some(hand),
            ..self
        }
    }

    /// Whether checks are made and bounds tracked (any mode but [`Mode::Silent`]).
    pub const fn is_recording(&self) -> bool {
        !matches!(self.mode, Mode::Silent)
    }

    /// Whether only the checks are kept ([`Mode::Checks`]).
    pub const fn is_checks_only(&self) -> bool {
        matches!(self.mode, Mode::Checks { .. })
    }
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
}
