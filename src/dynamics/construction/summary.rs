//! What is reckoned from the drawn turning-force diagram: its mean height by every rule of
//! LH G, the indicated power both ways (LH H), and the flywheel (LH J, KG Abb. 1062).

use super::super::rules::{self, Planimeter};
use super::super::{
    model, DynamicsDrawing, DynamicsRequest, DynamicsResults, Engine, Flywheel, MeanHeight, Power,
};
use crate::kernel::Point;
use crate::protocol::{note, Board, Label, Note, Topic, Weighted};

const N_MEAN: Note = note(
    "mean height of the turning-force diagram: T_m",
    Some("mittlerer Tangentialdruck"),
    "LH G, Gl. 52-60",
    Topic::Forces,
);
const N_POWER: Note = note(
    "indicated power from the mean pressures and from T_m",
    Some("indizierte Leistung"),
    "LH H, Gl. 65-70",
    Topic::Forces,
);
const N_FLY: Note = note(
    "excess work over the mean resistance and the flywheel",
    Some("Schwungradberechnung"),
    "LH J; KG Abb. 1062, 1064",
    Topic::Forces,
);
const N_TABLE: Note = note(
    "table of the mean heights, the power and the flywheel",
    Some("Auswertung"),
    "LH G, H, J",
    Topic::Forces,
);

/// Millimetre paper: squares of 1 mm (LH G.c).
const CELL_MM: f64 = 1.0;
/// The planimeter's vernier reads a tenth of a unit in a thousand (LH G.d: 0.1 cm² on a
/// 100 cm² wheel turn): its reading is held to 1e-3 of the diagram's bounding rectangle.
const PLANIMETER_RESOLUTION: f64 = 1e-3;
/// Trace step of the simulated planimeter (mm of sheet).
const TRACE_STEP_MM: f64 = 0.05;

/// Mean heights, power and flywheel as the request asks; written into `res` and, on a
/// recording board, as tallies with their checks and a table.
pub(super) fn finish(
    b: &mut Board,
    e: &Engine,
    dr: &DynamicsDrawing,
    request: &DynamicsRequest,
    res: &mut DynamicsResults,
    table_at: Point,
) {
    let wanted = request.mean_height || request.power || request.flywheel;
    if res.turning.is_empty() || !wanted {
        if !res.mean_area.is_empty() || res.resistance.is_some() {
            table(b, e, res, table_at);
        }
        return;
    }
    let exact = e.t_m();
    res.t_m_exact = Some(exact);
    if request.mean_height || request.power {
        res.mean_heights = mean_heights(b, e, dr, (&res.turning, &res.turning_ids), exact);
    }
    if request.power {
        res.power = Some(power(b, e, res));
    }
    if request.flywheel {
        res.flywheel = Some(flywheel(b, e, (&res.turning, &res.turning_ids), exact));
    }
    table(b, e, res, table_at);
}

/// The diagram as drawn: (x, y) in sheet mm, x the developed arc, closed at 360°.
fn drawn(e: &Engine, dr: &DynamicsDrawing, turning: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let r_mm = e.kinematics.r / dr.length_scale;
    let mut pts: Vec<(f64, f64)> = turning
        .iter()
        .map(|&(t, v)| (r_mm * t.to_radians(), v / dr.force_scale))
        .collect();
    if let Some(&(_, v0)) = turning.first() {
        pts.push((r_mm * std::f64::consts::TAU, v0 / dr.force_scale));
    }
    pts
}

/// Whether the shaft angles divide the revolution equally: Simpson's and the 3/8 rule need
/// equal strips (LH G: "es müssen dann neue Ordinaten eingezeichnet werden"); the rays by
/// rod-length arcs give unequal ones.
fn equal_strips(turning: &[(f64, f64)]) -> bool {
    let n = turning.len();
    turning
        .iter()
        .enumerate()
        .all(|(k, p)| (p.0 - 360.0 * k as f64 / n as f64).abs() < 1e-9)
}

fn mean_heights(
    b: &mut Board,
    e: &Engine,
    dr: &DynamicsDrawing,
    (turning, ids): (&[(f64, f64)], &[crate::protocol::ObjId]),
    exact: f64,
) -> Vec<MeanHeight> {
    // Each rule is a weighted mean of the ordinates read off the diagram: their bounds
    // follow into it, each with the weight 1/n.
    let ords_read = Weighted {
        inputs: ids,
        weight: 1.0 / ids.len().max(1) as f64,
    };
    let mut ords: Vec<f64> = turning.iter().map(|p| p.1).collect();
    ords.push(ords[0]);
    let equal = equal_strips(turning);
    let pts = drawn(e, dr, turning);
    let length = pts.last().map_or(0.0, |p| p.0);
    let to_tm = |area_mm2: f64| area_mm2 / length * dr.force_scale;
    let mut closed = pts.clone();
    closed.push((length, 0.0));
    closed.push((0.0, 0.0));
    // The drawn polygon's own area: what a rule over the drawn ordinates measures.
    let polygon = -rules::polygon_area(&closed);
    let mut out = vec![MeanHeight {
        rule: "trapezoid (Gl. 55)".into(),
        t_m: rules::trapezoid_revolution(turning),
        error: 0.0,
    }];
    let trap = b.reckon(out[0].t_m, "kg", Label::plain("T_m"), ords_read, N_MEAN);
    b.check(
        &trap,
        "T_m by the trapezoid rule = drawn polygon’s area / 2πr",
        "kg",
        "LH Gl. 55",
        exact.abs(),
        || to_tm(polygon),
    );
    if equal {
        out.extend(equal_strip_rules(b, e, turning, &ords, ords_read));
    }
    let squares = rules::count_squares(&pts, CELL_MM);
    let sq = b.reckon(to_tm(squares), "kg", Label::NONE, ords_read, N_MEAN);
    b.check_within(
        &sq,
        "T_m by counting millimetre squares",
        "kg",
        "LH G.c",
        exact.abs(),
        || {
            (
                to_tm(polygon),
                to_tm(rules::count_squares_bound(&pts, CELL_MM)),
            )
        },
    );
    out.push(MeanHeight {
        rule: "millimetre squares".into(),
        t_m: sq.g,
        error: 0.0,
    });
    if let Some(pl) = planimeter(b, (&pts, &closed), polygon, exact, &to_tm, ords_read) {
        out.push(pl);
    }
    for m in &mut out {
        m.error = m.t_m - exact;
    }
    out
}

/// Simpson's rule and the 3/8 rule over ordinates at equal strips, where their count allows,
/// each held to the same rule over the exact turning force at the same shaft angles.
fn equal_strip_rules(
    b: &mut Board,
    e: &Engine,
    turning: &[(f64, f64)],
    ords: &[f64],
    ords_read: Weighted<'_>,
) -> Vec<MeanHeight> {
    let exact = || -> Vec<f64> {
        let k = &e.kinematics;
        let mut t: Vec<f64> = turning
            .iter()
            .map(|p| model::turning_force(k, &e.cylinders, e.efficiency, p.0))
            .collect();
        t.extend(t.first().copied());
        t
    };
    // Judged at the diagram's largest ordinate: a rule sums the ordinates, whose rounding
    // follows their size, not the mean's.
    let largest = ords.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    type Rule = fn(&[f64]) -> Option<f64>;
    let rules: [(&str, &str, &str, Rule); 2] = [
        (
            "Simpson (Gl. 58)",
            "T_m by Simpson’s rule",
            "LH Gl. 56-58",
            rules::simpson,
        ),
        (
            "3/8 rule (Gl. 59)",
            "T_m by the 3/8 rule",
            "LH Gl. 59",
            rules::three_eighths,
        ),
    ];
    let mut out = Vec::with_capacity(2);
    for (rule, quantity, formula, apply) in rules {
        let Some(t_m) = apply(ords) else { continue };
        // Simpson's weights reach 4/3 of the trapezoid's, the 3/8 rule's 9/8.
        let weighted = Weighted {
            weight: ords_read.weight * 4.0 / 3.0,
            ..ords_read
        };
        let value = b.reckon(t_m, "kg", Label::NONE, weighted, N_MEAN);
        b.check(&value, quantity, "kg", formula, largest, || {
            apply(&exact()).unwrap_or(f64::NAN)
        });
        out.push(MeanHeight {
            rule: rule.into(),
            t_m,
            error: 0.0,
        });
    }
    out
}

/// T_m by a simulated polar planimeter traced round the drawn outline (pole below the
/// diagram, arms long enough to reach every point), held to the polygon's area within the
/// instrument's resolution.
/// A point of the drawn diagram (mm on the sheet).
type Xy = (f64, f64);

fn planimeter(
    b: &mut Board,
    (pts, closed): (&[Xy], &[Xy]),
    polygon: f64,
    exact: f64,
    to_tm: &dyn Fn(f64) -> f64,
    ords_read: Weighted<'_>,
) -> Option<MeanHeight> {
    let length = pts.last().map_or(0.0, |p| p.0);
    let ymax = pts.iter().fold(0.0f64, |m, p| m.max(p.1.abs()));
    let depth = 0.5 * length + ymax;
    let instrument = Planimeter {
        pole: (0.5 * length, -depth),
        pole_arm: depth + 0.5 * length,
        tracer_arm: depth + 0.5 * length,
        wheel: 0.4 * (depth + 0.5 * length),
    };
    let area = instrument.trace(closed, TRACE_STEP_MM)?;
    let pl = b.reckon(to_tm(-area), "kg", Label::NONE, ords_read, N_MEAN);
    // The vernier's resolution over the diagram's rectangle, and the rounding of the trace
    // (some 1e-12 of the arm's square per step) where the diagram is flat.
    let steps = closed.len() as f64 + 2.0 * length / TRACE_STEP_MM;
    let bound =
        PLANIMETER_RESOLUTION * length * 2.0 * ymax + 1e-12 * instrument.tracer_arm.powi(2) * steps;
    b.check_within(
        &pl,
        "T_m by the polar planimeter (simulated)",
        "kg",
        "LH G.d, Abb. 71",
        exact.abs(),
        || (to_tm(polygon), to_tm(bound)),
    );
    Some(MeanHeight {
        rule: "polar planimeter".into(),
        t_m: pl.g,
        error: 0.0,
    })
}

fn power(b: &mut Board, e: &Engine, res: &DynamicsResults) -> Power {
    let from_pressures = e.power_from_pressures();
    let total: f64 = from_pressures.iter().sum();
    let exact = res.t_m_exact.unwrap_or(0.0);
    let v = e.kinematics.v;
    let from_t_m = model::power_from_turning(exact, v);
    let n = b.tally(from_t_m, "PS", Label::plain("N_i"), &[], N_POWER);
    b.check(
        &n,
        "power from T_m = from the mean pressures (P_m/T_m = π/2)",
        "PS",
        "LH Gl. 68-70",
        total.abs(),
        || total,
    );
    let drawn = res.mean_heights.first().map_or(exact, |m| m.t_m);
    Power {
        from_pressures,
        from_t_m,
        from_drawn_t_m: model::power_from_turning(drawn, v),
    }
}

/// The energy curve E(θ) = ∫ (T − T_m) r dθ (m·kg) over a revolution, from `samples`
/// ordinates: its extremes and where they fall.
fn excess(turning: &[(f64, f64)], t_m: f64, r_m: f64) -> (f64, f64, f64) {
    let n = turning.len();
    let (mut e, mut emax, mut emin) = (0.0, 0.0, 0.0);
    let (mut fast, mut slow) = (0.0, 0.0);
    for k in 0..n {
        let (a, b) = (turning[k].1, turning[(k + 1) % n].1);
        let theta = if k + 1 == n { 360.0 } else { turning[k + 1].0 };
        let h = (theta - turning[k].0).to_radians();
        e += 0.5 * (a + b - 2.0 * t_m) * r_m * h;
        if e > emax {
            emax = e;
            fast = theta;
        }
        if e < emin {
            emin = e;
            slow = theta;
        }
    }
    (emax - emin, fast % 360.0, slow % 360.0)
}

/// The largest fluctuation of energy ΔE from the drawn ordinates (LH J): the energy curve
/// summed division by division, checked against the same sums over the exact turning force
/// at the same angles. The exact ΔE of the continuous curve is written beside it in the
/// table; the two differ by the division's resolution, which is the rule's, not the
/// drawing's (LH J's locomotive at 20 divisions: 1185 against 1329 m·kg).
fn flywheel(
    b: &mut Board,
    e: &Engine,
    (turning, ids): (&[(f64, f64)], &[crate::protocol::ObjId]),
    exact: f64,
) -> Flywheel {
    let k = &e.kinematics;
    let r_m = k.r / 1000.0;
    let (de, fast, slow) = excess(turning, exact, r_m);
    let (de_ref, _, _) = model::energy_extremes(k, &e.cylinders, e.efficiency, exact);
    // An ordinate off by δ moves the energy curve by δ·r·h beyond it (two half strips of
    // width h): the bound of ΔE follows every ordinate read off the diagram.
    let step = turning
        .windows(2)
        .map(|w| w[1].0 - w[0].0)
        .chain(turning.last().map(|p| 360.0 - p.0))
        .fold(0.0f64, f64::max)
        .to_radians();
    let read = Weighted {
        inputs: ids,
        weight: r_m * step,
    };
    let t = b.reckon(de, "m·kg", Label::plain("ΔE"), read, N_FLY);
    b.check(
        &t,
        "largest fluctuation of energy ΔE = the same sums over the exact turning force",
        "m·kg",
        "LH J; KG Abb. 1064",
        de_ref.abs(),
        || {
            let ords: Vec<(f64, f64)> = (turning.iter())
                .map(|&(th, _)| (th, model::turning_force(k, &e.cylinders, e.efficiency, th)))
                .collect();
            excess(&ords, exact, r_m).0
        },
    );
    let omega = k.v / r_m;
    Flywheel {
        resistance: exact,
        delta_e: de,
        delta_e_exact: de_ref,
        fastest_deg: fast,
        slowest_deg: slow,
        moment_of_inertia: e.irregularity.map(|d| de / (d * omega * omega)),
    }
}

/// The table of KG (297) against (296), the mean heights, the power and the flywheel; the
/// power is η·N_i, and named so, where the turning force carries the efficiency η.
fn table(b: &mut Board, e: &Engine, res: &DynamicsResults, at: Point) {
    if !b.is_recording() {
        return;
    }
    use crate::fmt::num;
    let eta = e.efficiency;
    // Each row names its quantity and unit; the error is in the row's unit.
    let mut rows = vec![vec!["".to_string(), "value".into(), "error".into()]];
    mean_area_rows(&mut rows, e, res);
    for m in &res.mean_heights {
        let name = format!("T_m, {} [kg]", m.rule);
        rows.push(vec![name, num(m.t_m, 1), num(m.error, 2)]);
    }
    if let Some(x) = res.t_m_exact {
        rows.push(vec!["T_m exact [kg]".into(), num(x, 1), "".into()]);
    }
    resistance_rows(&mut rows, res);
    if let Some(p) = &res.power {
        let total: f64 = p.from_pressures.iter().sum();
        let n = if eta == 1.0 {
            "N_i".to_string()
        } else {
            format!("η·N_i (η = {})", num(eta, 3))
        };
        rows.push(vec![format!("{n} from p_m [PS]"), num(total, 1), "".into()]);
        rows.push(vec![
            format!("{n} from T_m [PS]"),
            num(p.from_t_m, 1),
            "".into(),
        ]);
    }
    if let Some(f) = &res.flywheel {
        rows.push(vec![
            "ΔE [m·kg]".into(),
            num(f.delta_e, 1),
            num(f.delta_e - f.delta_e_exact, 1),
        ]);
        rows.push(vec![
            "ΔE exact [m·kg]".into(),
            num(f.delta_e_exact, 1),
            "".into(),
        ]);
        if let Some(j) = f.moment_of_inertia {
            rows.push(vec!["J [kg·m·s²]".into(), num(j, 2), "".into()]);
        }
    }
    // A table of no errors (KG 297 alone) leaves that column out.
    if rows.iter().skip(1).all(|r| r[2].is_empty()) {
        rows.iter_mut().for_each(|r| drop(r.pop()));
    }
    b.table(at, rows, &[], N_TABLE);
}

/// KG (297)'s rows: each cylinder's effective areas, their mean and the largest departure.
fn mean_area_rows(rows: &mut Vec<Vec<String>>, e: &Engine, res: &DynamicsResults) {
    use crate::fmt::num;
    for (cyl, m) in e.cylinders.iter().zip(&res.mean_area) {
        let of = if e.cylinders.len() > 1 {
            format!("{}: ", cyl.name)
        } else {
            String::new()
        };
        let mut row = |name: String, value: String| rows.push(vec![name, value, "".into()]);
        row(format!("{of}F′, cover side [cm²]"), num(m.cover_cm2, 1));
        row(format!("{of}F″, crank side [cm²]"), num(m.crank_cm2, 1));
        row(format!("{of}F = (F′+F″)/2 [cm²]"), num(m.mean_cm2, 1));
        let at = crate::fmt::num(m.at_deg, 3);
        row(
            format!("{of}F·p_ü − P, largest (θ = {at}°) [kg]"),
            num(m.difference, 1),
        );
        row(
            format!("{of}the same, of the largest P [%]"),
            num(100.0 * m.relative, 2),
        );
    }
}

/// KG Abb. 1067's rows: the pumps' mean resistance by the trapezoid rule and exactly.
fn resistance_rows(rows: &mut Vec<Vec<String>>, res: &DynamicsResults) {
    use crate::fmt::num;
    if let Some(r) = &res.resistance {
        rows.push(vec![
            "T_pm, trapezoid (Gl. 55) [kg]".into(),
            num(r.mean, 1),
            num(r.mean - r.mean_exact, 2),
        ]);
        rows.push(vec![
            "T_pm exact = Σ(P_p1 + P_p2)/π [kg]".into(),
            num(r.mean_exact, 1),
            "".into(),
        ]);
    }
}
