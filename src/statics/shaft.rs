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

use super::beam::{construct_beam_numbered, BeamDrawing, BeamRequest, BeamResults};
use super::{Beam, PointLoad};
use crate::kernel::tolerance::REL_POSITION_EPS;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{
    note, Board, ConstructionError, Label, Note, Reading, Role, Scale, Topic, Trace, Weighted, H,
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

/// The torque rectangle CFGH of height `x` mm over the twisted stretch, above the base of
/// the moment areas (LH Abb. 28: C where the area begins, H under the pulley).
fn torque_rectangle(
    b: &mut Board,
    (c, h): (&H<Point>, &H<Point>),
    base: &H<Line>,
    x: f64,
) -> Result<(), ConstructionError> {
    let up_c = b.perpendicular(base, c, Role::Construction, N_TQ_CORNER);
    let up_h = b.perpendicular(base, h, Role::Construction, N_TQ_CORNER);
    // x is laid off upwards: the perpendicular's direction may point either way.
    let sx = if up_c.g.dir.y >= 0.0 { x } else { -x };
    let f = b.lay_off(c, &up_c, sx, Role::Construction.named("F"), N_TQ_CORNER)?;
    let top = b.parallel(base, &f, Role::Construction, N_TQ_CORNER);
    let g = b.meet_point(&top, &up_h, Label::plain("G"), N_TQ_CORNER)?;
    b.curve(&[*c, f, g, *h, *c], Trace::Polygon, Role::Result, N_TQ_RECT);
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
    let k = 1000.0 / dr.length_scale;
    let xs = samples(shaft, k);
    let beam = |loads: &[PointLoad]| Beam {
        supports: shaft.supports,
        ends: shaft.ends,
        point_loads: loads.to_vec(),
        uniform_loads: vec![],
    };
    let (b1, b2) = (beam(&shaft.plane_1), beam(&shaft.plane_2));
    let ms = dr.length_scale / 1000.0 * dr.pole_distance; // kg·m per mm of ordinate
    let mut y_next = dr.origin.y;
    let r1 = plane_moments(b, &b1, dr, &xs, &mut y_next, 0)?;
    let n1 = shaft.plane_1.len() as u32;
    let r2 = plane_moments(b, &b2, dr, &xs, &mut y_next, n1)?;
    // The triangles of Abb. 27 rise by up to |y1| + |y2| above their base points.
    let largest = |r: &BeamResults| {
        r.sections
            .iter()
            .map(|s| s.moment.abs())
            .fold(0.0, f64::max)
    };
    let rise = (largest(&r1) + largest(&r2)) / ms;
    let torque_mm = torque(b, shaft, dr, y_next)?;
    // The resultant and ideal moment areas on one base, the torque rectangle above it.
    let area_y = y_next - torque_mm.map_or(0.0, |(x, _)| x);
    y_next = area_y - rise - AREA_GAP_MM;
    let single = single_plane(shaft, &r1, &r2);
    let mut c = Combine {
        shaft,
        dr,
        k,
        ms,
        y0: y_next - if single.is_some() { 0.0 } else { rise },
        mref: largest(&r1)
            .max(largest(&r2))
            .max(shaft.torque.map_or(0.0, |t| t.md.abs() * shaft.alpha0)),
        s1: super::closed_form::Sections::new(&b1),
        s2: super::closed_form::Sections::new(&b2),
        torque_mm: torque_mm.map(|(_, ax)| ax),
        next_q: f64::NEG_INFINITY,
        next_r: f64::NEG_INFINITY,
    };
    let tol = REL_POSITION_EPS * (shaft.ends[1] - shaft.ends[0]).max(1.0);
    let at = |rows: &[super::SectionRow], x: f64| {
        rows.iter()
            .find(|s| (s.x - x).abs() <= tol)
            .map_or(0.0, |s| s.moment)
    };
    let read = |x: f64| {
        let r = single?;
        let i = r.sections.iter().position(|s| (s.x - x).abs() <= tol)?;
        r.moment_handles.get(i).copied()
    };
    let mut rows = Vec::new();
    let mut area = Vec::new();
    for &x in &xs {
        let (row, sec) = c.section(b, x, (at(&r1.sections, x), at(&r2.sections, x)), read(x))?;
        rows.push(row);
        area.push(sec);
    }
    let areas = Areas {
        shaft,
        k,
        ms,
        origin_x: dr.origin.x,
        base_y: area_y,
        events: sections(shaft),
        tol,
    };
    areas.draw(b, &area, torque_mm.map(|(x, _)| x))?;
    Ok(rows)
}

/// One plane alone, sagging everywhere: its moment area is the bending moment area, read off
/// at each section already (LH Abb. 28 draws no parallelogram).
fn single_plane<'r>(
    shaft: &Shaft,
    r1: &'r BeamResults,
    r2: &'r BeamResults,
) -> Option<&'r BeamResults> {
    let sagging = |r: &BeamResults| r.sections.iter().all(|s| s.moment >= 0.0);
    match (shaft.plane_1.is_empty(), shaft.plane_2.is_empty()) {
        (false, true) if sagging(r1) => Some(r1),
        (true, false) if sagging(r2) => Some(r2),
        _ => None,
    }
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

/// Sheet mm between two sections of a stretch where the resultant or ideal moment is curved
/// (LH C.7: "durch häufige Wiederholung der Konstruktion"), at most.
const SAMPLE_MM: f64 = 12.0;
/// Equal parts a curved stretch between two sections is divided into, at most.
const MAX_PARTS: usize = 6;

/// The sections the moments are constructed at: the ends, the [`sections`], and, between two
/// of them where M_b or M_i is curved (loads in both planes at an angle; a torque), equal
/// parts of at most [`SAMPLE_MM`] on the sheet. Where M_b and M_i are straight between two
/// sections (one plane, no torque), the two sections give the line.
fn samples(shaft: &Shaft, k: f64) -> Vec<f64> {
    let mut events = shaft.ends.to_vec();
    events.extend(sections(shaft));
    events.sort_by(f64::total_cmp);
    let span = shaft.ends[1] - shaft.ends[0];
    let tol = REL_POSITION_EPS * span.max(1.0);
    events.dedup_by(|a, b| (*a - *b).abs() <= tol);
    let both = !shaft.plane_1.is_empty()
        && !shaft.plane_2.is_empty()
        && crate::kernel::angle::sin_cos_deg(shaft.angle_deg).0.abs() > REL_POSITION_EPS;
    let twisted = |a: f64, b: f64| {
        shaft
            .torque
            .is_some_and(|t| t.md != 0.0 && a >= t.from - tol && b <= t.to + tol)
    };
    let mut xs = vec![events[0]];
    for w in events.windows(2) {
        let (a, b) = (w[0], w[1]);
        if both || twisted(a, b) {
            let parts = ((b - a) * k / SAMPLE_MM)
                .ceil()
                .clamp(1.0, MAX_PARTS as f64) as usize;
            xs.extend((1..parts).map(|j| a + (b - a) * j as f64 / parts as f64));
        }
        xs.push(b);
    }
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
    first_load: u32,
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
    let r = construct_beam_numbered(b, bm, &d, &req, xs, first_load)?;
    let ms = dr.length_scale / 1000.0 * dr.pole_distance;
    let depth = r
        .sections
        .iter()
        .map(|s| s.moment.abs())
        .fold(0.0, f64::max)
        / ms;
    *y_next -= depth + PLANE_GAP_MM;
    Ok(r)
}

/// The torque's ordinate by Gl. 12 when the radius is known (its pole triangle right of the
/// shaft at `y`), else at the moment scale. Returns the ordinate x and α₀·x (mm), the leg of
/// the ideal moment's triangle.
fn torque(
    b: &mut Board,
    shaft: &Shaft,
    dr: &BeamDrawing,
    y: f64,
) -> Result<Option<(f64, f64)>, ConstructionError> {
    let Some(t) = shaft.torque.filter(|t| t.md != 0.0) else {
        return Ok(None);
    };
    let ms = dr.length_scale / 1000.0 * dr.pole_distance;
    let k = 1000.0 / dr.length_scale;
    let direct = t.md.abs() / ms;
    Ok(Some(match t.radius {
        Some(r) => {
            let at = Point::new(shaft.ends[1] * k + dr.origin.x + 40.0, y);
            torque_ordinate(b, &t, r, shaft.alpha0, dr, at, Scale::new(ms, "kg·m"))?
        }
        None => (direct, shaft.alpha0 * direct),
    }))
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
    /// The leftmost sheet x the next parallelogram (Abb. 27) may take: each stands at its
    /// section or, where the one before reaches further, a gap right of it.
    next_q: f64,
    /// The same for the triangles of Abb. 29.
    next_r: f64,
}

/// Sheet mm from the deepest ordinate of one plane's moment area to the next plane's beam,
/// which carries its load arrows and their letters above it.
const PLANE_GAP_MM: f64 = 40.0;
/// Sheet mm from the deepest ordinate of the moment areas to the constructions of Abb. 27.
const AREA_GAP_MM: f64 = 25.0;

/// Sheet mm between two neighbouring constructions of Abb. 27 or Abb. 29.
const BESIDE_MM: f64 = 4.0;

impl Combine<'_> {
    /// The closed form of M_b at x.
    fn mb_closed(&self, x: f64) -> f64 {
        combined(self.s1.moment(x), self.s2.moment(x), self.shaft.angle_deg)
    }

    /// Everything at one section: M_b (read off the one plane's area, or by the
    /// parallelogram), M_i by Abb. 29 where a torque acts (elsewhere M_i = M_b), the diameter.
    fn section(
        &mut self,
        b: &mut Board,
        x: f64,
        (m1, m2): (f64, f64),
        read: Option<H<f64>>,
    ) -> Result<(ShaftRow, AreaSection), ConstructionError> {
        let mb = match read {
            Some(h) => self.single(b, x, h),
            None => self.combined(b, x, m1, m2)?,
        };
        let mb_value = mb.map_or(0.0, |h| h.g);
        let tol = REL_POSITION_EPS * (self.shaft.ends[1] - self.shaft.ends[0]).max(1.0);
        let md = (self.shaft.torque)
            .filter(|t| x >= t.from - tol && x <= t.to + tol)
            .map_or(0.0, |t| t.md);
        let mi = if md != 0.0 {
            Some(self.ideal(b, x, mb_value, md)?)
        } else {
            None
        };
        let mi_value = mi.map_or(mb_value, |h| h.g);
        let diameter_mm =
            (self.shaft.kb).map(|kb| 10.0 * super::sizing::shaft_diameter_cm(100.0 * mi_value, kb));
        let row = ShaftRow {
            x,
            m1,
            m2,
            mb: mb_value,
            md,
            mi: mi_value,
            diameter_mm,
        };
        Ok((row, AreaSection { x, mb, mi }))
    }

    /// The moment of the one loaded plane, read off its moment area, as M_b (no
    /// parallelogram: LH Abb. 28), none where it is nought.
    fn single(&mut self, b: &mut Board, x: f64, h: H<f64>) -> Option<H<f64>> {
        if h.g <= b.tolerance().length * self.ms {
            return None;
        }
        if let Some(kb) = self.shaft.kb {
            self.diameter(b, x, &h, kb);
        }
        Some(h)
    }

    /// The parallelogram of the ordinates (Abb. 27) at the section's base point: y₁ up, y₂
    /// turned through α from it; the diagonal is M_b, read off and checked.
    fn combined(
        &mut self,
        b: &mut Board,
        x: f64,
        m1: f64,
        m2: f64,
    ) -> Result<Option<H<f64>>, ConstructionError> {
        let (ms, mscale) = (self.ms, Scale::new(self.ms, "kg·m"));
        let (sin_a, cos_a) = crate::kernel::angle::sin_cos_deg(self.shaft.angle_deg);
        // y₂ reaches -y₂·sin α to the side of the base point.
        let side = -m2 / ms * sin_a;
        let qx = (x * self.k + self.dr.origin.x).max(self.next_q - side.min(0.0));
        self.next_q = qx + side.max(0.0) + BESIDE_MM;
        let q = b.point(
            Point::new(qx, self.y0),
            Role::Given.labelled(Label::quiet("Q", 0)),
            N_BASE,
        );
        let (aux, con) = (Role::Auxiliary, Role::Construction);
        let dir1 = b.line_dir(&q, Vector::new(0.0, 1.0), aux, N_DIR1)?;
        let e1 = b.lay_off(&q, &dir1, m1 / ms, con, N_Y1)?;
        // The second plane turned through α from the first (counter-clockwise from "up").
        let dir2 = b.line_dir(&e1, Vector::new(-sin_a, cos_a), aux, N_DIR2)?;
        let e2 = b.lay_off(&e1, &dir2, m2 / ms, con, N_Y2)?;
        if (e2.g - q.g).norm() <= b.tolerance().length {
            return Ok(None);
        }
        let yl = b.line_through(&q, &e2, Role::Result, N_Y)?;
        let h = b.measure(&q, &e2, &yl, mscale, Label::quiet("Mb", 0), N_MB);
        let formula = "LH C.7: √(M1² + M2² + 2 M1 M2 cos α)";
        let what = "resultant bending moment M_b";
        b.check(&h, what, "kg·m", formula, self.mref, || self.mb_closed(x));
        if let Some(kb) = self.shaft.kb {
            self.diameter(b, x, &h, kb);
        }
        Ok(Some(h))
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
    fn ideal(
        &mut self,
        b: &mut Board,
        x: f64,
        mb: f64,
        md: f64,
    ) -> Result<H<f64>, ConstructionError> {
        let (ms, mscale) = (self.ms, Scale::new(self.ms, "kg·m"));
        let rx = (x * self.k + self.dr.origin.x + BESIDE_MM).max(self.next_r);
        self.next_r = rx + mb.abs() / ms + BESIDE_MM;
        let tx = self.torque_mm.unwrap_or(self.shaft.alpha0 * md.abs() / ms);
        let at = Point::new(rx, self.y0 - 10.0 - tx);
        let base = b.point(at, Role::Given.labelled(Label::quiet("R", 0)), N_BASE);
        let (aux, con) = (Role::Auxiliary, Role::Construction);
        let leg = b.line_dir(&base, Vector::new(1.0, 0.0), aux, N_LEG_Y)?;
        let ey = b.lay_off(&base, &leg, mb / ms, con, N_LEG_Y)?;
        let normal = b.perpendicular(&leg, &ey, aux, N_NORMAL);
        let alpha0 = self.shaft.alpha0;
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
        Ok(yi)
    }
}

const N_AREA_BASE: Note = note(
    "base of the resultant and ideal moment areas",
    Some("Momentenfläche"),
    "LH C.7-8, Abb. 26, 28",
    Topic::Moment,
);
const N_AREA_MB: Note = note(
    "resultant bending ordinate y carried to the section with the dividers",
    Some("resultierendes Biegungsmoment"),
    "LH C.7, Abb. 26",
    Topic::Moment,
);
const N_AREA_LINE: Note = note(
    "the resultant bending moment area",
    Some("Momentenfläche UVWZ"),
    "LH C.7, Abb. 26",
    Topic::Moment,
);
const N_AREA_MI: Note = note(
    "ideal ordinate y_i laid off from the bending line towards the torque",
    Some("ideelles Moment"),
    "LH C.8, Gl. 13, Abb. 28",
    Topic::Moment,
);
const N_AREA_CURVE: Note = note(
    "the curve RN of the ideal moment: the ideal moment area CEDHNR",
    Some("ideelle Momentenfläche"),
    "LH C.8, Abb. 28",
    Topic::Moment,
);

/// One section of the moment areas: the resultant bending moment read off there (none where
/// it is zero) and the ideal moment (where a torque acts).
struct AreaSection {
    x: f64,
    mb: Option<H<f64>>,
    mi: Option<H<f64>>,
}

/// The resultant bending moment area on a base of its own, its ordinates carried over from
/// the parallelograms (LH Abb. 26: UVWZ), and, where a torque acts, the torque rectangle CFGH
/// above the base and the ideal moment laid off from the bending line through the base
/// towards it: the curve RN, the ideal moment area CEDHNR (LH Abb. 28).
struct Areas<'a> {
    shaft: &'a Shaft,
    k: f64,
    ms: f64,
    origin_x: f64,
    base_y: f64,
    /// Supports, loads and the ends of the torque.
    events: Vec<f64>,
    tol: f64,
}

impl Areas<'_> {
    fn at(&self, x: f64, y: f64) -> bool {
        (x - y).abs() <= self.tol
    }

    /// The book's letters: on the base U … Z (C, H, E with a torque), at the bending line V, W …
    /// under the loads (D at the end of the torque).
    fn names(&self, secs: &[AreaSection]) -> (Vec<Label>, Vec<Label>) {
        let t = self.shaft.torque.filter(|t| t.md != 0.0);
        let last = secs.len() - 1;
        let mut next = ["V", "W", "X", "Y"].into_iter();
        let loads: Vec<f64> = self
            .shaft
            .plane_1
            .iter()
            .chain(&self.shaft.plane_2)
            .map(|l| l.x)
            .collect();
        let mut feet = Vec::new();
        let mut tops = Vec::new();
        for (i, s) in secs.iter().enumerate() {
            let foot = match t {
                Some(t) if self.at(s.x, t.from) => Label::plain("C"),
                Some(t) if self.at(s.x, t.to) => Label::plain("H"),
                Some(_) if i == last => Label::plain("E"),
                None if i == 0 => Label::plain("U"),
                None if i == last => Label::plain("Z"),
                _ => Label::NONE,
            };
            let top = match t {
                Some(t) if self.at(s.x, t.to) && s.mb.is_some() => Label::plain("D"),
                None if s.mb.is_some() && loads.iter().any(|&x| self.at(s.x, x)) => {
                    next.next().map_or(Label::NONE, Label::plain)
                }
                _ => Label::NONE,
            };
            feet.push(foot);
            tops.push(top);
        }
        (feet, tops)
    }

    /// Feet on the base, M_b carried down from each, M_i laid back up from the bending line.
    fn draw(
        &self,
        b: &mut Board,
        secs: &[AreaSection],
        torque_x: Option<f64>,
    ) -> Result<(), ConstructionError> {
        let (feet_names, top_names) = self.names(secs);
        let x0 = secs[0].x;
        let left = b.point(
            Point::new(x0 * self.k + self.origin_x, self.base_y),
            Role::Given.labelled(feet_names[0].clone()),
            N_AREA_BASE,
        );
        let base = b.line_dir(&left, Vector::new(1.0, 0.0), Role::Axis, N_AREA_BASE)?;
        let (aux, con) = (Role::Auxiliary, Role::Construction);
        let (mut feet, mut tops, mut ideals) = (vec![], vec![], vec![]);
        for (i, s) in secs.iter().enumerate() {
            let foot = if i == 0 {
                left
            } else {
                let name = feet_names[i].clone();
                b.lay_off(
                    &left,
                    &base,
                    (s.x - x0) * self.k,
                    con.labelled(name),
                    N_AREA_BASE,
                )?
            };
            let top = match &s.mb {
                Some(mb) => {
                    let down = b.line_dir(&foot, Vector::new(0.0, -1.0), aux, N_AREA_MB)?;
                    let reading = Reading {
                        value: mb,
                        per_mm: self.ms,
                    };
                    let mark = con.labelled(top_names[i].clone());
                    b.transfer(&foot, &down, reading, mark, N_AREA_MB)?
                }
                None => foot,
            };
            if let Some(mi) = &s.mi {
                let name = if ideals.is_empty() {
                    Label::plain("R")
                } else if secs.get(i + 1).is_none_or(|n| n.mi.is_none()) {
                    Label::plain("N")
                } else {
                    Label::NONE
                };
                ideals.push((i, self.ideal_point(b, &top, mi, name)?));
            }
            feet.push(foot);
            tops.push(top);
        }
        self.outline(b, &tops, Role::Result, N_AREA_LINE);
        self.ideal_outline(b, &tops, &ideals);
        if let (Some(t), Some(x)) = (self.shaft.torque, torque_x) {
            let c = secs.iter().position(|s| self.at(s.x, t.from));
            let h = secs.iter().position(|s| self.at(s.x, t.to));
            if let (Some(c), Some(h)) = (c, h) {
                torque_rectangle(b, (&feet[c], &feet[h]), &base, x)?;
            }
        }
        Ok(())
    }

    /// The ideal ordinate laid off from the bending line `top` up through the base.
    fn ideal_point(
        &self,
        b: &mut Board,
        top: &H<Point>,
        mi: &H<f64>,
        name: Label,
    ) -> Result<H<Point>, ConstructionError> {
        let up = b.line_dir(top, Vector::new(0.0, 1.0), Role::Auxiliary, N_AREA_MI)?;
        let reading = Reading {
            value: mi,
            per_mm: self.ms,
        };
        b.transfer(
            top,
            &up,
            reading,
            Role::Construction.labelled(name),
            N_AREA_MI,
        )
    }

    /// The ideal curve RN through the ideal points, its last point named N, and the verticals
    /// at its ends, which close the area CEDHNR with the bending line.
    fn ideal_outline(&self, b: &mut Board, tops: &[H<Point>], ideals: &[(usize, H<Point>)]) {
        let (Some(&(i0, p0)), Some(&(i1, p1))) = (ideals.first(), ideals.last()) else {
            return;
        };
        if i1 == i0 {
            return;
        }
        let pts: Vec<H<Point>> = ideals.iter().map(|(_, p)| *p).collect();
        b.curve(&pts, Trace::Smooth, Role::Result, N_AREA_CURVE);
        b.segment(&tops[i0], &p0, Role::Result, N_AREA_CURVE);
        b.segment(&tops[i1], &p1, Role::Result, N_AREA_CURVE);
    }

    /// The bending line through `pts`, smooth between two events (where it is curved), with
    /// corners at the events.
    fn outline(&self, b: &mut Board, pts: &[H<Point>], role: Role, note: Note) {
        let mut from = 0;
        for i in 1..pts.len() {
            let x = (pts[i].g.x - self.origin_x) / self.k;
            if i == pts.len() - 1 || self.events.iter().any(|&e| self.at(x, e)) {
                let trace = if i - from > 1 {
                    Trace::Smooth
                } else {
                    Trace::Polygon
                };
                b.curve(&pts[from..=i], trace, role, note.clone());
                from = i;
            }
        }
    }
}
