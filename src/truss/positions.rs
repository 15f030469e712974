//! The table of a moving load's positions (LH B.4, Aufgabe 5, Tabelle 2): for each position
//! the support reactions, and the most loaded diagonal and vertical of the web with their
//! forces. The book draws the Cremona plans of the dead load and of three crane positions,
//! and finds the web forces of all ten positions by Ritter's section (D = A / sin δ,
//! V = −Q₁); here every position is constructed and checked (its plan drawn or not), and the
//! table is read off the plans.

use super::cremona::{signed_kg, CaseResult};
use super::layout::HEADING_MM;
use super::notes::N_POSITIONS;
use super::Truss;
use crate::kernel::tolerance::PARALLEL_SIN_EPS;
use crate::kernel::Point;
use crate::protocol::{Board, Part};

/// How a member runs, for the table's columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Run {
    Chord,
    Vertical,
    Diagonal,
}

/// How member `m` runs. A vertical on a supported joint counts as neither: it carries the
/// support's reaction, which the table gives (in LH Tafel I the trestle under the girder).
fn run(t: &Truss, m: usize) -> Option<Run> {
    let [a, b] = t.members[m].ends;
    let on_support = |j: usize| t.supports.iter().any(|s| s.joint == j);
    let d = t.joints[b].at - t.joints[a].at;
    let len = d.norm();
    if d.x.abs() <= PARALLEL_SIN_EPS * len {
        (!on_support(a) && !on_support(b)).then_some(Run::Vertical)
    } else if d.y.abs() <= PARALLEL_SIN_EPS * len {
        Some(Run::Chord)
    } else {
        Some(Run::Diagonal)
    }
}

/// The member of a run with the largest force by magnitude in one case (the first of equal
/// ones), with its force (kg); `None` where the truss has no such member.
fn most_loaded(t: &Truss, r: &CaseResult, of: Run) -> Option<(usize, f64)> {
    (r.members.iter().enumerate())
        .filter(|(m, _)| run(t, *m) == Some(of))
        .map(|(m, f)| (m, f.force))
        .fold(None, |best, (m, f)| match best {
            Some((_, g)) if f64::abs(g) >= f.abs() => best,
            _ => Some((m, f)),
        })
}

/// The rows of the table: a head (the position, each support's vertical reaction, the most
/// loaded diagonal and vertical and their forces), then one row per position. The verticals
/// on the supports are left out: they carry the reactions.
pub fn positions_rows(
    t: &Truss,
    positions: &[(&str, &CaseResult)],
    zero_kg: f64,
) -> Vec<Vec<String>> {
    let mut head = vec!["Laststellung".to_string()];
    head.extend(t.supports.iter().map(|s| format!("{} kg", s.name)));
    head.extend(["Diagonale", "D kg", "Vertikale", "V kg"].map(String::from));
    let mut rows = vec![head];
    for (name, r) in positions {
        let mut row = vec![name.to_string()];
        row.extend(r.reactions.iter().map(|s| signed_kg(s.force.y, zero_kg)));
        for of in [Run::Diagonal, Run::Vertical] {
            match most_loaded(t, r, of) {
                Some((m, f)) => row.extend([t.members[m].name.to_string(), signed_kg(f, zero_kg)]),
                None => row.extend(["–".to_string(), "–".to_string()]),
            }
        }
        rows.push(row);
    }
    rows
}

/// Writes the table of the positions of the moving load named `load`, under a heading, as a
/// free part of the figure ([`Part::free`]: the sheet layout sets it in a hole the plans
/// leave), in row `row`. `positions` are the positions' names and results, in the order of
/// the load's path; `zero_kg` is the force written as 0.
///
/// ```
/// use graphostatik::truss::{cremona::*, positions::*, *};
/// use graphostatik::kernel::{Point, Vector};
/// use graphostatik::protocol::Board;
/// // A triangle, span 2 m, height 1 m, with a vertical post to the apex.
/// let j = |n: &str, x, y| Joint { name: n.into(), at: Point::new(x, y) };
/// let m = |n: &str, a, b| Member { name: n.into(), ends: [a, b] };
/// let t = Truss::new(
///     vec![j("I", 0.0, 0.0), j("II", 2.0, 0.0), j("III", 1.0, 1.0), j("IV", 1.0, 0.0)],
///     vec![m("1", 0, 2), m("2", 2, 1), m("3", 0, 3), m("4", 3, 1), m("5", 3, 2)],
///     vec![Support::pinned(0, "A"), Support::roller(1, Vector::new(0.0, 1.0), "B")],
/// );
/// let at = |joint, name: &str| LoadCase { name: name.into(),
///     loads: vec![JointLoad { joint, force: Vector::new(0.0, -1000.0) }],
///     force_scale: None, drawn: name == "at IV", book_name: None };
/// let cases = [at(3, "at IV"), at(2, "at III")];
/// let mut b = Board::recording().with_figure_size(400.0);
/// let r = construct_truss(&mut b, &t, &cases,
///     &TrussDrawing { length_scale: 20.0, force_scale: 20.0 }).unwrap();
/// let rows = positions_rows(&t, &[("at IV", &r[0]), ("at III", &r[1])], 1e-6);
/// // 1000 kg at the post's foot hangs on the post; at the apex the post carries nothing.
/// assert_eq!(rows[1], ["at IV", "+500", "+500", "1", "−707", "5", "+1000"]);
/// assert_eq!(rows[2][5..], ["5", "0"]);
/// ```
pub fn write_positions_table(
    b: &mut Board,
    t: &Truss,
    load: &str,
    positions: &[(&str, &CaseResult)],
    zero_kg: f64,
    row: u16,
) {
    let (heading, rows) = if b.is_drawing() {
        let heading = format!("{load}: every position, its most loaded diagonal and vertical");
        (vec![vec![heading]], positions_rows(t, positions, zero_kg))
    } else {
        (Vec::new(), Vec::new())
    };
    b.set_part(Part::free(row, 0));
    b.table(Point::new(0.0, HEADING_MM), heading, &[], N_POSITIONS);
    b.table(Point::origin(), rows, &[], N_POSITIONS);
    b.set_part(Part::default());
}
