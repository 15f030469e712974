//! The turning-force diagram over the developed crank circle (LH F, Abb. 67; KG Abb. 1064):
//! each cylinder's tangential force laid off at the arc r·θ, the ordinates of the cylinders
//! added with the dividers, η applied.

use super::super::model;
use super::Builder;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{note, ConstructionError, Label, Note, Reading, Role, Topic, Trace, H};

const N_AXIS_O: Note = note(
    "start of the developed crank circle",
    Some("Abwicklung des Kurbelkreises"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_AXIS: Note = note(
    "the crank circle developed on a straight line, 2πr long",
    Some("abgewickelte Kurbelkreislinie"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_ANGLES: Note = note(
    "the crank angles written under the developed circle",
    Some("Kurbelwinkel"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_ARC: Note = note(
    "the arc r·θ laid off along the developed circle",
    Some("Bogen r·α"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_ORD: Note = note(
    "ordinate at the developed crank position",
    Some("Ordinate"),
    "LH Abb. 67",
    Topic::Forces,
);
const N_T_EACH: Note = note(
    "a cylinder’s tangential force (times η) laid off on top of the others",
    Some("Tangentialdruck, Ordinaten addiert"),
    "LH F; KG Abb. 1064",
    Topic::Forces,
);
pub(super) const N_T_SINGLE: Note = note(
    "a cylinder’s tangential force (times η) laid off alone from the developed circle",
    Some("Tangentialdruck eines Zylinders"),
    "LH F, Abb. 67",
    Topic::Forces,
);
const N_CURVE_SINGLE: Note = note(
    "a single cylinder’s turning-force curve, drawn before their sum",
    Some("Tangentialdrucklinie eines Zylinders"),
    "LH F, Abb. 67; KG Abb. 1064",
    Topic::Forces,
);
pub(super) const N_T_SUM: Note = note(
    "turning force on the shaft read off",
    Some("resultierender Tangentialdruck"),
    "LH Abb. 67; KG Abb. 1062, 1064",
    Topic::Forces,
);
const N_MEAN_AT: Note = note(
    "the mean height T_m laid off (trapezoid rule over the drawn ordinates)",
    Some("mittlerer Tangentialdruck"),
    "LH G, Gl. 55, 60",
    Topic::Forces,
);
const N_MEAN_LINE: Note = note(
    "the mean resistance: the rectangle of equal area",
    Some("Widerstandslinie, Rechteck abcd"),
    "LH J; KG Abb. 1064",
    Topic::Forces,
);
pub(super) const N_T_FULL: Note = note(
    "the turning force before the reduction by η: the cylinders’ T laid off as one length",
    Some("Tangentialdruck ohne Wirkungsgrad"),
    "KG Abb. 1062",
    Topic::Forces,
);
const N_CURVE_FULL: Note = note(
    "the turning force before the reduction by η",
    Some("Tangentialdrucklinie"),
    "KG Abb. 1062",
    Topic::Forces,
);
const N_CURVE: Note = note(
    "turning-force diagram",
    Some("Tangentialdruckdiagramm"),
    "LH Abb. 67; KG Abb. 1064",
    Topic::Forces,
);

impl Builder<'_> {
    /// Where the turning-force diagram's axis begins on the sheet.
    pub(super) fn turning_origin(&self) -> Point {
        let nc = self.e.cylinders.len() as f64;
        Point::new(-self.r_mm, -(nc - 0.3) * self.row_height)
    }

    /// The diagram: the sum of the cylinders' T at every shaft angle and at 360°, read off and
    /// checked against [`model::turning_force`]. Returns (θ, T) per shaft angle.
    pub(super) fn turning_diagram(&mut self) -> Result<Ordinates, ConstructionError> {
        let frame = self.developed_circle(self.turning_origin())?;
        let nc = self.e.cylinders.len();
        let (pts, full, singles, (out, ids)) = if self.stroke_parts.is_some() && nc > 1 {
            let u = self.unequal_ordinates(&frame)?;
            let singles = if self.b.is_recording() {
                u.singles
            } else {
                Vec::new()
            };
            (u.ends, u.full, singles, u.ordinates)
        } else {
            self.equal_ordinates(&frame)?
        };
        self.b.clear_context();
        // Where η < 1, KG Abb. 1062 draws the turning force before and after the reduction:
        // T in a full line, η·T, which the resistance is measured against, dashed
        // ("gestrichelte Linie").
        let role = if full.is_empty() {
            Role::Result.named("T")
        } else {
            self.b
                .curve(&full, Trace::Polygon, Role::Result.named("T"), N_CURVE_FULL);
            Role::Reduced.named("η·T")
        };
        self.b.curve(&pts, Trace::Polygon, role, N_CURVE);
        let mean = self.mean_line(&frame, &out)?;
        self.excess_areas(&pts, (&mean.0, &mean.1))?;
        // The single cylinders' curves after the areas' signs, so that their names are
        // placed clear of them.
        for (c, single) in singles.iter().enumerate() {
            let name = Label::named(self.e.cylinders[c].name.clone());
            let mark = Role::Construction.labelled(name);
            self.b.curve(single, Trace::Polygon, mark, N_CURVE_SINGLE);
        }
        Ok((out, ids))
    }

    /// The crank circle developed on a straight line from `origin`, its ordinate direction,
    /// and the crank angles written under it every 90°.
    pub(super) fn developed_circle(
        &mut self,
        origin: Point,
    ) -> Result<TurningFrame, ConstructionError> {
        let o = self.b.point(origin, Role::Given.named("0"), N_AXIS_O);
        let axis = self
            .b
            .line_dir(&o, Vector::new(1.0, 0.0), Role::Axis, N_AXIS)?;
        let up = self.b.perpendicular(&axis, &o, Role::Axis, N_ORD);
        let mm_per_deg = self.r_mm * std::f64::consts::PI / 180.0;
        super::super::angle_marks(self.b, o.g, (mm_per_deg, 90.0, 360.0), N_ANGLES);
        Ok(TurningFrame { o, axis, up })
    }

    /// The ordinates where every cylinder has a ray at every shaft angle: at each, the
    /// cylinders' η·T laid off on top of each other.
    fn equal_ordinates(&mut self, frame: &TurningFrame) -> Result<Drawn, ConstructionError> {
        let n = self.thetas.len();
        let mut pts: Vec<H<Point>> = Vec::with_capacity(n + 1);
        let mut full: Vec<H<Point>> = Vec::new();
        let nc = self.e.cylinders.len();
        let mut singles: Vec<Vec<H<Point>>> = vec![Vec::new(); if nc > 1 { nc } else { 0 }];
        let (mut out, mut ids) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for k in 0..=n {
            let (foot, end, sum) = self.turning_ordinate(frame, k, &mut singles)?;
            pts.push(end);
            full.extend(self.unreduced(frame, k, &foot)?);
            if k < n {
                out.push((self.thetas[k], sum.g));
                ids.push(sum.id);
            }
        }
        Ok((pts, full, singles, (out, ids)))
    }

    /// Where η < 1, on a board that records, the k-th ordinate's turning force before the
    /// reduction, the cylinders' T laid off as one length, for the unreduced curve of KG
    /// Abb. 1062.
    fn unreduced(
        &mut self,
        fr: &TurningFrame,
        k: usize,
        foot: &H<Point>,
    ) -> Result<Option<H<Point>>, ConstructionError> {
        let eta = self.e.efficiency;
        if eta == 1.0 || !self.b.is_recording() {
            return Ok(None);
        }
        let kk = k % self.thetas.len();
        let t: f64 = (self.tangential.iter())
            .map(|t| t.as_ref().map_or(0.0, |t| t[kk].g))
            .sum();
        let at = self.b.lay_off(
            foot,
            &fr.up,
            t / self.dr.force_scale,
            Role::Construction,
            N_T_FULL,
        )?;
        Ok(Some(at))
    }

    /// The foot and ordinate of the abscissa θ on the developed circle (360° is its end),
    /// the check context set to θ.
    pub(super) fn foot(
        &mut self,
        fr: &TurningFrame,
        theta: f64,
    ) -> Result<Foot, ConstructionError> {
        self.b
            .set_context(|| format!("θ = {}°", crate::fmt::num(theta, 3)));
        let arc = self.r_mm * theta.to_radians();
        let at = (self.b).lay_off(&fr.o, &fr.axis, arc, Role::Construction, N_ARC)?;
        let ord = (self.b).perpendicular(&fr.axis, &at, Role::Construction, N_ORD);
        Ok(Foot { theta, at, ord })
    }

    /// The ordinate at the k-th shaft angle (k = n is 360°): every cylinder's η·T laid off on
    /// top of the others, the sum read off and checked; where there are several cylinders
    /// and the board records, each one's η·T laid off alone too, its point added to
    /// `singles` (LH F draws the single cylinders' curves before their sum). Returns the
    /// ordinate's foot on the developed circle, its end and the sum.
    fn turning_ordinate(
        &mut self,
        fr: &TurningFrame,
        k: usize,
        singles: &mut [Vec<H<Point>>],
    ) -> Result<Ordinate, ConstructionError> {
        let n = self.thetas.len();
        let kk = k % n;
        let theta = if k == n { 360.0 } else { self.thetas[kk] };
        let Foot { at: a, ord, .. } = self.foot(fr, theta)?;
        let mut end = a;
        for c in 0..self.e.cylinders.len() {
            // η·T carried from the polar figure with the dividers: its bound follows it.
            let t = (self.tangential[c].as_ref()).map_or(H::NONE_ZERO, |t| t[kk]);
            let reading = Reading {
                value: &t,
                per_mm: self.dr.force_scale / self.e.efficiency,
            };
            end = self
                .b
                .transfer(&end, &ord, reading, Role::Force, N_T_EACH)?;
            if let Some(single) = singles.get_mut(c).filter(|_| self.b.is_recording()) {
                // The first cylinder's lies at the bottom of the sum: its point is the sum's
                // first; every other is laid off from the circle alone.
                single.push(match c {
                    0 => end,
                    _ => (self.b).transfer(&a, &ord, reading, Role::Construction, N_T_SINGLE)?,
                });
            }
        }
        let sum = self
            .b
            .measure(&a, &end, &fr.up, self.force_scale(), Label::NONE, N_T_SUM);
        let (kin, cyls, eta) = (self.e.kinematics, &self.e.cylinders, self.e.efficiency);
        let reference = eta * self.force_refs.iter().sum::<f64>();
        self.b.check(
            &sum,
            "turning force Σ η·T",
            "kg",
            "LH F; KG (303)",
            reference,
            || model::turning_force(&kin, cyls, eta, theta),
        );
        Ok((a, end, sum))
    }

    /// The rectangle of equal area: the mean resistance over the developed circle, at the
    /// trapezoid mean of the drawn ordinates.
    /// Returns the mean line's ends, at 0° and at 360°.
    fn mean_line(
        &mut self,
        fr: &TurningFrame,
        out: &[(f64, f64)],
    ) -> Result<(H<Point>, H<Point>), ConstructionError> {
        let mean = super::super::rules::trapezoid_revolution(out);
        self.mean_height(fr, (mean, "T_m"), (N_MEAN_AT, N_MEAN_LINE))
    }

    /// A mean height `value` (kg) laid off from the developed circle's start, named `name`,
    /// and carried along the whole circle, 2πr. Returns the line's ends, at 0° and at 360°.
    pub(super) fn mean_height(
        &mut self,
        fr: &TurningFrame,
        (value, name): (f64, &'static str),
        (at_note, line_note): (Note, Note),
    ) -> Result<(H<Point>, H<Point>), ConstructionError> {
        let m = self.b.lay_off(
            &fr.o,
            &fr.up,
            value / self.dr.force_scale,
            Role::Construction.named(name),
            at_note,
        )?;
        let line = self
            .b
            .parallel(&fr.axis, &m, Role::Auxiliary, line_note.clone());
        let tau = std::f64::consts::TAU;
        let end = (self.b).lay_off(&m, &line, self.r_mm * tau, Role::Auxiliary, line_note)?;
        Ok((m, end))
    }
}

/// The turning force at each shaft angle (degrees, kg) and the objects it was read as.
pub(super) type Ordinates = (Vec<(f64, f64)>, Vec<crate::protocol::ObjId>);

/// One ordinate of the turning-force diagram: its foot on the developed circle, its end, and
/// the sum read off.
type Ordinate = (H<Point>, H<Point>, H<f64>);

/// What the diagram's ordinates draw: the sum's ends, the unreduced curve's points (η < 1),
/// each cylinder's single curve, and the sums read off.
type Drawn = (Vec<H<Point>>, Vec<H<Point>>, Vec<Vec<H<Point>>>, Ordinates);

/// Where an abscissa stands on the developed circle: its angle, its foot and its ordinate.
pub(super) struct Foot {
    pub(super) theta: f64,
    pub(super) at: H<Point>,
    pub(super) ord: H<Line>,
}

/// The axis of the developed crank circle, its start and its ordinate direction.
pub(super) struct TurningFrame {
    pub(super) o: H<Point>,
    pub(super) axis: H<Line>,
    pub(super) up: H<Line>,
}
