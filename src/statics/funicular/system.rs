//! The construction of a force system (LH A.2-4, C.2, Abb. 22): position plan, force polygon,
//! funicular polygon, the resultant (or couple, or equilibrium), and resolutions.

use super::notes::*;
use super::polygon::{self, StringStyle};
use super::{
    extent, resolve, sum_and_moment, Components, Force, Resolution, Resultant, SystemDrawing,
    SystemResults,
};
use crate::kernel::tolerance::{REL_CLOSURE_EPS, REL_LAYOUT_EPS, REL_LOCAL_FRAME, REL_TIE_EPS};
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, ConstructionError, Cut, Label, Note, Role, Scale, H};

mod collinear;

/// The letter of the given forces, numbered from 1: LH's P₁, P₂, … (C.2, Abb. 22: "die
/// vier Kräfte P₁, P₂, P₃ und P₄").
pub const FORCE_LETTER: &str = "P";

/// Length of a force's arrow in the position plan (mm): the plan shows place and sense only.
const ARROW_MM: f64 = 12.0;
/// Gap between the position plan and the force polygon (mm).
const GAP_MM: f64 = 30.0;

/// A force system's construction on a board: its closed forms, scales and drawn parts.
struct System<'a, 'b> {
    b: &'b mut Board,
    forces: &'a [Force],
    dr: &'a SystemDrawing,
    /// Sheet mm per m.
    k: f64,
    kg: Scale,
    /// ΣF and ΣM about the origin (closed forms).
    r_cf: Vector,
    m_cf: f64,
    /// The largest force and the farthest point of application: the check references.
    fmax: f64,
    reach: f64,
    /// What the origin of the frame is ("origin", "first point of application").
    origin: &'static str,
}

/// The position plan: each force's line of action and point of application, and the
/// rightmost point of application on the sheet (mm).
type Plan = (Vec<H<Line>>, Vec<H<Point>>, f64);

/// The force polygon: its corners, each force's side, the closing side's ends, the
/// resultant's length on the sheet and its components.
struct Polygon {
    /// The chain's corners, for the pole's rays (empty where no funicular polygon follows).
    pts: Vec<H<Point>>,
    /// Each force's side: its tail and its head.
    sides: Vec<(H<Point>, H<Point>)>,
    /// The closing side R, from `first` to `last`.
    first: H<Point>,
    last: H<Point>,
    /// The sum of its sides (mm): what its closing side is judged against.
    sides_mm: f64,
    axis_x: H<Line>,
    r_len: f64,
    /// R as read off (kg).
    r: Vector,
}

/// Constructs the force polygon, the funicular polygon and the resultant (or couple) of a
/// system of forces, and resolves the forces asked for along two directions.
///
/// # Errors
/// [`ConstructionError`] where the construction meets a case it cannot draw through: a pole
/// on a side of the force polygon (a string parallel to its own line of action), a resolution
/// along two parallel directions, a force of zero length on a line of action.
///
/// ```
/// use graphostatik::statics::funicular::*;
/// use graphostatik::protocol::Board;
/// // Two parallel downward forces: the resultant 300 kg lies at the lever rule a:b = K2:K1.
/// let forces = [Force::new((0.0, 0.0), (0.0, -100.0)), Force::new((3.0, 0.0), (0.0, -200.0))];
/// let d = SystemDrawing { length_scale: 50.0, force_scale: 10.0, pole: None,
///     plan_at: None, unit: "kg" };
/// let mut b = Board::recording();
/// let r = construct_system(&mut b, &forces, &d, &[]).unwrap();
/// match r.resultant {
///     Resultant::Force { r, through, .. } => {
///         assert!((r.y + 300.0).abs() < 1e-9);
///         assert!((through.x - 2.0).abs() < 1e-9);
///     }
///     other => panic!("{other:?}"),
/// }
/// assert!(b.all_passed());
/// ```
pub fn construct_system(
    b: &mut Board,
    forces: &[Force],
    dr: &SystemDrawing,
    resolutions: &[Resolution],
) -> Result<SystemResults, ConstructionError> {
    if forces.is_empty() {
        return Err(ConstructionError::unsupported(
            "forces",
            "a force system needs at least one force",
        ));
    }
    // Forces applied farther from the origin than REL_LOCAL_FRAME times their spread are
    // constructed from the first point of application; the resultant's line and its moment
    // are given back about the scene's origin.
    let o = forces[0].at;
    let spread = forces.iter().map(|f| (f.at - o).norm()).fold(0.0, f64::max);
    let reach = forces
        .iter()
        .map(|f| f.at.x.abs().max(f.at.y.abs()))
        .fold(0.0, f64::max);
    if dr.plan_at.is_none() && o != Point::origin() && reach > REL_LOCAL_FRAME * spread {
        let local: Vec<Force> = forces
            .iter()
            .map(|f| Force {
                at: Point::from(f.at - o),
                f: f.f,
            })
            .collect();
        let mut r = build(b, &local, dr, resolutions, "first point of application")?;
        if let Resultant::Force {
            r: rv,
            through,
            moment,
        } = &mut r.resultant
        {
            *through = Point::new(through.x + o.x, through.y + o.y);
            *moment += o.x * rv.y - o.y * rv.x;
        }
        return Ok(r);
    }
    build(b, forces, dr, resolutions, "origin")
}

/// The construction of [`construct_system`] in the frame the forces are given in; `origin`
/// names where that frame's origin is, for the moment check.
fn build(
    b: &mut Board,
    forces: &[Force],
    dr: &SystemDrawing,
    resolutions: &[Resolution],
    origin: &'static str,
) -> Result<SystemResults, ConstructionError> {
    let (r_cf, m_cf) = sum_and_moment(forces);
    let (fmax, reach) = extent(forces);
    let mut s = System {
        b,
        forces,
        dr,
        k: 1000.0 / dr.length_scale,
        kg: Scale::kg(dr.force_scale),
        r_cf,
        m_cf,
        fmax,
        reach,
        origin,
    };
    let plan = s.position_plan()?;
    if let Some(u) = s.common_line() {
        return s.on_one_line(&plan, u, resolutions);
    }
    let (lines, _, xmax) = plan;
    let poly = s.force_polygon(&lines, xmax)?;
    let pole_at = match dr.pole {
        Some(p) => poly.pts[0].g + p / dr.force_scale,
        None => default_pole(
            &poly.pts.iter().map(|p| p.g).collect::<Vec<_>>(),
            fmax / dr.force_scale,
        ),
    };
    let rays = polygon::pole_and_rays(s.b, pole_at, &poly.pts)?;
    let start =
        s.b.point(lines[0].g.origin, Role::Given.named("I"), N_STRING_START);
    let strings = polygon::strings(
        s.b,
        &rays.rays,
        &start,
        true,
        StringStyle::RESULT,
        |_, j| Ok(lines[j]),
    )?
    .strings;
    let outcome = s.resultant(&poly, &rays.pole, &start, &strings)?;
    s.resolved(outcome, &poly, resolutions)
}

impl System<'_, '_> {
    /// The results: the resultant found, and each resolution asked for, made on the force
    /// polygon's sides.
    fn resolved(
        &mut self,
        (resultant, resultant_line): (Resultant, Option<H<Line>>),
        poly: &Polygon,
        resolutions: &[Resolution],
    ) -> Result<SystemResults, ConstructionError> {
        let mut components = Vec::new();
        for (j, res) in resolutions.iter().enumerate() {
            components.push(self.resolution(j, res, &poly.sides)?);
        }
        Ok(SystemResults {
            resultant,
            resultant_line,
            components,
        })
    }

    /// Sheet point of a point in m.
    fn sheet(&self, p: Point) -> Point {
        Point::new(p.x * self.k, p.y * self.k)
    }

    /// Points of application, arrows and lines of action: the lines, the points, and the
    /// rightmost point of application on the sheet.
    fn position_plan(&mut self) -> Result<Plan, ConstructionError> {
        let mut lines = Vec::with_capacity(self.forces.len());
        let mut apps = Vec::with_capacity(self.forces.len());
        let mut xmax = f64::MIN;
        for (i, f) in self.forces.iter().enumerate() {
            let v = f.f;
            let len = v.norm();
            if len == 0.0 {
                return Err(ConstructionError::unsupported(
                    format!("forces[{i}]"),
                    format!(
                        "force {} has no direction: a zero force has no line of action (leave it out)",
                        i + 1
                    ),
                ));
            }
            let at = self.sheet(f.at);
            let b = &mut *self.b;
            let a = b.point(
                at,
                Role::Given.labelled(Label::quiet("a", i as u32 + 1)),
                N_APPLICATION,
            );
            let label = Label::indexed(FORCE_LETTER, i as u32 + 1);
            let tail = b.point(
                a.g - v * (ARROW_MM / len),
                Role::Given.labelled(label),
                N_ARROW,
            );
            b.segment(&tail, &a, Role::Force, N_ARROW);
            lines.push(b.line_dir(&a, v, Role::Construction, N_LINE)?);
            xmax = xmax.max(a.g.x);
            apps.push(a);
        }
        Ok((lines, apps, xmax))
    }

    /// The forces laid off head to tail, each parallel to its line of action; the closing
    /// side R and its components read off and checked.
    fn force_polygon(
        &mut self,
        lines: &[H<Line>],
        xmax: f64,
    ) -> Result<Polygon, ConstructionError> {
        let fs = self.dr.force_scale;
        let origin = match self.dr.plan_at {
            Some(p) => p,
            None => Point::new(xmax + GAP_MM + self.fmax / fs, 0.0),
        };
        let b = &mut *self.b;
        let p0 = b.point(origin, Role::Given.named("0"), N_START);
        let mut pts = vec![p0];
        for (i, f) in self.forces.iter().enumerate() {
            let prev = pts[i];
            let dir = b.parallel(&lines[i], &prev, Role::Auxiliary, N_DIRECTION);
            let len = f.f.x.hypot(f.f.y) / fs;
            let label = Label::indexed("", i as u32 + 1);
            pts.push(b.lay_off(&prev, &dir, len, Role::Force.labelled(label), N_LAY_OFF)?);
        }
        let end = pts[self.forces.len()];
        let r_len = (end.g - p0.g).norm();
        let tol = b.tolerance().length;
        let (aux, none) = (Role::Auxiliary, Label::NONE);
        let axis_x = b.line_dir(
            &p0,
            Vector::new(1.0, 0.0),
            aux.labelled(none.clone()),
            N_AXIS_X,
        )?;
        let axis_y = b.line_dir(&p0, Vector::new(0.0, 1.0), aux.labelled(none), N_AXIS_Y)?;
        if r_len > tol {
            b.segment(&p0, &end, Role::Force.named("R"), N_RESULTANT);
        }
        let (kg, unit, fmax, r_cf) = (self.kg, self.dr.unit, self.fmax, self.r_cf);
        let rx = b.measure(&p0, &end, &axis_x, kg, Label::quiet("Rx", 0), N_RX);
        let what = "resultant, horizontal component";
        b.check(&rx, what, unit, "ΣFx", fmax, || r_cf.x);
        let ry = b.measure(&p0, &end, &axis_y, kg, Label::quiet("Ry", 0), N_RY);
        b.check(
            &ry,
            "resultant, vertical component",
            unit,
            "ΣFy",
            fmax,
            || r_cf.y,
        );
        let sides_mm = self.forces.iter().map(|f| f.f.x.hypot(f.f.y)).sum::<f64>() / fs;
        Ok(Polygon {
            sides: pts.windows(2).map(|w| (w[0], w[1])).collect(),
            first: p0,
            last: end,
            pts,
            sides_mm,
            axis_x,
            r_len,
            r: Vector::new(rx.g, ry.g),
        })
    }

    /// What the outer strings give: where they meet, the resultant's line of action through
    /// that point; parallel, a couple; coincident (or R = 0), equilibrium.
    fn resultant(
        &mut self,
        poly: &Polygon,
        pole: &H<Point>,
        start: &H<Point>,
        strings: &[H<Line>],
    ) -> Result<(Resultant, Option<H<Line>>), ConstructionError> {
        let n = strings.len() - 1;
        let tol = self.b.tolerance().length;
        let cut = self
            .b
            .meet(&strings[0], &strings[n], Label::plain("X"), N_FIRST_LAST);
        // The force polygon closes when R is nothing against its sides (not against the sheet):
        // then the outer strings are parallel to rounding, and a couple unless they coincide.
        let closed = poly.r_len <= tol.max(REL_CLOSURE_EPS * poly.sides_mm);
        let out = match cut {
            Cut::Point(x, _) if !closed => {
                let (r, line) = self.resultant_force(poly, &x, Role::Result)?;
                (r, Some(line))
            }
            Cut::Coincident => (Resultant::Equilibrium, None),
            Cut::Parallel { .. } => (self.couple(poly, pole, start, strings), None),
            Cut::Point(..) => {
                let last = strings[n].g;
                let apart = crate::kernel::cross(&(start.g - last.origin), &last.dir).abs();
                if apart <= tol {
                    (Resultant::Equilibrium, None)
                } else {
                    (self.couple(poly, pole, start, strings), None)
                }
            }
        };
        if let Resultant::Equilibrium = out.0 {
            self.no_moment(poly, start, N_FIRST_LAST);
        }
        Ok(out)
    }

    /// Both polygons close: the checks are that R = 0 (read off before) and ΣM = 0.
    fn no_moment(&mut self, poly: &Polygon, start: &H<Point>, note: Note) {
        let mscale = Scale::new(self.dr.force_scale / self.k, "kg·m");
        let (mref, m_cf) = (self.fmax * self.reach, self.m_cf);
        let b = &mut *self.b;
        let z = b.measure(start, start, &poly.axis_x, mscale, Label::NONE, note);
        let what = "moment of the system (equilibrium)";
        b.check(&z, what, "kg·m", "ΣM = x·Fy − y·Fx", mref, || m_cf);
    }

    /// The resultant through X, parallel to R of the force polygon, its line drawn in `pen`,
    /// and its moment about the origin: |R| times the signed distance of its line, read off
    /// and checked.
    fn resultant_force(
        &mut self,
        poly: &Polygon,
        x: &H<Point>,
        pen: Role,
    ) -> Result<(Resultant, H<Line>), ConstructionError> {
        let (p0, end) = (poly.first, poly.last);
        let (k, fs) = (self.k, self.dr.force_scale);
        let (mref, m_cf) = (self.fmax * self.reach, self.m_cf);
        let b = &mut *self.b;
        // The direction of R in the force plan, carried over through X.
        let r_dir = b.line_through(&p0, &end, Role::Auxiliary, N_RESULTANT)?;
        let r_line = b.parallel(&r_dir, x, pen, N_R_LINE);
        let o = b.point(Point::origin(), Role::Given, N_R_MOMENT);
        let foot = b.foot(&r_line, &o, Role::Construction, N_R_MOMENT);
        let normal = H {
            id: r_line.id,
            g: Line {
                origin: o.g,
                dir: Vector::new(r_line.g.dir.y, -r_line.g.dir.x),
            },
        };
        let scale = Scale::new(poly.r_len * fs / k, "kg·m");
        let d = b.measure(&o, &foot, &normal, scale, Label::NONE, N_R_MOMENT);
        let what = format!("moment of the resultant about the {}", self.origin);
        b.check(&d, what, "kg·m", "ΣM = x·Fy − y·Fx", mref, || m_cf);
        let r = Resultant::Force {
            r: poly.r,
            through: Point::new(x.g.x / k, x.g.y / k),
            moment: d.g,
        };
        Ok((r, r_line))
    }

    /// A couple: the outer strings are parallel; its moment is |ray 0| × their distance,
    /// counter-clockwise positive from the sense in which the chain runs.
    fn couple(
        &mut self,
        poly: &Polygon,
        pole: &H<Point>,
        start: &H<Point>,
        strings: &[H<Line>],
    ) -> Resultant {
        let n = strings.len() - 1;
        let (k, fs) = (self.k, self.dr.force_scale);
        let (mref, m_cf) = (self.fmax * self.reach, self.m_cf);
        let b = &mut *self.b;
        let foot = b.foot(&strings[n], start, Role::Construction, N_COUPLE_FOOT);
        let ray0 = (poly.pts[0].g - pole.g).norm();
        let normal = H {
            id: strings[0].id,
            g: Line {
                origin: start.g,
                dir: strings[0].g.normal(),
            },
        };
        let sense = (poly.pts[0].g - pole.g)
            .dot(&Vector::new(strings[0].g.dir.x, strings[0].g.dir.y))
            .signum();
        let scale = Scale::new(ray0 * fs / k * sense, "kg·m");
        let m = b.measure(start, &foot, &normal, scale, Label::quiet("M", 0), N_COUPLE);
        let abs = H {
            id: m.id,
            g: m.g.abs(),
        };
        let what = "moment of the couple";
        b.check(&abs, what, "kg·m", "ΣM = x·Fy − y·Fx", mref, || {
            m_cf.abs()
        });
        Resultant::Couple { moment: m.g }
    }

    /// Resolution `j`: the force (or its equilibrant) between two parallels to the given
    /// directions through its ends, the components read off and checked (LH A.2, Abb. 3).
    fn resolution(
        &mut self,
        j: usize,
        res: &Resolution,
        sides: &[(H<Point>, H<Point>)],
    ) -> Result<Components, ConstructionError> {
        let n = self.forces.len();
        let f = self.forces.get(res.force).ok_or_else(|| {
            ConstructionError::unsupported(
                format!("resolutions[{j}].force"),
                format!("resolution {j} names force {} of {n}", res.force + 1),
            )
        })?;
        let (s1, c1) = crate::kernel::angle::sin_cos_deg(res.along[0]);
        let (s2, c2) = crate::kernel::angle::sin_cos_deg(res.along[1]);
        let (t, h) = sides[res.force];
        let (tail, head, fv) = if res.equilibrant {
            (h, t, -f.f)
        } else {
            (t, h, f.f)
        };
        let (kg, unit, fmax) = (self.kg, self.dr.unit, self.fmax);
        let b = &mut *self.b;
        let aux = Role::Auxiliary;
        let l1 = b.line_dir(&tail, Vector::new(c1, s1), aux, N_RESOLVE_LINE)?;
        let l2 = b.line_dir(&head, Vector::new(c2, s2), aux, N_RESOLVE_LINE)?;
        let cpt = b
            .meet_point(&l1, &l2, Label::quiet("K", j as u32), N_RESOLVE_CUT)
            .map_err(|_| {
                ConstructionError::unsupported(
                    format!("resolutions[{j}].along"),
                    format!("resolution {j}: the two directions are parallel"),
                )
            })?;
        let s = |i: usize| Label::quiet("S", (2 * j + i) as u32);
        let k1 = b.measure(&tail, &cpt, &l1, kg, s(1), N_RESOLVE_MEASURE);
        let k2 = b.measure(&cpt, &head, &l2, kg, s(2), N_RESOLVE_MEASURE);
        // The directions are not parallel: the cut above found a point.
        let exact = resolve(fv, Vector::new(c1, s1), Vector::new(c2, s2));
        let first = "component along the first direction";
        // The directions are not parallel (the cut above found a point), so the solve has one.
        if let Some(e) = exact {
            b.check(&k1, first, unit, "2×2 solve", fmax, || e.first);
        }
        let second = "component along the second direction";
        if let Some(e) = exact {
            b.check(&k2, second, unit, "2×2 solve", fmax, || e.second);
        }
        b.segment(&tail, &cpt, Role::Force, N_COMPONENT);
        b.segment(&cpt, &head, Role::Force, N_COMPONENT);
        Ok(Components {
            first: k1.g,
            second: k2.g,
        })
    }
}

/// A pole clear of every side of the force polygon: beside the chain's middle, at about half
/// its extent, nudged until no pole ray runs along a side.
fn default_pole(pts: &[Point], fmax_mm: f64) -> Point {
    let n = pts.len();
    let mut c = Vector::zeros();
    for p in pts {
        c += p.coords;
    }
    let c = Point::from(c / n as f64);
    let span = pts
        .iter()
        .map(|p| (p - c).norm())
        .fold(0.0, f64::max)
        .max(fmax_mm)
        .max(1.0);
    let chord = pts[n - 1] - pts[0];
    let side = if chord.norm() > REL_LAYOUT_EPS * span {
        Vector::new(-chord.y, chord.x) / chord.norm()
    } else {
        Vector::new(-1.0, 0.0)
    };
    // Try a few positions; keep the first whose rays all cut their sides at a fair angle.
    let mut best = c + side * span;
    let mut best_score = f64::MIN;
    for t in 0..12 {
        let a = t as f64 * 0.47;
        let dir = Vector::new(
            side.x * a.cos() - side.y * a.sin(),
            side.x * a.sin() + side.y * a.cos(),
        );
        let cand = c + dir * (0.8 * span);
        let mut score = f64::MAX;
        for w in pts.windows(2) {
            let sd = w[1] - w[0];
            let l = sd.norm();
            if l == 0.0 {
                continue;
            }
            for q in w {
                let r = q - cand;
                let rl = r.norm();
                if rl == 0.0 {
                    score = f64::MIN;
                    continue;
                }
                let s = (r.x * sd.y - r.y * sd.x).abs() / (rl * l);
                score = score.min(s);
            }
        }
        if score > best_score + REL_TIE_EPS {
            best_score = score;
            best = cand;
        }
        if score > 0.26 {
            break;
        }
    }
    best
}
