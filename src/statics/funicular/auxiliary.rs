//! The resultant of two parallel forces by two equal and opposite auxiliary forces (LH C.1,
//! Abb. 21).

use super::notes::*;
use super::{Force, SystemDrawing};
use crate::kernel::tolerance::PARALLEL_SIN_EPS;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, ConstructionError, Label, Role, Scale, H};

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
/// let k1 = Force::new((0.0, 0.0), (0.0, -100.0));
/// let k2 = Force::new((3.0, 0.0), (0.0, -200.0));
/// let d = SystemDrawing { length_scale: 50.0, force_scale: 10.0, pole: None, plan_at: None, unit: "kg" };
/// let mut b = Board::recording();
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
    let (v1, v2) = (k1.f, k2.f);
    if v1.norm() == 0.0
        || v2.norm() == 0.0
        || crate::kernel::cross(&v1, &v2).abs() > PARALLEL_SIN_EPS * v1.norm() * v2.norm()
    {
        return Err(ConstructionError::unsupported(
            "forces",
            "the auxiliary-force construction takes two parallel, non-zero forces",
        ));
    }
    let k = 1000.0 / dr.length_scale;
    let fs = dr.force_scale;
    let dir = v1 / v1.norm();
    // The auxiliary forces P' and P'' = -P' must share one line of action to cancel: the
    // line joining the points of application (across the forces only where that is
    // horizontal, as in Abb. 21).
    let join = k2.at - k1.at;
    if join.norm() == 0.0
        || crate::kernel::cross(&join, &dir).abs() <= PARALLEL_SIN_EPS * join.norm()
    {
        return Err(ConstructionError::unsupported(
            "forces",
            "the points of application lie on one line of action: the resultant acts on it, and the auxiliary forces have no line to act along",
        ));
    }
    let across = join / join.norm();
    let mut partial = Vec::new();
    for (i, (f, sense)) in [(k1, 1.0), (k2, -1.0)].into_iter().enumerate() {
        partial.push(partial_resultant(
            b,
            i,
            f,
            sense * aux,
            (dir, across),
            k,
            fs,
        )?);
    }
    let x = b
        .meet_point(
            &partial[0].line,
            &partial[1].line,
            Label::plain("X"),
            N_AUX_X,
        )
        .map_err(|_| {
            ConstructionError::unsupported(
                "forces",
                "the forces are equal and opposite, or so nearly that their resultant lies beyond the drawing (its partial resultants do not meet): a couple",
            )
        })?;
    let ratio = (k1.f.dot(&dir), k2.f.dot(&dir));
    let dist = ((k2.at.x - k1.at.x).powi(2) + (k2.at.y - k1.at.y).powi(2)).sqrt();
    lever_arm(b, &partial, &x, ratio, (dist, 1.0 / k))
}

/// The resultant through X, parallel to the forces (to K1's line of action), cuts the join
/// of the points of application at distance a from the first, read off at `m_per_mm` and
/// checked by the lever rule a = l·K2/(K1 + K2) (`(m1, m2)`: the forces along their
/// direction; `dist`: l in m).
fn lever_arm(
    b: &mut Board,
    partial: &[Partial],
    x: &H<Point>,
    (m1, m2): (f64, f64),
    (dist, m_per_mm): (f64, f64),
) -> Result<f64, ConstructionError> {
    let r_line = b.parallel(&partial[0].along, x, Role::Result, N_AUX_LINE);
    let (a1, a2) = (partial[0].at, partial[1].at);
    let join = b.line_through(&a1, &a2, Role::Construction, N_AUX_FOOT)?;
    let c = b.meet_point(&r_line, &join, Label::plain("R"), N_AUX_FOOT)?;
    let metres = Scale::new(m_per_mm, "m");
    let a = b.measure(&a1, &c, &join, metres, Label::quiet("a", 0), N_AUX_A);
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

/// A force at its point of application, its line of action, and the line of its partial
/// resultant with the auxiliary force.
struct Partial {
    at: H<Point>,
    along: H<Line>,
    line: H<Line>,
}

/// The partial resultant of force `f` (the `i`-th, along `dir`) and its auxiliary force of
/// `aux` kg along `across` (the join of the points of application), by the parallelogram at
/// its point of application: the point, the force's line, and the line of the partial
/// resultant.
fn partial_resultant(
    b: &mut Board,
    i: usize,
    f: Force,
    aux: f64,
    (dir, across): (Vector, Vector),
    k: f64,
    fs: f64,
) -> Result<Partial, ConstructionError> {
    let at = Point::new(f.at.x * k, f.at.y * k);
    let a = b.point(
        at,
        Role::Given.labelled(Label::indexed("K", i as u32 + 1)),
        N_APPLICATION,
    );
    let along = b.line_dir(&a, dir, Role::Construction, N_LINE)?;
    let fv = f.f;
    let e = b.lay_off(&a, &along, fv.dot(&dir) / fs, Role::Force, N_AUX_FORCE)?;
    let cross_line = b.line_dir(&a, across, Role::Auxiliary, N_AUX)?;
    let h = b.lay_off(&a, &cross_line, aux / fs, Role::Force, N_AUX)?;
    let p1 = b.parallel(&cross_line, &e, Role::Auxiliary, N_AUX_PAR);
    let p2 = b.parallel(&along, &h, Role::Auxiliary, N_AUX_PAR);
    let r_end = b.meet_point(&p1, &p2, Label::NONE, N_AUX_PAR)?;
    let r_part = b.line_through(&a, &r_end, Role::Construction, N_AUX_R)?;
    Ok(Partial {
        at: a,
        along,
        line: r_part,
    })
}
