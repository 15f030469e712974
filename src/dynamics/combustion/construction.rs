//! The construction of a combustion engine's forces (KG Abb. 1058, 1060): per shaft angle the
//! gas force laid off over the developed cycle, the inertia laid against it, the tangential
//! force by the slider-crank's polar construction ([`crate::crank`]), and the turning-force
//! diagram of all cylinders with its mean.

use super::{turning_force, GasCylinder};
use crate::crank::{self, Angles, CrankDrive, Drawing, PistonForce, Request};
use crate::dynamics::model::Kinematics;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{
    Board, ConstructionError, Label, Note, Part, Reading, Role, Scale, Topic, Trace, Weighted, H,
};

fn n(caption: &'static str, term: Option<&'static str>) -> Note {
    crate::protocol::note(
        caption,
        term,
        "KG XIV B.4, Abb. 1056-1060",
        Topic::Custom("combustion engine"),
    )
}

/// A combustion engine: its crank and its cylinders on one shaft.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct GasEngine {
    /// Crank radius, rod ratio, crank-pin speed.
    pub kinematics: Kinematics,
    /// The cylinders, firing evenly over the cycle.
    pub cylinders: Vec<GasCylinder>,
    /// The cycle (720° or 360°).
    pub cycle_deg: f64,
}

/// Scales: machine mm per sheet mm, kg per mm, sheet mm per degree of the developed cycle.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct GasDrawing {
    /// Length scale 1 : n (the crank figures).
    pub length_scale: f64,
    /// kg per mm.
    pub force_scale: f64,
    /// Sheet mm per degree of shaft angle in the developed diagrams.
    pub mm_per_deg: f64,
}

/// One shaft angle's values read off the construction.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct GasRow {
    /// Shaft angle (degrees over the cycle).
    pub shaft: f64,
    /// Per cylinder: gas force, resulting force, tangential force (kg).
    pub cylinders: Vec<[f64; 3]>,
    /// The turning force of all cylinders (kg).
    pub turning: f64,
}

/// The results.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct GasResults {
    /// Per shaft angle.
    pub rows: Vec<GasRow>,
    /// The mean of the drawn turning-force ordinates (kg).
    pub t_m: f64,
    /// The exact mean turning force over the cycle (kg).
    pub t_m_exact: f64,
}

/// Constructs the engine's forces at `divisions` equal shaft angles over the cycle: each
/// cylinder's piston-force diagram, its tangential force by the polar construction, and the
/// turning-force diagram with its mean.
///
/// # Errors
/// A kernel refusal (a validated scene has none).
pub fn construct(
    b: &mut Board,
    e: &GasEngine,
    dr: &GasDrawing,
    divisions: usize,
) -> Result<GasResults, ConstructionError> {
    let shafts: Vec<f64> = (0..divisions)
        .map(|k| e.cycle_deg * k as f64 / divisions as f64)
        .collect();
    let mut rows: Vec<GasRow> = shafts
        .iter()
        .map(|&shaft| GasRow {
            shaft,
            cylinders: Vec::new(),
            turning: 0.0,
        })
        .collect();
    let mut depth = 0.0;
    // Per cylinder, its tangential force at every shaft angle as read off its polar figure.
    let mut reads: Vec<Vec<H<f64>>> = Vec::with_capacity(e.cylinders.len());
    // Each cylinder's row: its gas pressure diagram, its piston-force diagram over the
    // developed cycle, and beside them its crank figure with the polar force plan; the
    // turning-force diagram under the force diagrams, the table under that. One cylinder's
    // crank figure shares no row with another's: it goes where the sheet has room (a free
    // part), as the table does.
    for c in 0..e.cylinders.len() {
        let forces = force_diagram(b, e, dr, (c, &shafts), &mut depth)?;
        b.set_part(match e.cylinders.len() {
            1 => Part::free(c as u16, 2),
            _ => Part::at(c as u16, 2),
        });
        let t = tangential(b, e, dr, (c, &shafts, &forces), depth)?;
        for (row, (f, t)) in rows.iter_mut().zip(forces.iter().zip(&t)) {
            row.cylinders.push([f.0, f.1, t.g]);
            row.turning += t.g;
        }
        reads.push(t);
    }
    let t_m_exact = super::mean_turning_force(&e.kinematics, &e.cylinders, e.cycle_deg);
    b.set_part(Part::at(e.cylinders.len() as u16, 1));
    let t_m = turning_diagram(b, e, dr, (&rows, &reads, t_m_exact), depth)?;
    b.set_part(Part::default());
    Ok(GasResults {
        rows,
        t_m,
        t_m_exact,
    })
}

/// A base line over the developed cycle at `y`, from x = 0 to the right, its start lettered
/// with `name` (the cylinder's, where the engine has several) and the shaft angle written
/// under it every 180°.
fn base(
    b: &mut Board,
    (y, mm_per_deg, cycle_deg): (f64, f64, f64),
    name: Label,
    note: Note,
) -> Result<(H<Point>, H<Line>), ConstructionError> {
    let start = b.point(Point::new(0.0, y), Role::Axis.labelled(name), note.clone());
    let marks = (mm_per_deg, 180.0, cycle_deg);
    crate::dynamics::angle_marks(b, start.g, marks, note.clone());
    let line = b.line_dir(&start, Vector::new(1.0, 0.0), Role::Axis, note)?;
    Ok((start, line))
}

/// The foot of the ordinate at `shaft` on a base line, and the ordinate.
fn ordinate(
    b: &mut Board,
    (start, line): (&H<Point>, &H<Line>),
    at_mm: f64,
) -> Result<(H<Point>, H<Line>), ConstructionError> {
    let foot = b.lay_off(
        start,
        line,
        at_mm,
        Role::Construction,
        n(
            "the shaft angle on the developed cycle",
            Some("Kurbelwinkel auf dem abgewickelten Arbeitsspiel"),
        ),
    )?;
    let up = b.perpendicular(
        line,
        &foot,
        Role::Construction,
        n("ordinate", Some("Ordinate")),
    );
    Ok((foot, up))
}

/// Cylinder c's piston-force diagram over the developed cycle (KG Abb. 1058): the gas force
/// (a-a) and, with the masses, the resulting force (b-b), each ordinate checked. Returns
/// (gas, resulting) per shaft angle; `depth` grows by the diagram's height.
fn force_diagram(
    b: &mut Board,
    e: &GasEngine,
    dr: &GasDrawing,
    (c, shafts): (usize, &[f64]),
    depth: &mut f64,
) -> Result<Vec<(f64, f64)>, ConstructionError> {
    let cyl = &e.cylinders[c];
    let peak = cyl.area_cm2 * (cyl.cycle.peak_at - super::ATMOSPHERE_AT);
    *depth += peak / dr.force_scale + 15.0;
    let name = cyl.name.clone();
    b.set_part(Part::at(c as u16, 0));
    let scales = (-*depth, dr.length_scale, dr.force_scale);
    let pushes = super::indicator::diagram(b, e, (c, shafts), scales)?;
    b.set_part(Part::at(c as u16, 1));
    let lettered = match e.cylinders.len() {
        1 => Label::NONE,
        _ => Label::named(format!("cylinder {name}")),
    };
    let axis = base(
        b,
        (-*depth, dr.mm_per_deg, e.cycle_deg),
        lettered,
        n(
            "the piston-force diagram over the cycle",
            Some("Kolbenüberdrucklinie"),
        ),
    )?;
    let (mut gas_pts, mut res_pts, mut out) = (Vec::new(), Vec::new(), Vec::new());
    for (&shaft, push) in shafts.iter().zip(&pushes) {
        b.set_context(|| format!("{name}, shaft {}°", crate::fmt::num(shaft, 3)));
        let (tip, rtip, pv, rv) = force_ray(b, e, dr, (c, shaft, push), (&axis, peak))?;
        gas_pts.push(tip);
        res_pts.push(rtip);
        out.push((pv, rv));
    }
    b.clear_context();
    b.curve(
        &gas_pts,
        Trace::Polygon,
        Role::Result.named("a"),
        n(
            "the gas force over the cycle (a-a)",
            Some("Gasdrucklinie (a-a)"),
        ),
    );
    if cyl.mass > 0.0 {
        b.curve(
            &res_pts,
            Trace::Polygon,
            Role::Result.named("b"),
            n(
                "the resulting force over the cycle (b-b)",
                Some("resultierende Kolbenkraftlinie (b-b)"),
            ),
        );
    }
    Ok(out)
}

/// One ordinate of cylinder c's piston-force diagram: the gas force laid off and read, the
/// inertia laid against it and the resulting force read, each checked. The two tips and the
/// two values.
fn force_ray(
    b: &mut Board,
    e: &GasEngine,
    dr: &GasDrawing,
    (c, shaft, push): (usize, f64, &H<f64>),
    (axis, peak): (&(H<Point>, H<Line>), f64),
) -> Result<(H<Point>, H<Point>, f64, f64), ConstructionError> {
    let cyl = &e.cylinders[c];
    let k = &e.kinematics;
    let fs = Scale::new(dr.force_scale, "kg");
    let (foot, up) = ordinate(b, (&axis.0, &axis.1), shaft * dr.mm_per_deg)?;
    let p = cyl.gas_force(k, shaft);
    // The base runs to +x: the ordinate's direction points up the sheet. The indicator's
    // ordinate is carried over with the dividers, turned down where the gas pushes against
    // the piston's motion (the return strokes).
    let (stroke, _) = crate::crank::closed_form::book_angle(cyl.angles(shaft).1);
    let reading = Reading {
        value: push,
        per_mm: stroke.sign() * dr.force_scale,
    };
    let tip = b.transfer(
        &foot,
        &up,
        reading,
        Role::Force,
        n(
            "the gas force carried over from the pressure diagram",
            Some("Kolbenkraft"),
        ),
    )?;
    let pv = b.measure(
        &foot,
        &tip,
        &up,
        fs,
        Label::NONE,
        n("the gas force P read off", Some("Gasdruck abgegriffen")),
    );
    b.check(
        &pv,
        "gas force P",
        "kg",
        "KG Abb. 1058 a-a: (p − 1 at)·F",
        peak,
        || p,
    );
    let mb = k.inertia(cyl.mass, cyl.angles(shaft).1);
    let rtip = b.lay_off(
        &tip,
        &up,
        -mb / dr.force_scale,
        Role::Construction,
        n("the inertia M·b laid against it", Some("Massendruck")),
    )?;
    let rv = b.measure(
        &foot,
        &rtip,
        &up,
        fs,
        Label::NONE,
        n(
            "the resulting force P − M·b read off",
            Some("resultierende Kolbenkraft abgegriffen"),
        ),
    );
    b.check(
        &rv,
        "resulting force P − M·b",
        "kg",
        "KG Abb. 1058 b-b",
        peak,
        || cyl.resulting(k, shaft),
    );
    Ok((tip, rtip, pv.g, rv.g))
}

/// Cylinder c's tangential force at every shaft angle by the slider-crank's polar
/// construction from its resulting forces, drawn beside the diagrams: as read off.
fn tangential(
    b: &mut Board,
    e: &GasEngine,
    dr: &GasDrawing,
    (c, shafts, forces): (usize, &[f64], &[(f64, f64)]),
    depth: f64,
) -> Result<Vec<H<f64>>, ConstructionError> {
    let cyl = &e.cylinders[c];
    let k = &e.kinematics;
    let drive = CrankDrive {
        crank_radius: k.r,
        rod_length: k.rod().unwrap_or(0.0),
        finite_rod: k.lambda > 0.0,
        crank_pin_speed: k.v,
        piston_force: PistonForce::PerAngle(forces.iter().map(|f| f.1).collect()),
    };
    let thetas: Vec<f64> = shafts.iter().map(|&s| cyl.angles(s).1).collect();
    let drawing = Drawing {
        length_scale: dr.length_scale,
        force_scale: dr.force_scale,
        velocity_scale: 1.0,
        acceleration_scale: 1.0,
    };
    let request = Request {
        tangential_force: true,
        ..Request::default()
    };
    let reach = (k.r + k.rod().unwrap_or(0.0)) / dr.length_scale;
    let origin = Point::new(e.cycle_deg * dr.mm_per_deg + 2.0 * reach + 20.0, -depth);
    let res = crank::construct_at(
        b,
        &drive,
        &drawing,
        &Angles::Degrees(thetas),
        &request,
        origin,
    )?;
    Ok(res
        .rows
        .iter()
        .map(|r| r.tangential_read.unwrap_or(H::NONE_ZERO))
        .collect())
}

/// The turning-force diagram over the cycle: every cylinder's tangential force added on each
/// ordinate, the curve, and the mean of the ordinates (the trapezoid rule on a periodic
/// curve), checked against the rule applied to the exact turning force; the exact mean and
/// the mean from the indicated work written beside it.
fn turning_diagram(
    b: &mut Board,
    e: &GasEngine,
    dr: &GasDrawing,
    (rows, reads, exact): (&[GasRow], &[Vec<H<f64>>], f64),
    depth: f64,
) -> Result<f64, ConstructionError> {
    let k = &e.kinematics;
    let top = rows.iter().map(|r| r.turning.abs()).fold(0.0, f64::max);
    let y = -depth - top / dr.force_scale - 30.0;
    let axis = base(
        b,
        (y, dr.mm_per_deg, e.cycle_deg),
        Label::NONE,
        n(
            "the turning-force diagram over the cycle",
            Some("Drehkraftlinie"),
        ),
    )?;
    let fs = Scale::new(dr.force_scale, "kg");
    let (mut pts, mut ids) = (Vec::new(), Vec::new());
    for (i, r) in rows.iter().enumerate() {
        b.set_context(|| format!("shaft {}°", crate::fmt::num(r.shaft, 3)));
        let (foot, up) = ordinate(b, (&axis.0, &axis.1), r.shaft * dr.mm_per_deg)?;
        let tip = add_up(b, dr, (&foot, &up), reads.iter().map(|t| &t[i]))?;
        let t = b.measure(
            &foot,
            &tip,
            &up,
            fs,
            Label::NONE,
            n(
                "the turning force read off",
                Some("Tangentialdruck abgegriffen"),
            ),
        );
        b.check(
            &t,
            "turning force T",
            "kg",
            "Σ P·sin(φ ± ψ)/cos ψ over the cylinders",
            top,
            || turning_force(k, &e.cylinders, r.shaft),
        );
        pts.push(tip);
        ids.push(t.id);
    }
    b.clear_context();
    b.curve(
        &pts,
        Trace::Polygon,
        Role::Result.named("T"),
        n("the turning force over the cycle", Some("Drehkraftlinie")),
    );
    let mean = mean_of_ordinates(b, e, rows, (&ids, top));
    let row = b.part().row;
    b.set_part(Part::free(row + 1, 1));
    mean_table(b, e, (mean, exact, &ids), y - top / dr.force_scale - 15.0);
    Ok(mean)
}

/// The cylinders' tangential forces carried from their polar figures one on top of the
/// other with the dividers on the ordinate at `foot` (so that the sum's bound follows each
/// reading): one cylinder's as a force, several thin and their sum as the force. Returns
/// the sum's end.
fn add_up<'a>(
    b: &mut Board,
    dr: &GasDrawing,
    (foot, up): (&H<Point>, &H<Line>),
    reads: impl ExactSizeIterator<Item = &'a H<f64>>,
) -> Result<H<Point>, ConstructionError> {
    let note = n(
        "the cylinders’ tangential forces added on the ordinate",
        Some("Drehkraft"),
    );
    let one = reads.len() == 1;
    let piece = if one { Role::Force } else { Role::Construction };
    let mut tip = *foot;
    for t in reads {
        let reading = Reading {
            value: t,
            per_mm: dr.force_scale,
        };
        tip = b.transfer(&tip, up, reading, piece, note.clone())?;
    }
    if !one {
        b.segment(foot, &tip, Role::Force, note);
    }
    Ok(tip)
}

/// The mean of the turning force's ordinates (the trapezoid rule on the periodic curve),
/// checked against the same rule on the exact turning force.
fn mean_of_ordinates(
    b: &mut Board,
    e: &GasEngine,
    rows: &[GasRow],
    (ids, top): (&[crate::protocol::ObjId], f64),
) -> f64 {
    let k = &e.kinematics;
    let count = rows.len() as f64;
    let mean = rows.iter().map(|r| r.turning).sum::<f64>() / count;
    let tm = b.reckon(
        mean,
        "kg",
        Label::quiet("T_m", 0),
        Weighted {
            inputs: ids,
            weight: 1.0 / count,
        },
        n(
            "the mean turning force: the mean of the ordinates over the cycle",
            Some("mittlere Drehkraft"),
        ),
    );
    b.check(
        &tm,
        "mean turning force T_m (ordinates)",
        "kg",
        "the mean of the exact ordinates",
        top,
        || {
            let exact: f64 = rows
                .iter()
                .map(|r| turning_force(k, &e.cylinders, r.shaft))
                .sum();
            exact / count
        },
    );
    mean
}

/// The table of the mean turning force: from the ordinates, exactly (`exact`, integrated
/// once by the caller), and from the indicated work, written on the sheet at height `y`.
fn mean_table(
    b: &mut Board,
    e: &GasEngine,
    (mean, exact, ids): (f64, f64, &[crate::protocol::ObjId]),
    y: f64,
) {
    if !b.is_recording() {
        return;
    }
    let work = super::mean_from_work(&e.kinematics, &e.cylinders, e.cycle_deg);
    let table = vec![
        vec!["T_m".to_string(), "kg".to_string()],
        vec!["from the ordinates".into(), crate::fmt::num(mean, 1)],
        vec!["exact integral".into(), crate::fmt::num(exact, 1)],
        vec!["from the indicated work".into(), crate::fmt::num(work, 1)],
    ];
    let at = Point::new(0.0, y);
    b.table(
        at,
        table,
        ids,
        n(
            "the mean turning force by the rule, exactly, and from the work",
            Some("mittlerer Tangentialdruck"),
        ),
    );
}
