//! The scotch yoke (Kurbelschleife, KG XIV, Abb. 1069): the crank pin slides in a slot at
//! right angles to the stroke, so the yoke moves exactly as the pin's projection on the line
//! of the stroke: x′ = R(1 − cos φ), c′ = v·sin φ, b′ = v²/R·cos φ.
//!
//! Per crank angle the construction drops the pin onto the line of the stroke (the slot), and
//! projects the pin's velocity v (on the tangent) and its acceleration v²/R (along the crank,
//! towards O) onto the same line. The ordinates are carried over the stroke into a velocity
//! and an acceleration diagram: a half circle (an ellipse at unequal scales) and a straight
//! line. Beside them, where a rod is given, the slider-crank of the same stroke is drawn by
//! [`crate::crank`] and its curves are laid into the same diagrams, as the book compares them.

use crate::crank::{self, Angles, CrankDrive, CrankResults, Drawing, PistonForce, Request};
use crate::kernel::Point;
use crate::protocol::{
    Board, ConstructionError, Drawn, Label, Note, Part, Reading, Role, Scale, Topic, Trace, H,
};

fn n(caption: &'static str, term: Option<&'static str>) -> Note {
    crate::protocol::note(
        caption,
        term,
        "KG XIV, Abb. 1069",
        Topic::Custom("scotch yoke"),
    )
}

/// The yoke: crank radius, crank-pin speed, and the slider-crank rod to compare with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Yoke {
    /// Crank radius R (mm of the machine).
    pub crank_radius: f64,
    /// Crank-pin speed v (m/s).
    pub crank_pin_speed: f64,
    /// The rod of a slider-crank of the same stroke (mm), drawn beside the yoke where the
    /// request asks for `slider_crank`.
    pub compare_rod: Option<f64>,
}

impl Yoke {
    /// The pin's centripetal acceleration v²/R (m/s²): the yoke's largest, at the dead
    /// centres.
    pub fn v2_over_r(&self) -> f64 {
        self.crank_pin_speed * self.crank_pin_speed / (self.crank_radius / 1000.0)
    }
}

crate::protocol::request_set! {
    /// What a scotch-yoke scene can ask for besides the path (its `outputs`).
    pub struct YokeRequest as "YokeOutput" {
        /// The velocity c′ over the stroke.
        velocity,
        /// The acceleration b′ over the stroke.
        acceleration,
        /// The slider-crank of the same stroke, drawn beside and laid into the diagrams
        /// (with the yoke's `compare_rod`).
        slider_crank,
    }
}

/// One crank angle's values, read off the construction.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct YokeRow {
    /// Crank angle φ (degrees).
    pub phi: f64,
    /// Yoke path x′ from the dead centre (mm of the machine).
    pub x: f64,
    /// Yoke velocity c′ (m/s), if asked for.
    pub c: Option<f64>,
    /// Yoke acceleration b′ (m/s²), if asked for.
    pub b: Option<f64>,
}

/// The results: the yoke's rows, and the slider-crank's where it was drawn beside.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct YokeResults {
    /// Per crank angle.
    pub rows: Vec<YokeRow>,
    /// The slider-crank of the same stroke.
    pub slider_crank: Option<CrankResults>,
}

/// The frame: O, the line of the stroke (directed from the dead centre T through O), T, the
/// crank circle, and the base lines of the two diagrams.
struct Frame {
    o: H<Point>,
    axis: H<crate::kernel::Line>,
    t: H<Point>,
    circle: H<crate::kernel::Circle>,
    bases: [Option<(H<crate::kernel::Line>, H<Point>)>; 2],
}

/// Constructs the scotch yoke at every crank angle (LH/KG convention: φ from the dead centre,
/// counter-clockwise), its diagrams over the stroke, and the slider-crank beside it.
///
/// # Errors
/// A kernel refusal (a zero radius or a non-finite scale: a validated scene has none).
///
/// ```
/// use graphostatik::mechanisms::scotch_yoke::*;
/// use graphostatik::crank::{Angles, Drawing};
/// use graphostatik::protocol::Board;
/// let yoke = Yoke { crank_radius: 300.0, crank_pin_speed: 5.0, compare_rod: None };
/// let d = Drawing { length_scale: 10.0, force_scale: 1.0, velocity_scale: 0.1, acceleration_scale: 1.0 };
/// let rq = YokeRequest { velocity: true, acceleration: true, slider_crank: false };
/// let mut b = Board::recording();
/// let r = construct(&mut b, &yoke, &d, &Angles::Divisions(12), rq).unwrap();
/// // At 90°: x′ = R, c′ = v, b′ = 0 (KG Abb. 1069).
/// assert!((r.rows[3].x - 300.0).abs() < 1e-9 && (r.rows[3].c.unwrap() - 5.0).abs() < 1e-12);
/// assert!(b.all_passed());
/// ```
pub fn construct(
    b: &mut Board,
    yoke: &Yoke,
    dr: &Drawing,
    angles: &Angles,
    rq: YokeRequest,
) -> Result<YokeResults, ConstructionError> {
    let rod = yoke.compare_rod.filter(|_| rq.slider_crank);
    let drive = CrankDrive {
        crank_radius: yoke.crank_radius,
        rod_length: rod.unwrap_or(0.0),
        finite_rod: rod.is_some(),
        crank_pin_speed: yoke.crank_pin_speed,
        piston_force: PistonForce::Constant(0.0),
    };
    let thetas = angles.thetas(&drive);
    // Where a slider-crank is compared, it stands in the sheet's first column and the yoke
    // beside it in the second, each with its diagrams under it.
    if rod.is_some() {
        b.set_part(YOKE);
    }
    let fr = frame(b, yoke, dr, rq)?;
    let mut rows = Vec::with_capacity(thetas.len());
    let mut curves: [Vec<H<Point>>; 2] = [Vec::new(), Vec::new()];
    for (k, &phi) in thetas.iter().enumerate() {
        b.set_context(|| format!("φ = {}°", crate::fmt::num(phi, 3)));
        let (row, pts) = position(b, &fr, yoke, dr, (k as u32, phi, rq))?;
        rows.push(row);
        for (c, p) in curves.iter_mut().zip(pts) {
            c.extend(p);
        }
    }
    b.clear_context();
    // Over a full turn each curve closes on its first point (KG Abb. 1069's ellipse).
    for (pts, label) in curves.iter_mut().zip(["c′", "b′"]) {
        crate::crank::close_over_turn(&thetas, pts);
        if pts.len() > 1 {
            b.curve(
                pts,
                Trace::Smooth,
                Role::Result.labelled(Label::plain(label)),
                n(
                    "the yoke’s curve over the stroke",
                    Some("Kurve der Schleife über dem Hub"),
                ),
            );
        }
    }
    let slider_crank = match rod {
        Some(_) => Some(compare(b, &fr, &drive, dr, (&thetas, rq))?),
        None => None,
    };
    b.set_part(Part::default());
    Ok(YokeResults { rows, slider_crank })
}

/// O, the line of the stroke, the dead centre T, the crank circle, and the diagrams' bases.
fn frame(
    b: &mut Board,
    yoke: &Yoke,
    dr: &Drawing,
    rq: YokeRequest,
) -> Result<Frame, ConstructionError> {
    let r = yoke.crank_radius / dr.length_scale;
    let setup = n(
        "centre O, the line of the stroke, the crank circle",
        Some("Kurbelkreis"),
    );
    let o = b.point(Point::origin(), Role::Given.named("O"), setup.clone());
    let circle = b.circle(&o, r, Drawn::Whole, Role::Given, setup.clone())?;
    let t = b.point_on_circle(&circle, 0.0, Role::Axis.named("T"), setup.clone());
    let axis = b.line_through(&t, &o, Role::Axis, setup.clone())?;
    let c_mm = yoke.crank_pin_speed / dr.velocity_scale;
    let a_mm = yoke.v2_over_r() / dr.acceleration_scale;
    let mut depth = r + 12.0;
    let mut bases = [None, None];
    for (k, (on, up, down)) in [(rq.velocity, c_mm, c_mm), (rq.acceleration, a_mm, a_mm)]
        .into_iter()
        .enumerate()
    {
        if !on {
            continue;
        }
        depth += up;
        let base_note = n(
            "base line of the diagram over the stroke",
            Some("Grundlinie des Diagramms"),
        );
        let at = b.point(Point::new(r, -depth), Role::Axis, base_note.clone());
        let base = b.parallel(&axis, &at, Role::Axis, base_note);
        bases[k] = Some((base, at));
        depth += down + 12.0;
    }
    Ok(Frame {
        o,
        axis,
        t,
        circle,
        bases,
    })
}

/// One crank angle: the pin, its drop onto the stroke, the velocity and acceleration
/// projected, checked, and carried into the diagrams (their points).
fn position(
    b: &mut Board,
    fr: &Frame,
    yoke: &Yoke,
    dr: &Drawing,
    (k, phi, rq): (u32, f64, YokeRequest),
) -> Result<(YokeRow, Ordinates), ConstructionError> {
    let r_m = yoke.crank_radius;
    let pin = b.point_on_circle(
        &fr.circle,
        phi,
        Role::Result.labelled(Label::indexed("P", k)),
        n("the crank at φ", Some("Kurbel")),
    );
    let f = b.foot(
        &fr.axis,
        &pin,
        Role::Given.labelled(Label::indexed("F", k)),
        n(
            "the slot at right angles to the stroke: the yoke at F",
            Some("Kurbelschleife"),
        ),
    );
    let x = b.measure(
        &fr.t,
        &f,
        &fr.axis,
        Scale::new(dr.length_scale, "mm"),
        Label::quiet("x", 0),
        n("yoke path x′ = TF", Some("Kolbenweg")),
    );
    let c = crate::kernel::angle::sin_cos_deg(phi).1;
    b.check(
        &x,
        "yoke path x′",
        "mm",
        "KG Abb. 1069: x′ = R(1 − cos φ)",
        r_m,
        || r_m * (1.0 - c),
    );
    let mut row = YokeRow {
        phi,
        x: x.g,
        c: None,
        b: None,
    };
    if !(rq.velocity || rq.acceleration) {
        return Ok((row, [None, None]));
    }
    let along = b.parallel(
        &fr.axis,
        &pin,
        Role::Auxiliary,
        n(
            "parallel to the stroke through the pin",
            Some("Parallele zur Hubrichtung durch den Kurbelzapfen"),
        ),
    );
    let at = At { f, pin, along };
    let pts = vectors(b, fr, (yoke, dr), (&at, phi, rq), &mut row)?;
    Ok((row, pts))
}

/// The pin's velocity on the tangent and its acceleration along the crank, each projected on
/// the stroke ([`project`]) into `row` and its diagram.
fn vectors(
    b: &mut Board,
    fr: &Frame,
    (yoke, dr): (&Yoke, &Drawing),
    (at, phi, rq): (&At, f64, YokeRequest),
    row: &mut YokeRow,
) -> Result<Ordinates, ConstructionError> {
    let v = yoke.crank_pin_speed;
    let (s, c) = crate::kernel::angle::sin_cos_deg(phi);
    let pin = at.pin;
    let mut pts = [None, None];
    let crank = b.line_through(
        &fr.o,
        &pin,
        Role::Construction,
        n("the crank line", Some("Kurbelstrahl")),
    )?;
    if rq.velocity {
        let tangent = b.perpendicular(
            &crank,
            &pin,
            Role::Construction,
            n("tangent at the pin", Some("Tangente im Kurbelzapfen")),
        );
        let tip = b.lay_off(
            &pin,
            &tangent,
            v / dr.velocity_scale,
            Role::Velocity,
            n(
                "the pin’s velocity v on the tangent",
                Some("Umfangsgeschwindigkeit"),
            ),
        )?;
        let what = Projected {
            k: 0,
            scale: Scale::new(dr.velocity_scale, "m/s"),
            name: (
                "c",
                "yoke velocity c′",
                "KG Abb. 1069: c′ = v·sin φ",
                "Geschwindigkeit der Schleife",
            ),
            exact: (v, v * s),
        };
        let (cv, p) = project(b, fr, at, &tip, what)?;
        (row.c, pts[0]) = (Some(cv), p);
    }
    if rq.acceleration {
        let a = yoke.v2_over_r();
        let tip = b.lay_off(
            &pin,
            &crank,
            -a / dr.acceleration_scale,
            Role::Velocity,
            n(
                "the pin’s acceleration v²/R towards O",
                Some("Zentripetalbeschleunigung"),
            ),
        )?;
        let what = Projected {
            k: 1,
            scale: Scale::new(dr.acceleration_scale, "m/s²"),
            name: (
                "b",
                "yoke acceleration b′",
                "KG Abb. 1069: b′ = v²/R·cos φ",
                "Beschleunigung der Schleife",
            ),
            exact: (a, a * c),
        };
        let (bv, p) = project(b, fr, at, &tip, what)?;
        (row.b, pts[1]) = (Some(bv), p);
    }
    Ok(pts)
}

/// Where the yoke stands at one crank angle: its point F on the stroke, the pin, and the
/// parallel to the stroke through the pin.
struct At {
    f: H<Point>,
    pin: H<Point>,
    along: H<crate::kernel::Line>,
}

/// A vector at the pin projected on the stroke: the diagram it goes into (`k`), its scale,
/// its label, quantity, formula and German term, and its natural magnitude and closed form.
struct Projected {
    k: usize,
    scale: Scale,
    name: (&'static str, &'static str, &'static str, &'static str),
    exact: (f64, f64),
}

/// The diagram points of one crank angle, the velocity's and the acceleration's.
type Ordinates = [Option<H<Point>>; 2];

/// The tip of a vector at the pin dropped onto the parallel to the stroke, the projection read
/// off and checked, and carried into its diagram.
fn project(
    b: &mut Board,
    fr: &Frame,
    at: &At,
    tip: &H<Point>,
    what: Projected,
) -> Result<(f64, Option<H<Point>>), ConstructionError> {
    let (label, quantity, formula, term) = what.name;
    let w = b.foot(
        &at.along,
        tip,
        Role::Auxiliary,
        n(
            "projected on the line of the stroke",
            Some("Projektion auf die Hubrichtung"),
        ),
    );
    let value = b.measure(
        &at.pin,
        &w,
        &at.along,
        what.scale,
        Label::quiet(label, 0),
        n(quantity, Some(term)),
    );
    let (reference, closed) = what.exact;
    b.check(
        &value,
        quantity,
        what.scale.unit,
        formula,
        reference,
        || closed,
    );
    let p = ordinate(b, fr, what.k, &at.f, (&value, what.scale.per_mm))?;
    Ok((value.g, p))
}

/// The value carried over the stroke: F dropped onto diagram `k`'s base, the value laid off
/// at right angles there (the dividers' transfer).
fn ordinate(
    b: &mut Board,
    fr: &Frame,
    k: usize,
    f: &H<Point>,
    value: (&H<f64>, f64),
) -> Result<Option<H<Point>>, ConstructionError> {
    let Some((base, _)) = &fr.bases[k] else {
        return Ok(None);
    };
    let at = b.foot(
        base,
        f,
        Role::Auxiliary,
        n(
            "the yoke’s place carried down to the diagram",
            Some("Lage der Schleife ins Diagramm übertragen"),
        ),
    );
    let up = b.perpendicular(
        base,
        &at,
        Role::Construction,
        n("ordinate", Some("Ordinate")),
    );
    // The base runs from T through O (towards −x): its normal points down the sheet, and a
    // positive value is laid off upwards, against it.
    let (v, per_mm) = value;
    b.transfer(
        &at,
        &up,
        Reading {
            value: v,
            per_mm: -per_mm,
        },
        Role::Result,
        n(
            "the value laid off as an ordinate",
            Some("Ordinate abgetragen"),
        ),
    )
    .map(Some)
}

/// The sheet's column of the yoke, beside the compared slider-crank's.
const YOKE: Part = Part::at(0, 1);
/// The sheet's column of the compared slider-crank.
const SLIDER_CRANK: Part = Part::at(0, 0);

/// The slider-crank of the same stroke, drawn beside the yoke by [`crank::construct_at`]
/// with its own checks (Tolle's diagram under its stroke), and its x, c and b laid into the
/// yoke's diagrams (dashed) from the same dead centre, so the two curves stand side by side.
fn compare(
    b: &mut Board,
    fr: &Frame,
    drive: &CrankDrive,
    dr: &Drawing,
    (thetas, rq): (&[f64], YokeRequest),
) -> Result<CrankResults, ConstructionError> {
    let origin = Point::origin();
    b.set_part(SLIDER_CRANK);
    let request = Request {
        piston_path: true,
        velocity_parallel: rq.velocity,
        acceleration: rq.acceleration,
        ..Request::default()
    };
    let res = crank::construct_at(
        b,
        drive,
        dr,
        &Angles::Degrees(thetas.to_vec()),
        &request,
        origin,
    )?;
    b.set_part(YOKE);
    let note = n(
        "the slider-crank of the same stroke laid into the diagram",
        Some("Schubkurbel"),
    );
    for (k, scale) in [(0, dr.velocity_scale), (1, dr.acceleration_scale)] {
        compare_curve(b, fr, &res, dr, k, scale, &note)?;
    }
    Ok(res)
}

/// The slider-crank's curve `k` (0: velocity, 1: acceleration, at `scale` per mm) laid over
/// the yoke's base line of the same diagram, where it is drawn.
fn compare_curve(
    b: &mut Board,
    fr: &Frame,
    res: &CrankResults,
    dr: &Drawing,
    k: usize,
    scale: f64,
    note: &Note,
) -> Result<(), ConstructionError> {
    let Some((base, _)) = &fr.bases[k] else {
        return Ok(());
    };
    let mut pts = Vec::new();
    let foot = b.foot(base, &fr.t, Role::Auxiliary, note.clone());
    for row in &res.rows {
        // The books give b in the direction of motion (positive while the piston speeds
        // up); the diagram reads it along the line of the stroke, as the yoke's b′.
        let sign = match row.stroke {
            crate::crank::closed_form::Stroke::Out => 1.0,
            crate::crank::closed_form::Stroke::Return => -1.0,
        };
        let value = if k == 0 {
            row.c_parallel
        } else {
            row.acceleration.map(|a| sign * a)
        };
        let (Some(x), Some(v)) = (row.x, value) else {
            continue;
        };
        let at = b.lay_off(
            &foot,
            base,
            x / dr.length_scale,
            Role::Auxiliary,
            note.clone(),
        )?;
        let up = b.perpendicular(base, &at, Role::Auxiliary, note.clone());
        pts.push(b.lay_off(&at, &up, -v / scale, Role::Auxiliary, note.clone())?);
    }
    let angles: Vec<f64> = res.rows.iter().map(|r| r.theta).collect();
    crate::crank::close_over_turn(&angles, &mut pts);
    if pts.len() > 1 {
        b.curve(&pts, Trace::Smooth, Role::Auxiliary, note.clone());
    }
    Ok(())
}
