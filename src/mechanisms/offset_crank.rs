//! The offset slider-crank (geschränkter Schubkurbeltrieb, KG XIV, Abb. 1046): the line of
//! the stroke passes the shaft at the distance a (the offset), so the two dead centres no
//! longer lie on one line through O. They are found by the arcs L + R and L − R about O cut
//! with the line of the stroke; between them the outstroke takes 180° + δ of the crank and the
//! return 180° − δ, δ = arcsin(a/(L − R)) − arcsin(a/(L + R)), and the stroke is longer than
//! 2R.
//!
//! Per crank angle the crosshead K is the cut of the arc L about the pin with the line of the
//! stroke; the piston velocity is c = v·OQ/R, Q where the rod cuts the perpendicular to the
//! stroke through O (the rod's instantaneous centre gives the same similar triangles as for
//! the straight crank); the driving piston force P splits at K into the rod force S and the
//! guide force N, and S carried to the pin gives the tangential force T on the tangent. At a
//! = 0 every value is the straight slider-crank's ([`crate::crank`]).

use crate::kernel::{Branch, Circle, Line, Point, Vector};
use crate::protocol::{
    Board, ConstructionError, Drawn, Label, Note, Reading, Role, Scale, Topic, Trace, H,
};

fn n(caption: &'static str, term: Option<&'static str>) -> Note {
    crate::protocol::note(
        caption,
        term,
        "KG XIV, Abb. 1046",
        Topic::Custom("offset crank"),
    )
}

/// The mechanism in mm of the machine, m/s and kg.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffsetCrank {
    /// Crank radius R.
    pub crank_radius: f64,
    /// Rod length L.
    pub rod_length: f64,
    /// Offset a of the line of the stroke from O (positive: on the side the pin passes on
    /// the outstroke, counter-clockwise from the crosshead's side).
    pub offset: f64,
    /// Crank-pin speed v (m/s).
    pub crank_pin_speed: f64,
    /// The driving piston force P (kg, pushing the piston the way it moves), if forces are
    /// asked for.
    pub piston_force: Option<f64>,
}

/// The closed forms of one crank angle by loop closure.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct OffsetValues {
    /// Piston path from the inner dead centre (mm).
    pub x: f64,
    /// Piston velocity, positive on the outstroke (m/s).
    pub c: f64,
    /// Rod force S, positive in compression (kg).
    pub rod_force: f64,
    /// Guide force N (kg): what the crosshead presses on its guide, positive towards the side
    /// of positive offsets.
    pub guide_force: f64,
    /// Tangential force T at the pin, positive when it drives (kg).
    pub tangential_force: f64,
}

impl OffsetCrank {
    /// Whether the lengths make a crank that turns round: R, L positive, |a| < L − R (at
    /// |a| = L − R the arc L − R about O only touches the line of the stroke).
    pub fn validate(&self) -> Result<(), (&'static str, String)> {
        let (r, l, a) = (self.crank_radius, self.rod_length, self.offset);
        let pos = |x: f64| x.is_finite() && x > 0.0;
        if !pos(r) {
            return Err(("crank_radius", "must be a positive finite number".into()));
        }
        if !(pos(l) && l > r) {
            return Err((
                "rod_length",
                format!("must be longer than the crank R = {r}, got {l}"),
            ));
        }
        if !(a.is_finite() && a.abs() < l - r) {
            return Err(("offset", format!(
                "|a| must be less than L − R = {} mm so that the crank turns round (the arc L − R about O must cut the line of the stroke), got {}",
                crate::fmt::num(l - r, 6), crate::fmt::num(a, 6)
            )));
        }
        if !pos(self.crank_pin_speed) {
            return Err(("crank_pin_speed", "must be a positive finite number".into()));
        }
        Ok(())
    }

    /// The crank angles of the inner and outer dead centres (degrees from the line through O
    /// parallel to the stroke, towards the crosshead): arcsin(a/(L + R)) and
    /// 180° + arcsin(a/(L − R)).
    pub fn dead_centres(&self) -> (f64, f64) {
        let (r, l, a) = (self.crank_radius, self.rod_length, self.offset);
        (
            (a / (l + r)).asin().to_degrees(),
            180.0 + (a / (l - r)).asin().to_degrees(),
        )
    }

    /// The stroke √((L + R)² − a²) − √((L − R)² − a²) (mm).
    pub fn stroke(&self) -> f64 {
        let (r, l, a) = (self.crank_radius, self.rod_length, self.offset);
        ((l + r) * (l + r) - a * a).sqrt() - ((l - r) * (l - r) - a * a).sqrt()
    }

    /// Whether the crank angle θ lies on the outstroke (from the inner dead centre to the
    /// outer, counter-clockwise).
    pub fn outstroke(&self, theta: f64) -> bool {
        let (i, o) = self.dead_centres();
        (theta - i).rem_euclid(360.0) < o - i
    }

    /// The closed forms at the crank angle θ (degrees, counter-clockwise from the line through
    /// O parallel to the stroke, towards the crosshead).
    pub fn exact(&self, theta: f64) -> OffsetValues {
        let (r, l, a) = (self.crank_radius, self.rod_length, self.offset);
        let (s, c) = crate::kernel::angle::sin_cos_deg(theta);
        let across = a - r * s;
        // h² = (L − across)(L + across), each factor from the given lengths and a half-angle
        // sine: L − across = (L − a − R) + 2R·sin²(θ/2 + 45°), L + across = (L + a − R) +
        // 2R·sin²(θ/2 − 45°). Near a locking position (across → L) L² − across² cancelled
        // the digits S = P·L/h is read with (4e-3 kg of 2.1e7 at L = a + R + 1e-5; now 0).
        let (up, _) = crate::kernel::angle::sin_cos_deg(theta / 2.0 + 45.0);
        let (down, _) = crate::kernel::angle::sin_cos_deg(theta / 2.0 - 45.0);
        let minus = (l - a - r) + 2.0 * r * up * up;
        let plus = (l + a - r) + 2.0 * r * down * down;
        let h = (minus * plus).max(0.0).sqrt();
        let x = ((l + r) * (l + r) - a * a).sqrt() - (r * c + h);
        let q = r * s - across * r * c / h;
        let v = self.crank_pin_speed * q / r;
        let p = self.piston_force.unwrap_or(0.0);
        let dir = if self.outstroke(theta) { -1.0 } else { 1.0 };
        // The rod from K to the pin: (R cos θ − d, R sin θ − a) / L, d − R cos θ = h.
        let (ex, ey) = (-h / l, -across / l);
        let rod = dir * p / ex;
        let guide = -rod * ey;
        let tangential = rod * (-ex * s + ey * c);
        OffsetValues {
            x,
            c: v,
            rod_force: rod,
            guide_force: guide,
            tangential_force: tangential,
        }
    }
}

crate::protocol::request_set! {
    /// What an offset-crank scene can ask for besides the path (its `outputs`).
    pub struct OffsetRequest as "OffsetOutput" {
        /// The piston velocity by Q on the perpendicular through O.
        velocity,
        /// The rod, guide and tangential forces S, N and T from the piston force.
        forces,
    }
}

/// One crank angle's values read off the construction (`None` where not asked for).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct OffsetRow {
    /// Crank angle θ (degrees).
    pub theta: f64,
    /// On the outstroke.
    pub outstroke: bool,
    /// Piston path from the inner dead centre (mm).
    pub x: f64,
    /// Piston velocity, positive on the outstroke (m/s).
    pub c: Option<f64>,
    /// Rod force S (kg).
    pub rod_force: Option<f64>,
    /// Guide force N (kg).
    pub guide_force: Option<f64>,
    /// Tangential force T (kg).
    pub tangential_force: Option<f64>,
}

/// The results: the dead centres and the rows.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct OffsetResults {
    /// The angle δ between the two dead centres' crank positions and a straight line
    /// (degrees): the outstroke takes 180° + δ, the return 180° − δ.
    pub delta: f64,
    /// The stroke between the dead centres (mm).
    pub stroke: f64,
    /// Per crank angle.
    pub rows: Vec<OffsetRow>,
}

/// Sheet scales: length 1 : n, velocity m/s per mm, force kg per mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffsetScales {
    /// Length scale 1 : n.
    pub length: f64,
    /// m/s per mm.
    pub velocity: f64,
    /// kg per mm.
    pub force: f64,
}

struct Frame {
    o: H<Point>,
    circle: H<Circle>,
    path: H<Line>,
    across: H<Line>,
    inner: H<Point>,
}

/// Constructs the offset slider-crank: its dead centres by the arcs L ± R, the angle δ and
/// the stroke, and per crank angle the crosshead, the path, and (as asked) the velocity and
/// the forces, each checked against the loop's closed form.
///
/// # Errors
/// [`ConstructionError::Unsupported`] naming the length at fault
/// ([`OffsetCrank::validate`]); a kernel refusal otherwise.
///
/// ```
/// use graphostatik::mechanisms::offset_crank::*;
/// use graphostatik::protocol::Board;
/// let k = OffsetCrank { crank_radius: 100.0, rod_length: 400.0, offset: 60.0, crank_pin_speed: 2.0, piston_force: Some(1000.0) };
/// let sc = OffsetScales { length: 5.0, velocity: 0.05, force: 25.0 };
/// let rq = OffsetRequest { velocity: true, forces: true };
/// let mut b = Board::recording();
/// let r = construct(&mut b, &k, sc, &[0.0, 90.0, 200.0], rq).unwrap();
/// // KG Abb. 1046: the outstroke takes more than half a turn, and the stroke exceeds 2R.
/// assert!(r.delta > 0.0 && r.stroke > 200.0);
/// assert!(b.all_passed());
/// ```
pub fn construct(
    b: &mut Board,
    k: &OffsetCrank,
    sc: OffsetScales,
    thetas: &[f64],
    rq: OffsetRequest,
) -> Result<OffsetResults, ConstructionError> {
    k.validate()
        .map_err(|(input, reason)| ConstructionError::Unsupported {
            input: input.into(),
            reason,
        })?;
    let (fr, mut res) = frame(b, k, sc)?;
    let shown = crate::crank::shown_position(thetas);
    let mut tips = Vec::with_capacity(thetas.len() + 1);
    for (i, &theta) in thetas.iter().enumerate() {
        b.set_context(|| format!("θ = {}°", crate::fmt::num(theta, 3)));
        let (row, tip) = position(b, &fr, (k, sc), (i as u32, theta, rq), shown == Some(i))?;
        res.rows.push(row);
        tips.extend(tip);
    }
    b.clear_context();
    velocity_curve(b, thetas, tips);
    Ok(res)
}

/// The velocity diagram over the stroke (KG Abb. 1046): the tips of c laid off across the
/// line of the stroke at the crosshead, joined in the order of the crank angles, closed over
/// a full turn (outstroke on one side, return on the other).
fn velocity_curve(b: &mut Board, thetas: &[f64], mut tips: Vec<H<Point>>) {
    crate::crank::close_over_turn(thetas, &mut tips);
    if tips.len() > 1 {
        b.curve(
            &tips,
            Trace::Smooth,
            Role::Result.named("c"),
            n(
                "the piston velocity over the stroke",
                Some("Geschwindigkeitsdiagramm"),
            ),
        );
    }
}

/// O, the crank circle, the line of the stroke at the offset (directed along the outstroke),
/// the perpendicular to it through O, and the dead centres by the arcs L + R and L − R.
fn frame(
    b: &mut Board,
    k: &OffsetCrank,
    sc: OffsetScales,
) -> Result<(Frame, OffsetResults), ConstructionError> {
    let ls = sc.length;
    let setup = n(
        "the shaft O, the crank circle, the line of the stroke at the offset a",
        Some("Schränkung"),
    );
    let o = b.point(Point::origin(), Role::Given.named("O"), setup.clone());
    let circle = b.circle(
        &o,
        k.crank_radius / ls,
        Drawn::Whole,
        Role::Given,
        setup.clone(),
    )?;
    let across = b.line_dir(&o, Vector::new(0.0, 1.0), Role::Axis, setup.clone())?;
    let foot = b.point(Point::new(0.0, k.offset / ls), Role::Axis, setup.clone());
    let path = b.line_dir(&foot, Vector::new(-1.0, 0.0), Role::Axis, setup)?;
    let (inner, res) = dead_centres(b, (&o, &path), k, ls)?;
    Ok((
        Frame {
            o,
            circle,
            path,
            across,
            inner,
        },
        res,
    ))
}

/// The dead centres by the arcs L + R and L − R about O on the line of the stroke, the stroke
/// between them and the angle δ of their crank lines; the inner dead centre and the results.
fn dead_centres(
    b: &mut Board,
    (o, path): (&H<Point>, &H<Line>),
    k: &OffsetCrank,
    ls: f64,
) -> Result<(H<Point>, OffsetResults), ConstructionError> {
    let mut ends = Vec::with_capacity(2);
    for (reach, name, caption) in [
        (
            k.rod_length + k.crank_radius,
            "T₁",
            "the inner dead centre: the arc L + R about O on the line of the stroke",
        ),
        (
            k.rod_length - k.crank_radius,
            "T₂",
            "the outer dead centre: the arc L − R about O on the line of the stroke",
        ),
    ] {
        let arc = b.circle(
            o,
            reach / ls,
            Drawn::Marks,
            Role::Construction,
            n(caption, Some("Totpunkt")),
        )?;
        ends.push(b.cut_line_circle(
            path,
            &arc,
            Branch::First,
            Label::plain(name),
            n(caption, Some("Totpunkt")),
        )?);
    }
    let stroke = b.measure(
        &ends[0],
        &ends[1],
        path,
        Scale::new(ls, "mm"),
        Label::quiet("s", 0),
        n("the stroke between the dead centres", Some("Hub")),
    );
    b.check(
        &stroke,
        "stroke",
        "mm",
        "√((L + R)² − a²) − √((L − R)² − a²)",
        k.rod_length,
        || k.stroke(),
    );
    let delta = b.measure_angle(
        o,
        &ends[0],
        &ends[1],
        Label::quiet("δ", 0),
        n(
            "the angle δ between the dead centres’ crank lines: the outstroke takes 180° + δ",
            Some("Winkel zwischen den Totlagen"),
        ),
    );
    let (i, out) = k.dead_centres();
    b.check(
        &delta,
        "angle δ of the dead centres",
        "°",
        "δ = arcsin(a/(L − R)) − arcsin(a/(L + R))",
        180.0,
        || (out - 180.0 - i).abs(),
    );
    let res = OffsetResults {
        delta: delta.g * k.offset.signum(),
        stroke: stroke.g,
        rows: Vec::new(),
    };
    Ok((ends[0], res))
}

/// The pin at θ, the crosshead K where the arc of the rod length about it cuts the line of
/// the stroke, and the rod.
fn crosshead(
    b: &mut Board,
    fr: &Frame,
    (k, ls): (&OffsetCrank, f64),
    (i, theta, pen): (u32, f64, Role),
) -> Result<At, ConstructionError> {
    let pin = b.point_on_circle(
        &fr.circle,
        theta,
        pen.labelled(Label::indexed("P", i)),
        n("the crank pin at θ", Some("Kurbelzapfen")),
    );
    let arc = b.circle(
        &pin,
        k.rod_length / ls,
        Drawn::Marks,
        Role::Construction,
        n(
            "the arc of the rod length about the pin",
            Some("Kreisbogen mit der Schubstangenlänge"),
        ),
    )?;
    let head = b.cut_line_circle(
        &fr.path,
        &arc,
        Branch::First,
        Label::quiet("K", i),
        n(
            "the crosshead K on the line of the stroke",
            Some("Kreuzkopf"),
        ),
    )?;
    let rod = b.line_through(
        &head,
        &pin,
        Role::Construction,
        n("the line of the rod", Some("Schubstangenrichtung")),
    )?;
    b.segment(&head, &pin, pen, n("the rod", Some("Schubstange")));
    Ok(At {
        pin,
        head,
        rod,
        outstroke: k.outstroke(theta),
    })
}

/// One crank angle: the pin, the crosshead by the arc L, the path, and the velocity and
/// forces as asked.
fn position(
    b: &mut Board,
    fr: &Frame,
    (k, sc): (&OffsetCrank, OffsetScales),
    (i, theta, rq): (u32, f64, OffsetRequest),
    shown: bool,
) -> Result<(OffsetRow, Option<H<Point>>), ConstructionError> {
    let ls = sc.length;
    // One position in the result pen, the others thin (the plates' way).
    let pen = crate::crank::position_pen(shown);
    let at = crosshead(b, fr, (k, ls), (i, theta, pen))?;
    let x = b.measure(
        &fr.inner,
        &at.head,
        &fr.path,
        Scale::new(ls, "mm"),
        Label::quiet("x", 0),
        n(
            "the piston path from the inner dead centre",
            Some("Kolbenweg"),
        ),
    );
    let exact = k.exact(theta);
    b.check(
        &x,
        "piston path x",
        "mm",
        "x = √((L + R)² − a²) − R cos θ − √(L² − (a − R sin θ)²)",
        k.rod_length,
        || exact.x,
    );
    let mut row = OffsetRow {
        theta,
        outstroke: at.outstroke,
        x: x.g,
        c: None,
        rod_force: None,
        guide_force: None,
        tangential_force: None,
    };
    let mut tip = None;
    if rq.velocity {
        let c = velocity(b, fr, (k, sc), (&at.rod, i), exact.c)?;
        row.c = Some(c.g);
        tip = Some(velocity_ordinate(b, fr, sc, &at.head, &c)?);
    }
    if let (true, Some(p)) = (rq.forces, k.piston_force) {
        let f = forces(b, fr, sc, &at, (p, &exact))?;
        (row.rod_force, row.guide_force, row.tangential_force) =
            (Some(f[0]), Some(f[1]), Some(f[2]));
    }
    Ok((row, tip))
}

/// c carried with the dividers onto the perpendicular to the line of the stroke at the
/// crosshead, at the velocity scale: a point of the velocity diagram over the stroke.
fn velocity_ordinate(
    b: &mut Board,
    fr: &Frame,
    sc: OffsetScales,
    head: &H<Point>,
    c: &H<f64>,
) -> Result<H<Point>, ConstructionError> {
    let note = n(
        "c laid off across the stroke at the crosshead",
        Some("Ordinate"),
    );
    let up = b.perpendicular(&fr.path, head, Role::Construction, note.clone());
    b.transfer(
        head,
        &up,
        Reading {
            value: c,
            per_mm: sc.velocity,
        },
        Role::Construction,
        note,
    )
}

/// The piston velocity c = v·OQ/R: Q where the rod cuts the perpendicular to the stroke
/// through O.
fn velocity(
    b: &mut Board,
    fr: &Frame,
    (k, sc): (&OffsetCrank, OffsetScales),
    (rod, i): (&H<Line>, u32),
    exact_c: f64,
) -> Result<H<f64>, ConstructionError> {
    let ls = sc.length;
    let q = b.meet_point(
        rod,
        &fr.across,
        Label::quiet("Q", i),
        n(
            "Q: the rod cuts the perpendicular to the stroke through O",
            Some("Schnittpunkt Q"),
        ),
    )?;
    let c = b.measure(
        &fr.o,
        &q,
        &fr.across,
        Scale::new(ls * k.crank_pin_speed / k.crank_radius, "m/s"),
        Label::quiet("c", 0),
        n(
            "the piston velocity c = v·OQ/R",
            Some("Kolbengeschwindigkeit"),
        ),
    );
    b.check(
        &c,
        "piston velocity c",
        "m/s",
        "c = v·(sin θ − (a − R sin θ) cos θ/√(L² − (a − R sin θ)²))",
        k.crank_pin_speed,
        || exact_c,
    );
    Ok(c)
}

/// The pin, the crosshead and the rod at one crank angle, and the stroke it is on.
struct At {
    pin: H<Point>,
    head: H<Point>,
    rod: H<Line>,
    outstroke: bool,
}

/// The piston force laid off at K along the motion, split into S along the rod and N across
/// the stroke; S carried to the pin and dropped onto the tangent: T.
fn forces(
    b: &mut Board,
    fr: &Frame,
    sc: OffsetScales,
    at: &At,
    (p, exact): (f64, &OffsetValues),
) -> Result<[f64; 3], ConstructionError> {
    let fs = Scale::new(sc.force, "kg");
    let along = if at.outstroke { 1.0 } else { -1.0 };
    let tip = b.lay_off(
        &at.head,
        &fr.path,
        along * p / sc.force,
        Role::Force,
        n(
            "the piston force P at the crosshead, along the motion",
            Some("Kolbenkraft"),
        ),
    )?;
    let cross = b.perpendicular(
        &fr.path,
        &tip,
        Role::Construction,
        n(
            "across the stroke through P’s tip",
            Some("Senkrechte zur Hubrichtung durch die Spitze von P"),
        ),
    );
    let split = b.meet_point(
        &cross,
        &at.rod,
        Label::NONE,
        n(
            "P split along the rod and across the stroke",
            Some("Kräftezerlegung"),
        ),
    )?;
    let s = b.measure(
        &at.head,
        &split,
        &at.rod,
        fs,
        Label::quiet("S", 0),
        n("the rod force S", Some("Stangenkraft")),
    );
    b.check(
        &s,
        "rod force S",
        "kg",
        "S = P·L/√(L² − (a − R sin θ)²)",
        p,
        || exact.rod_force,
    );
    let nf = b.measure(
        &split,
        &tip,
        &fr.across,
        fs,
        Label::quiet("N", 0),
        n("the guide force N", Some("Gleitbahndruck")),
    );
    b.check(
        &nf,
        "guide force N",
        "kg",
        "N = S·(a − R sin θ)/L",
        p,
        || exact.guide_force,
    );
    let t = tangential(b, fr, (sc, fs), at, (&s, exact.tangential_force, p))?;
    Ok([s.g, nf.g, t])
}

/// S carried from the crosshead to the pin and dropped onto the tangent there: the
/// tangential force T.
fn tangential(
    b: &mut Board,
    fr: &Frame,
    (sc, fs): (OffsetScales, Scale),
    at: &At,
    (s, exact_t, p): (&H<f64>, f64, f64),
) -> Result<f64, ConstructionError> {
    let carried = b.transfer(
        &at.pin,
        &at.rod,
        Reading {
            value: s,
            per_mm: sc.force,
        },
        Role::Force,
        n(
            "S carried to the pin",
            Some("S in den Kurbelzapfen verschoben"),
        ),
    )?;
    let crank = b.line_through(
        &fr.o,
        &at.pin,
        Role::Construction,
        n("the crank line", Some("Kurbelstrahl")),
    )?;
    let tangent = b.perpendicular(
        &crank,
        &at.pin,
        Role::Construction,
        n("the tangent at the pin", Some("Tangente im Kurbelzapfen")),
    );
    let t_foot = b.foot(
        &tangent,
        &carried,
        Role::Construction,
        n(
            "S dropped onto the tangent",
            Some("S auf die Tangente gelotet"),
        ),
    );
    let t = b.measure(
        &at.pin,
        &t_foot,
        &tangent,
        fs,
        Label::quiet("T", 0),
        n("the tangential force T", Some("Tangentialkraft")),
    );
    b.check(&t, "tangential force T", "kg", "T = P·|c|/v", p, || {
        exact_t
    });
    Ok(t.g)
}
