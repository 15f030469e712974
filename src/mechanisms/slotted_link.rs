//! The oscillating slotted link (schwingende Kurbelschleife, KG XIV, Abb. 1071-1072): the
//! crank pin C, turning about M at the uniform speed v, slides in the slotted lever DE, which
//! swings about D and drives the table at E. The working stroke takes the crank angle 2α, the
//! return 2β, found by the perpendiculars from M on the lever's outer positions (its tangents
//! to the crank circle): the table's mean speeds are in the ratio v_a/v_r = β/α.
//!
//! Per crank angle the construction follows KG: F is the foot of the perpendicular from M on
//! DC (it lies on the circle over MD), G the foot of E on the line MD, and the parallel to CG
//! through F cuts DG in H; the table speed is c = v/r · GH. At the crank's highest point it is
//! c₁ = vR/(e + r) (KG 304), at its lowest c₂ = vR/(e − r) (KG 305): e → r makes the return
//! speed grow without bound, and [`construct`] refuses e ≤ r.
//!
//! The table is taken as driven at E directly (a block in a slot of the table at right angles
//! to its guide), so that its path is E's projection on the guide, s = R(r/e − sin ψ) from the
//! start of the working stroke, where ψ is the lever's angle from MD.

use crate::kernel::{Circle, Line, Point};
use crate::protocol::{
    Board, ConstructionError, Drawn, Label, Note, Reading, Role, Scale, Topic, Trace, Weighted, H,
};

fn n(caption: &'static str, term: Option<&'static str>) -> Note {
    crate::protocol::note(
        caption,
        term,
        "KG XIV, Abb. 1071-1072",
        Topic::Custom("slotted link"),
    )
}

/// The mechanism, in mm of the machine and m/s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlottedLink {
    /// Crank radius r = MC.
    pub crank_radius: f64,
    /// Distance e = MD of the lever's pivot D from the crank's centre M (e > r).
    pub centre_distance: f64,
    /// Lever length R = DE (at least e + r, so that the slot holds the pin at the top).
    pub lever_length: f64,
    /// Crank-pin speed v (m/s).
    pub crank_pin_speed: f64,
}

/// Why a slotted link cannot be built.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LinkError {
    /// e ≤ r: D inside the crank circle, the lever turns round (no return stroke), and at
    /// e = r the return speed c₂ = vR/(e − r) is infinite.
    PivotInsideCrankCircle,
    /// R < e + r: the pin leaves the slot at the top of the crank circle.
    LeverTooShort,
    /// A length or the speed is not a positive finite number.
    NotPositive,
}

impl SlottedLink {
    /// Whether the lengths make a quick-return link.
    pub fn validate(&self) -> Result<(), LinkError> {
        let (r, e, l) = (self.crank_radius, self.centre_distance, self.lever_length);
        let pos = |x: f64| x.is_finite() && x > 0.0;
        if !(pos(r) && pos(e) && pos(l) && pos(self.crank_pin_speed)) {
            return Err(LinkError::NotPositive);
        }
        if e <= r {
            return Err(LinkError::PivotInsideCrankCircle);
        }
        if l < e + r {
            return Err(LinkError::LeverTooShort);
        }
        Ok(())
    }

    /// Half the return angle, β = arccos(r/e) (degrees).
    pub fn beta(&self) -> f64 {
        (self.crank_radius / self.centre_distance)
            .acos()
            .to_degrees()
    }

    /// Half the working angle, α = 180° − β (degrees).
    pub fn alpha(&self) -> f64 {
        180.0 - self.beta()
    }

    /// The table's stroke 2R·r/e (mm).
    pub fn stroke(&self) -> f64 {
        2.0 * self.lever_length * self.crank_radius / self.centre_distance
    }

    /// The largest working speed c₁ = vR/(e + r) (KG 304).
    pub fn c1(&self) -> f64 {
        self.crank_pin_speed * self.lever_length / (self.centre_distance + self.crank_radius)
    }

    /// The largest return speed c₂ = vR/(e − r) (KG 305).
    pub fn c2(&self) -> f64 {
        self.crank_pin_speed * self.lever_length / (self.centre_distance - self.crank_radius)
    }

    /// The closed forms at the crank angle φ from the start of the working stroke: the table's
    /// path s (mm) and speed c (m/s, positive in the working direction), by loop closure.
    pub fn exact(&self, phi: f64) -> (f64, f64) {
        let (r, e, l) = (self.crank_radius, self.centre_distance, self.lever_length);
        let (s, c) = crate::kernel::angle::sin_cos_deg(self.theta(phi));
        // C relative to D, MD along +y: (r cos θ, e + r sin θ).
        let (x, y) = (r * c, e + r * s);
        let d2 = x.mul_add(x, y * y);
        let d = d2.sqrt();
        let path = l * (r / e - x / d);
        let speed = self.crank_pin_speed * l * (y / d) * e.mul_add(s, r) / d2;
        (path, speed)
    }

    /// The crank's angle from M's horizontal (counter-clockwise, degrees) at φ from the start
    /// of the working stroke: that start is the tangent point β past M's lowest point.
    fn theta(&self, phi: f64) -> f64 {
        phi + self.beta() - 90.0
    }
}

crate::protocol::request_set! {
    /// What a slotted-link scene can ask for besides the positions (its `outputs`).
    pub struct LinkRequest as "LinkOutput" {
        /// The table speed over the stroke (Abb. 1072), with c₁ and c₂.
        velocity,
    }
}

/// One crank angle's values, read off the construction.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LinkRow {
    /// Crank angle φ from the start of the working stroke (degrees).
    pub phi: f64,
    /// The table's path s from the start of the working stroke (mm of the machine).
    pub s: f64,
    /// The table's speed c (m/s, positive in the working direction), if asked for.
    pub c: Option<f64>,
}

/// The results: the angles and speeds of the whole link and the rows per crank angle.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct LinkResults {
    /// Per crank angle.
    pub rows: Vec<LinkRow>,
    /// Half the working angle α (degrees), measured.
    pub alpha: f64,
    /// Half the return angle β (degrees), measured.
    pub beta: f64,
    /// The ratio of the mean speeds v_a/v_r = β/α.
    pub ratio: f64,
    /// The table's stroke (mm of the machine), measured.
    pub stroke: f64,
    /// c₁ and c₂ (m/s), constructed at the crank's highest and lowest points (velocity
    /// asked for).
    pub c1_c2: Option<(f64, f64)>,
}

/// The frame: D, M, the line MD, the crank circle, the table's guide, the start of the stroke
/// on it, and the base line of the velocity diagram.
struct Frame {
    d: H<Point>,
    m: H<Point>,
    axis: H<Line>,
    circle: H<Circle>,
    guide: H<Line>,
    start: H<Point>,
    base: Option<H<Line>>,
    /// How many crank positions the figure draws: a crowd of them is lettered every
    /// second … ([`Label::of_crowd`]).
    positions: usize,
}

/// The scales of a slotted link's figure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkScales {
    /// Length scale 1 : n.
    pub length: f64,
    /// m/s per mm of the table's speed.
    pub velocity: f64,
}

/// Sheet and machine units of one construction.
#[derive(Debug, Clone, Copy)]
struct Units {
    length_scale: f64,
    velocity_scale: f64,
}

impl LinkError {
    /// The refusal as a construction error naming the input.
    fn refusal(self, link: &SlottedLink) -> ConstructionError {
        let (r, e, l) = (link.crank_radius, link.centre_distance, link.lever_length);
        let num = |x: f64| crate::fmt::num(x, 6);
        let (input, reason) = match self {
            LinkError::PivotInsideCrankCircle => ("centre_distance", format!(
                "the lever's pivot D must lie outside the crank circle (e > r), got e = {} mm, r = {} mm: at e = r the return speed c₂ = vR/(e − r) is infinite (KG 305), and inside it the lever turns round",
                num(e), num(r)
            )),
            LinkError::LeverTooShort => ("lever_length", format!(
                "the lever DE = {} mm is shorter than e + r = {} mm: the pin leaves the slot at the top of the crank circle",
                num(l), num(e + r)
            )),
            LinkError::NotPositive => ("crank_radius", "every length and the speed must be positive finite numbers".to_string()),
        };
        ConstructionError::Unsupported {
            input: input.into(),
            reason,
        }
    }
}

/// Constructs the slotted link at every crank angle φ (degrees from the start of the working
/// stroke, counter-clockwise), its outer positions, angles and stroke, and, with the velocity
/// asked for, the table speed by KG's parallel through F, its diagram over the stroke, and c₁
/// and c₂ at the crank's highest and lowest points.
///
/// # Errors
/// [`ConstructionError::Unsupported`] naming the length at fault for a link that is not a
/// quick return ([`SlottedLink::validate`]); a kernel refusal otherwise.
///
/// ```
/// use graphostatik::mechanisms::slotted_link::*;
/// use graphostatik::protocol::Board;
/// // KG Abb. 1071 with r = 100, e = 200, R = 500 mm: β = arccos(r/e) = 60°, α = 120°.
/// let link = SlottedLink { crank_radius: 100.0, centre_distance: 200.0, lever_length: 500.0, crank_pin_speed: 1.0 };
/// let mut b = Board::recording();
/// let scales = LinkScales { length: 5.0, velocity: 0.02 };
/// let r = construct(&mut b, &link, scales, &[0.0, 120.0, 300.0], LinkRequest { velocity: true }).unwrap();
/// assert!((r.ratio - 0.5).abs() < 1e-12);          // v_a/v_r = β/α
/// let (c1, c2) = r.c1_c2.unwrap();
/// assert!((c1 - 500.0 / 300.0).abs() < 1e-12);     // KG 304: vR/(e + r)
/// assert!((c2 - 500.0 / 100.0).abs() < 1e-12);     // KG 305: vR/(e − r)
/// assert!(b.all_passed());
/// ```
pub fn construct(
    b: &mut Board,
    link: &SlottedLink,
    scales: LinkScales,
    phis: &[f64],
    rq: LinkRequest,
) -> Result<LinkResults, ConstructionError> {
    link.validate().map_err(|e| e.refusal(link))?;
    let u = Units {
        length_scale: scales.length,
        velocity_scale: scales.velocity,
    };
    let mut fr = frame(b, link, u, rq.velocity)?;
    fr.positions = phis.len();
    let mut res = outer_positions(b, &mut fr, link, u)?;
    let mut curve = Vec::with_capacity(phis.len());
    let shown = shown_index(link, phis);
    for (k, &phi) in phis.iter().enumerate() {
        b.set_context(|| format!("φ = {}°", crate::fmt::num(phi, 3)));
        let at = (k as u32, phi, rq.velocity, shown == Some(k));
        let (row, p) = position(b, &fr, (link, u), at)?;
        res.rows.push(row);
        curve.extend(p);
    }
    b.clear_context();
    if curve.len() > 1 {
        b.curve(
            &curve,
            Trace::Smooth,
            Role::Result.named("c"),
            n(
                "the table speed over the stroke",
                Some("Geschwindigkeitsriß"),
            ),
        );
    }
    if rq.velocity {
        res.c1_c2 = Some(extremes(b, &fr, link, u)?);
    }
    Ok(res)
}

/// D, M, the line MD, the crank circle, the circle over MD, the table's guide at right angles
/// to MD through the top of E's arc, and the velocity diagram's base line above it.
fn frame(
    b: &mut Board,
    link: &SlottedLink,
    u: Units,
    velocity: bool,
) -> Result<Frame, ConstructionError> {
    let ls = u.length_scale;
    let setup = n(
        "the lever’s pivot D, the crank’s centre M, the crank circle",
        Some("Kurbelkreis"),
    );
    let d = b.point(Point::origin(), Role::Given.named("D"), setup.clone());
    b.ground(&d, setup.clone());
    let e = link.centre_distance / ls;
    let m = b.point(Point::new(0.0, e), Role::Given.named("M"), setup.clone());
    let axis = b.line_through(&d, &m, Role::Axis, setup.clone())?;
    let circle = b.circle(&m, link.crank_radius / ls, Drawn::Whole, Role::Given, setup)?;
    let top = link.lever_length / ls;
    let guide_note = n(
        "the table’s guide at right angles to MD, through the top of E’s arc",
        Some("Tischführung"),
    );
    let e0 = b.lay_off(&d, &axis, top, Role::Axis, guide_note.clone())?;
    // The working stroke runs from right to left (the crank turns counter-clockwise).
    let guide = b.line_dir(
        &e0,
        crate::kernel::Vector::new(-1.0, 0.0),
        Role::Axis,
        guide_note,
    )?;
    let base = if velocity {
        let up = 12.0 + link.c2().max(link.c1()) / u.velocity_scale;
        let note = n(
            "base line of the velocity diagram over the stroke",
            Some("Grundlinie des Geschwindigkeitsdiagramms"),
        );
        let at = b.lay_off(&d, &axis, top + up, Role::Axis, note.clone())?;
        Some(b.parallel(&guide, &at, Role::Axis, note))
    } else {
        None
    };
    Ok(Frame {
        d,
        m,
        axis,
        circle,
        guide,
        start: e0,
        base,
        positions: 0,
    })
}

/// The lever's outer positions: the tangents from D to the crank circle, whose points of
/// contact are the cuts of the crank circle with the circle over MD (the feet of the
/// perpendiculars from M, KG), and E's outer positions A and B carried onto the guide. The
/// points of contact and A′, B′ on the guide.
fn tangents(
    b: &mut Board,
    fr: &Frame,
    link: &SlottedLink,
    u: Units,
) -> Result<[[H<Point>; 2]; 2], ConstructionError> {
    let ls = u.length_scale;
    let thales_note = n("the circle over MD", Some("Thaleskreis"));
    let mid = b.divide_at(&fr.d, &fr.m, 0.5, Label::NONE, thales_note.clone())?;
    let e = link.centre_distance / ls;
    let thales = b.circle(&mid, e / 2.0, Drawn::Whole, Role::Construction, thales_note)?;
    let mut ends = Vec::with_capacity(2);
    let mut touch = Vec::with_capacity(2);
    for (name, branch) in [
        ("A", crate::kernel::Branch::Second),
        ("B", crate::kernel::Branch::First),
    ] {
        let t = b.cut_circle_circle(&fr.circle, &thales, branch, Label::NONE, n("the lever’s outer position touches the crank circle where the circle over MD cuts it", Some("Totlage")))?;
        let lever = b.line_through(
            &fr.d,
            &t,
            Role::Construction,
            n("the lever in its outer position", Some("Schwinghebel")),
        )?;
        let end = b.lay_off(
            &fr.d,
            &lever,
            link.lever_length / ls,
            Role::Result.labelled(Label::plain(name)),
            n("E’s outer position on its arc", Some("äußerste Lage von E")),
        )?;
        ends.push(b.foot(
            &fr.guide,
            &end,
            Role::Auxiliary,
            n(
                "E’s outer position carried onto the guide",
                Some("äußerste Lage von E auf die Führung übertragen"),
            ),
        ));
        touch.push(t);
    }
    Ok([[touch[0], touch[1]], [ends[0], ends[1]]])
}

/// The return angle 2β between the points of contact at M, the ratio β/α, and the table's
/// stroke between E's two outer positions (whose first is the start of the working stroke).
fn outer_positions(
    b: &mut Board,
    fr: &mut Frame,
    link: &SlottedLink,
    u: Units,
) -> Result<LinkResults, ConstructionError> {
    let ls = u.length_scale;
    let [touch, ends] = tangents(b, fr, link, u)?;
    fr.start = ends[0];
    let two_beta = b.measure_angle(
        &fr.m,
        &touch[0],
        &touch[1],
        Label::quiet("2β", 0),
        n("the return angle 2β at M", Some("Rücklaufwinkel")),
    );
    b.check(
        &two_beta,
        "return angle 2β",
        "°",
        "KG Abb. 1071: cos β = r/e",
        180.0,
        || 2.0 * link.beta(),
    );
    quick_return_angles(b, fr, link, (&touch, &two_beta), u);
    let beta = two_beta.g / 2.0;
    let alpha = 180.0 - beta;
    let ratio = b.reckon(
        beta / alpha,
        "",
        Label::quiet("β/α", 0),
        Weighted {
            inputs: &[two_beta.id],
            weight: 90.0 / (alpha * alpha),
        },
        n(
            "the mean speeds v_a/v_r = β/α",
            Some("mittlere Geschwindigkeiten"),
        ),
    );
    b.check(
        &ratio,
        "mean speeds v_a/v_r = β/α",
        "",
        "KG Abb. 1071: v_a/v_r = β/α",
        1.0,
        || link.beta() / link.alpha(),
    );
    let stroke = b.measure(
        &ends[0],
        &ends[1],
        &fr.guide,
        Scale::new(ls, "mm"),
        Label::quiet("H", 0),
        n(
            "the table’s stroke between E’s outer positions",
            Some("Hub"),
        ),
    );
    b.check(
        &stroke,
        "table stroke",
        "mm",
        "2R·r/e",
        link.lever_length,
        || link.stroke(),
    );
    Ok(LinkResults {
        rows: Vec::new(),
        alpha,
        beta,
        ratio: ratio.g,
        stroke: stroke.g,
        c1_c2: None,
    })
}

/// The crank's two limiting positions, MK at right angles to the lever's outer positions DA
/// and DB (KG: "durch Fällen der Lote von M auf die äußersten Lagen des Hebels"), and the
/// angles they part the crank circle into, each marked at M with its letter: the working
/// stroke's 2α over the side away from D, the return's 2β over the side of D. 2α = 360° − 2β
/// is checked against α = 180° − β, cos β = r/e.
fn quick_return_angles(
    b: &mut Board,
    fr: &Frame,
    link: &SlottedLink,
    (touch, two_beta): (&[H<Point>; 2], &H<f64>),
    u: Units,
) {
    let limit = n(
        "the crank in its limiting positions: the perpendiculars from M on the lever’s outer positions DA and DB",
        Some("Lot von M auf die äußerste Lage des Hebels"),
    );
    for t in touch {
        b.segment(&fr.m, t, Role::Result, limit.clone());
    }
    let dir = |x: &H<Point>| (x.g - fr.m.g).y.atan2((x.g - fr.m.g).x).to_degrees();
    let start = dir(&touch[0]);
    // The short way round from the first point of contact to the second passes D's side.
    let ret = (dir(&touch[1]) - start + 540.0).rem_euclid(360.0) - 180.0;
    let work = ret.signum() * (360.0 - ret.abs());
    let r = link.crank_radius / u.length_scale;
    b.angle_arc(
        &fr.m,
        0.4 * r,
        (start, ret),
        Role::Given.named("2β"),
        n(
            "the return stroke’s crank angle 2β, on the side of D",
            Some("Rücklaufwinkel 2β"),
        ),
    );
    b.angle_arc(
        &fr.m,
        0.55 * r,
        (start + ret, work),
        Role::Given.named("2α"),
        n(
            "the working stroke’s crank angle 2α, on the side away from D",
            Some("Arbeitswinkel 2α"),
        ),
    );
    let two_alpha = b.reckon(
        360.0 - two_beta.g,
        "°",
        Label::quiet("2α", 0),
        Weighted {
            inputs: &[two_beta.id],
            weight: 1.0,
        },
        n("the working angle 2α = 360° − 2β", Some("Arbeitswinkel")),
    );
    b.check(
        &two_alpha,
        "working angle 2α",
        "°",
        "KG Abb. 1071: α = 180° − β, cos β = r/e",
        360.0,
        || 2.0 * link.alpha(),
    );
}

/// Where the lever stands at one crank angle: the pin C, the lever DC, E on it, F (the foot
/// from M) and G (E's foot on MD).
struct Lever {
    k: u32,
    c: H<Point>,
    lever: H<Line>,
    e: H<Point>,
    /// The position lettered in full as the book letters Abb. 1071 (E, F, G, H).
    shown: bool,
}

impl Lever {
    /// The name of a point of this position: written at the position shown, kept in the
    /// protocol only at the others.
    fn name(&self, base: &'static str) -> Label {
        crate::crank::position_name(base, self.k, self.shown)
    }
}

/// The position lettered in full: the one nearest a quarter of the working stroke (φ = α/2),
/// where C, F, G and H stand apart (at the stroke's middle the lever lies on MD).
fn shown_index(link: &SlottedLink, phis: &[f64]) -> Option<usize> {
    let want = link.alpha() / 2.0;
    (0..phis.len()).min_by(|&a, &b| (phis[a] - want).abs().total_cmp(&(phis[b] - want).abs()))
}

/// The pin at the crank's angle `theta` (degrees from M's horizontal), the lever through it,
/// and E at the lever's length from D.
fn lever_at(
    b: &mut Board,
    fr: &Frame,
    link: &SlottedLink,
    u: Units,
    (k, theta, shown): (u32, f64, bool),
) -> Result<Lever, ConstructionError> {
    // One position in the result pen, the others thin (the plates' way); the two extra
    // positions of the largest speeds keep their pins' names in the protocol only.
    let pen = crate::crank::position_pen(shown);
    // The position drawn in full is lettered whatever the crowd.
    let name = if k < 90 {
        let crowd = Label::of_crowd("C", k, fr.positions);
        Label {
            shown: crowd.shown || shown,
            ..crowd
        }
    } else {
        Label::quiet("C", k)
    };
    let c = b.point_on_circle(
        &fr.circle,
        theta,
        pen.labelled(name),
        n("the crank pin C at φ", Some("Kurbelzapfen")),
    );
    let lever = b.line_through(
        &fr.d,
        &c,
        pen,
        n("the slotted lever through D and C", Some("Kurbelschleife")),
    )?;
    let e = b.lay_off(
        &fr.d,
        &lever,
        link.lever_length / u.length_scale,
        pen.labelled(crate::crank::position_name("E", k, shown)),
        n(
            "E at the lever’s length from D",
            Some("Endpunkt E des Hebels"),
        ),
    )?;
    Ok(Lever {
        k,
        c,
        lever,
        e,
        shown,
    })
}

/// One crank angle: the lever, the table's place on the guide and its path checked, and the
/// table speed with its point in the velocity diagram where asked for.
fn position(
    b: &mut Board,
    fr: &Frame,
    (link, u): (&SlottedLink, Units),
    (k, phi, velocity, shown): (u32, f64, bool, bool),
) -> Result<(LinkRow, Option<H<Point>>), ConstructionError> {
    let lv = lever_at(b, fr, link, u, (k, link.theta(phi), shown))?;
    let place = b.foot(
        &fr.guide,
        &lv.e,
        crate::crank::position_pen(lv.shown).labelled(Label::quiet("S", k)),
        n("the table’s place: E on the guide", Some("Tisch")),
    );
    let s = b.measure(
        &fr.start,
        &place,
        &fr.guide,
        Scale::new(u.length_scale, "mm"),
        Label::quiet("s", 0),
        n(
            "the table’s path s from the start of the working stroke",
            Some("Tischweg"),
        ),
    );
    let (path, speed) = link.exact(phi);
    b.check(
        &s,
        "table path s",
        "mm",
        "s = R(r/e − sin ψ)",
        link.lever_length,
        || path,
    );
    let mut row = LinkRow {
        phi,
        s: s.g,
        c: None,
    };
    if !velocity {
        return Ok((row, None));
    }
    let c = table_speed(b, fr, (link, u), &lv)?;
    b.check(
        &c,
        "table speed c",
        "m/s",
        "c = v/r · GH = vR·cos ψ·(e sin θ + r)/DC²",
        link.c2(),
        || speed,
    );
    row.c = Some(c.g);
    let p = ordinate(b, fr, &place, (&c, u.velocity_scale))?;
    Ok((row, p))
}

/// The table speed c = v/r · GH (KG): F the foot of the perpendicular from M on the lever, G
/// E's foot on MD, and H where the parallel to CG through F cuts DG. Where CG runs too close
/// to MD for a clean cut (the lever near MD: at the crank's highest and lowest points it lies
/// on it), DF and DC are carried with the dividers onto the perpendicular to MD at D first,
/// which gives the same H by the same intercept theorem.
fn table_speed(
    b: &mut Board,
    fr: &Frame,
    (link, u): (&SlottedLink, Units),
    lv: &Lever,
) -> Result<H<f64>, ConstructionError> {
    let f = b.foot(
        &lv.lever,
        &fr.m,
        Role::Construction.labelled(lv.name("F")),
        n(
            "F, the foot of the perpendicular from M on DC, on the circle over MD",
            Some("Fußpunkt F (Thaleskreis über MD)"),
        ),
    );
    let g = b.foot(
        &fr.axis,
        &lv.e,
        Role::Construction.labelled(lv.name("G")),
        n("G, E’s foot on MD", Some("Fußpunkt G")),
    );
    let sin_direct = sin_to(&fr.axis, lv.c.g, g.g);
    let (dc, gd) = ((lv.c.g - fr.d.g).norm(), (g.g - fr.d.g).norm());
    let sin_swung = dc / dc.hypot(gd);
    let (c, f) = if sin_direct >= sin_swung.min(crate::kernel::tolerance::GLANCING_ANGLE.sin()) {
        (lv.c, f)
    } else {
        swing(b, fr, lv, &f)?
    };
    let h = cg_parallel(b, fr, (&c, &g, &f), lv.name("H"))?;
    let per_mm = u.length_scale * link.crank_pin_speed / link.crank_radius;
    Ok(b.measure(
        &h,
        &g,
        &fr.axis,
        Scale::new(per_mm, "m/s"),
        Label::quiet("c", 0),
        n("the table speed c = v/r · GH", Some("Tischgeschwindigkeit")),
    ))
}

/// The sine of the angle between `line` and the line through `p` and `q` (0 where they
/// coincide).
fn sin_to(line: &H<Line>, p: Point, q: Point) -> f64 {
    let d = q - p;
    let len = d.norm();
    if len == 0.0 {
        return 0.0;
    }
    (line.g.dir.perp(&d) / len).abs()
}

/// DF and DC read along the lever and carried from D onto the perpendicular to MD at D: F′
/// and C′, for a cut with CG that does not glance.
fn swing(
    b: &mut Board,
    fr: &Frame,
    lv: &Lever,
    f: &H<Point>,
) -> Result<(H<Point>, H<Point>), ConstructionError> {
    let carry = n(
        "DF and DC carried onto the perpendicular to MD at D (the lever lies too close to MD for the cut)",
        Some("Strecken auf das Lot übertragen"),
    );
    let across = b.perpendicular(&fr.axis, &fr.d, Role::Construction, carry.clone());
    let sheet = Scale::new(1.0, "mm");
    let df = b.measure(&fr.d, f, &lv.lever, sheet, Label::NONE, carry.clone());
    let dc = b.measure(&fr.d, &lv.c, &lv.lever, sheet, Label::NONE, carry.clone());
    let f2 = b.transfer(
        &fr.d,
        &across,
        Reading {
            value: &df,
            per_mm: 1.0,
        },
        Role::Construction.labelled(Label::quiet("F′", lv.k)),
        carry.clone(),
    )?;
    let c2 = b.transfer(
        &fr.d,
        &across,
        Reading {
            value: &dc,
            per_mm: 1.0,
        },
        Role::Construction.labelled(Label::quiet("C′", lv.k)),
        carry,
    )?;
    Ok((c2, f2))
}

/// H: the line CG, the parallel to it through F, and its cut with MD.
fn cg_parallel(
    b: &mut Board,
    fr: &Frame,
    (c, g, f): (&H<Point>, &H<Point>, &H<Point>),
    name: Label,
) -> Result<H<Point>, ConstructionError> {
    let cg = b.line_through(
        c,
        g,
        Role::Construction,
        n("C joined with G", Some("Verbindungslinie CG")),
    )?;
    let fh = b.parallel(
        &cg,
        f,
        Role::Construction,
        n(
            "the parallel to CG through F",
            Some("Parallele zu CG durch F"),
        ),
    );
    b.meet_point(
        &fh,
        &fr.axis,
        name,
        n(
            "H, where the parallel cuts DG: GH = GD·FC/CD",
            Some("Schnittpunkt H"),
        ),
    )
}

/// The table speed carried over the stroke: the table's place dropped onto the diagram's
/// base, the speed laid off at right angles there (working stroke up, return down).
fn ordinate(
    b: &mut Board,
    fr: &Frame,
    place: &H<Point>,
    (c, per_mm): (&H<f64>, f64),
) -> Result<Option<H<Point>>, ConstructionError> {
    let Some(base) = &fr.base else {
        return Ok(None);
    };
    let note = n(
        "the table’s place carried up to the diagram",
        Some("Lage des Tisches ins Diagramm übertragen"),
    );
    let at = b.foot(base, place, Role::Auxiliary, note);
    let up = b.perpendicular(
        base,
        &at,
        Role::Construction,
        n("ordinate", Some("Ordinate")),
    );
    // The base runs towards −x: its normal points down the sheet, so a working speed
    // (positive) is laid off against it, upwards.
    b.transfer(
        &at,
        &up,
        Reading {
            value: c,
            per_mm: -per_mm,
        },
        Role::Construction,
        n(
            "the speed laid off as an ordinate",
            Some("Geschwindigkeit als Ordinate abgetragen"),
        ),
    )
    .map(Some)
}

/// c₁ and c₂: the construction at the crank's highest and lowest points, checked against KG
/// 304 and 305.
fn extremes(
    b: &mut Board,
    fr: &Frame,
    link: &SlottedLink,
    u: Units,
) -> Result<(f64, f64), ConstructionError> {
    let mut out = [0.0; 2];
    let cases = [
        (
            90.0,
            1.0,
            "largest working speed c₁",
            "KG 304: c₁ = vR/(e + r)",
            link.c1(),
        ),
        (
            270.0,
            -1.0,
            "largest return speed c₂",
            "KG 305: c₂ = vR/(e − r)",
            link.c2(),
        ),
    ];
    for (k, (theta, sign, quantity, formula, exact)) in cases.into_iter().enumerate() {
        b.set_context(|| quantity.to_string());
        let lv = lever_at(b, fr, link, u, (90 + k as u32, theta, false))?;
        let c = table_speed(b, fr, (link, u), &lv)?;
        b.check(&c, quantity, "m/s", formula, link.c2(), || sign * exact);
        out[k] = sign * c.g;
    }
    b.clear_context();
    Ok((out[0], out[1]))
}
