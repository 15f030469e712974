//! The demand-driven construction of the engine's diagrams.

use super::model::{self, Cylinder};
use super::{DynamicsDrawing, DynamicsRequest, DynamicsResults, Engine, RayRow};
use crate::crank::closed_form as cf;
use crate::crank::tolle::{self, TolleAxis, TolleCurve, OUTSTROKE, RETURN_STROKE};
use crate::crank::{self, Angles, CrankDrive, Drawing, PistonForce, Request};
use crate::kernel::{Line, Point};
use crate::protocol::{
    note, Board, ConstructionError, Label, Note, Part, Reading, Role, Scale, Topic, Trace, H,
};

mod excess;
mod mean_area;
mod reduction;
mod summary;

const N_FOOT: Note = note(
    "piston position on the diagram axis",
    Some("Kolbenstellung"),
    "LH Abb. 58",
    Topic::Forces,
);
const N_ORD: Note = note(
    "ordinate over the piston position",
    Some("Ordinate"),
    "LH Abb. 45, 58",
    Topic::Forces,
);
const N_WORK: Note = note(
    "working side: F_w · p laid off at force scale (reduction factor R = F_w/(f·k))",
    Some("Kolbendruck P₁"),
    "LH Gl. 16-19",
    Topic::Forces,
);
const N_BACK: Note = note(
    "back side laid off against it: the net pressure a_ü = a₁ − a₂",
    Some("Überdruck"),
    "LH Gl. 40-42, Abb. 58; KG (296)",
    Topic::Forces,
);
const N_PUMP: Note = note(
    "the pump’s force rectangle laid against the steam force reduced by η",
    Some("Pumpendruck"),
    "KG Abb. 1053, 1065-1066",
    Topic::Forces,
);
const N_PUMP_RECT: Note = note(
    "the pump’s force rectangle over the stroke: P_p1 out, P_p2 back",
    Some("Pumpendruck, Rechteck"),
    "KG Abb. 1065",
    Topic::Forces,
);
const N_PUMP_READ: Note = note(
    "the pump force taken off the rectangle",
    Some("Pumpenkraft"),
    "KG Abb. 1053, 1065",
    Topic::Forces,
);
const N_CURVE_STEAM: Note = note(
    "the steam’s net force reduced by η, which the rectangle is laid over",
    Some("verkleinerte Dampfüberdruckfläche"),
    "KG Abb. 1065",
    Topic::Forces,
);
const N_P: Note = note(
    "net piston force P read off",
    Some("Überdruck P"),
    "LH Gl. 42; KG (296)",
    Topic::Forces,
);
const N_B_TRANSFER: Note = note(
    "the inertia ordinate transferred with the dividers and taken off",
    Some("resultierende Überdruckkurve"),
    "LH C.1, Abb. 58",
    Topic::Forces,
);
const N_RES: Note = note(
    "resulting force P − M·b read off",
    Some("resultierender Überdruck"),
    "LH Abb. 58; KG Abb. 1055",
    Topic::Forces,
);
const N_CURVE_P: Note = note(
    "net-pressure curve",
    Some("Überdruckkurve"),
    "LH Abb. 58",
    Topic::Forces,
);
const N_CURVE_R: Note = note(
    "resulting net-pressure curve",
    Some("resultierende Überdruckkurve"),
    "LH Abb. 58",
    Topic::Forces,
);

/// One drawn ray: the foot on the axis, the ordinate line, the points of the net pressure and
/// of the resulting force, and the values read off.
#[derive(Clone, Copy)]
struct Ray {
    /// The ray's foot on the diagram axis.
    foot: H<Point>,
    /// The end of the working side's force laid off from the foot.
    work_point: H<Point>,
    /// The steam's net force alone (η·(P₁ − P₂)), before a pump's force is laid against it.
    steam_point: H<Point>,
    p_point: H<Point>,
    r_point: H<Point>,
    row_p: f64,
    row_b: f64,
    row_r: f64,
}

/// On an ordinate: the end of the working side's force, the steam's net force alone, and the
/// net piston force (the same where there is no pump).
type NetPoints = (H<Point>, H<Point>, H<Point>);

struct Diagram {
    axis: TolleAxis,
    curves: Option<[TolleCurve; 2]>,
}

pub(super) struct Builder<'a> {
    b: &'a mut Board,
    e: &'a Engine,
    dr: &'a DynamicsDrawing,
    /// Every cylinder's rays by rod-length arcs through this many parts of its stroke.
    stroke_parts: Option<usize>,
    thetas: Vec<f64>,
    r_mm: f64,
    diagrams: Vec<Option<Diagram>>,
    rays: Vec<Vec<Option<Ray>>>,
    /// Per cylinder, the tangential force on each ray as read off its polar figure.
    tangential: Vec<Option<Vec<H<f64>>>>,
    row_height: f64,
    /// Per cylinder, the largest force its diagrams draw: the scale its checks are judged at.
    force_refs: Vec<f64>,
}

/// Constructs what `request` asks for on the crank `rays`: n equal divisions of the shaft's
/// revolution, every cylinder at those shaft angles plus its offset; or each cylinder's stroke
/// in n equal parts with its rays by rod-length arcs (LH Abb. 59), each cylinder's rays then
/// at shaft angles of its own, and the turning-force diagram on all of them (LH F, Abb. 67).
///
/// # Errors
/// A [`ConstructionError`] where a step has no solution; a validated scene gives none.
pub fn construct(
    board: &mut Board,
    engine: &Engine,
    drawing: &DynamicsDrawing,
    rays: &Angles,
    request: &DynamicsRequest,
) -> Result<DynamicsResults, ConstructionError> {
    let nc = engine.cylinders.len();
    // Per cylinder, the largest force its diagrams draw: the checks' scale and the layout's.
    let force_refs: Vec<f64> = engine
        .cylinders
        .iter()
        .map(|c| max_abs_force(&engine.kinematics, c))
        .collect();
    let fmax = force_refs.iter().copied().fold(f64::MIN_POSITIVE, f64::max);
    let thetas = rays.thetas(&drive(&engine.kinematics, PistonForce::Constant(0.0)));
    let divisions = thetas.len();
    let mut bl = Builder {
        b: board,
        e: engine,
        dr: drawing,
        stroke_parts: match rays {
            Angles::StrokeParts(n) => Some(*n),
            _ => None,
        },
        thetas,
        r_mm: engine.kinematics.r / drawing.length_scale,
        diagrams: (0..nc).map(|_| None).collect(),
        rays: (0..nc).map(|_| vec![None; divisions]).collect(),
        tangential: vec![None; nc],
        row_height: 2.6 * fmax / drawing.force_scale + 20.0,
        force_refs,
    };
    // Steps per ray and cylinder (net pressure 6, inertia 9, the crank's polar construction
    // about 12) and per turning ordinate (3 + cylinders): reserved once.
    let per = divisions * nc;
    bl.b.reserve(
        40 * nc + 27 * per + 4 * divisions,
        60 * nc + 40 * per + 6 * divisions,
    );
    let mut res = DynamicsResults::default();
    let want_t = request.turning_force
        || request.mean_height
        || request.power
        || request.flywheel
        || request.resistance_line;
    // The sheet: each cylinder a row (its indicator diagrams, its crank figure, its polar
    // diagrams), the turning-force diagram under them, the table under that.
    // The cards' reductions first, as the books begin (LH A), each cylinder's a row of
    // its own and their table under them; the rows after them keep their order.
    let first = if request.reduction { nc as u16 + 1 } else { 0 };
    let row = |c: usize| Part::at(first + c as u16, 0);
    if request.reduction {
        reduction::reduce_all(bl.b, engine, drawing)?;
    }
    if request.net_pressure || request.mean_area || want_t {
        res.mean_area = bl.net_pressures(&row, request.mean_area)?;
    }
    if want_t {
        for c in 0..nc {
            bl.b.set_part(row(c));
            bl.tangential(c)?;
        }
        bl.b.set_part(row(nc));
        (res.turning, res.turning_ids) = bl.turning_diagram()?;
    }
    if request.resistance_line && !res.turning.is_empty() {
        bl.b.set_part(row(nc + 1));
        res.resistance = Some(bl.resistance_line((&res.turning, &res.turning_ids))?);
    }
    res.rays = bl.rows();
    bl.b.clear_context();
    let lowest = res.turning.iter().fold(0.0f64, |m, p| m.max(p.1.abs())) / drawing.force_scale;
    let table_at = bl.turning_origin() - crate::kernel::Vector::new(0.0, lowest + 15.0);
    let table = row(nc + 1 + request.resistance_line as usize);
    bl.b.set_part(Part::free(table.row, table.col));
    summary::finish(bl.b, engine, drawing, request, &mut res, table_at);
    bl.b.set_part(Part::default());
    Ok(res)
}

/// The crank drive of the engine's kinematics with the piston force `p`.
fn drive(kin: &model::Kinematics, p: PistonForce) -> CrankDrive {
    CrankDrive {
        crank_radius: kin.r,
        rod_length: kin.rod().unwrap_or(5.0 * kin.r),
        finite_rod: kin.lambda > 0.0,
        crank_pin_speed: kin.v,
        piston_force: p,
    }
}

/// The largest |P|, |M·b| of a cylinder (kg): the scale its checks are judged at.
fn max_abs_force(k: &model::Kinematics, c: &Cylinder) -> f64 {
    let mut m: f64 = (c.mass * k.a() * (1.0 + k.lambda)).abs();
    for i in 0..72 {
        let t = 5.0 * i as f64;
        m = m
            .max(k.resulting_force(c, t).abs())
            .max(c.pressure_force(t, k.x_frac(t)).abs());
    }
    m.max(f64::MIN_POSITIVE)
}

impl Builder<'_> {
    fn cyl(&self, c: usize) -> &Cylinder {
        &self.e.cylinders[c]
    }

    /// Cylinder c's crank angle on its k-th ray: the shaft angle plus its offset, or where
    /// the stroke is divided, the k-th ray of its own stroke's parts (LH F: each cylinder's
    /// rays by rod-length arcs through its own stroke).
    fn crank_deg(&self, c: usize, k: usize) -> f64 {
        let offset = self.cyl(c).offset_deg;
        if offset == 0.0 || self.stroke_parts.is_some() {
            self.thetas[k]
        } else {
            (self.thetas[k] + offset).rem_euclid(360.0)
        }
    }

    /// The shaft angle of cylinder c's k-th ray: the first cylinder's crank angle.
    fn shaft_deg(&self, c: usize, k: usize) -> f64 {
        let offset = self.cyl(c).offset_deg;
        if offset == 0.0 || self.stroke_parts.is_none() {
            self.thetas[k]
        } else {
            (self.thetas[k] - offset).rem_euclid(360.0)
        }
    }

    fn force_scale(&self) -> Scale {
        Scale::kg(self.dr.force_scale)
    }

    /// Every cylinder's net-pressure diagram in its row of the sheet, and KG (297) on it where
    /// `mean_area` asks for it.
    fn net_pressures(
        &mut self,
        row: &dyn Fn(usize) -> Part,
        mean_area: bool,
    ) -> Result<Vec<super::MeanArea>, ConstructionError> {
        let mut out = Vec::new();
        for c in 0..self.e.cylinders.len() {
            self.b.set_part(row(c));
            for k in 0..self.thetas.len() {
                self.ray(c, k)?;
            }
            self.curves(c);
            self.pump_rectangles(c)?;
            if mean_area {
                out.push(self.mean_area(c)?);
            }
        }
        Ok(out)
    }

    /// The net-pressure diagram of cylinder c: its axis under the stroke and, with masses,
    /// the two inertia parabolas at force scale (LH B.4: CD = M·v²/r·3λ).
    fn diagram(&mut self, c: usize) -> Result<&Diagram, ConstructionError> {
        if self.diagrams[c].is_none() {
            let k = self.e.kinematics;
            let middle = Point::new(0.0, -(c as f64) * self.row_height);
            // The situation: the cylinder, and the stroke whose parabola a step draws.
            let cyl = self.e.cylinders[c].name.clone();
            let situation = |b: &mut Board| match cyl.is_empty() {
                true => b.clear_context(),
                false => b.set_context(|| cyl.clone()),
            };
            situation(self.b);
            let axis = tolle::axis(self.b, middle, self.r_mm, Topic::Forces)?;
            let mass = self.cyl(c).mass;
            let curves = if mass > 0.0 {
                let a_mm = mass * k.a() / self.dr.force_scale;
                let cp = tolle::point_c(self.b, &axis, self.r_mm, k.lambda)?;
                let curve = |b: &mut Board, sign: f64, name: &'static str| {
                    let stroke = if sign > 0.0 { OUTSTROKE } else { RETURN_STROKE };
                    let curve = |b: &mut Board| {
                        tolle::curve(b, &axis, &cp, a_mm, k.lambda, sign, Label::plain(name))
                    };
                    b.naming(|s| s.push_str(stroke), curve)
                };
                let (out, _) = curve(self.b, 1.0, "B₀")?;
                let (ret, _) = curve(self.b, -1.0, "B'₀")?;
                self.check_cd(c, (&axis, &cp, &out));
                situation(self.b);
                for (cv, stroke) in [(out, OUTSTROKE), (ret, RETURN_STROKE)] {
                    self.b.naming(
                        |s| s.push_str(stroke),
                        |b| {
                            tolle::balance(b, &axis, &cv);
                            let pts = tolle::envelope(b, &cv, 10);
                            if pts.len() >= 2 {
                                b.curve(
                                    &pts,
                                    Trace::Smooth,
                                    Role::Construction.named("B"),
                                    N_CURVE_B,
                                );
                            }
                        },
                    );
                }
                Some([out, ret])
            } else {
                None
            };
            self.b.clear_context();
            self.diagrams[c] = Some(Diagram { axis, curves });
        }
        Ok(self.diagrams[c].as_ref().expect("set above"))
    }

    /// CD of cylinder c's outstroke parabola read off at the force scale and held to Tolle's
    /// 3λ·M·v²/r (LH B.4: "CD = 5075 kg").
    fn check_cd(&mut self, c: usize, (axis, cp, out): (&TolleAxis, &tolle::TolleC, &TolleCurve)) {
        let name = &self.e.cylinders[c].name;
        self.b.set_context(|| name.clone());
        let cd = tolle::read_cd(self.b, axis, cp, out, self.force_scale());
        let k = self.e.kinematics;
        let ma = self.cyl(c).mass * k.a();
        self.b.check(
            &cd,
            "CD = 3λ·M·v²/r, taken off between C and D (Tolle)",
            "kg",
            "LH B.4, Abb. 58",
            (ma * (1.0 + k.lambda)).max(self.force_refs[c]),
            || 3.0 * k.lambda * ma,
        );
        self.b.clear_context();
    }

    /// The net pressure and resulting force on ray k of cylinder c (LH Abb. 58).
    fn ray(&mut self, c: usize, k: usize) -> Result<Ray, ConstructionError> {
        if let Some(r) = self.rays[c][k] {
            return Ok(r);
        }
        let theta = self.crank_deg(c, k);
        let e = self.e;
        let d = self.diagram(c)?;
        let (axis, curves) = (d.axis, d.curves);
        let name = &e.cylinders[c].name;
        self.b
            .set_context(|| format!("{name}, θ = {}°", crate::fmt::num(theta, 3)));
        let kin = self.e.kinematics;
        let x = kin.x_frac(theta);
        let foot = self.b.lay_off(
            &axis.ends[0],
            &axis.axis,
            x * 2.0 * self.r_mm,
            Role::Construction,
            N_FOOT,
        )?;
        let ord = self
            .b
            .perpendicular(&axis.axis, &foot, Role::Construction, N_ORD);
        let ((work_point, steam_point, p_point), p) =
            self.net_pressure(c, theta, x, foot, ord, axis.vertical)?;
        let (r_point, b, r) = match curves {
            Some(cv) => self.resulting(c, theta, (foot, p_point, ord), &axis, &cv)?,
            None => (p_point, 0.0, p),
        };
        let ray = Ray {
            foot,
            work_point,
            steam_point,
            p_point,
            r_point,
            row_p: p,
            row_b: b,
            row_r: r,
        };
        self.rays[c][k] = Some(ray);
        Ok(ray)
    }

    /// The working side's force up, the back side's down from its end: the net pressure.
    fn net_pressure(
        &mut self,
        c: usize,
        theta: f64,
        x: f64,
        foot: H<Point>,
        ord: H<Line>,
        vertical: H<Line>,
    ) -> Result<(NetPoints, f64), ConstructionError> {
        let cyl = self.cyl(c);
        let (stroke, _) = cf::book_angle(theta);
        let ((ws, u_work), (bs, u_back)) = cyl.sides(stroke, x);
        let (work, back) = (
            ws.area_cm2 * ws.indicator.working(u_work),
            bs.area_cm2 * bs.indicator.back(u_back),
        );
        let k = self.dr.force_scale;
        let pump = cyl.pump;
        let eta = cyl.drawn_steam_share();
        let w = self
            .b
            .lay_off(&foot, &ord, eta * work / k, Role::Force, N_WORK)?;
        let mut pp = self
            .b
            .lay_off(&w, &ord, -eta * back / k, Role::Construction, N_BACK)?;
        let load = pump.map_or(0.0, |p| p.force(stroke));
        let steam = pp;
        if pump.is_some() {
            pp = self.b.lay_off(&pp, &ord, -load / k, Role::Force, N_PUMP)?;
        }
        let p = self
            .b
            .measure(&foot, &pp, &vertical, self.force_scale(), Label::NONE, N_P);
        let cyl = &self.e.cylinders[c];
        self.b.check(
            &p,
            "net piston force P",
            "kg",
            "LH Gl. 40-42; KG (296); with a pump KG Abb. 1065",
            work.abs().max(back.abs()).max(load).max(self.force_refs[c]),
            || cyl.pressure_force(theta, x),
        );
        Ok(((w, steam, pp), p.g))
    }

    /// The inertia force on Tolle's parabola, transferred onto the net-pressure ordinate.
    fn resulting(
        &mut self,
        c: usize,
        theta: f64,
        (foot, pp, ord): (H<Point>, H<Point>, H<Line>),
        axis: &TolleAxis,
        curves: &[TolleCurve; 2],
    ) -> Result<(H<Point>, f64, f64), ConstructionError> {
        let (stroke, _) = cf::book_angle(theta);
        let curve = curves[(stroke == cf::Stroke::Return) as usize];
        let s = crate::kernel::angle::sin_cos_deg(theta / 2.0).0.powi(2);
        let q = tolle::point_at(self.b, &curve, s, Label::NONE)?;
        let xs = Scale {
            per_mm: self.dr.length_scale,
            unit: "mm",
        };
        let (_, bval) = tolle::read(
            self.b,
            axis,
            &q,
            xs,
            self.force_scale(),
            (Label::NONE, Label::NONE),
        );
        let kin = self.e.kinematics;
        let mass = self.cyl(c).mass;
        // Judged at the diagram's force scale, as every ordinate drawn on it: the parabola is
        // read off the same sheet as the net pressure, whose largest force may dwarf it.
        let bref = (mass * kin.a() * (1.0 + kin.lambda)).max(self.force_refs[c]);
        self.b.check(
            &bval,
            "inertia force M·b (Tolle’s parabola)",
            "kg",
            "KG (298); LH Gl. 35, 39",
            bref,
            || kin.inertia(mass, theta),
        );
        let rp = self.b.transfer(
            &pp,
            &ord,
            Reading {
                value: &bval,
                per_mm: -self.dr.force_scale,
            },
            Role::Construction,
            N_B_TRANSFER,
        )?;
        let r = self.b.measure(
            &foot,
            &rp,
            &axis.vertical,
            self.force_scale(),
            Label::NONE,
            N_RES,
        );
        let cyl = &self.e.cylinders[c];
        let pref = r.g.abs().max(bref);
        self.b.check(
            &r,
            "resulting force P − M·b",
            "kg",
            "LH C.1, Abb. 58",
            pref,
            || kin.resulting_force(cyl, theta),
        );
        Ok((rp, bval.g, r.g))
    }

    /// The net-pressure and resulting curves of cylinder c, outstroke and return.
    fn curves(&mut self, c: usize) {
        if !self.b.is_recording() {
            return;
        }
        let n = self.thetas.len();
        for ret in [false, true] {
            let mut idx: Vec<usize> = (0..n)
                .filter(|&k| (self.crank_deg(c, k) >= 180.0) == ret)
                .collect();
            idx.sort_by(|&a, &b| {
                let (xa, xb) = (
                    self.e.kinematics.x_frac(self.crank_deg(c, a)),
                    self.e.kinematics.x_frac(self.crank_deg(c, b)),
                );
                xa.total_cmp(&xb)
            });
            let rays: Vec<Ray> = idx.iter().filter_map(|&k| self.rays[c][k]).collect();
            let p: Vec<H<Point>> = rays.iter().map(|r| r.p_point).collect();
            let r: Vec<H<Point>> = rays.iter().map(|r| r.r_point).collect();
            if p.len() >= 2 && self.cyl(c).pump.is_some() {
                let steam: Vec<H<Point>> = rays.iter().map(|r| r.steam_point).collect();
                let mark = Role::Given.named(if ret { "S'" } else { "S" });
                self.b.curve(&steam, Trace::Smooth, mark, N_CURVE_STEAM);
            }
            if p.len() >= 2 {
                self.b
                    .curve(&p, Trace::Smooth, Role::Result.named("P"), N_CURVE_P);
                if self.cyl(c).mass > 0.0 {
                    self.b.curve(&r, Trace::Smooth, Role::Result, N_CURVE_R);
                }
            }
        }
    }

    /// The pump's force rectangle of cylinder c for each stroke (KG Abb. 1065): its
    /// resistance, the same over a stroke, laid up from both dead centres and joined, over
    /// the steam force reduced by η; what lies between is what the crank drive carries.
    fn pump_rectangles(&mut self, c: usize) -> Result<(), ConstructionError> {
        let Some(pump) = self.cyl(c).pump else {
            return Ok(());
        };
        let axis = self.diagram(c)?.axis;
        let ends = axis.ends;
        let mut ups = Vec::with_capacity(2);
        for e in &ends {
            ups.push(
                self.b
                    .perpendicular(&axis.axis, e, Role::Construction, N_ORD),
            );
        }
        let k = self.dr.force_scale;
        let cylinder = &self.e.cylinders[c].name;
        self.b.set_context(|| cylinder.clone());
        let sides = [
            (cf::Stroke::Out, "P_p1", "pump force P_p1 (outstroke)"),
            (cf::Stroke::Return, "P_p2", "pump force P_p2 (return)"),
        ];
        for (stroke, name, what) in sides {
            let force = pump.force(stroke);
            let a = self
                .b
                .lay_off(&ends[0], &ups[0], force / k, Role::Given, N_PUMP_RECT)?;
            let b = self
                .b
                .lay_off(&ends[1], &ups[1], force / k, Role::Given, N_PUMP_RECT)?;
            let mark = Role::Given.named(name);
            self.b.curve(&[a, b], Trace::Polygon, mark, N_PUMP_RECT);
            // Its height taken off again at the force scale (KG: "P_p1 = 3490 kg").
            let p = self.b.measure(
                &ends[1],
                &b,
                &ups[1],
                self.force_scale(),
                Label::NONE,
                N_PUMP_READ,
            );
            let reference = force.abs().max(self.force_refs[c]);
            self.b
                .check(&p, what, "kg", "KG Abb. 1053, 1065", reference, || force);
        }
        self.b.clear_context();
        Ok(())
    }

    /// The tangential force on every ray of cylinder c by the polar construction of
    /// [`crank`] (LH Abb. 65; KG Abb. 1063), beside the cylinder's diagram.
    fn tangential(&mut self, c: usize) -> Result<(), ConstructionError> {
        if self.tangential[c].is_some() {
            return Ok(());
        }
        let n = self.thetas.len();
        let forces: Vec<f64> = (0..n)
            .map(|k| self.rays[c][k].map_or(0.0, |r| r.row_r))
            .collect();
        let origin = Point::new(
            2.0 * self.r_mm + 20.0 + self.rod_mm(),
            -(c as f64) * self.row_height,
        );
        // The crank's steps and checks within the cylinder's name ("HP, θ = 30°").
        let name = self.e.cylinders[c].name.clone();
        let t = self.polar_construction(c, forces, origin, name)?;
        self.tangential[c] = Some(t);
        Ok(())
    }

    /// The drawn rod's length (mm of the sheet; five cranks for the infinite rod's figure).
    fn rod_mm(&self) -> f64 {
        drive(&self.e.kinematics, PistonForce::Constant(0.0)).rod_length / self.dr.length_scale
    }

    /// The tangential force of the piston `forces` (one per ray, driving positive) on cylinder
    /// c's rays by the crank's polar construction with its shaft centre at `origin`, every
    /// step and check within `context`: as read off, per ray.
    fn polar_construction(
        &mut self,
        c: usize,
        forces: Vec<f64>,
        origin: Point,
        context: String,
    ) -> Result<Vec<H<f64>>, ConstructionError> {
        let angles: Vec<f64> = (0..self.thetas.len())
            .map(|k| self.crank_deg(c, k))
            .collect();
        let drive = drive(&self.e.kinematics, PistonForce::PerAngle(forces));
        let drawing = Drawing {
            length_scale: self.dr.length_scale,
            force_scale: self.dr.force_scale,
            velocity_scale: 1.0,
            acceleration_scale: 1.0,
        };
        let req = Request {
            tangential_force: true,
            polar_diagrams: true,
            ..Request::default()
        };
        self.b.set_context(|| context);
        // Every cylinder's rays by rod-length arcs through its own stroke where the stroke is
        // divided (the angles are the same), at their crank angles otherwise.
        let rays = match self.stroke_parts {
            Some(n) => Angles::StrokeParts(n),
            None => Angles::Degrees(angles),
        };
        let res = crank::construct_at(self.b, &drive, &drawing, &rays, &req, origin)?;
        self.b.clear_context();
        Ok((res.rows.iter())
            .map(|r| r.tangential_read.unwrap_or(H::NONE_ZERO))
            .collect())
    }

    fn rows(&self) -> Vec<Vec<RayRow>> {
        (0..self.e.cylinders.len())
            .map(|c| {
                (0..self.thetas.len())
                    .filter_map(|k| {
                        self.rays[c][k].map(|r| RayRow {
                            shaft_deg: self.shaft_deg(c, k),
                            crank_deg: self.crank_deg(c, k),
                            pressure_force: r.row_p,
                            inertia: r.row_b,
                            resulting: r.row_r,
                            tangential: self.tangential[c].as_ref().map(|t| t[k].g),
                        })
                    })
                    .collect()
            })
            .collect()
    }
}

const N_CURVE_B: Note = note(
    "inertia parabola at force scale (CD = M·v²/r·3λ)",
    Some("Beschleunigungsdruckkurve"),
    "LH B.4, Abb. 58",
    Topic::Acceleration,
);

mod resistance;
mod turning;
mod unequal;
