//! The Cremona force plan (LH B.4, Abb. 17, Regel 1 and 2), with the support reactions by the
//! funicular polygon and its closing line (LH C.2).
//!
//! # Reactions
//! With a pin at A and a roller at B: the force polygon of the loads, a pole O and its rays;
//! the first string through A (the only point of A's reaction known), each further string from
//! the cut of the previous one with the next load's line of action, the last one cut with
//! B's reaction line in b′. The closing line A b′, carried parallel through O, cuts the
//! parallel to B's reaction through the end of the force polygon: that point divides the
//! closing side of the force polygon into B and A. This works for any directions, loads
//! parallel or not.
//!
//! # The plan in Bow's notation
//! Every space of the truss drawing gets a point of the plan: the spaces between the external
//! forces (loads and reactions, taken clockwise round the outline) are the corners of the
//! external force polygon; each triangle of the truss is found where the parallels to two of
//! its members through the points of the neighbouring spaces meet. That is the joint
//! polygon of a joint where only the space between two members is unknown, so two unknown
//! member forces (Regel 2: clockwise round every joint, kept for the whole plan). Every member
//! then appears once, as the segment between the points of the two spaces it separates.
//!
//! Going clockwise round joint a across member m from the space L on its left (seen from a
//! towards b) to the space R, the member acts on a as the plan vector from L to R. If that
//! vector points from a towards b the member pulls at the joint: tension (+); towards a,
//! it pushes: compression (−) (Regel 1).

use super::bow::*;
use super::faces::{self, PlaneGraph};
use super::graphic_reactions::*;
use super::labels::*;
use super::layout::*;
use super::matrix::{self, Solution};
use super::notes::*;
use super::plan::*;
use super::{JointLoad, LoadCase, SupportKind, Truss};
use crate::kernel::{Line, Point};
use crate::protocol::{Board, ConstructionError, Label, Part, Role, H};

pub use super::plan::{CaseResult, ReactionForce, TrussDrawing, ZERO_FORCE_REL};

/// Constructs the truss drawing and, per load case, the reactions and the Cremona plan,
/// each checked member by member against the sparse solve of the joint equations at every
/// size; the rank test is made at every size (see [`matrix::analyse`]).
///
/// # Errors
/// A truss that is not determinate, not a plane drawing, or whose plan stalls (three unknown
/// members at every remaining joint: Ritter's section would be needed), and loads at joints
/// off the outline.
///
/// ```
/// use graphostatik::truss::{cremona::*, *};
/// use graphostatik::kernel::{Point, Vector};
/// use graphostatik::protocol::Board;
/// // A triangle, span 2 m, height 1 m, 1000 kg at the apex: each rafter −707 kg, the tie +500.
/// let j = |n: &str, x, y| Joint { name: n.into(), at: Point::new(x, y) };
/// let m = |n: &str, a, b| Member { name: n.into(), ends: [a, b] };
/// let t = Truss::new(
///     vec![j("I", 0.0, 0.0), j("II", 2.0, 0.0), j("III", 1.0, 1.0)],
///     vec![m("1", 0, 2), m("2", 2, 1), m("3", 0, 1)],
///     vec![
///         Support::pinned(0, "A"),
///         Support::roller(1, Vector::new(0.0, 1.0), "B"),
///     ],
/// );
/// let case = LoadCase { name: "P".into(),
///     loads: vec![JointLoad { joint: 2, force: Vector::new(0.0, -1000.0) }],
///     force_scale: None, drawn: true, book_name: None };
/// let mut b = Board::recording().with_figure_size(400.0);
/// let r = construct_truss(&mut b, &t, &[case],
///     &TrussDrawing { length_scale: 20.0, force_scale: 20.0 }).unwrap();
/// let s: Vec<f64> = r[0].members.iter().map(|m| m.force).collect();
/// assert!((s[0] + 707.1068).abs() < 1e-3 && (s[2] - 500.0).abs() < 1e-9);
/// assert!(b.steps().iter().flat_map(|s| &s.checks).all(|c| c.passed));
/// ```
pub fn construct_truss(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
) -> Result<Vec<CaseResult>, ConstructionError> {
    construct(b, t, cases, dr, true, &mut Rows::default(), &[])
}

/// A member left out of a truss but drawn dashed in its drawing (a counter-diagonal out of
/// action, LH B.5): its name, for the step's situation, and its two joints.
#[derive(Debug, Clone, Copy)]
pub struct SlackMember<'a> {
    /// The member's name in the whole truss ("60").
    pub name: &'a str,
    /// Its joints, as indices into the truss drawn.
    pub ends: [usize; 2],
}

/// As [`construct_truss`], drawing the cases' rows from `rows.top` (mm) downwards and moving
/// it below them: for figures that draw several trusses (sub-trusses, counter-diagonals
/// switched per case) one under the other. `slack` are the members left out of this truss
/// but drawn dashed in its drawing (counter-diagonals out of action).
///
/// # Errors
/// As [`construct_truss`].
pub fn construct_truss_rows(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
    rows: &mut Rows,
    slack: &[SlackMember<'_>],
) -> Result<Vec<CaseResult>, ConstructionError> {
    construct(b, t, cases, dr, true, rows, slack)
}

/// The plan alone, without the rank test and the sparse solve: what a drafter does, and what
/// the benchmark times against the sparse solve. The plan still refuses a truss it cannot
/// resolve (it stalls, or two members meet in line where a space must be fixed), and
/// [`CaseResult::plan_residual`] still reports the balance at every joint.
///
/// # Errors
/// As [`construct_truss`].
pub fn construct_plan(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
) -> Result<Vec<CaseResult>, ConstructionError> {
    construct(b, t, cases, dr, false, &mut Rows::default(), &[])
}

fn construct(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
    checked: bool,
    rows: &mut Rows,
    slack: &[SlackMember<'_>],
) -> Result<Vec<CaseResult>, ConstructionError> {
    // The rank test at every size: sparse for the usual square system, the SVD for the rest
    // up to DENSE_MAX_JOINTS, the pebble game above. The plan alone is not tested: a truss
    // that is not determinate is found by the plan stalling.
    if checked {
        determinate(t)?;
    }
    let g = plane_drawing(t)?;
    let sup = supports(t)?;
    let mut out = Vec::with_capacity(cases.len());
    // The independent solve is sparse: every member is checked at every size.
    let sols = if checked {
        matrix::solve_all(t, cases)
    } else {
        vec![None; cases.len()]
    };
    let figure_scale = dr.length_scale;
    // Of several drawings, the numbered one is drawn at the scale its numbers need: a
    // Bauplan larger than the load positions' sketches (LH Aufgabe 5, Tafel I).
    let several = cases.len() > 1 || rows.heading.is_some();
    for (case, sol) in cases.iter().zip(sols) {
        let numbered = case.drawn && rows.numbered(t.members.len());
        let length_scale = if numbered && several {
            numbered_scale(t, figure_scale)
        } else {
            figure_scale
        };
        // A case with a force scale of its own draws its plan (and its loads) at it.
        let dr = &TrussDrawing {
            force_scale: case.force_scale.unwrap_or(dr.force_scale),
            length_scale,
        };
        let c = Case {
            t,
            g: g.as_ref(),
            case,
            sol: sol.as_ref(),
            dr,
            sup,
            slack,
            numbered,
        };
        // Each case a row of the sheet, its parts constructed once, each in its own frame.
        // A case not drawn is constructed and checked all the same, in a row that the sheet
        // leaves out (the walk-through shows it as one page).
        b.set_part(Part::packed(rows.row, TRUSS));
        b.set_context(|| case.name.clone());
        let r = if case.drawn {
            construct_case(b, &c)?
        } else {
            b.unseen(|b| construct_case(b, &c))?
        };
        b.clear_context();
        // Several cases: each row under its case's name (dead load, wind, snow), as the
        // plates head their plans.
        let heading = rows.heading.take();
        if case.drawn {
            let named = || (cases.len() > 1).then(|| case_heading(cases, case, dr.force_scale));
            if let Some(heading) = heading.or_else(named) {
                write_heading(b, &c, heading, figure_scale, &r, rows.row);
            }
        }
        rows.row += 1;
        out.push(r.result);
    }
    b.set_part(Part::default());
    Ok(out)
}

/// The case's name over its row, with its length scale where it is not the figure's.
fn write_heading(
    b: &mut Board,
    c: &Case,
    mut heading: String,
    figure_scale: f64,
    r: &CaseOut,
    row: u16,
) {
    let length_scale = c.dr.length_scale;
    if length_scale != figure_scale {
        heading += &format!(", lengths 1 : {}", crate::fmt::num(length_scale, 3));
    }
    let name = vec![vec![heading]];
    let k = 1000.0 / length_scale;
    let joints_top = (c.t.joints.iter()).fold(f64::NEG_INFINITY, |y, j| y.max(j.at.y * k));
    let [x0, _, _, y1] = r.truss_box;
    let y1 = y1.max(joints_top + JOINT_NAMES_MM);
    b.set_part(Part::packed(row, TRUSS));
    b.table(Point::new(x0, y1 + HEADING_MM), name, &[], N_CASE_NAME);
}

/// The length (mm) a numbered member is drawn at least, where the figure draws several
/// trusses and may draw the numbered one larger: a number a side of it, and room for a
/// crossing diagonal's beside it. Well under the shortest member of a drawing at the book's
/// scale that carries its numbers (LH Aufgabe 4's member 5, 16.1 mm at 1 : 50), so that a
/// joint dragged a little does not double the drawing (at 16 mm, a 2 cm move of joint V
/// did: the sheet went from 656 to 1,105 mm tall); LH Aufgabe 5's 10 mm members are
/// drawn twice as large, as Tafel I draws its Bauplan.
const NUMBERED_MEMBER_MM: f64 = 12.0;
/// The most a numbered drawing is enlarged over the figure's length scale.
const MOST_ENLARGED: f64 = 4.0;

/// The length scale 1 : n of a truss drawing that numbers its members among other drawings
/// at `length_scale`: that scale divided by the least whole factor (at most
/// [`MOST_ENLARGED`]) that draws the shortest member [`NUMBERED_MEMBER_MM`] long.
fn numbered_scale(t: &Truss, length_scale: f64) -> f64 {
    let shortest = (0..t.members.len())
        .map(|m| t.member_dir(m).1)
        .fold(f64::INFINITY, f64::min)
        * 1000.0
        / length_scale;
    if !(shortest > 0.0 && shortest < NUMBERED_MEMBER_MM) {
        return length_scale;
    }
    length_scale / (NUMBERED_MEMBER_MM / shortest).ceil().min(MOST_ENLARGED)
}

/// The force scales (kg per mm) the plans of `cases` are drawn at, each once, in the order
/// of the cases: the figure's, and those of cases with a scale of their own.
pub fn force_scales<'a>(
    cases: &'a [LoadCase],
    dr: &'a TrussDrawing,
) -> impl Iterator<Item = f64> + 'a {
    let mut seen: Vec<u64> = Vec::new();
    cases
        .iter()
        .map(|c| c.force_scale.unwrap_or(dr.force_scale))
        .filter(move |f| {
            let new = !seen.contains(&f.to_bits());
            seen.push(f.to_bits());
            new
        })
}

/// A case's heading over its row: its name (after the book's, where it has one), and its
/// force scale where the figure's plans are drawn at more than one ("I (crane at O9), 1 mm =
/// 100 kg"), as each plan is read at its own (LH Aufgabe 5).
pub(super) fn case_heading(cases: &[LoadCase], case: &LoadCase, force_scale: f64) -> String {
    if cases.iter().any(|c| c.force_scale.is_some()) {
        format!(
            "{}, 1 mm = {} kg",
            case.title(),
            crate::fmt::num(force_scale, 6)
        )
    } else {
        case.title()
    }
}

/// The rank test (LH Gl. 2 and more): a mechanism names the joint that can move.
fn determinate(t: &Truss) -> Result<(), ConstructionError> {
    match matrix::analyse(t).determinacy {
        matrix::Determinacy::Determinate => Ok(()),
        matrix::Determinacy::Mechanism { joint, freedoms } => Err(ConstructionError::Mechanism {
            joint: t.joints[joint].name.to_string(),
            freedoms,
        }),
        matrix::Determinacy::OverDeterminate { redundant } => {
            Err(ConstructionError::OverDeterminate {
                redundant,
                members: t.members.len(),
                needed: 2 * t.joints.len() as i64 - 3,
            })
        }
        matrix::Determinacy::Undecided { .. } => Err(ConstructionError::unsupported(
            "members",
            matrix::undecided_reason(t),
        )),
    }
}

/// The truss as a plane drawing for Bow's notation; `None` where members cross (the joint
/// polygons are drawn one by one instead).
fn plane_drawing(t: &Truss) -> Result<Option<PlaneGraph>, ConstructionError> {
    match faces::plane_graph(t) {
        Ok(g) => Ok(Some(g)),
        Err(faces::GraphError::Crossing) => Ok(None),
        Err(faces::GraphError::Disconnected { joint }) => Err(ConstructionError::Disconnected {
            joint: t.joints[joint].name.to_string(),
        }),
    }
}

/// One case as [`construct_case`] draws it: the truss, its plane drawing (if it has one),
/// the case, the sparse solve, the scales, where its parts go, the supports as the reaction
/// construction takes them, and the members out of action.
#[derive(Clone, Copy)]
struct Case<'a> {
    t: &'a Truss,
    g: Option<&'a PlaneGraph>,
    case: &'a LoadCase,
    sol: Option<&'a Solution>,
    dr: &'a TrussDrawing,
    sup: Supports,
    slack: &'a [SlackMember<'a>],
    /// Whether this case's drawing letters its members with their numbers.
    numbered: bool,
}

/// The most member numbers a figure writes over all its truss drawings; past it only the
/// first drawing is numbered (the crowd rule: the books number the members once, and every
/// plan's table uses the same numbers).
const MEMBER_NUMBERS: usize = 120;

/// The sheet row the next case of a figure of several truss drawings goes in, and how many
/// member numbers its drawings have written ([`construct_truss_rows`]).
#[derive(Debug, Clone, Default)]
pub struct Rows {
    /// The row of the next case ([`Part::row`]; rows go downwards from 0).
    pub row: u16,
    numbers: usize,
    /// The heading of the next row, where its caller draws the cases of one figure one at a
    /// time (the tension-only diagonals settle per case): written over it, then cleared.
    pub(super) heading: Option<String>,
}

impl Rows {
    /// Whether a drawing of `members` members is numbered, counting its numbers if it is.
    fn numbered(&mut self, members: usize) -> bool {
        let yes = self.numbers == 0 || self.numbers + members <= MEMBER_NUMBERS;
        if yes {
            self.numbers += members;
        }
        yes
    }
}

/// The truss drawing of a case: the joints, the members' lines, the rollers' reaction lines.
struct Drawn {
    jp: Vec<H<Point>>,
    mline: Vec<H<Line>>,
    rlines: Vec<Option<H<Line>>>,
}

/// One load case: the truss drawing with its loads, the reactions, the plan (in Bow's
/// notation, or joint by joint), the table of member forces, the zero-force members.
fn construct_case(b: &mut Board, c: &Case) -> Result<CaseOut, ConstructionError> {
    let Case {
        t,
        g,
        case,
        sol,
        dr,
        sup,
        ..
    } = *c;
    let fs = dr.force_scale;
    let maxload = case
        .loads
        .iter()
        .map(|l| l.force.norm())
        .fold(0.0, f64::max);
    let mut truss_box = EMPTY;
    let drawn = draw_truss(b, c, &mut truss_box)?;
    let loads = draw_loads(b, c, &drawn.jp, &mut truss_box);
    let inp = ReactionInput {
        t,
        sup,
        sol,
        fs,
        maxload,
        jp: &drawn.jp,
        rlines: &drawn.rlines,
        loads: &loads,
    };
    let reactions = draw_reactions(b, &inp, &mut truss_box)?;
    let external = External::of(t, &loads, reactions, maxload);
    // Bow's notation needs a plane drawing and every external force on the outline;
    // otherwise the joint polygons are drawn one by one (LH Abb. 17a).
    let ctx = PlanContext {
        t,
        case,
        ext: &external,
        sol,
        dr,
        at: Point::origin(),
        mline: &drawn.mline,
        maxload,
    };
    column(b, PLAN);
    // The outline is found once: whether Bow's notation applies, and where it starts.
    let outlined = g.and_then(|g| Some((g, outline(t, g, &external).ok()?)));
    let (result, plan_box) = match outlined {
        Some((g, round)) => cremona_plan(b, &ctx, g, round)?,
        None => super::joints::joint_polygons(b, &ctx)?,
    };
    let zero_kg = ZERO_FORCE_REL * check_reference(maxload, &external);
    write_table(b, &result, zero_kg, plan_box);
    column(b, TRUSS);
    mark_zero_members(b, t, &result, &drawn.jp, zero_kg);
    if !truss_box[0].is_finite() {
        truss_box = [0.0; 4];
    }
    Ok(CaseOut { result, truss_box })
}

/// The truss drawn to scale (Bauplan): joints, members (each the line through its joints,
/// which the plan's parallels and readings refer to), the members out of action dashed, each
/// support's reaction line (a roller's) or point (a pin's).
fn draw_truss(
    b: &mut Board,
    c: &Case,
    truss_box: &mut [f64; 4],
) -> Result<Drawn, ConstructionError> {
    let Case {
        t,
        case,
        dr,
        slack,
        numbered,
        ..
    } = *c;
    let k = 1000.0 / dr.length_scale;
    // Each step names its object in its context ("dead load: member 5"), as the walk-through
    // and the figure's layers show it; a board that keeps only its checks skips the names (no
    // check is made in these steps).
    let jp: Vec<H<Point>> = t
        .joints
        .iter()
        .enumerate()
        .map(|(i, j)| {
            let p = Point::from(j.at.coords * k);
            grow(truss_box, p, Point::origin());
            b.set_context_within(Some(&case.name), || format!("joint {}", j.name));
            b.point(p, Role::Given.labelled(joint_label(b, t, i)), N_JOINT)
        })
        .collect();
    let mut mline = Vec::with_capacity(t.members.len());
    for (m, mem) in t.members.iter().enumerate() {
        let [i, j] = mem.ends;
        b.set_context_within(Some(&case.name), || format!("member {}", mem.name));
        mline.push(b.line_through(
            &jp[i],
            &jp[j],
            match numbered {
                true => Role::Given.labelled(member_number(b, t, m)),
                false => Role::Given.into(),
            },
            N_MEMBER,
        )?);
    }
    for m in slack {
        let [i, j] = m.ends;
        b.set_context_within(Some(&case.name), || format!("member {}", m.name));
        b.segment(&jp[i], &jp[j], Role::Auxiliary, N_SLACK);
    }
    let mut rlines: Vec<Option<H<Line>>> = vec![None; t.supports.len()];
    for (si, s) in t.supports.iter().enumerate() {
        let label = support_label(t, si);
        b.set_context_within(Some(&case.name), || format!("support {}", s.name));
        match s.kind {
            SupportKind::Roller { dir } => {
                let line = b.line_dir(&jp[s.joint], dir, Role::Guide.labelled(label), N_SUPPORT)?;
                rlines[si] = Some(line);
            }
            SupportKind::Pinned => {
                b.point(jp[s.joint].g, Role::Guide.labelled(label), N_SUPPORT);
            }
        }
    }
    b.set_context(|| case.name.clone());
    Ok(Drawn { jp, mline, rlines })
}

/// The loads, drawn as arrows ending at their joints, in the order of their joints (left to
/// right, then bottom to top): the order of the force polygon.
fn draw_loads(
    b: &mut Board,
    c: &Case,
    jp: &[H<Point>],
    truss_box: &mut [f64; 4],
) -> Vec<JointLoad> {
    let Case { t, case, dr, .. } = *c;
    let mut loads: Vec<JointLoad> = case
        .loads
        .iter()
        .copied()
        .filter(|l| l.force.norm() > 0.0)
        .collect();
    loads.sort_by(|a, c| {
        let (pa, pc) = (t.joints[a.joint].at, t.joints[c.joint].at);
        pa.x.total_cmp(&pc.x).then(pa.y.total_cmp(&pc.y))
    });
    for (k, l) in loads.iter().enumerate() {
        let head = jp[l.joint];
        let at = &t.joints[l.joint].name;
        b.set_context_within(Some(&case.name), || format!("load at joint {at}"));
        let tail = b.point(head.g - l.force / dr.force_scale, Role::Given, N_LOAD);
        grow(truss_box, tail.g, Point::origin());
        b.segment(
            &tail,
            &head,
            Role::Force.labelled(Label::indexed("P", k as u32 + 1)),
            N_LOAD,
        );
    }
    b.set_context(|| case.name.clone());
    loads
}

/// A force as the book's tables write it: signed (tension +, compression −) in whole kg,
/// "0" within `zero_kg`.
pub(super) fn signed_kg(f: f64, zero_kg: f64) -> String {
    if f.abs() <= zero_kg {
        "0".to_string()
    } else if f > 0.0 {
        format!("+{}", crate::fmt::num(f, 0))
    } else {
        format!("−{}", crate::fmt::num(-f, 0))
    }
}

/// The rows of the evaluation: a head, the members, the reactions.
fn table_rows(result: &CaseResult, zero_kg: f64) -> Vec<Vec<String>> {
    let mut rows = vec![vec![
        "Stab".to_string(),
        "Strecke mm".to_string(),
        "Stabkraft kg".to_string(),
        "Art".to_string(),
    ]];
    for mf in &result.members {
        let kind = if mf.force.abs() <= zero_kg {
            "Nullstab"
        } else if mf.force > 0.0 {
            "Zug"
        } else {
            "Druck"
        };
        rows.push(vec![
            mf.member.as_str().to_owned(),
            crate::fmt::num(mf.plan_mm, 1),
            signed_kg(mf.force, zero_kg),
            kind.to_string(),
        ]);
    }
    // The reactions below the members, by magnitude (the book's "G" and "A" of Aufgabe 3).
    for r in &result.reactions {
        let f = r.magnitude();
        rows.push(vec![
            r.support.clone(),
            crate::fmt::num(r.plan_mm, 1),
            if f <= zero_kg {
                "0".to_string()
            } else {
                crate::fmt::num(f, 0)
            },
            "Auflager".to_string(),
        ]);
    }
    rows
}

/// The evaluation of the plan written beside it (LH B.4, "Auswertung"): member, length in
/// the plan, force, tension or compression, then the reactions by magnitude; `plan_box` is
/// the plan's extent.
fn write_table(b: &mut Board, result: &CaseResult, zero_kg: f64, plan_box: [f64; 4]) {
    // The rows are written only where the drawing is kept.
    let rows = if b.is_drawing() {
        table_rows(result, zero_kg)
    } else {
        Vec::new()
    };
    let corner = Point::new(plan_box[2] + 12.0, plan_box[3]);
    b.table(corner, rows, &[], N_TABLE);
}

/// Zero-force members (Nullstäbe) marked in the truss drawing.
fn mark_zero_members(b: &mut Board, t: &Truss, result: &CaseResult, jp: &[H<Point>], zero_kg: f64) {
    let base = b.context();
    let case = result.case.as_str();
    for (m, f) in result.members.iter().enumerate() {
        if f.force.abs() <= zero_kg {
            let [i, j] = t.members[m].ends;
            b.set_context_within(Some(case), || format!("member {}", t.members[m].name));
            b.segment(&jp[i], &jp[j], Role::Auxiliary.named("0"), N_ZERO);
        }
    }
    b.restore_context(base);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The numbered drawing of several is enlarged by the least whole factor that draws its
    /// shortest member 12 mm long, at most four times; a drawing whose members have room
    /// keeps the figure's scale.
    #[test]
    fn a_numbered_drawing_is_enlarged_only_as_far_as_its_numbers_need() {
        let truss = |side: f64| Truss::triangle(side, side);
        // The crane bridge's panels: 2 m at 1 : 200 are 10 mm, drawn at 1 : 100.
        assert_eq!(numbered_scale(&truss(2.0), 200.0), 100.0);
        // 2 m at 1 : 100 are 20 mm: room enough.
        assert_eq!(numbered_scale(&truss(2.0), 100.0), 100.0);
        // 0.1 m at 1 : 200 would need 32 times: four at most.
        assert_eq!(numbered_scale(&truss(0.1), 200.0), 50.0);
    }
}
