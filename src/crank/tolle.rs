//! Tolle's parabola (LH B.3-4, Abb. 55-57; KG Abb. 1050): the piston acceleration, or the
//! inertia force, over the piston path, drawn by its two tangents at the dead centres.
//!
//! Over the stroke 2r with its middle O, the curve starts at T, the ordinate (1 + λ)·a at the
//! inner dead centre, and ends at T₁, −(1 − λ)·a at the outer one (a = v²/r, or M·v²/r for the
//! force). The tangents there meet at D, the point at OC = λr from the middle and CD = 3λ·a
//! below the axis (Tolle). The chord TT₁ passes through C: the book's control.
//!
//! The parabola is the quadratic curve with control points T, D, T₁, and its point at the
//! parameter s = sin²(θ/2) is exactly the book's pair (Gl. 21, Gl. 29): abscissa
//! `r(1 − cos θ) + λr/2 · sin²θ`, ordinate `a(cos θ + λ cos 2θ)`. The drafter divides both
//! tangents into equal parts and joins 1 with 1, 2 with 2, …: each joining line touches the
//! parabola at the point dividing it in the same ratio, so the points at k/n are constructed,
//! and the point at any crank angle is the same division at s (de Casteljau's construction).

use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, ConstructionError, Label, Note, Role, Scale, Topic, Weighted, H};

/// The situation of the steps of the outstroke's parabola (the curve above the axis at the
/// inner dead centre, T or B₀) and of the return stroke's (T′, B′₀).
pub(crate) const OUTSTROKE: &str = "outstroke";
/// See [`OUTSTROKE`].
pub(crate) const RETURN_STROKE: &str = "return stroke";

fn n(caption: &'static str, term: &'static str, book: &'static str) -> Note {
    crate::protocol::note(caption, Some(term), book, Topic::Acceleration)
}

fn nt(topic: Topic, caption: &'static str, term: &'static str, book: &'static str) -> Note {
    crate::protocol::note(caption, Some(term), book, topic)
}

/// The axis of a Tolle diagram under the stroke: its middle O, the dead-centre ends and the
/// ordinate lines there and at C (shared by the outstroke and return curves).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TolleAxis {
    /// The middle O of the stroke on the diagram axis.
    pub o: H<Point>,
    /// The diagram axis (the piston path laid out, +x the outstroke).
    pub axis: H<Line>,
    /// The vertical through O, for reading ordinates.
    pub vertical: H<Line>,
    /// Ends of the stroke: inner and outer dead centre on the axis.
    pub ends: [H<Point>; 2],
    /// The ordinate lines at the two ends.
    pub ordinates: [H<Line>; 2],
}

/// C, at OC = λr from O towards the outer dead centre, and the ordinate through it: where
/// the tangents of both curves meet below or above.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TolleC {
    /// The point C on the axis.
    pub c: H<Point>,
    /// The ordinate through C.
    pub ord: H<Line>,
}

/// One curve: T, D, T₁ (sheet points) and its sense (+1: the outstroke as the books draw it,
/// accelerations up; −1: its mirror image, the return stroke).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TolleCurve {
    pub t: H<Point>,
    pub d: H<Point>,
    pub t1: H<Point>,
}

/// Lays out the axis with its middle at `middle` (sheet) and the dead centres at `half` mm
/// either side, under `topic` (the acceleration diagram, or a net-pressure diagram).
pub(crate) fn axis(
    b: &mut Board,
    middle: Point,
    half: f64,
    topic: Topic,
) -> Result<TolleAxis, ConstructionError> {
    let o = b.point(
        middle,
        Role::Given.named("O"),
        nt(
            topic,
            "middle of the stroke on the diagram axis",
            "Hubmitte",
            "LH Abb. 55",
        ),
    );
    let axis = b.line_dir(
        &o,
        Vector::new(1.0, 0.0),
        Role::Axis,
        nt(
            topic,
            "diagram axis: the piston path laid out",
            "Abszissenachse",
            "LH Abb. 55",
        ),
    )?;
    let vertical = b.perpendicular(
        &axis,
        &o,
        Role::Axis,
        nt(
            topic,
            "ordinate line through O",
            "Mittelsenkrechte",
            "LH Abb. 55",
        ),
    );
    let (ends, ordinates) = ends(b, &o, &axis, half, topic)?;
    Ok(TolleAxis {
        o,
        axis,
        vertical,
        ends,
        ordinates,
    })
}

/// C at OC = λ·half from O towards the outer dead centre, with its ordinate (Tolle).
pub(crate) fn point_c(
    b: &mut Board,
    ax: &TolleAxis,
    half: f64,
    lambda: f64,
) -> Result<TolleC, ConstructionError> {
    let c = b.lay_off(
        &ax.o,
        &ax.axis,
        lambda * half,
        Role::Construction.named("C"),
        n(
            "OC = λ·r towards the outer dead centre",
            "Strecke OC (Tolle)",
            "LH B.3, Abb. 55",
        ),
    )?;
    let ord = b.perpendicular(
        &ax.axis,
        &c,
        Role::Construction,
        n("ordinate through C", "Lot in C", "LH Abb. 55"),
    );
    Ok(TolleC { c, ord })
}

/// The two dead centres on the axis and the ordinate lines through them.
type Ends = ([H<Point>; 2], [H<Line>; 2]);

/// The dead centres at half a stroke either side of O and the ordinate lines through them.
fn ends(
    b: &mut Board,
    o: &H<Point>,
    axis: &H<Line>,
    half: f64,
    topic: Topic,
) -> Result<Ends, ConstructionError> {
    let ends_note = nt(
        topic,
        "the dead centres at half a stroke from O",
        "Totpunkte",
        "LH Abb. 55",
    );
    let ord_note = nt(
        topic,
        "ordinate at the dead centre",
        "Totpunktordinate",
        "LH Abb. 55",
    );
    let mut pts = [*o; 2];
    let mut lines = [*axis; 2];
    for (k, sign) in [-1.0, 1.0].into_iter().enumerate() {
        let e = b.lay_off(o, axis, sign * half, Role::Construction, ends_note.clone())?;
        lines[k] = b.perpendicular(axis, &e, Role::Construction, ord_note.clone());
        pts[k] = e;
    }
    Ok((pts, lines))
}

/// The tangents and the control of one curve: T = (1 + λ)·a and T₁ = −(1 − λ)·a (sheet mm,
/// times `sense`), D at CD = 3λ·a, the chord TT₁ cut with the axis; returns the curve and
/// the cut (to be checked against C).
pub(crate) fn curve(
    b: &mut Board,
    ax: &TolleAxis,
    c: &TolleC,
    a_mm: f64,
    lambda: f64,
    sense: f64,
    name: Label,
) -> Result<(TolleCurve, H<Point>), ConstructionError> {
    let t = b.lay_off(
        &ax.ends[0],
        &ax.ordinates[0],
        sense * (1.0 + lambda) * a_mm,
        Role::Construction.labelled(name),
        n(
            "(1 + λ)·v²/r at the inner dead centre",
            "Beschleunigung im Totpunkt",
            "LH Gl. 30, 32",
        ),
    )?;
    let t1 = b.lay_off(
        &ax.ends[1],
        &ax.ordinates[1],
        -sense * (1.0 - lambda) * a_mm,
        Role::Construction,
        n(
            "(1 − λ)·v²/r at the outer dead centre",
            "Verzögerung im Totpunkt",
            "LH Gl. 31, 33",
        ),
    )?;
    let d = b.lay_off(
        &c.c,
        &c.ord,
        -sense * 3.0 * lambda * a_mm,
        Role::Construction.named("D"),
        n(
            "CD = 3λ·v²/r: the tangents meet in D",
            "Strecke CD (Tolle)",
            "LH B.3, Abb. 55",
        ),
    )?;
    let tan = n(
        "tangent to the parabola at the dead centre",
        "Parabeltangente",
        "LH Abb. 55",
    );
    b.segment(&t, &d, Role::Construction, tan.clone());
    b.segment(&d, &t1, Role::Construction, tan.clone());
    let chord = b.line_through(
        &t,
        &t1,
        Role::Auxiliary,
        n(
            "chord TT₁ (control: it passes through C)",
            "Parabelsehne",
            "LH Abb. 55, 57",
        ),
    )?;
    let c_cut = b.meet_point(
        &chord,
        &ax.axis,
        Label::NONE,
        n("the chord cuts the axis", "Kontrolle durch C", "LH Abb. 55"),
    )?;
    Ok((TolleCurve { t, d, t1 }, c_cut))
}

/// CD taken off with the dividers from D to C, at the ordinates' scale `ys`: Tolle's 3λ·a
/// (positive for the outstroke's curve, whose D lies under the axis). The book computes CD
/// and lays it off (LH B.3: "CD = 77,7 m/sek²"); reading it back puts the printed length
/// beside what the sheet holds.
pub(crate) fn read_cd(
    b: &mut Board,
    ax: &TolleAxis,
    c: &TolleC,
    curve: &TolleCurve,
    ys: Scale,
) -> H<f64> {
    b.measure(
        &curve.d,
        &c.c,
        &ax.vertical,
        ys,
        Label::NONE,
        n(
            "CD taken off with the dividers",
            "Strecke CD (Tolle)",
            "LH B.3, Abb. 55",
        ),
    )
}

/// The areas of acceleration and retardation (LH B.3, Abb. 56: "für die aufgewandte
/// Beschleunigung und die Verzögerung gleich"): the signed area between the curve and the
/// axis, from the constructed points T, D, T₁, exactly (the integrand y·x' of the quadratic
/// curve is a cubic: two Gauss points integrate it without error), tallied and checked
/// against zero relative to the rectangle of the stroke and the largest ordinate. Tolle's D
/// makes it vanish: with CD other than 3λ·a it would not.
pub(crate) fn balance(b: &mut Board, ax: &TolleAxis, c: &TolleCurve) -> H<f64> {
    let (dir, up) = (ax.axis.g.dir, ax.vertical.g.dir);
    let o = ax.o.g;
    let coords = |s: f64| {
        let w = [(1.0 - s) * (1.0 - s), 2.0 * s * (1.0 - s), s * s];
        let p = [c.t.g, c.d.g, c.t1.g];
        let v = (p[0] - o) * w[0] + (p[1] - o) * w[1] + (p[2] - o) * w[2];
        let dv = ((c.d.g - c.t.g) * (1.0 - s) + (c.t1.g - c.d.g) * s) * 2.0;
        (v.dot(&up), dv.dot(&dir))
    };
    let g = 0.5 / 3f64.sqrt();
    let area: f64 = [0.5 - g, 0.5 + g]
        .iter()
        .map(|&s| {
            let (y, dx) = coords(s);
            0.5 * y * dx
        })
        .sum();
    let width = (ax.ends[1].g - ax.ends[0].g).norm();
    let height = (c.t.g - ax.ends[0].g)
        .norm()
        .max((c.t1.g - ax.ends[1].g).norm());
    // A point of the three moved by 1 mm changes the area by less than the sheet's
    // width plus height (mm² per mm).
    let h = b.reckon(
        area,
        "mm²",
        Label::NONE,
        Weighted {
            inputs: &[c.t.id, c.d.id, c.t1.id],
            weight: width + height,
        },
        n(
            "the areas of acceleration and retardation: their difference",
            "Beschleunigungs- und Verzögerungsfläche gleich",
            "LH B.3, Abb. 56; KG B.4b",
        ),
    );
    b.check(
        &h,
        "area of acceleration − area of retardation (on the sheet)",
        "mm²",
        "LH B.3, Abb. 56",
        width * height,
        || 0.0,
    );
    h
}

/// The envelope as the book draws it: both tangents divided into `parts` equal parts, point k
/// joined with point k; on each joining line the curve point dividing it as k : (parts − k).
/// Returns the curve points from T to T₁ (only on a recording board: it is the drawing).
pub(crate) fn envelope(b: &mut Board, c: &TolleCurve, parts: usize) -> Vec<H<Point>> {
    if !b.is_recording() {
        return Vec::new();
    }
    let div = n(
        "divide both tangents into equal parts",
        "Teilung der Tangenten",
        "LH Abb. 55",
    );
    let p = b.naming(
        |s| s.push_str("tangent TD"),
        |b| b.divide_segment(&c.t, &c.d, parts, "", div.clone()),
    );
    let q = b.naming(
        |s| s.push_str("tangent DT₁"),
        |b| b.divide_segment(&c.d, &c.t1, parts, "", div.clone()),
    );
    let join = n(
        "join 1 with 1, 2 with 2, …: tangents of the parabola",
        "Umhüllende",
        "LH Abb. 55",
    );
    let touch = n(
        "the point of contact divides the joining line alike",
        "Berührungspunkt",
        "LH Abb. 55",
    );
    let mut out = vec![c.t];
    for k in 1..parts {
        let s = k as f64 / parts as f64;
        let contact = b.naming(
            |s| {
                use std::fmt::Write;
                let _ = write!(s, "{k} with {k}");
            },
            |b| {
                b.segment(&p[k], &q[k], Role::Construction, join.clone());
                b.divide_at(&p[k], &q[k], s, Label::NONE, touch.clone())
            },
        );
        if let Ok(pt) = contact {
            out.push(pt);
        }
    }
    out.push(c.t1);
    out
}

/// The curve point at parameter `s` ∈ [0, 1] (s = sin²(θ/2) for the crank angle θ): both
/// tangents divided at s, the joining line divided at s again.
pub(crate) fn point_at(
    b: &mut Board,
    c: &TolleCurve,
    s: f64,
    label: Label,
) -> Result<H<Point>, ConstructionError> {
    let div = n(
        "divide both tangents in the ratio of the crank angle",
        "Teilung der Tangenten",
        "LH Abb. 55",
    );
    let p = b.naming(
        |s| s.push_str("tangent TD"),
        |b| b.divide_at(&c.t, &c.d, s, Label::NONE, div.clone()),
    )?;
    let q = b.naming(
        |s| s.push_str("tangent DT₁"),
        |b| b.divide_at(&c.d, &c.t1, s, Label::NONE, div.clone()),
    )?;
    b.segment(
        &p,
        &q,
        Role::Construction,
        n(
            "the joining line touches the parabola",
            "Parabeltangente",
            "LH Abb. 55",
        ),
    );
    b.divide_at(
        &p,
        &q,
        s,
        label,
        n(
            "the point of contact for the crank angle",
            "Parabelpunkt",
            "LH Abb. 55",
        ),
    )
}

/// Reads off a curve point: its abscissa from the inner dead centre (length `xs`) and its
/// ordinate (`ys`), with the foot on the axis drawn.
pub(crate) fn read(
    b: &mut Board,
    ax: &TolleAxis,
    q: &H<Point>,
    xs: Scale,
    ys: Scale,
    labels: (Label, Label),
) -> (H<f64>, H<f64>) {
    let foot = b.foot(
        &ax.axis,
        q,
        Role::Construction,
        n("ordinate of the curve point", "Ordinate", "LH Abb. 55"),
    );
    let x = b.measure(
        &ax.ends[0],
        &foot,
        &ax.axis,
        xs,
        labels.0,
        n(
            "piston path of the point from the inner dead centre",
            "Kolbenweg",
            "LH Gl. 21",
        ),
    );
    let y = b.measure(
        &foot,
        q,
        &ax.vertical,
        ys,
        labels.1,
        n(
            "ordinate read off at its scale",
            "Ordinate",
            "LH Gl. 29; KG (291)",
        ),
    );
    (x, y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_areas_balance_only_with_tolles_d() {
        let mut b = Board::recording().with_figure_size(200.0);
        let (half, lam, a) = (20.0, 0.2, 10.0);
        let ax = axis(&mut b, Point::new(0.0, 0.0), half, Topic::Acceleration).unwrap();
        let c = point_c(&mut b, &ax, half, lam).unwrap();
        let (good, _) = curve(&mut b, &ax, &c, a, lam, 1.0, Label::plain("T")).unwrap();
        assert!(balance(&mut b, &ax, &good).g.abs() < 1e-12);
        // D at 2λ·a instead of 3λ·a: the lobes no longer balance, and the check says so.
        let note = n("test", "test", "test");
        let d = b.point(Point::new(lam * half, -2.0 * lam * a), Role::Given, note);
        let wrong = TolleCurve { d, ..good };
        let area = balance(&mut b, &ax, &wrong);
        assert!(area.g.abs() > 1.0, "{}", area.g);
        assert_eq!(b.checks().filter(|c| !c.passed).count(), 1);
    }
}
