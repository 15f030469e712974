//! The support reactions by the funicular polygon (LH C.2): a pin and a roller by the closing
//! line, three rollers by Culmann's line; each read off the force plan and checked by the
//! moment equations and the dense solve.

use super::matrix::Solution;
use super::notes::*;
use super::{SupportKind, Truss};
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, ConstructionError, Label, Role, Scale, H};

/// The supports, as the reaction construction takes them.
#[derive(Debug, Clone, Copy)]
pub(super) enum Supports {
    /// A pin and a roller: the closing line of the funicular polygon (LH C.2).
    PinRoller {
        pin: usize,
        roller: usize,
        dir: Vector,
    },
    /// Three rollers: Culmann's line (the resultant with one reaction balances the other
    /// two, so both pairs act along the line through their meeting points).
    Rollers([(usize, Vector); 3]),
}

/// Index of support `s` in [`Truss::supports`] by joint.
pub(super) fn support_index(t: &Truss, joint: usize) -> usize {
    t.supports
        .iter()
        .position(|s| s.joint == joint)
        .expect("a support at that joint")
}

/// The reaction supports: one pin and one roller, or three rollers.
pub(super) fn supports(t: &Truss) -> Result<Supports, ConstructionError> {
    let pins: Vec<_> = t
        .supports
        .iter()
        .filter(|s| s.kind == SupportKind::Pinned)
        .collect();
    let rollers: Vec<_> = t
        .supports
        .iter()
        .filter_map(|s| match s.kind {
            SupportKind::Roller { dir } => Some((s.joint, dir)),
            _ => None,
        })
        .collect();
    match (pins.len(), rollers.len()) {
        (1, 1) => Ok(Supports::PinRoller {
            pin: pins[0].joint,
            roller: rollers[0].0,
            dir: rollers[0].1,
        }),
        (0, 3) => Ok(Supports::Rollers([rollers[0], rollers[1], rollers[2]])),
        _ => Err(ConstructionError::unsupported("supports", format!(
            "the graphic reactions need one pin and one roller, or three rollers; the truss has {} pin(s) and {} roller(s)",
            pins.len(),
            rollers.len()
        ))),
    }
}

/// The pole for the reaction construction: off the left of the loads' resultant by about the
/// polygon's size, picked among a few candidates for the best-conditioned cuts of strings with
/// lines of action and of the last string with B's line.
pub(super) fn choose_pole(corners: &[Point], loads: &[Vector], rdir: Vector) -> Point {
    let (first, last) = (corners[0], corners[corners.len() - 1]);
    let mid = Point::from((first.coords + last.coords) * 0.5);
    let span = corners
        .iter()
        .map(|c| (c - mid).norm())
        .fold(0.0, f64::max)
        .max(10.0);
    let chord = last - first;
    // Off to the side of the closing chord; if the polygon closes, of its longest side.
    let along = if chord.norm() > 1e-9 * span {
        chord
    } else {
        loads
            .iter()
            .copied()
            .max_by(|a, b| a.norm().total_cmp(&b.norm()))
            .unwrap_or(Vector::new(0.0, 1.0))
    };
    let n = Vector::new(-along.y, along.x).normalize();
    // A pole on a corner or on a ray parallel to the next line of action scores 0.
    let sin = |a: Vector, b: Vector| {
        let d = a.norm() * b.norm();
        if d > 1e-9 * span * b.norm() {
            (a.x * b.y - a.y * b.x).abs() / d
        } else {
            0.0
        }
    };
    let score = |o: Point| -> f64 {
        let mut worst = f64::INFINITY;
        for (i, l) in loads.iter().enumerate() {
            worst = worst.min(sin(corners[i] - o, *l));
        }
        worst.min(sin(last - o, rdir))
    };
    let mut best = (mid + n * span, -1.0);
    for (f, turn) in [
        (1.0, 0.0),
        (1.0, 0.5),
        (1.0, -0.5),
        (1.6, 0.0),
        (0.7, 0.3),
        (1.3, -0.8),
        (2.0, 1.0),
    ] {
        let o = mid + n * (f * span) + along.normalize() * (turn * span);
        let s = score(o);
        if s > best.1 * (1.0 + 1e-9) {
            best = (o, s);
        }
    }
    best.0
}

/// A reaction in the force plan: its support (index), tail and head.
pub(super) type PlanReaction = (usize, H<Point>, H<Point>);

/// Three rollers (Culmann): the resultant R of the loads and the lone roller's reaction
/// meet in P, the other two reaction lines in Q; R and the lone reaction together balance
/// the other two, so their sum acts along PQ. In the force plan, the parallel to the lone
/// roller through the end of the loads and the parallel to PQ through their start give the
/// lone reaction; the other two follow by resolving along their lines. Of the three rollers
/// the lone one is the one with the best-conditioned cuts. Returns (support index, tail,
/// head) of each reaction in the force plan.
#[allow(clippy::too_many_arguments)]
pub(super) fn culmann(
    b: &mut Board,
    t: &Truss,
    rlines: &[Option<H<Line>>],
    first: &H<Line>,
    last_string: &H<Line>,
    fh: &[H<Point>],
    r: &[(usize, Vector); 3],
) -> Result<Vec<PlanReaction>, ConstructionError> {
    let n = fh.len() - 1;
    let rv = fh[n].g - fh[0].g;
    let span = fh
        .iter()
        .map(|f| (f.g - fh[0].g).norm())
        .fold(0.0, f64::max);
    if rv.norm() <= 1e-9 * span.max(f64::MIN_POSITIVE) {
        return Err(ConstructionError::unsupported("loads", 
            "the loads form a couple (their force polygon closes): three rollers need a resultant to cut",
        ));
    }
    let on_r = b.meet_point(first, last_string, Label::quiet("R", 0), N_RESULTANT)?;
    let rl = b.line_dir(
        &on_r,
        rv,
        Label::plain("R"),
        Role::Construction,
        N_RESULTANT,
    )?;
    let sin = |a: Vector, c: Vector| (a.x * c.y - a.y * c.x).abs() / (a.norm() * c.norm());
    let mut best = (0, -1.0);
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let score = sin(rv, r[k].1).min(sin(r[i].1, r[j].1));
        if score > best.1 {
            best = (k, score);
        }
    }
    let k = best.0;
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let line = |s: usize| rlines[support_index(t, r[s].0)].expect("a roller has a line");
    let (lk, li, lj) = (line(k), line(i), line(j));
    let p = b.meet_point(&rl, &lk, Label::quiet("P", 0), N_CULMANN_P)?;
    let q = b.meet_point(&li, &lj, Label::quiet("Q", 0), N_CULMANN_Q)?;
    let c = b.line_through(&p, &q, Label::plain("c"), Role::Construction, N_CULMANN)?;
    let (f0, last) = (fh[0], fh[n]);
    let along_k = b.parallel(&lk, &last, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let along_c = b.parallel(&c, &f0, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let x = b.meet_point(&along_k, &along_c, Label::quiet("X", 0), N_CULMANN_PLAN)?;
    let along_i = b.parallel(&li, &x, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let along_j = b.parallel(&lj, &f0, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let y = b.meet_point(&along_i, &along_j, Label::quiet("Y", 0), N_CULMANN_PLAN)?;
    Ok(vec![
        (support_index(t, r[k].0), last, x),
        (support_index(t, r[i].0), x, y),
        (support_index(t, r[j].0), y, f0),
    ])
}

/// Reads each reaction off the force plan and checks it by the moment equations of the whole
/// truss (LH C.2) and against the dense solve: a roller's along its line, a pin's by its
/// horizontal and vertical parts.
#[allow(clippy::too_many_arguments)]
pub(super) fn read_reactions(
    b: &mut Board,
    t: &Truss,
    segs: &[Option<(H<Point>, H<Point>)>],
    rlines: &[Option<H<Line>>],
    sol: Option<&Solution>,
    by_moments: Option<&[Vector]>,
    reference: f64,
    fs: f64,
) -> Result<(), ConstructionError> {
    let kg = Scale::kg(fs);
    let f = "joint equilibrium, dense LU (nalgebra)";
    let fm = "moments about the other supports (LH C.2)";
    let mut col = 0;
    for (si, sup) in t.supports.iter().enumerate() {
        let first_col = col;
        col += match sup.kind {
            SupportKind::Pinned => 2,
            SupportKind::Roller { .. } => 1,
        };
        let Some((from, to)) = segs[si] else {
            continue;
        };
        match sup.kind {
            SupportKind::Roller { dir } => {
                let line = rlines[si].expect("a roller has a line");
                let v = b.measure(&from, &to, &line, kg, Label::quiet("R", 0), N_REACT);
                if let Some(m) = by_moments {
                    b.check(
                        &v,
                        "roller reaction by moments",
                        "kg",
                        fm,
                        reference,
                        || m[si].dot(&dir),
                    );
                }
                if let Some(sol) = sol {
                    b.check(
                        &v,
                        "roller reaction along its line",
                        "kg",
                        f,
                        reference,
                        || sol.reactions[first_col],
                    );
                }
            }
            SupportKind::Pinned => {
                let xa = b.line_dir(
                    &from,
                    Vector::new(1.0, 0.0),
                    Label::NONE,
                    Role::Auxiliary,
                    N_AXIS,
                )?;
                let ya = b.line_dir(
                    &from,
                    Vector::new(0.0, 1.0),
                    Label::NONE,
                    Role::Auxiliary,
                    N_AXIS,
                )?;
                let ax = b.measure(&from, &to, &xa, kg, Label::quiet("Ax", 0), N_REACT);
                let ay = b.measure(&from, &to, &ya, kg, Label::quiet("Ay", 0), N_REACT);
                if let Some(m) = by_moments {
                    b.check(
                        &ax,
                        "pin reaction by moments, horizontal",
                        "kg",
                        fm,
                        reference,
                        || m[si].x,
                    );
                    b.check(
                        &ay,
                        "pin reaction by moments, vertical",
                        "kg",
                        fm,
                        reference,
                        || m[si].y,
                    );
                }
                if let Some(sol) = sol {
                    b.check(&ax, "pin reaction, horizontal", "kg", f, reference, || {
                        sol.reactions[first_col]
                    });
                    b.check(&ay, "pin reaction, vertical", "kg", f, reference, || {
                        sol.reactions[first_col + 1]
                    });
                }
            }
        }
    }
    Ok(())
}
