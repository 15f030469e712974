//! The reference replay: every step of a construction evaluated a second time in
//! double-double arithmetic (about 32 digits, the `twofloat` crate), from its inputs'
//! double-double values.
//!
//! The procedures are not forked: the same procedure code drives a board, and a board made
//! with [`BoardConfig::with_reference`](super::BoardConfig::with_reference) evaluates each kernel step
//! twice, in f64 (the result the procedure goes on with) and in double-double from the
//! reference values of the step's inputs. The decisions (which branch of a cut, which case)
//! are taken once, in f64; the numbers a procedure hands a step (a length to lay off, a
//! ratio, a given point) are taken as exact. What f64 loses in the geometry, against the
//! same construction carried with twice the digits, is then measured per step and set
//! beside what the propagated bound ([`super::accuracy`]) predicted.

use super::accuracy::WorstCut;
use super::step::StepId;
use crate::kernel::{Point, Vector};
use serde::Serialize;
use twofloat::TwoFloat as D;

/// One step of the reference replay: how far f64 strayed from the double-double replay, and
/// how far the propagated bound said it could.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReferenceRow {
    /// The step.
    pub step: StepId,
    /// |f64 − reference| of the step's results, the largest (mm for a point, the unit for a
    /// number).
    pub observed: f64,
    /// The propagated bound of the same results, the largest.
    pub bound: f64,
    /// The magnitude the digits are counted against: the figure's size for a point, the
    /// value's (or its check's reference magnitude) for a number.
    pub scale: f64,
    /// The most glancing cut the results depend on.
    pub worst_cut: Option<WorstCut>,
}

impl ReferenceRow {
    /// The decimal digits f64 lost: log₁₀ of the observed error over one rounding of the
    /// scale (0 for a result exact to the last bit).
    pub fn digits_lost(&self) -> f64 {
        digits(self.observed, self.scale)
    }

    /// The digits the propagated bound predicted would be lost.
    pub fn digits_predicted(&self) -> f64 {
        digits(self.bound, self.scale)
    }
}

fn digits(err: f64, scale: f64) -> f64 {
    let ulp = f64::EPSILON / 2.0 * scale;
    if ulp > 0.0 && err.is_finite() {
        (err.max(ulp) / ulp).log10()
    } else if err.is_finite() {
        0.0
    } else {
        f64::INFINITY
    }
}

/// A point or vector in double-double.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DP {
    pub x: D,
    pub y: D,
}

impl DP {
    pub fn of(p: &Point) -> DP {
        DP {
            x: D::from(p.x),
            y: D::from(p.y),
        }
    }
    pub fn of_vec(v: &Vector) -> DP {
        DP {
            x: D::from(v.x),
            y: D::from(v.y),
        }
    }
    pub fn add(&self, o: &DP) -> DP {
        DP {
            x: self.x + o.x,
            y: self.y + o.y,
        }
    }
    pub fn sub(&self, o: &DP) -> DP {
        DP {
            x: self.x - o.x,
            y: self.y - o.y,
        }
    }
    pub fn scale(&self, k: D) -> DP {
        DP {
            x: self.x * k,
            y: self.y * k,
        }
    }
    pub fn dot(&self, o: &DP) -> D {
        self.x * o.x + self.y * o.y
    }
    pub fn cross(&self, o: &DP) -> D {
        self.x * o.y - self.y * o.x
    }
    pub fn norm(&self) -> D {
        self.dot(self).sqrt()
    }
    pub fn unit(&self) -> DP {
        let n = self.norm();
        if n.hi() > 0.0 {
            self.scale(D::from(1.0) / n)
        } else {
            *self
        }
    }
    /// Turned 90° counter-clockwise.
    pub fn normal(&self) -> DP {
        DP {
            x: -self.y,
            y: self.x,
        }
    }
    /// The distance (f64) of an f64 point from this one.
    pub fn off(&self, p: &Point) -> f64 {
        let dx = D::from(p.x) - self.x;
        let dy = D::from(p.y) - self.y;
        dx.hi().hypot(dy.hi())
    }
    /// `a (1 − t) + b t`, as the kernel divides a segment.
    pub fn between(a: &DP, b: &DP, t: f64) -> DP {
        let t = D::from(t);
        let s = D::from(1.0) - t;
        DP {
            x: a.x * s + b.x * t,
            y: a.y * s + b.y * t,
        }
    }
}

/// The reference value of an object.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) enum Shadow {
    /// Nothing to replay (a drawn segment, a curve, a table).
    #[default]
    None,
    /// A point.
    Point(DP),
    /// A line: a point on it and a unit direction.
    Line {
        /// Its origin.
        o: DP,
        /// Its unit direction.
        d: DP,
    },
    /// A circle.
    Circle {
        /// Its centre.
        c: DP,
        /// Its radius.
        r: D,
    },
    /// A number.
    Scalar(D),
}

/// The point where two lines meet: on the first line, as the kernel computes it.
pub(crate) fn meet(ao: &DP, ad: &DP, bo: &DP, bd: &DP) -> DP {
    let w = bo.sub(ao);
    let s = ad.cross(bd);
    let t = w.cross(bd) / s;
    ao.add(&ad.scale(t))
}

/// The two points where a line meets a circle (one twice for a tangency), the one nearer
/// the point the f64 step took first.
pub(crate) fn line_circle(o: &DP, d: &DP, c: &DP, r: D, near: &Point) -> DP {
    let t0 = c.sub(o).dot(d);
    let foot = o.add(&d.scale(t0));
    let h2 = r * r - c.sub(&foot).dot(&c.sub(&foot));
    let h = if h2.hi() > 0.0 {
        h2.sqrt()
    } else {
        D::from(0.0)
    };
    nearer(&foot.add(&d.scale(h)), &foot.sub(&d.scale(h)), near)
}

/// The two points where two circles meet (one twice for a tangency), the one nearer the
/// point the f64 step took.
pub(crate) fn circle_circle(c1: &DP, r1: D, c2: &DP, r2: D, near: &Point) -> DP {
    let v = c2.sub(c1);
    let d = v.norm();
    if d.hi() == 0.0 {
        return *c1;
    }
    let u = v.scale(D::from(1.0) / d);
    let a = (d * d + r1 * r1 - r2 * r2) / (d * D::from(2.0));
    let h2 = r1 * r1 - a * a;
    let h = if h2.hi() > 0.0 {
        h2.sqrt()
    } else {
        D::from(0.0)
    };
    let m = c1.add(&u.scale(a));
    nearer(
        &m.add(&u.normal().scale(h)),
        &m.sub(&u.normal().scale(h)),
        near,
    )
}

fn nearer(p: &DP, q: &DP, near: &Point) -> DP {
    if p.off(near) <= q.off(near) {
        *p
    } else {
        *q
    }
}

/// The angle (degrees) at `v` from the ray through `a` to the ray through `b`, in [0°, 180°].
pub(crate) fn angle_deg(v: &DP, a: &DP, b: &DP) -> D {
    let (u, w) = (a.sub(v), b.sub(v));
    let rad = u.cross(&w).abs().atan2(u.dot(&w));
    rad * D::from(180.0) / twofloat::consts::PI
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_glancing_meeting_point_has_its_digits_in_double_double() {
        // Lines at 1e-8 rad meeting at x = 1e8: f64 loses about 8 digits, double-double not.
        let o = DP::of(&Point::new(0.0, 0.0));
        let d = DP::of_vec(&Vector::new(1.0, 0.0));
        let bo = DP::of(&Point::new(0.0, 1.0));
        let bd = DP::of_vec(&Vector::new(1.0, -1e-8)).unit();
        let p = meet(&o, &d, &bo, &bd);
        assert!((p.x - D::from(1e8)).abs().hi() < 1e-14 * 1e8);
        assert_eq!(p.y.hi(), 0.0);
    }

    #[test]
    fn circle_cuts_pick_the_branch_of_the_f64_step() {
        let c1 = DP::of(&Point::new(0.0, 0.0));
        let c2 = DP::of(&Point::new(1.0, 0.0));
        let up = circle_circle(&c1, D::from(1.0), &c2, D::from(1.0), &Point::new(0.5, 0.8));
        let down = circle_circle(&c1, D::from(1.0), &c2, D::from(1.0), &Point::new(0.5, -0.8));
        assert!(up.y.hi() > 0.86 && down.y.hi() < -0.86);
        let l = line_circle(
            &c1,
            &DP::of_vec(&Vector::new(1.0, 0.0)),
            &c2,
            D::from(1.0),
            &Point::new(2.1, 0.0),
        );
        assert_eq!(l.x.hi(), 2.0);
    }
}
