//! How far a constructed value can be off: a first-order error bound that every object on a
//! recording board carries, propagated through each step from the objects the step uses.
//!
//! The drafter knows the rule: a point found by two lines meeting at θ is off by `δ / sin θ`
//! when either line is off by `δ` across itself, and a line ruled through two points is
//! turned by their errors over their distance. Applied step by step, the rule gives every
//! point, line, circle and measured number a bound of its error, amplified by every cut it
//! depends on, not only by the last one. The crank's rod force S is found by cutting the rod
//! with a perpendicular after the crosshead was found by cutting the rod-length circle with
//! the guide: near λ = 1 at 90° both cuts are glancing, and S's error grows as the square of
//! their amplification, which the bound follows and the row's own cut angle would not.
//!
//! Which errors the steps add is an [`ErrorModel`]: f64's rounding
//! ([`ErrorModel::ROUNDING`], what a board uses) or a draftsman's pencil, set square and
//! scale rule ([`ErrorModel::drafting`]).

use super::step::StepId;
use crate::kernel::tolerance::OP_ROUNDOFF;
use crate::kernel::{Conditioning, Line, Point, Vector};
use serde::Serialize;

/// The errors each step adds before the amplification of the cuts.
///
/// ```
/// use graphostatik::protocol::ErrorModel;
/// let m = ErrorModel::drafting(0.1, 0.001, 0.05);
/// assert_eq!(m.mark_mm, 0.1);
/// assert!(ErrorModel::ROUNDING.rel < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ErrorModel {
    /// Relative error of every coordinate or number a step computes (f64's rounding).
    pub rel: f64,
    /// Error (mm) of every point marked and every line drawn: half a pencil line.
    pub mark_mm: f64,
    /// Error (rad) of every direction set with a set square or a protractor.
    pub angle_rad: f64,
    /// Error (mm) of every length set on, or read off, the scale rule.
    pub read_mm: f64,
}

impl ErrorModel {
    /// f64's rounding: [`OP_ROUNDOFF`] relative per step, nothing else.
    pub const ROUNDING: ErrorModel = ErrorModel {
        rel: OP_ROUNDOFF,
        mark_mm: 0.0,
        angle_rad: 0.0,
        read_mm: 0.0,
    };

    /// A draftsman: points and lines off by `mark_mm` (half the pencil line), directions by
    /// `angle_rad`, lengths by `read_mm` on the scale rule; f64's rounding besides.
    pub const fn drafting(mark_mm: f64, angle_rad: f64, read_mm: f64) -> ErrorModel {
        ErrorModel {
            rel: OP_ROUNDOFF,
            mark_mm,
            angle_rad,
            read_mm,
        }
    }

    fn round(&self, p: &Point) -> f64 {
        self.rel * p.coords.norm()
    }
}

/// The worst-conditioned cut a value depends on: its step and its meeting angle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WorstCut {
    /// The step of the cut.
    pub step: StepId,
    /// Its meeting angle and amplification.
    pub conditioning: Conditioning,
}

/// The worst cut a track depends on, as a board's tracks file it: the cut's place among
/// the cuts they keep (0: none; [`Worst::OWN`]: the cut the step being followed makes,
/// filed with its object) and its amplification, reckoned once when the cut is made, so
/// that comparing two cuts costs one comparison, not two `hypot`s.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Worst {
    pub amp: f64,
    pub place: u32,
}

impl Worst {
    /// No cut.
    pub const NONE: Worst = Worst { amp: 0.0, place: 0 };
    /// The place of the cut the step being followed makes, before it is filed.
    pub const OWN: u32 = u32::MAX;

    /// The cut the step being followed makes, at `cond`.
    pub fn own(cond: Conditioning) -> Worst {
        Worst {
            amp: cond.amplification(),
            place: Worst::OWN,
        }
    }

    /// Whether there is a cut.
    pub fn is_some(&self) -> bool {
        self.place != 0
    }

    /// The more glancing of two cuts (the larger amplification; the earlier one on a tie).
    #[inline]
    pub fn or_worse(self, other: Worst) -> Worst {
        if other.is_some() && (!self.is_some() || other.amp > self.amp) {
            other
        } else {
            self
        }
    }
}

/// The error bound an object carries. For a point: its distance from where it should be
/// (mm); for a line: its offset at its origin (mm) and its turn (rad), so that it is off by
/// `err + turn·d` at distance `d` along it; for a circle: its radial error (mm); for a number:
/// its error in its unit.
///
/// A point cut on a line that is known better than the other (a vertex of a funicular
/// polygon on its load's line of action) is off mostly along that line: it keeps the
/// line's direction as its `axis` and how far it can be off across it (`off`). A line then
/// drawn through the point is off across itself by the part of the error across its own
/// direction. Without this, each vertex of a polygon of n sides handed its whole error on
/// to the next side, amplified by the next cut: bounds grew as (1/sin θ)ⁿ (1e45 for a beam
/// of 2,000 loads whose real error is 2e-9), where the error itself grows as n.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Track {
    pub err: f64,
    pub turn: f64,
    pub worst: Worst,
    /// For a point: the direction (unit) its error is known to lie mostly along; zero if
    /// none is known.
    pub axis: Vector,
    /// For a point with an `axis`: its error across the axis (mm), at most `err`.
    pub off: f64,
}

impl Track {
    /// How far a line carrying this track is off across itself at `p`.
    pub fn across(&self, line: &Line, p: &Point) -> f64 {
        self.err + self.turn * (p - line.origin).norm()
    }

    /// How far a point carrying this track is off across a line through it in direction
    /// `dir`: the error's part along the axis turned into that line's normal, and its part
    /// across the axis; never more than the whole error.
    pub fn across_dir(&self, dir: &Vector) -> f64 {
        let n = dir.norm();
        if self.axis == Vector::zeros() || n.is_nan() || n <= 0.0 {
            return self.err;
        }
        let (sin, cos) = (self.axis.perp(dir).abs() / n, self.axis.dot(dir).abs() / n);
        self.err.min(self.err * sin + self.off * cos)
    }

    fn with(err: f64, turn: f64, worst: Worst) -> Track {
        Track {
            err,
            turn,
            worst,
            axis: Vector::zeros(),
            off: err,
        }
    }
}

/// The tracks of the kernel's steps under an error model.
impl ErrorModel {
    /// A given point.
    pub(crate) fn given(&self, p: &Point) -> Track {
        Track::with(self.round(p) + self.mark_mm, 0.0, Worst::NONE)
    }

    /// A line through a point in a given direction.
    pub(crate) fn line_at(&self, p: &Track, dir: &Vector) -> Track {
        Track::with(
            p.across_dir(dir) + self.mark_mm,
            self.angle_rad + self.rel,
            p.worst,
        )
    }

    /// The line from `a` through `b` (`len` mm apart).
    pub(crate) fn ruled(&self, a: &Track, b: &Track, len: f64) -> Track {
        let turn = (a.err + b.err + self.mark_mm) / len + self.rel;
        Track::with(a.err + self.mark_mm, turn, a.worst.or_worse(b.worst))
    }

    /// A parallel or perpendicular to a line through a point (set squares), in direction
    /// `dir`.
    pub(crate) fn slid(&self, line: &Track, p: &Track, dir: &Vector) -> Track {
        let turn = line.turn + self.angle_rad + self.rel;
        Track::with(
            p.across_dir(dir) + self.mark_mm,
            turn,
            line.worst.or_worse(p.worst),
        )
    }

    /// A circle of radius `r` about a centre (the compass set on the scale rule).
    pub(crate) fn compass(&self, c: &Track, center: &Point, r: f64) -> Track {
        let err = c.err + self.read_mm + self.mark_mm + self.rel * (center.coords.norm() + r);
        Track::with(err, 0.0, c.worst)
    }

    /// The point of a circle of radius `r` at a given angle (protractor or equal division).
    pub(crate) fn on_circle(&self, circle: &Track, p: &Point, r: f64) -> Track {
        let err = circle.err + self.round(p) + r * self.angle_rad + self.mark_mm;
        Track::with(err, 0.0, circle.worst)
    }

    /// `len` mm laid off from a point along a line, to `p`; `carried` is the error (mm) of a
    /// length taken from a value read earlier (the dividers' transfer).
    pub(crate) fn laid(
        &self,
        from: &Track,
        along: &Track,
        len: f64,
        p: &Point,
        carried: &Track,
    ) -> Track {
        let err = from.err
            + len.abs() * along.turn
            + carried.err
            + self.read_mm
            + self.mark_mm
            + self.round(p);
        Track::with(
            err,
            0.0,
            from.worst.or_worse(along.worst).or_worse(carried.worst),
        )
    }

    /// A point between two points at the ratio `t` (an equal division, a tangent divided).
    pub(crate) fn between(&self, a: &Track, b: &Track, t: f64, p: &Point) -> Track {
        let err = (1.0 - t).abs() * a.err + t.abs() * b.err + self.round(p) + self.mark_mm;
        Track::with(err, 0.0, a.worst.or_worse(b.worst))
    }

    /// The foot `f` of the perpendicular from a point (`at`) on a line.
    pub(crate) fn foot(
        &self,
        line: &Track,
        l: &Line,
        (p, at): (&Track, &Point),
        f: &Point,
    ) -> Track {
        let err = p.err
            + line.across(l, f)
            + self.angle_rad * (at - f).norm()
            + self.round(f)
            + self.mark_mm;
        Track::with(err, 0.0, line.worst.or_worse(p.worst))
    }

    /// The point `p` where two curves meet at `cond`, each off by `delta` (mm, summed) across
    /// itself there, `extent` the magnitude of the coordinates the cut computes with, `radius`
    /// the larger radius of a curved cut (`0` for two lines): `δ / sin θ`, and no more than
    /// the `√(2rδ) + δ` by which a circle shifted by `δ` moves a near-tangent point. `own` is
    /// the cut itself ([`Worst::own`]: its amplification).
    pub(crate) fn cut(
        &self,
        own: Worst,
        (delta, extent, radius): (f64, f64, f64),
        worst: Worst,
    ) -> Track {
        let delta = delta + self.rel * extent;
        let mut err = own.amp * delta;
        if radius > 0.0 {
            err = err.min((2.0 * radius * delta).sqrt() + delta);
        }
        Track::with(err + self.mark_mm, 0.0, worst.or_worse(own))
    }

    /// The point `p` where lines `a` and `b` meet at `cond`, each off by its `across` (mm)
    /// there: [`ErrorModel::cut`], and, since the point lies on the line known better, its
    /// error across that line is that line's own and the cut's rounding (the point keeps
    /// that line's direction as its axis).
    pub(crate) fn cut_lines(
        &self,
        own: Worst,
        (a, b): ((f64, Vector), (f64, Vector)),
        extent: f64,
        worst: Worst,
    ) -> Track {
        let mut t = self.cut(own, (a.0 + b.0, extent, 0.0), worst);
        let (across, dir) = if b.0 <= a.0 { b } else { a };
        let n = dir.norm();
        if n > 0.0 && n.is_finite() {
            let rounding = own.amp * self.rel * extent + self.mark_mm;
            t.axis = dir / n;
            t.off = (across + rounding).min(t.err);
        }
        t
    }

    /// A length between two points, read along a line's direction (`len` mm) at `per_mm`.
    pub(crate) fn measured(
        &self,
        ends: (&Track, &Track),
        axis: &Track,
        len: f64,
        per_mm: f64,
        at: (&Point, &Point),
    ) -> Track {
        let mm = ends.0.err
            + ends.1.err
            + len.abs() * axis.turn
            + self.read_mm
            + self.rel * (at.0.coords.norm() + at.1.coords.norm());
        let worst = ends.0.worst.or_worse(ends.1.worst).or_worse(axis.worst);
        Track::with(
            mm * per_mm.abs() + self.rel * (len * per_mm).abs(),
            0.0,
            worst,
        )
    }

    /// An angle (degrees) at a vertex between rays of lengths `lu` and `lv` mm.
    pub(crate) fn angle(
        &self,
        v: &Track,
        from: &Track,
        to: &Track,
        (lu, lv): (f64, f64),
        deg: f64,
    ) -> Track {
        let rad = (v.err + from.err) / lu + (v.err + to.err) / lv + self.angle_rad;
        let worst = v.worst.or_worse(from.worst).or_worse(to.worst);
        Track::with(rad.to_degrees() + self.rel * deg.abs(), 0.0, worst)
    }

    /// A number reckoned from numbers (each with its track and value): the sum of their
    /// errors and the rounding of summing them.
    pub(crate) fn reckoned<'a>(
        &self,
        inputs: impl Iterator<Item = &'a (Track, f64)>,
        value: f64,
    ) -> Track {
        let mut t = Track::with(self.rel * value.abs(), 0.0, Worst::NONE);
        for (i, v) in inputs {
            t.err += i.err + self.rel * v.abs();
            t.worst = t.worst.or_worse(i.worst);
        }
        t
    }
}
