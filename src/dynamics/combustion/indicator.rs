//! A cylinder's gas pressure over the stroke (KG Abb. 1056, 1057, 1059): the indicator
//! diagram the piston-force diagram over the developed cycle (Abb. 1058, 1060) is drawn from.
//! It stands beside that diagram on the same base line, the atmosphere, at the same force
//! scale (the pressure above the atmosphere times the piston's area), so that each ordinate
//! is carried across with the dividers: the force diagram's ordinate at a shaft angle is the
//! indicator's at the piston's place in the stroke, turned down on the return strokes.

use super::GasEngine;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{note, Board, ConstructionError, Label, Note, Role, Scale, Topic, Trace, H};

fn n(caption: &'static str, term: Option<&'static str>) -> Note {
    note(
        caption,
        term,
        "KG XIV B.4, Abb. 1056, 1057, 1059",
        Topic::Custom("combustion engine"),
    )
}

/// How far left of the developed cycle's start the stroke's end stands (mm).
const GAP_MM: f64 = 20.0;

/// Cylinder c's indicator diagram on the base line at `y`, its stroke ending [`GAP_MM`] left
/// of the developed cycle's start, at the length scale: at each shaft angle the piston's
/// place laid off on the stroke, the pressure above the atmosphere (as force) on its
/// ordinate, and the curve through them over the whole cycle. Returns each ordinate's force
/// read off (kg, the gas pushing), in shaft order, for the developed diagram to carry over.
pub(super) fn diagram(
    b: &mut Board,
    e: &GasEngine,
    (c, shafts): (usize, &[f64]),
    (y, length_scale, force_scale): (f64, f64, f64),
) -> Result<Vec<H<f64>>, ConstructionError> {
    let cyl = &e.cylinders[c];
    let k = &e.kinematics;
    let stroke = 2.0 * k.r / length_scale;
    let base_note = n("the stroke under the gas pressure diagram", Some("Hub"));
    let end = Point::new(-GAP_MM, y);
    let start = b.point(
        end - Vector::new(stroke, 0.0),
        Role::Axis,
        base_note.clone(),
    );
    let base = b.line_dir(&start, Vector::new(1.0, 0.0), Role::Axis, base_note)?;
    let fs = Scale::new(force_scale, "kg");
    let peak = cyl.area_cm2 * (cyl.cycle.peak_at - super::ATMOSPHERE_AT);
    let (mut pts, mut read) = (Vec::new(), Vec::new());
    for &shaft in shafts {
        b.set_context(|| format!("{}, shaft {}°", cyl.name, crate::fmt::num(shaft, 3)));
        let (alpha, theta) = cyl.angles(shaft);
        let u = k.x_frac(theta);
        let push = cyl.area_cm2 * (cyl.cycle.pressure(alpha, u) - super::ATMOSPHERE_AT);
        let (tip, v) = ordinate(b, (&start, &base), (u * stroke, push / force_scale), fs)?;
        b.check(
            &v,
            "gas pressure above the atmosphere, as force (p − 1 at)·F",
            "kg",
            "KG Abb. 1056-1057, 1059",
            peak,
            || push,
        );
        pts.push(tip);
        read.push(v);
    }
    b.clear_context();
    if let Some(first) = pts.first().copied() {
        pts.push(first);
    }
    b.curve(
        &pts,
        Trace::Polygon,
        Role::Result.named("p"),
        n("the gas pressure over the stroke", Some("Druckverlauf")),
    );
    Ok(read)
}

/// The piston's place `at` mm along the stroke, the pressure's ordinate `mm` high over it,
/// and the force it stands for read off.
fn ordinate(
    b: &mut Board,
    (start, base): (&H<Point>, &H<Line>),
    (at, mm): (f64, f64),
    fs: Scale,
) -> Result<(H<Point>, H<f64>), ConstructionError> {
    let foot = b.lay_off(
        start,
        base,
        at,
        Role::Construction,
        n("the piston’s place on the stroke", Some("Kolbenstellung")),
    )?;
    let up = b.perpendicular(
        base,
        &foot,
        Role::Construction,
        n("ordinate", Some("Ordinate")),
    );
    let tip = b.lay_off(
        &foot,
        &up,
        mm,
        Role::Construction,
        n(
            "the pressure above the atmosphere, at the force scale",
            Some("Überdruck"),
        ),
    )?;
    let v = b.measure(
        &foot,
        &tip,
        &up,
        fs,
        Label::NONE,
        n("the gas pressure’s force read off", Some("abgegriffen")),
    );
    Ok((tip, v))
}
