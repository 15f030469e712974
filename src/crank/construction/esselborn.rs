//! Esselborn's construction of the crank position of the largest piston velocity (LH B.2,
//! Abb. 52): at the dead centre T₁ of the crank circle erect the perpendicular T₁B₁ = L, swing
//! B₁ about O onto the piston line at B, and the arc of L about B cuts the crank circle at A,
//! where the rod OA ⊥ AB stands perpendicular to the crank (the triangle OT₁B₁ turned about O).
//!
//! The rod-perpendicular position is the book's claim for the maximum; the exact maximum lies
//! a little later (79.100° against 78.690° for R/L = 1/5), and LH's printed 79°16' is neither:
//! it is the zero of the approximate acceleration, Gl. 29. The three are set side by side.

use super::super::closed_form as cf;
use super::{Builder, MaxVelocity};
use crate::kernel::{Branch, Circle, Line, Point, Vector};
use crate::protocol::{
    note, ConstructionError, Drawn, Label, Note, Role, Scale, Topic, Weighted, H,
};

const N_MEAN_SPEED: Note = note(
    "the mean piston speed c_m as the mean of the drawn velocities over equal times of a stroke",
    Some("mittlere Kolbengeschwindigkeit"),
    "LH B.2, Gl. 26",
    Topic::Velocity,
);
const N_MEAN: Note = note(
    "the largest piston velocity against the mean piston speed c_m = 2v/π",
    Some("mittlere Kolbengeschwindigkeit"),
    "LH B.2",
    Topic::Velocity,
);
const N_PERP: Note = note(
    "perpendicular to the piston line at the dead centre T₁",
    Some("Lot in T₁"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_B1: Note = note(
    "lay off T₁B₁ = L on it",
    Some("T₁B₁ = l"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_OB1: Note = note(
    "join B₁ with O: the triangle OT₁B₁, turned about O until OB₁ falls on the piston line, \
     gives B",
    Some("B₁ mit O verbinden"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_SWING: Note = note(
    "swing B₁ about O (the triangle OT₁B₁ turned about O)",
    Some("Drehung um O"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_B: Note = note(
    "the arc cuts the piston line: crosshead B",
    Some("Kreuzkopf B"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_ROD_ARC: Note = note(
    "arc with the rod length L about B",
    Some("Schubstangenkreisbogen"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_A: Note = note(
    "it cuts the crank circle at A: the rod stands perpendicular to the crank",
    Some("Kurbelstellung für c_max"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_A_INF: Note = note(
    "infinite rod: the crank on the vertical through O",
    Some("Kurbelstellung für c_max"),
    "LH Abb. 54",
    Topic::Velocity,
);
const N_ROD_INF: Note = note(
    "infinite rod: the rod direction parallel to the piston line",
    Some("Schubstangenrichtung"),
    "LH Abb. 54",
    Topic::Velocity,
);
const N_CRANK: Note = note(
    "crank OA and rod AB",
    Some("Kurbel und Schubstange"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_ANGLE: Note = note(
    "crank angle of A from the dead centre",
    Some("Kurbelwinkel α"),
    "LH B.2",
    Topic::Velocity,
);
const N_A2: Note = note(
    "on the return: the arc about B cuts the crank circle again, under the piston line, at A′",
    Some("Kurbelstellung für c_max auf dem Rückgang"),
    "LH B.2, Abb. 52",
    Topic::Velocity,
);
const N_CRANK2: Note = note(
    "crank OA′ and rod A′B on the return",
    Some("Kurbel und Schubstange"),
    "LH B.2, Abb. 52",
    Topic::Velocity,
);
const N_DEAD2: Note = note(
    "the dead centre where the return begins",
    Some("Totpunkt"),
    "LH B.2",
    Topic::Velocity,
);
const N_ANGLE2: Note = note(
    "crank angle of A′, counted from the dead centre where the return begins",
    Some("Kurbelwinkel auf dem Rückgang"),
    "LH B.2",
    Topic::Velocity,
);
const N_RIGHT: Note = note(
    "the angle at A between crank and rod",
    Some("rechter Winkel bei A"),
    "LH Abb. 52",
    Topic::Velocity,
);
const N_V: Note = note(
    "v laid off on the crank ray OA",
    Some("Kurbelzapfengeschwindigkeit v"),
    "KG Abb. 1049",
    Topic::Velocity,
);
const N_PAR: Note = note(
    "parallel to the rod through the end of v cuts the vertical: c at A",
    Some("Kolbengeschwindigkeit"),
    "KG Abb. 1049",
    Topic::Velocity,
);
const N_C: Note = note(
    "piston velocity at Esselborn’s position",
    Some("c_max"),
    "LH Gl. 25; KG (288)",
    Topic::Velocity,
);

/// Esselborn's figure: the crosshead B (or a point of the infinite rod), the pin A, the rod,
/// and the rod-length arc about B where the rod is finite.
type Position = (H<Point>, H<Point>, H<Line>, Option<H<Circle>>);

impl Builder<'_> {
    /// Esselborn's construction, the velocity there by the parallel to the rod, and the exact
    /// and book angles beside it.
    pub(super) fn esselborn(&mut self) -> Result<MaxVelocity, ConstructionError> {
        let f = self.frame()?;
        let (o, axis, vertical, circle, dead) =
            (f.o, f.piston_line, f.vertical, f.crank_circle, f.dead);
        let (b_pt, a, rod, arc) = if self.d.finite_rod {
            self.esselborn_point(o, axis, circle, dead)?
        } else {
            self.infinite_rod_point(o, axis, vertical, circle)?
        };
        let angle = self
            .b
            .measure_angle(&o, &dead, &a, Label::plain("α"), N_ANGLE);
        let lam = self.lambda();
        self.b.check(
            &angle,
            "crank angle of the rod perpendicular to the crank (Esselborn)",
            "°",
            "tg α = L/R (LH Abb. 52)",
            90.0,
            || cf::rod_perpendicular_angle(lam),
        );
        let right = self.b.measure_angle(&a, &o, &b_pt, Label::NONE, N_RIGHT);
        self.b.check(
            &right,
            "angle between crank and rod at A",
            "°",
            "LH Abb. 52",
            90.0,
            || 90.0,
        );
        let c = self.esselborn_velocity(o, vertical, a, rod)?;
        let v = self.d.crank_pin_speed;
        let phi = angle.g;
        self.b.check(
            &c,
            "piston velocity at Esselborn’s position",
            "m/s",
            "c = v sin(α + β)/cos β (KG 288)",
            v,
            || v * cf::sin_factor(lam, phi, cf::Stroke::Out),
        );
        self.against_mean_speed(&c, (lam, phi));
        self.v_over_mean_speed();
        self.on_the_return((b_pt, a, rod, arc))?;
        let exact = cf::max_velocity_angle(lam);
        Ok(MaxVelocity {
            esselborn_deg: angle.g,
            c_esselborn: c.g,
            exact_deg: exact,
            c_max: v * cf::sin_factor(lam, exact, cf::Stroke::Out),
            book_deg: cf::approx_zero_acceleration_angle(lam),
        })
    }

    /// The largest piston velocity against the mean piston speed c_m = 2s·n/60 = 2v/π
    /// (LH B.2: c_max = 1.6 c_m for r/l = 1/5), reckoned from the constructed c.
    fn against_mean_speed(&mut self, c: &H<f64>, (lam, phi): (f64, f64)) {
        let c_m = 2.0 * self.d.crank_pin_speed / std::f64::consts::PI;
        let ratio = self.b.reckon(
            c.g / c_m,
            "",
            Label::quiet("c", 1),
            Weighted {
                inputs: &[c.id],
                weight: 1.0 / c_m,
            },
            N_MEAN,
        );
        self.b.check(
            &ratio,
            "c_max / c_m, the mean piston speed c_m = 2v/π",
            "",
            "LH B.2: c_m = 2s·n/60",
            1.0,
            || cf::sin_factor(lam, phi, cf::Stroke::Out) * std::f64::consts::FRAC_PI_2,
        );
    }

    /// LH Gl. 26, v/c_m = π/2, with c_m the piston's mean speed over a stroke read off the
    /// construction: the drawn velocities at equal crank angles (equal times) from dead centre
    /// to dead centre, their mean by Simpson's rule, and held to the same rule over the exact
    /// velocities. Only where the velocity is constructed on an even number of equal strips
    /// of the outstroke.
    fn v_over_mean_speed(&mut self) {
        let mut idx: Vec<usize> = (0..self.thetas.len())
            .filter(|&i| self.thetas[i] <= 180.0 + 1e-9)
            .collect();
        idx.sort_by(|a, b| self.thetas[*a].total_cmp(&self.thetas[*b]));
        let m = idx.len().saturating_sub(1);
        let step = 180.0 / m.max(1) as f64;
        let equal =
            (idx.iter().enumerate()).all(|(j, &i)| (self.thetas[i] - j as f64 * step).abs() < 1e-9);
        let cs: Option<Vec<H<f64>>> = (idx.iter())
            .map(|&i| self.cache[i].c_parallel.or(self.cache[i].c_ic))
            .collect();
        let (Some(cs), true) = (cs, equal && m >= 2 && m % 2 == 0) else {
            return;
        };
        let weight = |j: usize| match j {
            0 => 1.0,
            j if j == m => 1.0,
            j if j % 2 == 1 => 4.0,
            _ => 2.0,
        };
        // The mean over the stroke's time: h/3·Σ w·c over π, h = π/m.
        let mean_of = |c: &dyn Fn(usize) -> f64| {
            (0..=m).map(|j| weight(j) * c(j)).sum::<f64>() / (3.0 * m as f64)
        };
        let c_m = mean_of(&|j| cs[j].g);
        let v = self.d.crank_pin_speed;
        let lam = self.lambda();
        let exact_m = mean_of(&|j| v * cf::sin_factor(lam, j as f64 * step, cf::Stroke::Out));
        if c_m <= 0.0 || exact_m <= 0.0 {
            return;
        }
        let ids: Vec<_> = cs.iter().map(|c| c.id).collect();
        let ratio = self.b.reckon(
            v / c_m,
            "",
            Label::NONE,
            // A velocity off by δ moves c_m by at most 4δ/(3m), and v/c_m by v/c_m² of that.
            Weighted {
                inputs: &ids,
                weight: v / (c_m * c_m) * 4.0 / (3.0 * m as f64),
            },
            N_MEAN_SPEED,
        );
        self.b.check(
            &ratio,
            "v / c_m, c_m the drawn velocities’ mean over the stroke (Simpson)",
            "",
            "LH Gl. 26: v/c_m = π/2",
            std::f64::consts::FRAC_PI_2,
            || v / exact_m,
        );
    }

    /// The points B (crosshead) and A (crank pin) of Esselborn's figure.
    fn esselborn_point(
        &mut self,
        o: H<Point>,
        axis: H<Line>,
        circle: H<Circle>,
        dead: H<Point>,
    ) -> Result<Position, ConstructionError> {
        let b = &mut *self.b;
        let perp = b.perpendicular(&axis, &dead, Role::Construction, N_PERP);
        // Upwards: the pin runs over the upper half on the outstroke.
        let up = if perp.g.dir.dot(&Vector::new(0.0, 1.0)) >= 0.0 {
            1.0
        } else {
            -1.0
        };
        let b1 = b.lay_off(
            &dead,
            &perp,
            up * self.l,
            Role::Construction.named("B₁"),
            N_B1,
        )?;
        b.segment(&o, &b1, Role::Construction, N_OB1);
        let swing = b.circle(
            &o,
            (b1.g - o.g).norm(),
            Drawn::Marks,
            Role::Construction,
            N_SWING,
        )?;
        let bp = b.cut_line_circle(&axis, &swing, Branch::First, Label::plain("B"), N_B)?;
        let arc = b.circle(&bp, self.l, Drawn::Marks, Role::Construction, N_ROD_ARC)?;
        let a = b.cut_circle_circle(&circle, &arc, Branch::Near(b1.g), Label::plain("A"), N_A)?;
        b.segment(&o, &a, Role::Result, N_CRANK);
        b.segment(&a, &bp, Role::Result, N_CRANK);
        let rod = b.line_through(&bp, &a, Role::Construction, N_CRANK)?;
        Ok((bp, a, rod, Some(arc)))
    }

    /// The infinitely long rod stays parallel to the piston line: it is perpendicular to the
    /// crank where the crank stands on the vertical through O (90°, LH Abb. 54).
    fn infinite_rod_point(
        &mut self,
        o: H<Point>,
        axis: H<Line>,
        vertical: H<Line>,
        circle: H<Circle>,
    ) -> Result<Position, ConstructionError> {
        let b = &mut *self.b;
        let top = Point::new(o.g.x, o.g.y + self.r);
        let a = b.cut_line_circle(
            &vertical,
            &circle,
            Branch::Near(top),
            Label::plain("A"),
            N_A_INF,
        )?;
        b.segment(&o, &a, Role::Result, N_CRANK);
        let rod = b.parallel(&axis, &a, Role::Construction, N_ROD_INF);
        let bp = b.lay_off(&a, &rod, -self.r, Role::Result, N_ROD_INF)?;
        Ok((bp, a, rod, None))
    }

    /// The same position on the return (LH B.2: 100°44′ on the return against 79°16′ on the
    /// outstroke): the rod-length arc about B cuts the crank circle a second time, under the
    /// piston line, at A′ (the infinite rod: the crank straight down). Its angle is read from
    /// the dead centre where the return begins, as LH counts the return's angles.
    fn on_the_return(&mut self, (bp, a, _, arc): Position) -> Result<(), ConstructionError> {
        let f = self.frame()?;
        let (o, axis, vertical, circle, dead) =
            (f.o, f.piston_line, f.vertical, f.crank_circle, f.dead);
        let b = &mut *self.b;
        // A′ is A mirrored in the piston line; the return begins opposite the first dead centre.
        let under = Point::new(a.g.x, 2.0 * o.g.y - a.g.y);
        let opposite = Point::from(2.0 * o.g.coords - dead.g.coords);
        let a2 = match arc {
            Some(arc) => {
                b.cut_circle_circle(&circle, &arc, Branch::Near(under), Label::plain("A′"), N_A2)?
            }
            None => b.cut_line_circle(
                &vertical,
                &circle,
                Branch::Near(under),
                Label::plain("A′"),
                N_A2,
            )?,
        };
        b.segment(&o, &a2, Role::Result, N_CRANK2);
        if arc.is_some() {
            b.segment(&a2, &bp, Role::Result, N_CRANK2);
        }
        let start =
            b.cut_line_circle(&axis, &circle, Branch::Near(opposite), Label::NONE, N_DEAD2)?;
        let angle = b.measure_angle(&o, &start, &a2, Label::plain("α′"), N_ANGLE2);
        let lam = self.lambda();
        self.b.check(
            &angle,
            "crank angle of the rod perpendicular to the crank on the return (Esselborn)",
            "°",
            "180° − α, α from tg α = L/R (LH Abb. 52)",
            90.0,
            || 180.0 - cf::rod_perpendicular_angle(lam),
        );
        if arc.is_some() {
            let right = self.b.measure_angle(&a2, &o, &bp, Label::NONE, N_RIGHT);
            let what = "angle between crank and rod at A′ (the return)";
            self.b.check(&right, what, "°", "LH Abb. 52", 90.0, || 90.0);
        }
        Ok(())
    }

    /// The piston velocity at A by the parallel to the rod through the end of v (KG Abb. 1049).
    fn esselborn_velocity(
        &mut self,
        o: H<Point>,
        vertical: H<Line>,
        a: H<Point>,
        rod: H<Line>,
    ) -> Result<H<f64>, ConstructionError> {
        let b = &mut *self.b;
        let ray = b.line_through(&o, &a, Role::Construction, N_V)?;
        let v_mm = self.d.crank_pin_speed / self.scales.velocity_scale;
        let e = b.lay_off(&o, &ray, v_mm, Role::Velocity, N_V)?;
        let par = b.parallel(&rod, &e, Role::Auxiliary, N_PAR);
        let fpt = b.meet_point(&par, &vertical, Label::NONE, N_PAR)?;
        let scale = Scale {
            per_mm: self.scales.velocity_scale,
            unit: "m/s",
        };
        Ok(b.measure(&o, &fpt, &vertical, scale, Label::plain("c"), N_C))
    }
}
