//! Shafts: bending moments in two planes combined (LH C.7, Abb. 26-27), and bending with
//! torsion combined into the ideal moment (LH C.8, Gl. 12-13, Abb. 28-29).
//!
//! # The construction
//! Each load plane gets its own moment area with the same pole distance H, so that all
//! ordinates are moments at one scale. At every section the two ordinates y₁, y₂ are laid off
//! head to tail at the angle α between the planes, as forces are (Abb. 27): the closing side
//! is the resultant bending ordinate y, M_b = y·H. Where a torque M_d acts, its ordinate
//! x = α₀·M_d/H stands at right angles to y; the hypotenuse of the right triangle on y and x is
//! √(y² + x²), and the ideal moment (Gl. 13)
//!
//! y_i = 3/8 · y + 5/8 · √(y² + x²)
//!
//! is laid off by dividing both into eighths and adding three eighths of the one to five
//! eighths of the other (Abb. 29).

use super::beam::{construct_beam_at, BeamDrawing, BeamRequest, BeamResults};
use super::{Beam, PointLoad};
use crate::kernel::tolerance::REL_POSITION_EPS;
use crate::kernel::{Point, Vector};
use crate::protocol::{
    note, Board, ConstructionError, Label, Note, Role, Scale, Topic, Trace, Weighted, H,
};
use serde::Serialize;

const N_BASE: Note = note(
    "base point of the combination at the section",
    Some("Querschnitt"),
    "LH Abb. 27",
    Topic::Moment,
);
const N_DIR1: Note = note(
    "direction of the first load plane",
    Some("Lastebene I"),
    "LH Abb. 27",
    Topic::Moment,
);
const N_Y1: Note = note(
    "ordinate y1 of the first plane",
    Some("y1"),
    "LH Abb. 27",
    Topic::Moment,
);
const N_DIR2: Note = note(
    "direction of the second load plane, at the angle between the planes",
    Some("Lastebene II"),
    "LH Abb. 27",
    Topic::Moment,
);
const N_Y2: Note = note(
    "ordinate y2 laid on at the angle between the planes",
    Some("y2"),
    "LH Abb. 27",
    Topic::Moment,
);
const N_Y: Note = note(
    "closing side: the resultant bending ordinate y",
    Some("resultierendes Moment"),
    "LH Abb. 27",
    Topic::Moment,
);
const N_MB: Note = note(
    "resultant bending moment M_b = y·H",
    Some("Biegungsmoment"),
    "LH C.7",
    Topic::Moment,
);
const N_D: Note = note(
    "diameter d = ∛(M_b / 0.1·k_b) from the ordinate",
    Some("Wellendurchmesser"),
    "LH I Aufgabe 7",
    Topic::Moment,
);
const N_LEG_Y: Note = note(
    "bending ordinate y as one leg",
    Some("Biegungsordinate"),
    "LH Abb. 29",
    Topic::Moment,
);
const N_NORMAL: Note = note(
    "perpendicular at its end",
    Some("Senkrechte"),
    "LH Abb. 29",
    Topic::Moment,
);
const N_LEG_X: Note = note(
    "torque ordinate α0·x as the other leg",
    Some("Drehmomentordinate"),
    "LH Gl. 12, Abb. 29",
    Topic::Moment,
);
const N_HYP: Note = note(
    "hypotenuse √(y² + x²)",
    Some("Hypotenuse"),
    "LH Abb. 29",
    Topic::Moment,
);
const N_EIGHTHS: Note = note(
    "divide into eighths",
    Some("Achtel"),
    "LH Gl. 13, Abb. 29",
    Topic::Moment,
);
const N_ADD: Note = note(
    "five eighths of the hypotenuse laid on after three eighths of y",
    Some("ideelles Moment"),
    "LH Gl. 13, Abb. 29",
    Topic::Moment,
);
const N_MI: Note = note(
    "ideal moment M_i = y_i·H",
    Some("ideelles Moment"),
    "LH Gl. 13",
    Topic::Moment,
);

const N_TQ_POLE: Note = note(
    "pole O of the twisting force",
    Some("Pol"),
    "LH Gl. 12, Abb. 28",
    Topic::Moment,
);
const N_TQ_FORCE: Note = note(
    "twisting force P = M_d / r at the pole distance H",
    Some("Kraft P"),
    "LH Gl. 12, Abb. 28",
    Topic::Moment,
);
const N_TQ_RAY: Note = note(
    "pole ray to an end of P",
    Some("Polstrahl"),
    "LH Gl. 12, Abb. 28",
    Topic::Moment,
);
const N_TQ_AXIS: Note = note(
    "perpendicular from the pole to the line of P",
    Some("Polweite"),
    "LH Gl. 12",
    Topic::Moment,
);
const N_TQ_R: Note = note(
    "radius r laid off from the pole at the length scale",
    Some("Abstand r"),
    "LH Gl. 12",
    Topic::Moment,
);
const N_TQ_PAR: Note = note(
    "parallel to P at distance r from the pole",
    Some("Parallele im Abstande r"),
    "LH Gl. 12",
    Topic::Moment,
);
const N_TQ_CUT: Note = note(
    "the parallel cuts the pole ray",
    Some("Schnittpunkt"),
    "LH Gl. 12",
    Topic::Moment,
);
const N_TQ_X: Note = note(
    "torque ordinate x: x/r = P/H, so x·H = P·r = M_d (intercept theorem)",
    Some("Drehmomentordinate"),
    "LH Gl. 12",
    Topic::Moment,
);
const N_TQ_R0: Note = note(
    "α0·r laid off from the pole",
    Some("Abstand α0·r"),
    "LH Gl. 12-13",
    Topic::Moment,
);
const N_TQ_X0: Note = note(
    "weighted torque ordinate α0·x cut off at distance α0·r",
    Some("Drehmomentordinate"),
    "LH Gl. 12-13",
    Topic::Moment,
);
const N_TQ_RECT: Note = note(
    "torque rectangle CFGH of height x over the twisted stretch",
    Some("Drehmomentfläche"),
    "LH Abb. 28",
    Topic::Moment,
);
const N_TQ_CORNER: Note = note(
    "corner of the torque rectangle",
    Some("Drehmomentfläche"),
    "LH Abb. 28",
    Topic::Moment,
);

/// A torque M_d (kg·m) acting on the stretch of shaft from `from` to `to` (m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Torque {
    /// Start of the twisted stretch (m).
    pub from: f64,
    /// End (m).
    pub to: f64,
    /// Torque (kg·m).
    pub md: f64,
    /// Radius (m) at which the twisting force P = M_d / r acts (the pulley or crank radius).
    /// With it the torque ordinate is constructed as the book does (Gl. 12): the parallel to P
    /// at distance r from the pole cuts the pole rays of P in x, x·H = P·r. Without it the
    /// ordinate M_d / H is laid off directly.
    pub radius: Option<f64>,
}

/// A shaft on two supports with loads in two planes and a torque.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Shaft {
    /// Supports A and B (m).
    pub supports: [f64; 2],
    /// Ends (m).
    pub ends: [f64; 2],
    /// Loads in the first plane (kg).
    pub plane_1: Vec<PointLoad>,
    /// Loads in the second plane (kg).
    pub plane_2: Vec<PointLoad>,
    /// Angle between the two load planes (degrees), 90 for perpendicular planes.
    pub angle_deg: f64,
    /// The torque, if any.
    pub torque: Option<Torque>,
    /// Bach's ratio α0 of the allowed bending and torsion stresses, which weights the torque
    /// in Gl. 13 (the issue asks for 1 and 1.5).
    pub alpha0: f64,
    /// Allowed bending stress k_b (kg/cm²): with it, each section reports the diameter the
    /// ideal moment needs, d = ∛(M_i / (0.1·k_b)) (LH Aufgabe 7).
    pub kb: Option<f64>,
}

/// One section of the shaft.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShaftRow {
    /// Position (m).
    pub x: f64,
    /// Bending moment in the first plane (kg·m).
    pub m1: f64,
    /// In the second plane (kg·m).
    pub m2: f64,
    /// Resultant bending moment (kg·m).
    pub mb: f64,
    /// Torque there (kg·m).
    pub md: f64,
    /// Ideal moment (kg·m).
    pub mi: f64,
    /// Diameter the ideal moment needs (mm), if k_b is given.
    pub diameter_mm: Option<f64>,
}

/// The closed forms: M_b from M₁, M₂ at the angle α; M_i by Gl. 13.
pub fn combined(m1: f64, m2: f64, angle_deg: f64) -> f64 {
    let (_, c) = crate::kernel::angle::sin_cos_deg(angle_deg);
    (m1 * m1 + m2 * m2 + 2.0 * m1 * m2 * c).max(0.0).sqrt()
}

/// Gl. 13: M_i = 3/8 M_b + 5/8 √(M_b² + (α0·M_d)²).
pub fn ideal(mb: f64, md: f64, alpha0: f64) -> f64 {
    0.375 * mb + 0.625 * mb.hypot(alpha0 * md)
}

/// The torque ordinate by the pole triangle of the twisting force (LH Gl. 12): P = M_d / r is
/// drawn at the pole distance H from the pole O; the parallel to P at distance r from O cuts
/// the two pole rays in the ordinate x, and x/r = P/H gives x·H = P·r = M_d. A second parallel
/// at α0·r cuts off α0·x, the leg of Abb. 29. Returns (x, α0·x) in mm.
fn torque_ordinate(
    b: &mut Board,
    t: &Torque,
    r: f64,
    alpha0: f64,
    dr: &BeamDrawing,
    pole_at: Point,
    mscale: Scale,
) -> Result<(f64, f64), ConstructionError> {
    let p_mm = t.md.abs() / r / dr.force_scale;
    let h_mm = dr.pole_distance / dr.force_scale;
    let r_mm = r * 1000.0 / dr.length_scale;
    let o = b.point(pole_at, Role::Given.named("O"), N_TQ_POLE);
    let down = Vector::new(0.0, -1.0);
    let top = b.point(
        pole_at + Vector::new(h_mm, 0.5 * p_mm),
        Role::Given.labelled(Label::quiet("P", 0)),
        N_TQ_FORCE,
    );
    let line_p = b.line_dir(&top, down, Role::Construction, N_TQ_FORCE)?;
    let bottom = b.lay_off(&top, &line_p, p_mm, Role::Force.named("P"), N_TQ_FORCE)?;
    let ray_top = b.line_through(&o, &top, Role::Construction, N_TQ_RAY)?;
    let ray_bottom = b.line_through(&o, &bottom, Role::Construction, N_TQ_RAY)?;
    let axis = b.perpendicular(&line_p, &o, Role::Auxiliary, N_TQ_AXIS);
    let cut_off = |b: &mut Board, dist: f64, n_r: Note, n_x: Note, weight: f64| {
        let foot = b.lay_off(&o, &axis, dist, Role::Construction, n_r)?;
        let par = b.parallel(&line_p, &foot, Role::Construction, N_TQ_PAR);
        let c1 = b.meet_point(&ray_top, &par, Label::NONE, N_TQ_CUT)?;
        let c2 = b.meet_point(&ray_bottom, &par, Label::NONE, N_TQ_CUT)?;
        b.segment(&c1, &c2, Role::Result, n_x.clone());
        let x = b.measure(&c1, &c2, &line_p, mscale, Label::quiet("Md", 0), n_x);
        b.check(
            &x,
            "torque ordinate read as a moment",
            "kg·m",
            "LH Gl. 12: x·H = P·r",
            weight * t.md.abs(),
            || weight * t.md.abs(),
        );
        Ok::<f64, ConstructionError>((c2.g - c1.g).norm())
    };
    let x = cut_off(b, r_mm, N_TQ_R, N_TQ_X, 1.0)?;
    let ax = if alpha0 == 1.0 {
        x
    } else {
        cut_off(b, alpha0 * r_mm, N_TQ_R0, N_TQ_X0, alpha0)?
    };
    Ok((x, ax))
}

/// The torque rectangle CFGH of height `x` mm over the twisted stretch (LH Abb. 28).
fn torque_rectangle(
    b: &mut Board,
    t: &Torque,
    x: f64,
    dr: &BeamDrawing,
    base_y: f64,
) -> Result<(), ConstructionError> {
    let k = 1000.0 / dr.length_scale;
    let c = b.point(
        Point::new(t.from * k + dr.origin.x, base_y),
        Role::Given.named("C"),
        N_TQ_CORNER,
    );
    let base = b.line_dir(&c, Vector::new(1.0, 0.0), Role::Axis, N_TQ_CORNER)?;
    let h = b.lay_off(
        &c,
        &base,
        (t.to - t.from) * k,
        Role::Construction.named("H"),
        N_TQ_CORNER,
    )?;
    let up_c = b.perpendicular(&base, &c, Role::Construction, N_TQ_CORNER);
    let up_h = b.perpendicular(&base, &h, Role::Construction, N_TQ_CORNER);
    // x is laid off upwards: the perpendicular's direction may point either way.
    let sx = if up_c.g.dir.y >= 0.0 { x } else { -x };
    let f = b.lay_off(&c, &up_c, sx, Role::Construction.named("F"), N_TQ_CORNER)?;
    let top = b.parallel(&base, &f, Role::Construction, N_TQ_CORNER);
    let g = b.meet_point(&top, &up_h, Label::plain("G"), N_TQ_CORNER)?;
    b.curve(&[c, f, g, h, c], Trace::Polygon, Role::Result, N_TQ_RECT);
    Ok(())
}

/// Constructs both moment areas, their combination and the ideal moment at every section
/// (supports, loads of either plane, ends of the torque).
///
/// # Errors
/// As [`construct_beam_at`].
///
/// ```
/// use graphostatik::statics::{shaft::*, BeamDrawing, PointLoad};
/// use graphostatik::protocol::Board;
/// let shaft = Shaft { supports: [0.0, 1.0], ends: [0.0, 1.0],
///     plane_1: vec![PointLoad { x: 0.4, p: 300.0 }], plane_2: vec![PointLoad { x: 0.4, p: 400.0 }],
///     angle_deg: 90.0, torque: Some(Torque { from: 0.0, to: 0.4, md: 100.0, radius: Some(0.2) }), alpha0: 1.0,
///     kb: Some(1000.0) };
/// let d = BeamDrawing { length_scale: 10.0, force_scale: 10.0, pole_distance: 500.0,
///     parabola_divisions: 8, origin: graphostatik::kernel::Point::origin() };
/// let mut b = Board::recording().with_figure_size(300.0);
/// let rows = construct_shaft(&mut b, &shaft, &d).unwrap();
/// let at = rows.iter().find(|r| (r.x - 0.4).abs() < 1e-12).unwrap();
/// // M1 = 300·0.4·0.6 = 72, M2 = 96: perpendicular planes give M_b = 120 kg·m.
/// assert!((at.mb - 120.0).abs() < 1e-9);
/// // d = ∛(M_i / (0.1 k_b)) with M_i in kg·cm.
/// assert!((at.diameter_mm.unwrap() - 10.0 * (100.0 * at.mi / 100.0).cbrt()).abs() < 1e-9);
/// assert!(b.steps().iter().flat_map(|s| &s.checks).all(|c| c.passed));
/// ```
pub fn construct_shaft(
    b: &mut Board,
    shaft: &Shaft,
    dr: &BeamDrawing,
) -> Result<Vec<ShaftRow>, ConstructionError> {
    let xs = sections(shaft);
    let beam = |loads: &[PointLoad]| Beam {
        supports: shaft.supports,
        ends: shaft.ends,
        point_loads: loads.to_vec(),
        uniform_loads: vec![],
    };
    let (b1, b2) = (beam(&shaft.plane_1), beam(&shaft.plane_2));
    let ms = dr.length_scale / 1000.0 * dr.pole_distance; // kg·m per mm of ordinate
    let mut y_next = dr.origin.y;
    let r1 = plane_moments(b, &b1, dr, &xs, &mut y_next)?;
    let r2 = plane_moments(b, &b2, dr, &xs, &mut y_next)?;
    // The triangles of Abb. 27 rise by up to |y1| + |y2| above their base points.
    let largest = |r: &BeamResults| {
        r.sections
            .iter()
            .map(|s| s.moment.abs())
            .fold(0.0, f64::max)
    };
    let rise = (largest(&r1) + largest(&r2)) / ms;
    let torque_mm = torque(b, shaft, dr, &mut y_next)?;
    let c = Combine {
        shaft,
        dr,
        k: 1000.0 / dr.length_scale,
        ms,
        y0: y_next - rise,
        mref: largest(&r1)
            .max(largest(&r2))
            .max(shaft.torque.map_or(0.0, |t| t.md.abs() * shaft.alpha0)),
        s1: super::closed_form::Sections::new(&b1),
        s2: super::closed_form::Sections::new(&b2),
        torque_mm,
    };
    let tol = REL_POSITION_EPS * (shaft.ends[1] - shaft.ends[0]).max(1.0);
    let at = |rows: &[super::SectionRow], x: f64| {
        rows.iter()
            .find(|s| (s.x - x).abs() <= tol)
            .map_or(0.0, |s| s.moment)
    };
    let mut rows = Vec::new();
    for &x in &xs {
        let (m1, m2) = (at(&r1.sections, x), at(&r2.sections, x));
        let mb = c.combined(b, x, m1, m2)?;
        let md = shaft
            .torque
            .filter(|t| x >= t.from - tol && x <= t.to + tol)
            .map_or(0.0, |t| t.md);
        // The ideal moment (Abb. 29), where a torque acts; elsewhere it equals M_b.
        let mi = if md != 0.0 {
            c.ideal(b, x, mb, md)?
        } else {
            mb
        };
        let diameter_mm = shaft
            .kb
            .map(|kb| 10.0 * super::sizing::shaft_diameter_cm(100.0 * mi, kb));
        rows.push(ShaftRow {
            x,
            m1,
            m2,
            mb,
            md,
            mi,
            diameter_mm,
        });
    }
    Ok(rows)
}

/// The sections of a shaft: supports, loads of either plane, ends of the torque, ordered,
/// those within the position tolerance merged.
fn sections(shaft: &Shaft) -> Vec<f64> {
    let mut xs: Vec<f64> = shaft.supports.to_vec();
    xs.extend(shaft.plane_1.iter().chain(&shaft.plane_2).map(|l| l.x));
    if let Some(t) = shaft.torque {
        xs.push(t.from);
        xs.push(t.to);
    }
    xs.sort_by(f64::total_cmp);
    let span = shaft.ends[1] - shaft.ends[0];
    xs.dedup_by(|a, b| (*a - *b).abs() <= REL_POSITION_EPS * span.max(1.0));
    xs
}

/// The moment area of one plane at `y_next` (moved below it), measured at the sections; a
/// plane without loads has no moment area to draw: its ordinates are zero.
fn plane_moments(
    b: &mut Board,
    bm: &Beam,
    dr: &BeamDrawing,
    xs: &[f64],
    y_next: &mut f64,
) -> Result<BeamResults, ConstructionError> {
    if bm.point_loads.is_empty() {
        return Ok(BeamResults {
            reactions: super::beam::Reactions { a: 0.0, b: 0.0 },
            sections: xs
                .iter()
                .map(|&x| super::SectionRow {
                    x,
                    what: "x".into(),
                    moment: 0.0,
                })
                .collect(),
            zero_moments: vec![],
            shear: vec![],
            max_moment: None,
            moment_handles: vec![],
        });
    }
    let req = BeamRequest {
        reactions: true,
        moment_area: true,
        shear_diagram: false,
    };
    let mut d = *dr;
    d.origin = Point::new(dr.origin.x, *y_next);
    let r = construct_beam_at(b, bm, &d, &req, xs)?;
    let ms = dr.length_scale / 1000.0 * dr.pole_distance;
    let depth = r
        .sections
        .iter()
        .map(|s| s.moment.abs())
        .fold(0.0, f64::max)
        / ms;
    *y_next -= depth + 90.0;
    Ok(r)
}

/// The torque: its ordinate by Gl. 12 when the radius is known (else at the moment scale),
/// and its rectangle, at `y_next` (moved below it). Returns α₀ times the ordinate (mm), the
/// leg of the ideal moment's triangle.
fn torque(
    b: &mut Board,
    shaft: &Shaft,
    dr: &BeamDrawing,
    y_next: &mut f64,
) -> Result<Option<f64>, ConstructionError> {
    let Some(t) = shaft.torque.filter(|t| t.md != 0.0) else {
        return Ok(None);
    };
    let ms = dr.length_scale / 1000.0 * dr.pole_distance;
    let k = 1000.0 / dr.length_scale;
    let direct = t.md.abs() / ms;
    let (x, ax) = match t.radius {
        Some(r) => {
            let at = Point::new(shaft.ends[1] * k + dr.origin.x + 40.0, *y_next);
            torque_ordinate(b, &t, r, shaft.alpha0, dr, at, Scale::new(ms, "kg·m"))?
        }
        None => (direct, shaft.alpha0 * direct),
    };
    torque_rectangle(b, &t, x, dr, *y_next - x)?;
    *y_next -= x + 40.0;
    Ok(Some(ax))
}

/// The combination of the two planes and the torque at each section.
struct Combine<'a> {
    shaft: &'a Shaft,
    dr: &'a BeamDrawing,
    /// Sheet mm per m.
    k: f64,
    /// kg·m per mm of ordinate.
    ms: f64,
    /// The base line of the parallelograms and triangles (mm).
    y0: f64,
    /// The largest moment: the reference of the checks.
    mref: f64,
    s1: super::closed_form::Sections<'a>,
    s2: super::closed_form::Sections<'a>,
    /// α₀ × the torque ordinate (mm), where the torque was drawn.
    torque_mm: Option<f64>,
}

impl Combine<'_> {
    /// The closed form of M_b at x.
    fn mb_closed(&self, x: f64) -> f64 {
        combined(self.s1.moment(x), self.s2.moment(x), self.shaft.angle_deg)
    }

    /// The parallelogram of the ordinates (Abb. 27) at the section's base point: y₁ up, y₂
    /// turned through α from it; the diagonal is M_b, read off and checked.
    fn combined(&self, b: &mut Board, x: f64, m1: f64, m2: f64) -> Result<f64, ConstructionError> {
        let (ms, mscale) = (self.ms, Scale::new(self.ms, "kg·m"));
        let (sin_a, cos_a) = crate::kernel::angle::sin_cos_deg(self.shaft.angle_deg);
        let at = Point::new(x * self.k + self.dr.origin.x, self.y0);
        let q = b.point(at, Role::Given.labelled(Label::quiet("Q", 0)), N_BASE);
        let (aux, con) = (Role::Auxiliary, Role::Construction);
        let dir1 = b.line_dir(&q, Vector::new(0.0, 1.0), aux, N_DIR1)?;
        let e1 = b.lay_off(&q, &dir1, m1 / ms, con, N_Y1)?;
        // The second plane turned through α from the first (counter-clockwise from "up").
        let dir2 = b.line_dir(&e1, Vector::new(-sin_a, cos_a), aux, N_DIR2)?;
        let e2 = b.lay_off(&e1, &dir2, m2 / ms, con, N_Y2)?;
        if (e2.g - q.g).norm() <= b.tolerance().length {
            return Ok(0.0);
        }
        let yl = b.line_through(&q, &e2, Role::Result, N_Y)?;
        let h = b.measure(&q, &e2, &yl, mscale, Label::quiet("Mb", 0), N_MB);
        let formula = "LH C.7: √(M1² + M2² + 2 M1 M2 cos α)";
        let what = "resultant bending moment M_b";
        b.check(&h, what, "kg·m", formula, self.mref, || self.mb_closed(x));
        if let Some(kb) = self.shaft.kb {
            self.diameter(b, x, &h, kb);
        }
        Ok(h.g)
    }

    /// The diameter the bending moment read off at x needs, d = ∛(M_b / 0.1·k_b) (LH I
    /// Aufgabe 7: "d = 2,92·∛25 = 85 mm"), reckoned from the ordinate and checked against
    /// the same rule over the closed-form M_b.
    fn diameter(&self, b: &mut Board, x: f64, mb: &H<f64>, kb: f64) {
        let d_mm = |m: f64| 10.0 * super::sizing::shaft_diameter_cm(100.0 * m, kb);
        let (d, closed, largest) = (d_mm(mb.g), d_mm(self.mb_closed(x)), d_mm(self.mref));
        // dd/dM = d/(3M): how far d moves for one kg·m of the ordinate's error.
        let weight = d / (3.0 * mb.g.abs());
        if ![d, closed, largest, weight].iter().all(|v| v.is_finite()) {
            // A k_b so small that no number holds the diameter: no row.
            return;
        }
        b.set_context(|| format!("x = {} m", crate::fmt::num(x, 4)));
        let h = b.reckon(
            d,
            "mm",
            Label::NONE,
            Weighted {
                inputs: &[mb.id],
                weight,
            },
            N_D,
        );
        b.check(
            &h,
            "shaft diameter d for M_b at k_b",
            "mm",
            "LH C.7, Aufgabe 7: M_b = 0,1·d³·k_b",
            largest,
            || closed,
        );
        b.clear_context();
    }

    /// The ideal moment by the construction of Abb. 29 (Gl. 13): legs M_b and α₀·M_d, the
    /// hypotenuse, both divided into eighths; 3/8 of the one and 5/8 of the other laid end to
    /// end on the leg, read off and checked.
    fn ideal(&self, b: &mut Board, x: f64, mb: f64, md: f64) -> Result<f64, ConstructionError> {
        let (ms, mscale) = (self.ms, Scale::new(self.ms, "kg·m"));
        let at = Point::new(x * self.k + self.dr.origin.x + 4.0, self.y0 - 10.0);
        let base = b.point(at, Role::Given.labelled(Label::quiet("R", 0)), N_BASE);
        let (aux, con) = (Role::Auxiliary, Role::Construction);
        let leg = b.line_dir(&base, Vector::new(1.0, 0.0), aux, N_LEG_Y)?;
        let ey = b.lay_off(&base, &leg, mb / ms, con, N_LEG_Y)?;
        let normal = b.perpendicular(&leg, &ey, aux, N_NORMAL);
        let alpha0 = self.shaft.alpha0;
        let tx = self.torque_mm.unwrap_or(alpha0 * md.abs() / ms);
        let ex = b.lay_off(&ey, &normal, tx, con, N_LEG_X)?;
        // The hypotenuse drawn; its five eighths are taken off it below.
        b.line_through(&base, &ex, con, N_HYP)?;
        let y8 = b.divide_segment(&base, &ey, 8, "y", N_EIGHTHS);
        let h8 = b.divide_segment(&base, &ex, 8, "h", N_EIGHTHS);
        // 3/8 y along the leg, then 5/8 of the hypotenuse further along the same line.
        let five = (h8[5].g - base.g).norm();
        let sum = b.lay_off(&y8[3], &leg, five, Role::Result, N_ADD)?;
        let yi = b.measure(&base, &sum, &leg, mscale, Label::quiet("Mi", 0), N_MI);
        b.check(
            &yi,
            "ideal moment M_i",
            "kg·m",
            "LH Gl. 13",
            self.mref,
            || ideal(self.mb_closed(x), md, alpha0),
        );
        Ok(yi.g)
    }
}
