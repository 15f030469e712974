//! The pumps' resistance line (KG Abb. 1067): "die Widerstandslinie der Arbeitsmaschine
//! getrennt abzuleiten und sie mit der Drehkraftlinie der Kraftmaschine zu vergleichen".
//!
//! Each pump's force rectangle (P_p1 out, P_p2 back) is carried through a crank figure of its
//! own by the polar construction, as the steam's force is; its tangential force T_p is laid off
//! over a second developed crank circle, and on the same ordinate the turning force T of the
//! diagram above is transferred on top of it with the dividers: T_s = T + T_p, the steam
//! engine's own turning force, which the resistance line is compared with. Where T_s stands
//! above T_p the steam drives more than the pump takes.

use super::super::{model, rules, Resistance};
use super::turning::TurningFrame;
use super::Builder;
use crate::kernel::{Point, Vector};
use crate::protocol::{
    note, ConstructionError, Label, Note, ObjId, Reading, Role, Topic, Trace, Weighted, H,
};

const N_ARC: Note = note(
    "the arc r·θ laid off along the second developed circle",
    Some("Bogen r·α"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_ORD: Note = note(
    "ordinate at the developed crank position",
    Some("Ordinate"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_TP: Note = note(
    "the pumps’ resistance T_p laid off from the developed circle",
    Some("Widerstand der Pumpe"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_TP_READ: Note = note(
    "the pumps’ resistance T_p read off",
    Some("Widerstand der Pumpe"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_TS: Note = note(
    "the turning force T carried on top of T_p with the dividers: T_s = T + T_p",
    Some("Drehkraft der Kraftmaschine"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_TS_READ: Note = note(
    "the steam engine’s own turning force T_s read off",
    Some("Drehkraft der Kraftmaschine"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_CURVE_TP: Note = note(
    "the pumps’ resistance line: the rectangles give curves like sine lines",
    Some("Widerstandslinie der Arbeitsmaschine"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_CURVE_TS: Note = note(
    "the steam engine’s turning-force line, compared with the resistance line",
    Some("Drehkraftlinie der Kraftmaschine"),
    "KG Abb. 1067",
    Topic::Forces,
);
const N_MEAN: Note = note(
    "the mean resistance T_pm (trapezoid rule over the drawn ordinates)",
    Some("mittlerer Widerstand"),
    "KG Abb. 1067; LH G, Gl. 55",
    Topic::Forces,
);
const N_MEAN_LINE: Note = note(
    "the mean resistance carried along the developed circle",
    Some("mittlerer Widerstand"),
    "KG Abb. 1067",
    Topic::Forces,
);

/// The turning-force diagram's ordinates at the rays' shaft angles, as read (degrees, kg),
/// and the objects they were read as.
type Turning<'a> = (&'a [(f64, f64)], &'a [ObjId]);

/// The pumps' scale, and on every ordinate: the ends of T_p and T_s, and the two read off.
struct Drawn {
    /// The scale the pumps' checks are judged at: their largest forces, summed.
    pump_ref: f64,
    tp_ends: Vec<H<Point>>,
    ts_ends: Vec<H<Point>>,
    tp: Vec<H<f64>>,
    ts: Vec<H<f64>>,
}

impl Builder<'_> {
    /// The pumps' resistance line and the steam engine's turning force over a developed circle
    /// of their own, each ordinate read off and checked; `turning` is the turning-force
    /// diagram's ordinates at the shaft angles of the rays, as read (their objects in the
    /// second slice).
    pub(super) fn resistance_line(
        &mut self,
        turning: Turning<'_>,
    ) -> Result<Resistance, ConstructionError> {
        let origin = self.turning_origin() - Vector::new(0.0, self.row_height);
        let tp = self.pump_tangentials(origin)?;
        self.b.clear_context();
        let frame = self.developed_circle(origin)?;
        let n = turning.0.len();
        let mut d = Drawn {
            pump_ref: (self.e.cylinders.iter())
                .filter_map(|c| c.pump.map(|p| p.largest_force()))
                .sum(),
            tp_ends: Vec::with_capacity(n + 1),
            ts_ends: Vec::with_capacity(n + 1),
            tp: Vec::with_capacity(n + 1),
            ts: Vec::with_capacity(n + 1),
        };
        for k in 0..=n {
            self.resistance_ordinate(&frame, k, (&tp, turning), &mut d)?;
        }
        self.b.clear_context();
        self.b.curve(
            &d.ts_ends,
            Trace::Polygon,
            Role::Result.named("T_s"),
            N_CURVE_TS,
        );
        self.b.curve(
            &d.tp_ends,
            Trace::Polygon,
            Role::Reduced.named("T_p"),
            N_CURVE_TP,
        );
        let thetas: Vec<f64> = turning.0.iter().map(|p| p.0).collect();
        let mean = self.mean_resistance(&frame, &thetas, &d.tp[..n])?;
        let mean_exact: f64 = (self.e.cylinders.iter())
            .filter_map(|c| c.pump.map(|p| p.mean_resistance()))
            .sum();
        Ok(Resistance {
            ordinates: (0..n).map(|k| (thetas[k], d.tp[k].g, d.ts[k].g)).collect(),
            mean,
            mean_exact,
        })
    }

    /// Every pump's rectangle through a crank figure of its own right of the diagram at
    /// `origin`, one beside the other; per pump, its tangential force T_p on each ray as read
    /// off its polar figure.
    fn pump_tangentials(&mut self, origin: Point) -> Result<Vec<Vec<H<f64>>>, ConstructionError> {
        let n = self.thetas.len();
        let mut each = Vec::new();
        let (r, l) = (self.r_mm, self.rod_mm());
        let mut x = origin.x + std::f64::consts::TAU * r + 20.0 + l + r;
        for c in 0..self.e.cylinders.len() {
            let Some(pump) = self.cyl(c).pump else {
                continue;
            };
            let forces: Vec<f64> = (0..n)
                .map(|k| pump.force(crate::crank::closed_form::book_angle(self.crank_deg(c, k)).0))
                .collect();
            let widest = forces.iter().fold(0.0f64, |m, f| m.max(f.abs())) / self.dr.force_scale;
            let name = format!("{}: pump resistance", self.cyl(c).name);
            each.push(self.polar_construction(c, forces, Point::new(x, origin.y), name)?);
            // The next pump's figure right of this one's polar diagram.
            x += 2.0 * r + 0.15 * (r + l) + 2.1 * widest + 20.0 + l;
        }
        Ok(each)
    }

    /// The ordinate at the k-th shaft angle (k = n is 360°): every pump's T_p carried from its
    /// polar figure, one on top of the other, and read; T carried on top of them and T_s
    /// read, each checked against its closed form.
    fn resistance_ordinate(
        &mut self,
        fr: &TurningFrame,
        k: usize,
        (tp, (turning, ids)): (&[Vec<H<f64>>], Turning<'_>),
        d: &mut Drawn,
    ) -> Result<(), ConstructionError> {
        let n = turning.len();
        let kk = k % n;
        let theta = if k == n { 360.0 } else { turning[kk].0 };
        self.b
            .set_context(|| format!("resistance line, θ = {}°", crate::fmt::num(theta, 3)));
        let fs = self.dr.force_scale;
        let arc = self.r_mm * theta.to_radians();
        let at = (self.b).lay_off(&fr.o, &fr.axis, arc, Role::Construction, N_ARC)?;
        let ord = (self.b).perpendicular(&fr.axis, &at, Role::Construction, N_ORD);
        let mut tp_end = at;
        for pump in tp {
            let reading = Reading {
                value: &pump[kk],
                per_mm: fs,
            };
            tp_end = (self.b).transfer(&tp_end, &ord, reading, Role::Construction, N_TP)?;
        }
        let tp_read = (self.b).measure(
            &at,
            &tp_end,
            &fr.up,
            self.force_scale(),
            Label::NONE,
            N_TP_READ,
        );
        let (kin, cyls, eta) = (self.e.kinematics, &self.e.cylinders, self.e.efficiency);
        let pump_ref = d.pump_ref;
        self.b.check(
            &tp_read,
            "pumps’ resistance T_p = P_p·sin(φ ± ψ)/cos ψ",
            "kg",
            "KG Abb. 1067; KG (303)",
            pump_ref,
            || model::pump_resistance(&kin, cyls, theta),
        );
        let t = H {
            id: ids[kk],
            g: turning[kk].1,
        };
        let reading = Reading {
            value: &t,
            per_mm: fs,
        };
        let ts_end = (self.b).transfer(&tp_end, &ord, reading, Role::Construction, N_TS)?;
        let ts_read = (self.b).measure(
            &at,
            &ts_end,
            &fr.up,
            self.force_scale(),
            Label::NONE,
            N_TS_READ,
        );
        let reference = eta * self.force_refs.iter().sum::<f64>() + pump_ref;
        self.b.check(
            &ts_read,
            "steam engine’s turning force T_s = T + T_p",
            "kg",
            "KG Abb. 1067",
            reference,
            || model::steam_turning_force(&kin, cyls, eta, theta),
        );
        d.tp_ends.push(tp_end);
        d.ts_ends.push(ts_end);
        d.tp.push(tp_read);
        d.ts.push(ts_read);
        Ok(())
    }

    /// The mean resistance by the trapezoid rule over the drawn T_p (closed at 360°), checked
    /// against the same rule over the exact resistance, laid off and carried along the
    /// developed circle.
    fn mean_resistance(
        &mut self,
        fr: &TurningFrame,
        thetas: &[f64],
        tp: &[H<f64>],
    ) -> Result<f64, ConstructionError> {
        let at = |v: &dyn Fn(f64, usize) -> f64| -> Vec<(f64, f64)> {
            (thetas.iter().enumerate())
                .map(|(k, &t)| (t, v(t, k)))
                .collect()
        };
        let drawn = rules::trapezoid_revolution(&at(&|_, k| tp[k].g));
        let ids: Vec<ObjId> = tp.iter().map(|h| h.id).collect();
        let weighted = Weighted {
            inputs: &ids,
            weight: 1.0 / ids.len().max(1) as f64,
        };
        let mean = (self.b).reckon(drawn, "kg", Label::plain("T_pm"), weighted, N_MEAN);
        let (kin, cyls) = (self.e.kinematics, &self.e.cylinders);
        let exact = at(&|t, _| model::pump_resistance(&kin, cyls, t));
        let reference = tp.iter().fold(0.0f64, |m, h| m.max(h.g.abs()));
        self.b.check(
            &mean,
            "mean resistance T_pm by the trapezoid rule",
            "kg",
            "KG Abb. 1067; LH Gl. 55",
            reference,
            || rules::trapezoid_revolution(&exact),
        );
        self.mean_height(fr, (drawn, "T_pm"), (N_MEAN, N_MEAN_LINE))?;
        Ok(drawn)
    }
}
