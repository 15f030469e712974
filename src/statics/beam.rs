//! Beams by the funicular polygon: reactions by the closing line (LH C.4, Abb. 24), the moment
//! area M = y·H (C.5, Gl. 11), the shear diagram from the force plan (C.6, Abb. 25), overhangs
//! with their undercut moment area (Aufgabe 6, Abb. 34), and the parabola of a uniform load
//! drawn by its tangents (Abb. 36, 37).
//!
//! # The construction
//! The loads are laid off head to tail on the load line; the pole O lies at the pole distance
//! H to the right of it. The strings of the funicular polygon run parallel to the pole rays
//! between the verticals of the loads (a uniform load acts, for the polygon, as its resultant
//! at its centre). The **first** string (before every load), extended, cuts the vertical of
//! support A, and the **last** string cuts the vertical of support B: the line through these
//! two points is the closing line. Its parallel through O cuts the load line in C, which divides
//! it into A and B. The moment at a section is H times the ordinate from the polygon to the
//! closing line — on an overhang, to the first or last string instead, so that with overhangs
//! the moment area is undercut (*hinterschnitten*). Over a uniform load the polygon's corner is
//! replaced by the parabola that touches the two strings at the verticals of the load's ends:
//! both tangents are divided into equal parts, the joins 1–1, 2–2, … are tangents of the
//! parabola, and each touches it at the point dividing it in the same ratio.

use super::closed_form as cf;
use super::Beam;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{note, Board, ConstructionError, Label, Note, Role, Scale, Topic, H};
use serde::Serialize;

const N_BEAM_START: Note = note(
    "left end of the beam",
    Some("Trägerende"),
    "LH Abb. 24",
    Topic::Loads,
);
const N_BEAM_AXIS: Note = note("beam axis", Some("Trägerachse"), "LH Abb. 24", Topic::Loads);
const N_BEAM_END: Note = note(
    "right end of the beam",
    Some("Trägerende"),
    "LH Abb. 24",
    Topic::Loads,
);
const N_BEAM: Note = note("the beam", Some("Träger"), "LH Abb. 24", Topic::Loads);
const N_SUPPORT: Note = note("support", Some("Auflager"), "LH Abb. 24", Topic::Loads);
const N_SUPPORT_SYMBOL: Note = note(
    "support drawn",
    Some("Auflager"),
    "LH Abb. 24",
    Topic::Loads,
);
const N_SUPPORT_VERTICAL: Note = note(
    "vertical through the support",
    Some("Auflagersenkrechte"),
    "LH Abb. 24",
    Topic::Loads,
);
const N_LOAD: Note = note("point load", Some("Einzellast"), "LH Abb. 24", Topic::Loads);
const N_LOAD_ARROW: Note = note(
    "point load drawn",
    Some("Einzellast"),
    "LH Abb. 24",
    Topic::Loads,
);
const N_UNIFORM: Note = note(
    "uniform load",
    Some("gleichmäßig verteilte Last"),
    "LH Abb. 36",
    Topic::Loads,
);
const N_UNIFORM_RESULTANT: Note = note(
    "its resultant Q = q·l at the centre",
    Some("Mittelkraft im Schwerpunkt"),
    "LH Abb. 36",
    Topic::Loads,
);
const N_LOAD_VERTICAL: Note = note(
    "line of action of the load",
    Some("Kraftrichtung"),
    "LH Abb. 22, 24",
    Topic::Loads,
);
const N_END_VERTICAL: Note = note(
    "vertical through an end of the uniform load",
    Some("Lastgrenze"),
    "LH Abb. 36",
    Topic::Loads,
);
const N_LOAD_LINE_START: Note = note(
    "start of the load line",
    Some("Kräftepolygon"),
    "LH Abb. 24",
    Topic::ForcePlan,
);
const N_LOAD_LINE: Note = note(
    "load line",
    Some("Kräftepolygon"),
    "LH Abb. 24",
    Topic::ForcePlan,
);
const N_LAY_OFF: Note = note(
    "lay off the load at the force scale",
    Some("Kräftemaßstab"),
    "LH A.1, Abb. 24",
    Topic::ForcePlan,
);
const N_POLE: Note = note(
    "pole O at the pole distance H",
    Some("Pol, Polweite"),
    "LH Abb. 22, 24",
    Topic::ForcePlan,
);
const N_RAY: Note = note(
    "pole ray",
    Some("Polstrahl"),
    "LH Abb. 22, 24",
    Topic::ForcePlan,
);
const N_START: Note = note(
    "start of the funicular polygon",
    Some("Seilpolygon"),
    "LH Abb. 24",
    Topic::Funicular,
);
const N_STRING: Note = note(
    "string parallel to the pole ray",
    Some("Seilseite"),
    "LH Abb. 22, 24",
    Topic::Funicular,
);
const N_CORNER: Note = note(
    "string cuts the next line of action",
    Some("Seileck"),
    "LH Abb. 22, 24",
    Topic::Funicular,
);
const N_END_STRING_CUT: Note = note(
    "first or last string cuts the support vertical",
    Some("Seilseite"),
    "LH Abb. 24, 34",
    Topic::Reactions,
);
const N_CLOSING: Note = note(
    "closing line",
    Some("Schlußlinie"),
    "LH Abb. 24",
    Topic::Reactions,
);
const N_CLOSING_PARALLEL: Note = note(
    "parallel to the closing line through the pole",
    Some("Parallele zur Schlußlinie"),
    "LH Abb. 24",
    Topic::Reactions,
);
const N_C: Note = note(
    "it cuts the load line: A and B",
    Some("Auflagerdrücke"),
    "LH Abb. 24",
    Topic::Reactions,
);
const N_REACTION_A: Note = note(
    "reaction A read off the load line",
    Some("Auflagerdruck A"),
    "LH Abb. 24",
    Topic::Reactions,
);
const N_REACTION_B: Note = note(
    "reaction B read off the load line",
    Some("Auflagerdruck B"),
    "LH Abb. 24",
    Topic::Reactions,
);
const N_REACTION_ARROW: Note = note(
    "reaction drawn",
    Some("Auflagerdruck"),
    "LH Abb. 24",
    Topic::Reactions,
);
const N_POLY_AT: Note = note(
    "the polygon on the vertical of the section",
    Some("Seilpolygon"),
    "LH Abb. 24",
    Topic::Moment,
);
const N_REF_AT: Note = note(
    "closing line (or end string) on the vertical of the section",
    Some("Schlußlinie"),
    "LH Abb. 24, 34",
    Topic::Moment,
);
const N_ORDINATE: Note = note(
    "ordinate y of the moment area",
    Some("Momentenordinate"),
    "LH Gl. 11",
    Topic::Moment,
);
const N_MOMENT: Note = note(
    "bending moment M = y·H",
    Some("Biegungsmoment"),
    "LH Gl. 11",
    Topic::Moment,
);
const N_TANGENT_POINT: Note = note(
    "string cuts the vertical at the end of the load: tangent point",
    Some("Berührungspunkt"),
    "LH Abb. 36",
    Topic::Moment,
);
const N_DIVIDE_TANGENT: Note = note(
    "divide the tangent into equal parts",
    Some("Teilung der Tangente"),
    "LH Abb. 36",
    Topic::Moment,
);
const N_ENVELOPE: Note = note(
    "join k–k: a tangent of the parabola",
    Some("Parabeltangente"),
    "LH Abb. 36",
    Topic::Moment,
);
const N_TOUCH: Note = note(
    "the point dividing the join in the same ratio lies on the parabola",
    Some("Parabelpunkt"),
    "LH Abb. 36",
    Topic::Moment,
);
const N_PARABOLA: Note = note(
    "parabola of the uniform load",
    Some("Parabel"),
    "LH Abb. 36, 37",
    Topic::Moment,
);
const N_SECTION_VERTICAL: Note = note(
    "vertical through the section",
    Some("Schnitt"),
    "LH Abb. 24",
    Topic::Moment,
);
const N_INFLECTION: Note = note(
    "the polygon cuts the closing line: zero moment",
    Some("Wendepunkt"),
    "LH Abb. 34",
    Topic::Moment,
);
const N_INFLECTION_X: Note = note(
    "position of the zero moment",
    Some("Querschnitt C"),
    "LH Abb. 34",
    Topic::Moment,
);
const N_SHEAR_BASE_START: Note = note(
    "zero line of the shear diagram",
    Some("Nullinie"),
    "LH Abb. 25",
    Topic::Shear,
);
const N_SHEAR_BASE: Note = note(
    "zero line of the shear diagram",
    Some("Nullinie"),
    "LH Abb. 25",
    Topic::Shear,
);
const N_SHEAR_FOOT: Note = note(
    "section on the zero line",
    Some("Nullinie"),
    "LH Abb. 25",
    Topic::Shear,
);
const N_SHEAR_MEASURE: Note = note(
    "shear force from the force plan",
    Some("Querkraft"),
    "LH C.6, Abb. 25",
    Topic::Shear,
);
const N_SHEAR_ORDINATE: Note = note(
    "transfer the shear force as ordinate",
    Some("Querkraftordinate"),
    "LH Abb. 25",
    Topic::Shear,
);
const N_SHEAR_DIAGRAM: Note = note(
    "shear diagram",
    Some("Querkraftdiagramm"),
    "LH Abb. 25",
    Topic::Shear,
);
const N_SHEAR_ZERO: Note = note(
    "the sloping shear line cuts the zero line: largest moment",
    Some("Nullpunkt der Querkraft"),
    "LH Abb. 36, 37",
    Topic::Shear,
);
const N_SHEAR_ZERO_X: Note = note(
    "position of the zero shear",
    Some("Nullpunkt"),
    "LH Abb. 36",
    Topic::Shear,
);
const N_RATIO_1: Note = note(
    "the same ratio on the first tangent",
    Some("Teilverhältnis"),
    "LH Abb. 36",
    Topic::Moment,
);
const N_RATIO_2: Note = note(
    "the same ratio on the second tangent",
    Some("Teilverhältnis"),
    "LH Abb. 36",
    Topic::Moment,
);
const N_RATIO_JOIN: Note = note(
    "their join, a tangent of the parabola",
    Some("Parabeltangente"),
    "LH Abb. 36",
    Topic::Moment,
);
const N_RATIO_POINT: Note = note(
    "the parabola point over the zero shear",
    Some("Parabelpunkt"),
    "LH Abb. 36",
    Topic::Moment,
);

/// Length of a load arrow in the position plan (mm): the plan shows position and sense only.
const ARROW_MM: f64 = 12.0;
/// Gap between the beam and the force plan, and between the figure's parts (mm).
const GAP_MM: f64 = 25.0;
/// Half width of a drawn support (mm).
const SUPPORT_MM: f64 = 4.0;

/// Scales and choices of the drawing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BeamDrawing {
    /// Length scale 1 : n (m of beam per m of sheet).
    pub length_scale: f64,
    /// kg per mm of sheet.
    pub force_scale: f64,
    /// Pole distance H (kg).
    pub pole_distance: f64,
    /// Equal parts each tangent of a uniform load's parabola is divided into (≥ 2).
    pub parabola_divisions: usize,
    /// Where x = 0 of the beam lies on the sheet (mm), so that several beams (the two planes
    /// of a shaft) can share one sheet.
    pub origin: [f64; 2],
}

/// What to construct beyond the reactions (which everything needs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct BeamRequest {
    /// The moment area: M at every load, support and parabola point, zero moments.
    pub moment_area: bool,
    /// The shear diagram and the largest moment where the shear changes sign.
    pub shear_diagram: bool,
}

/// Constructed values at one section of the beam.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionRow {
    /// Position (m).
    pub x: f64,
    /// What is there ("P1", "A", "q1 2/8").
    pub what: String,
    /// Bending moment (kg·m).
    pub moment: f64,
}

/// The results of [`construct_beam`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BeamResults {
    /// Reactions A and B (kg).
    pub reactions: (f64, f64),
    /// Moments at the sections, ordered by x.
    pub sections: Vec<SectionRow>,
    /// Zero moments between the supports (m).
    pub zero_moments: Vec<f64>,
    /// Shear just right of each event: (x, V) (kg).
    pub shear: Vec<(f64, f64, f64)>,
    /// Largest |M| and where (kg·m, m), if the shear diagram was asked for.
    pub max_moment: Option<(f64, f64)>,
    /// The measured moment of each section, in the order of `sections`, for further checks.
    #[serde(skip)]
    pub moment_handles: Vec<H<f64>>,
}

/// A uniform load's force index, first tangent point, polygon corner, second tangent point.
type Tangents = (usize, H<Point>, H<Point>, H<Point>);

#[derive(Clone, Copy)]
enum Kind {
    Point(usize),
    Uniform(usize),
}

#[derive(Clone, Copy)]
struct Force {
    x: f64,
    p: f64,
    kind: Kind,
}

/// Constructs reactions, moment area and shear diagram of a beam on `board`.
///
/// # Errors
/// A [`ConstructionError`] if a step has no solution (a pole on the load line); a validated
/// scene never produces one.
///
/// ```
/// use graphostatik::statics::*;
/// use graphostatik::protocol::Board;
/// let beam = Beam { supports: [0.0, 6.0], ends: [0.0, 6.0],
///     point_loads: vec![PointLoad { x: 2.0, p: 600.0 }], uniform_loads: vec![] };
/// let drawing = BeamDrawing { length_scale: 50.0, force_scale: 20.0, pole_distance: 500.0,
///     parabola_divisions: 8, origin: [0.0, 0.0] };
/// let mut board = Board::new(300.0, true);
/// let r = construct_beam(&mut board, &beam, &drawing,
///     &BeamRequest { moment_area: true, shear_diagram: true }).unwrap();
/// assert!((r.reactions.0 - 400.0).abs() < 1e-9 && (r.reactions.1 - 200.0).abs() < 1e-9);
/// // M under the load = A·a = 400 kg · 2 m (LH Gl. 11).
/// assert!((r.max_moment.unwrap().0 - 800.0).abs() < 1e-9);
/// assert!(board.steps().iter().flat_map(|s| &s.checks).all(|c| c.passed));
/// ```
pub fn construct_beam(
    b: &mut Board,
    beam: &Beam,
    dr: &BeamDrawing,
    req: &BeamRequest,
) -> Result<BeamResults, ConstructionError> {
    construct_beam_at(b, beam, dr, req, &[])
}

/// [`construct_beam`], with the moment also measured at the given sections (m): a vertical
/// through the section cuts the polygon and the closing line (LH Abb. 24, section C). Sections
/// at a load or support are there already; sections inside a uniform load are refused (its
/// moment line is the parabola, read off at its division points).
///
/// # Errors
/// As [`construct_beam`], and [`ConstructionError::Unsupported`] for a section off the beam or
/// inside a uniform load.
pub fn construct_beam_at(
    b: &mut Board,
    beam: &Beam,
    dr: &BeamDrawing,
    req: &BeamRequest,
    extra_sections: &[f64],
) -> Result<BeamResults, ConstructionError> {
    for &x in extra_sections {
        if !(x >= beam.ends[0] && x <= beam.ends[1]) {
            return Err(ConstructionError::unsupported(
                "sections",
                format!("section x = {x} m lies off the beam"),
            ));
        }
        if beam.uniform_loads.iter().any(|u| x > u.from && x < u.to) {
            return Err(ConstructionError::unsupported("sections", format!(
                "section x = {x} m lies inside a uniform load: its moments are read off the parabola"
            )));
        }
    }
    check_layout(beam)?;
    // About 40 steps and 60 objects per load when everything is drawn.
    let nloads = beam.point_loads.len() + beam.uniform_loads.len() * (dr.parabola_divisions + 4);
    b.reserve(64 + 40 * nloads, 64 + 60 * nloads);
    let k = 1000.0 / dr.length_scale;
    let [ox, oy] = dr.origin;
    let sx = |x: f64| x * k + ox;
    let sy = |y: f64| y + oy;
    let fs = dr.force_scale;
    let h_mm = dr.pole_distance / fs;
    let down = Vector::new(0.0, -1.0);
    let up = Vector::new(0.0, 1.0);
    let kg = Scale::kg(fs);
    let moment_scale = Scale {
        per_mm: dr.length_scale / 1000.0 * dr.pole_distance,
        unit: "kg·m",
    };
    let (ra, rb) = cf::reactions(beam);
    // The closed forms of the checks, prepared once: O(log n) a section.
    let sections_cf = cf::Sections::new(beam);
    let total: f64 = beam.point_loads.iter().map(|l| l.p).sum::<f64>()
        + beam
            .uniform_loads
            .iter()
            .map(|u| u.resultant())
            .sum::<f64>();
    let pref = beam
        .point_loads
        .iter()
        .map(|l| l.p.abs())
        .chain(beam.uniform_loads.iter().map(|u| u.resultant().abs()))
        .fold(0.0, f64::max)
        .max(ra.abs())
        .max(rb.abs());
    let span = beam.ends[1] - beam.ends[0];
    let mref = pref * span;

    // The forces of the polygon, by their lines of action.
    let mut forces: Vec<Force> = beam
        .point_loads
        .iter()
        .enumerate()
        .map(|(i, l)| Force {
            x: l.x,
            p: l.p,
            kind: Kind::Point(i),
        })
        .chain(beam.uniform_loads.iter().enumerate().map(|(i, u)| Force {
            x: u.centre(),
            p: u.resultant(),
            kind: Kind::Uniform(i),
        }))
        .collect();
    forces.sort_by(|a, b| a.x.total_cmp(&b.x));
    let n = forces.len();

    // --- Position plan ----------------------------------------------------------------
    let left = b.point(
        Point::new(sx(beam.ends[0]), sy(0.0)),
        Label::NONE,
        Role::Given,
        N_BEAM_START,
    );
    let axis = b.line_dir(
        &left,
        Vector::new(1.0, 0.0),
        Label::NONE,
        Role::Axis,
        N_BEAM_AXIS,
    )?;
    let right = b.point(
        Point::new(sx(beam.ends[1]), sy(0.0)),
        Label::NONE,
        Role::Given,
        N_BEAM_END,
    );
    b.segment(&left, &right, Label::NONE, Role::Result, N_BEAM);
    let mut supports = Vec::new();
    let mut support_verticals = Vec::new();
    for (i, &x) in beam.supports.iter().enumerate() {
        let name = if i == 0 { "A" } else { "B" };
        let p = b.point(
            Point::new(sx(x), sy(0.0)),
            Label::plain(name),
            Role::Given,
            N_SUPPORT,
        );
        let l = b.point(
            Point::new(sx(x) - SUPPORT_MM, sy(-1.5)),
            Label::NONE,
            Role::Given,
            N_SUPPORT_SYMBOL,
        );
        let r = b.point(
            Point::new(sx(x) + SUPPORT_MM, sy(-1.5)),
            Label::NONE,
            Role::Given,
            N_SUPPORT_SYMBOL,
        );
        b.segment(&l, &r, Label::NONE, Role::Guide, N_SUPPORT_SYMBOL);
        support_verticals.push(b.line_dir(
            &p,
            down,
            Label::NONE,
            Role::Construction,
            N_SUPPORT_VERTICAL,
        )?);
        supports.push(p);
    }
    let mut verticals: Vec<H<Line>> = Vec::with_capacity(n);
    let mut end_verticals: Vec<(H<Line>, H<Line>)> = Vec::new();
    for (j, f) in forces.iter().enumerate() {
        let at = b.point(
            Point::new(sx(f.x), sy(0.0)),
            Label::quiet("L", j as u32 + 1),
            Role::Given,
            N_LOAD,
        );
        match f.kind {
            Kind::Point(i) => {
                let tail = b.point(
                    Point::new(sx(f.x), sy(ARROW_MM * f.p.signum())),
                    Label::indexed("P", i as u32 + 1),
                    Role::Given,
                    N_LOAD_ARROW,
                );
                b.segment(&tail, &at, Label::NONE, Role::Force, N_LOAD_ARROW);
            }
            Kind::Uniform(i) => {
                let u = beam.uniform_loads[i];
                let hgt = 0.5 * ARROW_MM;
                let corners = [
                    Point::new(sx(u.from), sy(0.0)),
                    Point::new(sx(u.from), sy(hgt)),
                    Point::new(sx(u.to), sy(hgt)),
                    Point::new(sx(u.to), sy(0.0)),
                ];
                let hs: Vec<H<Point>> = corners
                    .iter()
                    .map(|c| H {
                        id: crate::protocol::ObjId::NONE,
                        g: *c,
                    })
                    .collect();
                let a = b.point(corners[0], Label::NONE, Role::Given, N_UNIFORM);
                let bb = b.point(corners[3], Label::NONE, Role::Given, N_UNIFORM);
                b.curve(
                    &hs,
                    false,
                    Label::indexed("q", i as u32 + 1),
                    Role::Given,
                    N_UNIFORM,
                );
                let tail = b.point(
                    Point::new(sx(f.x), sy(ARROW_MM * 1.4)),
                    Label::indexed("Q", i as u32 + 1),
                    Role::Given,
                    N_UNIFORM_RESULTANT,
                );
                b.segment(
                    &tail,
                    &at,
                    Label::NONE,
                    Role::Auxiliary,
                    N_UNIFORM_RESULTANT,
                );
                let va = b.line_dir(&a, down, Label::NONE, Role::Construction, N_END_VERTICAL)?;
                let vb = b.line_dir(&bb, down, Label::NONE, Role::Construction, N_END_VERTICAL)?;
                end_verticals.push((va, vb));
            }
        }
        verticals.push(b.line_dir(&at, down, Label::NONE, Role::Construction, N_LOAD_VERTICAL)?);
    }

    // --- Force plan -------------------------------------------------------------------
    let total_mm = forces.iter().map(|f| f.p.abs()).sum::<f64>() / fs;
    let x_fp = sx(beam.ends[1]) + GAP_MM;
    let top = sy(0.5 * total_mm);
    let p0 = b.point(
        Point::new(x_fp, top),
        Label::plain("0"),
        Role::Given,
        N_LOAD_LINE_START,
    );
    let load_line = b.line_dir(&p0, down, Label::NONE, Role::Construction, N_LOAD_LINE)?;
    let mut pts = vec![p0];
    for (j, f) in forces.iter().enumerate() {
        let prev = pts[j];
        pts.push(b.lay_off(
            &prev,
            &load_line,
            f.p / fs,
            Label::indexed("", j as u32 + 1),
            Role::Force,
            N_LAY_OFF,
        )?);
    }
    // The pole on the right of the load line, at mid-height of the loads: the polygon sags.
    let net_mm = total / fs;
    let pole = b.point(
        Point::new(x_fp + h_mm, top - 0.5 * net_mm),
        Label::plain("O"),
        Role::Given,
        N_POLE,
    );
    let mut rays = Vec::with_capacity(n + 1);
    for p in &pts {
        rays.push(b.line_through(&pole, p, Label::NONE, Role::Construction, N_RAY)?);
    }

    // --- Funicular polygon ------------------------------------------------------------
    // Start on the leftmost vertical (support or load) below the beam.
    let y_f = -(GAP_MM + 0.5 * ARROW_MM);
    let x_first = forces
        .first()
        .map_or(beam.supports[0], |f| f.x)
        .min(beam.supports[0]);
    let start = b.point(
        Point::new(sx(x_first), sy(y_f)),
        Label::plain("I"),
        Role::Given,
        N_START,
    );
    let mut strings: Vec<H<Line>> = Vec::with_capacity(n + 1);
    strings.push(b.parallel(&rays[0], &start, Label::NONE, Role::Result, N_STRING));
    let mut corners: Vec<H<Point>> = Vec::with_capacity(n);
    for j in 0..n {
        let corner = b.meet_point(
            &strings[j],
            &verticals[j],
            Label::quiet("II", j as u32),
            N_CORNER,
        )?;
        corners.push(corner);
        strings.push(b.parallel(&rays[j + 1], &corner, Label::NONE, Role::Result, N_STRING));
    }
    // Closing line: first string on vertical A, last string on vertical B.
    let ia = b.meet_point(
        &strings[0],
        &support_verticals[0],
        Label::quiet("IA", 0),
        N_END_STRING_CUT,
    )?;
    let ib = b.meet_point(
        &strings[n],
        &support_verticals[1],
        Label::quiet("IB", 0),
        N_END_STRING_CUT,
    )?;
    let closing = b.line_through(&ia, &ib, Label::plain("s"), Role::Given, N_CLOSING)?;
    let par = b.parallel(
        &closing,
        &pole,
        Label::NONE,
        Role::Auxiliary,
        N_CLOSING_PARALLEL,
    );
    let c = b.meet_point(&par, &load_line, Label::plain("C"), N_C)?;
    let a_val = b.measure(&p0, &c, &load_line, kg, Label::quiet("A", 0), N_REACTION_A);
    b.check(&a_val, "reaction A", "kg", "ΣM_B = 0", pref, || ra);
    let b_val = b.measure(
        &c,
        &pts[n],
        &load_line,
        kg,
        Label::quiet("B", 0),
        N_REACTION_B,
    );
    b.check(&b_val, "reaction B", "kg", "ΣV = 0", pref, || rb);
    for (i, s) in supports.iter().enumerate() {
        let r = if i == 0 { a_val.g } else { b_val.g };
        let tail = b.lay_off(
            s,
            &support_verticals[i],
            ARROW_MM * r.signum(),
            Label::NONE,
            Role::Construction,
            N_REACTION_ARROW,
        )?;
        b.segment(&tail, s, Label::NONE, Role::Force, N_REACTION_ARROW);
    }

    // Which string is active at x, and which line the moment is measured to there.
    let string_at = |x: f64| forces.iter().filter(|f| f.x < x).count();
    let reference_at = |x: f64, strings: &[H<Line>]| -> H<Line> {
        if x < beam.supports[0] {
            strings[0]
        } else if x > beam.supports[1] {
            strings[n]
        } else {
            closing
        }
    };

    let mut sections: Vec<SectionRow> = Vec::new();
    // The measured moment of each section, to attach the check of the largest moment to.
    let mut handles: Vec<H<f64>> = Vec::new();
    let mut zero_moments = Vec::new();
    // Per uniform load: its force index, the two tangent points and the polygon corner.
    let mut parabola_data: Vec<Tangents> = Vec::new();

    // --- Moment area ------------------------------------------------------------------
    // Moment at a polygon point on a vertical: ordinate to the reference line, times H.
    // (No string is vertical: the pole lies off the load line, so every vertical cuts it.)
    let moment_at = |b: &mut Board,
                     x: f64,
                     poly: &H<Point>,
                     vertical: &H<Line>|
     -> Result<H<f64>, ConstructionError> {
        let refl = reference_at(x, &strings);
        let z = b.meet_point(&refl, vertical, Label::NONE, N_REF_AT)?;
        b.segment(poly, &z, Label::NONE, Role::Construction, N_ORDINATE);
        let up_line = H {
            id: vertical.id,
            g: Line {
                origin: vertical.g.origin,
                dir: up,
            },
        };
        let m = b.measure(poly, &z, &up_line, moment_scale, Label::NONE, N_MOMENT);
        b.check(
            &m,
            "bending moment M = y·H",
            "kg·m",
            "LH Gl. 11; method of sections",
            mref,
            || sections_cf.moment(x),
        );
        Ok(m)
    };
    if req.moment_area || req.shear_diagram {
        for (i, support_vertical) in support_verticals.iter().enumerate() {
            let x = beam.supports[i];
            let kstr = string_at(x);
            let poly = if kstr == 0 && i == 0 {
                ia
            } else {
                b.meet_point(&strings[kstr], support_vertical, Label::NONE, N_POLY_AT)?
            };
            let m = moment_at(b, x, &poly, support_vertical)?;
            let what = if i == 0 { "A" } else { "B" };
            sections.push(SectionRow {
                x,
                what: what.into(),
                moment: m.g,
            });
            handles.push(m);
        }
        for (j, f) in forces.iter().enumerate() {
            match f.kind {
                Kind::Point(i) => {
                    let m = moment_at(b, f.x, &corners[j], &verticals[j])?;
                    sections.push(SectionRow {
                        x: f.x,
                        what: format!("P{}", i + 1),
                        moment: m.g,
                    });
                    handles.push(m);
                }
                Kind::Uniform(i) => {
                    let u = beam.uniform_loads[i];
                    let (va, vb) = end_verticals[i];
                    let t1 = b.meet_point(
                        &strings[j],
                        &va,
                        Label::quiet("T", 2 * i as u32),
                        N_TANGENT_POINT,
                    )?;
                    let t2 = b.meet_point(
                        &strings[j + 1],
                        &vb,
                        Label::quiet("T", 2 * i as u32 + 1),
                        N_TANGENT_POINT,
                    )?;
                    let m = dr.parabola_divisions.max(2);
                    let d1 = b.divide_segment(&t1, &corners[j], m, "t", N_DIVIDE_TANGENT);
                    let d2 = b.divide_segment(&corners[j], &t2, m, "u", N_DIVIDE_TANGENT);
                    let mut parabola = vec![t1];
                    for kk in 1..m {
                        let join = b.line_through(
                            &d1[kk],
                            &d2[kk],
                            Label::NONE,
                            Role::Construction,
                            N_ENVELOPE,
                        )?;
                        let len = (d2[kk].g - d1[kk].g).norm();
                        let pt = b.lay_off(
                            &d1[kk],
                            &join,
                            len * kk as f64 / m as f64,
                            Label::NONE,
                            Role::Construction,
                            N_TOUCH,
                        )?;
                        parabola.push(pt);
                    }
                    parabola.push(t2);
                    b.curve(&parabola, true, Label::NONE, Role::Result, N_PARABOLA);
                    for (kk, pt) in parabola.iter().enumerate() {
                        let x = u.from + (u.to - u.from) * kk as f64 / m as f64;
                        let vert = if kk == 0 {
                            va
                        } else if kk == m {
                            vb
                        } else {
                            b.perpendicular(
                                &axis,
                                pt,
                                Label::NONE,
                                Role::Auxiliary,
                                N_SECTION_VERTICAL,
                            )
                        };
                        let vert = H {
                            id: vert.id,
                            g: Line {
                                origin: vert.g.origin,
                                dir: down,
                            },
                        };
                        let mm = moment_at(b, x, pt, &vert)?;
                        sections.push(SectionRow {
                            x,
                            what: format!("q{} {kk}/{m}", i + 1),
                            moment: mm.g,
                        });
                        handles.push(mm);
                    }
                    parabola_data.push((j, t1, corners[j], t2));
                }
            }
        }
        // Sections asked for besides the loads and supports.
        let tol_x = 1e-12 * span.max(1.0);
        for &x in extra_sections {
            let known = beam.supports.iter().any(|s| (s - x).abs() <= tol_x)
                || forces
                    .iter()
                    .any(|f| matches!(f.kind, Kind::Point(_)) && (f.x - x).abs() <= tol_x)
                || sections.iter().any(|s| (s.x - x).abs() <= tol_x);
            if known {
                continue;
            }
            let on = b.point(
                Point::new(sx(x), sy(0.0)),
                Label::quiet("x", 0),
                Role::Given,
                N_SECTION_VERTICAL,
            );
            let vertical =
                b.line_dir(&on, down, Label::NONE, Role::Auxiliary, N_SECTION_VERTICAL)?;
            let poly = b.meet_point(&strings[string_at(x)], &vertical, Label::NONE, N_POLY_AT)?;
            let m = moment_at(b, x, &poly, &vertical)?;
            sections.push(SectionRow {
                x,
                what: "x".into(),
                moment: m.g,
            });
            handles.push(m);
        }
        // Zero moments between the supports: a string of the polygon cuts the closing line
        // inside its own stretch.
        for kstr in 0..=n {
            let lo = if kstr == 0 {
                f64::NEG_INFINITY
            } else {
                forces[kstr - 1].x
            };
            let hi = if kstr == n {
                f64::INFINITY
            } else {
                forces[kstr].x
            };
            let (lo, hi) = (lo.max(beam.supports[0]), hi.min(beam.supports[1]));
            if lo >= hi {
                continue;
            }
            // Over a uniform load the polygon is not the moment line: skip those stretches.
            let in_uniform = beam.uniform_loads.iter().any(|u| u.from < hi && u.to > lo);
            if in_uniform {
                continue;
            }
            // Where would they cross? Only a crossing inside the stretch is drawn.
            let inside = match crate::kernel::intersect_line_line(
                &strings[kstr].g,
                &closing.g,
                &b.tolerance(),
            ) {
                crate::kernel::LineLine::Point { point, .. } => {
                    let x = (point.x - ox) / k;
                    let eps = 1e-9 * span;
                    x > lo + eps && x < hi - eps
                }
                _ => false,
            };
            if !inside {
                continue;
            }
            if let crate::protocol::Cut::Point(p, _) =
                b.meet(&strings[kstr], &closing, Label::NONE, N_INFLECTION)
            {
                {
                    let xm = b.measure(
                        &left,
                        &p,
                        &axis,
                        Scale {
                            per_mm: 1.0 / k,
                            unit: "m",
                        },
                        Label::NONE,
                        N_INFLECTION_X,
                    );
                    let x0 = xm.g + beam.ends[0];
                    let xm = H { id: xm.id, g: x0 };
                    // M is linear on this stretch: its zero by interpolation.
                    b.check(
                        &xm,
                        "position of the zero moment",
                        "m",
                        "method of sections",
                        span,
                        || {
                            let (mlo, mhi) = (sections_cf.moment(lo), sections_cf.moment(hi));
                            lo - mlo * (hi - lo) / (mhi - mlo)
                        },
                    );
                    zero_moments.push(x0);
                }
            }
        }
    }

    // --- Shear diagram ----------------------------------------------------------------
    let mut shear = Vec::new();
    let mut max_moment = None;
    if req.shear_diagram {
        // Below everything drawn so far (the polygon hangs as deep as M/H), by the largest
        // shear ordinate.
        let lowest = corners
            .iter()
            .chain([&start, &ia, &ib])
            .chain(pts.iter())
            .map(|p| p.g.y)
            .fold(sy(y_f), f64::min);
        let v_max = ra.abs().max(rb.abs()).max(total.abs()) / fs;
        let y_s = lowest - GAP_MM - v_max;
        let base0 = b.point(
            Point::new(sx(beam.ends[0]), y_s),
            Label::plain("V"),
            Role::Given,
            N_SHEAR_BASE_START,
        );
        let base = b.line_dir(
            &base0,
            Vector::new(1.0, 0.0),
            Label::NONE,
            Role::Axis,
            N_SHEAR_BASE,
        )?;
        // Events: ends, supports, point loads, ends of uniform loads.
        let mut events: Vec<f64> = vec![
            beam.ends[0],
            beam.ends[1],
            beam.supports[0],
            beam.supports[1],
        ];
        events.extend(beam.point_loads.iter().map(|l| l.x));
        for u in &beam.uniform_loads {
            events.push(u.from);
            events.push(u.to);
        }
        events.sort_by(f64::total_cmp);
        events.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * span.max(1.0));
        // Shear just right of x read off the force plan: from the load line point after the
        // loads left of (or at) x to p0, C or pn, by where x lies.
        // How many forces of the load line lie left of the section (at it, too, for the value
        // just right of it); a uniform load counts once its end is passed (V is continuous).
        // Those forces are a prefix of the load line, since no point load lies inside a
        // uniform load; counted by binary search, so that long beams stay linear.
        let mut point_xs: Vec<f64> = beam.point_loads.iter().map(|l| l.x).collect();
        point_xs.sort_by(f64::total_cmp);
        let mut uniform_ends: Vec<f64> = beam.uniform_loads.iter().map(|u| u.to).collect();
        uniform_ends.sort_by(f64::total_cmp);
        let depth_index = |x: f64, right: bool| -> usize {
            let points = if right {
                point_xs.partition_point(|&v| v <= x)
            } else {
                point_xs.partition_point(|&v| v < x)
            };
            points + uniform_ends.partition_point(|&v| v <= x)
        };
        let anchor = |x: f64, right: bool| -> H<Point> {
            let sa = beam.supports[0];
            let sb = beam.supports[1];
            let past_a = if right { x >= sa } else { x > sa };
            let past_b = if right { x >= sb } else { x > sb };
            if past_b {
                pts[n]
            } else if past_a {
                c
            } else {
                pts[0]
            }
        };
        let shear_at = |b: &mut Board, x: f64, right: bool| -> f64 {
            let m = b.measure(
                &pts[depth_index(x, right)],
                &anchor(x, right),
                &load_line,
                kg,
                Label::NONE,
                N_SHEAR_MEASURE,
            );
            let side = if right {
                "shear force V (right of the section)"
            } else {
                "shear force V (left of the section)"
            };
            b.check(&m, side, "kg", "method of sections", pref, || {
                sections_cf.shear(x, !right)
            });
            m.g
        };
        let mut diagram = Vec::new();
        let mut values: Vec<(f64, f64, f64)> = Vec::new();
        for (e, &x) in events.iter().enumerate() {
            let on_beam = b_point(b, sx(x), sy(0.0));
            let foot_v = b.line_dir(
                &on_beam,
                down,
                Label::NONE,
                Role::Auxiliary,
                N_SECTION_VERTICAL,
            )?;
            let foot = b.meet_point(&foot_v, &base, Label::NONE, N_SHEAR_FOOT)?;
            // Shear just left and just right of the event, read off the load line; none
            // outside the ends of the beam.
            let vl = if e == 0 {
                None
            } else {
                Some(shear_at(b, x, false))
            };
            let vr = if e + 1 == events.len() {
                None
            } else {
                Some(shear_at(b, x, true))
            };
            let up_line = H {
                id: foot_v.id,
                g: Line {
                    origin: foot.g,
                    dir: up,
                },
            };
            for v in [vl.unwrap_or(0.0), vr.unwrap_or(0.0)] {
                diagram.push(b.lay_off(
                    &foot,
                    &up_line,
                    v / fs,
                    Label::NONE,
                    Role::Construction,
                    N_SHEAR_ORDINATE,
                )?);
            }
            values.push((x, vl.unwrap_or(0.0), vr.unwrap_or(0.0)));
            shear.push((x, vl.unwrap_or(0.0), vr.unwrap_or(0.0)));
        }
        b.curve(
            &diagram,
            false,
            Label::plain("V"),
            Role::Result,
            N_SHEAR_DIAGRAM,
        );

        // Largest moment: where the shear changes sign — at an event, or inside a uniform load.
        let mut best: Option<(H<f64>, f64)> = None;
        let consider = |best: &mut Option<(H<f64>, f64)>, m: H<f64>, x: f64| {
            if best.is_none_or(|(bm, _)| m.g.abs() > bm.g.abs() + 1e-12 * mref) {
                *best = Some((m, x));
            }
        };
        let tol_x = 1e-12 * span.max(1.0);
        let event_at = |x: f64| -> Option<usize> {
            let i = events.partition_point(|e| *e < x - tol_x);
            (i < events.len() && (events[i] - x).abs() <= tol_x).then_some(i)
        };
        for (s, h) in sections.iter().zip(&handles) {
            // At an event (support, load, end of a uniform load) where the shear changes sign.
            if let Some(e) = event_at(s.x) {
                let (_, vl, vr) = values[e];
                if vl * vr <= 0.0 {
                    consider(&mut best, *h, s.x);
                }
            }
        }
        for (j, t1, d, t2) in parabola_data.iter().copied() {
            let Kind::Uniform(i) = forces[j].kind else {
                continue;
            };
            let u = beam.uniform_loads[i];
            let (Some(ea), Some(eb)) = (event_at(u.from), event_at(u.to)) else {
                continue;
            };
            let (va, vb) = (values[ea].2, values[eb].1);
            if va * vb < 0.0 {
                let pa = diagram[2 * ea + 1];
                let pb = diagram[2 * eb];
                let sl = b.line_through(&pa, &pb, Label::NONE, Role::Construction, N_SHEAR_ZERO)?;
                let z = b.meet_point(&sl, &base, Label::plain("x0"), N_SHEAR_ZERO)?;
                let xm = b.measure(
                    &base0,
                    &z,
                    &base,
                    Scale {
                        per_mm: 1.0 / k,
                        unit: "m",
                    },
                    Label::NONE,
                    N_SHEAR_ZERO_X,
                );
                let x0 = beam.ends[0] + xm.g;
                let t = (x0 - u.from) / (u.to - u.from);
                let l1 = b.line_through(&t1, &d, Label::NONE, Role::Auxiliary, N_RATIO_1)?;
                let q1 = b.lay_off(
                    &t1,
                    &l1,
                    t * (d.g - t1.g).norm(),
                    Label::NONE,
                    Role::Construction,
                    N_RATIO_1,
                )?;
                let l2 = b.line_through(&d, &t2, Label::NONE, Role::Auxiliary, N_RATIO_2)?;
                let q2 = b.lay_off(
                    &d,
                    &l2,
                    t * (t2.g - d.g).norm(),
                    Label::NONE,
                    Role::Construction,
                    N_RATIO_2,
                )?;
                let lj = b.line_through(&q1, &q2, Label::NONE, Role::Construction, N_RATIO_JOIN)?;
                let pp = b.lay_off(
                    &q1,
                    &lj,
                    t * (q2.g - q1.g).norm(),
                    Label::plain("M"),
                    Role::Construction,
                    N_RATIO_POINT,
                )?;
                let vert =
                    b.perpendicular(&axis, &pp, Label::NONE, Role::Auxiliary, N_SECTION_VERTICAL);
                let vert = H {
                    id: vert.id,
                    g: Line {
                        origin: vert.g.origin,
                        dir: down,
                    },
                };
                let m = moment_at(b, x0, &pp, &vert)?;
                sections.push(SectionRow {
                    x: x0,
                    what: format!("q{} max", i + 1),
                    moment: m.g,
                });
                handles.push(m);
                consider(&mut best, m, x0);
            }
        }
        if let Some((m, x)) = best {
            b.check(
                &m,
                "largest |M|, where the shear changes sign",
                "kg·m",
                "method of sections",
                mref,
                || cf::max_abs_moment(beam).0,
            );
            max_moment = Some((m.g, x));
        }
    }
    let mut order: Vec<usize> = (0..sections.len()).collect();
    order.sort_by(|&i, &j| sections[i].x.total_cmp(&sections[j].x));
    let moment_handles = order.iter().map(|&i| handles[i]).collect();
    let sections = order.iter().map(|&i| sections[i].clone()).collect();
    Ok(BeamResults {
        reactions: (a_val.g, b_val.g),
        sections,
        zero_moments,
        shear,
        max_moment,
        moment_handles,
    })
}

/// Height of the stringers above the beam in the position plan (mm).
const STRINGER_MM: f64 = 18.0;

const N_STRINGER: Note = note(
    "stringer between two cross beams",
    Some("Zwischenträger"),
    "LH Abb. 35",
    Topic::Loads,
);
const N_CROSS_BEAM: Note = note(
    "cross beam at a panel point",
    Some("Querträger"),
    "LH Abb. 35",
    Topic::Loads,
);
const N_PANEL_LOAD: Note = note(
    "load on a stringer",
    Some("Last auf dem Zwischenträger"),
    "LH Abb. 35",
    Topic::Loads,
);

/// The loads that reach the beam through stringers spanning between the panel points: each
/// stringer, simply supported on its two cross beams, hands its loads on by the lever rule
/// (LH Abb. 35). Panel points must be increasing and every load must lie between the first and
/// the last.
pub fn panel_loads(
    beam: &Beam,
    panel_points: &[f64],
) -> Result<Vec<super::PointLoad>, ConstructionError> {
    if panel_points.len() < 2
        || panel_points
            .windows(2)
            .any(|w| w[0].partial_cmp(&w[1]) != Some(std::cmp::Ordering::Less))
    {
        return Err(ConstructionError::unsupported(
            "stringers",
            "panel points: give at least two, increasing",
        ));
    }
    let (first, last) = (panel_points[0], panel_points[panel_points.len() - 1]);
    let mut out: Vec<f64> = vec![0.0; panel_points.len()];
    let mut carry = |x: f64, p: f64| -> Result<(), ConstructionError> {
        if x < first || x > last {
            return Err(ConstructionError::unsupported(
                "point_loads",
                format!("a load at {x} m lies outside the stringers [{first}, {last}] m"),
            ));
        }
        let i = panel_points
            .partition_point(|&s| s <= x)
            .clamp(1, panel_points.len() - 1)
            - 1;
        let (s0, s1) = (panel_points[i], panel_points[i + 1]);
        let t = (x - s0) / (s1 - s0);
        out[i] += p * (1.0 - t);
        out[i + 1] += p * t;
        Ok(())
    };
    for l in &beam.point_loads {
        carry(l.x, l.p)?;
    }
    for u in &beam.uniform_loads {
        if u.from < first || u.to > last {
            return Err(ConstructionError::unsupported(
                "uniform_loads",
                format!(
                "a uniform load over [{}, {}] m reaches outside the stringers [{first}, {last}] m",
                u.from, u.to
            ),
            ));
        }
        // Each panel's share of the uniform load, as its resultant at the share's middle.
        for w in panel_points.windows(2) {
            let (a, b) = (u.from.max(w[0]), u.to.min(w[1]));
            if b > a {
                carry(0.5 * (a + b), u.q * (b - a))?;
            }
        }
    }
    Ok(panel_points
        .iter()
        .zip(out)
        .map(|(&x, p)| super::PointLoad { x, p })
        .collect())
}

/// A beam loaded indirectly through stringers (LH Aufgabe 6, Abb. 35): the stringers and cross
/// beams are drawn, the loads reach the beam at the panel points (by [`panel_loads`]), and the
/// beam is constructed under those. At every panel point the moment is checked once more
/// against the *direct* loading: the indirect moment area touches the direct one there.
///
/// # Errors
/// As [`construct_beam`], and for panel points that do not cover the loads.
pub fn construct_beam_indirect(
    b: &mut Board,
    beam: &Beam,
    panel_points: &[f64],
    dr: &BeamDrawing,
    req: &BeamRequest,
) -> Result<BeamResults, ConstructionError> {
    let loads = panel_loads(beam, panel_points)?;
    let k = 1000.0 / dr.length_scale;
    let [ox, oy] = dr.origin;
    let sx = |x: f64| x * k + ox;
    // Stringers and cross beams above the beam, the given loads on the stringers.
    let mut tops = Vec::new();
    for &x in panel_points {
        let foot = b.point(
            Point::new(sx(x), oy),
            Label::NONE,
            Role::Given,
            N_CROSS_BEAM,
        );
        let top = b.point(
            Point::new(sx(x), oy + STRINGER_MM),
            Label::NONE,
            Role::Given,
            N_CROSS_BEAM,
        );
        b.segment(&foot, &top, Label::NONE, Role::Given, N_CROSS_BEAM);
        tops.push(top);
    }
    for w in tops.windows(2) {
        b.segment(&w[0], &w[1], Label::NONE, Role::Given, N_STRINGER);
    }
    for l in &beam.point_loads {
        let at = b.point(
            Point::new(sx(l.x), oy + STRINGER_MM),
            Label::NONE,
            Role::Given,
            N_PANEL_LOAD,
        );
        let tail = b.point(
            Point::new(sx(l.x), oy + STRINGER_MM + ARROW_MM * l.p.signum()),
            Label::NONE,
            Role::Given,
            N_PANEL_LOAD,
        );
        b.segment(&tail, &at, Label::NONE, Role::Force, N_PANEL_LOAD);
    }
    for (i, u) in beam.uniform_loads.iter().enumerate() {
        let h = 0.5 * ARROW_MM;
        let outline: Vec<H<Point>> = [(u.from, 0.0), (u.from, h), (u.to, h), (u.to, 0.0)]
            .iter()
            .map(|&(x, y)| H {
                id: crate::protocol::ObjId::NONE,
                g: Point::new(sx(x), oy + STRINGER_MM + y),
            })
            .collect();
        b.curve(
            &outline,
            false,
            Label::indexed("q", i as u32 + 1),
            Role::Given,
            N_PANEL_LOAD,
        );
    }
    let on_beam = Beam {
        supports: beam.supports,
        ends: beam.ends,
        point_loads: loads,
        uniform_loads: vec![],
    };
    let r = construct_beam_at(b, &on_beam, dr, req, panel_points)?;
    // The indirect moment area touches the direct one at the cross beams.
    let direct = cf::Sections::new(beam);
    let pref = r
        .sections
        .iter()
        .map(|s| s.moment.abs())
        .fold(0.0, f64::max)
        .max(1.0);
    for (s, h) in r.sections.iter().zip(&r.moment_handles) {
        if panel_points
            .iter()
            .any(|&p| (p - s.x).abs() <= 1e-12 * (beam.ends[1] - beam.ends[0]).max(1.0))
        {
            b.check(
                h,
                "moment at a cross beam = moment of the direct load",
                "kg·m",
                "LH Abb. 35; method of sections",
                pref,
                || direct.moment(s.x),
            );
        }
    }
    Ok(r)
}

/// The layouts the construction handles: A left of B, uniform loads that neither overlap nor
/// straddle a support nor hold a point load (split them there: the result is the same).
fn check_layout(beam: &Beam) -> Result<(), ConstructionError> {
    let [a, b] = beam.supports;
    if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
        return Err(ConstructionError::unsupported(
            "supports",
            format!("support A ({a} m) must lie left of support B ({b} m)"),
        ));
    }
    for (i, u) in beam.uniform_loads.iter().enumerate() {
        let inside = |x: f64| x > u.from && x < u.to;
        if u.from.partial_cmp(&u.to) != Some(std::cmp::Ordering::Less) {
            return Err(ConstructionError::unsupported(
                format!("uniform_loads[{i}]"),
                format!("uniform load {i} must end after it starts"),
            ));
        }
        if inside(a) || inside(b) {
            return Err(ConstructionError::unsupported(
                format!("uniform_loads[{i}]"),
                format!("uniform load {i} straddles a support: split it there"),
            ));
        }
        if beam.point_loads.iter().any(|l| inside(l.x)) {
            return Err(ConstructionError::unsupported(
                format!("uniform_loads[{i}]"),
                format!("a point load lies inside uniform load {i}: split the uniform load there"),
            ));
        }
        if beam.uniform_loads[i + 1..]
            .iter()
            .any(|w| w.from < u.to && w.to > u.from)
        {
            return Err(ConstructionError::unsupported(
                format!("uniform_loads[{i}]"),
                format!("uniform load {i} overlaps another: add their intensities"),
            ));
        }
    }
    Ok(())
}

fn b_point(b: &mut Board, x: f64, y: f64) -> H<Point> {
    b.point(Point::new(x, y), Label::NONE, Role::Given, N_SHEAR_FOOT)
}
