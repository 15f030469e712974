//! KG (297): the net piston force by one mean piston area, beside (296), which the net-pressure
//! diagram draws with each side's own area.
//!
//! KG B.4a takes the piston force of a double-acting cylinder as P = p₁·F′ − p₂·F″ (296), F′
//! and F″ the effective areas of the two sides, which the rods make unequal, and adds that one
//! may set F = (F′ + F″)/2 and reckon P = F·(p₁ − p₂) = F·p_ü (297), p_ü read off the two
//! indicator diagrams laid over each other (Abb. 1054). On every ray of the net-pressure
//! diagram the two forces laid off, P₁ = F_w·p₁ and P₂ = F_b·p₂, are read back with the
//! dividers: divided by their own areas they give the pressures again, and F·p_ü follows. The
//! difference F·p_ü − P = (F − F_w)·p₁ − (F − F_b)·p₂ is what the approximation costs. Where a
//! side works with the card's highest pressure, F_w = P₁/p₁ is the effective area read back
//! off the drawing: KG's F′ = 1546,3 cm² and F″ = 1511,9 cm² of Tafel I.

use super::super::MeanArea;
use super::Builder;
use crate::crank::closed_form as cf;
use crate::protocol::{note, ConstructionError, Label, Note, Topic, Weighted, H};

const N_P1: Note = note(
    "working side’s force P₁ = F_w·p₁ taken off with the dividers",
    Some("Kolbendruck P₁"),
    "KG (296); LH Gl. 16-19",
    Topic::Forces,
);
const N_P2: Note = note(
    "back side’s force P₂ = F_b·p₂ taken off with the dividers",
    Some("Gegendruck P₂"),
    "KG (296)",
    Topic::Forces,
);
const N_MEAN: Note = note(
    "net piston force by the mean area: F·p_ü = F·(P₁/F_w − P₂/F_b), F = (F′+F″)/2",
    Some("Kolbenkraft aus mittlerer Kolbenfläche"),
    "KG (297), Abb. 1054",
    Topic::Forces,
);
const N_AREA: Note = note(
    "effective piston area read back: F_w = P₁/p₁ where the side works with its highest pressure",
    Some("wirksame Kolbenfläche"),
    "KG (296), Tafel I; LH Gl. 18",
    Topic::Forces,
);

const N_COVER: Note = note(
    "the cover side’s force p₁·F′ over the outstroke: the line through the heads of the working forces",
    Some("Kolbendruck der Deckelseite p₁·F′"),
    "KG B.4a, (296), Abb. 1055",
    Topic::Forces,
);
const N_CRANK: Note = note(
    "the crank side’s force p₂·F″ over the return: the line through the heads of the working forces",
    Some("Kolbendruck der Kurbelseite p₂·F″"),
    "KG B.4a, (296), Abb. 1055",
    Topic::Forces,
);

/// A stroke's working and back side on one ray: their effective areas (cm²) and the pressures
/// their cards give there (at).
#[derive(Clone, Copy)]
struct Sides {
    f_work: f64,
    f_back: f64,
    p_work: f64,
    p_back: f64,
}

/// What one ray gives: the angle, F·p_ü as read, the steam force P as read, P₁ taken off.
struct Read {
    theta: f64,
    by_mean: f64,
    by_sides: f64,
    p1: H<f64>,
}

impl Builder<'_> {
    fn sides(&self, c: usize, theta: f64) -> Sides {
        let cyl = self.cyl(c);
        let x = self.e.kinematics.x_frac(theta);
        let ((work, u_work), (back, u_back)) = cyl.sides(cf::book_angle(theta).0, x);
        Sides {
            f_work: work.area_cm2,
            f_back: back.area_cm2,
            p_work: work.indicator.working(u_work),
            p_back: back.indicator.back(u_back),
        }
    }

    /// KG (297) on every drawn ray of cylinder c, and the effective areas read back where
    /// each side works with its highest pressure.
    pub(super) fn mean_area(&mut self, c: usize) -> Result<MeanArea, ConstructionError> {
        let mut read = Vec::with_capacity(self.thetas.len());
        for k in 0..self.thetas.len() {
            read.push(self.mean_area_ray(c, k)?);
        }
        for stroke in [cf::Stroke::Out, cf::Stroke::Return] {
            self.side_force_line(c, stroke);
            self.area_read_back(c, stroke, &read);
        }
        self.b.clear_context();
        let cyl = self.cyl(c);
        let worst = read.iter().fold(None::<&Read>, |w, r| match w {
            Some(w) if (w.by_mean - w.by_sides).abs() >= (r.by_mean - r.by_sides).abs() => Some(w),
            _ => Some(r),
        });
        let largest = read.iter().fold(0.0f64, |m, r| m.max(r.by_sides.abs()));
        let (difference, at_deg) = worst.map_or((0.0, 0.0), |w| (w.by_mean - w.by_sides, w.theta));
        Ok(MeanArea {
            cover_cm2: cyl.cover.area_cm2,
            crank_cm2: cyl.crank.area_cm2,
            mean_cm2: cyl.mean_area_cm2(),
            difference,
            at_deg,
            relative: if largest > 0.0 {
                difference / largest
            } else {
                0.0
            },
        })
    }

    /// On ray k of cylinder c: P₁ and P₂ taken off, F·p_ü reckoned from them and checked
    /// against F·(p₁ − p₂) from the cards.
    fn mean_area_ray(&mut self, c: usize, k: usize) -> Result<Read, ConstructionError> {
        let ray = self.ray(c, k)?;
        let theta = self.crank_deg(c, k);
        let vertical = self.diagram(c)?.axis.vertical;
        let name = &self.e.cylinders[c].name;
        self.b
            .set_context(|| format!("{name}, θ = {}°", crate::fmt::num(theta, 3)));
        let scale = self.force_scale();
        let p1 = (self.b).measure(
            &ray.foot,
            &ray.work_point,
            &vertical,
            scale,
            Label::NONE,
            N_P1,
        );
        let p2 = (self.b).measure(
            &ray.steam_point,
            &ray.work_point,
            &vertical,
            scale,
            Label::NONE,
            N_P2,
        );
        let cyl = self.cyl(c);
        let (eta, mean) = (cyl.drawn_steam_share(), cyl.mean_area_cm2());
        let Sides {
            f_work: fw,
            f_back: fb,
            p_work: pw,
            p_back: pb,
        } = self.sides(c, theta);
        // The steam's forces as drawn carry η where a pump shares the rod: undone here, as
        // (297) is the steam's force.
        let by_mean = mean * (p1.g / fw - p2.g / fb) / eta;
        let by_sides = (p1.g - p2.g) / eta;
        let weight = mean / (eta * fw.min(fb));
        let inputs = [p1.id, p2.id];
        let value = self.b.reckon(
            by_mean,
            "kg",
            Label::NONE,
            Weighted {
                inputs: &inputs,
                weight,
            },
            N_MEAN,
        );
        let reference = (fw * pw).abs().max((fb * pb).abs()).max(self.force_refs[c]);
        self.b.check(
            &value,
            "net piston force by the mean area F·p_ü (KG 297)",
            "kg",
            "KG (297): F·(p₁ − p₂), F = (F′+F″)/2",
            reference,
            || mean * (pw - pb),
        );
        Ok(Read {
            theta,
            by_mean,
            by_sides,
            p1,
        })
    }

    /// The line of the working side's force over `stroke` through the heads of the forces
    /// laid up on the rays, lettered with the side's area: p₁·F′ on the cover side over the
    /// outstroke, p₂·F″ on the crank side over the return (KG (296)); the net pressure P lies
    /// the back side's force under it.
    fn side_force_line(&mut self, c: usize, stroke: cf::Stroke) {
        if !self.b.is_recording() {
            return;
        }
        let kin = self.e.kinematics;
        let mut on: Vec<(f64, H<crate::kernel::Point>)> = (0..self.thetas.len())
            .filter(|&k| cf::book_angle(self.crank_deg(c, k)).0 == stroke)
            .filter_map(|k| {
                let x = kin.x_frac(self.crank_deg(c, k));
                self.rays[c][k].map(|r| (x, r.work_point))
            })
            .collect();
        on.sort_by(|a, b| a.0.total_cmp(&b.0));
        let points: Vec<_> = on.into_iter().map(|(_, p)| p).collect();
        if points.len() < 2 {
            return;
        }
        let (name, note) = match stroke {
            cf::Stroke::Out => ("p₁·F′", N_COVER),
            cf::Stroke::Return => ("p₂·F″", N_CRANK),
        };
        self.b.clear_context();
        let mark = crate::protocol::Role::Construction.named(name);
        self.b
            .curve(&points, crate::protocol::Trace::Smooth, mark, note);
    }

    /// The effective area of the side working on `stroke`, read back as P₁/p₁ on the first
    /// ray where its card is highest: KG's F′ and F″.
    fn area_read_back(&mut self, c: usize, stroke: cf::Stroke, read: &[Read]) {
        let on: Vec<(&Read, Sides)> = (read.iter())
            .filter(|r| cf::book_angle(r.theta).0 == stroke)
            .map(|r| (r, self.sides(c, r.theta)))
            .collect();
        // Chosen by the card, not by the readings: the first ray of the highest pressure.
        let top = on.iter().fold(f64::MIN, |m, (_, s)| m.max(s.p_work));
        let Some(&(&Read { theta, p1, .. }, sides)) =
            on.iter().find(|(_, s)| s.p_work >= top - 1e-12 * top.abs())
        else {
            return;
        };
        let (area, pw) = (sides.f_work, sides.p_work);
        // A side whose highest pressure is nought (a card below the atmosphere) gives no area.
        if pw.abs() <= f64::EPSILON * area {
            return;
        }
        let eta = self.cyl(c).drawn_steam_share();
        let name = &self.e.cylinders[c].name;
        self.b
            .set_context(|| format!("{name}, θ = {}°", crate::fmt::num(theta, 3)));
        let weight = 1.0 / (eta * pw.abs());
        let value = self.b.reckon(
            p1.g / (eta * pw),
            "cm²",
            Label::NONE,
            Weighted {
                inputs: &[p1.id],
                weight,
            },
            N_AREA,
        );
        let side = match stroke {
            cf::Stroke::Out => "effective piston area F′ = P₁/p₁ (cover side)",
            cf::Stroke::Return => "effective piston area F″ = P₁/p₁ (crank side)",
        };
        self.b.check(
            &value,
            side,
            "cm²",
            "KG (296): π/4·(D² − d²)",
            area,
            || area,
        );
    }
}
