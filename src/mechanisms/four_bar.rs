//! The four-bar linkages of KG XIV (Abb. 1043, 1045): the crank-rocker (Bogenschubkurbel),
//! whose crank OP turns round and whose rocker AB swings, and the parallel crank
//! (Parallelkurbel) of equal cranks and a coupler as long as the frame, as on a locomotive's
//! coupled axles.
//!
//! Per crank angle the coupler's far joint B is the cut of two circles: the coupler length L
//! about the pin P and the rocker length ρ about its pivot A, with the branch named (left or
//! right of the ray from P to A; for the parallel crank the branch that closes the
//! parallelogram). The rocker's dead positions (Totlagen) lie where crank and coupler are in
//! one line: B on the arcs L + R and L − R about O. The transmission angle μ at B between
//! coupler and rocker is reported and flagged where it falls below the limit a scene states.
//!
//! Grashof's rule decides whether the crank can turn round: with the shortest link s, the
//! longest l and the others p, q, it can when s + l ≤ p + q and the crank or the frame is the
//! shortest. At s + l = p + q (the parallel crank is such a linkage) the links fall into one
//! line at two crank angles: the two circles touch there, a typed tangency whose branch is
//! undetermined (the parallel crank may turn into the antiparallel one).

use crate::kernel::angle::triangle_angle;
use crate::kernel::{Branch, Circle, Point, Vector};
use crate::protocol::{Board, ConstructionError, Drawn, Label, Note, Part, Role, Topic, H};

fn n(caption: &'static str, term: Option<&'static str>) -> Note {
    crate::protocol::note(
        caption,
        term,
        "KG XIV, Abb. 1043, 1045",
        Topic::Custom("four-bar"),
    )
}

/// Which of the two closures of the loop B takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Assembly {
    /// B to the left of the ray from the pin P to the rocker's pivot A.
    Left,
    /// B to the right of that ray.
    Right,
    /// The parallel crank's closure: OPBA a parallelogram (PB parallel to OA).
    Parallel,
}

/// A four-bar linkage in mm of the machine: the frame OA along +x, the crank OP, the coupler
/// PB and the rocker AB.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourBar {
    /// Frame OA (the distance of the pivots) d.
    pub frame: f64,
    /// Crank OP = R.
    pub crank: f64,
    /// Coupler PB = L.
    pub coupler: f64,
    /// Rocker AB = ρ.
    pub rocker: f64,
    /// The closure taken.
    pub assembly: Assembly,
    /// The transmission angle below which a position is flagged (degrees).
    pub min_transmission: f64,
}

/// Why a four-bar cannot be driven round by its crank.
#[derive(Debug, Clone, PartialEq)]
pub enum FourBarError {
    /// A length is not a positive finite number (the link's name).
    NotPositive(&'static str),
    /// The longest link is at least as long as the other three together: the loop does not
    /// close (or only in one flat position).
    LoopOpen {
        /// The longest link's name.
        longest: &'static str,
    },
    /// Grashof's rule fails, or the shortest link is not the crank or the frame: the crank
    /// cannot turn round.
    NotGrashof {
        /// The lengths in the order frame, crank, coupler, rocker.
        lengths: [f64; 4],
    },
    /// The parallel closure asked of links that are not a parallel crank.
    NotParallel,
}

impl FourBarError {
    /// The input the error is about and a one-line reason.
    pub fn describe(&self) -> (&'static str, String) {
        match self {
            FourBarError::NotPositive(name) => (name, "must be a positive finite number".into()),
            FourBarError::LoopOpen { longest } => (longest, format!(
                "the {longest} is at least as long as the other three links together: the link lengths do not close the loop"
            )),
            FourBarError::NotGrashof { lengths: [d, r, l, p] } => ("crank", format!(
                // Every digit (shortest round trip): "rocker 150" for 149.999999999 hid why.
                "the crank cannot turn round (Grashof: shortest + longest ≤ the other two, and the crank or the frame the shortest): frame {d}, crank {r}, coupler {l}, rocker {p} mm"
            )),
            FourBarError::NotParallel => ("assembly", "the parallel closure needs a parallel crank: the rocker as long as the crank and the coupler as long as the frame".into()),
        }
    }
}

impl FourBar {
    fn lengths(&self) -> [(&'static str, f64); 4] {
        [
            ("frame", self.frame),
            ("crank", self.crank),
            ("coupler", self.coupler),
            ("rocker", self.rocker),
        ]
    }

    /// Whether the crank can turn round (Grashof, the crank or the frame shortest), and the
    /// closure fits the links.
    pub fn validate(&self) -> Result<(), FourBarError> {
        let links = self.lengths();
        if let Some((name, _)) = links.iter().find(|(_, x)| !(x.is_finite() && *x > 0.0)) {
            return Err(FourBarError::NotPositive(name));
        }
        let mut sorted = links;
        sorted.sort_by(|a, b| a.1.total_cmp(&b.1));
        let [s, p, q, l] = sorted.map(|x| x.1);
        if l >= s + p + q {
            return Err(FourBarError::LoopOpen {
                longest: sorted[3].0,
            });
        }
        let shortest_ok = self.crank <= s || self.frame <= s;
        if s + l > p + q || !shortest_ok {
            return Err(FourBarError::NotGrashof {
                lengths: links.map(|x| x.1),
            });
        }
        if self.assembly == Assembly::Parallel && !self.is_parallel() {
            return Err(FourBarError::NotParallel);
        }
        Ok(())
    }

    /// A parallel crank: rocker = crank and coupler = frame (to 1e-12 of the frame).
    pub fn is_parallel(&self) -> bool {
        let tol = 1e-12 * self.frame;
        (self.rocker - self.crank).abs() <= tol && (self.coupler - self.frame).abs() <= tol
    }

    /// Whether the rocker swings (a crank-rocker) rather than turning round too (a double
    /// crank: the frame the shortest link; or the rocker as short as the crank, as in the
    /// parallel crank).
    pub fn rocker_swings(&self) -> bool {
        let s = self
            .lengths()
            .map(|x| x.1)
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        self.frame > s && self.rocker > s
    }

    /// The closed forms at the crank angle θ (degrees from OA, counter-clockwise): B, the
    /// rocker's angle ∠OAB and the transmission angle μ = ∠PBA (degrees).
    pub fn exact(&self, theta: f64) -> (Point, f64, f64) {
        let (d, r, l, rho) = (self.frame, self.crank, self.coupler, self.rocker);
        let (s, c) = crate::kernel::angle::sin_cos_deg(theta);
        let p = Vector::new(r * c, r * s);
        let a = Vector::new(d, 0.0);
        // AB directly, not B − A: A is far from the pin when the crank is short, and B − A
        // would round the crank's own vector away.
        let ab = match self.assembly {
            Assembly::Parallel => p,
            side => {
                let pa = a - p;
                let f = pa.norm();
                let u = pa / f;
                // The angle at P between PA and PB, opposite the rocker.
                let (sin_g, cos_g) = triangle_angle(rho, l, f).sin_cos();
                let perp = Vector::new(-u.y, u.x) * if side == Assembly::Left { 1.0 } else { -1.0 };
                (u * cos_g + perp * sin_g) * l - pa
            }
        };
        let psi = ab.y.abs().atan2(-ab.x).to_degrees();
        (Point::from(a + ab), psi, self.mu_exact(theta).to_degrees())
    }

    /// The transmission angle μ at the crank angle θ (radians), by the half angle: with
    /// PA² = (d − r)² + 4dr·sin²(θ/2), PA² − (L − ρ)² = 4Lρ·sin²(μ/2) and
    /// (L + ρ)² − PA² = 4Lρ·cos²(μ/2), each formed from the given lengths without the
    /// cancellation of cos μ = (L² + ρ² − PA²)/2Lρ near 0° and 180° (the change points).
    fn mu_exact(&self, theta: f64) -> f64 {
        let (near, far, _) = self.mu_parts(theta);
        half_angles(near, far)
    }

    /// 4Lρ·sin²(μ/2), 4Lρ·cos²(μ/2) and PA at the crank angle θ ([`FourBar::mu_exact`]).
    fn mu_parts(&self, theta: f64) -> (f64, f64, f64) {
        let (d, r, l, rho) = (self.frame, self.crank, self.coupler, self.rocker);
        let (h, _) = crate::kernel::angle::sin_cos_deg(theta / 2.0);
        let q = 4.0 * d * r * h * h;
        let near = (d - r - l + rho) * (d - r + l - rho) + q;
        let far = (l + rho - d + r) * (l + rho + d - r) - q;
        (near, far, ((d - r) * (d - r) + q).sqrt())
    }

    /// The transmission angle μ at θ and how far it moves (both in degrees) when PA is
    /// `band` longer or shorter: the kernel takes two circles whose distance is within its
    /// length tolerance of touching as touching, so near a change point the construction
    /// may stand anywhere in that band. Away from one this is some 1e-12°; at one it is
    /// √(2·PA·band/Lρ), the square root a touching cut brings.
    pub fn transmission_within(&self, theta: f64, band: f64) -> (f64, f64) {
        let (near, far, f) = self.mu_parts(theta);
        let mu = half_angles(near, far);
        let dn = 2.0 * f * band + band * band;
        let moved = [(near + dn, far - dn), (near - dn, far + dn)]
            .map(|(n, f)| (half_angles(n, f) - mu).abs());
        (mu.to_degrees(), moved[0].max(moved[1]).to_degrees())
    }

    /// The transmission angle's extremes (μ_min, μ_max) in degrees, by the law of cosines in
    /// the triangle P B A with the crank in line with the frame: over it (θ = 0°, PA = |d − r|)
    /// and on it produced beyond O (θ = 180°, PA = d + r), where PA is shortest and longest:
    /// cos μ = (L² + ρ² − PA²)/(2Lρ).
    pub fn transmission_extremes(&self) -> (f64, f64) {
        let (d, r, l, rho) = (self.frame, self.crank, self.coupler, self.rocker);
        let by_cosines = |pa: f64| {
            let c = (l * l + rho * rho - pa * pa) / (2.0 * l * rho);
            c.clamp(-1.0, 1.0).acos().to_degrees()
        };
        (by_cosines((d - r).abs()), by_cosines(d + r))
    }

    /// The rocker's swing between its dead positions and the angle ϑ between the crank lines
    /// there (degrees): the crank takes 180° + ϑ one way and 180° − ϑ the other.
    pub fn dead_positions(&self) -> (f64, f64) {
        let (d, r, l, rho) = (self.frame, self.crank, self.coupler, self.rocker);
        let at_a = |reach: f64| triangle_angle(reach, d, rho);
        let at_o = |reach: f64| triangle_angle(rho, d, reach);
        (
            (at_a(l + r) - at_a(l - r)).abs().to_degrees(),
            (at_o(l + r) - at_o(l - r)).abs().to_degrees(),
        )
    }
}

crate::protocol::request_set! {
    /// What a four-bar scene can ask for besides the positions (its `outputs`).
    pub struct FourBarRequest as "FourBarOutput" {
        /// The rocker's dead positions by the arcs L ± R about O.
        dead_positions,
        /// The transmission angle at every position, flagged below the limit.
        transmission,
    }
}

/// One crank angle's values read off the construction.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FourBarRow {
    /// Crank angle θ (degrees from OA).
    pub theta: f64,
    /// The rocker's angle ∠OAB (degrees).
    pub rocker_angle: f64,
    /// The transmission angle μ = ∠PBA (degrees), if asked for.
    pub transmission: Option<f64>,
    /// μ (or 180° − μ) below the limit.
    pub flagged: bool,
    /// The two circles touched: the links lie in one line and the branch is undetermined.
    pub change_point: bool,
}

/// The results.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct FourBarResults {
    /// Per crank angle.
    pub rows: Vec<FourBarRow>,
    /// The rocker's swing and the angle ϑ of the crank lines at the dead positions (degrees),
    /// if asked for and the rocker swings.
    pub dead: Option<(f64, f64)>,
    /// The transmission angle's extremes (μ_min, μ_max) as constructed with the crank in
    /// line with the frame (degrees), if asked for and the rocker swings.
    pub transmission_extremes: Option<(f64, f64)>,
}

struct Frame {
    o: H<Point>,
    a: H<Point>,
    crank: H<Circle>,
    rocker: H<Circle>,
}

impl FourBar {
    /// The branch of the cut of the coupler's circle about the pin with the rocker's circle
    /// (from the pin's centre to A: `First` right, `Second` left).
    fn branch(&self, pin: Point, a: Point) -> Branch {
        match self.assembly {
            Assembly::Left => Branch::Second,
            Assembly::Right => Branch::First,
            Assembly::Parallel => Branch::Near(pin + (a - Point::origin())),
        }
    }
}

/// Constructs the four-bar at every crank angle θ (degrees from OA, counter-clockwise): B by
/// the two circles, the rocker's angle, and as asked the transmission angle and the rocker's
/// dead positions, each checked against the loop's closed form.
///
/// # Errors
/// [`ConstructionError::Unsupported`] naming the link at fault ([`FourBar::validate`]); a
/// kernel refusal otherwise.
///
/// ```
/// use graphostatik::mechanisms::four_bar::*;
/// use graphostatik::protocol::Board;
/// // A crank-rocker: frame 400, crank 100, coupler 350, rocker 300 mm (Grashof: 100 + 400 ≤ 650).
/// let fb = FourBar { frame: 400.0, crank: 100.0, coupler: 350.0, rocker: 300.0, assembly: Assembly::Left, min_transmission: 40.0 };
/// let rq = FourBarRequest { dead_positions: true, transmission: true };
/// let mut b = Board::recording();
/// let r = construct(&mut b, &fb, 5.0, &[0.0, 90.0, 180.0, 270.0], rq).unwrap();
/// let (swing, theta) = r.dead.unwrap();
/// assert!(swing > 0.0 && theta > 0.0);
/// assert!(b.all_passed());
/// ```
pub fn construct(
    b: &mut Board,
    fb: &FourBar,
    length_scale: f64,
    thetas: &[f64],
    rq: FourBarRequest,
) -> Result<FourBarResults, ConstructionError> {
    fb.validate().map_err(|e| {
        let (input, reason) = e.describe();
        ConstructionError::Unsupported {
            input: input.into(),
            reason,
        }
    })?;
    let fr = frame(b, fb, length_scale)?;
    let dead = if rq.dead_positions && fb.rocker_swings() {
        Some(dead_positions(b, &fr, fb, length_scale)?)
    } else {
        None
    };
    let mut rows = Vec::with_capacity(thetas.len());
    // One position in the result pen, the others thin (the plates' way).
    let shown = crate::crank::shown_position(thetas);
    for (i, &theta) in thetas.iter().enumerate() {
        b.set_context(|| format!("θ = {}°", crate::fmt::num(theta, 3)));
        let at = (i as u32, theta, rq, shown == Some(i));
        rows.push(position(b, &fr, (fb, length_scale), at)?);
    }
    b.clear_context();
    let extremes = if rq.transmission && fb.rocker_swings() {
        Some(extreme_transmission(b, &fr, fb, length_scale)?)
    } else {
        None
    };
    if fb.is_parallel() {
        change_points(b, &fr, fb, length_scale)?;
    }
    if rq.transmission {
        let drawn = shown.map(|i| rows[i]);
        flag_table(b, &fr, fb, (&rows, drawn, extremes));
    }
    Ok(FourBarResults {
        rows,
        dead,
        transmission_extremes: extremes,
    })
}

/// The radius (mm on the sheet) of the arcs that mark the transmission angle at B: 0.15 of
/// the shorter of coupler and rocker, 4 to 10 mm, at most half of it.
fn arc_radius(fb: &FourBar, ls: f64) -> f64 {
    let m = fb.coupler.min(fb.rocker) / ls;
    (0.15 * m).clamp(4.0, 10.0).min(0.5 * m)
}

/// Marks the angle at `v` between the rays to `p` and `q` (the one under 180°) with an arc
/// of `radius` mm lettered `name`.
fn mark_angle(
    b: &mut Board,
    (v, p, q): (&H<Point>, &H<Point>, &H<Point>),
    radius: f64,
    name: &'static str,
    note: Note,
) {
    let dir = |x: &H<Point>| (x.g - v.g).y.atan2((x.g - v.g).x).to_degrees();
    let start = dir(p);
    let sweep = (dir(q) - start + 540.0).rem_euclid(360.0) - 180.0;
    b.angle_arc(v, radius, (start, sweep), Role::Given.named(name), note);
}

/// The transmission angle's extremes of a crank-rocker, each at its own position with the
/// crank in line with the frame: over OA (θ = 0°, PA = d − r, μ_min) and on AO produced
/// beyond O (θ = 180°, PA = d + r, μ_max), the angle marked at B and checked against the
/// law of cosines in the triangle P B A.
fn extreme_transmission(
    b: &mut Board,
    fr: &Frame,
    fb: &FourBar,
    ls: f64,
) -> Result<(f64, f64), ConstructionError> {
    let (lo, hi) = fb.transmission_extremes();
    let cases = [
        (
            0.0,
            "μ_min",
            lo,
            n(
                "the crank over the frame OA (θ = 0°): PA = d − r is shortest, μ smallest",
                Some("kleinster Übertragungswinkel μ_min"),
            ),
        ),
        (
            180.0,
            "μ_max",
            hi,
            n(
                "the crank on AO produced beyond O (θ = 180°): PA = d + r is longest, μ largest",
                Some("größter Übertragungswinkel μ_max"),
            ),
        ),
    ];
    let mut out = [0.0; 2];
    for (k, (theta, name, exact, note)) in cases.into_iter().enumerate() {
        b.set_context(|| format!("{name}, θ = {}°", crate::fmt::num(theta, 3)));
        let (pin, joint) = pin_and_joint(b, fr, fb, ls, (theta, Label::NONE), &note)?;
        b.segment(&pin, &joint, Role::Construction, note.clone());
        b.segment(&fr.a, &joint, Role::Construction, note.clone());
        let mu = b.measure_angle(
            &joint,
            &pin,
            &fr.a,
            Label::quiet("μ", k as u32),
            note.clone(),
        );
        let band = fb.transmission_within(theta, b.tolerance().length * ls).1;
        let formula = match k {
            0 => "law of cosines: cos μ_min = (L² + ρ² − (d − r)²)/(2Lρ)",
            _ => "law of cosines: cos μ_max = (L² + ρ² − (d + r)²)/(2Lρ)",
        };
        b.check_within(&mu, name, "°", formula, 180.0, || (exact, band));
        mark_angle(b, (&joint, &pin, &fr.a), arc_radius(fb, ls), name, note);
        out[k] = mu.g;
    }
    b.clear_context();
    Ok((out[0], out[1]))
}

/// The crank pin at θ and the joint B where the coupler's circle about it cuts the rocker's
/// circle, the joint named `label`.
fn pin_and_joint(
    b: &mut Board,
    fr: &Frame,
    fb: &FourBar,
    ls: f64,
    (theta, label): (f64, Label),
    note: &Note,
) -> Result<(H<Point>, H<Point>), ConstructionError> {
    let pin = b.point_on_circle(&fr.crank, theta, Role::Construction, note.clone());
    let arc = b.circle(
        &pin,
        fb.coupler / ls,
        Drawn::Marks,
        Role::Construction,
        note.clone(),
    )?;
    let branch = fb.branch(pin.g, fr.a.g);
    let joint = b.cut_circle_circle(&arc, &fr.rocker, branch, label, note.clone())?;
    Ok((pin, joint))
}

/// The parallel crank's change points (Umschlagpunkte), U₁ at θ = 0° and U₂ at θ = 180°:
/// all four links in one line, the coupler's circle about the pin touching the rocker's
/// circle, so that the cut is one double point and the linkage may go on as the parallel or
/// as the antiparallel crank. The transmission angle there is checked to be 0°.
fn change_points(
    b: &mut Board,
    fr: &Frame,
    fb: &FourBar,
    ls: f64,
) -> Result<(), ConstructionError> {
    let cases = [
        (0.0, n("first change point U₁ (θ = 0°): crank, coupler, rocker and frame in one line, the coupler’s circle touches the rocker’s", Some("Umschlagpunkt (Verzweigungspunkt)"))),
        (180.0, n("second change point U₂ (θ = 180°): the links in one line again, the circles touch", Some("Umschlagpunkt (Verzweigungspunkt)"))),
    ];
    for (k, (theta, note)) in cases.into_iter().enumerate() {
        b.set_context(|| format!("U{}, θ = {}°", k + 1, crate::fmt::num(theta, 3)));
        let label = Label::indexed("U", k as u32 + 1);
        let (pin, joint) = pin_and_joint(b, fr, fb, ls, (theta, label), &note)?;
        b.segment(&pin, &joint, Role::Result, note.clone());
        b.segment(&fr.a, &joint, Role::Result, note.clone());
        let mu = b.measure_angle(&joint, &pin, &fr.a, Label::quiet("μ", 0), note);
        let within = fb.transmission_within(theta, b.tolerance().length * ls);
        b.check_within(
            &mu,
            "transmission angle at the change point",
            "°",
            "links in one line: μ = 0° (PA = L − ρ) or 180° (PA = L + ρ)",
            180.0,
            || within,
        );
    }
    b.clear_context();
    Ok(())
}

/// O and A on the frame line, the crank circle about O and the rocker's circle about A.
fn frame(b: &mut Board, fb: &FourBar, ls: f64) -> Result<Frame, ConstructionError> {
    let setup = n(
        "the pivots O and A, the crank circle and the rocker’s circle",
        Some("Gestell"),
    );
    let o = b.point(Point::origin(), Role::Given.named("O"), setup.clone());
    let a = b.point(
        Point::new(fb.frame / ls, 0.0),
        Role::Given.named("A"),
        setup.clone(),
    );
    b.segment(&o, &a, Role::Given, setup.clone());
    b.ground(&o, setup.clone());
    b.ground(&a, setup.clone());
    let crank = b.circle(&o, fb.crank / ls, Drawn::Whole, Role::Given, setup.clone())?;
    let rocker = b.circle(
        &a,
        fb.rocker / ls,
        if fb.rocker_swings() {
            Drawn::Marks
        } else {
            Drawn::Whole
        },
        Role::Given,
        setup,
    )?;
    Ok(Frame {
        o,
        a,
        crank,
        rocker,
    })
}

/// The rocker's dead positions: crank and coupler in one line, B on the arcs L + R and L − R
/// about O; the swing ∠B₁AB₂ and the angle ϑ = ∠B₁OB₂ of the crank lines there.
fn dead_positions(
    b: &mut Board,
    fr: &Frame,
    fb: &FourBar,
    ls: f64,
) -> Result<(f64, f64), ConstructionError> {
    let mut ends = Vec::with_capacity(2);
    for (reach, name, caption) in [
        (
            fb.coupler + fb.crank,
            "B₁",
            "crank and coupler stretched: the arc L + R about O cuts the rocker’s circle",
        ),
        (
            fb.coupler - fb.crank,
            "B₂",
            "crank and coupler folded: the arc L − R about O cuts the rocker’s circle",
        ),
    ] {
        let note = n(caption, Some("Totlage"));
        let arc = b.circle(
            &fr.o,
            reach / ls,
            Drawn::Marks,
            Role::Construction,
            note.clone(),
        )?;
        let branch = fb.branch(fr.o.g, fr.a.g);
        let end =
            b.cut_circle_circle(&arc, &fr.rocker, branch, Label::plain(name), note.clone())?;
        b.segment(&fr.a, &end, Role::Result, note);
        ends.push(end);
    }
    let (swing, theta) = fb.dead_positions();
    let sw = b.measure_angle(
        &fr.a,
        &ends[0],
        &ends[1],
        Label::quiet("Ψ", 0),
        n(
            "the rocker’s swing between its dead positions",
            Some("Schwingwinkel"),
        ),
    );
    b.check(
        &sw,
        "rocker swing",
        "°",
        "from the triangles O A B₁,₂: cos ∠OAB = (d² + ρ² − (L ± R)²)/(2dρ)",
        180.0,
        || swing,
    );
    let th = b.measure_angle(&fr.o, &ends[0], &ends[1], Label::quiet("ϑ", 0), n("the angle ϑ between the crank lines of the dead positions: the crank takes 180° ± ϑ between them", Some("Winkel der Totlagen")));
    b.check(
        &th,
        "crank angle ϑ between the dead positions",
        "°",
        "cos ∠AOB = (d² + (L ± R)² − ρ²)/(2d(L ± R))",
        180.0,
        || theta,
    );
    Ok((sw.g, th.g))
}

/// One crank angle: the pin, B by the two circles (a touching pair typed as a change point),
/// the coupler and the rocker drawn, the rocker's angle and the transmission angle checked.
fn position(
    b: &mut Board,
    fr: &Frame,
    (fb, ls): (&FourBar, f64),
    (i, theta, rq, shown): (u32, f64, FourBarRequest, bool),
) -> Result<FourBarRow, ConstructionError> {
    let pen = crate::crank::position_pen(shown);
    let pin = b.point_on_circle(
        &fr.crank,
        theta,
        pen.labelled(Label::indexed("P", i)),
        n("the crank pin at θ", Some("Kurbelzapfen")),
    );
    let arc = b.circle(
        &pin,
        fb.coupler / ls,
        Drawn::Marks,
        Role::Construction,
        n("the coupler’s length about the pin", Some("Koppel")),
    )?;
    let branch = fb.branch(pin.g, fr.a.g);
    // A parallel crank's B at a change point is lettered U there (change_points).
    let on_line = crate::kernel::angle::wrap_360(theta) % 180.0 == 0.0;
    let name = match fb.is_parallel() && on_line {
        true => Label::quiet("B", i),
        false => Label::indexed("B", i),
    };
    let joint = b.cut_circle_circle(
        &arc,
        &fr.rocker,
        branch,
        name,
        n(
            "B where the coupler’s circle cuts the rocker’s",
            Some("Gelenkpunkt B: Koppelkreis schneidet Schwingenkreis"),
        ),
    )?;
    let change_point = b.last_cut_touched();
    b.segment(&pin, &joint, pen, n("the coupler", Some("Koppel")));
    b.segment(&fr.a, &joint, pen, n("the rocker", Some("Schwinge")));
    let (_, psi, _) = fb.exact(theta);
    let angle = b.measure_angle(
        &fr.a,
        &fr.o,
        &joint,
        Label::quiet("ψ", 0),
        n("the rocker’s angle ∠OAB", Some("Schwingenwinkel")),
    );
    b.check(
        &angle,
        "rocker angle ∠OAB",
        "°",
        "loop closure: B from the triangle P B A",
        180.0,
        || psi,
    );
    let mut row = FourBarRow {
        theta,
        rocker_angle: angle.g,
        transmission: None,
        flagged: false,
        change_point,
    };
    if rq.transmission {
        let mu = fb.transmission_within(theta, b.tolerance().length * ls);
        let t = transmission(b, fr, fb, (&pin, &joint), mu);
        if shown {
            let note = n(
                "the transmission angle μ at B marked: the angle between coupler and rocker",
                Some("Übertragungswinkel μ"),
            );
            mark_angle(b, (&joint, &pin, &fr.a), arc_radius(fb, ls), "μ", note);
        }
        row.transmission = Some(t);
        row.flagged = t.min(180.0 - t) < fb.min_transmission;
    }
    Ok(row)
}

/// The angle 2·atan2(√near, √far), both clamped at 0 (radians).
fn half_angles(near: f64, far: f64) -> f64 {
    2.0 * near.max(0.0).sqrt().atan2(far.max(0.0).sqrt())
}

/// The transmission angle μ = ∠PBA between coupler and rocker, checked against the closed
/// form `mu` = (μ, the band it may move in at a change point); its note says when it falls
/// below the limit.
fn transmission(
    b: &mut Board,
    fr: &Frame,
    fb: &FourBar,
    (pin, joint): (&H<Point>, &H<Point>),
    (mu, band): (f64, f64),
) -> f64 {
    let caption = if mu.min(180.0 - mu) < fb.min_transmission {
        "the transmission angle μ at B: below the limit"
    } else {
        "the transmission angle μ at B"
    };
    let t = b.measure_angle(
        joint,
        pin,
        &fr.a,
        Label::quiet("μ", 0),
        n(caption, Some("Übertragungswinkel")),
    );
    b.check_within(
        &t,
        "transmission angle μ",
        "°",
        "tan²(μ/2) = (PA² − (L − ρ)²)/((L + ρ)² − PA²)",
        180.0,
        || (mu, band),
    );
    t.g
}

/// The transmission angle in words on the sheet: at the position drawn, its extremes where
/// the rocker swings, and the positions where it comes nearer than the limit to 0° or 180°.
fn flag_table(
    b: &mut Board,
    fr: &Frame,
    fb: &FourBar,
    (rows, drawn, extremes): (&[FourBarRow], Option<FourBarRow>, Option<(f64, f64)>),
) {
    let deg = |x: f64| format!("{}°", crate::fmt::num(x, 2));
    let at = |theta: f64| format!("θ = {}°", crate::fmt::num(theta, 3));
    let mut table = vec![vec![
        "transmission angle μ between coupler and rocker".to_string(),
        "μ".to_string(),
    ]];
    if let Some(r) = drawn {
        let mu = r.transmission.unwrap_or_default();
        table.push(vec![
            format!("at the position drawn, {}", at(r.theta)),
            deg(mu),
        ]);
    }
    if let Some((lo, hi)) = extremes {
        table.push(vec![
            "smallest μ_min, crank over OA (θ = 0°)".into(),
            deg(lo),
        ]);
        table.push(vec![
            "largest μ_max, crank on AO beyond O (θ = 180°)".into(),
            deg(hi),
        ]);
    }
    let limit = fb.min_transmission;
    let span = format!(
        "under {}° or over {}°",
        crate::fmt::num(limit, 3),
        crate::fmt::num(180.0 - limit, 3)
    );
    let flagged: Vec<&FourBarRow> = rows.iter().filter(|r| r.flagged).collect();
    if flagged.is_empty() {
        table.push(vec![format!("{span}: at no position"), String::new()]);
    } else {
        table.push(vec![format!("{span} at"), String::new()]);
    }
    table.extend(flagged.iter().map(|r| {
        let mu = r.transmission.unwrap_or_default();
        let what = if r.change_point { ", change point" } else { "" };
        vec![format!("  {}{what}", at(r.theta)), deg(mu)]
    }));
    // In a column of its own: the sheet layout sets it a gap right of the mechanism, level
    // with the foot of the crank circle.
    b.set_part(TABLE);
    let corner = Point::new(fr.a.g.x, -fr.crank.g.radius);
    b.table(
        corner,
        table,
        &[],
        n(
            "the transmission angle: at the position drawn, its extremes, the positions near 0° or 180°",
            Some("Übertragungswinkel"),
        ),
    );
    b.set_part(Part::default());
}

/// The part of the sheet that holds the table of flagged positions: a column right of the
/// mechanism's.
const TABLE: Part = Part::free(0, 1);
