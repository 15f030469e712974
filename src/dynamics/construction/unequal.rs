//! LH F's unequal abscissae for every cylinder: each cylinder's crank rays found by rod-length
//! arcs through its own stroke's equal parts (LH C.2, Abb. 59), so that its tangential forces
//! stand on the developed circle at abscissae of its own, the second cylinder's a quarter
//! circle on (LH F: "so muß das andere nach Abwicklung eines Viertelkreises … anfangen").
//!
//! Before the ordinates can be added, each cylinder's curve is drawn alone; at every abscissa
//! of either cylinder the ordinate of the other is then taken off its drawn curve, which
//! between two of its points is their chord, and laid on top with the dividers. The sum is
//! held to what that construction stands for: the exact η·T of a cylinder whose ray it is,
//! the chord between the exact values of its neighbours for one whose ray it is not. What the
//! chords cost against the exact turning force shows in the mean heights, which are measured
//! against the exact T_m.

use super::turning::{Foot, Ordinates, TurningFrame, N_T_FULL, N_T_SINGLE, N_T_SUM};
use super::Builder;
use crate::kernel::Point;
use crate::protocol::{note, ConstructionError, Label, Note, Reading, Role, Topic, H};

const N_SHIFT: Note = note(
    "a cylinder’s point carried a whole developed circle on, where its curve runs over the end",
    Some("Abwicklung, periodisch fortgesetzt"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_CHORD: Note = note(
    "a cylinder’s curve between two of its own points",
    Some("Tangentialdrucklinie eines Zylinders"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_CUT: Note = note(
    "the other cylinder’s curve cut by this ordinate",
    Some("Ordinate der anderen Kurve"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_TAKE: Note = note(
    "that ordinate taken off with the dividers",
    Some("Ordinate abgegriffen"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_ADD: Note = note(
    "a cylinder’s ordinate laid on top of the others: the ordinates added",
    Some("Ordinaten addiert"),
    "LH F, Abb. 67",
    Topic::Forces,
);

/// One of a cylinder's own ordinates.
#[derive(Clone, Copy)]
struct OwnPoint {
    /// Its shaft angle (degrees).
    theta: f64,
    /// η·T laid off alone from the developed circle.
    point: H<Point>,
    /// η·T from the model (kg).
    exact: f64,
    /// The length laid off (mm).
    len: f64,
}

/// One cylinder's own ordinates, ascending.
type Own = Vec<OwnPoint>;

/// The ends of the sum, the unreduced curve's points (η < 1), the points of each single
/// curve, and the sums read off.
pub(super) struct Unequal {
    pub ends: Vec<H<Point>>,
    pub full: Vec<H<Point>>,
    pub singles: Vec<Vec<H<Point>>>,
    pub ordinates: Ordinates,
}

impl Builder<'_> {
    /// Every cylinder's shaft angles, merged: the abscissae of the sum (degrees, ascending).
    fn abscissae(&self) -> Vec<f64> {
        let n = self.thetas.len();
        let mut all: Vec<f64> = (0..self.e.cylinders.len())
            .flat_map(|c| (0..n).map(move |k| (c, k)))
            .map(|(c, k)| self.shaft_deg(c, k))
            .collect();
        all.sort_by(f64::total_cmp);
        all.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
        all
    }

    /// The diagram's ordinates where the cylinders' abscissae differ: each one's own points
    /// first, then at every abscissa each cylinder's ordinate, its own or taken off its curve,
    /// laid on top of the others, the sum read off and checked.
    pub(super) fn unequal_ordinates(
        &mut self,
        fr: &TurningFrame,
    ) -> Result<Unequal, ConstructionError> {
        let mut feet = Vec::new();
        for theta in self.abscissae().into_iter().chain([360.0]) {
            feet.push(self.foot(fr, theta)?);
        }
        let nc = self.e.cylinders.len();
        let mut own: Vec<Own> = Vec::with_capacity(nc);
        for c in 0..nc {
            own.push(self.own_points(c, &feet)?);
        }
        let mut out = Unequal {
            ends: Vec::with_capacity(feet.len()),
            full: Vec::new(),
            singles: vec![Vec::new(); nc],
            ordinates: (Vec::new(), Vec::new()),
        };
        let last = feet.len() - 1;
        for (j, f) in feet.iter().enumerate() {
            let (end, sum) = self.add_up(fr, f, &own, &mut out.singles)?;
            out.ends.push(end);
            let eta = self.e.efficiency;
            if eta != 1.0 && self.b.is_recording() {
                let len = sum.g / (eta * self.dr.force_scale);
                let at = (self.b).lay_off(&f.at, &fr.up, len, Role::Construction, N_T_FULL)?;
                out.full.push(at);
            }
            if j < last {
                out.ordinates.0.push((f.theta, sum.g));
                out.ordinates.1.push(sum.id);
            }
        }
        self.b.clear_context();
        Ok(out)
    }

    /// Cylinder c's η·T laid off alone at each of its own abscissae (and at 360° where one of
    /// them is 0°), ascending.
    fn own_points(&mut self, c: usize, feet: &[Foot]) -> Result<Own, ConstructionError> {
        let n = self.thetas.len();
        let t = self.tangential[c].clone().unwrap_or_default();
        let eta = self.e.efficiency;
        let mut own: Own = Vec::with_capacity(n + 1);
        for f in feet {
            let theta = f.theta % 360.0;
            let Some(k) = (0..n).find(|&k| (self.shaft_deg(c, k) - theta).abs() < 1e-9) else {
                continue;
            };
            self.b
                .set_context(|| format!("θ = {}°", crate::fmt::num(f.theta, 3)));
            let len = eta * t[k].g / self.dr.force_scale;
            let reading = Reading {
                value: &t[k],
                per_mm: self.dr.force_scale / eta,
            };
            let p = (self.b).transfer(&f.at, &f.ord, reading, Role::Construction, N_T_SINGLE)?;
            let exact = self.exact_t(c, self.crank_deg(c, k));
            own.push(OwnPoint {
                theta: f.theta,
                point: p,
                exact,
                len,
            });
        }
        Ok(own)
    }

    /// η·T of cylinder c at its crank angle, from the model.
    fn exact_t(&self, c: usize, crank_deg: f64) -> f64 {
        self.e.efficiency * self.e.kinematics.tangential(self.cyl(c), crank_deg)
    }

    /// At the abscissa f: every cylinder's ordinate on top of the others, the sum read off
    /// and checked. Returns the end of the sum and the sum.
    fn add_up(
        &mut self,
        fr: &TurningFrame,
        f: &Foot,
        own: &[Own],
        singles: &mut [Vec<H<Point>>],
    ) -> Result<(H<Point>, H<f64>), ConstructionError> {
        self.b
            .set_context(|| format!("θ = {}°", crate::fmt::num(f.theta, 3)));
        let kf = self.dr.force_scale;
        let (mut end, mut closed) = (f.at, 0.0);
        for (c, pts) in own.iter().enumerate() {
            let (point, exact) = match pts.iter().find(|p| (p.theta - f.theta).abs() < 1e-9) {
                Some(p) => (p.point, p.exact),
                None => self.taken_off(fr, f, pts)?,
            };
            singles[c].push(point);
            let value = (self.b).measure(
                &f.at,
                &point,
                &fr.up,
                self.force_scale(),
                Label::NONE,
                N_TAKE,
            );
            end = (self.b).transfer(
                &end,
                &f.ord,
                Reading {
                    value: &value,
                    per_mm: kf,
                },
                Role::Force,
                N_ADD,
            )?;
            closed += exact;
        }
        let sum = (self.b).measure(
            &f.at,
            &end,
            &fr.up,
            self.force_scale(),
            Label::NONE,
            N_T_SUM,
        );
        let reference = self.e.efficiency * self.force_refs.iter().sum::<f64>();
        self.b.check(
            &sum,
            "turning force Σ η·T, the curves’ ordinates added",
            "kg",
            "LH F: each cylinder’s η·T on its own rays, between them its curve’s chord",
            reference,
            || closed,
        );
        Ok((end, sum))
    }

    /// Where cylinder `pts` has no ray at f: its curve, the chord between its neighbouring
    /// points, cut by f's ordinate. Where the curve runs over an end of the developed circle,
    /// its point beyond the other end is laid off a whole circle on, as the drafter continues
    /// the curve past the end. Returns the point cut and what the chord gives between the
    /// exact values.
    fn taken_off(
        &mut self,
        fr: &TurningFrame,
        f: &Foot,
        pts: &[OwnPoint],
    ) -> Result<(H<Point>, f64), ConstructionError> {
        let after = pts.iter().position(|p| p.theta > f.theta);
        let (first, last) = (pts[0], pts[pts.len() - 1]);
        let (a, b) = match after {
            Some(0) => (self.carried(fr, last, -360.0)?, first),
            Some(i) => (pts[i - 1], pts[i]),
            None => (last, self.carried(fr, first, 360.0)?),
        };
        // A carried point's foot had its own context.
        self.b
            .set_context(|| format!("θ = {}°", crate::fmt::num(f.theta, 3)));
        let chord = (self.b).line_through(&a.point, &b.point, Role::Construction, N_CHORD)?;
        let q = (self.b).meet_point(&f.ord, &chord, Label::NONE, N_CUT)?;
        let s = (f.theta - a.theta) / (b.theta - a.theta);
        Ok((q, a.exact + s * (b.exact - a.exact)))
    }

    /// The own point p laid off again `by` degrees along the developed circle.
    fn carried(
        &mut self,
        fr: &TurningFrame,
        p: OwnPoint,
        by: f64,
    ) -> Result<OwnPoint, ConstructionError> {
        let f = self.foot(fr, p.theta + by)?;
        let point = (self.b).lay_off(&f.at, &f.ord, p.len, Role::Construction, N_SHIFT)?;
        Ok(OwnPoint {
            theta: f.theta,
            point,
            ..p
        })
    }
}
