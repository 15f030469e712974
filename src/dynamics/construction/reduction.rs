//! The indicator card reduced (LH A, Abb. 42-45). The card as the indicator drew it is
//! divided by 11 ordinates into 10 equal strips, and each ordinate a is taken off with the
//! dividers; the new length l′ is divided the same way, and each a laid off again at a new
//! spring scale f′ (a′ = a·f′/f, Gl. 15) where the book redraws the card so, and at the
//! piston force's scale (a₁ = a·F_w/(f·k) = a·R, Gl. 18-19). The reduction factor R is read
//! off the drawing as a₁/a, side by side, and checked against F_w/(f·k).

use super::super::model::{self, Cylinder, IndicatorCard, Side};
use super::super::{rules, DynamicsDrawing, Engine};
use crate::fmt::num;
use crate::kernel::{Line, Point};
use crate::protocol::{
    note, Board, ConstructionError, Label, Note, ObjId, Part, Reading, Role, Scale, Topic, Trace,
    Weighted, H,
};

/// The strips the card and the new length are divided into (LH A: 11 ordinates).
const STRIPS: usize = 10;
/// Where the pressure scale stands left of the card (mm).
const SCALE_X: f64 = -8.0;
/// The least distance of two lettered marks of the pressure scale (mm).
const LETTERED_MM: f64 = 6.0;
/// From a panel's highest ordinate to its heading's top (mm): the heading's two rows of
/// 3.6 mm and 5 mm of room under them.
const HEADING_MM: f64 = 12.2;

const N_BASE: Note = note(
    "the absolute zero line over the diagram’s length",
    Some("absolute Nullinie"),
    "LH A, Abb. 42",
    Topic::Forces,
);
const N_ATM: Note = note(
    "the atmospheric line, 1 at above absolute zero",
    Some("atmosphärische Linie"),
    "LH A, Abb. 42",
    Topic::Forces,
);
const N_CARD: Note = note(
    "the indicator card as the indicator drew it",
    Some("Indikatordiagramm"),
    "LH A, Abb. 42",
    Topic::Forces,
);
const N_STRIPS: Note = note(
    "the length divided into 10 equal strips by 11 ordinates",
    Some("10 gleich breite Flächenstreifen"),
    "LH A, Abb. 42, 44",
    Topic::Forces,
);
const N_ORD: Note = note(
    "ordinate at a division point",
    Some("Ordinate"),
    "LH A, Abb. 42, 44",
    Topic::Forces,
);
const N_MEET: Note = note(
    "where the ordinate meets the card",
    Some("Ordinate a"),
    "LH A, Abb. 42",
    Topic::Forces,
);
const N_TAKE: Note = note(
    "ordinate a taken off with the dividers",
    Some("Ordinate a"),
    "LH Gl. 14",
    Topic::Forces,
);
const N_SCALE: Note = note(
    "the spring scale: f mm for 1 at (p = a/f)",
    Some("Federmaßstab"),
    "LH A, Gl. 14, Abb. 42",
    Topic::Forces,
);
const N_RESPRING: Note = note(
    "ordinate laid off at the new spring scale: a′ = a·f′/f",
    Some("Ordinate a′"),
    "LH Gl. 15, Abb. 44",
    Topic::Forces,
);
const N_FORCE: Note = note(
    "ordinate laid off at the force scale: a₁ = a·F_w/(f·k) = a·R",
    Some("reduzierte Ordinate a₁"),
    "LH Gl. 16-19, Abb. 45",
    Topic::Forces,
);
const N_READ: Note = note(
    "the redrawn ordinate measured",
    Some("Ordinate"),
    "LH Gl. 15, 17",
    Topic::Forces,
);
const N_R: Note = note(
    "the reduction factor read off as a₁/a at the card’s highest ordinate",
    Some("Reduktionsfaktor R"),
    "LH Gl. 18-19",
    Topic::Forces,
);
const N_R_TABLE: Note = note(
    "the reduction factors: R = F_w/(f·k), each side’s effective piston area F_w",
    Some("Reduktionsfaktor"),
    "LH Gl. 16-19",
    Topic::Forces,
);
const N_MEAN: Note = note(
    "the mean pressure from the card’s 11 ordinates: p_m = h_m/f",
    Some("mittlerer indizierter Druck"),
    "LH G, Gl. 53-58",
    Topic::Forces,
);
const N_POWER: Note = note(
    "indicated power from the two sides’ mean pressures",
    Some("indizierte Leistung"),
    "LH H, Gl. 65-68",
    Topic::Forces,
);
const N_REDUCED: Note = note(
    "the reduced diagram through the ordinates’ ends",
    Some("reduziertes Diagramm"),
    "LH A, Abb. 44, 45",
    Topic::Forces,
);
const N_HEAD: Note = note(
    "the panel’s heading: the cylinder, the length and the scale",
    Some("Überschrift"),
    "LH A, Abb. 42-45",
    Topic::Forces,
);

/// The four curves of a card: each side's working and back stroke.
#[derive(Clone, Copy)]
struct Curve {
    /// The crank side (Kurbelseite), else the cover side (Deckelseite).
    crank: bool,
    /// The working stroke, else the back stroke.
    working: bool,
}

const CURVES: [Curve; 4] = [
    Curve {
        crank: false,
        working: true,
    },
    Curve {
        crank: false,
        working: false,
    },
    Curve {
        crank: true,
        working: true,
    },
    Curve {
        crank: true,
        working: false,
    },
];

impl Curve {
    fn side<'a>(&self, c: &'a Cylinder) -> &'a Side {
        if self.crank {
            &c.crank
        } else {
            &c.cover
        }
    }

    /// The side's own stroke coordinate u at the fraction x of the card's length from the
    /// left dead centre: the crank side's stroke runs the other way.
    fn u(&self, x: f64) -> f64 {
        if self.crank {
            1.0 - x
        } else {
            x
        }
    }

    /// The absolute pressure (at) at the fraction x of the card's length.
    fn pressure(&self, c: &Cylinder, x: f64) -> f64 {
        let ind = &self.side(c).indicator;
        if self.working {
            ind.working(self.u(x))
        } else {
            ind.back(self.u(x))
        }
    }

    fn name(&self) -> &'static str {
        match (self.crank, self.working) {
            (false, true) => "cover side, working stroke",
            (false, false) => "cover side, back stroke",
            (true, true) => "crank side, working stroke",
            (true, false) => "crank side, back stroke",
        }
    }
}

/// A panel: its base line divided into strips and the ordinates at the division points.
struct Panel {
    base: H<Line>,
    feet: Vec<H<Point>>,
    ords: Vec<H<Line>>,
}

/// The base line of `length` mm from the part's origin, divided into strips, with its
/// ordinates.
fn panel(b: &mut Board, length: f64) -> Result<Panel, ConstructionError> {
    let origin = b.point(Point::new(0.0, 0.0), Role::Given, N_BASE);
    let end = b.point(Point::new(length, 0.0), Role::Given, N_BASE);
    let base = b.line_through(&origin, &end, Role::Given, N_BASE)?;
    let feet = b.divide_segment(&origin, &end, STRIPS, "", N_STRIPS);
    let ords = feet
        .iter()
        .map(|f| b.perpendicular(&base, f, Role::Construction, N_ORD))
        .collect();
    Ok(Panel { base, feet, ords })
}

/// The ordinates of a card's four curves taken off (mm), `[curve][ordinate]`.
type Taken = Vec<Vec<H<f64>>>;
/// The pressure scale's marks: the whole at each stands for, its height taken off (mm).
type Marks = Vec<(u32, H<f64>)>;
/// On a piston force's ordinate: its end and the force read there.
type ForceEnd = (H<Point>, H<f64>);

/// The reduction factors and mean pressures of the cards, one row a side, with the objects
/// they were read from.
#[derive(Default)]
pub(super) struct FactorRows {
    rows: Vec<Vec<String>>,
    ids: Vec<ObjId>,
}

/// Draws the reduction of each cylinder's card in a row of its own (the card, the card
/// redrawn at its new spring scale where one is given, and the piston forces), and under
/// them the table of reduction factors and mean pressures; rows `0 ..= cylinders`.
pub(super) fn reduce_all(
    b: &mut Board,
    e: &Engine,
    dr: &DynamicsDrawing,
) -> Result<(), ConstructionError> {
    let mut table = FactorRows::default();
    for c in 0..e.cylinders.len() {
        reduce(b, e, dr, c, &mut table)?;
    }
    b.set_part(Part::packed(e.cylinders.len() as u16, 0));
    let head = [
        "cylinder, side",
        "piston area [cm²]",
        "R",
        "p_m trapezoid",
        "p_m Simpson",
        "p_m exact [at]",
    ];
    let mut rows = vec![head.map(String::from).to_vec()];
    rows.append(&mut table.rows);
    b.table(Point::new(0.0, 0.0), rows, &table.ids, N_R_TABLE);
    Ok(())
}

/// Draws the reduction of cylinder `c`'s card in row `c` of the sheet, its factors and
/// mean pressures added to `table`.
fn reduce(
    b: &mut Board,
    e: &Engine,
    dr: &DynamicsDrawing,
    c: usize,
    table: &mut FactorRows,
) -> Result<(), ConstructionError> {
    let cyl = &e.cylinders[c];
    let Some(card) = cyl.card else {
        return Ok(());
    };
    let row = c as u16;
    let new_length = 2.0 * e.kinematics.r / dr.length_scale;
    let top = peak(cyl);
    b.set_part(Part::packed(row, 0));
    b.clear_context();
    let (taken, ticks) = the_card(b, cyl, &card, top)?;
    let means = [false, true].map(|crank| mean_pressures(b, cyl, (&card, top), &taken, crank));
    indicated_power(b, e, cyl, &means);
    let mut col = 1;
    if let Some(f_new) = card.respring_mm_per_at {
        b.set_part(Part::packed(row, col));
        respring(b, cyl, (&card, f_new, new_length), (&taken, &ticks), top)?;
        col += 1;
    }
    b.set_part(Part::packed(row, col));
    let factors = piston_forces(b, cyl, (&card, dr.force_scale, new_length), &taken, top)?;
    for (crank, f_w, r) in factors {
        let side = if crank {
            "crank side (K)"
        } else {
            "cover side (D)"
        };
        let (trap, simp, exact, _) = means[usize::from(crank)];
        let cells = [
            num(f_w, 1),
            num(r.g, 3),
            num(trap.g, 3),
            num(simp.g, 3),
            num(exact, 3),
        ];
        let name = format!("{}, {side}", cyl.name);
        table
            .rows
            .push(std::iter::once(name).chain(cells).collect());
        table.ids.extend([r.id, trap.id, simp.id]);
    }
    b.clear_context();
    Ok(())
}

/// The highest absolute pressure on the card's ordinates and corners (at).
fn peak(cyl: &Cylinder) -> f64 {
    let mut xs: Vec<f64> = (0..=STRIPS).map(|i| i as f64 / STRIPS as f64).collect();
    for side in [&cyl.cover, &cyl.crank] {
        xs.extend(side.indicator.corners().iter().map(|u| u.clamp(0.0, 1.0)));
    }
    CURVES
        .iter()
        .flat_map(|cv| xs.iter().map(move |&x| (cv, x)))
        .map(|(cv, x)| cv.pressure(cyl, x).max(cv.pressure(cyl, 1.0 - x)))
        .fold(0.0, f64::max)
}

/// The card (Abb. 42): its base, the atmospheric line, its four curves, its pressure scale
/// and its 11 ordinates taken off on each curve. Returns the ordinates and the scale's marks
/// (the whole at they stand for, and their height taken off).
fn the_card(
    b: &mut Board,
    cyl: &Cylinder,
    card: &IndicatorCard,
    top: f64,
) -> Result<(Taken, Marks), ConstructionError> {
    let (l, f) = (card.length_mm, card.spring_mm_per_at);
    heading(
        b,
        top * f,
        [
            format!("{}: the card as taken", cyl.name),
            format!("l = {} mm, f = {} mm = 1 at abs.", num(l, 3), num(f, 3)),
        ],
    );
    let p = panel(b, l)?;
    atmospheric_line(b, l, f);
    draw_card(b, cyl, card);
    let ticks = scale_marks(b, &p, f, top)?;
    let mut taken = Vec::with_capacity(CURVES.len());
    for cv in CURVES {
        let mut row = Vec::with_capacity(STRIPS + 1);
        for i in 0..=STRIPS {
            let x = i as f64 / STRIPS as f64;
            let a = f * cv.pressure(cyl, x);
            let pt = b.lay_off(&p.feet[i], &p.ords[i], a, Role::Construction, N_MEET)?;
            let mm = Scale::new(1.0, "mm");
            row.push(b.measure(&p.feet[i], &pt, &p.ords[i], mm, Label::NONE, N_TAKE));
        }
        taken.push(row);
    }
    Ok((taken, ticks))
}

/// The atmospheric line 1 at over the absolute zero line, at the spring scale `f`.
fn atmospheric_line(b: &mut Board, l: f64, f: f64) {
    let a = b.point(Point::new(0.0, f), Role::Auxiliary, N_ATM);
    let z = b.point(Point::new(l, f), Role::Auxiliary, N_ATM);
    b.segment(&a, &z, Role::Auxiliary.named("atm"), N_ATM);
}

/// The card's two diagrams, each closed: the working stroke out and the back stroke home,
/// through its corners and 48 strips between.
fn draw_card(b: &mut Board, cyl: &Cylinder, card: &IndicatorCard) {
    if !b.is_recording() {
        return;
    }
    let (l, f) = (card.length_mm, card.spring_mm_per_at);
    for (crank, name) in [(false, "D"), (true, "K")] {
        let side = if crank { &cyl.crank } else { &cyl.cover };
        let mut xs: Vec<f64> = (0..=48).map(|i| f64::from(i) / 48.0).collect();
        xs.extend(
            side.indicator
                .corners()
                .iter()
                .map(|u| if crank { 1.0 - u } else { *u })
                .filter(|x| (0.0..=1.0).contains(x)),
        );
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        let working = Curve {
            crank,
            working: true,
        };
        let back = Curve {
            crank,
            working: false,
        };
        let mut pts: Vec<Point> = xs
            .iter()
            .map(|&x| Point::new(x * l, f * working.pressure(cyl, x)))
            .collect();
        pts.extend(
            xs.iter()
                .rev()
                .map(|&x| Point::new(x * l, f * back.pressure(cyl, x))),
        );
        pts.push(pts[0]);
        b.given_curve(&pts, Trace::Polygon, Role::Given.named(name), N_CARD);
    }
}

/// The pressure scale's marks: every whole at from 0 to the card's peak where marks a whole
/// at apart stand clear, lettered `step` apart where the letters do (at least
/// [`LETTERED_MM`]): `(at, label)`.
fn scale_steps(f: f64, top: f64) -> Vec<(u32, Label)> {
    let step = [1u32, 2, 5, 10, 20, 50, 100]
        .into_iter()
        .find(|&s| f64::from(s) * f >= LETTERED_MM)
        .unwrap_or(100);
    let each = if f >= 1.0 { 1 } else { step };
    let last = top.ceil().min(1000.0) as u32;
    (0..=last)
        .filter(|k| k % each == 0)
        .map(|k| {
            let label = if k % step == 0 {
                Label::named(k.to_string())
            } else {
                Label::NONE
            };
            (k, label)
        })
        .collect()
}

/// The pressure scale left of the card: a mark every at, lettered where they stand clear,
/// each mark's height taken off for the card redrawn at its new spring scale.
fn scale_marks(b: &mut Board, p: &Panel, f: f64, top: f64) -> Result<Marks, ConstructionError> {
    let foot = b.point(Point::new(SCALE_X, 0.0), Role::Construction, N_SCALE);
    let rule = b.perpendicular(&p.base, &foot, Role::Construction, N_SCALE);
    let mut out = Vec::new();
    for (k, label) in scale_steps(f, top) {
        let mark = b.lay_off(
            &foot,
            &rule,
            f * f64::from(k),
            Role::Axis.labelled(label),
            N_SCALE,
        )?;
        let mm = Scale::new(1.0, "mm");
        out.push((k, b.measure(&foot, &mark, &rule, mm, Label::NONE, N_TAKE)));
    }
    Ok(out)
}

/// The card redrawn over the new length at the spring scale f′ (Abb. 44), its pressure
/// scale with it: every ordinate and mark a′ = a·f′/f, checked.
fn respring(
    b: &mut Board,
    cyl: &Cylinder,
    (card, f_new, length): (&IndicatorCard, f64, f64),
    (taken, ticks): (&Taken, &[(u32, H<f64>)]),
    top: f64,
) -> Result<(), ConstructionError> {
    let f = card.spring_mm_per_at;
    heading(
        b,
        top * f_new,
        [
            format!("{}: the new length", cyl.name),
            format!(
                "l′ = {} mm, f′ = {} mm = 1 at abs.",
                num(length, 3),
                num(f_new, 3)
            ),
        ],
    );
    let p = panel(b, length)?;
    atmospheric_line(b, length, f_new);
    let per_mm = f / f_new;
    let foot = b.point(Point::new(SCALE_X, 0.0), Role::Construction, N_SCALE);
    let rule = b.perpendicular(&p.base, &foot, Role::Construction, N_SCALE);
    let mut labels = scale_steps(f_new, top);
    let name = &cyl.name;
    for (k, a) in ticks {
        let label = match labels.iter().position(|s| s.0 == *k) {
            Some(j) => std::mem::replace(&mut labels[j].1, Label::NONE),
            None => Label::NONE,
        };
        b.set_context(|| format!("{name}, {k} at"));
        let at = b.transfer(
            &foot,
            &rule,
            Reading { value: a, per_mm },
            Role::Axis.labelled(label),
            N_RESPRING,
        )?;
        check_respring(b, (&foot, &at, &rule), (f, f_new), f64::from(*k), top);
    }
    let mut ends = Vec::with_capacity(CURVES.len());
    for (cv, row) in CURVES.iter().zip(taken) {
        let mut pts = Vec::with_capacity(row.len());
        for (i, a) in row.iter().enumerate() {
            let x = i as f64 / STRIPS as f64;
            let (foot, ord) = (&p.feet[i], &p.ords[i]);
            let pt = lay_again(
                b,
                &p,
                (name, cv, i),
                Reading { value: a, per_mm },
                N_RESPRING,
            )?;
            check_respring(b, (foot, &pt, ord), (f, f_new), cv.pressure(cyl, x), top);
            pts.push(pt);
        }
        ends.push(pts);
    }
    b.clear_context();
    reduced_curves(b, &ends, Role::Result);
    Ok(())
}

/// The ordinate `i` of curve `cv` taken off the card laid off again on the panel `p`'s
/// ordinate `i` at the reading's scale, the check context naming it ("right, cover side,
/// working stroke, a₃").
fn lay_again(
    b: &mut Board,
    p: &Panel,
    (name, cv, i): (&str, &Curve, usize),
    reading: Reading<'_>,
    note: Note,
) -> Result<H<Point>, ConstructionError> {
    b.set_context(|| format!("{name}, {}, a{}", cv.name(), subscript(i)));
    b.transfer(&p.feet[i], &p.ords[i], reading, Role::Construction, note)
}

/// The redrawn ordinate from `foot` to `pt` measured and held to a′ = a·f′/f, a = f·p.
fn check_respring(
    b: &mut Board,
    (foot, pt, ord): (&H<Point>, &H<Point>, &H<Line>),
    (f, f_new): (f64, f64),
    p: f64,
    top: f64,
) {
    let mm = Scale::new(1.0, "mm");
    let a_new = b.measure(foot, pt, ord, mm, Label::NONE, N_READ);
    b.check(
        &a_new,
        "ordinate a′ = a·f′/f",
        "mm",
        "LH Gl. 15",
        top * f_new,
        || super::super::model::respring(f * p, f, f_new),
    );
}

/// The piston forces over the new length (Abb. 45): each ordinate laid off at the side's
/// reduction factor, read at the force scale and held to F_w·p; R read off as a₁/a.
fn piston_forces(
    b: &mut Board,
    cyl: &Cylinder,
    (card, k, length): (&IndicatorCard, f64, f64),
    taken: &Taken,
    top: f64,
) -> Result<Vec<Factor>, ConstructionError> {
    let f = card.spring_mm_per_at;
    let area = area_of(cyl);
    heading(
        b,
        top * area / k,
        [
            format!("{}: the piston forces", cyl.name),
            format!("l′ = {} mm, 1 mm = {} kg", num(length, 3), num(k, 4)),
        ],
    );
    let p = panel(b, length)?;
    let name = &cyl.name;
    let mut ends = Vec::with_capacity(CURVES.len());
    let mut factors = Vec::with_capacity(2);
    for (cv, row) in CURVES.iter().zip(taken) {
        let f_w = cv.side(cyl).area_cm2;
        let per_mm = f * k / f_w;
        let mut pts = Vec::with_capacity(row.len());
        for (i, a) in row.iter().enumerate() {
            let x = i as f64 / STRIPS as f64;
            let (foot, ord) = (&p.feet[i], &p.ords[i]);
            let pt = lay_again(b, &p, (name, cv, i), Reading { value: a, per_mm }, N_FORCE)?;
            let force = b.measure(foot, &pt, ord, Scale::kg(k), Label::NONE, N_READ);
            b.check(
                &force,
                "piston force P = F_w·p",
                "kg",
                "LH Gl. 16-18",
                top * area,
                || f_w * cv.pressure(cyl, x),
            );
            pts.push((pt, force));
        }
        if cv.working {
            if let Some(r) = read_factor(b, cyl, cv, (row, &pts), (f, k)) {
                factors.push((cv.crank, f_w, r));
            }
        }
        ends.push(pts.into_iter().map(|(pt, _)| pt).collect());
    }
    b.clear_context();
    reduced_curves(b, &ends, Role::Result);
    Ok(factors)
}

/// The larger of a cylinder's two effective piston areas (cm²): the piston-force panel's
/// height per at.
fn area_of(cyl: &Cylinder) -> f64 {
    cyl.cover.area_cm2.max(cyl.crank.area_cm2)
}

/// A side's reduction factor: the crank side or not, its piston area F_w (cm²), R read off.
type Factor = (bool, f64, H<f64>);

/// A side's mean pressure by the trapezoid rule and by Simpson's rule over the card's
/// ordinates, exactly, and by Simpson's rule over the exact pressures (at).
type Means = (H<f64>, H<f64>, f64, f64);

/// The side's mean pressure p_m = h_m/f (LH Gl. 53) from the widths of its card at the 11
/// ordinates, by the trapezoid rule (Gl. 55) and by Simpson's rule (Gl. 58), each held to
/// the same rule over the exact pressures at the same ordinates.
fn mean_pressures(
    b: &mut Board,
    cyl: &Cylinder,
    (card, reference): (&IndicatorCard, f64),
    taken: &Taken,
    crank: bool,
) -> Means {
    let f = card.spring_mm_per_at;
    let first = 2 * usize::from(crank);
    let (work, back) = (&taken[first], &taken[first + 1]);
    let widths: Vec<f64> = work
        .iter()
        .zip(back)
        .map(|(w, k)| (w.g - k.g) / f)
        .collect();
    let (cw, cb) = (CURVES[first], CURVES[first + 1]);
    let exact: Vec<f64> = (0..=STRIPS)
        .map(|i| i as f64 / STRIPS as f64)
        .map(|x| cw.pressure(cyl, x) - cb.pressure(cyl, x))
        .collect();
    let inputs: Vec<_> = work.iter().chain(back).map(|h| h.id).collect();
    let simpson_exact = rules::simpson(&exact).unwrap_or(rules::trapezoid(&exact));
    let side = if crank { "crank side" } else { "cover side" };
    let name = &cyl.name;
    b.set_context(|| format!("{name}, {side}"));
    let trapezoid = rules::trapezoid(&widths);
    let weighted = Weighted {
        inputs: &inputs,
        weight: 1.0 / (STRIPS as f64 * f),
    };
    let trap = b.reckon(trapezoid, "at", Label::NONE, weighted, N_MEAN);
    b.check(
        &trap,
        "p_m by the trapezoid rule",
        "at",
        "LH Gl. 53, 55",
        reference,
        || rules::trapezoid(&exact),
    );
    // Ten strips: Simpson's rule applies (an even number), the 3/8 rule does not.
    let simpson = rules::simpson(&widths).unwrap_or(trapezoid);
    let weighted = Weighted {
        inputs: &inputs,
        weight: 4.0 / (3.0 * STRIPS as f64 * f),
    };
    let simp = b.reckon(simpson, "at", Label::NONE, weighted, N_MEAN);
    b.check(
        &simp,
        "p_m by Simpson’s rule",
        "at",
        "LH Gl. 53, 58",
        reference,
        || simpson_exact,
    );
    b.clear_context();
    let ind = if crank { &cyl.crank } else { &cyl.cover };
    (trap, simp, ind.indicator.mean_pressure(), simpson_exact)
}

/// The cylinder's indicated power from its two sides' mean pressures by Simpson's rule,
/// N_i = (F_D p_m^D + F_K p_m^K)·s·n/(75·60) (LH H, Gl. 65-68: "608 PS" for the
/// locomotive), held to the same over the exact pressures.
fn indicated_power(b: &mut Board, e: &Engine, cyl: &Cylinder, means: &[Means; 2]) {
    let (s, n) = e.stroke_and_rpm();
    let areas = [cyl.cover.area_cm2, cyl.crank.area_cm2];
    let of = |p: [f64; 2]| model::indicated_power([(areas[0], p[0]), (areas[1], p[1])], s, n);
    let (value, exact) = (
        of([means[0].1.g, means[1].1.g]),
        of([means[0].3, means[1].3]),
    );
    // One at of either side's p_m moves N_i by at most the larger area's share.
    let weight = of([1.0, 0.0]).max(of([0.0, 1.0]));
    if !(value.is_finite() && exact.is_finite() && weight.is_finite()) {
        // A speed or an area that a number cannot carry into the power: no row.
        return;
    }
    let name = &cyl.name;
    b.set_context(|| name.clone());
    let inputs = [means[0].1.id, means[1].1.id];
    let power = b.reckon(
        value,
        "PS",
        Label::NONE,
        Weighted {
            inputs: &inputs,
            weight,
        },
        N_POWER,
    );
    b.check(
        &power,
        "indicated power N_i from the sides’ p_m (Simpson)",
        "PS",
        "LH H, Gl. 65-68",
        exact,
        || exact,
    );
    b.clear_context();
}

/// The reduction factor of a side read off its working stroke's highest ordinate: R = a₁/a
/// with a₁ = P/k, held to F_w/(f·k) (LH Gl. 19).
fn read_factor(
    b: &mut Board,
    cyl: &Cylinder,
    cv: &Curve,
    (taken, forces): (&[H<f64>], &[ForceEnd]),
    (f, k): (f64, f64),
) -> Option<H<f64>> {
    let i = (0..taken.len()).max_by(|&i, &j| taken[i].g.total_cmp(&taken[j].g))?;
    let (a, force) = (taken[i], forces[i].1);
    if a.g <= 0.0 {
        return None;
    }
    let r = force.g / (k * a.g);
    let weight = (1.0 / (k * a.g)).max(r / a.g);
    let label = if cv.crank { "R_K" } else { "R_D" };
    let inputs = [force.id, a.id];
    let weighted = Weighted {
        inputs: &inputs,
        weight,
    };
    let side = if cv.crank { "crank side" } else { "cover side" };
    let name = &cyl.name;
    b.set_context(|| format!("{name}, {side}"));
    let value = b.reckon(r, "", Label::named(label), weighted, N_R);
    let f_w = cv.side(cyl).area_cm2;
    b.check(
        &value,
        "reduction factor R = a₁/a",
        "",
        "LH Gl. 18-19: R = F_w/(f·k)",
        r,
        || super::super::model::reduction_factor(f_w, f, k),
    );
    Some(value)
}

/// Each side's reduced diagram, closed: the working stroke's ordinates out, the back
/// stroke's home.
fn reduced_curves(b: &mut Board, ends: &[Vec<H<Point>>], role: Role) {
    for (side, name) in [(0, "D"), (2, "K")] {
        let mut pts = ends[side].clone();
        pts.extend(ends[side + 1].iter().rev().copied());
        if let Some(&first) = pts.first() {
            pts.push(first);
        }
        b.curve(&pts, Trace::Polygon, role.named(name), N_REDUCED);
    }
}

/// A panel's heading over its highest ordinate `top` (mm).
fn heading(b: &mut Board, top: f64, [title, scales]: [String; 2]) {
    b.table(
        Point::new(0.0, top + HEADING_MM),
        vec![vec![title], vec![scales]],
        &[],
        N_HEAD,
    );
}

/// The ordinate's index as the books write it (a₀ … a₁₀).
fn subscript(i: usize) -> String {
    i.to_string()
        .chars()
        .filter_map(crate::fmt::subscript_of)
        .collect()
}
