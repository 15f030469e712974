//! Forces in the plane (LH A.2-4, C.2): the force polygon with its resultant and equilibrant,
//! the funicular polygon that places the resultant's line of action, the couple when the
//! force polygon closes but the funicular polygon does not, and the resolution of a force
//! along two given lines (the parallelogram of forces).
//!
//! # The construction (LH Abb. 22)
//! The forces are laid off head to tail: the closing side from the start to the end of the
//! chain is the resultant R (reversed, the equilibrant). From a pole O, rays run to the
//! corners of the chain; the strings of the funicular polygon run parallel to them between the
//! lines of action: string k between force k and force k + 1, string 0 before the first, string
//! n after the last. The first and the last string meet on the resultant's line of action. If
//! R = 0 they are parallel: a couple of moment |ray 0| × their distance, or, if they coincide,
//! equilibrium (force polygon and funicular polygon both closed).

pub mod polygon;

use crate::kernel::{Line, Point, Vector};
use crate::protocol::{note, Board, ConstructionError, Cut, Label, Note, Role, Scale, Topic, H};
use polygon::StringStyle;
use serde::Serialize;

const N_APPLICATION: Note = note(
    "point of application",
    Some("Angriffspunkt"),
    "LH A.1, Abb. 1",
    Topic::Loads,
);
const N_ARROW: Note = note(
    "force drawn in the position plan",
    Some("Kraft"),
    "LH Abb. 22",
    Topic::Loads,
);
const N_LINE: Note = note(
    "line of action",
    Some("Aktionslinie"),
    "LH A.1, Abb. 22",
    Topic::Loads,
);
const N_START: Note = note(
    "start of the force polygon",
    Some("Kräftepolygon"),
    "LH A.4, Abb. 7",
    Topic::ForcePlan,
);
const N_DIRECTION: Note = note(
    "parallel to the line of action",
    Some("Kraftrichtung"),
    "LH A.4",
    Topic::ForcePlan,
);
const N_LAY_OFF: Note = note(
    "lay off the force at the force scale",
    Some("Kräftemaßstab"),
    "LH A.4, Abb. 7",
    Topic::ForcePlan,
);
const N_RESULTANT: Note = note(
    "closing side: the resultant R",
    Some("Resultierende"),
    "LH A.3-4, Abb. 5-7",
    Topic::ForcePlan,
);
const N_RX: Note = note(
    "horizontal component of R",
    Some("Resultierende"),
    "LH A.4",
    Topic::ForcePlan,
);
const N_RY: Note = note(
    "vertical component of R",
    Some("Resultierende"),
    "LH A.4",
    Topic::ForcePlan,
);
const N_AXIS_X: Note = note(
    "horizontal through the start",
    Some("Waagerechte"),
    "LH A.4",
    Topic::ForcePlan,
);
const N_AXIS_Y: Note = note(
    "vertical through the start",
    Some("Senkrechte"),
    "LH A.4",
    Topic::ForcePlan,
);
const N_STRING_START: Note = note(
    "start of the funicular polygon on the first line of action",
    Some("Seilpolygon"),
    "LH Abb. 22",
    Topic::Funicular,
);
const N_FIRST_LAST: Note = note(
    "first and last string meet on the resultant",
    Some("Schnitt der äußeren Seilseiten"),
    "LH C.2, Abb. 22",
    Topic::Funicular,
);
const N_R_LINE: Note = note(
    "line of action of the resultant",
    Some("Aktionslinie der Resultierenden"),
    "LH C.2, Abb. 22",
    Topic::Funicular,
);
const N_R_MOMENT: Note = note(
    "moment of R about the origin, read off its line of action",
    Some("Moment"),
    "LH C.2",
    Topic::Funicular,
);
const N_COUPLE_FOOT: Note = note(
    "foot of the perpendicular between the parallel outer strings",
    Some("Kräftepaar"),
    "LH C.2",
    Topic::Funicular,
);
const N_COUPLE: Note = note(
    "couple: |ray 0| × distance of the outer strings",
    Some("Kräftepaar"),
    "LH C.2",
    Topic::Funicular,
);
const N_RESOLVE_LINE: Note = note(
    "parallel to a given direction through an end of the force",
    Some("Kräfteparallelogramm"),
    "LH A.2, Abb. 3",
    Topic::ForcePlan,
);
const N_RESOLVE_CUT: Note = note(
    "the parallels meet: the components",
    Some("Kräfteparallelogramm"),
    "LH A.2, Abb. 3",
    Topic::ForcePlan,
);
const N_RESOLVE_MEASURE: Note = note(
    "component read off at the force scale",
    Some("Komponente"),
    "LH A.2, Aufgabe 2",
    Topic::ForcePlan,
);
const N_COMPONENT: Note = note(
    "component drawn",
    Some("Komponente"),
    "LH A.2",
    Topic::ForcePlan,
);

/// A force: point of application (m) and components (kg), x to the right, y up.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Force {
    /// Point of application (m).
    pub at: [f64; 2],
    /// Components (kg).
    pub f: [f64; 2],
}

/// The outcome of the funicular polygon.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Resultant {
    /// A single force R through the point `through` (m), and its moment about the origin.
    Force {
        /// Components of R (kg).
        r: [f64; 2],
        /// A point of its line of action (m).
        through: [f64; 2],
        /// Moment of R about the origin (kg·m, counter-clockwise positive).
        moment: f64,
    },
    /// The force polygon closes but the funicular polygon does not: a couple (kg·m).
    Couple {
        /// Its moment (kg·m, counter-clockwise positive).
        moment: f64,
    },
    /// Force polygon and funicular polygon both close.
    Equilibrium,
}

/// Drawing choices.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SystemDrawing {
    /// Length scale 1 : n.
    pub length_scale: f64,
    /// kg per mm of sheet.
    pub force_scale: f64,
    /// The pole relative to the start of the force polygon (kg, x and y); `None` chooses one.
    pub pole: Option<[f64; 2]>,
    /// Where the force polygon starts on the sheet (mm); `None` puts it right of the forces.
    pub plan_at: Option<[f64; 2]>,
    /// The unit of the "forces" ("kg"; "m²" when areas stand for weights, LH C.3).
    pub unit: &'static str,
}

/// A force to resolve along two directions (degrees from +x).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Resolution {
    /// Index of the force.
    pub force: usize,
    /// The two directions (degrees).
    pub along: [f64; 2],
    /// Resolve the equilibrant −F instead: the two forces that hold F in balance (the rope
    /// tensions of LH Aufgabe 2).
    pub equilibrant: bool,
}

/// Results of [`construct_system`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SystemResults {
    /// What the system reduces to.
    pub resultant: Resultant,
    /// The resultant's line of action on the board, where there is one.
    #[serde(skip)]
    pub resultant_line: Option<H<Line>>,
    /// Components of the resolved forces along their two directions (kg).
    pub components: Vec<[f64; 2]>,
}

/// Closed forms: the vector sum and the moment about the origin.
pub fn sum_and_moment(forces: &[Force]) -> ([f64; 2], f64) {
    let mut r = [0.0, 0.0];
    let mut m = 0.0;
    for f in forces {
        r[0] += f.f[0];
        r[1] += f.f[1];
        m += f.at[0] * f.f[1] - f.at[1] * f.f[0];
    }
    (r, m)
}

/// The largest force (kg) and the farthest point of application from the origin (m, at least
/// 1): the magnitudes a force system's tolerances and default scales are relative to.
pub fn extent(forces: &[Force]) -> (f64, f64) {
    let fmax = forces
        .iter()
        .map(|f| f.f[0].hypot(f.f[1]))
        .fold(0.0, f64::max);
    let reach = forces
        .iter()
        .map(|f| f.at[0].hypot(f.at[1]))
        .fold(0.0, f64::max)
        .max(1.0);
    (fmax, reach)
}

/// Closed form of the resolution of `f` along unit directions `d1`, `d2`: the 2×2 solve.
pub fn resolve(f: [f64; 2], d1: [f64; 2], d2: [f64; 2]) -> Option<[f64; 2]> {
    let det = d1[0] * d2[1] - d1[1] * d2[0];
    if det.abs() < 1e-12 {
        return None;
    }
    Some([
        (f[0] * d2[1] - f[1] * d2[0]) / det,
        (d1[0] * f[1] - d1[1] * f[0]) / det,
    ])
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
/// let forces = [Force { at: [0.0, 0.0], f: [0.0, -100.0] }, Force { at: [3.0, 0.0], f: [0.0, -200.0] }];
/// let d = SystemDrawing { length_scale: 50.0, force_scale: 10.0, pole: None,
///     plan_at: None, unit: "kg" };
/// let mut b = Board::new(200.0, true);
/// let r = construct_system(&mut b, &forces, &d, &[]).unwrap();
/// match r.resultant {
///     Resultant::Force { r, through, .. } => {
///         assert!((r[1] + 300.0).abs() < 1e-9);
///         assert!((through[0] - 2.0).abs() < 1e-9);
///     }
///     other => panic!("{other:?}"),
/// }
/// assert!(b.steps().iter().flat_map(|s| &s.checks).all(|c| c.passed));
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
    let k = 1000.0 / dr.length_scale;
    let fs = dr.force_scale;
    let sp = |p: [f64; 2]| Point::new(p[0] * k, p[1] * k);
    let (r_cf, m_cf) = sum_and_moment(forces);
    let (fmax, reach) = extent(forces);
    let kg = Scale::kg(fs);

    // --- Position plan: points of application, arrows, lines of action ------------------
    let mut lines = Vec::with_capacity(forces.len());
    let mut xmax = f64::MIN;
    for (i, f) in forces.iter().enumerate() {
        let v = Vector::new(f.f[0], f.f[1]);
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
        let a = b.point(
            sp(f.at),
            Label::quiet("a", i as u32 + 1),
            Role::Given,
            N_APPLICATION,
        );
        let tail = b.point(
            a.g - v * (12.0 / len),
            Label::indexed("F", i as u32 + 1),
            Role::Given,
            N_ARROW,
        );
        b.segment(&tail, &a, Label::NONE, Role::Force, N_ARROW);
        lines.push(b.line_dir(&a, v, Label::NONE, Role::Construction, N_LINE)?);
        xmax = xmax.max(a.g.x);
    }

    // --- Force polygon ----------------------------------------------------------------
    let origin = match dr.plan_at {
        Some([x, y]) => Point::new(x, y),
        None => Point::new(xmax + 30.0 + fmax / fs, 0.0),
    };
    let p0 = b.point(origin, Label::plain("0"), Role::Given, N_START);
    let mut pts = vec![p0];
    for (i, f) in forces.iter().enumerate() {
        let prev = pts[i];
        let dir = b.parallel(&lines[i], &prev, Label::NONE, Role::Auxiliary, N_DIRECTION);
        let len = f.f[0].hypot(f.f[1]) / fs;
        pts.push(b.lay_off(
            &prev,
            &dir,
            len,
            Label::indexed("", i as u32 + 1),
            Role::Force,
            N_LAY_OFF,
        )?);
    }
    let n = forces.len();
    let end = pts[n];
    let r_len = (end.g - p0.g).norm();
    let tol = b.tolerance().length;
    let ax = b.line_dir(
        &p0,
        Vector::new(1.0, 0.0),
        Label::NONE,
        Role::Auxiliary,
        N_AXIS_X,
    )?;
    let ay = b.line_dir(
        &p0,
        Vector::new(0.0, 1.0),
        Label::NONE,
        Role::Auxiliary,
        N_AXIS_Y,
    )?;
    if r_len > tol {
        b.segment(&p0, &end, Label::plain("R"), Role::Force, N_RESULTANT);
    }
    let rx = b.measure(&p0, &end, &ax, kg, Label::quiet("Rx", 0), N_RX);
    b.check(
        &rx,
        "resultant, horizontal component",
        dr.unit,
        "ΣFx",
        fmax,
        || r_cf[0],
    );
    let ry = b.measure(&p0, &end, &ay, kg, Label::quiet("Ry", 0), N_RY);
    b.check(
        &ry,
        "resultant, vertical component",
        dr.unit,
        "ΣFy",
        fmax,
        || r_cf[1],
    );

    // --- Pole and rays ----------------------------------------------------------------
    let pole_at = match dr.pole {
        Some(p) => p0.g + Vector::new(p[0], p[1]) / fs,
        None => default_pole(&pts.iter().map(|p| p.g).collect::<Vec<_>>(), fmax / fs),
    };
    let polygon::Rays { pole, rays } = polygon::pole_and_rays(b, pole_at, &pts)?;

    // --- Funicular polygon ------------------------------------------------------------
    let start = b.point(
        lines[0].g.origin,
        Label::plain("I"),
        Role::Given,
        N_STRING_START,
    );
    let strings = polygon::strings(b, &rays, &start, true, StringStyle::RESULT, |_, j| {
        Ok(lines[j])
    })?
    .strings;
    let mscale = Scale {
        per_mm: fs / k,
        unit: "kg·m",
    };
    let mref = fmax * reach;
    let mut resultant_line = None;
    let resultant = match b.meet(&strings[0], &strings[n], Label::plain("X"), N_FIRST_LAST) {
        Cut::Point(x, _) if r_len > tol => {
            // The direction of R in the force plan, carried over through X.
            let r_dir = b.line_through(&p0, &end, Label::NONE, Role::Auxiliary, N_RESULTANT)?;
            let r_line = b.parallel(&r_dir, &x, Label::NONE, Role::Result, N_R_LINE);
            resultant_line = Some(r_line);
            // Moment of R about the origin: |R| times the signed distance of its line.
            let o = b.point(Point::origin(), Label::NONE, Role::Given, N_R_MOMENT);
            let foot = b.foot(&r_line, &o, Label::NONE, Role::Construction, N_R_MOMENT);
            let normal = H {
                id: r_line.id,
                g: Line {
                    origin: o.g,
                    dir: Vector::new(r_line.g.dir.y, -r_line.g.dir.x),
                },
            };
            let d = b.measure(
                &o,
                &foot,
                &normal,
                Scale {
                    per_mm: r_len * fs / k,
                    unit: "kg·m",
                },
                Label::NONE,
                N_R_MOMENT,
            );
            b.check(
                &d,
                "moment of the resultant about the origin",
                "kg·m",
                "ΣM = x·Fy − y·Fx",
                mref,
                || m_cf,
            );
            Resultant::Force {
                r: [rx.g, ry.g],
                through: [x.g.x / k, x.g.y / k],
                moment: d.g,
            }
        }
        Cut::Point(..) | Cut::Coincident => Resultant::Equilibrium,
        Cut::Parallel { .. } => {
            // A couple: the outer strings are parallel; its moment is |ray 0| × their distance.
            let foot = b.foot(
                &strings[n],
                &start,
                Label::NONE,
                Role::Construction,
                N_COUPLE_FOOT,
            );
            let ray0 = (pts[0].g - pole.g).norm();
            let normal = H {
                id: strings[0].id,
                g: Line {
                    origin: start.g,
                    dir: strings[0].g.normal(),
                },
            };
            // Sign: counter-clockwise positive, from the sense in which the chain runs.
            let sense = (pts[0].g - pole.g)
                .dot(&Vector::new(strings[0].g.dir.x, strings[0].g.dir.y))
                .signum();
            let m = b.measure(
                &start,
                &foot,
                &normal,
                Scale {
                    per_mm: ray0 * fs / k * sense,
                    unit: "kg·m",
                },
                Label::quiet("M", 0),
                N_COUPLE,
            );
            b.check(
                &H {
                    id: m.id,
                    g: m.g.abs(),
                },
                "moment of the couple",
                "kg·m",
                "ΣM = x·Fy − y·Fx",
                mref,
                || m_cf.abs(),
            );
            Resultant::Couple { moment: m.g }
        }
    };
    if let Resultant::Equilibrium = resultant {
        // Both polygons close: the checks are that R = 0 (above) and ΣM = 0.
        let z = b.measure(&start, &start, &ax, mscale, Label::NONE, N_FIRST_LAST);
        b.check(
            &z,
            "moment of the system (equilibrium)",
            "kg·m",
            "ΣM = x·Fy − y·Fx",
            mref,
            || m_cf,
        );
    }

    // --- Resolutions ------------------------------------------------------------------
    let mut components = Vec::new();
    for (j, res) in resolutions.iter().enumerate() {
        let f = forces.get(res.force).ok_or_else(|| {
            ConstructionError::unsupported(
                format!("resolutions[{j}].force"),
                format!("resolution {j} names force {} of {n}", res.force + 1),
            )
        })?;
        let (s1, c1) = crate::kernel::angle::sin_cos_deg(res.along[0]);
        let (s2, c2) = crate::kernel::angle::sin_cos_deg(res.along[1]);
        let (tail, head) = if res.equilibrant {
            (pts[res.force + 1], pts[res.force])
        } else {
            (pts[res.force], pts[res.force + 1])
        };
        let fv = if res.equilibrant {
            [-f.f[0], -f.f[1]]
        } else {
            f.f
        };
        let l1 = b.line_dir(
            &tail,
            Vector::new(c1, s1),
            Label::NONE,
            Role::Auxiliary,
            N_RESOLVE_LINE,
        )?;
        let l2 = b.line_dir(
            &head,
            Vector::new(c2, s2),
            Label::NONE,
            Role::Auxiliary,
            N_RESOLVE_LINE,
        )?;
        let cpt = b
            .meet_point(&l1, &l2, Label::quiet("K", j as u32), N_RESOLVE_CUT)
            .map_err(|_| {
                ConstructionError::unsupported(
                    format!("resolutions[{j}].along"),
                    format!("resolution {j}: the two directions are parallel"),
                )
            })?;
        let k1 = b.measure(
            &tail,
            &cpt,
            &l1,
            kg,
            Label::quiet("S", 2 * j as u32 + 1),
            N_RESOLVE_MEASURE,
        );
        let k2 = b.measure(
            &cpt,
            &head,
            &l2,
            kg,
            Label::quiet("S", 2 * j as u32 + 2),
            N_RESOLVE_MEASURE,
        );
        let exact = resolve(fv, [c1, s1], [c2, s2]).unwrap_or([f64::NAN; 2]);
        b.check(
            &k1,
            "component along the first direction",
            dr.unit,
            "2×2 solve",
            fmax,
            || exact[0],
        );
        b.check(
            &k2,
            "component along the second direction",
            dr.unit,
            "2×2 solve",
            fmax,
            || exact[1],
        );
        b.segment(&tail, &cpt, Label::NONE, Role::Force, N_COMPONENT);
        b.segment(&cpt, &head, Label::NONE, Role::Force, N_COMPONENT);
        components.push([k1.g, k2.g]);
    }
    Ok(SystemResults {
        resultant,
        resultant_line,
        components,
    })
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
    let side = if chord.norm() > 1e-9 * span {
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
        if score > best_score + 1e-12 {
            best_score = score;
            best = cand;
        }
        if score > 0.26 {
            break;
        }
    }
    best
}

const N_AUX_FORCE: Note = note(
    "force laid off at its point of application",
    Some("Parallelkraft"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
const N_AUX: Note = note(
    "auxiliary force P′ (and its opposite P″)",
    Some("Hilfskraft"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
const N_AUX_PAR: Note = note(
    "parallelogram of the force and the auxiliary force",
    Some("Kräfteparallelogramm"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
const N_AUX_R: Note = note(
    "line of action of the partial resultant",
    Some("Teilresultierende"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
const N_AUX_X: Note = note(
    "the partial resultants meet on the resultant",
    Some("Endresultierende"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
const N_AUX_LINE: Note = note(
    "the resultant, parallel to the forces",
    Some("Resultierende"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
const N_AUX_FOOT: Note = note(
    "the resultant cuts the line joining the points of application",
    Some("Hebelgesetz"),
    "LH C.1, Abb. 21",
    Topic::Funicular,
);
const N_AUX_A: Note = note(
    "distance a from the first point of application",
    Some("a : b = K2 : K1"),
    "LH C.1",
    Topic::Funicular,
);

/// The resultant of two parallel forces by two equal and opposite auxiliary forces (LH C.1,
/// Abb. 21): P′ at the first point of application, P″ = −P′ at the second, each combined with
/// its force by the parallelogram; the two partial resultants meet on the resultant, which runs
/// parallel to the forces and divides the distance of the points of application by the lever
/// rule a : b = K₂ : K₁. `aux` is |P′| (kg), drawn across the forces.
///
/// # Errors
/// [`ConstructionError::Unsupported`] if the forces are not parallel, or equal and opposite (a
/// couple: the partial resultants are parallel and the step records it).
///
/// ```
/// use graphostatik::statics::funicular::*;
/// use graphostatik::protocol::Board;
/// let k1 = Force { at: [0.0, 0.0], f: [0.0, -100.0] };
/// let k2 = Force { at: [3.0, 0.0], f: [0.0, -200.0] };
/// let d = SystemDrawing { length_scale: 50.0, force_scale: 10.0, pole: None, plan_at: None, unit: "kg" };
/// let mut b = Board::new(200.0, true);
/// let a = parallel_pair_by_auxiliary_forces(&mut b, k1, k2, 150.0, &d).unwrap();
/// assert!((a - 2.0).abs() < 1e-9); // a : b = 2 : 1 = K2 : K1
/// assert!(b.steps().iter().flat_map(|s| &s.checks).all(|c| c.passed));
/// ```
pub fn parallel_pair_by_auxiliary_forces(
    b: &mut Board,
    k1: Force,
    k2: Force,
    aux: f64,
    dr: &SystemDrawing,
) -> Result<f64, ConstructionError> {
    let v1 = Vector::new(k1.f[0], k1.f[1]);
    let v2 = Vector::new(k2.f[0], k2.f[1]);
    if v1.norm() == 0.0
        || v2.norm() == 0.0
        || crate::kernel::cross(&v1, &v2).abs() > 1e-12 * v1.norm() * v2.norm()
    {
        return Err(ConstructionError::unsupported(
            "forces",
            "the auxiliary-force construction takes two parallel, non-zero forces",
        ));
    }
    let k = 1000.0 / dr.length_scale;
    let fs = dr.force_scale;
    let dir = v1 / v1.norm();
    let across = Vector::new(-dir.y, dir.x);
    let mut partial = Vec::new();
    for (i, (f, sense)) in [(k1, 1.0), (k2, -1.0)].into_iter().enumerate() {
        let a = b.point(
            Point::new(f.at[0] * k, f.at[1] * k),
            Label::indexed("K", i as u32 + 1),
            Role::Given,
            N_APPLICATION,
        );
        let along = b.line_dir(&a, dir, Label::NONE, Role::Construction, N_LINE)?;
        let fv = Vector::new(f.f[0], f.f[1]);
        let e = b.lay_off(
            &a,
            &along,
            fv.dot(&dir) / fs,
            Label::NONE,
            Role::Force,
            N_AUX_FORCE,
        )?;
        let cross_line = b.line_dir(&a, across, Label::NONE, Role::Auxiliary, N_AUX)?;
        let h = b.lay_off(
            &a,
            &cross_line,
            sense * aux / fs,
            Label::NONE,
            Role::Force,
            N_AUX,
        )?;
        let p1 = b.parallel(&cross_line, &e, Label::NONE, Role::Auxiliary, N_AUX_PAR);
        let p2 = b.parallel(&along, &h, Label::NONE, Role::Auxiliary, N_AUX_PAR);
        let r_end = b.meet_point(&p1, &p2, Label::NONE, N_AUX_PAR)?;
        let r_part = b.line_through(&a, &r_end, Label::NONE, Role::Construction, N_AUX_R)?;
        partial.push((a, along, r_part));
    }
    let x = b
        .meet_point(&partial[0].2, &partial[1].2, Label::plain("X"), N_AUX_X)
        .map_err(|_| {
            ConstructionError::unsupported(
                "forces",
                "equal and opposite forces: a couple, no single resultant",
            )
        })?;
    // The resultant runs parallel to the forces (to K1's line of action), through X.
    let r_line = b.parallel(&partial[0].1, &x, Label::NONE, Role::Result, N_AUX_LINE);
    let (a1, a2) = (partial[0].0, partial[1].0);
    let join = b.line_through(&a1, &a2, Label::NONE, Role::Construction, N_AUX_FOOT)?;
    let c = b.meet_point(&r_line, &join, Label::plain("R"), N_AUX_FOOT)?;
    let a = b.measure(
        &a1,
        &c,
        &join,
        Scale {
            per_mm: 1.0 / k,
            unit: "m",
        },
        Label::quiet("a", 0),
        N_AUX_A,
    );
    let (m1, m2) = (v1.dot(&dir), v2.dot(&dir));
    let dist = ((k2.at[0] - k1.at[0]).powi(2) + (k2.at[1] - k1.at[1]).powi(2)).sqrt();
    b.check(
        &a,
        "distance a of the resultant (lever rule a : b = K2 : K1)",
        "m",
        "LH C.1: a = l·K2/(K1 + K2)",
        dist,
        || dist * m2 / (m1 + m2),
    );
    Ok(a.g)
}
