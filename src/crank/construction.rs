//! The demand-driven construction of the slider-crank figures.

use super::closed_form as cf;
use super::{Angles, CrankDrive, Drawing, Request};
use crate::kernel::angle::SinCos;
use crate::kernel::{Branch, Circle, Line, Point, Vector};
use crate::protocol::{
    note, Board, ConstructionError, Cut, Drawn, Label, Note, Reading, Role, Scale, Topic, Trace,
    Turning, H,
};
use serde::Serialize;

mod accel;
mod esselborn;
mod fixed_arc;

const N_CENTRE: Note = note(
    "crank shaft centre O",
    Some("Kurbelwellenmitte"),
    "KG Abb. 1044",
    Topic::Setup,
);
const N_PISTON_LINE: Note = note(
    "piston line through O",
    Some("Kolbenweglinie"),
    "KG Abb. 1047",
    Topic::Setup,
);
const N_VERTICAL: Note = note(
    "vertical centre line through O",
    Some("senkrechte Mittellinie"),
    "KG Abb. 1049; LH Abb. 53",
    Topic::Setup,
);
const N_CRANK_CIRCLE: Note = note(
    "crank circle of radius R",
    Some("Kurbelkreis"),
    "KG Abb. 1047; LH Abb. 49",
    Topic::Setup,
);
const N_DEAD_CENTRE: Note = note(
    "inner dead centre: crank circle cuts the piston line",
    Some("innerer Totpunkt"),
    "KG Abb. 1044",
    Topic::Setup,
);
const N_DEAD_ARC: Note = note(
    "arc with the rod length about the dead centre",
    Some("Schubstangenkreisbogen"),
    "LH Abb. 49",
    Topic::Setup,
);
const N_DEAD_CROSSHEAD: Note = note(
    "crosshead dead centre: the arc cuts the piston line",
    Some("Kreuzkopftotpunkt"),
    "LH Abb. 49",
    Topic::Setup,
);
const N_GUIDE: Note = note(
    "crosshead guide: the stroke s = 2R laid off from the dead centre",
    Some("Gleitbahn, Hub"),
    "KG Abb. 1044",
    Topic::Setup,
);
const N_DIVIDE: Note = note(
    "divide the crank circle into equal parts",
    Some("Teilung des Kurbelkreises"),
    "KG B.4a; LH Abb. 59",
    Topic::PistonPath,
);
const N_CRANK_AT: Note = note(
    "crank position at the crank angle",
    Some("Kurbelstellung"),
    "KG Abb. 1047",
    Topic::PistonPath,
);
const N_ROD_ARC: Note = note(
    "arc with the rod length L about the crank pin",
    Some("Schubstangenkreisbogen"),
    "KG Abb. 1047; LH Abb. 46, 49",
    Topic::PistonPath,
);
const N_CROSSHEAD: Note = note(
    "the arc cuts the piston line: crosshead position",
    Some("Kreuzkopfstellung"),
    "KG Abb. 1047; LH Abb. 49",
    Topic::PistonPath,
);
const N_PIN_VERTICAL: Note = note(
    "infinite rod: perpendicular from the crank pin to the piston line",
    Some("unendlich lange Schubstange"),
    "LH Abb. 48, Gl. 23",
    Topic::PistonPath,
);
const N_ROD: Note = note(
    "connecting rod from crosshead to crank pin",
    Some("Schubstange"),
    "KG Abb. 1044",
    Topic::PistonPath,
);
const N_MEASURE_X: Note = note(
    "piston path x measured from the dead centre",
    Some("Kolbenweg"),
    "KG (285); LH Gl. 20, 23",
    Topic::PistonPath,
);
const N_U: Note = note(
    "u: the outstroke’s path at 90° less the return’s",
    Some("Wegunterschied"),
    "LH B.1, Gl. 22",
    Topic::PistonPath,
);
const N_ROD_LINE: Note = note(
    "rod direction extended",
    Some("Schubstangenrichtung"),
    "KG Abb. 1049; LH Abb. 53",
    Topic::Velocity,
);
const N_ROD_LINE_INF: Note = note(
    "infinite rod: rod direction parallel to the piston line",
    Some("Schubstangenrichtung"),
    "LH Abb. 54",
    Topic::Velocity,
);
const N_CRANK_RAY: Note = note(
    "crank ray through O and the crank pin",
    Some("Kurbelstrahl"),
    "KG Abb. 1049",
    Topic::Velocity,
);
const N_V_ON_RAY: Note = note(
    "lay off v on the crank ray",
    Some("Kurbelzapfengeschwindigkeit v"),
    "KG Abb. 1049",
    Topic::Velocity,
);
const N_V_PARALLEL: Note = note(
    "parallel to the rod through the end of v",
    Some("Parallele zur Schubstange"),
    "KG Abb. 1049",
    Topic::Velocity,
);
const N_V_CUT: Note = note(
    "the parallel cuts the vertical centre line",
    Some("Schnitt mit der Mittelsenkrechten"),
    "KG Abb. 1049",
    Topic::Velocity,
);
const N_V_MEASURE: Note = note(
    "piston velocity c = MF",
    Some("Kolbengeschwindigkeit"),
    "KG (288)",
    Topic::Velocity,
);
const N_IC_CUT: Note = note(
    "rod line cuts the vertical through O: y = OD",
    Some("Abschnitt y"),
    "LH Abb. 53, Gl. 27",
    Topic::Velocity,
);
const N_IC_MEASURE: Note = note(
    "piston velocity c = ω·y",
    Some("Kolbengeschwindigkeit"),
    "LH Gl. 28",
    Topic::Velocity,
);
const N_IC_NORMAL: Note = note(
    "normal to the guide through the crosshead",
    Some("Senkrechte auf c"),
    "LH Abb. 53",
    Topic::Velocity,
);
const N_IC_POINT: Note = note(
    "instantaneous centre of the rod: crank ray cuts the normal",
    Some("Momentanpol C"),
    "LH Abb. 53",
    Topic::Velocity,
);
const N_C_NORMAL: Note = note(
    "ordinate line over the crosshead position",
    Some("Ordinate"),
    "KG Abb. 1049",
    Topic::Velocity,
);
const N_C_ORDINATE: Note = note(
    "transfer c as ordinate over the piston position",
    Some("Geschwindigkeitsordinate"),
    "KG Abb. 1049; LH Abb. 53",
    Topic::Velocity,
);
const N_C_CURVE: Note = note(
    "velocity curve over the piston path",
    Some("Geschwindigkeitskurve"),
    "KG Abb. 1049; LH Abb. 53",
    Topic::Velocity,
);
const N_P_AT_CROSSHEAD: Note = note(
    "lay off the piston force P at the crosshead",
    Some("Kolbenkraft P"),
    "LH Abb. 30, 61; KG Abb. 1061",
    Topic::Forces,
);
const N_P_NORMAL: Note = note(
    "normal to the guide through the end of P",
    Some("Senkrechte zur Gleitbahn"),
    "LH Abb. 30, 61",
    Topic::Forces,
);
const N_S_CUT: Note = note(
    "rod line cuts the normal: parallelogram of P into S and N",
    Some("Kräfteparallelogramm"),
    "LH Abb. 30, 61; KG Abb. 1061",
    Topic::Forces,
);
const N_S_MEASURE: Note = note(
    "rod force S",
    Some("Schubstangenkraft"),
    "KG (300); LH Gl. 43",
    Topic::Forces,
);
const N_N_MEASURE: Note = note(
    "guide force N",
    Some("Druck auf die Kreuzkopfbahn"),
    "KG (301); LH Gl. 44",
    Topic::Forces,
);
const N_S_VEC: Note = note(
    "rod force S drawn",
    Some("Schubstangenkraft"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_N_VEC: Note = note(
    "guide force N drawn",
    Some("Normaldruck"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_CRANK_LINE_F: Note = note(
    "crank line from the pin through O",
    Some("Kurbelradius"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_S_AT_PIN: Note = note(
    "lay off S at the crank pin along the rod",
    Some("Schubstangenkraft am Kurbelzapfen"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_TANGENT: Note = note(
    "tangent to the crank circle at the pin",
    Some("Tangente"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_PAR_CRANK: Note = note(
    "parallel to the crank through the end of S",
    Some("Parallele zum Kurbelradius"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_PAR_TANGENT: Note = note(
    "parallel to the tangent through the end of S",
    Some("Parallele zur Tangente"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_T_CUT: Note = note(
    "cut on the tangent: tangential component",
    Some("Tangentialdruck"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_K_CUT: Note = note(
    "cut on the crank line: radial component",
    Some("Kurbeldruck"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_T_RES_MEASURE: Note = note(
    "tangential force T from the parallelogram at the pin",
    Some("Tangentialdruck"),
    "LH Gl. 48",
    Topic::Forces,
);
const N_K_MEASURE: Note = note(
    "radial force K",
    Some("Kurbeldruck"),
    "LH Gl. 49; KG (302)",
    Topic::Forces,
);
const N_T_VEC: Note = note(
    "tangential force T drawn",
    Some("Tangentialdruck"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_K_VEC: Note = note(
    "radial force K drawn",
    Some("Kurbeldruck"),
    "LH Abb. 61",
    Topic::Forces,
);
const N_POLAR_CENTRE: Note = note(
    "centre of the polar force figure",
    Some("verkleinerter Kurbelkreis"),
    "KG Abb. 1063",
    Topic::Forces,
);
const N_POLAR_VERTICAL: Note = note(
    "vertical axis of the polar force figure",
    Some("Vertikalachse"),
    "LH Abb. 65",
    Topic::Forces,
);
const N_POLAR_RAY: Note = note(
    "crank ray carried over parallel",
    Some("Kurbelstrahl"),
    "LH Abb. 65; KG Abb. 1063",
    Topic::Forces,
);
const N_POLAR_P: Note = note(
    "lay off P on the crank ray",
    Some("Überdruck P auf dem Kurbelstrahl"),
    "LH Abb. 65; KG Abb. 1063",
    Topic::Forces,
);
const N_POLAR_PAR: Note = note(
    "parallel to the rod through the end of P",
    Some("Parallele zur Schubstangenrichtung"),
    "LH Abb. 65; KG Abb. 1063",
    Topic::Forces,
);
const N_POLAR_CUT: Note = note(
    "the parallel cuts the vertical axis: T = OC",
    Some("Tangentialdruck"),
    "LH Abb. 65; KG Abb. 1063",
    Topic::Forces,
);
const N_POLAR_MEASURE: Note = note(
    "tangential force T read off the vertical axis",
    Some("Tangentialdruck"),
    "KG (303); LH Gl. 48",
    Topic::Forces,
);
const N_POLAR_OC: Note = note(
    "T drawn as the force OC along the vertical axis",
    Some("Tangentialdruck"),
    "LH Abb. 65; KG Abb. 1063",
    Topic::Forces,
);

const N_STROKE_END: Note = note(
    "the stroke laid off along the piston line",
    Some("Hub"),
    "LH C.2, Abb. 59",
    Topic::PistonPath,
);
const N_STROKE_DIVIDE: Note = note(
    "divide the stroke into equal parts",
    Some("Teilung des Hubes"),
    "LH C.2, Abb. 59",
    Topic::PistonPath,
);
const N_OUTER_DEAD: Note = note(
    "outer dead centre: the other end of the diameter",
    Some("äußerer Totpunkt"),
    "LH Abb. 59",
    Topic::PistonPath,
);
const N_STROKE_ARC: Note = note(
    "arc with the rod length about the division point",
    Some("Schubstangenkreisbogen"),
    "LH C.2, Abb. 59",
    Topic::PistonPath,
);
const N_STROKE_PERP: Note = note(
    "infinite rod: perpendicular through the division point",
    Some("senkrechte Gerade"),
    "LH C.2, Abb. 60",
    Topic::PistonPath,
);
const N_STROKE_PIN: Note = note(
    "it cuts the crank circle: the crank pin and its ray",
    Some("Radiusvektor"),
    "LH C.2, Abb. 59",
    Topic::PistonPath,
);
const N_POLAR_ZERO: Note = note(
    "the crank circle about O′ as the zero line of the polar turning-force diagram",
    Some("Kurbelkreis als Nullinie"),
    "LH F, Abb. 59",
    Topic::Forces,
);
const N_POLAR_T: Note = note(
    "T laid off on the crank ray from the crank circle (inside where it is negative)",
    Some("polarer Tangentialdruck"),
    "LH F, Abb. 59",
    Topic::Forces,
);
const N_POLAR_P_CURVE: Note = note(
    "polar net-pressure diagram: the ends of P on the crank rays joined",
    Some("polares Überdruckdiagramm"),
    "LH C.2, Abb. 59",
    Topic::Forces,
);
const N_POLAR_T_CURVE: Note = note(
    "polar turning-force diagram",
    Some("polares Drehkraftdiagramm"),
    "LH F, Abb. 59",
    Topic::Forces,
);

/// The constructed values at one crank angle; `None` where not requested.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AngleRow {
    /// Full crank angle θ from the inner dead centre (degrees).
    pub theta: f64,
    /// Outstroke or return stroke.
    pub stroke: cf::Stroke,
    /// The book's φ, counted from the dead centre where the stroke began (degrees).
    pub phi: f64,
    /// Driving piston force P at this angle (kg).
    pub piston_force: f64,
    /// Piston position from the inner dead centre (mm).
    pub x: Option<f64>,
    /// The same by the arc drawn once (LH Abb. 49) (mm).
    pub x_fixed_arc: Option<f64>,
    /// Piston velocity by the parallel to the rod (m/s).
    pub c_parallel: Option<f64>,
    /// Piston velocity by the instantaneous centre (m/s).
    pub c_instant_centre: Option<f64>,
    /// Rod force S (kg).
    pub rod_force: Option<f64>,
    /// Guide force N (kg).
    pub guide_force: Option<f64>,
    /// Tangential force T by the polar construction (kg).
    pub tangential_force: Option<f64>,
    /// The same as read off the board, for a caller that lays it off again with the
    /// dividers ([`Board::transfer`]), so that its bound follows the construction's.
    #[serde(skip)]
    pub tangential_read: Option<H<f64>>,
    /// Tangential force T from the parallelogram at the pin (kg).
    pub tangential_force_at_pin: Option<f64>,
    /// Radial force K (kg).
    pub radial_force: Option<f64>,
    /// Piston acceleration by Tolle's parabola (m/s²), in the direction of motion as the books
    /// give it (KG 291, LH Gl. 29): positive while the piston speeds up.
    pub acceleration: Option<f64>,
    /// The abscissa of that point from the inner dead centre (mm): the approximate piston
    /// path of LH Gl. 21 that the parabola is drawn over.
    pub acceleration_x: Option<f64>,
}

/// The results of [`construct`]: one row per crank angle.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CrankResults {
    /// One row per requested crank angle, in the order given.
    pub rows: Vec<AngleRow>,
    /// Esselborn's construction of the crank angle of the largest piston velocity, when
    /// asked for.
    pub max_velocity: Option<MaxVelocity>,
}

/// The crank position of the largest piston velocity (LH B.2, Abb. 52; K3).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MaxVelocity {
    /// The crank angle φ from the inner dead centre where the rod stands perpendicular to
    /// the crank, constructed (degrees): tg φ = L/R.
    pub esselborn_deg: f64,
    /// The piston velocity there, constructed (m/s).
    pub c_esselborn: f64,
    /// The crank angle of the exact maximum (degrees), the zero of the exact acceleration.
    pub exact_deg: f64,
    /// The exact largest piston velocity (m/s).
    pub c_max: f64,
    /// The zero of the book's approximate acceleration (KG 291, LH Gl. 29), LH's 79°16'
    /// for R/L = 1/5 (degrees).
    pub book_deg: f64,
}

struct Frame {
    o: H<Point>,
    piston_line: H<Line>,
    vertical: H<Line>,
    crank_circle: H<Circle>,
    /// The crank pin at the inner dead centre.
    dead: H<Point>,
    /// Reference for the piston path: the crosshead at the inner dead centre (finite rod)
    /// or the foot of the crank pin there (infinite rod).
    x0: H<Point>,
}

struct PolarFrame {
    o: H<Point>,
    vertical: H<Line>,
}

#[derive(Default)]
struct Cache {
    pin: Option<H<Point>>,
    crosshead: Option<H<Point>>,
    x: Option<H<f64>>,
    rod_line: Option<H<Line>>,
    crank_ray: Option<H<Line>>,
    c_parallel: Option<H<f64>>,
    c_ic: Option<H<f64>>,
    c_point: Option<H<Point>>,
    s: Option<(H<f64>, H<f64>)>,
    k: Option<H<f64>>,
    t_res: Option<H<f64>>,
    t_polar: Option<H<f64>>,
    /// The end of P laid off on the crank ray of the polar figure, and the ray.
    p_end: Option<(H<Point>, H<Line>)>,
    x_fixed: Option<f64>,
    accel: Option<(H<f64>, H<f64>)>,
}

/// The two fixed curves: arcs (finite rod) or perpendiculars (infinite rod).
#[derive(Clone, Copy)]
enum Fixed {
    Arcs([H<Circle>; 2]),
    Lines([H<Line>; 2]),
}

/// Tolle's diagram: its axis and the outstroke and return curves.
struct Tolle {
    axis: super::tolle::TolleAxis,
    curves: [super::tolle::TolleCurve; 2],
}

struct Builder<'a> {
    b: &'a mut Board,
    d: &'a CrankDrive,
    scales: &'a Drawing,
    thetas: Vec<f64>,
    /// The position drawn in the result pen; the others are drawn thin, as the plates
    /// draw one position of a mechanism heavy and the rest as construction.
    shown: Option<usize>,
    divisions: Option<usize>,
    /// The stroke divided into this many parts (LH Abb. 59), when the rays are found so.
    stroke_parts: Option<usize>,
    r: f64,
    l: f64,
    frame: Option<Frame>,
    polar: Option<PolarFrame>,
    divided: Option<Vec<H<Point>>>,
    tolle: Option<Tolle>,
    /// The division points of the stroke (LH Abb. 59).
    stroke_points: Option<Vec<H<Point>>>,
    /// The arcs drawn once for the piston path (LH Abb. 49).
    fixed: Option<Fixed>,
    cache: Vec<Cache>,
    /// Where the shaft centre O stands on the sheet.
    origin: Point,
    /// The caller's context when the construction began (an engine's cylinder, "HP"): every
    /// angle's context is set within it ("HP, θ = 30°").
    base: Option<std::sync::Arc<str>>,
    /// The names of the pins at the listed angles ([`pin_names`]).
    pin_names: Vec<Label>,
}

/// Constructs the requested slider-crank quantities at every crank angle on `board`.
///
/// Every constructed value is read off at its scale and checked against the closed form
/// (see [`closed_form`](super::closed_form)); intersections carry their conditioning.
///
/// # Errors
/// A [`ConstructionError`] if a step has no solution (a rod that cannot reach the piston line,
/// a zero scale); a validated scene never produces one.
pub fn construct(
    board: &mut Board,
    drive: &CrankDrive,
    drawing: &Drawing,
    angles: &Angles,
    request: &Request,
) -> Result<CrankResults, ConstructionError> {
    construct_at(board, drive, drawing, angles, request, Point::origin())
}

/// The pen of a mechanism's links at one of several positions: the result pen for the one
/// shown in full, thin for the others (the plates' way).
pub fn position_pen(shown: bool) -> Role {
    if shown {
        Role::Result
    } else {
        Role::Construction
    }
}

/// The name of a point at position `k` of several: written (`base`, as the plates letter
/// the one position they draw in full) where it is shown, kept in the protocol only
/// (`base` with index `k`) at the others.
pub fn position_name(base: &'static str, k: u32, shown: bool) -> Label {
    if shown {
        Label::plain(base)
    } else {
        Label::quiet(base, k)
    }
}

/// The names of the crank pins at the angles `thetas`: Aₖ for the k-th, written in the
/// figure once for each place on the circle and as the plates letter a crowd. The pin at
/// θ = 0 is the dead centre, named A already (not A₀ beside it); a pin of the second turn
/// (a four-stroke engine's 720°) stands where one of the first does and is not lettered
/// again; of the places left, every one, second … is lettered ([`Label::crowd_every`]),
/// and always the position `shown` in full.
fn pin_names(thetas: &[f64], shown: Option<usize>) -> Vec<Label> {
    // Places on the circle to a nano-degree: the angles are the scene's or its divisions'.
    let place = |t: f64| (t.rem_euclid(360.0) * 1e9).round() as i64 % 360_000_000_000;
    let mut seen = std::collections::HashSet::new();
    let first: Vec<bool> = thetas.iter().map(|t| seen.insert(place(*t))).collect();
    let every = Label::crowd_every(seen.len());
    let mut j = 0;
    (thetas.iter().zip(&first).enumerate())
        .map(|(i, (t, first))| {
            let k = i as u32;
            let lettered = *first && place(*t) != 0 && (j % every == 0 || shown == Some(i));
            j += usize::from(*first);
            match lettered {
                true => Label::indexed("A", k),
                false => Label::quiet("A", k),
            }
        })
        .collect()
}

/// A curve's points over the crank angles `thetas`, closed on the first where they are a
/// full turn ([`spans_full_turn`]).
pub fn close_over_turn(thetas: &[f64], pts: &mut Vec<H<Point>>) {
    if spans_full_turn(thetas) && pts.len() > 2 {
        pts.push(pts[0]);
    }
}

/// Whether the crank angles are a full turn in equal steps (0°, 30°, …, 330° in any order):
/// then a curve over them closes on its first point.
///
/// ```
/// use graphostatik::crank::spans_full_turn;
/// assert!(spans_full_turn(&[0.0, 90.0, 180.0, 270.0]));
/// assert!(spans_full_turn(&[90.0, 210.0, 330.0]));
/// assert!(!spans_full_turn(&[0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0]));
/// assert!(!spans_full_turn(&[0.0, 180.0]));
/// ```
pub fn spans_full_turn(thetas: &[f64]) -> bool {
    let n = thetas.len();
    if n < 3 {
        return false;
    }
    let mut t: Vec<f64> = thetas
        .iter()
        .map(|x| crate::kernel::angle::wrap_360(*x))
        .collect();
    t.sort_by(f64::total_cmp);
    let step = 360.0 / n as f64;
    let tol = crate::kernel::tolerance::REL_LAYOUT_EPS * 360.0;
    (t.windows(2).all(|w| (w[1] - w[0] - step).abs() <= tol))
        && ((t[0] + 360.0 - t[n - 1]) - step).abs() <= tol
}

/// The position a figure of several crank angles draws in the result pen: the first off the
/// dead centres (where crank and rod lie on the piston line and show nothing).
pub fn shown_position(thetas: &[f64]) -> Option<usize> {
    (thetas.iter()).position(|t| crate::kernel::angle::wrap_360(*t) % 180.0 != 0.0)
}

/// [`construct`] with the shaft centre O at `origin` on the sheet: several drives on one
/// sheet (the cylinders of an engine, each with its polar force figure).
pub fn construct_at(
    board: &mut Board,
    drive: &CrankDrive,
    drawing: &Drawing,
    angles: &Angles,
    request: &Request,
    origin: Point,
) -> Result<CrankResults, ConstructionError> {
    let thetas = angles.thetas(drive);
    let n = thetas.len();
    let board_context = board.context();
    let mut bl = Builder {
        b: board,
        d: drive,
        scales: drawing,
        divisions: match angles {
            Angles::Divisions(n) => Some(*n),
            Angles::Degrees(_) | Angles::StrokeParts(_) => None,
        },
        stroke_parts: match angles {
            Angles::StrokeParts(n) => Some(*n),
            _ => None,
        },
        shown: shown_position(&thetas),
        thetas,
        r: drive.crank_radius / drawing.length_scale,
        l: drive.rod_length / drawing.length_scale,
        frame: None,
        polar: None,
        divided: None,
        tolle: None,
        stroke_points: None,
        fixed: None,
        origin,
        cache: (0..n).map(|_| Cache::default()).collect(),
        base: board_context,
        pin_names: Vec::new(),
    };
    bl.pin_names = pin_names(&bl.thetas, bl.shown);
    let want_c = request.velocity_parallel || request.velocity_instant_centre;
    // Upper bounds of the steps per angle each output adds (objects: about twice as many).
    let per_angle = 6
        + 8 * (request.velocity_parallel as usize)
        + 6 * (request.velocity_instant_centre as usize)
        + 3 * (want_c as usize)
        + 8 * ((request.rod_force || request.guide_force || request.radial_force) as usize)
        + 12 * (request.radial_force as usize)
        + 8 * (request.tangential_force as usize)
        + 8 * (request.acceleration as usize);
    bl.b.reserve(16 + per_angle * n, 16 + 2 * per_angle * n);
    for i in 0..n {
        bl.angle(i, request)?;
    }
    bl.base_context();
    if request.piston_path && drive.finite_rod {
        bl.path_difference()?;
    }
    let max_velocity = if request.max_velocity {
        Some(bl.esselborn()?)
    } else {
        None
    };
    if request.polar_diagrams && request.tangential_force && bl.b.is_recording() {
        bl.polar_diagrams()?;
    }
    if want_c && bl.b.is_recording() {
        bl.velocity_curve()?;
    }
    let rows = (0..n).map(|i| bl.row(i)).collect();
    Ok(CrankResults { rows, max_velocity })
}

impl Builder<'_> {
    /// Back to the caller's context (none for a crank drawn alone).
    fn base_context(&mut self) {
        self.b.set_context_to(self.base.clone());
    }

    /// The context of the crank angle θ, within the caller's ("HP, θ = 30°").
    fn angle_context(&mut self, theta: f64) {
        let base = self.base.as_deref();
        self.b.set_context(|| match base {
            Some(c) => format!("{c}, θ = {}°", crate::fmt::num(theta, 3)),
            None => format!("θ = {}°", crate::fmt::num(theta, 3)),
        });
    }

    /// The pin of ray i found from the stroke's division point by the arc with the rod length
    /// (LH Abb. 59), or the perpendicular for the infinite rod (Abb. 60); the dead centres are
    /// the ends of the diameter, where the arc only touches the crank circle.
    fn pin_by_rod_arc(&mut self, i: usize, n: usize) -> Result<H<Point>, ConstructionError> {
        let f = self.frame.as_ref().expect("frame built");
        let (circle, o, axis, dead, x0) = (f.crank_circle, f.o, f.piston_line, f.dead, f.x0);
        if self.stroke_points.is_none() {
            self.base_context();
            let end = self
                .b
                .lay_off(&x0, &axis, 2.0 * self.r, Role::Construction, N_STROKE_END)?;
            let pts = self.b.divide_segment(&x0, &end, n, "X", N_STROKE_DIVIDE);
            self.stroke_points = Some(pts);
            let theta = self.thetas[i];
            self.angle_context(theta);
        }
        let (k, out) = if i <= n {
            (i, true)
        } else {
            (2 * n - i, false)
        };
        let pin = if k == 0 {
            dead
        } else if k == n {
            self.b
                .lay_off(&dead, &axis, 2.0 * self.r, Role::Construction, N_OUTER_DEAD)?
        } else {
            let xk = self.stroke_points.as_ref().expect("divided above")[k];
            let side = o.g + Vector::new(0.0, if out { self.r } else { -self.r });
            if self.d.finite_rod {
                let arc =
                    self.b
                        .circle(&xk, self.l, Drawn::Marks, Role::Construction, N_STROKE_ARC)?;
                self.b.cut_circle_circle(
                    &circle,
                    &arc,
                    Branch::Near(side),
                    Label::of_crowd("A", i as u32, 2 * n),
                    N_STROKE_PIN,
                )?
            } else {
                let perp = self
                    .b
                    .perpendicular(&axis, &xk, Role::Construction, N_STROKE_PERP);
                self.b.cut_line_circle(
                    &perp,
                    &circle,
                    Branch::Near(side),
                    Label::of_crowd("A", i as u32, 2 * n),
                    N_STROKE_PIN,
                )?
            }
        };
        let pen = self.pen(i);
        self.b.segment(&o, &pin, pen, N_CRANK_AT);
        Ok(pin)
    }

    /// Everything `request` asks for at the i-th crank angle.
    fn angle(&mut self, i: usize, request: &Request) -> Result<(), ConstructionError> {
        let theta = self.thetas[i];
        self.angle_context(theta);
        if request.piston_path {
            self.x(i)?;
        }
        if request.piston_path_fixed_arc {
            self.x_fixed_arc(i)?;
        }
        if request.velocity_parallel {
            self.c_parallel(i)?;
        }
        if request.velocity_instant_centre {
            self.c_instant_centre(i)?;
        }
        // The velocity curve's ordinate is only drawn: a board that does not record has no
        // figure to draw it in, and no result depends on it.
        if (request.velocity_parallel || request.velocity_instant_centre) && self.b.is_recording() {
            self.c_point(i)?;
        }
        if request.rod_force || request.guide_force {
            self.s_n(i)?;
        }
        if request.radial_force {
            self.k_t(i)?;
        }
        if request.tangential_force {
            self.t_polar(i)?;
        }
        if request.acceleration {
            self.acceleration(i)?;
        }
        Ok(())
    }

    fn row(&self, i: usize) -> AngleRow {
        let c = &self.cache[i];
        let theta = self.thetas[i];
        let (stroke, phi) = cf::book_angle(theta);
        AngleRow {
            theta,
            stroke,
            phi,
            piston_force: self.d.piston_force.at(i),
            x: c.x.map(|h| h.g),
            x_fixed_arc: c.x_fixed,
            c_parallel: c.c_parallel.map(|h| h.g),
            c_instant_centre: c.c_ic.map(|h| h.g),
            rod_force: c.s.map(|(s, _)| s.g),
            guide_force: c.s.map(|(_, n)| n.g),
            tangential_force: c.t_polar.map(|h| h.g),
            tangential_read: c.t_polar,
            tangential_force_at_pin: c.t_res.map(|h| h.g),
            radial_force: c.k.map(|h| h.g),
            acceleration: c.accel.map(|(_, b)| b.g),
            acceleration_x: c.accel.map(|(x, _)| x.g),
        }
    }

    fn lambda(&self) -> f64 {
        self.d.lambda()
    }

    /// The driving force at angle i, signed along +x (the way a driving force pushes the piston).
    fn p_x(&self, i: usize) -> f64 {
        cf::book_angle(self.thetas[i]).0.sign() * self.d.piston_force.at(i)
    }

    /// The frame (centre, piston line, vertical, crank circle, dead centre), built once; the
    /// fast path is inlined, as every step of every angle asks for it.
    #[inline(always)]
    fn frame(&mut self) -> Result<&Frame, ConstructionError> {
        if self.frame.is_none() {
            self.build_frame()?;
        }
        Ok(self.frame.as_ref().expect("built above"))
    }

    #[inline(never)]
    fn build_frame(&mut self) -> Result<(), ConstructionError> {
        {
            let b = &mut *self.b;
            let o = b.point(self.origin, Role::Given.named("O"), N_CENTRE);
            let piston_line = b.line_dir(&o, Vector::new(1.0, 0.0), Role::Axis, N_PISTON_LINE)?;
            let vertical = b.line_dir(&o, Vector::new(0.0, 1.0), Role::Axis, N_VERTICAL)?;
            let crank_circle = b.circle(&o, self.r, Drawn::Whole, Role::Given, N_CRANK_CIRCLE)?;
            let dead = b.cut_line_circle(
                &piston_line,
                &crank_circle,
                Branch::First,
                Label::plain("A"),
                N_DEAD_CENTRE,
            )?;
            let dead_pin = dead;
            let x0 = if self.d.finite_rod {
                let arc = b.circle(&dead, self.l, Drawn::Marks, Role::Construction, N_DEAD_ARC)?;
                b.cut_line_circle(
                    &piston_line,
                    &arc,
                    Branch::First,
                    Label::plain("T"),
                    N_DEAD_CROSSHEAD,
                )?
            } else {
                dead
            };
            // The crosshead guide over the stroke; an infinitely long rod has none to draw.
            if self.d.finite_rod {
                b.lay_off(&x0, &piston_line, 2.0 * self.r, Role::Guide, N_GUIDE)?;
            }
            self.frame = Some(Frame {
                o,
                piston_line,
                vertical,
                crank_circle,
                dead: dead_pin,
                x0,
            });
        }
        Ok(())
    }

    /// The pen of the crank and rod at the i-th angle: heavy for the position shown, thin for
    /// the others.
    fn pen(&self, i: usize) -> Role {
        position_pen(self.shown == Some(i))
    }

    /// The name of a force's end at the i-th angle: written (S, N, T, K, as the plates
    /// letter the one position they draw in full) at the position shown, kept in the
    /// protocol only at the others.
    fn force_name(&self, base: &'static str, i: usize) -> Label {
        position_name(base, i as u32, self.shown == Some(i))
    }

    fn pin(&mut self, i: usize) -> Result<H<Point>, ConstructionError> {
        if let Some(p) = self.cache[i].pin {
            return Ok(p);
        }
        self.frame()?;
        let f = self.frame.as_ref().expect("frame built");
        let (circle, o) = (f.crank_circle, f.o);
        let p = if let Some(n) = self.stroke_parts {
            self.pin_by_rod_arc(i, n)?
        } else if let Some(n) = self.divisions {
            if self.divided.is_none() {
                // Clockwise from the inner dead centre (180° on the sheet): the pin runs over
                // the upper half on the outstroke. The dead centre is named A already: its
                // division point is not named A₀ beside it.
                self.base_context();
                let pts = self.b.divide_circle(
                    &circle,
                    180.0,
                    n,
                    Turning::Clockwise,
                    ("A", true),
                    N_DIVIDE,
                );
                self.divided = Some(pts);
                let theta = self.thetas[i];
                self.angle_context(theta);
            }
            let pin = self.divided.as_ref().expect("divided above")[i];
            let pen = self.pen(i);
            self.b.segment(&o, &pin, pen, N_CRANK_AT);
            pin
        } else {
            // The pin at 180° − θ on the sheet, by the sine and cosine of θ itself: forming
            // 180 − θ would round a small θ (1e-9° came out 1e-5 relative off).
            let (s, c) = crate::kernel::angle::sin_cos_deg(self.thetas[i]);
            let pen = self.pen(i);
            self.b.point_on_circle_dir(
                &circle,
                SinCos { sin: s, cos: -c },
                pen.labelled(self.pin_names[i].clone()),
                N_CRANK_AT,
            )
        };
        self.cache[i].pin = Some(p);
        Ok(p)
    }

    fn crosshead(&mut self, i: usize) -> Result<H<Point>, ConstructionError> {
        if let Some(p) = self.cache[i].crosshead {
            return Ok(p);
        }
        let pin = self.pin(i)?;
        let piston_line = self.frame()?.piston_line;
        let b = if self.d.finite_rod {
            let arc = self
                .b
                .circle(&pin, self.l, Drawn::Marks, Role::Construction, N_ROD_ARC)?;
            let b = self.b.cut_line_circle(
                &piston_line,
                &arc,
                Branch::First,
                Label::quiet("B", i as u32),
                N_CROSSHEAD,
            )?;
            let pen = self.pen(i);
            self.b.segment(&b, &pin, pen, N_ROD);
            b
        } else {
            self.b.foot(
                &piston_line,
                &pin,
                Role::Construction.labelled(Label::quiet("B", i as u32)),
                N_PIN_VERTICAL,
            )
        };
        self.cache[i].crosshead = Some(b);
        Ok(b)
    }

    fn x(&mut self, i: usize) -> Result<H<f64>, ConstructionError> {
        if let Some(x) = self.cache[i].x {
            return Ok(x);
        }
        let bpt = self.crosshead(i)?;
        let f = self.frame()?;
        let (x0, axis) = (f.x0, f.piston_line);
        let scale = Scale {
            per_mm: self.scales.length_scale,
            unit: "mm",
        };
        let x = self.b.measure(
            &x0,
            &bpt,
            &axis,
            scale,
            Label::quiet("x", i as u32),
            N_MEASURE_X,
        );
        let (r, rod, theta) = (self.d.crank_radius, self.d.rod(), self.thetas[i]);
        self.b.check(
            &x,
            "piston path x",
            "mm",
            "KG (285); LH Gl. 20, 23",
            r,
            || cf::piston_position(r, rod, theta),
        );
        self.cache[i].x = Some(x);
        Ok(x)
    }

    /// The difference u of the outstroke's and the return's paths at 90° (LH B.1, Gl. 22):
    /// the outstroke's x(90°) from the inner dead centre less the return's 2R − x(270°) from
    /// the outer one, both read off the figure; where both positions are drawn.
    fn path_difference(&mut self) -> Result<(), ConstructionError> {
        let at = |deg: f64| self.thetas.iter().position(|t| (t - deg).abs() < 1e-9);
        let (Some(i), Some(j)) = (at(90.0), at(270.0)) else {
            return Ok(());
        };
        let (out, ret) = (self.x(i)?, self.x(j)?);
        let (r, l) = (self.d.crank_radius, self.d.rod_length);
        let u = self.b.tally(
            out.g + ret.g - 2.0 * r,
            "mm",
            Label::NONE,
            &[out.id, ret.id],
            N_U,
        );
        self.b.check(
            &u,
            "path difference u of outstroke and return at 90°",
            "mm",
            "LH B.1, Gl. 22",
            r,
            || cf::path_difference(r, l),
        );
        Ok(())
    }

    fn rod_line(&mut self, i: usize) -> Result<H<Line>, ConstructionError> {
        if let Some(l) = self.cache[i].rod_line {
            return Ok(l);
        }
        let pin = self.pin(i)?;
        let line = if self.d.finite_rod {
            let b = self.crosshead(i)?;
            self.b
                .line_through(&b, &pin, Role::Construction, N_ROD_LINE)?
        } else {
            let axis = self.frame()?.piston_line;
            self.b
                .parallel(&axis, &pin, Role::Construction, N_ROD_LINE_INF)
        };
        self.cache[i].rod_line = Some(line);
        Ok(line)
    }

    fn crank_ray(&mut self, i: usize) -> Result<H<Line>, ConstructionError> {
        if let Some(l) = self.cache[i].crank_ray {
            return Ok(l);
        }
        let pin = self.pin(i)?;
        let o = self.frame()?.o;
        let line = self
            .b
            .line_through(&o, &pin, Role::Construction, N_CRANK_RAY)?;
        self.cache[i].crank_ray = Some(line);
        Ok(line)
    }

    fn c_parallel(&mut self, i: usize) -> Result<H<f64>, ConstructionError> {
        if let Some(c) = self.cache[i].c_parallel {
            return Ok(c);
        }
        let rod = self.rod_line(i)?;
        let ray = self.crank_ray(i)?;
        let f = self.frame()?;
        let (o, vertical) = (f.o, f.vertical);
        let v_mm = self.d.crank_pin_speed / self.scales.velocity_scale;
        let e = self.b.lay_off(
            &o,
            &ray,
            v_mm,
            Role::Velocity.labelled(Label::quiet("V", i as u32)),
            N_V_ON_RAY,
        )?;
        let par = self.b.parallel(&rod, &e, Role::Auxiliary, N_V_PARALLEL);
        let fpt = self
            .b
            .meet_point(&par, &vertical, Label::quiet("F", i as u32), N_V_CUT)?;
        let scale = Scale {
            per_mm: self.scales.velocity_scale,
            unit: "m/s",
        };
        let c = self.b.measure(
            &o,
            &fpt,
            &vertical,
            scale,
            Label::quiet("c", i as u32),
            N_V_MEASURE,
        );
        let (v, lam, theta) = (self.d.crank_pin_speed, self.lambda(), self.thetas[i]);
        self.b.check(
            &c,
            "piston velocity c (parallel)",
            "m/s",
            "KG (288)",
            v,
            || cf::piston_velocity(v, lam, theta),
        );
        self.cache[i].c_parallel = Some(c);
        Ok(c)
    }

    fn c_instant_centre(&mut self, i: usize) -> Result<H<f64>, ConstructionError> {
        if let Some(c) = self.cache[i].c_ic {
            return Ok(c);
        }
        let rod = self.rod_line(i)?;
        let f = self.frame()?;
        let (o, vertical, piston_line) = (f.o, f.vertical, f.piston_line);
        if self.d.finite_rod {
            // The instantaneous centre itself (LH Abb. 53): at θ = 90°, 270° the crank ray is
            // parallel to the normal and the centre lies at infinity (the rod translates).
            let ray = self.crank_ray(i)?;
            let b = self.crosshead(i)?;
            let normal = self
                .b
                .perpendicular(&piston_line, &b, Role::Auxiliary, N_IC_NORMAL);
            match self
                .b
                .meet(&ray, &normal, Label::quiet("C", i as u32), N_IC_POINT)
            {
                Cut::Point(..) | Cut::Parallel { .. } => {}
                Cut::Coincident => {
                    // Only if the crosshead sat on the shaft: excluded by L > R.
                }
            }
        }
        let dpt = self
            .b
            .meet_point(&rod, &vertical, Label::quiet("D", i as u32), N_IC_CUT)?;
        let omega = self.d.omega();
        let scale = Scale {
            per_mm: omega * self.scales.length_scale / 1000.0,
            unit: "m/s",
        };
        let c = self.b.measure(
            &o,
            &dpt,
            &vertical,
            scale,
            Label::quiet("c", i as u32),
            N_IC_MEASURE,
        );
        let (v, lam, theta) = (self.d.crank_pin_speed, self.lambda(), self.thetas[i]);
        self.b.check(
            &c,
            "piston velocity c = ω·y",
            "m/s",
            "LH Gl. 28; KG (288)",
            v,
            || cf::piston_velocity(v, lam, theta),
        );
        self.cache[i].c_ic = Some(c);
        Ok(c)
    }

    /// The point of the velocity curve over the crosshead position (KG Abb. 1049).
    fn c_point(&mut self, i: usize) -> Result<H<Point>, ConstructionError> {
        if let Some(p) = self.cache[i].c_point {
            return Ok(p);
        }
        let c = match (self.cache[i].c_parallel, self.cache[i].c_ic) {
            (Some(c), _) | (None, Some(c)) => c,
            (None, None) => self.c_parallel(i)?,
        };
        let b = self.crosshead(i)?;
        let axis = self.frame()?.piston_line;
        let normal = self.b.perpendicular(&axis, &b, Role::Auxiliary, N_C_NORMAL);
        let q = self.b.transfer(
            &b,
            &normal,
            Reading {
                value: &c,
                per_mm: self.scales.velocity_scale,
            },
            Role::Construction.labelled(Label::quiet("Q", i as u32)),
            N_C_ORDINATE,
        )?;
        self.cache[i].c_point = Some(q);
        Ok(q)
    }

    fn velocity_curve(&mut self) -> Result<(), ConstructionError> {
        // Order the points by crank angle; close the loop over a full revolution.
        let mut idx: Vec<usize> = (0..self.thetas.len()).collect();
        idx.sort_by(|a, b| self.thetas[*a].total_cmp(&self.thetas[*b]));
        let mut pts: Vec<H<Point>> = idx.iter().filter_map(|&i| self.cache[i].c_point).collect();
        if (self.divisions.is_some() || spans_full_turn(&self.thetas)) && pts.len() > 2 {
            pts.push(pts[0]);
        }
        if pts.len() >= 2 {
            self.b
                .curve(&pts, Trace::Smooth, Role::Result.named("c"), N_C_CURVE);
        }
        Ok(())
    }

    /// The parallelogram of P at the crosshead: S along the rod, N normal to the guide.
    fn s_n(&mut self, i: usize) -> Result<(H<f64>, H<f64>), ConstructionError> {
        if let Some(sn) = self.cache[i].s {
            return Ok(sn);
        }
        let b = self.crosshead(i)?;
        let axis = self.frame()?.piston_line;
        // The rod's line through the crosshead; for the infinitely long rod the piston line.
        let rod = if self.d.finite_rod {
            self.rod_line(i)?
        } else {
            axis
        };
        let p_mm = self.p_x(i) / self.scales.force_scale;
        let p_name = self.force_name("P", i);
        let e = self.b.lay_off(
            &b,
            &axis,
            p_mm,
            Role::Force.labelled(p_name),
            N_P_AT_CROSSHEAD,
        )?;
        let normal = self.b.perpendicular(&axis, &e, Role::Auxiliary, N_P_NORMAL);
        let fpt = self
            .b
            .meet_point(&rod, &normal, self.force_name("S", i), N_S_CUT)?;
        let scale = Scale::kg(self.scales.force_scale);
        let s = self.b.measure(
            &b,
            &fpt,
            &rod,
            scale,
            Label::quiet("S", i as u32),
            N_S_MEASURE,
        );
        let n = self.b.measure(
            &e,
            &fpt,
            &normal,
            scale,
            Label::quiet("N", i as u32),
            N_N_MEASURE,
        );
        self.b.segment(&b, &fpt, Role::Force, N_S_VEC);
        self.b.segment(&e, &fpt, Role::Force, N_N_VEC);
        let (p, lam, theta) = (self.d.piston_force.at(i), self.lambda(), self.thetas[i]);
        let pref = p.abs();
        self.b
            .check(&s, "rod force S", "kg", "KG (300); LH Gl. 43", pref, || {
                cf::rod_force(p, lam, theta)
            });
        self.b.check(
            &n,
            "guide force N",
            "kg",
            "KG (301); LH Gl. 44",
            pref,
            || cf::guide_force(p, lam, theta),
        );
        self.cache[i].s = Some((s, n));
        Ok((s, n))
    }

    /// S resolved at the crank pin into K along the crank and T along the tangent.
    fn k_t(&mut self, i: usize) -> Result<(H<f64>, H<f64>), ConstructionError> {
        if let (Some(k), Some(t)) = (self.cache[i].k, self.cache[i].t_res) {
            return Ok((k, t));
        }
        let (s, _) = self.s_n(i)?;
        let rod = self.rod_line(i)?;
        let pin = self.pin(i)?;
        let o = self.frame()?.o;
        // The crank line directed from the pin to O: its left normal is the sense of rotation.
        let crank = self
            .b
            .line_through(&pin, &o, Role::Construction, N_CRANK_LINE_F)?;
        let g = self.b.transfer(
            &pin,
            &rod,
            Reading {
                value: &s,
                per_mm: self.scales.force_scale,
            },
            Role::Force.labelled(Label::quiet("G", i as u32)),
            N_S_AT_PIN,
        )?;
        let tangent = self
            .b
            .perpendicular(&crank, &pin, Role::Construction, N_TANGENT);
        let par_crank = self.b.parallel(&crank, &g, Role::Auxiliary, N_PAR_CRANK);
        let par_tan = self
            .b
            .parallel(&tangent, &g, Role::Auxiliary, N_PAR_TANGENT);
        let tp = self
            .b
            .meet_point(&par_crank, &tangent, self.force_name("T", i), N_T_CUT)?;
        let kp = self
            .b
            .meet_point(&par_tan, &crank, self.force_name("K", i), N_K_CUT)?;
        let scale = Scale::kg(self.scales.force_scale);
        let t = self.b.measure(
            &pin,
            &tp,
            &tangent,
            scale,
            Label::quiet("T", i as u32),
            N_T_RES_MEASURE,
        );
        let k = self.b.measure(
            &pin,
            &kp,
            &crank,
            scale,
            Label::quiet("K", i as u32),
            N_K_MEASURE,
        );
        self.b.segment(&pin, &tp, Role::Force, N_T_VEC);
        self.b.segment(&pin, &kp, Role::Force, N_K_VEC);
        let (p, lam, theta) = (self.d.piston_force.at(i), self.lambda(), self.thetas[i]);
        let pref = p.abs();
        self.b.check(
            &t,
            "tangential force T (at the pin)",
            "kg",
            "LH Gl. 48; KG (303)",
            pref,
            || cf::tangential_force(p, lam, theta),
        );
        self.b.check(
            &k,
            "radial force K",
            "kg",
            "LH Gl. 49; KG (302)",
            pref,
            || cf::radial_force(p, lam, theta),
        );
        self.cache[i].k = Some(k);
        self.cache[i].t_res = Some(t);
        Ok((k, t))
    }

    fn polar_frame(&mut self) -> Result<&PolarFrame, ConstructionError> {
        if self.polar.is_none() {
            // Beside the mechanism, clear of the crank circle by the largest force.
            let pmax = self.d.piston_force.max_abs() / self.scales.force_scale;
            let gap = 0.15 * (self.r + self.l);
            let centre = self.origin + Vector::new(self.r + gap + pmax * 1.05, 0.0);
            self.base_context();
            let o = self
                .b
                .point(centre, Role::Given.named("O'"), N_POLAR_CENTRE);
            let vertical =
                self.b
                    .line_dir(&o, Vector::new(0.0, 1.0), Role::Axis, N_POLAR_VERTICAL)?;
            self.polar = Some(PolarFrame { o, vertical });
        }
        Ok(self.polar.as_ref().expect("set above"))
    }

    /// LH Abb. 65 / KG Abb. 1063: P on the crank ray, parallel to the rod through its end.
    fn t_polar(&mut self, i: usize) -> Result<H<f64>, ConstructionError> {
        if let Some(t) = self.cache[i].t_polar {
            return Ok(t);
        }
        let rod = self.rod_line(i)?;
        let ray = self.crank_ray(i)?;
        let first = self.polar.is_none();
        let pf = self.polar_frame()?;
        let (o, vertical) = (pf.o, pf.vertical);
        if first {
            let theta = self.thetas[i];
            self.angle_context(theta);
        }
        let ray_f = self.b.parallel(&ray, &o, Role::Auxiliary, N_POLAR_RAY);
        // P on the crank ray of its own stroke, outward where it drives (LH Abb. 59: the
        // outstroke's diagram on one half of the crank circle, the return's on the other).
        // On the stroke whose driving sense is −x, P so laid is −P along +x: the parallel to
        // the rod then cuts the vertical on the other side of O, and T is read from C to O.
        let along_x = cf::book_angle(self.thetas[i]).0.sign();
        let p_mm = self.d.piston_force.at(i) / self.scales.force_scale;
        let bp = self.b.lay_off(
            &o,
            &ray_f,
            p_mm,
            Role::Force.labelled(Label::quiet("P", i as u32)),
            N_POLAR_P,
        )?;
        let par = self.b.parallel(&rod, &bp, Role::Auxiliary, N_POLAR_PAR);
        let cpt = self
            .b
            .meet_point(&par, &vertical, Label::quiet("C", i as u32), N_POLAR_CUT)?;
        let scale = Scale::kg(self.scales.force_scale);
        let (from, to) = if along_x < 0.0 {
            (&cpt, &o)
        } else {
            (&o, &cpt)
        };
        let t = self.b.measure(
            from,
            to,
            &vertical,
            scale,
            Label::quiet("T", i as u32),
            N_POLAR_MEASURE,
        );
        self.b.segment(&o, &cpt, Role::Force, N_POLAR_OC);
        let (p, lam, theta) = (self.d.piston_force.at(i), self.lambda(), self.thetas[i]);
        self.b.check(
            &t,
            "tangential force T (polar)",
            "kg",
            "KG (303); LH Gl. 48",
            p.abs(),
            || cf::tangential_force(p, lam, theta),
        );
        self.cache[i].t_polar = Some(t);
        self.cache[i].p_end = Some((bp, ray_f));
        Ok(t)
    }

    /// The polar diagrams on the polar figure's rays (LH Abb. 59): the ends of P joined in the
    /// order of the crank angles, and T laid off from the crank circle drawn about O'.
    fn polar_diagrams(&mut self) -> Result<(), ConstructionError> {
        let Some(pf) = self.polar.as_ref() else {
            return Ok(());
        };
        let o = pf.o;
        self.base_context();
        let circle = self
            .b
            .circle(&o, self.r, Drawn::Whole, Role::Construction, N_POLAR_ZERO)?;
        let mut idx: Vec<usize> = (0..self.thetas.len()).collect();
        idx.sort_by(|a, b| self.thetas[*a].total_cmp(&self.thetas[*b]));
        let mut p_pts = Vec::with_capacity(idx.len() + 1);
        let mut t_pts = Vec::with_capacity(idx.len() + 1);
        for &i in &idx {
            let (Some((p_end, ray)), Some(t)) = (self.cache[i].p_end, self.cache[i].t_polar) else {
                continue;
            };
            p_pts.push(p_end);
            // The ray's direction points from O to the pin: the crank circle lies at +r on it.
            let at = self.b.lay_off(
                &o,
                &ray,
                self.r + t.g / self.scales.force_scale,
                Role::Construction,
                N_POLAR_T,
            )?;
            t_pts.push(at);
        }
        let _ = circle;
        if self.divisions.is_some() || self.stroke_parts.is_some() || spans_full_turn(&self.thetas)
        {
            if let (Some(&p0), Some(&t0)) = (p_pts.first(), t_pts.first()) {
                p_pts.push(p0);
                t_pts.push(t0);
            }
        }
        if p_pts.len() >= 2 {
            self.b.curve(
                &p_pts,
                Trace::Polygon,
                Role::Result.named("P"),
                N_POLAR_P_CURVE,
            );
            self.b.curve(
                &t_pts,
                Trace::Polygon,
                Role::Result.named("T"),
                N_POLAR_T_CURVE,
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lettered pins of a list of angles, as the figure writes them.
    fn lettered(thetas: &[f64], shown: Option<usize>) -> Vec<u32> {
        (pin_names(thetas, shown).into_iter())
            .filter(|l| l.shown)
            .filter_map(|l| l.index)
            .collect()
    }

    /// Twelve positions are lettered each but the dead centre; 48 over a four-stroke
    /// engine's two turns are 24 places on the circle, lettered every second once; the
    /// position drawn in full is lettered whatever the crowd.
    #[test]
    fn a_crowd_of_crank_pins_is_lettered_as_the_plates_letter_it() {
        let every = |n: usize, step: f64| -> Vec<f64> { (0..n).map(|k| k as f64 * step).collect() };
        assert_eq!(
            lettered(&every(12, 30.0), None),
            (1..12).collect::<Vec<u32>>()
        );
        let two_turns = lettered(&every(48, 15.0), None);
        assert_eq!(two_turns, (1..12).map(|k| 2 * k).collect::<Vec<u32>>());
        assert_eq!(
            lettered(&every(48, 15.0), Some(3)),
            [2, 3, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22]
        );
        assert_eq!(lettered(&[0.0, 360.0, 720.0], None), Vec::<u32>::new());
    }
}
